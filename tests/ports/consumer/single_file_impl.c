/* The one file of tests/ports/consumer/single_file.c's program that compiles the
 * single-file runtimes' code (FRESNEL_IMPLEMENTATION), each type given. */
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
