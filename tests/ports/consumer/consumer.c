/* A small program as a firmware or game would write it: compiled against the
 * installed library (pkg-config) and against vendored include/ + src/f32/. */
#include <stdio.h>

#include "fresnel.h"

int main(void)
{
    const fresnel_rgb gold_f0 = {1.0f, 0.78f, 0.34f};
    const fresnel_rgb gold_f82 = {0.97f, 0.84f, 0.55f};
    float c;
    for (c = 0.0f; c <= 1.0f; c += 0.25f) {
        fresnel_rgb f = fresnel_f82_rgb(gold_f0, gold_f82, c);
        printf("%.2f %.6f %.6f %.6f %.6f\n", c, f.r, f.g, f.b, fresnel_dielectric(1.5f, c));
    }
    return 0;
}
