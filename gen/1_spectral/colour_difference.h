/* Colour differences for the report: linear RGB of a colour space -> CIE XYZ
 * -> CIELAB -> CIEDE2000 [CIE 15:2004 for CIELAB; Sharma, Wu, Dalal 2005,
 * "The CIEDE2000 color-difference formula: implementation notes,
 * supplementary test data, and mathematical observations", Color Res. Appl.
 * 30(1) 21-30, for CIEDE2000 with kL = kC = kH = 1].
 *
 * The RGB values are those gen/1_spectral/spectral.h produces for a colour_space: its
 * xyz_to_rgb maps D65-lit XYZ to RGB with a perfect reflector at exactly
 * (1,1,1). Inverting that matrix therefore undoes the chromatic adaptation as
 * well, and the Lab white is the XYZ of RGB (1,1,1) under the inverse, so a
 * perfect reflector is L* = 100, a* = b* = 0 in every space. Because the
 * adaptation is undone, the Lab of an RGB triple depends only on the XYZ it
 * came from, not on which space carried it (up to rounding).
 *
 * RGB outside [0, 1] (out-of-gamut F0, e.g. gold's red ~1.04 in linear sRGB)
 * is used as is: no clamping. Host only. */
#ifndef FRESNEL_COLOUR_DIFFERENCE_H
#define FRESNEL_COLOUR_DIFFERENCE_H

#include "1_spectral/spectral.h"

/* The inverse of cs->xyz_to_rgb and the white it implies, computed once when
 * many colours of one space are converted. */
typedef struct lab_space {
    double rgb_to_xyz[3][3];
    double white[3]; /* XYZ of RGB (1,1,1); Y = 1 for the spaces of colour_space_load */
} lab_space;

/* 0, or -1 when cs->xyz_to_rgb is singular (never for a loaded space). */
int lab_space_init(lab_space *ls, const colour_space *cs);
void lab_space_xyz(const lab_space *ls, const double rgb[3], double xyz[3]);
void lab_space_lab(const lab_space *ls, const double rgb[3], double lab[3]);

/* XYZ relative to white -> L*, a*, b* (CIE 15:2004, with the linear segment
 * below (6/29)^3, which also keeps negative XYZ finite). */
void lab_from_xyz(const double xyz[3], const double white[3], double lab[3]);

/* One-shot conveniences: invert the matrix on every call. A singular matrix
 * gives NaN. */
void lab_from_linear_rgb(const colour_space *cs, const double rgb[3], double lab[3]);
double delta_e2000_rgb(const colour_space *cs, const double a[3], const double b[3]);

/* CIEDE2000 between two CIELAB colours; symmetric, 0 for equal inputs. */
double ciede2000(const double lab1[3], const double lab2[3]);

#endif
