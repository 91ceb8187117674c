/* Other renderers' exact conductor Fresnel (gen/bench/peers.h: this
 * project's transcriptions of Mitsuba 3's fresnel_conductor and pbrt-v4's
 * FrComplex, and the versions they follow) as out-of-line calls, for the
 * accuracy rows of `fresnel bench --targets` and the call rows of `make
 * bench`. Never part of the runtime. */
#ifndef FRESNEL_BENCH_COMPARE_H
#define FRESNEL_BENCH_COMPARE_H

float cmp_mitsuba_conductor(float eta, float kappa, float c);
float cmp_pbrt_conductor(float eta, float kappa, float c);

#endif
