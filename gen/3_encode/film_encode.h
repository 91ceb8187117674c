/* The thin-film model's constants in each number type (fresnel_film.h), and
 * back: the decoders give the double model of exactly the stored values,
 * the reference each type's error bound is measured against. Host only. */
#ifndef FRESNEL_FILM_ENCODE_H
#define FRESNEL_FILM_ENCODE_H

#include "common/reference_film.h"

void film_encode_f32(const film_model *m, fresnel_film *out);
void film_decode_f32(const fresnel_film *in, film_model *m);
/* 0, or -1 when a value lies outside the Q15 layout's range (a0 in
 * [-2, 2), opd and decay < 16, |A| + |B| < 1, |P| < 2, |Q| < 1; the
 * weights |2 c| < 8). */
int film_encode_q15(const film_model *m, fresnel_film_q15 *out);
void film_decode_q15(const fresnel_film_q15 *in, film_model *m);
#if FRESNEL_HAS_F16
void film_encode_f16(const film_model *m, fresnel_film_f16 *out);
void film_decode_f16(const fresnel_film_f16 *in, film_model *m);
#endif

#endif
