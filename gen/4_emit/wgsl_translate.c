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
 *    (float f32, vec3 vec3f, int i32). Anything else (loops, local arrays,
 *    a global declaration) is refused with a message, so a construct the
 *    source gains later is reported rather than mistranslated. */
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

struct wgsl_tr {
    macro *m;
    int nm, capm;
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

/* ---------------------------------------------------------- translator */

/* WGSL's name for a GLSL type or constructor, or NULL. */
static const char *wgsl_type(const char *s)
{
    static const char *const map[][2] = {{"float", "f32"}, {"vec2", "vec2f"}, {"vec3", "vec3f"}, {"vec4", "vec4f"},
                                         {"int", "i32"},   {"bool", "bool"}};
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

/* The expression [a, b): ?: as select(else, then, condition), each
 * bracketed part and each of its comma-separated parts translated alike. */
static int expr(tr *t, int a, int b)
{
    static const char *const q[] = {"?", NULL};
    int i = top_level(t, a, b, q);
    if (a >= b)
        return fail("expected an expression");
    if (i < b) {
        int depth = 0, nest = 0, j;
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
        put(&t->o, "select");
        put(&t->o, "(");
        if (expr(t, j + 1, b))
            return -1;
        put(&t->o, ",");
        if (expr(t, i + 1, j))
            return -1;
        put(&t->o, ",");
        if (expr(t, a, i))
            return -1;
        put(&t->o, ")");
        return 0;
    }
    for (i = a; i < b; i++) {
        const char *s = t->v[i], *w = wgsl_type(s);
        if (!strcmp(s, "(") || !strcmp(s, "[")) {
            static const char *const comma[] = {",", NULL};
            int c = closing(t, i), p;
            if (c < 0 || c >= b)
                return fail("expected the bracket opened before '%s' to close", i + 1 < b ? t->v[i + 1] : "");
            put(&t->o, s);
            for (p = i + 1; p < c;) {
                int e = top_level(t, p, c, comma);
                if (expr(t, p, e))
                    return -1;
                if (e < c)
                    put(&t->o, ",");
                p = e + 1;
            }
            put(&t->o, t->v[c]);
            i = c;
        } else if (!strcmp(s, "++") || !strcmp(s, "--") || !strcmp(s, "{") || !strcmp(s, ";"))
            return fail("expected an expression without '%s'", s);
        else
            put(&t->o, w ? w : s);
    }
    return 0;
}

/* The end (index of ';') of the statement starting at i, or -1. */
static int stmt_end(const tr *t, int i, int b)
{
    static const char *const semi[] = {";", NULL};
    int e = top_level(t, i, b, semi);
    return e < b ? e : -1;
}

static int stmts(tr *t, int a, int b, int indent);

/* The statement at i (within [i, b)) at indent; *next past it. */
static int stmt(tr *t, int i, int b, int indent, int *next)
{
    const char *s = t->v[i], *w = wgsl_type(s);
    int e;
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
        if (e > i + 1 && expr(t, i + 1, e))
            return -1;
        put(&t->o, ";");
        return 0;
    }
    if (!strcmp(s, "const"))
        return fail("expected no local const (not in the subset)");
    if (w) {
        /* T a, b = e, ...; -> var a: T; var b: T = e; ... */
        static const char *const comma[] = {",", NULL};
        int p = i + 1;
        while (p < e) {
            int d = top_level(t, p, e, comma);
            if (!is_ident(t->v[p]) || (d > p + 1 && !eq(t, p + 1, "=")))
                return fail("expected NAME or NAME = value in a declaration of %s, got '%s'", s, t->v[p]);
            newline(&t->o, indent);
            put(&t->o, "var");
            put(&t->o, t->v[p]);
            fputs(": ", t->o.f);
            fputs(w, t->o.f);
            t->o.prev = w;
            if (d > p + 1) {
                put(&t->o, "=");
                if (expr(t, p + 2, d))
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
        newline(&t->o, indent);
        if (expr(t, i, a))
            return -1;
        if (a < e) {
            put(&t->o, t->v[a]);
            if (expr(t, a + 1, e))
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
static int functions(tr *t)
{
    int i = 0;
    while (i < t->n) {
        const char *rt = wgsl_type(t->v[i]), *name;
        int p, close, body, end, mutated[32], np = 0, k;
        if (!rt || i + 2 >= t->n || !is_ident(t->v[i + 1]) || !eq(t, i + 2, "("))
            return fail("expected a function definition, got '%s %s'", t->v[i], i + 1 < t->n ? t->v[i + 1] : "");
        name = t->v[i + 1];
        if ((close = closing(t, i + 2)) < 0)
            return fail("%s: expected ')'", name);
        if (eq(t, close + 1, ";")) { /* a prototype: WGSL needs none */
            i = close + 2;
            continue;
        }
        if (!eq(t, close + 1, "{") || (end = closing(t, close + 1)) < 0)
            return fail("%s: expected a body", name);
        body = close + 2;
        fprintf(t->o.f, "fn %s(", name);
        for (p = i + 3; p < close; np++) {
            const char *pt = wgsl_type(t->v[p]), *pn = p + 1 < close ? t->v[p + 1] : "";
            if (np == 32)
                return fail("%s: expected at most 32 parameters", name);
            if (!pt || !is_ident(pn))
                return fail("%s: expected a parameter TYPE NAME, got '%s'", name, t->v[p]);
            mutated[np] = assigns(t, body, end, pn);
            fprintf(t->o.f, "%s%s%s: ", np ? ", " : "", pn, mutated[np] ? "_in" : "");
            if (eq(t, p + 2, "[")) { /* T name[N] */
                if (p + 4 >= close || !eq(t, p + 4, "]"))
                    return fail("%s: expected [N] after %s", name, pn);
                fprintf(t->o.f, "array<%s, %s>", pt, t->v[p + 3]);
                p += 3;
            } else
                fputs(pt, t->o.f);
            p += 2;
            if (p < close && !eq(t, p, ","))
                return fail("%s: expected ',' after parameter %s", name, pn);
            p++;
        }
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

wgsl_tr *wgsl_tr_new(void)
{
    /* WGSL's spellings of the shader names (fresnel.glsl, OTHER LANGUAGES):
     * binary32 throughout, no precision qualifiers. */
    static const char *const spellings[] = {
        "FRESNEL_WGSL 1",     "FRESNEL_MP float",    "FRESNEL_MP3 vec3",   "FRESNEL_HP float",
        "FRESNEL_HP2 vec2",   "FRESNEL_HP3 vec3",    "FRESNEL_VEC2 vec2",  "FRESNEL_VEC3 vec3",
        "FRESNEL_SATURATE(x) saturate(x)"};
    wgsl_tr *t = calloc(1, sizeof *t);
    unsigned i;
    for (i = 0; t && i < sizeof spellings / sizeof spellings[0]; i++)
        if (define(t, spellings[i])) {
            wgsl_tr_free(t);
            return NULL;
        }
    return t;
}

void wgsl_tr_free(wgsl_tr *t)
{
    int i;
    if (!t)
        return;
    for (i = 0; i < t->nm; i++)
        macro_free(&t->m[i]);
    free(t->m);
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
