/* Shared by the fuzz targets: turning arbitrary bytes into inputs,
 * and reporting an oracle violation.
 *
 * Built two ways. Under libFuzzer (`make fuzz`) a violation prints what was
 * expected and aborts, so libFuzzer saves the input as a crash file. Built
 * with -DFUZZ_REPLAY and tests/fuzz/replay_main.c (`make test`), a violation
 * prints a FAIL line and the replay goes on to the next corpus file.
 *
 * Byte decoding. The fuzzer mutates bytes, so every value is chosen by a
 * mode byte followed by four payload bytes; missing bytes read as 0. The
 * modes make each interesting region reachable by a short mutation rather
 * than by chance: raw binary32 bit patterns (NaN payloads, +-Inf,
 * subnormals, negative zero), a table of special values, uniform in [0, 1],
 * log-uniform over a wide range, and points within a few ulps of 0 and 1. */
#ifndef FRESNEL_FUZZ_H
#define FRESNEL_FUZZ_H

#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* The smallest positive binary32 subnormal (C11 names it FLT_TRUE_MIN). */
#define FUZZ_SUBNORMAL_MIN 0x1p-149f

#ifdef FUZZ_REPLAY
int fuzz_failures; /* counted by replay_main.c per corpus file */
#define FUZZ_FAIL(...)                                                                             \
    do {                                                                                           \
        fuzz_failures++;                                                                           \
        printf("FAIL fuzz oracle (%s:%d): ", __FILE__, __LINE__);                                  \
        printf(__VA_ARGS__);                                                                       \
        printf("\n");                                                                              \
    } while (0)
#else
#define FUZZ_FAIL(...)                                                                             \
    do {                                                                                           \
        fprintf(stderr, "fuzz oracle violated (%s:%d): ", __FILE__, __LINE__);                     \
        fprintf(stderr, __VA_ARGS__);                                                              \
        fprintf(stderr, "\n");                                                                     \
        abort();                                                                                   \
    } while (0)
#endif

typedef struct fuzz_bytes {
    const uint8_t *p;
    size_t n;
} fuzz_bytes;

static inline uint8_t fuzz_u8(fuzz_bytes *b)
{
    uint8_t v = 0;
    if (b->n) {
        v = *b->p++;
        b->n--;
    }
    return v;
}

static inline uint32_t fuzz_u32(fuzz_bytes *b)
{
    uint32_t v = 0;
    int i;
    for (i = 0; i < 4; i++)
        v = (v << 8) | fuzz_u8(b);
    return v;
}

static inline float fuzz_bits_to_float(uint32_t u)
{
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

/* A float from the next five bytes; [lo, hi] (lo > 0) is the parameter's
 * natural scale for the log-uniform mode, which reaches a decade beyond it
 * on each side. */
static inline float fuzz_float(fuzz_bytes *b, float lo, float hi)
{
    static const float special[] = {
        0.0f, -0.0f, 1.0f, -1.0f, 0.5f, 2.0f, 1e-30f, 1e-8f, 1e-7f, 1e-6f, 1.0f - 1e-7f,
        1.0f + 1e-7f, 1.0f / 7.0f, 0.15f, 5.0f, 0.04f, 1.04f, 1.5f, 1.33f, 2.42f, 0.17f, 3.5f,
        100.0f, 1000.0f, 1e4f, 1e5f, 1e-3f, 0.01f, FLT_MIN, FLT_MAX, -FLT_MAX, FUZZ_SUBNORMAL_MIN,
        FLT_EPSILON, 0.99999994f, 1.00000012f, 1e-18f, 0.9999f, 5.96e-8f};
    uint8_t mode = fuzz_u8(b);
    uint32_t u = fuzz_u32(b);
    double x = u / 4294967295.0;
    switch (mode % 8) {
    case 0:
        return fuzz_bits_to_float(u);
    case 1:
        switch (u % 4) {
        case 0: return NAN;
        case 1: return INFINITY;
        case 2: return -INFINITY;
        default: return fuzz_bits_to_float(0x7f800000u | (u >> 9) | 1u); /* some NaN payload */
        }
    case 2:
    case 3:
        return special[u % (sizeof special / sizeof special[0])];
    case 4:
        return (float)x;
    case 5: {
        double l = log((double)lo) - log(10.0), h = log((double)hi) + log(10.0);
        return (float)exp(l + (h - l) * x);
    }
    case 6: { /* a few ulps from 0 or 1, on either side */
        float k = (float)((u >> 2) % 16);
        switch (u & 3) {
        case 0: return 1.0f - k * (FLT_EPSILON / 2.0f);
        case 1: return 1.0f + k * FLT_EPSILON;
        case 2: return k * FUZZ_SUBNORMAL_MIN;
        default: return -k * FUZZ_SUBNORMAL_MIN;
        }
    }
    default:
        return (float)(lo + (hi - lo) * x);
    }
}


#endif
