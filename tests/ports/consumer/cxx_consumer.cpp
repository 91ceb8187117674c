// A C++17 program using every public header and one function of each number
// type: binary32 (fresnel.h), Q1.15 fixed point (fresnel_fixed.h, and the
// inline fresnel_fixed_fast.h) and, where
// the compiler has _Float16, binary16 (fresnel_f16.h). tests/ports/test_consumers.sh
// builds it with g++ and clang++ (-Wall -Wextra -Wpedantic -Werror) against
// libfresnel.a and compares its output with consumer.c's numbers.
#include <cstdio>

#include "fresnel.h"
#include "fresnel_config.h"
#include "fresnel_f16.h"
#include "fresnel_fixed.h"
#include "fresnel_fixed_fast.h"

int main()
{
    const fresnel_rgb gold_f0 = {1.0f, 0.78f, 0.34f};
    const fresnel_rgb gold_f82 = {0.97f, 0.84f, 0.55f};
    for (float c = 0.0f; c <= 1.0f; c += 0.25f) {
        const fresnel_rgb f = fresnel_f82_rgb(gold_f0, gold_f82, c);
        std::printf("%.2f %.6f %.6f %.6f %.6f\n", static_cast<double>(c), static_cast<double>(f.r),
                    static_cast<double>(f.g), static_cast<double>(f.b),
                    static_cast<double>(fresnel_dielectric(1.5f, c)));
    }
    // Schlick at F0 = 0.04 (1311/32768), cos 0.5, in each type
    std::printf("q15 %d\n", static_cast<int>(fresnel_schlick_q15(1311, 16384)));
    std::printf("q15-fast %d\n", static_cast<int>(fresnel_schlick_q15_fast(1311, 16384)));
#if FRESNEL_HAS_F16
    const fresnel_f16 h = fresnel_schlick_f16(static_cast<fresnel_f16>(0.04f), static_cast<fresnel_f16>(0.5f));
    std::printf("f16 %.4f\n", static_cast<double>(h));
#else
    std::printf("f16 not in this compiler\n");
#endif
    return 0;
}
