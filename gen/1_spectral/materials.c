/* data/materials.csv: the index of the <id>.csv tables, with the names and
 * dataset credits that data/README.md gives them, so generated code and the
 * `materials` listing can say which measurement a constant came from. */
#include <string.h>

#include "common/cli.h"
#include "1_spectral/spectral.h"

#define MATERIALS_HEADER "id,name,dataset,kind"

/* Ids become file names (data/<id>.csv) and command-line arguments, so keep
 * them to lower-case letters, digits and '_': portable and unambiguous. */
static int id_ok(const char *id)
{
    size_t len = strlen(id);
    return len > 0 && len < sizeof ((material_info *)0)->id &&
           strspn(id, "abcdefghijklmnopqrstuvwxyz0123456789_") == len;
}

static int copy_field(const csv_reader *r, char *dst, size_t size, const char *src,
                      const char *column)
{
    size_t len = strlen(src);
    if (len == 0)
        return csv_error(r, "column %s: expected text, got an empty field", column);
    if (len >= size)
        return csv_error(r, "column %s: expected at most %d characters, got %d", column,
                         (int)size - 1, (int)len);
    memcpy(dst, src, len + 1);
    return 0;
}

static int parse_material(const csv_reader *r, char *row, material_info *m)
{
    char *field[4];
    int count = csv_split(row, field, 4);
    if (count != 4)
        return csv_error(r, "expected 4 columns (" MATERIALS_HEADER "), got %d", count);
    if (!id_ok(field[0]))
        return csv_error(r, "column id: expected 1-31 characters of a-z, 0-9 and '_', got '%.40s'",
                         field[0]);
    if (strcmp(field[3], "metal") && strcmp(field[3], "dielectric"))
        return csv_error(r, "column kind: expected 'metal' or 'dielectric', got '%.40s'", field[3]);
    if (copy_field(r, m->id, sizeof m->id, field[0], "id") ||
        copy_field(r, m->name, sizeof m->name, field[1], "name") ||
        copy_field(r, m->dataset, sizeof m->dataset, field[2], "dataset") ||
        copy_field(r, m->kind, sizeof m->kind, field[3], "kind"))
        return CLI_BAD_INPUT;
    return 0;
}

static int open_index(const char *dir, char *path, size_t size, csv_reader *r)
{
    if ((size_t)snprintf(path, size, "%s/materials.csv", dir) >= size)
        return cli_error(dir, "data directory path too long");
    return csv_open(r, path, MATERIALS_HEADER);
}

int material_list(const char *dir, material_info *out, int max)
{
    char path[1024];
    csv_reader r;
    char *row;
    int count = 0, got, i;
    if (open_index(dir, path, sizeof path, &r))
        return -1;
    while ((got = csv_next_row(&r, &row)) == 1) {
        material_info m;
        if (parse_material(&r, row, &m))
            goto fail;
        for (i = 0; i < count; i++)
            if (!strcmp(out[i].id, m.id)) {
                csv_error(&r, "id '%s' already listed", m.id);
                goto fail;
            }
        if (count == max) {
            csv_error(&r, "expected at most %d materials", max);
            goto fail;
        }
        out[count++] = m;
    }
    if (got < 0)
        goto fail;
    csv_close(&r);
    return count;
fail:
    csv_close(&r);
    return -1;
}

int material_lookup(const char *dir, const char *id, material_info *out, const char *where)
{
    /* The ids seen are kept to suggest the nearest one for a typo. */
    enum { MAX_SEEN = 256 };
    static char seen[MAX_SEEN][sizeof out->id];
    const char *names[MAX_SEEN + 1], *near;
    char path[1024];
    csv_reader r;
    char *row;
    int got, count = 0;
    if (open_index(dir, path, sizeof path, &r))
        return CLI_BAD_INPUT;
    while ((got = csv_next_row(&r, &row)) == 1) {
        if (parse_material(&r, row, out))
            break;
        if (!strcmp(out->id, id)) {
            csv_close(&r);
            return 0;
        }
        if (count < MAX_SEEN) {
            strcpy(seen[count], out->id);
            names[count] = seen[count];
            count++;
        }
    }
    csv_close(&r);
    names[count] = NULL;
    if (got == 0 && (near = cli_suggest(id, names)) != NULL)
        cli_error(where, "unknown material '%s' (did you mean '%s'?)", id, near);
    else if (got == 0)
        cli_error(where, "unknown material '%s' (not in %s; `fresnel materials` lists them)", id,
                  path);
    return CLI_BAD_INPUT;
}
