/* The peers' algorithms (gen/bench/peers.h) as out-of-line functions, each
 * compiled in this translation unit only, so that a loop calling them, like
 * a loop calling the runtime's functions, cannot inline them or hoist the
 * material's constants (see bench_compare.h). */
#include "bench/bench_compare.h"

#include "bench/peers.h"

float cmp_mitsuba_conductor(float eta, float kappa, float c) { return peer_mitsuba_conductor(eta, kappa, c); }

float cmp_pbrt_conductor(float eta, float kappa, float c) { return peer_pbrt_conductor(eta, kappa, c); }
