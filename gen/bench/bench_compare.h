/* Other projects' exact conductor Fresnel, re-implemented from their
 * published formulas for `fresnel bench --targets` only (gen/bench/bench_targets.c):
 * never part of the runtime. Written here from the formulas, not copied.
 * Each is compiled in its own translation unit (gen/bench/bench_compare.c), so that,
 * like the runtime's functions, it is a call the benchmark loop cannot inline
 * or hoist material constants out of. */
#ifndef FRESNEL_BENCH_COMPARE_H
#define FRESNEL_BENCH_COMPARE_H

/* The textbook real form as Mitsuba 3 (fresnel_conductor) and MaterialX
 * (mx_fresnel_conductor) evaluate it, binary32 throughout:
 *   A = eta^2 - kappa^2 - sin^2,  a^2 + b^2 = sqrt(A^2 + 4 eta^2 kappa^2),
 *   a = sqrt((a^2 + b^2 + A)/2)   (square roots of max(0, x)),
 *   Rs = (a^2+b^2 + c^2 - 2ac) / (a^2+b^2 + c^2 + 2ac),
 *   Rp = Rs (c^2 (a^2+b^2) + sin^4 - 2ac sin^2) / (c^2 (a^2+b^2) + sin^4 + 2ac sin^2),
 * sin^2 = 1 - c^2 rounded, F = (Rs + Rp)/2. c is clamped to [0, 1] first. */
float cmp_mitsuba_conductor(float eta, float kappa, float c);

/* pbrt-v4's FrComplex form: complex arithmetic on the relative index
 * n = eta + i kappa, binary32 throughout:
 *   sin^2 t = (1 - c^2) / n^2,  cos t = sqrt(1 - sin^2 t)   (principal complex root),
 *   r_par = (n c - cos t) / (n c + cos t),  r_perp = (c - n cos t) / (c + n cos t),
 *   F = (|r_par|^2 + |r_perp|^2) / 2,
 * with textbook complex division ((a c + b d) + i (b c - a d)) / (c^2 + d^2) and
 * square root sqrt(z) = t1 + i t2, t1 = sqrt((|z| + |Re z|)/2),
 * t2 = Im z / (2 t1) (swapped, with signs, for Re z < 0). c clamped to [0, 1]. */
float cmp_pbrt_conductor(float eta, float kappa, float c);

#endif
