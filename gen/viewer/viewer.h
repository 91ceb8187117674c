/* `fresnel viewer` (viewer.c): a scene as one self-contained HTML page that
 * renders its materials with each of its models beside the spectral
 * reference, in WebGL 2, through the GLSL port. */
#ifndef FRESNEL_VIEWER_H
#define FRESNEL_VIEWER_H

/* Nodes of the page's reference table, uniform in sqrt(c). */
#define VIEWER_REF_NODES 1024

/* A scene's thin film: the slider's thickness steps across the scene's
 * film_thickness range, the one the page starts at (and its probes use),
 * and the nodes (uniform in sqrt(c)) of the film's reference table per
 * material and step. */
#define VIEWER_FILM_STEPS 51
#define VIEWER_FILM_START 25
#define VIEWER_FILM_REF_NODES 128
struct scene;
double viewer_film_d(const struct scene *sc, int step);

/* Load the manifest, derive its materials and write OUT_DIR/index.html
 * (the directory is made if missing; the file written to a temporary and
 * renamed only on success). cross_path: a `make cross-count` output for the
 * Cortex-M0 costs, or NULL. 0, or a CLI_* status after a message. */
int viewer_write(const char *manifest, const char *out_dir, const char *dir_option, const char *cross_path);

#endif
