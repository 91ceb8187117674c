/* Fuzzes the scene manifest parser (gen/scene/scene.c).
 *
 * Oracle, for any bytes as a manifest:
 *   - no crash, no sanitizer report, no leak;
 *   - scene_load either succeeds, prints nothing, and returns a scene that
 *     keeps every rule of gen/scene/scene.h (required keys set, ids [a-z0-9_]+ of
 *     at most 31 characters, no duplicates, known models, types, space and
 *     spacing, sigma and n1 in range); or returns CLI_BAD_INPUT with exactly
 *     one message "path:N: ..." naming a line of the file. */
#include "fuzz_parser.h"

#include "common/cli.h"
#include "scene/scene.h"
#include "1_spectral/spectral.h"

static scene sc;

static int in_table(const char *const *table, const char *s)
{
    int i;
    for (i = 0; table[i]; i++)
        if (!strcmp(table[i], s))
            return 1;
    return 0;
}

static int valid_id(const char *id)
{
    size_t len = strlen(id);
    return len >= 1 && len <= 31 && strspn(id, "abcdefghijklmnopqrstuvwxyz0123456789_") == len;
}

static void check_scene(const scene *s)
{
    int i, j;
    if (!(s->materials_line > 0 && s->models_line > 0))
        FUZZ_FAIL("accepted without materials (line %d) or models (line %d)", s->materials_line,
                  s->models_line);
    if (!(s->material_count >= 1 && s->material_count <= SCENE_MAX_MATERIALS))
        FUZZ_FAIL("material_count %d", s->material_count);
    if (!(s->model_count >= 1 && s->model_count <= SCENE_MAX_MODELS))
        FUZZ_FAIL("model_count %d", s->model_count);
    if (!(s->type_count >= 1 && s->type_count <= NUMBER_TYPES))
        FUZZ_FAIL("type_count %d", s->type_count);
    for (i = 0; i < s->material_count && i < SCENE_MAX_MATERIALS; i++) {
        if (memchr(s->materials[i], '\0', SCENE_ID_SIZE) == NULL || !valid_id(s->materials[i]))
            FUZZ_FAIL("material %d: bad id '%.40s'", i, s->materials[i]);
        for (j = 0; j < i; j++)
            if (!strcmp(s->materials[i], s->materials[j]))
                FUZZ_FAIL("material '%s' accepted twice", s->materials[i]);
    }
    for (i = 0; i < s->model_count && i < SCENE_MAX_MODELS; i++) {
        const scene_entry *e = &s->models[i];
        scene_entry again;
        if (memchr(e->name, '\0', SCENE_NAME_SIZE) == NULL || scene_entry_parse(e->name, s->spacing, &again) ||
            again.row != e->row || again.lut_n != e->lut_n || strcmp(again.ident, e->ident))
            FUZZ_FAIL("model %d: '%.30s' unknown or typed wrongly", i, e->name);
        for (j = 0; j < i; j++)
            if (!strcmp(e->name, s->models[j].name))
                FUZZ_FAIL("model '%s' accepted twice", e->name);
    }
    for (i = 0; i < s->type_count && i < NUMBER_TYPES; i++)
        if (!((unsigned)s->types[i] < NUMBER_TYPES) ||
            number_type_parse(number_type_catalog[s->types[i]].name) != (int)s->types[i] ||
            !number_type_catalog[s->types[i]].available)
            FUZZ_FAIL("type %d: not an available row of the number type catalog", i);
    if (memchr(s->space, '\0', SCENE_NAME_SIZE) == NULL || !in_table(colour_space_ids, s->space))
        FUZZ_FAIL("unknown space accepted");
    if (!((unsigned)s->spacing <= LUT_GRAZING_PL) || !((unsigned)s->gamut <= GAMUT_KEEP))
        FUZZ_FAIL("LUT spacing %d or gamut policy %d out of range", (int)s->spacing, (int)s->gamut);
    if (!(s->sigma >= 0.0 && s->sigma <= 200.0))
        FUZZ_FAIL("sigma %g accepted", s->sigma);
    if (!(s->n1 >= 1.0 && s->n1 <= 4.0))
        FUZZ_FAIL("n1 %g accepted", s->n1);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char path[512];
    fuzz_capture cap;
    int rc;
    snprintf(path, sizeof path, "%s/s.scene", fuzz_scratch_dir());
    fuzz_write_file(path, data, size);
    fuzz_capture_begin(&cap);
    rc = scene_load(path, &sc);
    fuzz_capture_end(&cap);
    if (rc == 0) {
        if (cap.len)
            FUZZ_FAIL("scene_load succeeded but printed '%.200s'", cap.text);
        check_scene(&sc);
    } else {
        if (rc != CLI_BAD_INPUT)
            FUZZ_FAIL("scene_load returned %d, expected 0 or CLI_BAD_INPUT", rc);
        /* One message per bad line: every message names the file and a line. */
        const char *msg = cap.text;
        int ok = cap.text != NULL && fuzz_lines(cap.text, cap.len) >= 1;
        while (ok && msg && *msg) {
            const char *nl = strchr(msg, '\n');
            ok = fuzz_message_names_line(msg, path, data, size);
            msg = nl ? nl + 1 : NULL;
        }
        if (!ok)
            FUZZ_FAIL("scene_load rejection with a message that names no 'path:line:': '%.300s'",
                      cap.text ? cap.text : "");
    }
    free(cap.text);
    return 0;
}
