/* The one file of tests/ports/consumer/single_film.c's program that compiles the
 * single-file runtime's code (FRESNEL_IMPLEMENTATION) of the type given. */
#ifndef FRESNEL_LIBRARY
#define FRESNEL_IMPLEMENTATION
#ifdef WITH_F32
#include "fresnel_single_f32.h"
#endif
#ifdef WITH_Q15
#include "fresnel_single_q15.h"
#endif
#ifdef WITH_F16
#include "fresnel_single_f16.h"
#endif
#endif

void single_film_print(void);

int main(void)
{
    single_film_print();
    return 0;
}
