/* fresnel_fixed.h -- kept for existing code: the Q1.15 fixed-point API is
 * fresnel_q15.h, which this header includes. */
#ifndef FRESNEL_FIXED_H
#define FRESNEL_FIXED_H

#include "fresnel_q15.h"

#endif /* FRESNEL_FIXED_H */
