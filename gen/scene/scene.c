/* Scene manifest parser (format in scene.h). */
#include "scene/scene.h"

#include <ctype.h>
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>

#include "common/cli.h"
#include "1_spectral/spectral.h"
#include "fresnel_film.h"

const char *const scene_f_avg_names[] = {"no", "yes", NULL};

enum scene_key { KEY_MATERIALS, KEY_MODELS, KEY_SPACE, KEY_SIGMA, KEY_N1, KEY_TYPES,
                 KEY_LUT_SPACING, KEY_NAME, KEY_GAMUT, KEY_F_AVG, KEY_TARGETS, KEY_FILM, KEY_FILM_THICKNESS,
                 KEY_COUNT };
static const char *const key_names[] = {"materials", "models", "space",       "sigma", "n1",
                                        "types",     "lut_spacing", "name", "gamut", "f_avg", "targets",
                                        "film", "film_thickness", NULL};

#define SIGMA_MAX 200.0
#define SCENE_MAX_ERRORS 50
#define N1_MIN 1.0
#define N1_MAX 4.0
#define FILM_N_MAX 4.0

static int *key_line(scene *s, int key)
{
    switch (key) {
    case KEY_MATERIALS: return &s->materials_line;
    case KEY_MODELS: return &s->models_line;
    case KEY_SPACE: return &s->space_line;
    case KEY_SIGMA: return &s->sigma_line;
    case KEY_N1: return &s->n1_line;
    case KEY_TYPES: return &s->types_line;
    case KEY_NAME: return &s->name_line;
    case KEY_GAMUT: return &s->gamut_line;
    case KEY_F_AVG: return &s->f_avg_line;
    case KEY_TARGETS: return &s->targets_line;
    case KEY_FILM: return &s->film_line;
    case KEY_FILM_THICKNESS: return &s->film_thickness_line;
    default: return &s->lut_spacing_line;
    }
}

/* Messages echo whole user values, so neither part has a fixed length bound;
 * both are sized with a measuring vsnprintf before cli_error prints them. */
static int report(const char *path, int line, const char *fmt, ...)
{
    va_list ap;
    int len, where_len;
    char *msg, *where;
    va_start(ap, fmt);
    len = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    where_len = line > 0 ? snprintf(NULL, 0, "%s:%d", path, line) : (int)strlen(path);
    msg = malloc((size_t)(len > 0 ? len : 0) + 1);
    where = malloc((size_t)where_len + 1);
    if (msg == NULL || where == NULL) {
        free(msg);
        free(where);
        return cli_error(path, "out of memory reporting an error at line %d", line);
    }
    va_start(ap, fmt);
    vsnprintf(msg, (size_t)len + 1, fmt, ap);
    va_end(ap);
    if (line > 0)
        snprintf(where, (size_t)where_len + 1, "%s:%d", path, line);
    else
        memcpy(where, path, (size_t)where_len + 1);
    cli_error(where, "%s", msg);
    free(msg);
    free(where);
    return CLI_BAD_INPUT;
}

/* " (did you mean 'x'?)" when a name of table is a near miss of s, else "". */
static const char *hint(const char *const *table, const char *s, char *buf, size_t size)
{
    const char *near = cli_suggest(s, table);
    if (!near)
        return "";
    snprintf(buf, size, " (did you mean '%s'?)", near);
    return buf;
}

static int table_index(const char *const *table, const char *s)
{
    int i;
    for (i = 0; table[i] != NULL; i++)
        if (strcmp(table[i], s) == 0)
            return i;
    return -1;
}

/* "a, b, c" for messages; fits every table here with room to spare. */
static const char *table_list(const char *const *table, char *buf, size_t size)
{
    size_t used = 0;
    int i;
    buf[0] = '\0';
    for (i = 0; table[i] != NULL; i++) {
        int n = snprintf(buf + used, size - used, "%s%s", i ? ", " : "", table[i]);
        if (n < 0 || (size_t)n >= size - used)
            break;
        used += (size_t)n;
    }
    return buf;
}

static char *trim(char *s)
{
    char *end;
    while (isspace((unsigned char)*s))
        s++;
    end = s + strlen(s);
    while (end > s && isspace((unsigned char)end[-1]))
        end--;
    *end = '\0';
    return s;
}

/* Split off the next whitespace-separated token of *cursor, NUL-terminating
 * it in place; NULL when none is left. */
static char *next_token(char **cursor)
{
    char *p = *cursor, *start;
    while (isspace((unsigned char)*p))
        p++;
    if (*p == '\0') {
        *cursor = p;
        return NULL;
    }
    start = p;
    while (*p != '\0' && !isspace((unsigned char)*p))
        p++;
    if (*p != '\0')
        *p++ = '\0';
    *cursor = p;
    return start;
}

int scene_add_model(scene *s, const char *name, const char *where)
{
    if (s->model_count == SCENE_MAX_MODELS)
        return cli_error(where, "at most %d models", SCENE_MAX_MODELS);
    if (scene_entry_parse(name, s->spacing, &s->models[s->model_count]))
        return cli_error(where, "unknown model '%s' (fresnel gen --help lists the models)", name);
    s->model_count++;
    return 0;
}

int scene_entry_parse(const char *name, lut_spacing spacing, scene_entry *e)
{
    int i, row;
    memset(e, 0, sizeof *e);
    if (!name || strlen(name) >= sizeof e->name ||
        (row = model_scene_id(name, spacing, SCENE_LUT_MIN, SCENE_LUT_MAX, &e->lut_n)) < 0)
        return -1;
    e->row = (model_row_id)row;
    for (i = 0; name[i]; i++) {
        e->name[i] = name[i];
        e->ident[i] = name[i] == '-' ? '_' : name[i];
    }
    return 0;
}

static int material_id_ok(const char *id)
{
    for (; *id; id++)
        if (!((*id >= 'a' && *id <= 'z') || (*id >= '0' && *id <= '9') || *id == '_'))
            return 0;
    return 1;
}

static int find_model(const scene *s, const char *name)
{
    int i;
    for (i = 0; i < s->model_count; i++)
        if (strcmp(s->models[i].name, name) == 0)
            return i;
    return -1;
}

/* Append material id (named at line; file "" for the data pack's). */
static int add_material(const char *path, int line, const char *id, const char *file, scene *s)
{
    int i;
    if (!material_id_ok(id))
        return report(path, line, "expected material ids made of a-z, 0-9 and _, got '%s'%s", id,
                      strpbrk(id, "./") ? " (a file of your own is named by a line 'material ID = FILE')" : "");
    if (strlen(id) >= SCENE_ID_SIZE)
        return report(path, line, "expected a material id of at most %d characters, got '%s'", SCENE_ID_SIZE - 1, id);
    for (i = 0; i < s->material_count; i++)
        if (strcmp(s->materials[i], id) == 0)
            return report(path, line, "expected each material once, '%s' is already named at line %d", id,
                          s->material_line[i]);
    if (s->material_count == SCENE_MAX_MATERIALS)
        return report(path, line, "expected at most %d materials", SCENE_MAX_MATERIALS);
    strcpy(s->materials[s->material_count], id);
    strcpy(s->material_file[s->material_count], file);
    s->material_line[s->material_count++] = line;
    return 0;
}

static int parse_materials(const char *path, int line, char *value, scene *s)
{
    char *cursor = value, *id;
    while ((id = next_token(&cursor)) != NULL)
        if (add_material(path, line, id, "", s))
            return CLI_BAD_INPUT;
    return 0;
}

/* `material ID = FILE`: FILE relative to the manifest's directory unless
 * absolute. */
static int parse_material_file(const char *path, int line, char *id, const char *file, scene *s)
{
    const char *slash = strrchr(path, '/');
    int dir_len = file[0] == '/' || !slash ? 0 : (int)(slash - path) + 1;
    char resolved[SCENE_PATH_SIZE];
    if (*id == '\0' || strpbrk(id, " \t"))
        return report(path, line, "expected 'material ID = FILE' with one material id, got 'material %s'", id);
    if ((size_t)snprintf(resolved, sizeof resolved, "%.*s%s", dir_len, path, file) >= sizeof resolved)
        return report(path, line, "expected a file path of at most %d characters", SCENE_PATH_SIZE - 1);
    return add_material(path, line, id, resolved, s);
}

static int parse_models(const char *path, int line, char *value, scene *s)
{
    char *cursor = value, *model, names[256];
    const char *scene_models[SCENE_MAX_MODELS + 1];
    model_names(MODEL_SCENE, scene_models, SCENE_MAX_MODELS + 1);
    while ((model = next_token(&cursor)) != NULL) {
        scene_entry e;
        /* the LUT rows are those of grazing spacing until scene_load knows the key */
        if (scene_entry_parse(model, LUT_GRAZING, &e)) {
            if (strncmp(model, "lut", 3) == 0)
                return report(path, line,
                              "expected lutN, lutN-residual or lutN-cubic with N an integer in %d..%d "
                              "(no leading zeros), got '%s'",
                              SCENE_LUT_MIN, SCENE_LUT_MAX, model);
            char near[SCENE_NAME_SIZE + 32];
            return report(path, line,
                          "expected a model (one of %s, lutN, lutN-residual, lutN-cubic), got '%s'%s",
                          table_list(scene_models, names, sizeof names), model,
                          hint(scene_models, model, near, sizeof near));
        }
        if (find_model(s, model) >= 0)
            return report(path, line, "expected each model once, '%s' is listed twice", model);
        if (s->model_count == SCENE_MAX_MODELS)
            return report(path, line, "expected at most %d models", SCENE_MAX_MODELS);
        s->models[s->model_count++] = e;
    }
    return 0;
}

static int parse_types(const char *path, int line, char *value, scene *s)
{
    char *cursor = value, *type, names[256];
    const char *available[NUMBER_TYPES + 1];
    number_type_names(available, NUMBER_TYPES + 1);
    s->type_count = 0; /* replaces the default */
    while ((type = next_token(&cursor)) != NULL) {
        char near[SCENE_NAME_SIZE + 32];
        int t = number_type_parse(type), i;
        if (t < 0)
            return report(path, line, "expected a number type (one of %s), got '%s'%s",
                          table_list(available, names, sizeof names), type,
                          hint(available, type, near, sizeof near));
        if (!number_type_catalog[t].available)
            return report(path, line, "expected a number type this build of fresnel writes (one of %s), got '%s': "
                          "its compiler has no _Float16 (a gcc build has it)",
                          table_list(available, names, sizeof names), type);
        for (i = 0; i < s->type_count; i++)
            if ((int)s->types[i] == t)
                return report(path, line, "expected each type once, '%s' is listed twice",
                              number_type_catalog[t].name);
        s->types[s->type_count++] = (number_type_id)t;
    }
    return 0;
}

/* Other renderers whose parameters the header's comments give (targets.h). */
static int parse_targets(const char *path, int line, char *value, scene *s)
{
    const char *names[SCENE_MAX_TARGETS + 1];
    char *cursor = value, *name, list[256], near[SCENE_NAME_SIZE + 32];
    int t, k;
    target_names(names, SCENE_MAX_TARGETS + 1);
    while ((name = next_token(&cursor)) != NULL) {
        if ((t = target_parse(name)) < 0)
            return report(path, line, "expected a renderer target (one of %s), got '%s'%s",
                          table_list(names, list, sizeof list), name, hint(names, name, near, sizeof near));
        for (k = 0; k < s->target_count; k++)
            if ((int)s->targets[k] == t)
                return report(path, line, "expected each target once, '%s' is listed twice", name);
        if (s->target_count == SCENE_MAX_TARGETS)
            return report(path, line, "expected at most %d targets", SCENE_MAX_TARGETS);
        s->targets[s->target_count++] = (target_id)t;
    }
    return 0;
}

/* A value that must be one name of `table`: its index in *index. */
static int parse_choice(const char *path, int line, const char *what, const char *const *table, const char *value,
                        int *index)
{
    char names[256], near[SCENE_NAME_SIZE + 32];
    if (table == colour_space_ids && colour_space_find(value))
        value = colour_space_find(value); /* any case, common aliases */
    if ((*index = table_index(table, value)) < 0)
        return report(path, line, "expected a %s (one of %s), got '%s'%s", what,
                      table_list(table, names, sizeof names), value, hint(table, value, near, sizeof near));
    return 0;
}

static int parse_number(const char *path, int line, const char *key, const char *value,
                        double lo, double hi, double *out)
{
    double v;
    if (cli_parse_double(value, &v) != 0 || !(v >= lo && v <= hi))
        return report(path, line, "expected %s as a number in [%g, %g], got '%s'", key, lo, hi,
                      value);
    *out = v;
    return 0;
}

/* film_thickness = LO HI */
static int parse_thickness(const char *path, int line, char *value, scene *s)
{
    char *cursor = value, *lo = next_token(&cursor), *hi = next_token(&cursor);
    double max = FRESNEL_FILM_D_MAX;
    if (!lo || !hi || next_token(&cursor) || cli_parse_double(lo, &s->film_d_lo) ||
        cli_parse_double(hi, &s->film_d_hi) || !(s->film_d_lo >= 0.0 && s->film_d_lo <= s->film_d_hi &&
                                                 s->film_d_hi <= max))
        return report(path, line, "expected film_thickness as two numbers LO HI of nm, 0 <= LO <= HI <= %g, got '%s'",
                      max, value);
    return 0;
}

/* `film ID = N`: material ID's own film. */
static int parse_material_film(const char *path, int line, char *id, const char *value, scene *s)
{
    int i;
    if (*id == '\0' || strpbrk(id, " \t") || !material_id_ok(id))
        return report(path, line, "expected 'film ID = N' with one material id, got 'film %s'", id);
    for (i = 0; i < s->film_count; i++)
        if (!strcmp(s->film_material[i], id))
            return report(path, line, "expected one film per material, '%s' has one at line %d", id,
                          s->film_material_line[i]);
    if (s->film_count == SCENE_MAX_MATERIALS || strlen(id) >= SCENE_ID_SIZE)
        return report(path, line, "expected at most %d film lines of material ids of at most %d characters",
                      SCENE_MAX_MATERIALS, SCENE_ID_SIZE - 1);
    if (parse_number(path, line, "the film's index", value, 1.0, FILM_N_MAX, &s->film_material_n[s->film_count]))
        return CLI_BAD_INPUT;
    strcpy(s->film_material[s->film_count], id);
    s->film_material_line[s->film_count++] = line;
    return 0;
}

int scene_name_ok(const char *name)
{
    size_t i, len = strlen(name);
    if (len == 0 || len >= SCENE_PREFIX_SIZE || name[0] == '_' || name[len - 1] == '_')
        return 0;
    for (i = 0; i < len; i++)
        if (!(isalnum((unsigned char)name[i]) && (unsigned char)name[i] < 128) &&
            !(name[i] == '_' && name[i + 1] != '_'))
            return 0;
    return 1;
}

static int parse_name(const char *path, int line, const char *value, scene *s)
{
    if (!scene_name_ok(value))
        return report(path, line,
                      "expected name as a C identifier part: 1 to %d of A-Z a-z 0-9 _, no '_' at either end "
                      "and no '__' (C++ reserves it), got '%s'",
                      SCENE_PREFIX_SIZE - 1, value);
    strcpy(s->name, value);
    return 0;
}

void scene_name_from_path(const char *path, char out[SCENE_PREFIX_SIZE])
{
    const char *base = strrchr(path, '/'), *end;
    base = base ? base + 1 : path;
    end = base + strlen(base);
    if ((size_t)(end - base) > 6 && strcmp(end - 6, ".scene") == 0)
        end -= 6;
    cli_identifier(base, (size_t)(end - base), out, SCENE_PREFIX_SIZE, "scene");
}

static int parse_value(const char *path, int line, int key, char *value, scene *s)
{
    int i;
    switch (key) {
    case KEY_MATERIALS: return parse_materials(path, line, value, s);
    case KEY_MODELS: return parse_models(path, line, value, s);
    case KEY_TYPES: return parse_types(path, line, value, s);
    case KEY_TARGETS: return parse_targets(path, line, value, s);
    case KEY_NAME: return parse_name(path, line, value, s);
    case KEY_SPACE:
        if (parse_choice(path, line, "colour space", colour_space_ids, value, &i))
            return CLI_BAD_INPUT;
        snprintf(s->space, sizeof s->space, "%s", colour_space_ids[i]);
        return 0;
    case KEY_LUT_SPACING:
        if (parse_choice(path, line, "LUT spacing", lut_spacing_names, value, &i))
            return CLI_BAD_INPUT;
        s->spacing = (lut_spacing)i;
        return 0;
    case KEY_GAMUT:
        if (parse_choice(path, line, "gamut policy", gamut_policy_names, value, &i))
            return CLI_BAD_INPUT;
        s->gamut = (gamut_policy)i;
        return 0;
    case KEY_F_AVG:
        return parse_choice(path, line, "f_avg value", scene_f_avg_names, value, &s->f_avg);
    case KEY_SIGMA: return parse_number(path, line, "sigma (nm)", value, 0.0, SIGMA_MAX, &s->sigma);
    case KEY_FILM: return parse_number(path, line, "the film's index", value, 1.0, FILM_N_MAX, &s->film_n);
    case KEY_FILM_THICKNESS: return parse_thickness(path, line, value, s);
    default: return parse_number(path, line, "n1", value, N1_MIN, N1_MAX, &s->n1);
    }
}

void scene_defaults(scene *s)
{
    int i;
    memset(s, 0, sizeof *s);
    for (i = 0; i < SCENE_MAX_MATERIALS; i++)
        s->material_format[i] = NK_FORMAT_AUTO;
    strcpy(s->space, "srgb");
    s->spacing = LUT_GRAZING;
    s->gamut = GAMUT_MAP;
    s->types[0] = TYPE_F32;
    s->type_count = 1;
    s->sigma = 25.0;
    s->n1 = 1.0;
    s->film_d_hi = FRESNEL_FILM_D_MAX;
}

/* One non-blank, non-comment line, comments already cut off. */
static int parse_line(const char *path, int line, char *text, scene *s)
{
    char *eq = strchr(text, '='), *key, *value, names[256];
    int k, *where;
    if (eq == NULL)
        return report(path, line, "expected 'key = value', got '%s'", text);
    *eq = '\0';
    key = trim(text);
    value = trim(eq + 1);
    if (*key == '\0')
        return report(path, line, "expected a key before '='");
    if (!strncmp(key, "material", 8) && isspace((unsigned char)key[8])) {
        if (*value == '\0')
            return report(path, line, "expected a file after 'material %s ='", trim(key + 8));
        return parse_material_file(path, line, trim(key + 8), value, s);
    }
    if (!strncmp(key, "film", 4) && isspace((unsigned char)key[4])) {
        if (*value == '\0')
            return report(path, line, "expected an index after 'film %s ='", trim(key + 4));
        return parse_material_film(path, line, trim(key + 4), value, s);
    }
    k = table_index(key_names, key);
    if (k < 0) {
        char near[SCENE_NAME_SIZE + 32];
        return report(path, line, "expected a key (one of %s), got '%s'%s",
                      table_list(key_names, names, sizeof names), key, hint(key_names, key, near, sizeof near));
    }
    where = key_line(s, k);
    if (*where != 0)
        return report(path, line, "expected '%s' once, it is already set at line %d", key, *where);
    if (*value == '\0')
        return report(path, line, "expected a value after '%s ='", key);
    *where = line;
    return parse_value(path, line, k, value, s);
}

/* The film keys against the models, the materials and n1. */
static int check_film(const char *path, int last, const scene *s)
{
    int i, k, film = -1, first = s->film_line ? s->film_line : (s->film_count ? s->film_material_line[0] : 0);
    for (i = 0; i < s->model_count; i++)
        if (model_catalog[s->models[i].row].offered & MODEL_FILM)
            film = i;
    if (film < 0) {
        if (first || s->film_thickness_line)
            return report(path, first ? first : s->film_thickness_line,
                          "expected film keys only with a thin-film model in models (line %d lists none)",
                          s->models_line);
        return 0;
    }
    for (k = 0; k < s->film_count; k++) {
        for (i = 0; i < s->material_count && strcmp(s->materials[i], s->film_material[k]); i++)
            ;
        if (i == s->material_count)
            return report(path, s->film_material_line[k], "expected 'film ID = N' for a material of the scene, got '%s'",
                          s->film_material[k]);
    }
    for (i = 0; i < s->material_count; i++) {
        double n = scene_film_n(s, i);
        int at = s->film_line;
        for (k = 0; k < s->film_count; k++)
            if (!strcmp(s->materials[i], s->film_material[k]))
                at = s->film_material_line[k];
        if (n == 0.0)
            return report(path, last > 0 ? last : 1,
                          "expected 'film = N' or 'film %s = N': %s has no film for %s (line %d)", s->materials[i],
                          s->materials[i], s->models[film].name, s->models_line);
        if (n < s->n1)
            return report(path, at,
                          "expected a film index of at least n1 %g, got %g for %s: total reflection inside a film "
                          "less dense than the incident medium is outside the thin-film model's domain",
                          s->n1, n, s->materials[i]);
    }
    return 0;
}

int scene_load(const char *path, scene *out)
{
    FILE *f;
    char *buf = NULL;
    size_t cap = 0;
    ssize_t len;
    int line = 0, rc = 0, read_errno, errors = 0, m;
    scene_defaults(out);
    if ((rc = cli_open_input(path, &f)))
        return rc;
    for (;;) {
        char *text, *hash, *cr;
        errno = 0;
        len = getline(&buf, &cap, f);
        read_errno = errno;
        if (len < 0)
            break;
        line++;
        text = buf;
        if (strlen(text) != (size_t)len) {
            rc = report(path, line, "expected text, found a NUL byte");
            if (++errors == SCENE_MAX_ERRORS)
                break;
            continue;
        }
        if ((cr = strchr(text, '\r')) != NULL && strcmp(cr, "\r\n") && strcmp(cr, "\r")) {
            /* classic Mac OS line ends: the whole file would read as line 1 */
            rc = report(path, line, "expected lines ending in LF or CR LF, found a CR alone (classic Mac OS line ends)");
            break;
        }
        if (line == 1 && len >= 3 && memcmp(text, "\xEF\xBB\xBF", 3) == 0)
            text += 3;
        hash = strchr(text, '#');
        if (hash != NULL)
            *hash = '\0';
        text = trim(text);
        if (*text == '\0')
            continue;
        /* Every bad line is reported, each at its line, so one run lists
         * all there is to fix. */
        if (parse_line(path, line, text, out) != 0) {
            rc = CLI_BAD_INPUT;
            if (++errors == SCENE_MAX_ERRORS) {
                report(path, line, "stopping after %d errors", SCENE_MAX_ERRORS);
                break;
            }
        }
    }
    free(buf);
    if (rc == 0 && (ferror(f) || read_errno == ENOMEM)) {
        fclose(f); /* the file failed, not its content */
        return read_errno == ENOMEM ? cli_oom(path) : cli_read_failure(path, read_errno);
    }
    fclose(f);
    if (rc != 0)
        return rc;
    if (out->material_count == 0)
        return report(path, line > 0 ? line : 1,
                      "expected a 'materials = id ...' or 'material id = FILE' line, no material is named");
    if (out->models_line == 0)
        return report(path, line > 0 ? line : 1,
                      "expected a 'models = name ...' line, the required key is missing");
    if (out->spacing == LUT_GRAZING_PL && (out->type_count != 1 || out->types[0] != TYPE_Q15))
        return report(path, out->lut_spacing_line ? out->lut_spacing_line : 1,
                      "expected types = q15 with lut_spacing grazing-pl (its tables are for "
                      "fresnel_lut_pl_u16_q15_fast only)");
    if ((rc = check_film(path, line, out)))
        return rc;
    for (m = 0; m < out->model_count; m++) {
        scene_entry *e = &out->models[m];
        if (!e->lut_n)
            continue;
        if (out->spacing == LUT_GRAZING_PL && (model_catalog[e->row].form != LUT_PLAIN || e->lut_n > 64))
            return report(path, out->models_line,
                          "expected lutN with N <= 64 and no -cubic or -residual with lut_spacing grazing-pl, "
                          "got '%s'",
                          e->name);
        if (out->spacing == LUT_UNIFORM && model_catalog[e->row].form == LUT_CUBIC)
            return report(path, out->models_line,
                          "expected lut_spacing grazing with '%s' (the cubic reads nodes uniform in "
                          "sqrt(cos theta)), lut_spacing is uniform at line %d",
                          e->name, out->lut_spacing_line);
        e->row = model_lut_id(model_catalog[e->row].form, out->spacing);
    }
    return 0;
}

double scene_film_n(const scene *sc, int i)
{
    int k, film = 0;
    for (k = 0; k < sc->model_count; k++)
        film |= (model_catalog[sc->models[k].row].offered & MODEL_FILM) != 0;
    for (k = 0; film && k < sc->film_count; k++)
        if (!strcmp(sc->film_material[k], sc->materials[i]))
            return sc->film_material_n[k];
    return film ? sc->film_n : 0.0;
}

unsigned scene_reads(const scene *sc, int q15)
{
    unsigned reads = 0;
    int m;
    for (m = 0; m < sc->model_count; m++)
        reads |= q15 ? model_catalog[sc->models[m].row].q15_reads : model_catalog[sc->models[m].row].reads;
    return reads;
}

int scene_has_model(const scene *sc, const char *model)
{
    int i;
    for (i = 0; i < sc->model_count; i++)
        if (!strcmp(sc->models[i].name, model))
            return 1;
    return 0;
}

int scene_has_type(const scene *sc, number_type_id type)
{
    int i;
    for (i = 0; i < sc->type_count; i++)
        if (sc->types[i] == type)
            return 1;
    return 0;
}
