/* fresnel_fixed_fast.h -- kept for existing code: the Q1.15 fast paths are
 * fresnel_q15_fast.h, which this header includes. */
#ifndef FRESNEL_FIXED_FAST_H
#define FRESNEL_FIXED_FAST_H

#include "fresnel_q15_fast.h"

#endif /* FRESNEL_FIXED_FAST_H */
