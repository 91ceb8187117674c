/* fresnel_config.h -- compile-time feature selection, checked at compile time.
 *
 * One macro selects what a build contains:
 *
 *     cc -DFRESNEL_CONFIG='FRESNEL_CFG_NO_FLOAT|FRESNEL_CFG_NO_F16' ...
 *
 * FRESNEL_CONFIG is a bitwise OR of the flags below (default 0: everything
 * the compiler supports). Each source file of the runtime compiles to nothing
 * when its feature is switched off, so a build can take all of src/ and still
 * contain only what it asked for.
 *
 *   FRESNEL_CFG_NO_FLOAT  no binary32 functions (fresnel.h's declarations,
 *                         src/f32/). The fixed-point-only Cortex-M0 build
 *                         (ports/cross.sh) compiles all of src/ with
 *                         NO_FLOAT|NO_F16.
 *   FRESNEL_CFG_NO_F16    no _Float16 functions (fresnel_f16.h, src/f16/).
 *                         Implied when the compiler has no _Float16. Code
 *                         built by a compiler that has it (gcc, g++) against
 *                         a library built by one that has not (clang 14 on
 *                         x86-64) must say NO_F16 too.
 *   FRESNEL_CFG_NO_Q15    no Q1.15 fixed-point functions (fresnel_q15.h,
 *                         src/q15/).
 *   FRESNEL_CFG_NO_SIMD   the binary32 batches (fresnel_conductor_batch,
 *                         ..._rgb_batch) in portable C instead of the SSE2,
 *                         AVX, AVX-512 or AArch64 NEON intrinsics the
 *                         target macros select; same results.
 *
 * WHY ONE MACRO
 *   A misspelled stb-style switch (-DFRESNEL_NO_FLOT) is silently ignored by
 *   the preprocessor, and the build tests the wrong thing (libfixmath's test
 *   matrix shipped FIXMATH_NO_HARD_DIV, a name the library never read). Here
 *   the flags are names the C compiler must resolve: FRESNEL_CONFIG is used in
 *   a C constant expression below, where an unknown identifier
 *   (FRESNEL_CFG_NO_FLOT) is a hard error, and bits outside the known flags
 *   are rejected too. The spellings people try first (FRESNEL_NO_FLOAT, ...)
 *   stop the build with a pointer here.
 */
#ifndef FRESNEL_CONFIG_H
#define FRESNEL_CONFIG_H

#define FRESNEL_CFG_NO_FLOAT 0x1
#define FRESNEL_CFG_NO_F16 0x2
#define FRESNEL_CFG_NO_Q15 0x4
#define FRESNEL_CFG_NO_SIMD 0x8
#define FRESNEL_CFG_KNOWN_FLAGS 0xf

#ifndef FRESNEL_CONFIG
#define FRESNEL_CONFIG 0
#endif

#if defined(FRESNEL_NO_FLOAT) || defined(FRESNEL_NO_F16) || defined(FRESNEL_NO_FIXED) || defined(FRESNEL_NO_Q15) || \
    defined(FRESNEL_NO_FLOATS) || defined(FRESNEL_NO_FIXED_POINT) || defined(FRESNEL_NO_HALF) || \
    defined(FRESNEL_FIXED_ONLY) || defined(FRESNEL_CFG) || defined(FRESNEL_NO_SIMD)
#error "fresnel: configure with -DFRESNEL_CONFIG='FRESNEL_CFG_NO_FLOAT|...' (see fresnel_config.h)"
#endif

/* An unknown flag name is an undeclared identifier here; unknown bits make
 * the array size negative. (In #if the same name would quietly be 0.) */
typedef char fresnel_i_config_has_unknown_flags[(((FRESNEL_CONFIG) & ~FRESNEL_CFG_KNOWN_FLAGS) == 0) ? 1 : -1];

#define FRESNEL_HAS_FLOAT (((FRESNEL_CONFIG) & FRESNEL_CFG_NO_FLOAT) == 0)
#define FRESNEL_HAS_Q15 (((FRESNEL_CONFIG) & FRESNEL_CFG_NO_Q15) == 0)
#define FRESNEL_HAS_SIMD (((FRESNEL_CONFIG) & FRESNEL_CFG_NO_SIMD) == 0)

/* ALIASES: second names that code and generated headers may spell, each the
 * name of fresnel.h's NAMING rule it stands for (tests/repo/test_public_names.sh
 * reads this block), kept for existing code: FIXED is the Q1.15 type. */
#define FRESNEL_CFG_NO_FIXED FRESNEL_CFG_NO_Q15
#define FRESNEL_HAS_FIXED FRESNEL_HAS_Q15
/* end of ALIASES */
/* _Float16 needs the compiler's support as well as the configuration: gcc
 * defines __FLT16_MANT_DIG__ exactly where it accepts _Float16 (x86-64,
 * Arm with -mfp16-format=ieee or an FP16 FPU, AArch64); clang 14 on x86-64
 * does not. */
#if defined(__FLT16_MANT_DIG__)
#define FRESNEL_HAS_F16 (((FRESNEL_CONFIG) & FRESNEL_CFG_NO_F16) == 0)
#else
#define FRESNEL_HAS_F16 0
#endif

/* The runtime's internal helpers shared between its files are named
 * fresnel_i_* (not API; the public prefix keeps them out of the user's
 * namespace) and are declared with FRESNEL_I_HIDDEN, so a shared library
 * built from src/ does not export them where the toolchain has ELF/Mach-O
 * visibility. */
#if defined(__GNUC__) && !defined(_WIN32) && !defined(__CYGWIN__)
#define FRESNEL_I_HIDDEN __attribute__((visibility("hidden")))
#else
#define FRESNEL_I_HIDDEN
#endif

#endif /* FRESNEL_CONFIG_H */
