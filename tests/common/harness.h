/* Minimal test harness. Each check prints one line, "PASS name" or
 * "FAIL name: detail"; tests/run.sh counts them. main() returns
 * harness_exit(), non-zero when anything failed.
 *
 *   CHECK(name, cond, fmt, ...)   one assertion, printed with its detail on failure
 *   NOTE(fmt, ...)                an informational line (measured maxima etc.)
 */
#ifndef FRESNEL_HARNESS_H
#define FRESNEL_HARNESS_H

#include <stdio.h>

static int harness_failed_;
static int harness_passed_;

#define CHECK(name, cond, ...)                                                                     \
    do {                                                                                           \
        if (cond) {                                                                                \
            harness_passed_++;                                                                     \
            printf("PASS %s\n", (name));                                                           \
        } else {                                                                                   \
            harness_failed_++;                                                                     \
            printf("FAIL %s (%s:%d): ", (name), __FILE__, __LINE__);                               \
            printf(__VA_ARGS__);                                                                   \
            printf("\n");                                                                          \
        }                                                                                          \
    } while (0)

#define NOTE(...)                                                                                  \
    do {                                                                                           \
        printf("NOTE ");                                                                           \
        printf(__VA_ARGS__);                                                                       \
        printf("\n");                                                                              \
    } while (0)

static inline int harness_exit(void)
{
    fflush(stdout);
    return harness_failed_ ? 1 : 0;
}

#endif
