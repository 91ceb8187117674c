/* A program built against a generated scene header (make: build/scene_default.h
 * from data/scenes/default.scene): gold's reflectance over angle with each
 * model the scene names, as a shader would call them. */
#include <math.h>
#include <stdio.h>

#include "fresnel.h"
#include "scene_default.h"

int main(void)
{
    int deg;
    printf("gold in linear sRGB: theta, then R G B for schlick | f82 | exact (fitted eta, kappa) | lut32\n");
    for (deg = 0; deg <= 90; deg += 15) {
        float c = deg == 90 ? 0.0f : (float)cos(deg * 0.017453292519943295);
        fresnel_rgb s = fresnel_schlick_rgb(fresnel_default_au_f0, c);
        fresnel_rgb f = fresnel_f82_rgb(fresnel_default_au_f0, fresnel_default_au_f82, c);
        fresnel_rgb e = fresnel_conductor_rgb(fresnel_default_au_eta, fresnel_default_au_kappa, c);
        fresnel_rgb l = fresnel_lut_rgb(fresnel_default_au_lut32, 32, c);
        printf("%2d  %.3f %.3f %.3f | %.3f %.3f %.3f | %.3f %.3f %.3f | %.3f %.3f %.3f\n", deg, s.r, s.g, s.b, f.r,
               f.g, f.b, e.r, e.g, e.b, l.r, l.g, l.b);
    }
    return 0;
}
