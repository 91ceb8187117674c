/* The catalog's tables and the reading of its names: every name a manifest
 * or a command line may say is looked up here and nowhere else. */
#include <ctype.h>
#include <string.h>

#include "catalog/choices.h"
#include "catalog/models.h"
#include "catalog/number_types.h"
#include "catalog/targets.h"

#define FACTS_ROW(id, ...) {__VA_ARGS__},
const model_facts model_catalog[MODEL_ROWS] = {MODEL_CATALOG(FACTS_ROW) LUT_CATALOG(FACTS_ROW)};
#undef FACTS_ROW

#define TYPE_ROW(ID, ...) {.id = TYPE_##ID, __VA_ARGS__},
const number_type_facts number_type_catalog[NUMBER_TYPES] = {NUMBER_TYPE_CATALOG(TYPE_ROW)};
#undef TYPE_ROW
const int number_types_available = NUMBER_TYPES - !FRESNEL_HAS_F16;

#define TARGET_ROW(id) TARGET_NAME(id),
const char *const target_catalog_names[TARGETS + 1] = {TARGET_CATALOG(TARGET_ROW) NULL};
#undef TARGET_ROW

const char *const lut_spacing_names[] = {"grazing", "uniform", "grazing-pl", NULL};
const char *const gamut_policy_names[] = {"map", "clip", "keep", NULL};

int catalog_choice(const char *const *names, const char *name)
{
    int i;
    for (i = 0; name && names[i]; i++)
        if (!strcmp(names[i], name))
            return i;
    return -1;
}

/* N for a LUT name (N in lo..hi), setting *form; 0 for every other string. */
static int lut_size(const char *name, int lo, int hi, lut_form *form)
{
    const char *p;
    int n = 0, digits = 0, i;
    if (name == NULL || strncmp(name, "lut", 3) != 0)
        return 0;
    p = name + 3;
    if (*p == '0') /* one spelling per size, so duplicates are caught by name */
        return 0;
    while (isdigit((unsigned char)*p) && digits < 4) {
        n = n * 10 + (*p - '0');
        p++;
        digits++;
    }
    if (digits == 0 || n < lo || n > hi)
        return 0;
    /* the rest must be a LUT row's name after its "lutN" */
    for (i = MODEL_ROW_FIRST_LUT; i < MODEL_ROWS; i++)
        if (!strcmp(p, model_catalog[i].name + 4)) {
            *form = model_catalog[i].form;
            return n;
        }
    return 0;
}

model_row_id model_lut_id(lut_form form, lut_spacing spacing)
{
    int uniform = spacing == LUT_UNIFORM, i;
    for (i = MODEL_ROW_FIRST_LUT; i < MODEL_ROWS; i++)
        if (model_catalog[i].form == form && (model_catalog[i].uniform == uniform || form == LUT_CUBIC))
            break;
    return (model_row_id)i;
}

int model_scene_id(const char *name, lut_spacing spacing, int lo, int hi, int *lut_n)
{
    lut_form form = LUT_PLAIN;
    int i;
    *lut_n = lut_size(name, lo, hi, &form);
    if (!name)
        return -1;
    if (*lut_n)
        return (int)model_lut_id(form, spacing);
    for (i = 0; i < MODEL_ROW_FIRST_LUT; i++)
        if ((model_catalog[i].offered & MODEL_SCENE) && !strcmp(model_catalog[i].name, name))
            return i;
    return -1;
}

int model_names(unsigned offered, const char **out, int max)
{
    int i, n = 0;
    for (i = 0; i < MODEL_ROW_FIRST_LUT && n < max - 1; i++)
        if ((model_catalog[i].offered & offered) == offered)
            out[n++] = model_catalog[i].name;
    out[n] = NULL;
    return n;
}

int number_type_parse(const char *name)
{
    int i;
    for (i = 0; name && i < NUMBER_TYPES; i++)
        if (!strcmp(number_type_catalog[i].name, name) ||
            (number_type_catalog[i].alias && !strcmp(number_type_catalog[i].alias, name)))
            return i;
    return -1;
}

int number_type_names(const char **out, int max)
{
    int i, n = 0;
    for (i = 0; i < number_types_available && n < max - 1; i++)
        out[n++] = number_type_catalog[i].name;
    out[n] = NULL;
    return n;
}

int target_parse(const char *name) { return catalog_choice(target_catalog_names, name); }

int target_names(const char **out, int max)
{
    int i, n = 0;
    for (i = 0; i < TARGETS && n < max - 1; i++)
        out[n++] = target_catalog_names[i];
    out[n] = NULL;
    return n;
}
