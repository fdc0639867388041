/*
 * read_vtk.c - parses a legacy VTK file (.vtk, ASCII or BINARY) holding an
 * UNSTRUCTURED_GRID or a POLYDATA into points, triangles, line cells and
 * their data.
 *
 * Format (VTK file formats, "Simple Legacy Formats"): a version line, a
 * title, ASCII or BINARY, DATASET, then keyword sections. Binary data is
 * big-endian and starts after the newline that ends its keyword line. Cell
 * arrays come in two layouts: before version 5, "CELLS n size" and size
 * integers (count, ids...); from 5.1 (VTK 9 and meshio write it), "CELLS
 * noffsets nconn" then OFFSETS and CONNECTIVITY arrays. Read: triangles
 * (type 5, and polygons with 3 corners), lines and polylines (types 3, 4:
 * each piece a line cell), vertices (1, 2: ignored); SCALARS and FIELD arrays
 * "weight", "marker", "attribute" of POINT_DATA and "marker", "attribute" of
 * CELL_DATA (as read_vtu.c). Other arrays, VECTORS, NORMALS, TENSORS and
 * METADATA blocks are skipped. Errors give file:line (ASCII) or the byte
 * offset (BINARY).
 */
#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "io_text.h"
#include "vtu_data.h"

#define MAX_COUNT ((long long)INT32_MAX / 4)
#define WORD 64

/* The cells of a section: offsets (ncell+1) into conn, a VTK type each. */
typedef struct cellset {
    long long *off, *conn, *type;
    size_t ncell;
} cellset;

enum { S_VERTS, S_LINES, S_POLYS, S_STRIPS, S_GRID, S_N };

typedef struct vtk {
    cvm__vtu_file f; /* buf, name; f.appended marks where binary data begins */
    char *buf;
    size_t pos;
    int binary, polydata;
    long long np;
    double *xyz;
    cellset cs[S_N];
    long long *grid_types;
    long long ngrid_types;
    int data_of; /* 0 none, 1 POINT_DATA, 2 CELL_DATA */
    long long *pmark, *cmark;
    double *w, *pattr, *cattr;
    long long nattr;
} vtk;

static cvm_status fail(vtk *v, size_t at, cvm_status st, const char *fmt, ...) CVM__PRINTF(4, 5);
static cvm_status fail(vtk *v, size_t at, cvm_status st, const char *fmt, ...)
{
    char what[CVM__ERRMSG_LEN];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    return cvm__vtu_fail(&v->f, at, st, "%s", what);
}

static int space(char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

/* The next whitespace-separated word into w (truncated to WORD-1); 0 at the
 * end of the file. *at receives its offset. */
static int word(vtk *v, char *w, size_t *at)
{
    size_t s, n;
    while (v->pos < v->f.n && space(v->buf[v->pos]))
        v->pos++;
    *at = v->pos;
    if (v->pos >= v->f.n)
        return 0;
    s = v->pos;
    while (v->pos < v->f.n && !space(v->buf[v->pos]) && v->buf[v->pos] != '\0')
        v->pos++;
    if (v->pos == s) { /* a NUL byte outside binary data */
        w[0] = '\0';
        return 1;
    }
    n = v->pos - s < WORD - 1 ? v->pos - s : WORD - 1;
    memcpy(w, v->buf + s, n);
    w[n] = '\0';
    return 1;
}

static cvm_status need(vtk *v, char *w, const char *what)
{
    size_t at;
    if (!word(v, w, &at))
        return fail(v, at, CVM_E_IO_FORMAT, "the file ends before %s", what);
    return CVM_OK;
}

static cvm_status count(vtk *v, const char *what, long long *out)
{
    char w[WORD];
    size_t at = v->pos;
    cvm_status s = need(v, w, what);
    int r;
    *out = 0;
    if (s)
        return s;
    r = cvm__parse_long(w, 0, MAX_COUNT, out);
    if (r == 2 && w[0] != '-')
        return fail(v, at, CVM_E_TOO_LARGE, "%s '%s' exceeds %lld", what, w, MAX_COUNT);
    if (r)
        return fail(v, at, CVM_E_IO_FORMAT, "%s is '%s', not a non-negative integer", what, w);
    return CVM_OK;
}

/* Byte size and kind of a legacy type name; 0 when unknown. */
static int type_of(const char *t, int *kind)
{
    static const struct { const char *name; int size, kind; } k[] = {
        {"unsigned_char", 1, CVM__BIN_UNSIGNED}, {"char", 1, CVM__BIN_SIGNED},
        {"unsigned_short", 2, CVM__BIN_UNSIGNED}, {"short", 2, CVM__BIN_SIGNED},
        {"unsigned_int", 4, CVM__BIN_UNSIGNED}, {"int", 4, CVM__BIN_SIGNED},
        {"unsigned_long", 8, CVM__BIN_UNSIGNED}, {"long", 8, CVM__BIN_SIGNED},
        {"vtktypeint8", 1, CVM__BIN_SIGNED},     {"vtktypeuint8", 1, CVM__BIN_UNSIGNED},
        {"vtktypeint16", 2, CVM__BIN_SIGNED},    {"vtktypeuint16", 2, CVM__BIN_UNSIGNED},
        {"vtktypeint32", 4, CVM__BIN_SIGNED},    {"vtktypeuint32", 4, CVM__BIN_UNSIGNED},
        {"vtktypeint64", 8, CVM__BIN_SIGNED},    {"vtktypeuint64", 8, CVM__BIN_UNSIGNED},
        {"float", 4, CVM__BIN_FLOAT},            {"double", 8, CVM__BIN_FLOAT}};
    size_t i;
    for (i = 0; i < sizeof k / sizeof k[0]; i++)
        if (strcmp(t, k[i].name) == 0) {
            *kind = k[i].kind;
            return k[i].size;
        }
    return 0;
}

/* n values of type into a fresh array (long long when integer, else
 * double); skip: read past them without checking or keeping. */
static cvm_status values(vtk *v, const char *type, long long n, int integer, int skip,
                         const char *what, void **out)
{
    cvm__ctx *ctx = v->f.ctx;
    long long *l = NULL;
    double *d = NULL;
    int kind, size = type_of(type, &kind);
    size_t k, at = v->pos;
    *out = NULL;
    if (!size)
        return fail(v, at, CVM_E_UNSUPPORTED, "%s: data type '%s' is not read", what, type);
    if (v->binary) {
        while (v->pos < v->f.n && v->buf[v->pos] != '\n' && space(v->buf[v->pos]))
            v->pos++;
        if (v->pos >= v->f.n || v->buf[v->pos] != '\n' ||
            (unsigned long long)n * (unsigned)size > v->f.n - v->pos - 1)
            return fail(v, at, CVM_E_IO_FORMAT, "%s: %lld binary values of %s do not fit in the "
                        "file (truncated?)", what, n, type);
        at = ++v->pos;
    } else if ((unsigned long long)n > (v->f.n - v->pos) / 2 + 1) { /* a value and a space each */
        return fail(v, at, CVM_E_IO_FORMAT, "%s: %lld values do not fit in the rest of the file "
                    "(truncated?)", what, n);
    }
    if (!skip && (integer ? !(l = cvm__malloc(ctx, ((size_t)n + 1) * sizeof *l)) :
                            !(d = cvm__malloc(ctx, ((size_t)n + 1) * sizeof *d))))
        return cvm__nomem(ctx);
    if (v->binary) {
        for (k = 0; !skip && k < (size_t)n; k++) {
            long long lv = 0;
            double dv = 0;
            int r = cvm__bin_number((const unsigned char *)v->buf + at + k * (size_t)size, size,
                                    kind, 1, integer, &lv, &dv);
            if (r) {
                cvm__free(ctx, l);
                cvm__free(ctx, d);
                return fail(v, at + k * (size_t)size, r == 2 ? CVM_E_INPUT_NONFINITE : CVM_E_IO_FORMAT,
                            "%s: entry %lu (from 0) is not a %s", what, (unsigned long)k,
                            r == 2 ? "finite number" : "integer in [-2147483647, 2147483647]");
            }
            if (integer)
                l[k] = lv;
            else
                d[k] = dv;
        }
        v->pos += (size_t)n * (size_t)size;
        *out = integer ? (void *)l : (void *)d;
        return CVM_OK;
    }
    for (k = 0; k < (size_t)n; k++) {
        char w[WORD];
        int r;
        if (!word(v, w, &at)) {
            cvm__free(ctx, l);
            cvm__free(ctx, d);
            return fail(v, at, CVM_E_IO_FORMAT, "%s: the file ends after %lu of %lld values", what,
                        (unsigned long)k, n);
        }
        if (skip)
            continue;
        r = integer ? cvm__parse_long(w, -(long long)INT32_MAX, INT32_MAX, &l[k])
                    : cvm__parse_double(w, &d[k]);
        if (r) {
            cvm__free(ctx, l);
            cvm__free(ctx, d);
            return fail(v, at, !integer && r == 2 ? CVM_E_INPUT_NONFINITE : CVM_E_IO_FORMAT,
                        "%s: entry %lu (from 0) is '%s', not a%s", what, (unsigned long)k, w,
                        integer ? "n integer in [-2147483647, 2147483647]" :
                        r == 2 ? " finite number" : " number");
        }
    }
    *out = integer ? (void *)l : (void *)d;
    return CVM_OK;
}

/* A cell array "KEYWORD a b" in either layout into c; each cell gets type
 * t (-1: the grid's CELL_TYPES). */
static cvm_status cells(vtk *v, const char *key, long long t, cellset *c)
{
    cvm__ctx *ctx = v->f.ctx;
    char w[WORD], type[WORD];
    long long a, b, *raw = NULL;
    size_t at, save, k, i, nc;
    cvm_status s;
    if (c->off)
        return fail(v, v->pos, CVM_E_IO_FORMAT, "a second %s section", key);
    if ((s = count(v, key, &a)) || (s = count(v, key, &b)))
        return s;
    save = v->pos;
    if (word(v, w, &at) && strcmp(w, "OFFSETS") == 0) {
        if ((s = need(v, type, "the OFFSETS type")) ||
            (s = values(v, type, a, 1, 0, "OFFSETS", (void **)&c->off)))
            return s;
        if ((s = need(v, w, "CONNECTIVITY")))
            return s;
        if (strcmp(w, "CONNECTIVITY") != 0)
            return fail(v, at, CVM_E_IO_FORMAT, "%s: CONNECTIVITY expected, not '%s'", key, w);
        if ((s = need(v, type, "the CONNECTIVITY type")) ||
            (s = values(v, type, b, 1, 0, "CONNECTIVITY", (void **)&c->conn)))
            return s;
        nc = a > 0 ? (size_t)a - 1 : 0;
        for (k = 0; k <= nc && a > 0; k++)
            if ((k == 0 ? c->off[0] != 0 : c->off[k] < c->off[k - 1]) || c->off[k] > b ||
                (k == nc && c->off[k] != b))
                return fail(v, at, CVM_E_IO_FORMAT, "%s: offset %lu is %lld (offsets must rise "
                            "from 0 to %lld)", key, (unsigned long)k, c->off[k], b);
    } else {
        v->pos = save;
        if ((s = values(v, "int", b, 1, 0, key, (void **)&raw)))
            return s;
        nc = (size_t)a;
        c->off = cvm__malloc(ctx, (nc + 1) * sizeof *c->off);
        c->conn = cvm__malloc(ctx, ((size_t)b + 1) * sizeof *c->conn);
        if (!c->off || !c->conn) {
            cvm__free(ctx, raw);
            return cvm__nomem(ctx);
        }
        c->off[0] = 0;
        for (k = 0, i = 0; k < nc; k++) {
            long long m = i < (size_t)b ? raw[i] : -1;
            if (m < 0 || (size_t)m > (size_t)b - i - 1) {
                cvm__free(ctx, raw);
                return fail(v, save, CVM_E_IO_FORMAT, "%s: cell %lu has %lld points, which do not "
                            "fit the size %lld", key, (unsigned long)k, m, b);
            }
            memcpy(c->conn + c->off[k], raw + i + 1, (size_t)m * sizeof *raw);
            c->off[k + 1] = c->off[k] + m;
            i += (size_t)m + 1;
        }
        cvm__free(ctx, raw);
        if (i != (size_t)b)
            return fail(v, save, CVM_E_IO_FORMAT, "%s: %lld cells use %lu of the %lld values", key,
                        a, (unsigned long)i, b);
    }
    c->ncell = nc;
    if (t >= 0) {
        if (!(c->type = cvm__malloc(ctx, (nc + 1) * sizeof *c->type)))
            return cvm__nomem(ctx);
        for (k = 0; k < nc; k++)
            c->type[k] = t == 7 && c->off[k + 1] - c->off[k] == 3 ? 5 : t;
    }
    return CVM_OK;
}

static size_t total_cells(const vtk *v)
{
    size_t n = 0;
    int k;
    for (k = 0; k < S_N; k++)
        n += v->cs[k].ncell;
    return n;
}

/* One data array of the current POINT_DATA or CELL_DATA: kept by name, or skipped. */
static cvm_status data_array(vtk *v, size_t at, const char *name, long long ncomp,
                             long long ntuples, const char *type)
{
    int pt = v->data_of == 1;
    long long items = pt ? v->np : (long long)total_cells(v);
    void **slot = NULL;
    int integer = 0;
    char what[WORD + 16];
    if (ncomp < 1 || ncomp > 10000 || ncomp * ntuples > MAX_COUNT * 4)
        return fail(v, at, CVM_E_IO_FORMAT, "array '%s': bad number of components %lld", name, ncomp);
    if (!v->data_of) { /* field data of the whole data set (e.g. TIME): skipped */
        void *junk;
        return values(v, type, ncomp * ntuples, 0, 1, name, &junk);
    }
    if (ntuples != items)
        return fail(v, at, CVM_E_IO_FORMAT, "array '%s' has %lld tuples, the %s have %lld", name,
                    ntuples, pt ? "points" : "cells", items);
    if (strcmp(name, "weight") == 0 && ncomp == 1)
        slot = pt ? (void **)&v->w : NULL;
    else if (strcmp(name, "marker") == 0 && ncomp == 1) {
        slot = pt ? (void **)&v->pmark : (void **)&v->cmark;
        integer = 1;
    } else if (strcmp(name, "attribute") == 0 && (pt || ncomp == 1)) {
        slot = pt ? (void **)&v->pattr : (void **)&v->cattr;
        if (pt)
            v->nattr = ncomp;
    }
    snprintf(what, sizeof what, "%s '%s'", pt ? "point data" : "cell data", name);
    if (slot && *slot)
        return fail(v, at, CVM_E_IO_FORMAT, "a second %s array", what);
    if (!slot) {
        void *junk;
        return values(v, type, ncomp * ntuples, 0, 1, what, &junk);
    }
    return values(v, type, ncomp * ntuples, integer, 0, what, slot);
}

/* Skip the lines of a METADATA block up to the first blank one. */
static void skip_metadata(vtk *v)
{
    for (;;) {
        size_t s;
        int blank = 1;
        while (v->pos < v->f.n && v->buf[v->pos] != '\n')
            v->pos++;
        if (v->pos >= v->f.n)
            return;
        s = ++v->pos;
        while (v->pos < v->f.n && v->buf[v->pos] != '\n')
            blank &= space(v->buf[v->pos++]);
        if (blank) {
            v->pos = s;
            return;
        }
        v->pos = s;
    }
}

/* The word after the current one, if it is w; else nothing is consumed. */
static int next_is(vtk *v, const char *w)
{
    char x[WORD];
    size_t at, save = v->pos;
    if (word(v, x, &at) && strcmp(x, w) == 0)
        return 1;
    v->pos = save;
    return 0;
}

static cvm_status scalars(vtk *v, size_t at)
{
    char name[WORD], type[WORD], w[WORD];
    long long nc = 1;
    size_t save, wat;
    cvm_status s;
    if ((s = need(v, name, "the SCALARS name")) || (s = need(v, type, "the SCALARS type")))
        return s;
    save = v->pos;
    if (!word(v, w, &wat) || cvm__parse_long(w, 1, 4, &nc))
        v->pos = save;
    if (next_is(v, "LOOKUP_TABLE") && (s = need(v, w, "the LOOKUP_TABLE name")))
        return s;
    return data_array(v, at, name, nc, v->data_of == 1 ? v->np : (long long)total_cells(v), type);
}

static cvm_status field(vtk *v)
{
    char name[WORD], type[WORD];
    long long n, k, nc, nt;
    cvm_status s;
    if ((s = need(v, name, "the FIELD name")) || (s = count(v, "the FIELD array count", &n)))
        return s;
    for (k = 0; k < n; k++) {
        size_t at = v->pos;
        if ((s = need(v, name, "a FIELD array name")) || (s = count(v, "components", &nc)) ||
            (s = count(v, "tuples", &nt)) || (s = need(v, type, "a FIELD array type")) ||
            (s = data_array(v, at, name, nc, nt, type)))
            return s;
        if (next_is(v, "METADATA"))
            skip_metadata(v);
    }
    return CVM_OK;
}

/* Arrays that are skipped: KEYWORD name type, per = values per item. */
static cvm_status skipped(vtk *v, size_t at, const char *key, long long per)
{
    char name[WORD], type[WORD];
    cvm_status s;
    if ((s = need(v, name, key)) || (s = need(v, type, key)))
        return s;
    return data_array(v, at, "", per, v->data_of == 1 ? v->np : (long long)total_cells(v), type);
}

/* The keyword sections after the header. */
static cvm_status sections(vtk *v)
{
    char w[WORD], x[WORD];
    size_t at;
    long long n;
    cvm_status s = CVM_OK;
    while (!s && word(v, w, &at)) {
        if (strcmp(w, "DATASET") == 0) {
            if ((s = need(v, x, "the DATASET type")))
                return s;
            if (strcmp(x, "UNSTRUCTURED_GRID") != 0 && strcmp(x, "POLYDATA") != 0)
                return fail(v, at, CVM_E_UNSUPPORTED, "DATASET %s is not read (UNSTRUCTURED_GRID "
                            "or POLYDATA)", x);
            v->polydata = x[0] == 'P';
        } else if (strcmp(w, "POINTS") == 0) {
            if (v->xyz)
                return fail(v, at, CVM_E_IO_FORMAT, "a second POINTS section");
            if ((s = count(v, "the POINTS count", &v->np)) || (s = need(v, x, "the POINTS type")))
                return s;
            s = values(v, x, 3 * v->np, 0, 0, "POINTS", (void **)&v->xyz);
        } else if (strcmp(w, "METADATA") == 0) {
            skip_metadata(v);
        } else if (strcmp(w, "CELLS") == 0) {
            s = cells(v, w, -1, &v->cs[S_GRID]);
        } else if (strcmp(w, "CELL_TYPES") == 0) {
            if (v->grid_types)
                return fail(v, at, CVM_E_IO_FORMAT, "a second CELL_TYPES section");
            if (!(s = count(v, w, &v->ngrid_types)))
                s = values(v, "int", v->ngrid_types, 1, 0, w, (void **)&v->grid_types);
        } else if (strcmp(w, "VERTICES") == 0) {
            s = cells(v, w, 2, &v->cs[S_VERTS]);
        } else if (strcmp(w, "LINES") == 0) {
            s = cells(v, w, 4, &v->cs[S_LINES]);
        } else if (strcmp(w, "POLYGONS") == 0) {
            s = cells(v, w, 7, &v->cs[S_POLYS]);
        } else if (strcmp(w, "TRIANGLE_STRIPS") == 0) {
            s = cells(v, w, 6, &v->cs[S_STRIPS]);
        } else if (strcmp(w, "POINT_DATA") == 0 || strcmp(w, "CELL_DATA") == 0) {
            v->data_of = w[0] == 'P' ? 1 : 2;
            if (!(s = count(v, w, &n)) && n != (w[0] == 'P' ? v->np : (long long)total_cells(v)))
                return fail(v, at, CVM_E_IO_FORMAT, "%s %lld, but the file has %lld", w, n,
                            w[0] == 'P' ? v->np : (long long)total_cells(v));
        } else if (strcmp(w, "SCALARS") == 0) {
            s = scalars(v, at);
        } else if (strcmp(w, "FIELD") == 0) {
            s = field(v);
        } else if (strcmp(w, "VECTORS") == 0 || strcmp(w, "NORMALS") == 0) {
            s = skipped(v, at, w, 3);
        } else if (strcmp(w, "TENSORS") == 0) {
            s = skipped(v, at, w, 9);
        } else {
            return fail(v, at, CVM_E_UNSUPPORTED, "keyword '%s' is not read", w);
        }
    }
    return s;
}

/* The header: version line, title, ASCII or BINARY. */
static cvm_status header(vtk *v)
{
    static const char magic[] = "# vtk DataFile Version";
    char w[WORD];
    size_t at, k;
    if (v->f.n < sizeof magic - 1 || strncmp(v->buf, magic, sizeof magic - 1) != 0)
        return fail(v, 0, CVM_E_IO_FORMAT, "not a legacy VTK file (no '%s' line)", magic);
    for (k = 0; k < 2; k++) { /* version line, title */
        while (v->pos < v->f.n && v->buf[v->pos] != '\n')
            v->pos++;
        v->pos += v->pos < v->f.n;
    }
    if (!word(v, w, &at) || (strcmp(w, "ASCII") != 0 && strcmp(w, "BINARY") != 0))
        return fail(v, at, CVM_E_IO_FORMAT, "line 3 must be ASCII or BINARY");
    v->binary = w[0] == 'B';
    if (v->binary) {
        v->f.appended = v->pos; /* messages give byte offsets from here on */
        v->f.appended_raw = 1;
    } else if (memchr(v->buf, '\0', v->f.n)) {
        return fail(v, (size_t)((char *)memchr(v->buf, '\0', v->f.n) - v->buf), CVM_E_IO_FORMAT,
                    "NUL byte in an ASCII file");
    }
    return CVM_OK;
}

/* The cells of every section -> triangles and lines of out. */
static cvm_status build(vtk *v, cvm__vtu_mesh *out)
{
    cvm__ctx *ctx = v->f.ctx;
    size_t nt = 0, nl = 0, c = 0, k, j;
    int pass, sec;
    if (!v->xyz)
        return fail(v, v->f.n, CVM_E_IO_FORMAT, "no POINTS");
    if (!v->polydata && (!v->cs[S_GRID].off || !v->grid_types))
        return fail(v, v->f.n, CVM_E_IO_FORMAT, "an UNSTRUCTURED_GRID needs CELLS and CELL_TYPES");
    if (!v->polydata && (size_t)v->ngrid_types != v->cs[S_GRID].ncell)
        return fail(v, v->f.n, CVM_E_IO_FORMAT, "CELL_TYPES has %lld cells, CELLS %lu",
                    v->ngrid_types, (unsigned long)v->cs[S_GRID].ncell);
    if (v->polydata && v->cs[S_GRID].ncell)
        return fail(v, v->f.n, CVM_E_IO_FORMAT, "CELLS in a POLYDATA");
    v->cs[S_GRID].type = v->grid_types;
    v->grid_types = NULL;
    for (pass = 0; pass < 2; pass++) {
        c = 0;
        for (sec = 0; sec < S_N; sec++) {
            const cellset *cs = &v->cs[sec];
            for (k = 0; k < cs->ncell; k++, c++) {
                long long t = cs->type[k], m = cs->off[k + 1] - cs->off[k];
                const long long *id = cs->conn + cs->off[k];
                if (pass == 0) {
                    if (!((t == 1 && m == 1) || t == 2 || (t == 3 && m == 2) || (t == 4 && m >= 2) ||
                          ((t == 5 || t == 6) && m == 3)))
                        return fail(v, v->f.n, t == 3 || t == 5 || t == 1 ? CVM_E_IO_FORMAT :
                                    CVM_E_UNSUPPORTED, "cell %lu has VTK type %lld with %lld points "
                                    "(only triangles 5, lines 3, polylines 4 and vertices 1, 2 are "
                                    "read)", (unsigned long)c, t, m);
                    for (j = 0; j < (size_t)m; j++)
                        if (id[j] < 0 || id[j] >= v->np)
                            return fail(v, v->f.n, CVM_E_IO_FORMAT, "cell %lu names point %lld, "
                                        "which does not exist (points are numbered 0..%lld)",
                                        (unsigned long)c, id[j], v->np - 1);
                    nt += t == 5 || t == 6;
                    nl += t == 3 || t == 4 ? (size_t)m - 1 : 0;
                    continue;
                }
                if (t == 5 || t == 6) {
                    for (j = 0; j < 3; j++)
                        out->tri[3 * out->nt + j] = (int32_t)id[j];
                    if (out->tattr)
                        out->tattr[out->nt] = v->cattr[c];
                    out->nt++;
                } else if (t == 3 || t == 4) {
                    for (j = 0; j + 1 < (size_t)m; j++) {
                        out->p.seg[2 * out->p.nseg] = (int32_t)id[j];
                        out->p.seg[2 * out->p.nseg + 1] = (int32_t)id[j + 1];
                        if (out->p.smark)
                            out->p.smark[out->p.nseg] = (int32_t)v->cmark[c];
                        out->p.nseg++;
                    }
                }
            }
        }
        if (pass == 0) {
            out->tri = cvm__malloc(ctx, (3 * nt + 1) * sizeof *out->tri);
            out->tattr = v->cattr ? cvm__malloc(ctx, (nt + 1) * sizeof *out->tattr) : NULL;
            out->p.seg = cvm__malloc(ctx, (2 * nl + 1) * sizeof *out->p.seg);
            out->p.smark = v->cmark ? cvm__malloc(ctx, (nl + 1) * sizeof *out->p.smark) : NULL;
            if (!out->tri || (v->cattr && !out->tattr) || !out->p.seg || (v->cmark && !out->p.smark))
                return cvm__nomem(ctx);
        }
    }
    out->has_lines = nl > 0;
    return CVM_OK;
}

/* Points and point data -> out. */
static cvm_status build_points(vtk *v, cvm__vtu_mesh *out)
{
    size_t k, np = (size_t)v->np;
    cvm__ctx *ctx = v->f.ctx;
    out->p.xy = cvm__malloc(ctx, (2 * np + 1) * sizeof *out->p.xy);
    out->p.pmark = v->pmark ? cvm__malloc(ctx, (np + 1) * sizeof *out->p.pmark) : NULL;
    if (!out->p.xy || (v->pmark && !out->p.pmark))
        return cvm__nomem(ctx);
    for (k = 0; k < np; k++) {
        if (v->xyz[3 * k + 2] != 0)
            return fail(v, v->f.n, CVM_E_IO_FORMAT, "point %lu has z = %.17g (only planar meshes "
                        "are read)", (unsigned long)k, v->xyz[3 * k + 2]);
        out->p.xy[2 * k] = v->xyz[3 * k];
        out->p.xy[2 * k + 1] = v->xyz[3 * k + 1];
        if (out->p.pmark)
            out->p.pmark[k] = (int32_t)v->pmark[k];
    }
    out->p.np = np;
    out->p.pattr = v->pattr;
    out->p.nattr = v->pattr ? (size_t)v->nattr : 0;
    v->pattr = NULL;
    out->w = v->w;
    v->w = NULL;
    return CVM_OK;
}

cvm_status cvm__read_vtk(cvm__ctx *ctx, cvm__reader *r, const char *name, cvm__vtu_mesh *out)
{
    vtk v;
    cvm_status s;
    int k;
    memset(&v, 0, sizeof v);
    memset(out, 0, sizeof *out);
    v.f.ctx = ctx;
    v.f.name = name;
    if (!(s = cvm__slurp(ctx, r, name, &v.buf, &v.f.n))) {
        v.f.buf = v.buf;
        if (!(s = header(&v)) && !(s = sections(&v)) && !(s = build(&v, out)))
            s = build_points(&v, out);
    }
    cvm__free(ctx, v.buf);
    cvm__free(ctx, v.xyz);
    for (k = 0; k < S_N; k++) {
        cvm__free(ctx, v.cs[k].off);
        cvm__free(ctx, v.cs[k].conn);
        cvm__free(ctx, v.cs[k].type);
    }
    cvm__free(ctx, v.grid_types);
    cvm__free(ctx, v.pmark);
    cvm__free(ctx, v.cmark);
    cvm__free(ctx, v.w);
    cvm__free(ctx, v.pattr);
    cvm__free(ctx, v.cattr);
    if (s)
        cvm__vtu_mesh_free(ctx, out);
    return s;
}
