/* Black-box eta, kappa fit (see fit.h).
 *
 * The cost is a sum of squared residuals of a smooth two-parameter curve, so
 * a damped Gauss-Newton search (Levenberg-Marquardt) converges quadratically
 * wherever the target is reachable: a handful of iterations to round-off,
 * where Nelder-Mead needs hundreds of evaluations for the same precision.
 * Its weakness, settling in whichever basin it starts in, is covered by
 * starting it from the best local minima of a coarse grid over the range
 * real materials occupy.
 *
 * Parameters: log eta, since eta must stay positive and the curve responds
 * to its relative changes; and q = kappa^2, because reflectance is an even
 * function of kappa: near kappa = 0 (outside total reflection) it is linear
 * in q with a nonzero slope, so the dielectric edge q = 0 is an ordinary
 * bound that the search can reach exactly, stop on, or leave for a weak
 * absorber. (In log kappa that region is flat, and a search that wandered
 * into it stalled there.)
 *
 * The one place this is not enough is kappa = 0 with eta < 1, where total
 * reflection makes the cost kinked and full of narrow valleys; that edge
 * gets its own derivative-free search (fit_dielectric). */
#include "2_derive/fit.h"

#include <math.h>
#include <stddef.h>
#include <stdlib.h>

#include "common/reference.h"

/* Coarse grid: eta log-spaced over GRID_ETA_LO..HI, kappa 0 plus log-spaced
 * over GRID_KAPPA_LO..HI. Wider than metals' usual [0.05, 5] x [0, 10] so
 * that silver-like blues, metals seen from a dense medium (indices divided
 * by n1 up to 4) and high-index dielectrics start inside their basin rather
 * than at its rim. */
#define GRID_ETA 16
#define GRID_KAPPA 16
#define GRID_ETA_LO 0.02
#define GRID_ETA_HI 10.0
#define GRID_KAPPA_LO 0.01
#define GRID_KAPPA_HI 20.0

#define MAX_STARTS 4
#define MAX_ITERATIONS 100
/* Central differences, relative step: truncation ~ step^2 and cancellation
 * ~ 1e-16 / step both stay near 1e-10 relative, far below what moves the
 * converged point of a zero-residual fit. Q_SCALE_MIN keeps the q step
 * finite at q = 0. */
#define DIFF_STEP 1e-5
#define Q_SCALE_MIN 1e-3
/* Trust limits per iteration, so that one bad linearisation cannot throw the
 * search across the box: eta by at most a factor e^2, q by at most
 * 4 (q + 1). */
#define MAX_LOG_ETA_STEP 2.0
#define MAX_Q_STEP_FACTOR 4.0
#define CONVERGED_STEP 1e-12
/* Bracket width where golden-section hands over to the polish. */
#define GOLDEN_TOLERANCE 1e-7
/* Dielectric edge: at most this many intervals between total-reflection
 * breakpoints are scanned (3 points each), plus this many log-spaced points
 * above eta = 1; the best DIELECTRIC_KEEP are searched further. */
#define DIELECTRIC_INTERVALS 128
#define DIELECTRIC_ABOVE_ONE 40
#define DIELECTRIC_KEEP 3

typedef struct problem {
    const double *c, *t, *w; /* w: per-sample weights, or NULL for 1 */
    int n;
    double lo[2], hi[2]; /* bounds of log eta and q = kappa^2 */
    long evaluations;
    int iterations;
    int starts;
} problem;

static double weight(const problem *pb, int i) { return pb->w ? pb->w[i] : 1.0; }

static double sum_sq(problem *pb, const double p[2])
{
    double s = 0.0, eta = exp(p[0]), kappa = sqrt(p[1]);
    int i;
    for (i = 0; i < pb->n; i++) {
        double d = (ref_conductor(eta, kappa, pb->c[i]) - pb->t[i]) * weight(pb, i);
        s += d * d;
    }
    pb->evaluations += pb->n;
    return s;
}

static double clamp(double x, double lo, double hi)
{
    return x < lo ? lo : x > hi ? hi : x;
}

/* Levenberg-Marquardt from p = (log eta, kappa^2) within the box; a
 * parameter on a bound that the gradient pushes outwards is held there
 * (active set) while the other one moves. Leaves the best point found in p
 * and returns its cost. */
static double refine(problem *pb, double p[2])
{
    double lambda = 1e-3, cost = sum_sq(pb, p);
    int it, i;
    pb->starts++;
    for (it = 0; it < MAX_ITERATIONS && cost > 0.0; it++) {
        double a00 = 0.0, a01 = 0.0, a11 = 0.0, g0 = 0.0, g1 = 0.0, trace;
        double eta = exp(p[0]), kappa = sqrt(p[1]);
        double eta_up = exp(p[0] + DIFF_STEP), eta_down = exp(p[0] - DIFF_STEP);
        double hq = DIFF_STEP * fmax(p[1], Q_SCALE_MIN);
        /* At q < hq the central difference would need kappa^2 < 0, so there
         * the second probe goes to q + 2 hq for the one-sided formula. */
        int central = p[1] >= hq;
        double kappa_up = sqrt(p[1] + hq);
        double kappa_other = sqrt(central ? p[1] - hq : p[1] + 2.0 * hq);
        double step[2] = {0.0, 0.0};
        int free0, free1;

        pb->iterations++;
        for (i = 0; i < pb->n; i++) {
            double c = pb->c[i];
            double here = ref_conductor(eta, kappa, c);
            double d0 = (ref_conductor(eta_up, kappa, c) - ref_conductor(eta_down, kappa, c)) /
                        (2.0 * DIFF_STEP);
            double up = ref_conductor(eta, kappa_up, c);
            double other = ref_conductor(eta, kappa_other, c);
            double d1 = (central ? up - other : 4.0 * up - 3.0 * here - other) / (2.0 * hq);
            double r = (here - pb->t[i]) * weight(pb, i);
            d0 *= weight(pb, i);
            d1 *= weight(pb, i);
            a00 += d0 * d0;
            a01 += d0 * d1;
            a11 += d1 * d1;
            g0 += d0 * r;
            g1 += d1 * r;
        }
        pb->evaluations += 5L * pb->n;
        trace = a00 + a11;
        free0 = !((p[0] <= pb->lo[0] && g0 > 0.0) || (p[0] >= pb->hi[0] && g0 < 0.0));
        free1 = !((p[1] <= pb->lo[1] && g1 > 0.0) || (p[1] >= pb->hi[1] && g1 < 0.0));
        if (!free0)
            g0 = 0.0;
        if (!free1)
            g1 = 0.0;
        if (!(trace > 0.0) || (g0 == 0.0 && g1 == 0.0))
            break; /* stationary, flat (the model clamped), or held in a corner */

        for (;;) {
            /* Marquardt's scaling by the diagonal, floored so a direction the
             * curve hardly feels still gets a finite, damped step. */
            double d00 = a00 + lambda * fmax(a00, 1e-12 * trace);
            double d11 = a11 + lambda * fmax(a11, 1e-12 * trace);
            double det = d00 * d11 - a01 * a01, trial[2], trial_cost, scale = 1.0, q_limit;
            if (free0 && free1) {
                step[0] = det > 0.0 ? (-g0 * d11 + g1 * a01) / det : NAN;
                step[1] = det > 0.0 ? (-g1 * d00 + g0 * a01) / det : NAN;
            } else {
                step[0] = free0 ? -g0 / d00 : 0.0;
                step[1] = free1 ? -g1 / d11 : 0.0;
            }
            if (isfinite(step[0]) && isfinite(step[1])) {
                q_limit = MAX_Q_STEP_FACTOR * (p[1] + 1.0);
                if (fabs(step[0]) > MAX_LOG_ETA_STEP)
                    scale = MAX_LOG_ETA_STEP / fabs(step[0]);
                if (fabs(step[1]) * scale > q_limit)
                    scale = q_limit / fabs(step[1]);
                trial[0] = clamp(p[0] + scale * step[0], pb->lo[0], pb->hi[0]);
                trial[1] = clamp(p[1] + scale * step[1], pb->lo[1], pb->hi[1]);
                step[0] = trial[0] - p[0];
                step[1] = trial[1] - p[1];
                if (step[0] == 0.0 && step[1] == 0.0)
                    return cost; /* pressed against the box */
                trial_cost = sum_sq(pb, trial);
                if (trial_cost < cost) {
                    p[0] = trial[0];
                    p[1] = trial[1];
                    cost = trial_cost;
                    lambda = fmax(lambda * 0.3, 1e-12);
                    break;
                }
            }
            lambda *= 4.0;
            if (lambda > 1e10)
                return cost; /* no descent left at this precision: converged */
        }
        if (fabs(step[0]) < CONVERGED_STEP &&
            fabs(step[1]) < CONVERGED_STEP * fmax(p[1], Q_SCALE_MIN))
            break;
    }
    return cost;
}

static double grid_eta(int j)
{
    return GRID_ETA_LO * pow(GRID_ETA_HI / GRID_ETA_LO, (double)j / (GRID_ETA - 1));
}

/* Row 0 is kappa = 0; rows 1..GRID_KAPPA are log-spaced. */
static double grid_kappa(int row)
{
    if (row == 0)
        return 0.0;
    return GRID_KAPPA_LO * pow(GRID_KAPPA_HI / GRID_KAPPA_LO, (double)(row - 1) / (GRID_KAPPA - 1));
}

/* Local minima of the grid (no neighbour lower), best first, at most `max`;
 * ties go to the earlier cell so the choice is deterministic. */
static int grid_starts(const double cost[GRID_KAPPA + 1][GRID_ETA], int rows[], int cols[],
                       int max)
{
    int taken[GRID_KAPPA + 1][GRID_ETA] = {{0}};
    int count = 0;
    while (count < max) {
        int best_r = -1, best_c = -1, r, c;
        for (r = 0; r <= GRID_KAPPA; r++)
            for (c = 0; c < GRID_ETA; c++) {
                int dr, dc, is_min = 1;
                if (taken[r][c] || (best_r >= 0 && !(cost[r][c] < cost[best_r][best_c])))
                    continue;
                for (dr = -1; dr <= 1 && is_min; dr++)
                    for (dc = -1; dc <= 1 && is_min; dc++) {
                        int nr = r + dr, nc = c + dc;
                        if (nr >= 0 && nr <= GRID_KAPPA && nc >= 0 && nc < GRID_ETA &&
                            cost[nr][nc] < cost[r][c])
                            is_min = 0;
                    }
                if (is_min) {
                    best_r = r;
                    best_c = c;
                }
            }
        if (best_r < 0)
            break;
        taken[best_r][best_c] = 1;
        rows[count] = best_r;
        cols[count] = best_c;
        count++;
    }
    return count;
}

/* Refine from (log eta, q) and keep the result if it beats best[]. */
static void try_start(problem *pb, double log_eta, double q, double best[3])
{
    double p[2], got;
    p[0] = log_eta;
    p[1] = q;
    got = refine(pb, p);
    if (got < best[0]) {
        best[0] = got;
        best[1] = exp(p[0]);
        best[2] = sqrt(p[1]);
    }
}

/* A map from a search variable u to eta on the dielectric edge: log eta
 * above 1, and eta = a + (b - a) u^2 inside one interval between
 * total-reflection breakpoints below 1, which straightens the square-root
 * edge a sample makes as it leaves total reflection at eta = a. */
typedef struct eta_map {
    int squared;
    double a, b;
} eta_map;

static double map_eta(const eta_map *m, double u)
{
    return m->squared ? m->a + (m->b - m->a) * u * u : exp(u);
}

static double dielectric_cost(problem *pb, const eta_map *m, double u)
{
    double p[2];
    p[0] = log(map_eta(m, u));
    p[1] = 0.0;
    return sum_sq(pb, p);
}

/* Golden-section search of the kappa = 0 cost over u in [lo, hi]; returns
 * log eta of the best point seen. Derivative-free, so the steep edges that
 * catch Gauss-Newton do not stop it. */
static double golden(problem *pb, const eta_map *m, double lo, double hi)
{
    const double shrink = 0.6180339887498949; /* (sqrt 5 - 1) / 2 */
    double x1 = hi - shrink * (hi - lo), x2 = lo + shrink * (hi - lo);
    double f1 = dielectric_cost(pb, m, x1), f2 = dielectric_cost(pb, m, x2);
    while (hi - lo > GOLDEN_TOLERANCE) {
        if (f1 <= f2) {
            hi = x2;
            x2 = x1;
            f2 = f1;
            x1 = hi - shrink * (hi - lo);
            f1 = dielectric_cost(pb, m, x1);
        } else {
            lo = x1;
            x1 = x2;
            f1 = f2;
            x2 = lo + shrink * (hi - lo);
            f2 = dielectric_cost(pb, m, x2);
        }
    }
    return log(map_eta(m, f1 <= f2 ? x1 : x2));
}

/* The best DIELECTRIC_KEEP scan points, best first. */
typedef struct scan_point {
    double cost, u, lo, hi; /* u and the bracket around it */
    eta_map map;
} scan_point;

static void scan_offer(scan_point kept[], const scan_point *candidate)
{
    int i, j;
    for (i = 0; i < DIELECTRIC_KEEP; i++)
        if (candidate->cost < kept[i].cost) {
            for (j = DIELECTRIC_KEEP - 1; j > i; j--)
                kept[j] = kept[j - 1];
            kept[i] = *candidate;
            return;
        }
}

static int compare_double(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return a < b ? -1 : a > b;
}

/* kappa = 0 searched on its own. Below eta = 1 the cost has a kink, and
 * often a narrow valley, wherever the critical angle crosses a sample
 * (eta = sin theta_i), with secondary minima in between, so a grid of any
 * fixed spacing misses the answer for some targets. Each interval between
 * consecutive breakpoints is smooth; a few points in each find the right
 * one, golden-section finds the minimum in it, and refine() polishes (and
 * may leave kappa = 0 if a little absorption fits better). Above 1 there is
 * no total reflection and a log scan suffices. (Known miss: eta below about
 * 0.13 with the critical angle a few hundredths of a degree past a sample,
 * whose valley is narrower than the scan; no real material is there. If
 * malloc fails only the scan above 1 runs.) */
static void fit_dielectric(problem *pb, double best[3])
{
    scan_point kept[DIELECTRIC_KEEP], point;
    double *edges = malloc(((size_t)pb->n + 2) * sizeof *edges);
    int count = 0, i, j, stride;
    for (i = 0; i < DIELECTRIC_KEEP; i++)
        kept[i].cost = INFINITY;

    if (edges != NULL) {
        edges[count++] = FIT_ETA_MIN;
        edges[count++] = 1.0;
        for (i = 0; i < pb->n; i++) {
            double c = pb->c[i];
            if (c > 0.0 && c < 1.0 && sqrt((1.0 - c) * (1.0 + c)) > FIT_ETA_MIN)
                edges[count++] = sqrt((1.0 - c) * (1.0 + c));
        }
        qsort(edges, (size_t)count, sizeof *edges, compare_double);
        /* Many samples: merge intervals to bound the scan at
         * DIELECTRIC_INTERVALS x 3 cost evaluations. */
        stride = (count + DIELECTRIC_INTERVALS - 1) / DIELECTRIC_INTERVALS;
        for (i = 0; i + 1 < count; i += stride) {
            int next = i + stride < count ? i + stride : count - 1;
            if (!(edges[next] > edges[i]))
                continue;
            point.map.squared = 1;
            point.map.a = edges[i];
            point.map.b = edges[next];
            for (j = 0; j < 3; j++) {
                point.u = (j + 0.5) / 3.0;
                point.lo = j / 3.0;
                point.hi = (j + 1.0) / 3.0;
                point.cost = dielectric_cost(pb, &point.map, point.u);
                scan_offer(kept, &point);
            }
        }
        free(edges);
    }

    point.map.squared = 0;
    point.map.a = point.map.b = 0.0;
    for (j = 0; j < DIELECTRIC_ABOVE_ONE; j++) {
        double step = pb->hi[0] / DIELECTRIC_ABOVE_ONE;
        point.u = (j + 0.5) * step;
        point.lo = fmax(point.u - step, 0.0);
        point.hi = fmin(point.u + step, pb->hi[0]);
        point.cost = dielectric_cost(pb, &point.map, point.u);
        scan_offer(kept, &point);
    }

    for (i = 0; i < DIELECTRIC_KEEP && isfinite(kept[i].cost); i++) {
        double log_eta = golden(pb, &kept[i].map, kept[i].lo, kept[i].hi);
        try_start(pb, log_eta, 0.0, best);
    }
}

int fit_eta_kappa_weighted(const double *cos_theta, const double *target, const double *w, int n, double *eta,
                           double *kappa, fit_report *report)
{
    problem pb;
    double cost[GRID_KAPPA + 1][GRID_ETA];
    double best[3] = {INFINITY, 1.0, 0.0}; /* cost, eta, kappa */
    int rows[MAX_STARTS], cols[MAX_STARTS], starts, s, r, c;

    if (cos_theta == NULL || target == NULL || eta == NULL || kappa == NULL || n < 1)
        return -1;
    for (s = 0; s < n; s++)
        if (!isfinite(cos_theta[s]) || !isfinite(target[s]) || (w && !(w[s] > 0.0 && isfinite(w[s]))))
            return -1;

    pb.c = cos_theta;
    pb.t = target;
    pb.w = w;
    pb.n = n;
    pb.lo[0] = log(FIT_ETA_MIN);
    pb.hi[0] = log(FIT_ETA_MAX);
    pb.lo[1] = 0.0;
    pb.hi[1] = FIT_KAPPA_MAX * FIT_KAPPA_MAX;
    pb.evaluations = 0;
    pb.iterations = 0;
    pb.starts = 0;

    for (r = 0; r <= GRID_KAPPA; r++)
        for (c = 0; c < GRID_ETA; c++) {
            double p[2];
            p[0] = log(grid_eta(c));
            p[1] = grid_kappa(r) * grid_kappa(r);
            cost[r][c] = sum_sq(&pb, p);
        }

    fit_dielectric(&pb, best);
    starts = grid_starts((const double(*)[GRID_ETA])cost, rows, cols, MAX_STARTS);
    for (s = 0; s < starts; s++)
        try_start(&pb, log(grid_eta(cols[s])), grid_kappa(rows[s]) * grid_kappa(rows[s]), best);

    /* A kappa the curve cannot feel, one that moves the RMS by less than
     * reflectance round-off, is a dielectric's. */
    if (best[2] > 0.0) {
        double p[2], got;
        p[0] = log(best[1]);
        p[1] = 0.0;
        got = sum_sq(&pb, p);
        if (sqrt(got / n) - sqrt(best[0] / n) < 1e-15) {
            best[0] = got;
            best[2] = 0.0;
        }
    }

    *eta = best[1];
    *kappa = best[2];
    if (report) {
        double p[2];
        p[0] = log(best[1]);
        p[1] = best[2] * best[2];
        pb.w = NULL; /* the plain RMS, whatever the weights */
        report->rms = sqrt(sum_sq(&pb, p) / n);
        report->starts = pb.starts;
        report->iterations = pb.iterations;
        report->evaluations = pb.evaluations;
    }
    return 0;
}

int fit_eta_kappa_report(const double *cos_theta, const double *target, int n, double *eta, double *kappa,
                         fit_report *report)
{
    return fit_eta_kappa_weighted(cos_theta, target, NULL, n, eta, kappa, report);
}

int fit_eta_kappa(const double *cos_theta, const double *target, int n, double *eta,
                  double *kappa)
{
    return fit_eta_kappa_report(cos_theta, target, n, eta, kappa, NULL);
}
