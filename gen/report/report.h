/* `fresnel report`: every material x model x number type on accuracy, speed
 * and size. One file per part: report_accuracy.c measures,
 * report_plots.c draws, cmd_report.c runs and writes report.md. */
#ifndef FRESNEL_REPORT_H
#define FRESNEL_REPORT_H

#include <stdio.h>

#include "common/cli.h"
#include "1_spectral/colour_difference.h"
#include "2_derive/derive.h"
#include "model/number_type.h"
#include "scene/scene.h"
#include "model/encoded_scene.h"

#define REPORT_ANGLES 91 /* theta = 0, 1, ..., 90 degrees */
#define REPORT_MAX_TYPES 4
#define REPORT_HOFFMAN 14 /* metals in Hoffman's table */
#define REPORT_MAX_SPEED 8 /* --speed files: gcc and clang at each flag set, and more */

double report_cos(int angle); /* cos of angle degrees; exactly 0 at 90 */

typedef struct report_material {
    material_params p;
    spectrum *s;
    double gt[REPORT_ANGLES][3];     /* ground truth under the gamut policy: what models are measured against */
    double gt_raw[REPORT_ANGLES][3]; /* the unclipped spectral ground truth */
    int out_of_gamut;                /* gt_raw leaves the gamut at some angle (gamut_contains) */
    /* CIEDE2000 mean and max against gt_raw of each policy's own curve
     * (gamut_policy order: map, clip, keep). */
    double policy_de_mean[3], policy_de_max[3];
    scene_model *models;             /* one per report model: views of the encoded scene's (not freed) */
} report_material;

/* The report measures every available number type (model/number_type.h:
 * number_types[0 .. number_types_available - 1]). ns per RGB evaluation of
 * q in type t (bench.c): median of runs batches of n. */
double report_time(const number_type *t, const model_rgb *q, int n, int runs);
/* The Cortex-M0 mean instructions per call of row `name` in a `make
 * cross-count` output file; NaN when the file or the row is missing. */
double report_m0_count(const char *path, const char *name);

typedef struct report_cell {
    double de_mean, de_rms, de_max; /* CIEDE2000 against the ground truth under the gamut policy */
    double raw_de_mean, raw_de_max; /* CIEDE2000 against the unclipped ground truth */
    double abs_max[3];              /* max |model - GT| per channel */
    double vs_ref_max;              /* max |model in this type - same model in double| */
    double avg[3];                  /* the model's F_avg = 2 int F(mu) mu dmu in this type */
} report_cell;

/* The scene's thin-film model, measured over angle and thickness against
 * the film's spectral truth (report_film.c). */
typedef struct report_film_cell {
    double de_mean, de_max; /* CIEDE2000 against the truth held to [0, 1] */
    int worst_theta;        /* where de_max is: degrees, nm */
    double worst_d;
} report_film_cell;
/* The polarised peer's input sets (report_film.c names them). */
#define FILM_POLARISED_INPUTS 3

typedef struct report_film {
    int present;        /* the scene has the thin-film model */
    scene_entry entry;  /* its entry, taken out of the scene's models */
    int row;            /* its index in the encoded scene's models */
    double *film_n;     /* [material] the film's index */
    scene_model *models; /* [material]: views of the encoded scene's (not freed) */
    report_film_cell *cells; /* [material][type] */
    long samples;            /* angle x thickness samples per material */
    /* [material] the KHR_materials_iridescence peer's CIEDE2000 on the same
     * samples (ref_film_khr_iridescence, given the material's F0): mean,
     * max; measured where the scene's space is srgb (the peer's Rec. 709) */
    double *peer_mean, *peer_max;
    /* [input set][material] the polarised peer's (ref_film_belcour_polarised)
     * given each per-channel eta, kappa set the generator derives
     * (FILM_POLARISED_INPUTS, report_film.c) */
    double *pol_mean, *pol_max;
    /* CIEDE2000 summed over the materials by thickness band (quarters of the
     * scene's range) and angle band (FILM_ANGLE_BANDS, report_film.c), for
     * the binary32 film [0], the KHR peer [1] and the polarised one with its
     * best set [2 + set], and the samples per band */
    double band_de[2 + 3][4][4];
    long band_n[4][4];
    int peer_measured;
    double ns[NUMBER_TYPES], schlick_ns; /* ns per RGB evaluation; NaN when not timed */
} report_film;

/* One run of the report: the scene, its materials and every measurement. */
typedef struct report_run {
    const char *out_dir, *scene_path;
    scene full;         /* the scene as its manifest says (and --gamut), which es encodes */
    scene sc;           /* the models of angle alone: full without the thin-film row */
    encoded_scene es;
    gen_context *g;     /* es.g */
    lab_space ls;
    report_material *mats;
    report_cell *cells; /* [material][model][type] */
    double *ns;         /* [model][type] ns per RGB evaluation; NaN when not measured */
    double *instr;      /* [model][type] host instructions per RGB evaluation (callgrind); NaN when not measured */
    int timed_material; /* the material timings use */
    double hoffman_rms[REPORT_HOFFMAN][3]; /* ours in ACEScg: Schlick, fitted eta/kappa, point-sampled */
    int hoffman_in_gamut[REPORT_HOFFMAN];  /* F0 inside ACEScg, unclamped (gamut_contains) */
    const char *cross_path;                /* `make cross-count` output, or NULL */
    const char *size_path;                 /* `make size` output, or NULL */
    const char *spirv_path;                /* `make spirv-count` output, or NULL */
    /* `make bench` outputs (--speed FILE, one per flag set), already read */
    const char *speed_paths[REPORT_MAX_SPEED];
    const struct speed_file *speed[REPORT_MAX_SPEED];
    int speed_count;
    int timing;                            /* 0: --no-timing */
    report_film film;
    /* The files written so far, all committed together at the end:
     * report.md, pareto.svg, sigma.svg, one per material. */
    cli_outfile *out;
    int out_count, out_cap;
} report_run;
/* Opens DIR/name as the run's next output: its stream, or NULL after a
 * message (*status set). */
FILE *report_out_open(report_run *r, const char *name, int *status);

/* Hoffman's table [Hof20]: his 14 metals with our ids and his RMS CIEDE2000
 * columns (ACEScg). */
typedef struct report_hoffman_row {
    const char *id, *his_name;
    double schlick, fitted, point_sampled;
} report_hoffman_row;
extern const report_hoffman_row report_hoffman[REPORT_HOFFMAN];
/* Index of material id in the run, or -1. */
int report_material_index(const report_run *r, const char *id);
/* The project's targets for the library, each with its measured value and a
 * pass/miss mark: targets.md, the developers' file beside report.md
 * (report_targets.c). Needs hoffman_rms filled. */
void report_targets(report_run *r, FILE *f);

report_cell *report_cell_at(report_run *r, int mat, int model, int type);
int report_is_metal(const report_material *rm);
/* Mean over the scene's metals of each material's mean CIEDE2000, and the
 * worst max: what the summary and the Pareto plot show. */
void report_metal_summary(report_run *r, int model, int type, double *mean, double *worst);

#define REPORT_SIGMAS 4
extern const double report_sigmas[REPORT_SIGMAS]; /* 0, 12, 25, 50 nm */

/* The table of other renderers' metals (report_renderers.c). */
void report_renderers(report_run *r, FILE *f);

/* pareto.svg, sigma.svg, curves/<material>.svg (report_plots.c), opened
 * with report_out_open: 0 or a status. */
int report_plots(report_run *r, const double (*sigma_de)[REPORT_SIGMAS]);

/* Ground truth and the clamp's cost for one material. */
void report_ground_truth(const gen_context *g, const lab_space *ls, report_material *rm);
/* Accuracy of one prepared model in one type. */
void report_measure(const lab_space *ls, const report_material *rm, int model, const number_type *t,
                    report_cell *out);
/* Mean, RMS and max CIEDE2000 of a whole curve given per angle (rgb[REPORT_ANGLES][3]). */
void report_curve_de(const lab_space *ls, const double (*gt)[3], const double (*rgb)[3], double *mean,
                     double *rms, double *max);

/* report_film.c. take: after the scene is loaded, moves its thin-film model
 * out of sc.models into r->film (0, or CLI_BAD_INPUT after a message for a
 * scene whose only model it is); measure: after material
 * i is derived, prepares its film and measures it in every type; time: ns
 * per RGB evaluation and fresnel_schlick_rgb's, interleaved; write: the
 * report's section; free. Each does nothing for a scene without a film. */
int report_film_take(report_run *r, const char *scene_path);
int report_film_measure(report_run *r, int i);
void report_film_time(report_run *r);
void report_film_write(report_run *r, FILE *f);
void report_film_free(report_run *r);
/* The polarised peer's input set of least mean CIEDE2000 over the
 * materials (an index into pol_mean's sets): here, as the film's section
 * and the targets both read it. */
static inline int report_film_best_polarised(const report_film *f, int material_count)
{
    double mean[FILM_POLARISED_INPUTS] = {0};
    int best = 0, set, i;
    for (set = 0; set < FILM_POLARISED_INPUTS; set++) {
        for (i = 0; i < material_count; i++)
            mean[set] += f->pol_mean[set * material_count + i] / material_count;
        if (mean[set] < mean[best])
            best = set;
    }
    return best;
}

/* What `fresnel report` was asked for; report_write measures and writes it:
 * 0, or a CLI_* status after a message. */
typedef struct report_options {
    const char *scene_path, *out_dir, *data_dir; /* data_dir NULL: the default */
    const char *cross_path, *size_path;          /* `make cross-count`, `make size` output, or NULL */
    const char *spirv_path;                      /* `make spirv-count` output, or NULL */
    const char *speed_paths[REPORT_MAX_SPEED];   /* `make bench` outputs, read by report_write */
    int speed_count;
    int timing, instructions; /* 0: skip timing / callgrind counts */
    int gamut_given;          /* 1: gamut overrides the scene's key */
    gamut_policy gamut;
} report_options;
int report_write(const report_options *o);

#endif
