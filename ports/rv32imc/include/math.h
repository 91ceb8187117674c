/* Debian's riscv64-unknown-elf toolchain has no C library, so no <math.h>.
 * For `make size` only: the libm functions the binary32 runtime calls,
 * declared so that its own code can be compiled and measured; they are
 * left unresolved at link time, and the size table says "+ libm". */
#ifndef FRESNEL_RV32_MATH_H
#define FRESNEL_RV32_MATH_H
float sqrtf(float);
float expf(float);
float log1pf(float);
float fmaf(float, float, float);
float fabsf(float);
#endif
