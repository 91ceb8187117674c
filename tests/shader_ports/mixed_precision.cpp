// The mediump contract of the shader ports, measured on the host: the
// mediump-safe functions of ports/glsl/fresnel.glsl (the one source of the
// GLSL, HLSL and MSL ports), compiled as C++ with their mediump values in
// a type whose every operation is done in binary16 or in binary32 as a
// policy says (tests/shader_ports/msl/metal_stdlib, FRESNEL_MSL_HOST_MIXED:
// literals take the precision of the other operand, as in GLSL). That is
// what a GPU may do with mediump (GLSL ES), min16float (HLSL), half under
// relaxed rules, or f16 where a compiler widens some operations: any mix,
// per operation, with or without binary16 subnormals flushed to zero; a
// product kept in binary32 and summed in binary16 is a fused multiply-add.
//
// Inputs: every binary16 cosine in [0, 1] and the material set of the
// binary16 tests (tests/common/materials.h) inside the binary16 domain
// (eta, kappa <= 16), each parameter rounded to binary16 as a mediump
// uniform holds it; against the double reference (gen/common/reference.c)
// on those rounded inputs. Policies: every operation binary16, with and
// without flushing; every one binary32; each at random (4 seeds, with and
// without flushing); then, for the 8 worst inputs of each function, an
// adversarial search: from every operation binary16, flip one operation's
// precision at a time and keep the flip when the error grows, two sweeps
// over the operations, with and without flushing.
//
// Asserted: every result in [0, 1] and the max over every policy within
// the function's FRESNEL_MP_BOUND_* (ports/glsl/fresnel.glsl, MEDIUMP
// CONTRACT). A GPU that flushes binary16 subnormals also flushes a cosine
// below 2^-14 to 0; the column "c >= 2^-14" is the max without those
// cosines, and shows which inputs need highp. The NOTE table lines are
// ports/glsl/README.md's.
//   build/tests/mixed_precision     (tests/shader_ports/test_mixed_precision.sh)
#include <metal_stdlib>

#include <cmath>
#include <cstdio>
#include <cstring>

namespace port {
#include "fresnel.metal"
}

extern "C" {
#include "common/reference.h"
#include "harness.h"
#include "materials.h"
}

metal::mix_policy metal::mix;

using metal::half;

namespace {

const int NC = 15361; // binary16 cosines 0x0000 .. 0x3c00

float half_at(int bits)
{
    // every binary16 in [0, 1] from its bits: sign 0, exponent, fraction
    int e = bits >> 10, f = bits & 1023;
    return e == 0 ? (float)std::ldexp((double)f, -24) : (float)std::ldexp(1.0 + f / 1024.0, e - 15);
}

float to_half(double x) { return metal::round_to_half((float)x); }

// One function's inputs for one material and one cosine, binary16 values.
struct inputs {
    float n, k, f0, f82, a, alpha, eta_e, c;
};

struct func {
    const char *name;
    double bound; // FRESNEL_MP_BOUND_*
    int uses_c;   // 0: a function of the material alone (one evaluation per material)
    double (*port)(const inputs &x);
    double (*ref)(const inputs &x);
};

double p_schlick(const inputs &x) { return port::fresnel_schlick(half(x.f0), half(x.c)); }
double r_schlick(const inputs &x) { return ref_schlick(x.f0, x.c); }
double p_gen5(const inputs &x) { return port::fresnel_schlick_gen(half(x.f0), half(1.0f), half(5.0f), half(x.c)); }
double r_gen5(const inputs &x) { return ref_schlick_gen(x.f0, 1.0, 5.0, x.c); }
double p_gen25(const inputs &x) { return port::fresnel_schlick_gen(half(x.f0), half(1.0f), half(2.5f), half(x.c)); }
double r_gen25(const inputs &x) { return ref_schlick_gen(x.f0, 1.0, 2.5, x.c); }
double p_f82(const inputs &x) { return port::fresnel_f82(half(x.f0), half(x.f82), half(x.c)); }
double r_f82(const inputs &x) { return ref_f82(x.f0, x.f82, x.c); }
double p_lsk(const inputs &x) { return port::fresnel_lsk(half(x.n), half(x.k), half(x.c)); }
double r_lsk(const inputs &x) { return ref_lsk(x.n, x.k, x.c); }
double p_lsk_comp(const inputs &x)
{
    return port::fresnel_lsk_comp(half(x.n), half(x.k), half(x.a), half(x.alpha), half(x.c));
}
double r_lsk_comp(const inputs &x) { return ref_lsk_comp(x.n, x.k, x.a, x.alpha, x.c); }
double p_approx(const inputs &x) { return port::fresnel_approx_conductor(half(x.n), half(x.k), half(x.c)); }
double r_approx(const inputs &x) { return ref_approx_conductor(x.n, x.k, x.c); }
double p_f0_ior(const inputs &x) { return port::fresnel_f0_from_ior(half(x.n), half(x.k)); }
double r_f0_ior(const inputs &x) { return ref_f0_from_ior(x.n, x.k); }
double p_f0_medium(const inputs &x) { return port::fresnel_f0_in_medium(half(x.f0), half(x.eta_e)); }
double r_f0_medium(const inputs &x) { return ref_f0_in_medium(x.f0, x.eta_e); }

const func funcs[] = {
    {"fresnel_schlick", FRESNEL_MP_BOUND_SCHLICK, 1, p_schlick, r_schlick},
    {"fresnel_schlick_gen (p 5)", FRESNEL_MP_BOUND_SCHLICK_GEN, 1, p_gen5, r_gen5},
    {"fresnel_schlick_gen (p 2.5)", FRESNEL_MP_BOUND_SCHLICK_GEN, 1, p_gen25, r_gen25},
    {"fresnel_f82", FRESNEL_MP_BOUND_F82, 1, p_f82, r_f82},
    {"fresnel_lsk", FRESNEL_MP_BOUND_LSK, 1, p_lsk, r_lsk},
    {"fresnel_lsk_comp", FRESNEL_MP_BOUND_LSK_COMP, 1, p_lsk_comp, r_lsk_comp},
    {"fresnel_approx_conductor", FRESNEL_MP_BOUND_APPROX_CONDUCTOR, 1, p_approx, r_approx},
    {"fresnel_f0_from_ior", FRESNEL_MP_BOUND_F0_FROM_IOR, 0, p_f0_ior, r_f0_ior},
    {"fresnel_f0_in_medium (etaE 1.33, 1.5, 2.4)", FRESNEL_MP_BOUND_F0_IN_MEDIUM, 0, p_f0_medium, r_f0_medium},
};
const int NFUNC = (int)(sizeof funcs / sizeof funcs[0]);

// The policies of the measured columns.
enum { ALL16, ALL32, RANDOM, ADVERSARIAL, NCOL };

struct worst_input {
    double err;
    inputs x;
};

void set_policy(int mode, int ftz, uint64_t seed)
{
    metal::mix.mode = mode;
    metal::mix.ftz = ftz;
    metal::mix.state = seed;
    metal::mix.op = 0;
}

// |port - reference| under the current policy; *bad when the result is not
// a number in [0, 1].
double error_of(const func &f, const inputs &x, double ref, int *bad)
{
    double got;
    metal::mix.op = 0;
    got = f.port(x);
    if (!(got >= 0.0 && got <= 1.0))
        (*bad)++;
    return std::fabs(got - ref);
}

// The adversarial search on one input: a pattern of per-operation
// precisions (bit set: binary16), from all binary16, one flip at a time.
double adversarial(const func &f, const inputs &x, int ftz, int *bad)
{
    double ref = f.ref(x), best;
    int ops, sweep, i;
    set_policy(0, ftz, 0);
    f.port(x);
    ops = metal::mix.op < 128 ? metal::mix.op : 128;
    metal::mix.mode = 3;
    metal::mix.pattern[0] = metal::mix.pattern[1] = ~(uint64_t)0;
    best = error_of(f, x, ref, bad);
    for (sweep = 0; sweep < 2; sweep++)
        for (i = 0; i < ops; i++) {
            double e;
            metal::mix.pattern[i >> 6] ^= (uint64_t)1 << (i & 63);
            e = error_of(f, x, ref, bad);
            if (e > best)
                best = e;
            else
                metal::mix.pattern[i >> 6] ^= (uint64_t)1 << (i & 63);
        }
    return best;
}

} // namespace

int main()
{
    static test_material mats[TM_MAX];
    static const float eta_e[] = {1.33f, 1.5f, 2.4f};
    int nm = test_materials(mats), fi;
    if (nm < 0) {
        CHECK("mixed precision: the material set loads (data/)", 0, "cannot read data/");
        return harness_exit();
    }
    NOTE("table | function | binary16 | binary32 | random mix | adversarial mix | any mix | any mix, c >= 2^-14 | FRESNEL_MP_BOUND |");
    for (fi = 0; fi < NFUNC; fi++) {
        const func &f = funcs[fi];
        double col[NCOL] = {0, 0, 0, 0}, normal = 0.0; /* normal: c >= 2^-14 */
        worst_input top[8];
        int ntop = 0, bad = 0, mi, ci, ei, mode, ftz, s, inputs_n = 0;
        std::memset(top, 0, sizeof top);
        for (mi = 0; mi < nm; mi++) {
            const test_material &t = mats[mi];
            inputs x;
            double a, alpha;
            if (!(t.eta >= FRESNEL_ETA_MIN && t.eta <= 16.0 && t.kappa <= 16.0))
                continue;
            x.n = to_half(t.eta);
            x.k = to_half(t.kappa);
            x.f0 = to_half(ref_f0_from_ior(x.n, x.k));
            x.f82 = to_half(ref_conductor(x.n, x.k, 1.0 / 7.0));
            ref_lsk_fit(x.n, x.k, &a, &alpha);
            x.a = to_half(a);
            x.alpha = to_half(alpha);
            for (ei = 0; ei < (f.uses_c ? 1 : 3); ei++)
                for (ci = 0; ci < (f.uses_c ? NC : 1); ci++) {
                    double ref, worst = 0.0;
                    x.eta_e = to_half(eta_e[ei]);
                    x.c = half_at(ci);
                    ref = f.ref(x);
                    inputs_n++;
                    for (mode = 0; mode < 3; mode++)
                        for (ftz = 0; ftz < 2; ftz++)
                            for (s = 0; s < (mode == 2 ? 4 : 1); s++) {
                                double e;
                                if (mode == 1 && ftz)
                                    continue; // no binary16 value to flush
                                set_policy(mode, ftz, 0x9e3779b97f4a7c15ull * (uint64_t)(s + 1) + (uint64_t)ci);
                                e = error_of(f, x, ref, &bad);
                                if (e > col[mode])
                                    col[mode] = e;
                                if (e > worst)
                                    worst = e;
                                if (e > normal && (!f.uses_c || x.c >= 6.103515625e-05f))
                                    normal = e;
                            }
                    // keep the 8 worst inputs for the adversarial search
                    if (ntop < 8 || worst > top[ntop - 1].err) {
                        int k = ntop < 8 ? ntop++ : 7;
                        while (k > 0 && top[k - 1].err < worst) {
                            top[k] = top[k - 1];
                            k--;
                        }
                        top[k].err = worst;
                        top[k].x = x;
                    }
                }
        }
        for (mi = 0; mi < ntop; mi++)
            for (ftz = 0; ftz < 2; ftz++) {
                double e = adversarial(f, top[mi].x, ftz, &bad);
                if (e > col[ADVERSARIAL])
                    col[ADVERSARIAL] = e;
                if (e > normal && (!f.uses_c || top[mi].x.c >= 6.103515625e-05f))
                    normal = e;
            }
        {
            double any = col[0];
            char name[200];
            for (mode = 1; mode < NCOL; mode++)
                any = col[mode] > any ? col[mode] : any;
            std::snprintf(name, sizeof name, "mixed precision: %s, %d inputs, any mix of binary16 and binary32 per operation",
                          f.name, inputs_n);
            NOTE("table | %s | %.2g | %.2g | %.2g | %.2g | %.3g | %.3g | %.2g |", f.name, col[ALL16], col[ALL32],
                 col[RANDOM], col[ADVERSARIAL], any, normal, f.bound);
            CHECK(name, bad == 0 && any <= f.bound, "max error %.3g (FRESNEL_MP_BOUND %.3g), %d results not in [0, 1]",
                  any, f.bound, bad);
            // the policies are what they say: binary16 throughout is an
            // order of magnitude off where binary32 throughout is not
            std::snprintf(name, sizeof name, "mixed precision: %s: the binary16 policy rounds, the binary32 one does not",
                          f.name);
            CHECK(name, col[ALL16] > 1e-4 && col[ALL32] < 1e-5, "binary16 %.3g, binary32 %.3g", col[ALL16], col[ALL32]);
        }
    }
    return harness_exit();
}
