/* Scene manifest parser: a full manifest round-trips, defaults apply, and
 * every kind of bad input is rejected with CLI_BAD_INPUT and a message that
 * points at the right line. */
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "common/cli.h"
#include "harness.h"
#include "scene/scene.h"
#include "2_derive/derive.h"
#include "1_spectral/spectral.h"

static char tmp_dir[] = "/tmp/test_scene.XXXXXX";
static int manifest_count;
static char last_message[4096];

static void write_bytes(const char *path, const char *text, size_t len)
{
    FILE *f = fopen(path, "wb");
    if (f == NULL) {
        perror(path);
        exit(1);
    }
    fwrite(text, 1, len, f);
    fclose(f);
}

/* A fresh file per manifest, so a failing check names a file that still
 * holds the input it saw. */
static const char *write_manifest_len(const char *text, size_t len)
{
    static char path[512];
    snprintf(path, sizeof path, "%s/m%03d.scene", tmp_dir, ++manifest_count);
    write_bytes(path, text, len);
    return path;
}

static const char *write_manifest(const char *text)
{
    return write_manifest_len(text, strlen(text));
}

/* scene_load with stderr captured into last_message. */
static int load_capturing(const char *path, scene *s)
{
    char capture[600];
    int saved, fd, rc;
    size_t n;
    FILE *f;
    snprintf(capture, sizeof capture, "%s/stderr.txt", tmp_dir);
    fflush(stderr);
    saved = dup(2);
    fd = open(capture, O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (saved < 0 || fd < 0) {
        perror("capturing stderr");
        exit(1);
    }
    dup2(fd, 2);
    close(fd);
    rc = scene_load(path, s);
    fflush(stderr);
    dup2(saved, 2);
    close(saved);
    f = fopen(capture, "rb");
    n = f ? fread(last_message, 1, sizeof last_message - 1, f) : 0;
    last_message[n] = '\0';
    if (f)
        fclose(f);
    return rc;
}

/* The manifest must fail at `line` with a message containing `needle`. */
static void expect_error_len(const char *name, const char *text, size_t len, int line,
                             const char *needle)
{
    scene s;
    char where[600];
    const char *path = write_manifest_len(text, len);
    int rc = load_capturing(path, &s);
    snprintf(where, sizeof where, "%s:%d: ", path, line);
    CHECK(name,
          rc == CLI_BAD_INPUT && strncmp(last_message, where, strlen(where)) == 0 &&
              strchr(last_message, '\n') == last_message + strlen(last_message) - 1 &&
              (needle == NULL || strstr(last_message, needle) != NULL),
          "rc %d, expected one line starting '%s' containing '%s', got '%s'", rc, where,
          needle ? needle : "", last_message);
}

static void expect_error(const char *name, const char *text, int line, const char *needle)
{
    expect_error_len(name, text, strlen(text), line, needle);
}

static void test_full_manifest(void)
{
    static const char *const models[] = {"schlick", "lsk", "lsk-comp", "f82", "gulbrandsen",
                                         "cook-torrance", "exact", "exact-gaussian",
                                         "approx-conductor", "lut4", "lut16", "lut256-residual"};
    scene s;
    int i, ok;
    const char *path = write_manifest(
        "# demo scene\r\n"
        "materials = gold silver  cu_2o\t# trailing comment\r\n"
        "\r\n"
        "   # indented comment\n"
        "  models = schlick lsk lsk-comp f82 gulbrandsen cook-torrance exact exact-gaussian "
        "approx-conductor lut4 lut16 lut256-residual  \n"
        "space=display-p3\n"
        "sigma = 12.5\n"
        "n1 = 1.33 # water\n"
        "types = f32\n"
        "lut_spacing = uniform\n");
    int rc = load_capturing(path, &s);
    CHECK("scene full manifest loads", rc == 0, "rc %d: %s", rc, last_message);
    if (rc != 0)
        return;
    CHECK("scene full: no message", last_message[0] == '\0', "got '%s'", last_message);
    CHECK("scene full: materials",
          s.material_count == 3 && !strcmp(s.materials[0], "gold") &&
              !strcmp(s.materials[1], "silver") && !strcmp(s.materials[2], "cu_2o"),
          "count %d", s.material_count);
    ok = s.model_count == (int)(sizeof models / sizeof models[0]);
    for (i = 0; ok && i < s.model_count; i++)
        ok = !strcmp(s.models[i].name, models[i]);
    CHECK("scene full: models in file order", ok, "count %d", s.model_count);
    CHECK("scene full: models typed once (row, nodes, identifier; LUT rows at the scene's spacing)",
          s.models[2].row == MODEL_ROW_lsk_comp && s.models[2].lut_n == 0 &&
              !strcmp(s.models[2].ident, "lsk_comp") && s.models[11].lut_n == 256 &&
              s.models[11].row == model_lut_id(LUT_RESIDUAL, LUT_UNIFORM) &&
              s.models[11].row != model_lut_id(LUT_RESIDUAL, LUT_GRAZING) &&
              !strcmp(s.models[11].ident, "lut256_residual"),
          "lsk-comp %s, lut256-residual %d %s", s.models[2].ident, s.models[11].lut_n, s.models[11].ident);
    CHECK("scene full: space", !strcmp(s.space, "display-p3"), "'%s'", s.space);
    CHECK("scene full: sigma", s.sigma == 12.5, "%g", s.sigma);
    CHECK("scene full: n1", s.n1 == 1.33, "%g", s.n1);
    CHECK("scene full: types", s.type_count == 1 && s.types[0] == TYPE_F32, "count %d",
          s.type_count);
    CHECK("scene full: lut_spacing", s.spacing == LUT_UNIFORM, "%d", (int)s.spacing);
    CHECK("scene full: key lines",
          s.materials_line == 2 && s.models_line == 5 && s.space_line == 6 &&
              s.sigma_line == 7 && s.n1_line == 8 && s.types_line == 9 &&
              s.lut_spacing_line == 10,
          "materials %d models %d space %d sigma %d n1 %d types %d lut_spacing %d",
          s.materials_line, s.models_line, s.space_line, s.sigma_line, s.n1_line, s.types_line,
          s.lut_spacing_line);
}

static void test_defaults(void)
{
    scene s;
    /* BOM, and no newline at the end of the last line. */
    const char *path = write_manifest("\xEF\xBB\xBFmodels = f82\nmaterials = gold");
    int rc = load_capturing(path, &s);
    CHECK("scene defaults: loads", rc == 0, "rc %d: %s", rc, last_message);
    if (rc != 0)
        return;
    CHECK("scene defaults: values",
          !strcmp(s.space, "srgb") && s.sigma == 25.0 && s.n1 == 1.0 && s.type_count == 1 &&
              s.types[0] == TYPE_F32 && s.spacing == LUT_GRAZING && s.gamut == GAMUT_MAP,
          "space %s sigma %g n1 %g types %d lut_spacing %d gamut %d", s.space, s.sigma, s.n1,
          s.type_count, (int)s.spacing, (int)s.gamut);
    CHECK("scene defaults: lines 0 where defaulted, set where given",
          s.models_line == 1 && s.materials_line == 2 && s.space_line == 0 &&
              s.sigma_line == 0 && s.n1_line == 0 && s.types_line == 0 &&
              s.lut_spacing_line == 0,
          "models %d materials %d space %d", s.models_line, s.materials_line, s.space_line);
}

static void test_accepted_values(void)
{
    char text[4096];
    size_t used;
    scene s;
    int i, ok = 1;
    for (i = 0; ok && colour_space_ids[i] != NULL; i++) {
        snprintf(text, sizeof text, "materials = a\nmodels = exact\nspace = %s\n",
                 colour_space_ids[i]);
        ok = load_capturing(write_manifest(text), &s) == 0 &&
             !strcmp(s.space, colour_space_ids[i]);
    }
    CHECK("scene every space name accepted", ok, "failed at '%s': %s", colour_space_ids[i - 1],
          last_message);
    ok = load_capturing(write_manifest("materials = a\nmodels = exact\nsigma = 0\nn1 = 1\n"),
                        &s) == 0 && s.sigma == 0.0 && s.n1 == 1.0;
    ok = ok && load_capturing(write_manifest("materials = a\nmodels = exact\nsigma = 200\n"
                                             "n1 = 4.0\n"),
                              &s) == 0 && s.sigma == 200.0 && s.n1 == 4.0;
    ok = ok && load_capturing(write_manifest("materials = a\nmodels = exact\nsigma = 2.5e1\n"),
                              &s) == 0 && s.sigma == 25.0;
    CHECK("scene sigma and n1 range ends accepted", ok, "%s", last_message);
    ok = load_capturing(write_manifest("materials = a\nmodels = exact\nlut_spacing = grazing\n"),
                        &s) == 0 && s.spacing == LUT_GRAZING;
    CHECK("scene lut_spacing grazing accepted", ok, "%s", last_message);
    ok = load_capturing(write_manifest("materials = a\nmodels = exact\ntypes = fixed f32\n"), &s) == 0 &&
         s.type_count == 2 && s.types[0] == TYPE_Q15 && s.types[1] == TYPE_F32;
    CHECK("scene types: rows of the number type registry in file order, fixed, the second name of q15", ok, "%s",
          last_message);
    ok = load_capturing(write_manifest("materials = a\nmodels = exact\ntypes = f16\n"), &s) == 0;
    CHECK("scene types = f16 accepted where the build has _Float16, refused with a reason where not",
          FRESNEL_HAS_F16 ? ok && s.type_count == 1 && s.types[0] == TYPE_F16
                          : !ok && strstr(last_message, "_Float16") != NULL,
          "%s", last_message);

    used = (size_t)snprintf(text, sizeof text, "models = exact\nmaterials =");
    for (i = 0; i < SCENE_MAX_MATERIALS; i++)
        used += (size_t)snprintf(text + used, sizeof text - used, " m%d", i);
    snprintf(text + used, sizeof text - used, "\n");
    ok = load_capturing(write_manifest(text), &s) == 0 &&
         s.material_count == SCENE_MAX_MATERIALS && !strcmp(s.materials[63], "m63");
    CHECK("scene 64 materials accepted", ok, "rc/count %d: %s", s.material_count, last_message);

    ok = load_capturing(write_manifest("materials = abcdefghijklmnopqrstuvwxyz_0123\n"
                                       "models = exact\n"),
                        &s) == 0 &&
         strlen(s.materials[0]) == SCENE_ID_SIZE - 1;
    CHECK("scene 31-character material id accepted", ok, "%s", last_message);
}

/* The targets key: other renderers' parameters in the header's comments. */
static void test_renderer_targets(void)
{
    scene s;
    int rc = load_capturing(write_manifest("materials = a\nmodels = exact\ntargets = openpbr  gltf\tgulbrandsen\n"),
                            &s);
    CHECK("scene targets: listed in order", rc == 0 && s.target_count == 3 && !strcmp(target_catalog_names[s.targets[0]], "openpbr") &&
                                                 !strcmp(target_catalog_names[s.targets[1]], "gltf") && !strcmp(target_catalog_names[s.targets[2]], "gulbrandsen") &&
                                                 s.targets_line == 3,
          "rc %d count %d: %s", rc, s.target_count, last_message);
    rc = load_capturing(write_manifest("materials = a\nmodels = exact\n"), &s);
    CHECK("scene targets: none by default", rc == 0 && s.target_count == 0 && s.targets_line == 0, "%d",
          s.target_count);
    expect_error("scene error: unknown target lists them", "materials = a\nmodels = exact\ntargets = renderman\n", 3,
                 "expected a renderer target (one of openpbr, materialx, blender, unreal, gltf, filament, "
                 "gulbrandsen), got 'renderman'");
    expect_error("scene error: near-miss target", "materials = a\nmodels = exact\ntargets = blendr\n", 3,
                 "(did you mean 'blender'?)");
    expect_error("scene error: target twice", "materials = a\nmodels = exact\ntargets = unreal gltf unreal\n", 3,
                 "'unreal' is listed twice");
}

static void test_lut_names(void)
{
    static const struct {
        const char *name;
        int size, residual;
    } cases[] = {{"lut4", 4, 0},          {"lut256-residual", 256, 1}, {"lut32", 32, 0},
                 {"lut3", 0, 0},          {"lut257", 0, 0},            {"lut016", 0, 0},
                 {"lut", 0, 0},           {"lut-residual", 0, 0},      {"lut16-res", 0, 0},
                 {"lut16x", 0, 0},        {"lut+16", 0, 0},            {"lut 16", 0, 0},
                 {"lut00016", 0, 0},      {"lut99999999999", 0, 0},    {"LUT16", 0, 0},
                 {"exact", 0, 0},         {"lut16-residual-residual", 0, 0},
                 {"lut16-cubic", 16, 2},  {"lut16-cubic-residual", 0, 0}, {"lut16-cubi", 0, 0}};
    size_t i;
    scene_entry e;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char name[64];
        int size, form = -1;
        size = scene_entry_parse(cases[i].name, LUT_GRAZING, &e) ? 0 : e.lut_n;
        if (size)
            form = (int)model_catalog[e.row].form;
        snprintf(name, sizeof name, "scene lut size of '%s'", cases[i].name);
        CHECK(name, size == cases[i].size && (size == 0 || form == cases[i].residual), "got N %d form %d", size,
              form);
    }
    CHECK("scene model name of NULL", scene_entry_parse(NULL, LUT_GRAZING, &e) != 0, "accepted");
    CHECK("scene model names",
          !scene_entry_parse("f82", LUT_GRAZING, &e) && e.lut_n == 0 &&
              !scene_entry_parse("lut8-residual", LUT_GRAZING, &e) && e.lut_n == 8 &&
              scene_entry_parse("F82", LUT_GRAZING, &e) && scene_entry_parse("lut2", LUT_GRAZING, &e),
          "f82, lut8-residual, F82, lut2");
}

static void test_errors(void)
{
    static const char with_nul[] = "materials = gold\nmodels = ex\0act\n";
    char text[4096];
    size_t used;
    int i;

    expect_error("scene error: missing =", "materials = gold\nmodels exact\n", 2,
                 "expected 'key = value'");
    expect_error("scene error: empty key", "materials = gold\n= exact\n", 2, "key");
    expect_error("scene error: unknown key", "materials = gold\nmodels = exact\ncolour = srgb\n",
                 3, "'colour'");
    expect_error("scene error: key is case-sensitive", "Materials = gold\n", 1, "'Materials'");
    expect_error("scene error: duplicate key names both lines",
                 "materials = gold\nsigma = 20\nmodels = exact\nsigma = 30\n", 4, "line 2");
    expect_error("scene error: duplicate list key", "materials = gold\n\nmaterials = silver\n", 3,
                 "line 1");
    expect_error("scene error: empty value", "materials = gold\nspace =\n", 2, "value");
    expect_error("scene error: value only a comment", "materials = gold\nmodels = # none\n", 2,
                 "value");
    expect_error("scene error: value only blanks", "materials = \t \r\n", 1, "value");

    expect_error("scene error: sigma not a number", "sigma = abc\n", 1, "'abc'");
    expect_error("scene error: sigma trailing junk", "sigma = 25nm\n", 1, "'25nm'");
    expect_error("scene error: sigma two numbers", "sigma = 25 30\n", 1, "sigma");
    expect_error("scene error: sigma nan", "sigma = nan\n", 1, "sigma");
    expect_error("scene error: sigma inf", "sigma = inf\n", 1, "sigma");
    expect_error("scene error: sigma overflow", "sigma = 1e999\n", 1, "sigma");
    expect_error("scene error: sigma negative", "\nsigma = -1\n", 2, "[0, 200]");
    expect_error("scene error: sigma too large", "sigma = 200.001\n", 1, "[0, 200]");
    expect_error("scene error: n1 comma decimal", "n1 = 1,5\n", 1, "n1");
    expect_error("scene error: n1 below 1", "n1 = 0.99\n", 1, "[1, 4]");
    expect_error("scene error: n1 above 4", "n1 = 4.01\n", 1, "[1, 4]");

    expect_error("scene error: unknown space", "space = srgb-linear\n", 1, "display-p3");
    expect_error("scene error: two spaces", "space = srgb acescg\n", 1, "'srgb acescg'");
    {
        /* Colour-space names ignore case and take the common aliases. */
        static const char *const spellings[][2] = {{"sRGB", "srgb"},     {"rec709", "srgb"},   {"BT709", "srgb"},
                                                   {"p3", "display-p3"}, {"bt2020", "rec2020"}, {"ACEScg", "acescg"}};
        size_t k;
        for (k = 0; k < sizeof spellings / sizeof spellings[0]; k++) {
            char text[128], name[96];
            scene s;
            int rc;
            snprintf(text, sizeof text, "materials = au\nmodels = exact\nspace = %s\n", spellings[k][0]);
            rc = load_capturing(write_manifest_len(text, strlen(text)), &s);
            snprintf(name, sizeof name, "scene: space = %s is %s", spellings[k][0], spellings[k][1]);
            CHECK(name, rc == 0 && !strcmp(s.space, spellings[k][1]), "rc %d, space '%s', '%s'", rc,
                  rc == 0 ? s.space : "", last_message);
        }
    }
    expect_error("scene error: a near-miss space gets a suggestion", "space = srbg\n", 1, "did you mean 'srgb'?");
    expect_error("scene error: unknown model", "materials = gold\nmodels = f82 fresnel\n", 2,
                 "'fresnel'");
    expect_error("scene error: lut too small", "models = lut3\n", 1, "4..256");
    expect_error("scene error: lut too large", "models = lut257-residual\n", 1, "4..256");
    expect_error("scene error: grazing-pl spacing needs types = q15 only",
                 "materials = au\nmodels = lut32\nlut_spacing = grazing-pl\n", 3, "types = q15");
    expect_error("scene error: grazing-pl spacing with a cubic table",
                 "materials = au\nmodels = lut16-cubic\ntypes = q15\nlut_spacing = grazing-pl\n", 2, "N <= 64");
    expect_error("scene error: grazing-pl spacing with 128 nodes",
                 "materials = au\nmodels = lut128\ntypes = q15\nlut_spacing = grazing-pl\n", 2, "N <= 64");
    expect_error("scene error: cubic LUT with uniform spacing, at the models line",
                 "materials = au\nmodels = schlick lut16-cubic\nlut_spacing = uniform\n", 2, "lut_spacing grazing");
    expect_error("scene error: lut leading zero", "models = lut016\n", 1, "leading zeros");
    expect_error("scene error: lut bad suffix", "models = lut16-res\n", 1, "'lut16-res'");
    expect_error("scene error: unknown type", "types = f32 f64\n", 1, "'f64'");
    expect_error("scene error: unknown lut spacing", "lut_spacing = log\n", 1, "uniform");

    expect_error("scene error: duplicate material", "materials = gold silver gold\n", 1,
                 "'gold'");
    expect_error("scene error: duplicate model", "models = f82 exact f82\n", 1, "'f82'");
    expect_error("scene error: duplicate lut model", "models = lut16 lut16-residual lut16\n", 1,
                 "'lut16'");
    expect_error("scene error: duplicate type", "types = f32 f32\n", 1, "'f32'");

    expect_error("scene error: id upper case", "materials = Gold\n", 1, "'Gold'");
    expect_error("scene error: id with hyphen", "materials = gold rose-gold\n", 1, "'rose-gold'");
    expect_error("scene error: id non-ASCII", "materials = g\xC3\xB6ld\n", 1, "a-z");
    expect_error("scene error: id too long", "materials = abcdefghijklmnopqrstuvwxyz_01234\n", 1,
                 "at most 31");

    used = (size_t)snprintf(text, sizeof text, "models = exact\n\nmaterials =");
    for (i = 0; i <= SCENE_MAX_MATERIALS; i++)
        used += (size_t)snprintf(text + used, sizeof text - used, " m%d", i);
    snprintf(text + used, sizeof text - used, "\n");
    expect_error("scene error: 65 materials", text, 3, "at most 64");
    used = (size_t)snprintf(text, sizeof text, "models =");
    for (i = 0; i <= SCENE_MAX_MODELS; i++)
        used += (size_t)snprintf(text + used, sizeof text - used, " lut%d", 4 + i);
    snprintf(text + used, sizeof text - used, "\n");
    expect_error("scene error: 65 models", text, 1, "at most 64");

    expect_error("scene error: missing materials at last line",
                 "models = exact\nsigma = 10\n# end\n", 3, "'materials");
    expect_error("scene error: missing models at last line (no final newline)",
                 "materials = gold\n\nsigma = 10", 3, "'models");
    expect_error("scene error: empty file at line 1", "", 1, "'materials");
    expect_error("scene error: only comments", "# nothing\n# here\n", 2, "'materials");
    expect_error_len("scene error: NUL byte", with_nul, sizeof with_nul - 1, 2, "NUL");
    expect_error("scene error: CR-only line ends (classic Mac OS), named at the first",
                 "materials = au\rmodels = f82\r", 1, "found a CR alone");
    expect_error("scene error: BOM only on line 1", "materials = gold\n\xEF\xBB\xBFmodels = f82\n",
                 2, "key");
}

/* The thin film: `film = N` for every material, `film ID = N` for one,
 * `film_thickness = LO HI`; typed once, checked against the models, the
 * materials and n1. */
static void test_film(void)
{
    scene s;
    const char *path = write_manifest("film gold = 2.2\nmaterials = gold bk7 cu\nmodels = schlick thin-film\n"
                                      "film = 1.4\nfilm_thickness = 100 750.5\n");
    int rc = load_capturing(path, &s);
    CHECK("scene film: loads", rc == 0, "rc %d: %s", rc, last_message);
    if (rc == 0) {
        material_source m0 = scene_material(&s, 0), m1 = scene_material(&s, 1);
        CHECK("scene film: the film key, each material's own film (before its materials line), the range",
              s.film_n == 1.4 && scene_film_n(&s, 0) == 2.2 && scene_film_n(&s, 1) == 1.4 &&
                  scene_film_n(&s, 2) == 1.4 && m0.film_n == 2.2 && m1.film_n == 1.4 && s.film_d_lo == 100.0 &&
                  s.film_d_hi == 750.5 && (model_catalog[s.models[1].row].offered & MODEL_FILM),
              "film %g, gold %g, bk7 %g, range %g-%g", s.film_n, scene_film_n(&s, 0), scene_film_n(&s, 1),
              s.film_d_lo, s.film_d_hi);
    }
    path = write_manifest("materials = gold\nmodels = thin-film\nfilm gold = 1.5\n");
    rc = load_capturing(path, &s);
    CHECK("scene film: a material's own film alone; thickness left to run time (0 to FRESNEL_FILM_D_MAX)",
          rc == 0 && scene_film_n(&s, 0) == 1.5 && s.film_d_lo == 0.0 && s.film_d_hi == FRESNEL_FILM_D_MAX,
          "rc %d: %s", rc, last_message);
    path = write_manifest("materials = gold\nmodels = schlick\n");
    rc = load_capturing(path, &s);
    CHECK("scene film: no film without thin-film", rc == 0 && scene_film_n(&s, 0) == 0.0 &&
                                                       scene_material(&s, 0).film_n == 0.0,
          "rc %d", rc);
    expect_error("scene error: thin-film without a film", "materials = gold bk7\nmodels = thin-film\nfilm gold = 2\n",
                 3, "bk7 has no film");
    expect_error("scene error: a film without thin-film", "materials = gold\nmodels = exact\nfilm = 1.5\n", 3,
                 "thin-film model");
    expect_error("scene error: a thickness without thin-film", "materials = gold\nfilm_thickness = 0 10\nmodels = exact\n",
                 2, "thin-film model");
    expect_error("scene error: film below n1 (total reflection inside it)",
                 "n1 = 1.5\nmaterials = gold\nmodels = thin-film\nfilm = 1.33\n", 4, "at least n1 1.5");
    expect_error("scene error: a material's film below n1",
                 "n1 = 1.5\nmaterials = gold bk7\nmodels = thin-film\nfilm = 1.6\nfilm bk7 = 1.2\n", 5,
                 "1.2 for bk7");
    expect_error("scene error: film index out of range", "materials = gold\nmodels = thin-film\nfilm = 4.5\n", 3,
                 "in [1, 4]");
    expect_error("scene error: film index NaN", "materials = gold\nmodels = thin-film\nfilm = nan\n", 3,
                 "in [1, 4]");
    expect_error("scene error: a film of an unknown material",
                 "materials = gold\nmodels = thin-film\nfilm = 1.5\nfilm silver = 2\n", 4, "'silver'");
    expect_error("scene error: a material's film twice",
                 "materials = gold\nmodels = thin-film\nfilm gold = 1.5\nfilm gold = 2\n", 4, "line 3");
    expect_error("scene error: a film line with two ids", "materials = gold\nmodels = thin-film\nfilm a b = 1.5\n",
                 3, "one material id");
    expect_error("scene error: thickness reversed", "materials = gold\nmodels = thin-film\nfilm = 1.5\n"
                 "film_thickness = 500 100\n", 4, "LO <= HI");
    expect_error("scene error: thickness beyond the runtime's range",
                 "materials = gold\nmodels = thin-film\nfilm = 1.5\nfilm_thickness = 0 6000\n", 4, "HI <= 5000");
    expect_error("scene error: thickness negative",
                 "materials = gold\nmodels = thin-film\nfilm = 1.5\nfilm_thickness = -1 10\n", 4, "0 <= LO");
    expect_error("scene error: one thickness number",
                 "materials = gold\nmodels = thin-film\nfilm = 1.5\nfilm_thickness = 10\n", 4, "two numbers");
    expect_error("scene error: three thickness numbers",
                 "materials = gold\nmodels = thin-film\nfilm = 1.5\nfilm_thickness = 1 2 3\n", 4, "two numbers");
}

static void test_unreadable(void)
{
    scene s;
    char path[600], prefix[700];
    int rc;
    snprintf(path, sizeof path, "%s/does-not-exist.scene", tmp_dir);
    rc = load_capturing(path, &s);
    snprintf(prefix, sizeof prefix, "%s: cannot open: ", path);
    CHECK("scene error: missing file", rc == CLI_BAD_INPUT &&
                                           strncmp(last_message, prefix, strlen(prefix)) == 0,
          "rc %d, got '%s'", rc, last_message);
    rc = load_capturing(tmp_dir, &s);
    snprintf(prefix, sizeof prefix, "%s: cannot read: ", tmp_dir);
    CHECK("scene error: directory (a read error, exit 1)", rc == CLI_FAILURE &&
                                        strncmp(last_message, prefix, strlen(prefix)) == 0,
          "rc %d, got '%s'", rc, last_message);
}

int main(void)
{
    char path[600];
    int i;
    if (mkdtemp(tmp_dir) == NULL) {
        perror("mkdtemp");
        return 1;
    }
    test_full_manifest();
    test_defaults();
    test_accepted_values();
    test_lut_names();
    test_renderer_targets();
    test_errors();
    test_film();
    test_unreadable();
    if (!harness_failed_) {
        for (i = 1; i <= manifest_count; i++) {
            snprintf(path, sizeof path, "%s/m%03d.scene", tmp_dir, i);
            remove(path);
        }
        snprintf(path, sizeof path, "%s/stderr.txt", tmp_dir);
        remove(path);
        if (rmdir(tmp_dir) != 0)
            NOTE("could not remove %s", tmp_dir);
    } else {
        NOTE("manifests kept in %s", tmp_dir);
    }
    return harness_exit();
}
