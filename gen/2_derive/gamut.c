/* Stage 2, derive: the ground truth under the run's gamut policy (derive.h,
 * OUT-OF-GAMUT POLICY).
 *
 * map. At each node angle the in-gamut colour nearest in CIEDE2000 to the
 * unclipped truth is found by a bound-constrained pattern search (compass
 * steps along R, G and B, clamped to the box, halved when no step improves):
 * the coordinate directions conform to the box's faces, so the search ends
 * at a point where no feasible direction lowers the difference. It starts
 * from the per-channel clip and from the colour scaled by its largest
 * channel, and keeps the better end point. The mapped curve is the truth
 * plus a correction d = nearest - truth, which is 0 where the truth is in
 * the gamut; d is interpolated between the nodes by Catmull-Rom in theta,
 * so that the curve passes through every node's nearest colour and has a
 * continuous slope between them (the per-angle nearest colours alone have a
 * kink where the truth leaves the gamut, which a fitted model or table would
 * spend its freedom on). A final clamp to [0, 1] removes the interpolation's
 * overshoot, a few 1e-7 at most. */
#include <math.h>
#include <string.h>

#include "1_spectral/colour_difference.h"
#include "2_derive/derive.h"

static const double deg = 3.14159265358979323846 / 180.0;

static double de_to(const lab_space *ls, const double target_lab[3], const double rgb[3])
{
    double lab[3];
    lab_space_lab(ls, rgb, lab);
    return ciede2000(target_lab, lab);
}

static double search_box(const lab_space *ls, const double target_lab[3], double x[3])
{
    double best = de_to(ls, target_lab, x), step = 1.0 / 64.0;
    while (step > 1e-12) {
        int ch, moved = 0;
        for (ch = 0; ch < 3; ch++) {
            int dir;
            for (dir = -1; dir <= 1; dir += 2) {
                double y[3], d;
                memcpy(y, x, sizeof y);
                y[ch] += dir * step;
                y[ch] = y[ch] < 0.0 ? 0.0 : (y[ch] > 1.0 ? 1.0 : y[ch]);
                if (y[ch] == x[ch])
                    continue;
                d = de_to(ls, target_lab, y);
                if (d < best) {
                    best = d;
                    memcpy(x, y, sizeof y);
                    moved = 1;
                    break;
                }
            }
        }
        if (!moved)
            step *= 0.5;
    }
    return best;
}

double gamut_nearest(const lab_space *ls, const double truth[3], double out[3])
{
    double lab[3], clip[3], scaled[3], top = 0.0, d_clip, d_scaled;
    int ch;
    lab_space_lab(ls, truth, lab);
    for (ch = 0; ch < 3; ch++) {
        clip[ch] = truth[ch] < 0.0 ? 0.0 : (truth[ch] > 1.0 ? 1.0 : truth[ch]);
        top = truth[ch] > top ? truth[ch] : top;
    }
    for (ch = 0; ch < 3; ch++) {
        scaled[ch] = top > 1.0 ? truth[ch] / top : truth[ch];
        scaled[ch] = scaled[ch] < 0.0 ? 0.0 : scaled[ch];
    }
    d_clip = search_box(ls, lab, clip);
    d_scaled = search_box(ls, lab, scaled);
    memcpy(out, d_scaled < d_clip ? scaled : clip, 3 * sizeof *out);
    return d_scaled < d_clip ? d_scaled : d_clip;
}

int gamut_contains(const double rgb[3])
{
    int ch;
    for (ch = 0; ch < 3; ch++)
        if (!(rgb[ch] >= -GAMUT_TOLERANCE && rgb[ch] <= 1.0 + GAMUT_TOLERANCE))
            return 0;
    return 1;
}

static double node_cos(int k)
{
    return k == GAMUT_NODES - 1 ? 0.0 : cos(k * (90.0 / (GAMUT_NODES - 1)) * deg);
}

void gamut_map_build(const spectrum *s, const gen_context *g, material_params *p)
{
    lab_space ls;
    int k, ch;
    p->gamut_mapped = 0;
    if (g->gamut != GAMUT_MAP)
        return;
    lab_space_init(&ls, &g->cs);
    for (k = 0; k < GAMUT_NODES; k++) {
        double truth[3], near[3];
        ground_truth(s, &g->cm, &g->cs, p->n1, node_cos(k), truth);
        if (gamut_contains(truth)) {
            p->gamut_shift[k][0] = p->gamut_shift[k][1] = p->gamut_shift[k][2] = 0.0;
            continue;
        }
        gamut_nearest(&ls, truth, near);
        for (ch = 0; ch < 3; ch++)
            p->gamut_shift[k][ch] = near[ch] - truth[ch];
        p->gamut_mapped = 1;
    }
}

void ground_truth_gamut(const spectrum *s, const gen_context *g, const material_params *p, double c,
                        double rgb[3])
{
    int ch;
    ground_truth(s, &g->cm, &g->cs, p->n1, c, rgb);
    if (g->gamut == GAMUT_MAP && p->gamut_mapped) {
        double th = acos(c < 0.0 ? 0.0 : (c > 1.0 ? 1.0 : c)) / deg * ((GAMUT_NODES - 1) / 90.0), t;
        int j = (int)th, q[4], i;
        if (j > GAMUT_NODES - 2)
            j = GAMUT_NODES - 2;
        t = th - j;
        for (i = 0; i < 4; i++) {
            int n = j - 1 + i;
            q[i] = n < 0 ? 0 : (n > GAMUT_NODES - 1 ? GAMUT_NODES - 1 : n);
        }
        for (ch = 0; ch < 3; ch++) {
            double p0 = p->gamut_shift[q[0]][ch], p1 = p->gamut_shift[q[1]][ch], p2 = p->gamut_shift[q[2]][ch],
                   p3 = p->gamut_shift[q[3]][ch];
            rgb[ch] += p1 + 0.5 * t * (p2 - p0 + t * (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3 +
                                                      t * (3.0 * (p1 - p2) + p3 - p0)));
        }
    }
    for (ch = 0; ch < 3; ch++) {
        if (rgb[ch] < 0.0)
            rgb[ch] = 0.0;
        else if (rgb[ch] > 1.0 && (g->gamut != GAMUT_KEEP || rgb[ch] <= 1.0 + GAMUT_TOLERANCE))
            rgb[ch] = 1.0;
    }
}
