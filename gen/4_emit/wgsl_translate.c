/* GLSL subset to WGSL (wgsl_translate.h). Two stages over tokens:
 *
 * 1. A C preprocessor, enough for ports/glsl/fresnel.glsl: object-like and
 *    function-like #define (arguments expanded, then the result rescanned
 *    with the macro disabled, so nothing recurses), #undef, #if, #ifdef,
 *    #ifndef, #elif, #else, #endif with defined(), integers, ! && || and
 *    comparisons (an identifier left after expansion is 0, as in C, so
 *    __VERSION__ tests are false: WGSL is no GLSL version).
 * 2. A translator of the function definitions the preprocessor leaves:
 *    WGSL has no ?:, no unbraced if bodies, no C declarations and immutable
 *    parameters, so ?: becomes select(), every if body is braced, `T a = e`
 *    becomes `var a: T = e`, and a parameter the body assigns is taken as
 *    NAME_in and copied into a var NAME. Types and constructors are renamed
 *    (float f32, vec3 vec3f, int i32). Every expression is typed on the
 *    way (types below), and where the source mixes FRESNEL_MP (f16 with
 *    --wgsl-f16) and binary32 values the conversions GLSL makes implicitly
 *    are written out. Anything else (loops, local arrays, a global
 *    declaration, a name without a type) is refused with a message, so a
 *    construct the source gains later is reported rather than
 *    mistranslated. */
#include "4_emit/wgsl_translate.h"

#include <ctype.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

/* ------------------------------------------------------------ tokens */

typedef struct tokv {
    char **v;
    int n, cap;
} tokv;

static int tokv_push(tokv *t, const char *s, size_t len)
{
    char *c;
    if (t->n == t->cap) {
        int cap = t->cap ? 2 * t->cap : 64;
        char **v = realloc(t->v, (size_t)cap * sizeof *v);
        if (!v)
            return -1;
        t->v = v, t->cap = cap;
    }
    if (!(c = malloc(len + 1)))
        return -1;
    memcpy(c, s, len);
    c[len] = 0;
    t->v[t->n++] = c;
    return 0;
}
static int tokv_add(tokv *t, const char *s) { return tokv_push(t, s, strlen(s)); }
static void tokv_clear(tokv *t)
{
    int i;
    for (i = 0; i < t->n; i++)
        free(t->v[i]);
    t->n = 0;
}
static void tokv_free(tokv *t)
{
    tokv_clear(t);
    free(t->v);
    t->v = NULL, t->cap = 0;
}

static int is_ident_start(int c) { return isalpha(c) || c == '_'; }
static int is_ident(const char *s) { return is_ident_start((unsigned char)s[0]); }

/* Tokens of s[0..len) (comments already removed). */
static int lex(const char *s, size_t len, tokv *out)
{
    static const char *const two[] = {"==", "!=", "<=", ">=", "&&", "||", "+=", "-=",
                                      "*=", "/=", "++", "--", "##", "<<", ">>"};
    size_t i = 0, j;
    unsigned k;
    while (i < len) {
        unsigned char c = (unsigned char)s[i];
        if (isspace(c)) {
            i++;
            continue;
        }
        j = i + 1;
        if (is_ident_start(c)) {
            while (j < len && (isalnum((unsigned char)s[j]) || s[j] == '_'))
                j++;
        } else if (isdigit(c) || (c == '.' && i + 1 < len && isdigit((unsigned char)s[i + 1]))) {
            /* a pp-number: digits, '.', letters, and a sign after e/E */
            while (j < len && (isalnum((unsigned char)s[j]) || s[j] == '.' || s[j] == '_' ||
                               ((s[j] == '+' || s[j] == '-') && (s[j - 1] == 'e' || s[j - 1] == 'E'))))
                j++;
        } else {
            for (k = 0; k < sizeof two / sizeof two[0]; k++)
                if (i + 1 < len && s[i] == two[k][0] && s[i + 1] == two[k][1]) {
                    j = i + 2;
                    break;
                }
        }
        if (tokv_push(out, s + i, j - i))
            return -1;
        i = j;
    }
    return 0;
}

/* ------------------------------------------------------- preprocessor */

typedef struct macro {
    char *name;
    int func, nparams;
    char **params;
    tokv body;
} macro;

/* A function's signature, a module-scope value's type (types below). */
typedef struct ty ty;
typedef struct fnsig fnsig;
typedef struct sym sym;

struct wgsl_tr {
    macro *m;
    int nm, capm;
    fnsig *f; /* the functions translated so far, for their calls' conversions */
    int nf, capf;
    sym *g; /* module-scope values declared by wgsl_tr_declare */
    int ng, capg;
};

static int fail(const char *fmt, ...)
{
    va_list ap;
    fputs("wgsl: ", stderr);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    return -1;
}

static macro *find_macro(wgsl_tr *t, const char *name)
{
    int i;
    for (i = 0; i < t->nm; i++)
        if (!strcmp(t->m[i].name, name))
            return &t->m[i];
    return NULL;
}

static void macro_free(macro *m)
{
    int i;
    free(m->name);
    for (i = 0; i < m->nparams; i++)
        free(m->params[i]);
    free(m->params);
    tokv_free(&m->body);
}

static void undef(wgsl_tr *t, const char *name)
{
    macro *m = find_macro(t, name);
    if (!m)
        return;
    macro_free(m);
    *m = t->m[--t->nm];
}

/* #define from the text after the directive's name: NAME, then '('
 * directly after it for a function-like macro. */
static int define(wgsl_tr *t, const char *s)
{
    macro m;
    const char *p = s, *q;
    memset(&m, 0, sizeof m);
    while (isspace((unsigned char)*p))
        p++;
    for (q = p; isalnum((unsigned char)*q) || *q == '_'; q++)
        ;
    if (q == p || !(m.name = malloc((size_t)(q - p) + 1)))
        return fail("expected a macro name after #define, got '%s'", s);
    memcpy(m.name, p, (size_t)(q - p));
    m.name[q - p] = 0;
    if (*q == '(') {
        m.func = 1;
        for (q++;;) {
            while (isspace((unsigned char)*q) || *q == ',')
                q++;
            if (*q == ')') {
                q++;
                break;
            }
            for (p = q; isalnum((unsigned char)*q) || *q == '_'; q++)
                ;
            if (q == p) {
                fail("expected a parameter name in #define %s", m.name);
                free(m.name);
                return -1;
            }
            m.params = realloc(m.params, (size_t)(m.nparams + 1) * sizeof *m.params);
            if (!m.params || !(m.params[m.nparams] = malloc((size_t)(q - p) + 1)))
                return fail("out of memory");
            memcpy(m.params[m.nparams], p, (size_t)(q - p));
            m.params[m.nparams++][q - p] = 0;
        }
    }
    if (lex(q, strlen(q), &m.body))
        return fail("out of memory");
    undef(t, m.name);
    if (t->nm == t->capm) {
        int cap = t->capm ? 2 * t->capm : 64;
        macro *v = realloc(t->m, (size_t)cap * sizeof *v);
        if (!v)
            return fail("out of memory");
        t->m = v, t->capm = cap;
    }
    t->m[t->nm++] = m;
    return 0;
}

/* The macros being expanded (not expanded again inside themselves). */
typedef struct hide {
    const char *name;
    const struct hide *up;
} hide;

static int hidden(const hide *h, const char *name)
{
    for (; h; h = h->up)
        if (!strcmp(h->name, name))
            return 1;
    return 0;
}

static int expand(wgsl_tr *t, char **in, int n, const hide *h, tokv *out)
{
    int i, k;
    for (i = 0; i < n; i++) {
        macro *m = is_ident(in[i]) && !hidden(h, in[i]) ? find_macro(t, in[i]) : NULL;
        hide inner;
        if (!m || (m->func && (i + 1 >= n || strcmp(in[i + 1], "(")))) {
            if (tokv_add(out, in[i]))
                return -1;
            continue;
        }
        inner.name = m->name, inner.up = h;
        if (!m->func) {
            if (expand(t, m->body.v, m->body.n, &inner, out))
                return -1;
            continue;
        }
        {
            /* arguments: top-level comma-separated ranges, each expanded */
            int depth = 0, start = i + 2, j, na = 0, rc, lo[64], hi[64];
            tokv *args, sub = {0};
            for (j = i + 2; j < n; j++) {
                const char *s = in[j];
                if (!strcmp(s, "(") || !strcmp(s, "["))
                    depth++;
                else if ((!strcmp(s, ")") || !strcmp(s, "]")) && depth > 0)
                    depth--;
                else if (depth == 0 && (!strcmp(s, ",") || !strcmp(s, ")"))) {
                    if (na == 64)
                        return fail("macro %s: expected at most 64 arguments", m->name);
                    lo[na] = start, hi[na++] = j;
                    start = j + 1;
                    if (!strcmp(s, ")"))
                        break;
                }
            }
            if (m->nparams == 0 && na == 1 && lo[0] == hi[0])
                na = 0;
            if (j >= n || na != m->nparams)
                return fail("macro %s: expected %d arguments and ')'", m->name, m->nparams);
            if (!(args = calloc((size_t)na + 1, sizeof *args)))
                return -1;
            for (k = 0; k < na; k++)
                if (expand(t, in + lo[k], hi[k] - lo[k], h, &args[k]))
                    return -1;
            for (k = 0; k < m->body.n; k++) {
                int p;
                for (p = 0; p < m->nparams && strcmp(m->body.v[k], m->params[p]); p++)
                    ;
                if (p < m->nparams) {
                    int a;
                    for (a = 0; a < args[p].n; a++)
                        if (tokv_add(&sub, args[p].v[a]))
                            return -1;
                } else if (tokv_add(&sub, m->body.v[k]))
                    return -1;
            }
            rc = expand(t, sub.v, sub.n, &inner, out);
            tokv_free(&sub);
            for (k = 0; k < m->nparams; k++)
                tokv_free(&args[k]);
            free(args);
            if (rc)
                return -1;
            i = j;
        }
    }
    return 0;
}

/* #if expressions: precedence climbing over the expanded tokens. */
typedef struct cexpr {
    char **v;
    int n, i;
} cexpr;

static long ce_binary(cexpr *e, int level);
static long ce_unary(cexpr *e)
{
    const char *s = e->i < e->n ? e->v[e->i] : "";
    e->i++;
    if (!strcmp(s, "!"))
        return !ce_unary(e);
    if (!strcmp(s, "-"))
        return -ce_unary(e);
    if (!strcmp(s, "+"))
        return ce_unary(e);
    if (!strcmp(s, "(")) {
        long v = ce_binary(e, 0);
        e->i++; /* ')' */
        return v;
    }
    return isdigit((unsigned char)s[0]) ? strtol(s, NULL, 0) : 0;
}
static int ce_level(const char *s)
{
    static const char *const ops[][4] = {{"||"}, {"&&"}, {"==", "!="}, {"<", ">", "<=", ">="}, {"+", "-"},
                                         {"*", "/", "%"}};
    int l, k;
    for (l = 0; l < 6; l++)
        for (k = 0; k < 4 && ops[l][k]; k++)
            if (!strcmp(s, ops[l][k]))
                return l;
    return -1;
}
static long ce_binary(cexpr *e, int level)
{
    long a = ce_unary(e), b;
    for (;;) {
        const char *op = e->i < e->n ? e->v[e->i] : "";
        int l = ce_level(op);
        if (l < level)
            return a;
        e->i++;
        b = ce_binary(e, l + 1);
        switch (op[0]) {
        case '|': a = a || b; break;
        case '&': a = a && b; break;
        case '=': a = a == b; break;
        case '!': a = a != b; break;
        case '<': a = op[1] ? a <= b : a < b; break;
        case '>': a = op[1] ? a >= b : a > b; break;
        case '+': a = a + b; break;
        case '-': a = a - b; break;
        case '*': a = a * b; break;
        case '/': a = b ? a / b : 0; break;
        default: a = b ? a % b : 0; break;
        }
    }
}

static int eval_if(wgsl_tr *t, const char *s, long *v)
{
    tokv raw = {0}, def = {0}, x = {0};
    cexpr e;
    int i;
    if (lex(s, strlen(s), &raw))
        return -1;
    for (i = 0; i < raw.n; i++) {
        if (!strcmp(raw.v[i], "defined")) {
            int paren = i + 1 < raw.n && !strcmp(raw.v[i + 1], "(");
            const char *name = i + 1 + paren < raw.n ? raw.v[i + 1 + paren] : "";
            if (tokv_add(&def, find_macro(t, name) ? "1" : "0"))
                return -1;
            i += 1 + 2 * paren;
        } else if (tokv_add(&def, raw.v[i]))
            return -1;
    }
    if (expand(t, def.v, def.n, NULL, &x))
        return -1;
    e.v = x.v, e.n = x.n, e.i = 0;
    *v = ce_binary(&e, 0);
    tokv_free(&raw);
    tokv_free(&def);
    tokv_free(&x);
    return 0;
}

/* The source without comments, each replaced by a space (newlines kept),
 * and with backslash-newline joined. */
static char *strip(const char *s)
{
    size_t n = strlen(s), i = 0, o = 0;
    char *r = malloc(n + 1);
    if (!r)
        return NULL;
    while (i < n) {
        if (s[i] == '/' && s[i + 1] == '*') {
            for (i += 2; i < n && !(s[i] == '*' && s[i + 1] == '/'); i++)
                if (s[i] == '\n')
                    r[o++] = '\n';
            i += 2;
            r[o++] = ' ';
        } else if (s[i] == '/' && s[i + 1] == '/') {
            while (i < n && s[i] != '\n')
                i++;
        } else if (s[i] == '\\' && s[i + 1] == '\n') {
            i += 2;
        } else
            r[o++] = s[i++];
    }
    r[o] = 0;
    return r;
}

#define MAX_IF 64
/* Preprocess src with t's macros into out (the text outside directives,
 * expanded). */
static int preprocess(wgsl_tr *t, const char *src, tokv *out)
{
    char *text = strip(src), *line, *next;
    /* per #if level: whether its group is active, and whether one of its
     * groups was taken */
    int active[MAX_IF + 1], taken[MAX_IF + 1], depth = 0, rc = 0;
    tokv pend = {0};
    if (!text)
        return fail("out of memory");
    active[0] = 1, taken[0] = 1;
    for (line = text; line && !rc; line = next) {
        char *p = line, word[16];
        int w = 0;
        if ((next = strchr(line, '\n')))
            *next++ = 0;
        while (isspace((unsigned char)*p))
            p++;
        if (*p != '#') {
            if (active[depth] && lex(p, strlen(p), &pend))
                rc = fail("out of memory");
            continue;
        }
        /* a directive: the text before it is complete */
        if (pend.n && (rc = expand(t, pend.v, pend.n, NULL, out)))
            break;
        tokv_clear(&pend);
        for (p++; isspace((unsigned char)*p); p++)
            ;
        while (isalpha((unsigned char)*p) && w < 15)
            word[w++] = *p++;
        word[w] = 0;
        if (!strcmp(word, "if") || !strcmp(word, "ifdef") || !strcmp(word, "ifndef")) {
            long v = 0;
            if (depth == MAX_IF) {
                rc = fail("#if nested deeper than %d", MAX_IF);
                break;
            }
            if (active[depth]) {
                if (word[2] == 0)
                    rc = eval_if(t, p, &v);
                else {
                    char name[128];
                    if (sscanf(p, " %127[A-Za-z0-9_]", name) != 1)
                        name[0] = 0;
                    v = (find_macro(t, name) != NULL) == (word[2] == 'd');
                }
            }
            depth++;
            active[depth] = active[depth - 1] && v;
            taken[depth] = !active[depth - 1] || v;
        } else if (!strcmp(word, "elif")) {
            long v = 0;
            if (!depth) {
                rc = fail("#elif without #if");
                break;
            }
            if (!taken[depth])
                rc = eval_if(t, p, &v);
            active[depth] = !taken[depth] && v;
            taken[depth] = taken[depth] || v;
        } else if (!strcmp(word, "else")) {
            if (!depth) {
                rc = fail("#else without #if");
                break;
            }
            active[depth] = !taken[depth];
            taken[depth] = 1;
        } else if (!strcmp(word, "endif")) {
            if (!depth) {
                rc = fail("#endif without #if");
                break;
            }
            depth--;
        } else if (!active[depth]) {
            continue;
        } else if (!strcmp(word, "define")) {
            rc = define(t, p);
        } else if (!strcmp(word, "undef")) {
            char name[128];
            if (sscanf(p, " %127[A-Za-z0-9_]", name) == 1)
                undef(t, name);
        } else if (!strcmp(word, "error")) {
            rc = fail("#error%s", p);
        } /* #version, #extension, #pragma: nothing for WGSL */
    }
    if (!rc && depth)
        rc = fail("expected #endif");
    if (!rc && pend.n)
        rc = expand(t, pend.v, pend.n, NULL, out);
    tokv_free(&pend);
    free(text);
    return rc;
}

/* ------------------------------------------------------------- types */

/* What conversions need of a value's type. WGSL converts nothing
 * implicitly but its abstract literals, so where the source mixes
 * precisions (FRESNEL_MP and FRESNEL_HP: f16 and f32 when --wgsl-f16
 * spells FRESNEL_MP f16) the translator writes GLSL's implicit conversions
 * out: an operation between the two is done in f32 (GLSL: the higher
 * precision of its operands), and a value is converted to the type of the
 * parameter, variable or result it goes to. */
enum { E_ABSTRACT, E_INT, E_BOOL, E_F32, E_F16 };
struct ty {
    unsigned char e, n, arr; /* element, components 1-4, an array of them */
};

/* A GLSL type name's type; 0 when s is none. */
static int glsl_ty(const char *s, ty *out)
{
    static const struct {
        const char *name;
        unsigned char e, n;
    } map[] = {{"float", E_F32, 1},     {"vec2", E_F32, 2},    {"vec3", E_F32, 3},    {"vec4", E_F32, 4},
               {"float16_t", E_F16, 1}, {"f16vec2", E_F16, 2}, {"f16vec3", E_F16, 3}, {"f16vec4", E_F16, 4},
               {"int", E_INT, 1},       {"bool", E_BOOL, 1}};
    unsigned i;
    for (i = 0; i < sizeof map / sizeof map[0]; i++)
        if (!strcmp(s, map[i].name)) {
            out->e = map[i].e, out->n = map[i].n, out->arr = 0;
            return 1;
        }
    return 0;
}

/* WGSL's name of the float type of element e with n components. */
static const char *float_name(int e, int n)
{
    static const char *const f32[] = {"f32", "vec2f", "vec3f", "vec4f"}, *const f16[] = {"f16", "vec2h", "vec3h", "vec4h"};
    return (e == E_F16 ? f16 : f32)[n >= 1 && n <= 4 ? n - 1 : 0];
}

/* The type of an arithmetic operation (or a builtin's arguments) on a and
 * b: abstract takes the other's element, f16 with f32 is f32, a scalar
 * with a vector the vector. */
static ty unify(ty a, ty b)
{
    ty r;
    r.arr = 0;
    r.n = a.n > b.n ? a.n : b.n;
    if (a.e == E_ABSTRACT)
        r.e = b.e;
    else if (b.e == E_ABSTRACT)
        r.e = a.e;
    else if ((a.e == E_F16 && b.e == E_F32) || (a.e == E_F32 && b.e == E_F16))
        r.e = E_F32;
    else
        r.e = a.e;
    return r;
}

struct sym {
    char *name;
    ty type;
};
struct fnsig {
    char *name;
    ty ret;
    int np;
    ty p[32];
};

/* ---------------------------------------------------------- translator */

/* WGSL's name for a GLSL type or constructor, or NULL. */
static const char *wgsl_type(const char *s)
{
    static const char *const map[][2] = {{"float", "f32"},     {"vec2", "vec2f"},    {"vec3", "vec3f"},
                                         {"vec4", "vec4f"},    {"float16_t", "f16"}, {"f16vec2", "vec2h"},
                                         {"f16vec3", "vec3h"}, {"f16vec4", "vec4h"}, {"int", "i32"},
                                         {"bool", "bool"}};
    unsigned i;
    for (i = 0; i < sizeof map / sizeof map[0]; i++)
        if (!strcmp(s, map[i][0]))
            return map[i][1];
    return NULL;
}

/* Output text with C-like spacing between tokens. */
typedef struct out {
    FILE *f;
    const char *prev; /* the last token written, "" at a line's start */
    int prev_unary;
} out;

static int is_op(const char *s) { return !is_ident(s) && !isdigit((unsigned char)s[0]) && s[0] != '.'; }

static void put(out *o, const char *s)
{
    const char *p = o->prev;
    int unary = 0;
    if ((!strcmp(s, "-") || !strcmp(s, "!") || !strcmp(s, "+")) &&
        (!*p || !strcmp(p, "return") || (is_op(p) && strcmp(p, ")") && strcmp(p, "]"))))
        unary = 1;
    if (*p && strcmp(p, "(") && strcmp(p, "[") && strcmp(p, ".") && !o->prev_unary && strcmp(s, ")") &&
        strcmp(s, "]") && strcmp(s, ",") && strcmp(s, ";") && strcmp(s, ".") && strcmp(s, "[") &&
        !(!strcmp(s, "(") && !is_op(p) && strcmp(p, "if") && strcmp(p, "return")))
        fputc(' ', o->f);
    fputs(s, o->f);
    o->prev = s, o->prev_unary = unary;
}
static void newline(out *o, int indent)
{
    fputc('\n', o->f);
    while (indent-- > 0)
        fputs("    ", o->f);
    o->prev = "", o->prev_unary = 0;
}

typedef struct tr {
    char **v;
    int n;
    out o;
    wgsl_tr *w;
    struct {
        const char *name;
        ty type;
    } loc[256]; /* the function's parameters and variables */
    int nloc;
    ty ret; /* the function's result */
} tr;

static int eq(const tr *t, int i, const char *s) { return i < t->n && !strcmp(t->v[i], s); }

/* The index of the bracket closing the one at i, or -1. */
static int closing(const tr *t, int i)
{
    int depth = 0;
    for (; i < t->n; i++) {
        const char *s = t->v[i];
        if (!strcmp(s, "(") || !strcmp(s, "[") || !strcmp(s, "{"))
            depth++;
        else if ((!strcmp(s, ")") || !strcmp(s, "]") || !strcmp(s, "}")) && --depth == 0)
            return i;
    }
    return -1;
}

/* The first token in [a, b) at bracket depth 0 that is one of ops, or b. */
static int top_level(const tr *t, int a, int b, const char *const *ops)
{
    int depth = 0, i, k;
    for (i = a; i < b; i++) {
        const char *s = t->v[i];
        if (!strcmp(s, "(") || !strcmp(s, "[") || !strcmp(s, "{"))
            depth++;
        else if (!strcmp(s, ")") || !strcmp(s, "]") || !strcmp(s, "}"))
            depth--;
        else if (depth == 0)
            for (k = 0; ops[k]; k++)
                if (!strcmp(s, ops[k]))
                    return i;
    }
    return b;
}

static const char *const assign_ops[] = {"=", "+=", "-=", "*=", "/=", NULL};

/* ------------------------------------------------------- expressions */

static int ex(tr *t, int a, int b, int emit, ty *out);

/* The opening bracket of the one closing at c, searching from a; -1. */
static int opening(const tr *t, int c, int a)
{
    int depth = 0, i;
    for (i = c; i >= a; i--) {
        const char *s = t->v[i];
        if (!strcmp(s, ")") || !strcmp(s, "]") || !strcmp(s, "}"))
            depth++;
        else if ((!strcmp(s, "(") || !strcmp(s, "[") || !strcmp(s, "{")) && --depth == 0)
            return i;
    }
    return -1;
}

/* The precedence of the binary operator at i of [a, ...), lowest 1; 0 when
 * the token is no binary operator there (a sign, or not an operator). */
static int binary_level(const tr *t, int i, int a)
{
    static const char *const levels[][5] = {{"||"}, {"&&"}, {"==", "!="}, {"<", ">", "<=", ">="}, {"+", "-"},
                                            {"*", "/", "%"}};
    const char *s = t->v[i], *p;
    unsigned l, k;
    if (i == a)
        return 0;
    p = t->v[i - 1];
    if (!(is_ident(p) || isdigit((unsigned char)p[0]) || p[0] == '.' || !strcmp(p, ")") || !strcmp(p, "]")))
        return 0;
    for (l = 0; l < sizeof levels / sizeof levels[0]; l++)
        for (k = 0; k < 5 && levels[l][k]; k++)
            if (!strcmp(s, levels[l][k]))
                return (int)l + 1;
    return 0;
}

/* [a, b) printed (when emit) as element e where it is a float of the other
 * precision; *out its type before any conversion. e is E_ABSTRACT for "as
 * it is". */
static int ex_as(tr *t, int a, int b, int emit, int e, ty *out)
{
    ty x;
    if (ex(t, a, b, 0, &x))
        return -1;
    if (out)
        *out = x;
    if (!emit)
        return 0;
    if ((e == E_F16 || e == E_F32) && (x.e == E_F16 || x.e == E_F32) && x.e != e && !x.arr) {
        put(&t->o, float_name(e, x.n));
        put(&t->o, "(");
        if (ex(t, a, b, 1, NULL))
            return -1;
        put(&t->o, ")");
        return 0;
    }
    return ex(t, a, b, 1, NULL);
}

static const fnsig *find_fn(const wgsl_tr *w, const char *name)
{
    int i;
    for (i = 0; i < w->nf; i++)
        if (!strcmp(w->f[i].name, name))
            return &w->f[i];
    return NULL;
}

/* The builtins the source calls: their arguments take one type (but
 * select's condition), their result that type, dot's its element. */
static int is_builtin(const char *s)
{
    static const char *const names[] = {"clamp", "min",  "max",   "pow", "saturate", "sqrt", "floor", "exp",
                                        "dot",   "abs",  "select", "fma", "sin",      "cos",  "exp2",  "log2",
                                        "sign",  "fract", "ceil",  "round", "trunc",  NULL};
    int i;
    for (i = 0; names[i]; i++)
        if (!strcmp(s, names[i]))
            return 1;
    return 0;
}

/* A call name(args) over [a, b): b - 1 is its ')', o its '('. */
static int call(tr *t, int a, int o, int b, int emit, ty *out)
{
    static const char *const comma[] = {",", NULL};
    const char *name = t->v[a];
    const fnsig *sig = find_fn(t->w, name);
    ty args[32], u, r;
    int ends[33], na = 0, p, k, ctor, builtin = is_builtin(name);
    if (o != a + 1 || !is_ident(name))
        return fail("expected a function name before '(' at '%s'", name);
    ctor = glsl_ty(name, &r);
    if (!sig && !ctor && !builtin)
        return fail("unknown function %s", name);
    ends[0] = o;
    for (p = o + 1; p < b - 1 && na < 32; na++) {
        int e = top_level(t, p, b - 1, comma);
        if (ex(t, p, e, 0, &args[na]))
            return -1;
        ends[na + 1] = e;
        p = e + 1;
    }
    if (p < b - 1)
        return fail("%s: expected at most 32 arguments", name);
    u = na ? args[0] : r;
    for (k = 1; k < na && !(builtin && !strcmp(name, "select") && k == 2); k++)
        u = unify(u, args[k]);
    if (sig) {
        if (na != sig->np)
            return fail("%s: expected %d arguments, got %d", name, sig->np, na);
        r = sig->ret;
    } else if (builtin) {
        r = u;
        if (!strcmp(name, "dot"))
            r.n = 1;
    }
    if (out)
        *out = r;
    if (!emit)
        return 0;
    put(&t->o, ctor ? wgsl_type(name) : name);
    put(&t->o, "(");
    for (k = 0; k < na; k++) {
        /* a user function's argument as its parameter; a builtin's as the
         * others; a constructor of several as its element (one argument:
         * the constructor is the conversion) */
        int e = sig ? sig->p[k].e : builtin ? (k == 2 && !strcmp(name, "select") ? E_ABSTRACT : u.e)
                                             : na > 1 ? r.e : E_ABSTRACT;
        if (ex_as(t, ends[k] + 1, ends[k + 1], 1, e, NULL))
            return -1;
        if (k + 1 < na)
            put(&t->o, ",");
    }
    put(&t->o, ")");
    return 0;
}

/* The type of a name: a local, then a module-scope value. */
static int name_ty(const tr *t, const char *s, ty *out)
{
    int i;
    for (i = t->nloc - 1; i >= 0; i--)
        if (!strcmp(t->loc[i].name, s)) {
            *out = t->loc[i].type;
            return 0;
        }
    for (i = 0; i < t->w->ng; i++)
        if (!strcmp(t->w->g[i].name, s)) {
            *out = t->w->g[i].type;
            return 0;
        }
    return fail("unknown name %s", s);
}

/* The expression [a, b), printed in WGSL when emit, its type in *out:
 * ?: as select(else, then, condition), binary operators split at the
 * lowest precedence (rightmost: left to right), then signs, calls, [],
 * swizzles, brackets, names and literals. */
static int ex(tr *t, int a, int b, int emit, ty *out)
{
    static const char *const q[] = {"?", NULL};
    ty x, y, u;
    int i, best = 0, at = -1, depth = 0;
    if (a >= b)
        return fail("expected an expression");
    if ((i = top_level(t, a, b, q)) < b) {
        int nest = 0, j;
        for (j = i + 1; j < b; j++) {
            const char *s = t->v[j];
            if (!strcmp(s, "(") || !strcmp(s, "["))
                depth++;
            else if (!strcmp(s, ")") || !strcmp(s, "]"))
                depth--;
            else if (depth == 0 && !strcmp(s, "?"))
                nest++;
            else if (depth == 0 && !strcmp(s, ":") && nest-- == 0)
                break;
        }
        if (j >= b)
            return fail("expected ':' after '?'");
        if (ex(t, i + 1, j, 0, &x) || ex(t, j + 1, b, 0, &y))
            return -1;
        u = unify(x, y);
        if (out)
            *out = u;
        if (!emit)
            return 0;
        put(&t->o, "select");
        put(&t->o, "(");
        if (ex_as(t, j + 1, b, 1, u.e, NULL))
            return -1;
        put(&t->o, ",");
        if (ex_as(t, i + 1, j, 1, u.e, NULL))
            return -1;
        put(&t->o, ",");
        if (ex(t, a, i, 1, NULL))
            return -1;
        put(&t->o, ")");
        return 0;
    }
    for (i = a; i < b; i++) {
        const char *s = t->v[i];
        int l;
        if (!strcmp(s, "(") || !strcmp(s, "["))
            depth++;
        else if (!strcmp(s, ")") || !strcmp(s, "]"))
            depth--;
        else if (!strcmp(s, "++") || !strcmp(s, "--") || !strcmp(s, "{") || !strcmp(s, ";") || !strcmp(s, "="))
            return fail("expected an expression without '%s'", s);
        else if (depth == 0 && (l = binary_level(t, i, a)) && (!best || l <= best))
            best = l, at = i;
    }
    if (at >= 0) {
        int cmp = best == 3 || best == 4, logic = best <= 2;
        if (ex(t, a, at, 0, &x) || ex(t, at + 1, b, 0, &y))
            return -1;
        u = unify(x, y);
        if (out) {
            *out = u;
            if (cmp || logic)
                out->e = E_BOOL, out->n = 1;
        }
        if (!emit)
            return 0;
        return ex_as(t, a, at, 1, logic ? E_ABSTRACT : u.e, NULL) || (put(&t->o, t->v[at]), 0) ||
                       ex_as(t, at + 1, b, 1, logic ? E_ABSTRACT : u.e, NULL)
                   ? -1
                   : 0;
    }
    if (!strcmp(t->v[a], "-") || !strcmp(t->v[a], "+") || !strcmp(t->v[a], "!")) {
        if (emit)
            put(&t->o, t->v[a]);
        return ex(t, a + 1, b, emit, out);
    }
    if (!strcmp(t->v[b - 1], ")") || !strcmp(t->v[b - 1], "]")) {
        int o = opening(t, b - 1, a);
        if (o < 0)
            return fail("expected the bracket before '%s' to open", t->v[b - 1]);
        if (!strcmp(t->v[b - 1], ")") && o == a) { /* (e) */
            if (emit)
                put(&t->o, "(");
            if (ex(t, a + 1, b - 1, emit, out))
                return -1;
            if (emit)
                put(&t->o, ")");
            return 0;
        }
        if (!strcmp(t->v[b - 1], ")"))
            return call(t, a, o, b, emit, out);
        /* e[i]: an array's element or a vector's component */
        if (ex(t, a, o, emit, &x))
            return -1;
        if (emit)
            put(&t->o, "[");
        if (ex(t, o + 1, b - 1, emit, NULL))
            return -1;
        if (emit)
            put(&t->o, "]");
        if (x.arr)
            x.arr = 0;
        else
            x.n = 1;
        if (out)
            *out = x;
        return 0;
    }
    if (b - a >= 3 && !strcmp(t->v[b - 2], ".") && is_ident(t->v[b - 1])) { /* a swizzle */
        if (ex(t, a, b - 2, emit, &x))
            return -1;
        if (emit) {
            put(&t->o, ".");
            put(&t->o, t->v[b - 1]);
        }
        x.n = (unsigned char)strlen(t->v[b - 1]);
        if (out)
            *out = x;
        return 0;
    }
    if (b - a != 1)
        return fail("expected an operator or ';' after '%s'", t->v[a]);
    {
        const char *s = t->v[a];
        if (isdigit((unsigned char)s[0]) || s[0] == '.') {
            x.e = s[strlen(s) - 1] == 'u' ? E_INT : E_ABSTRACT, x.n = 1, x.arr = 0;
        } else if (!strcmp(s, "true") || !strcmp(s, "false")) {
            x.e = E_BOOL, x.n = 1, x.arr = 0;
        } else if (!is_ident(s) || name_ty(t, s, &x))
            return fail("expected a value, got '%s'", s);
        if (emit)
            put(&t->o, s);
        if (out)
            *out = x;
    }
    return 0;
}

static int expr(tr *t, int a, int b) { return ex(t, a, b, 1, NULL); }

/* The end (index of ';') of the statement starting at i, or -1. */
static int stmt_end(const tr *t, int i, int b)
{
    static const char *const semi[] = {";", NULL};
    int e = top_level(t, i, b, semi);
    return e < b ? e : -1;
}

static int stmts(tr *t, int a, int b, int indent);

static int add_local(tr *t, const char *name, ty type)
{
    if (t->nloc == (int)(sizeof t->loc / sizeof t->loc[0]))
        return fail("expected at most %d parameters and variables in a function",
                    (int)(sizeof t->loc / sizeof t->loc[0]));
    t->loc[t->nloc].name = name, t->loc[t->nloc].type = type;
    t->nloc++;
    return 0;
}

/* The statement at i (within [i, b)) at indent; *next past it. */
static int stmt(tr *t, int i, int b, int indent, int *next)
{
    const char *s = t->v[i], *w = wgsl_type(s);
    int e;
    ty decl;
    if (!strcmp(s, ";")) {
        *next = i + 1;
        return 0;
    }
    if (!strcmp(s, "{")) {
        int c = closing(t, i);
        if (c < 0 || c >= b)
            return fail("expected '}'");
        newline(&t->o, indent);
        put(&t->o, "{");
        if (stmts(t, i + 1, c, indent + 1))
            return -1;
        newline(&t->o, indent);
        put(&t->o, "}");
        *next = c + 1;
        return 0;
    }
    if (!strcmp(s, "if")) {
        int c = eq(t, i + 1, "(") ? closing(t, i + 1) : -1, n;
        if (c < 0 || c >= b)
            return fail("expected (condition) after if");
        newline(&t->o, indent);
        put(&t->o, "if");
        put(&t->o, "(");
        if (expr(t, i + 2, c))
            return -1;
        put(&t->o, ")");
        put(&t->o, "{");
        /* WGSL requires braces: a single statement gets them */
        if (eq(t, c + 1, "{")) {
            int cc = closing(t, c + 1);
            if (cc < 0 || stmts(t, c + 2, cc, indent + 1))
                return -1;
            n = cc + 1;
        } else if (c + 1 >= b || stmt(t, c + 1, b, indent + 1, &n))
            return fail("expected a statement after if (...)");
        if (eq(t, n, "else")) {
            newline(&t->o, indent);
            put(&t->o, "}");
            put(&t->o, "else");
            put(&t->o, "{");
            if (eq(t, n + 1, "{")) {
                int cc = closing(t, n + 1);
                if (cc < 0 || stmts(t, n + 2, cc, indent + 1))
                    return -1;
                n = cc + 1;
            } else if (n + 1 >= b || stmt(t, n + 1, b, indent + 1, &n))
                return fail("expected a statement after else");
        }
        newline(&t->o, indent);
        put(&t->o, "}");
        *next = n;
        return 0;
    }
    if ((e = stmt_end(t, i, b)) < 0)
        return fail("expected ';' after '%s'", s);
    *next = e + 1;
    if (!strcmp(s, "return")) {
        newline(&t->o, indent);
        put(&t->o, "return");
        if (e > i + 1 && ex_as(t, i + 1, e, 1, t->ret.e, NULL))
            return -1;
        put(&t->o, ";");
        return 0;
    }
    if (!strcmp(s, "const"))
        return fail("expected no local const (not in the subset)");
    if (w && glsl_ty(s, &decl)) {
        /* T a, b = e, ...; -> var a: T; var b: T = e; ... */
        static const char *const comma[] = {",", NULL};
        int p = i + 1;
        while (p < e) {
            int d = top_level(t, p, e, comma);
            if (!is_ident(t->v[p]) || (d > p + 1 && !eq(t, p + 1, "=")))
                return fail("expected NAME or NAME = value in a declaration of %s, got '%s'", s, t->v[p]);
            if (add_local(t, t->v[p], decl))
                return -1;
            newline(&t->o, indent);
            put(&t->o, "var");
            put(&t->o, t->v[p]);
            fputs(": ", t->o.f);
            fputs(w, t->o.f);
            t->o.prev = w;
            if (d > p + 1) {
                put(&t->o, "=");
                if (ex_as(t, p + 2, d, 1, decl.e, NULL))
                    return -1;
            }
            put(&t->o, ";");
            p = d + 1;
        }
        return 0;
    }
    if (!strcmp(s, "for") || !strcmp(s, "while") || !strcmp(s, "do") || !strcmp(s, "switch"))
        return fail("expected no '%s' (not in the subset)", s);
    {
        int a = top_level(t, i, e, assign_ops);
        ty lhs;
        newline(&t->o, indent);
        if (ex(t, i, a, 0, &lhs) || expr(t, i, a))
            return -1;
        if (a < e) {
            put(&t->o, t->v[a]);
            if (ex_as(t, a + 1, e, 1, lhs.e, NULL))
                return -1;
        }
        put(&t->o, ";");
    }
    return 0;
}

static int stmts(tr *t, int a, int b, int indent)
{
    int i = a;
    while (i < b)
        if (stmt(t, i, b, indent, &i))
            return -1;
    return 0;
}

/* Whether the body [a, b) assigns to name. */
static int assigns(const tr *t, int a, int b, const char *name)
{
    int i, k;
    for (i = a; i + 1 < b; i++)
        if (!strcmp(t->v[i], name) && (i == a || strcmp(t->v[i - 1], ".")))
            for (k = 0; assign_ops[k]; k++)
                if (!strcmp(t->v[i + 1], assign_ops[k]))
                    return 1;
    return 0;
}

/* Every function definition of the token list. */
/* Records function name's signature (a later definition replaces a
 * prototype's). */
static int add_fn(wgsl_tr *w, const char *name, const fnsig *sig)
{
    fnsig *f = (fnsig *)find_fn(w, name);
    if (!f) {
        if (w->nf == w->capf) {
            int cap = w->capf ? 2 * w->capf : 64;
            fnsig *v = realloc(w->f, (size_t)cap * sizeof *v);
            if (!v)
                return fail("out of memory");
            w->f = v, w->capf = cap;
        }
        f = &w->f[w->nf];
        if (!(f->name = malloc(strlen(name) + 1)))
            return fail("out of memory");
        strcpy(f->name, name);
        w->nf++;
    }
    f->ret = sig->ret, f->np = sig->np;
    memcpy(f->p, sig->p, sizeof f->p);
    return 0;
}

/* Every function definition of the token list. */
static int functions(tr *t)
{
    int i = 0;
    while (i < t->n) {
        const char *rt = wgsl_type(t->v[i]), *name;
        int p, close, body, end = -1, mutated[32], np = 0, k, proto;
        fnsig sig;
        if (!rt || !glsl_ty(t->v[i], &sig.ret) || i + 2 >= t->n || !is_ident(t->v[i + 1]) || !eq(t, i + 2, "("))
            return fail("expected a function definition, got '%s %s'", t->v[i], i + 1 < t->n ? t->v[i + 1] : "");
        name = t->v[i + 1];
        if ((close = closing(t, i + 2)) < 0)
            return fail("%s: expected ')'", name);
        proto = eq(t, close + 1, ";"); /* a prototype: WGSL needs none, its calls its signature */
        if (!proto && (!eq(t, close + 1, "{") || (end = closing(t, close + 1)) < 0))
            return fail("%s: expected a body", name);
        body = close + 2;
        t->nloc = 0;
        if (!proto)
            fprintf(t->o.f, "fn %s(", name);
        for (p = i + 3; p < close; np++) {
            const char *pt = wgsl_type(t->v[p]), *pn = p + 1 < close ? t->v[p + 1] : "";
            if (np == 32)
                return fail("%s: expected at most 32 parameters", name);
            if (!pt || !glsl_ty(t->v[p], &sig.p[np]) || !is_ident(pn))
                return fail("%s: expected a parameter TYPE NAME, got '%s'", name, t->v[p]);
            mutated[np] = !proto && assigns(t, body, end, pn);
            if (!proto)
                fprintf(t->o.f, "%s%s%s: ", np ? ", " : "", pn, mutated[np] ? "_in" : "");
            if (eq(t, p + 2, "[")) { /* T name[N] */
                if (p + 4 >= close || !eq(t, p + 4, "]"))
                    return fail("%s: expected [N] after %s", name, pn);
                if (!proto)
                    fprintf(t->o.f, "array<%s, %s>", pt, t->v[p + 3]);
                sig.p[np].arr = 1;
                p += 3;
            } else if (!proto)
                fputs(pt, t->o.f);
            if (add_local(t, pn, sig.p[np]))
                return -1;
            p += 2;
            if (p < close && !eq(t, p, ","))
                return fail("%s: expected ',' after parameter %s", name, pn);
            p++;
        }
        sig.np = np;
        if (add_fn(t->w, name, &sig))
            return -1;
        if (proto) {
            i = close + 2;
            continue;
        }
        t->ret = sig.ret;
        fprintf(t->o.f, ") -> %s {", rt);
        for (p = i + 3, k = 0; k < np; k++) {
            /* WGSL parameters are immutable: the one the body assigns is a copy */
            if (mutated[k])
                fprintf(t->o.f, "\n    var %s = %s_in;", t->v[p + 1], t->v[p + 1]);
            p += eq(t, p + 2, "[") ? 6 : 3;
        }
        t->o.prev = "";
        if (stmts(t, body, end, 1))
            return fail("in function %s", name);
        fputs("\n}\n", t->o.f);
        i = end + 1;
    }
    return 0;
}

/* ------------------------------------------------------------- API */

wgsl_tr *wgsl_tr_new(int f16)
{
    /* WGSL's spellings of the shader names (fresnel.glsl, OTHER LANGUAGES):
     * binary32, or with f16 the mediump-safe functions' values in f16 (the
     * translator's names for it are GLSL's float16_t and f16vec3); no
     * precision qualifiers. */
    static const char *const spellings[] = {
        "FRESNEL_WGSL 1",    "FRESNEL_HP float",  "FRESNEL_HP2 vec2", "FRESNEL_HP3 vec3",
        "FRESNEL_VEC2 vec2", "FRESNEL_VEC3 vec3", "FRESNEL_SATURATE(x) saturate(x)"};
    wgsl_tr *t = calloc(1, sizeof *t);
    unsigned i;
    int rc = !t;
    for (i = 0; !rc && i < sizeof spellings / sizeof spellings[0]; i++)
        rc = define(t, spellings[i]);
    if (!rc)
        rc = define(t, f16 ? "FRESNEL_MP float16_t" : "FRESNEL_MP float") ||
             define(t, f16 ? "FRESNEL_MP3 f16vec3" : "FRESNEL_MP3 vec3");
    if (rc) {
        wgsl_tr_free(t);
        return NULL;
    }
    return t;
}

int wgsl_tr_declare(wgsl_tr *t, const char *name, const char *glsl_type, int array)
{
    sym *g;
    if (t->ng == t->capg) {
        int cap = t->capg ? 2 * t->capg : 64;
        sym *v = realloc(t->g, (size_t)cap * sizeof *v);
        if (!v)
            return fail("out of memory");
        t->g = v, t->capg = cap;
    }
    g = &t->g[t->ng];
    if (!glsl_ty(glsl_type, &g->type))
        return fail("%s: unknown type %s", name, glsl_type);
    g->type.arr = array != 0;
    if (!(g->name = malloc(strlen(name) + 1)))
        return fail("out of memory");
    strcpy(g->name, name);
    t->ng++;
    return 0;
}

void wgsl_tr_free(wgsl_tr *t)
{
    int i;
    if (!t)
        return;
    for (i = 0; i < t->nm; i++)
        macro_free(&t->m[i]);
    for (i = 0; i < t->nf; i++)
        free(t->f[i].name);
    for (i = 0; i < t->ng; i++)
        free(t->g[i].name);
    free(t->m);
    free(t->f);
    free(t->g);
    free(t);
}

int wgsl_tr_text(wgsl_tr *t, const char *glsl, FILE *f)
{
    tokv toks = {0};
    tr x;
    int rc = preprocess(t, glsl, &toks);
    if (!rc) {
        x.v = toks.v, x.n = toks.n;
        x.o.f = f, x.o.prev = "", x.o.prev_unary = 0;
        x.w = t, x.nloc = 0;
        rc = functions(&x);
    }
    tokv_free(&toks);
    return rc;
}

/* The tool carries ports/glsl/fresnel.glsl (build/embed/viewer_assets.c,
 * gen/viewer/embed.sh; the viewer's page uses the same copy), so the
 * translation reads no file at run time. */
extern const unsigned char viewer_glsl_port[];
const char *wgsl_glsl_port(void) { return (const char *)viewer_glsl_port; }
