/*
 * read_vtu.c - parses a VTK XML UnstructuredGrid (.vtu) with ASCII data
 * arrays into points, triangles, line cells and their data.
 *
 * Format (VTK file formats, "XML File Formats", UnstructuredGrid): one
 * <Piece NumberOfPoints NumberOfCells> holding <Points> (one DataArray of 3
 * components; z must be 0), <Cells> (DataArrays "connectivity", "offsets",
 * "types"), and optionally <PointData>/<CellData>. Read: cell types 5
 * (triangle), 3 (line: a constrained edge) and 1 (vertex: ignored); point data
 * "weight", "marker" and "attribute" (any number of components); cell data
 * "marker" (of the lines) and "attribute" (of the triangles). Other arrays are
 * skipped. Only format="ascii" is read; binary, appended or compressed data is
 * CVM_E_UNSUPPORTED. This is a small tolerant tag scanner, not a general XML
 * parser: comments, processing instructions and any attribute order are
 * understood; entities and CDATA are not. Every error names file:line.
 */
#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "io_text.h"

#define MAX_COUNT ((long long)INT32_MAX / 4)
#define MAX_COMP 10000
#define ATTR_LEN 64

enum { SEC_NONE, SEC_POINTDATA, SEC_CELLDATA, SEC_POINTS, SEC_CELLS };

typedef struct vparser {
    cvm__ctx *ctx;
    const char *name; /* file name for messages */
    char *buf;        /* the whole file, NUL-terminated */
    size_t n, pos;
    int section, have_piece;
    long long np, nc;
    /* arrays read, NULL until seen */
    double *xyz;   /* 3*np (or 2*np) */
    long long *conn, *off, *types, *cmark, *pmark;
    size_t nconn;
    double *w, *pattr, *cattr;
    size_t nattr, ncomp_xyz;
    /* byte offsets of the contents of Points, connectivity, offsets, types:
       messages about an entry find its line from there */
    size_t at_xyz, at_conn, at_off, at_types;
} vparser;

/* 1-based line of byte offset at. */
static long line_of(const vparser *ps, size_t at)
{
    long line = 1;
    size_t i;
    for (i = 0; i < at && i < ps->n; i++)
        line += ps->buf[i] == '\n';
    return line;
}

/* Byte offset of entry k (from 0) of the array whose content starts at start. */
static size_t entry_at(const vparser *ps, size_t start, size_t k)
{
    size_t i = start, n = 0;
    for (;;) {
        while (i < ps->n && (ps->buf[i] == ' ' || ps->buf[i] == '\t' || ps->buf[i] == '\n' ||
                             ps->buf[i] == '\r'))
            i++;
        if (i >= ps->n || ps->buf[i] == '<' || n == k)
            return i;
        while (i < ps->n && ps->buf[i] != ' ' && ps->buf[i] != '\t' && ps->buf[i] != '\n' &&
               ps->buf[i] != '\r' && ps->buf[i] != '<')
            i++;
        n++;
    }
}

static cvm_status fail_at(vparser *ps, size_t at, cvm_status st, const char *fmt, ...)
    CVM__PRINTF(4, 5);
static cvm_status fail_at(vparser *ps, size_t at, cvm_status st, const char *fmt, ...)
{
    char what[CVM__ERRMSG_LEN];
    long line = line_of(ps, at);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    return cvm__error(ps->ctx, st, CVM_ENT_FILE_LINE, (int64_t)line, "%s:%ld: %s", ps->name, line,
                      what);
}

/* Read all of r into ps->buf. */
static cvm_status slurp(vparser *ps, cvm__reader *r)
{
    size_t cap = 0;
    for (;;) {
        long got;
        if (ps->n + 65536 + 1 > cap &&
            cvm__grow(ps->ctx, (void **)&ps->buf, &cap, ps->n + 65536 + 1, 1))
            return cvm__nomem(ps->ctx);
        if (ps->n && cvm__poll_cancel(ps->ctx, CVM_STAGE_READ, 0.0))
            return cvm__error(ps->ctx, CVM_INCOMPLETE_CANCELLED, CVM_ENT_NONE, -1,
                              "reading %s was cancelled", ps->name);
        got = r->read(r->self, ps->buf + ps->n, 65536);
        if (got < 0 || got > 65536)
            return cvm__error(ps->ctx, CVM_E_IO_READ, CVM_ENT_FILE_LINE, -1, "%s: read error",
                              ps->name);
        if (got == 0)
            break;
        ps->n += (size_t)got;
    }
    ps->buf[ps->n] = '\0';
    if (memchr(ps->buf, '\0', ps->n))
        return fail_at(ps, (size_t)((const char *)memchr(ps->buf, '\0', ps->n) - ps->buf),
                       CVM_E_IO_FORMAT, "NUL byte (not a text file?)");
    return CVM_OK;
}

/* Value of attribute key in the tag [s, e) into out (cap ATTR_LEN); 0 if absent. */
static int attr(const char *s, const char *e, const char *key, char *out)
{
    size_t k = strlen(key);
    const char *p;
    for (p = s + 1; p + k + 2 < e; p++) {
        const char *q;
        size_t n;
        if ((p[-1] != ' ' && p[-1] != '\t' && p[-1] != '\n' && p[-1] != '\r') ||
            strncmp(p, key, k) != 0 || p[k] != '=' || (p[k + 1] != '"' && p[k + 1] != '\''))
            continue;
        q = memchr(p + k + 2, p[k + 1], (size_t)(e - (p + k + 2)));
        if (!q)
            return 0;
        n = (size_t)(q - (p + k + 2));
        if (n >= ATTR_LEN)
            n = ATTR_LEN - 1;
        memcpy(out, p + k + 2, n);
        out[n] = '\0';
        return 1;
    }
    return 0;
}

/* A count attribute of the tag at [s, e). */
static cvm_status count_attr(vparser *ps, const char *s, const char *e, const char *key,
                             long long *out)
{
    char v[ATTR_LEN];
    int r;
    if (!attr(s, e, key, v))
        return fail_at(ps, (size_t)(s - ps->buf), CVM_E_IO_FORMAT, "<Piece> has no %s", key);
    r = cvm__parse_long(v, LLONG_MIN, LLONG_MAX, out);
    if (r == 1)
        return fail_at(ps, (size_t)(s - ps->buf), CVM_E_IO_FORMAT,
                       "%s=\"%s\" is not a non-negative integer", key, v);
    if ((r == 0 && *out < 0) || (r == 2 && v[0] == '-'))
        return fail_at(ps, (size_t)(s - ps->buf), CVM_E_IO_FORMAT, "%s=\"%s\" is negative", key, v);
    if (r == 2 || *out > MAX_COUNT)
        return fail_at(ps, (size_t)(s - ps->buf), CVM_E_TOO_LARGE, "%s=\"%s\" exceeds %lld", key, v,
                       MAX_COUNT);
    return CVM_OK;
}

/* Parse the whitespace-separated numbers of [s, e) into a fresh array of
 * exactly want values (want < 0: any count, *got receives it). */
static cvm_status numbers(vparser *ps, const char *s, const char *e, const char *what, int integer,
                          long long want, void **out, size_t *got)
{
    size_t cap = 0, n = 0;
    double *d = NULL;
    long long *l = NULL;
    const char *p = s;
    *out = NULL;
    for (;;) {
        char tok[CVM__DOUBLE_BUF + 24];
        const char *t;
        size_t len;
        int r;
        while (p < e && (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r'))
            p++;
        if (p >= e)
            break;
        t = p;
        while (p < e && *p != ' ' && *p != '\t' && *p != '\n' && *p != '\r')
            p++;
        len = (size_t)(p - t);
        if (want >= 0 && (long long)n >= want) {
            cvm__free(ps->ctx, integer ? (void *)l : (void *)d);
            return fail_at(ps, (size_t)(t - ps->buf), CVM_E_IO_FORMAT,
                           "%s: more than the %lld values expected", what, want);
        }
        if (len >= sizeof tok)
            len = sizeof tok - 1; /* too long for a number: fails below */
        memcpy(tok, t, len);
        tok[len] = '\0';
        if (n + 1 > cap && cvm__grow(ps->ctx, integer ? (void **)&l : (void **)&d, &cap, n + 1,
                                     integer ? sizeof *l : sizeof *d))
            goto nomem;
        if (integer) {
            r = cvm__parse_long(tok, -(long long)INT32_MAX, INT32_MAX, &l[n]);
            if (r) {
                cvm__free(ps->ctx, l);
                return fail_at(ps, (size_t)(t - ps->buf), CVM_E_IO_FORMAT,
                               "%s: entry %lld (from 0) is '%s', not an integer in [%lld, %lld]",
                               what, (long long)n, tok, -(long long)INT32_MAX, (long long)INT32_MAX);
            }
        } else {
            r = cvm__parse_double(tok, &d[n]);
            if (r) {
                cvm__free(ps->ctx, d);
                return fail_at(ps, (size_t)(t - ps->buf),
                               r == 2 ? CVM_E_INPUT_NONFINITE : CVM_E_IO_FORMAT,
                               "%s: entry %lld (from 0) is '%s', not a %snumber", what,
                               (long long)n, tok, r == 2 ? "finite " : "");
            }
        }
        n++;
    }
    if (want >= 0 && (long long)n != want) {
        cvm__free(ps->ctx, integer ? (void *)l : (void *)d);
        return fail_at(ps, (size_t)(e - ps->buf), CVM_E_IO_FORMAT, "%s: %lld values, expected %lld",
                       what, (long long)n, want);
    }
    if (!(integer ? (void *)l : (void *)d)) { /* empty: still a valid array */
        if (integer ? !(l = cvm__malloc(ps->ctx, sizeof *l)) : !(d = cvm__malloc(ps->ctx, sizeof *d)))
            goto nomem;
    }
    *out = integer ? (void *)l : (void *)d;
    if (got)
        *got = n;
    return CVM_OK;
nomem:
    cvm__free(ps->ctx, l);
    cvm__free(ps->ctx, d);
    return cvm__nomem(ps->ctx);
}

/* Store one array into *slot, refusing a second one of the same role. */
static cvm_status take(vparser *ps, const char *s, const char *e, const char *what, int integer,
                       long long want, void **slot, size_t *got)
{
    if (*slot)
        return fail_at(ps, (size_t)(s - ps->buf), CVM_E_IO_FORMAT, "a second %s array", what);
    return numbers(ps, s, e, what, integer, want, slot, got);
}

/* A <DataArray> whose start tag is [ts, te) and content [cs, ce). */
static cvm_status data_array(vparser *ps, const char *ts, const char *te, const char *cs,
                             const char *ce)
{
    char name[ATTR_LEN] = "", fmt[ATTR_LEN] = "", comp[ATTR_LEN] = "1";
    long long nc = 1;
    size_t at = (size_t)(ts - ps->buf);
    attr(ts, te, "Name", name);
    attr(ts, te, "NumberOfComponents", comp);
    if (!attr(ts, te, "format", fmt))
        return fail_at(ps, at, CVM_E_IO_FORMAT, "DataArray '%s' has no format", name);
    if (strcmp(fmt, "ascii") != 0)
        return fail_at(ps, at, CVM_E_UNSUPPORTED, "DataArray '%s': only format=\"ascii\" is read",
                       name);
    if (cvm__parse_long(comp, 1, MAX_COMP, &nc))
        return fail_at(ps, at, CVM_E_IO_FORMAT, "DataArray '%s': bad NumberOfComponents", name);
    if (!ps->have_piece)
        return fail_at(ps, at, CVM_E_IO_FORMAT, "DataArray '%s' outside a <Piece>", name);
    switch (ps->section) {
    case SEC_POINTS:
        if (nc != 3 && nc != 2)
            return fail_at(ps, at, CVM_E_IO_FORMAT, "Points have %lld components (need 3)", nc);
        ps->ncomp_xyz = (size_t)nc;
        ps->at_xyz = (size_t)(cs - ps->buf);
        return take(ps, cs, ce, "Points", 0, nc * ps->np, (void **)&ps->xyz, NULL);
    case SEC_CELLS:
        if (strcmp(name, "connectivity") == 0) {
            ps->at_conn = (size_t)(cs - ps->buf);
            return take(ps, cs, ce, "connectivity", 1, -1, (void **)&ps->conn, &ps->nconn);
        }
        if (strcmp(name, "offsets") == 0) {
            ps->at_off = (size_t)(cs - ps->buf);
            return take(ps, cs, ce, "offsets", 1, ps->nc, (void **)&ps->off, NULL);
        }
        if (strcmp(name, "types") == 0) {
            ps->at_types = (size_t)(cs - ps->buf);
            return take(ps, cs, ce, "types", 1, ps->nc, (void **)&ps->types, NULL);
        }
        return CVM_OK;
    case SEC_POINTDATA:
        if (strcmp(name, "weight") == 0 && nc == 1)
            return take(ps, cs, ce, "weight", 0, ps->np, (void **)&ps->w, NULL);
        if (strcmp(name, "marker") == 0 && nc == 1)
            return take(ps, cs, ce, "point marker", 1, ps->np, (void **)&ps->pmark, NULL);
        if (strcmp(name, "attribute") == 0) {
            ps->nattr = (size_t)nc;
            return take(ps, cs, ce, "point attribute", 0, nc * ps->np, (void **)&ps->pattr, NULL);
        }
        return CVM_OK;
    case SEC_CELLDATA:
        if (strcmp(name, "marker") == 0 && nc == 1)
            return take(ps, cs, ce, "cell marker", 1, ps->nc, (void **)&ps->cmark, NULL);
        if (strcmp(name, "attribute") == 0 && nc == 1)
            return take(ps, cs, ce, "cell attribute", 0, ps->nc, (void **)&ps->cattr, NULL);
        return CVM_OK;
    default:
        return CVM_OK; /* e.g. FieldData */
    }
}

/* Tag name at p (after '<' and an optional '/') equals name. */
static int is_tag(const char *p, const char *name)
{
    size_t k = strlen(name);
    return strncmp(p, name, k) == 0 &&
           (p[k] == ' ' || p[k] == '>' || p[k] == '/' || p[k] == '\t' || p[k] == '\n' || p[k] == '\r');
}

/* Walk every tag of the file. */
static cvm_status scan_tags(vparser *ps)
{
    static const struct { const char *name; int sec; } secs[] = {
        {"PointData", SEC_POINTDATA}, {"CellData", SEC_CELLDATA}, {"Points", SEC_POINTS},
        {"Cells", SEC_CELLS}};
    const char *b = ps->buf, *p = b, *end = b + ps->n;
    int seen_file = 0;
    size_t k;
    cvm_status s;
    while ((p = memchr(p, '<', (size_t)(end - p))) != NULL) {
        const char *te, *q = p + 1;
        int closing = *q == '/';
        if (strncmp(p, "<!--", 4) == 0) {
            const char *c = strstr(p + 4, "-->");
            if (!c)
                return fail_at(ps, (size_t)(p - b), CVM_E_IO_FORMAT, "unterminated comment");
            p = c + 3;
            continue;
        }
        te = memchr(p, '>', (size_t)(end - p));
        if (!te)
            return fail_at(ps, (size_t)(p - b), CVM_E_IO_FORMAT,
                           "unterminated tag (truncated file?)");
        q += closing;
        if (*q == '?' || *q == '!') {
            p = te + 1;
            continue;
        }
        if (!closing && is_tag(q, "VTKFile")) {
            char v[ATTR_LEN];
            if (!attr(p, te, "type", v) || strcmp(v, "UnstructuredGrid") != 0)
                return fail_at(ps, (size_t)(p - b), CVM_E_UNSUPPORTED,
                               "not a VTK UnstructuredGrid file");
            if (attr(p, te, "compressor", v))
                return fail_at(ps, (size_t)(p - b), CVM_E_UNSUPPORTED,
                               "compressed data (%s) is not read", v);
            seen_file = 1;
        } else if (!closing && is_tag(q, "Piece")) {
            if (ps->have_piece)
                return fail_at(ps, (size_t)(p - b), CVM_E_UNSUPPORTED,
                               "more than one <Piece> is not read");
            if ((s = count_attr(ps, p, te, "NumberOfPoints", &ps->np)) ||
                (s = count_attr(ps, p, te, "NumberOfCells", &ps->nc)))
                return s;
            ps->have_piece = 1;
        } else if (!closing && is_tag(q, "AppendedData")) {
            return fail_at(ps, (size_t)(p - b), CVM_E_UNSUPPORTED,
                           "<AppendedData> is not read (write ASCII data arrays)");
        } else if (is_tag(q, "DataArray")) {
            const char *ce;
            if (closing)
                return fail_at(ps, (size_t)(p - b), CVM_E_IO_FORMAT, "stray </DataArray>");
            if (te[-1] == '/') { /* <DataArray ... /> : empty */
                if ((s = data_array(ps, p, te, te, te)))
                    return s;
                p = te + 1;
                continue;
            }
            ce = strstr(te + 1, "</DataArray");
            if (!ce)
                return fail_at(ps, (size_t)(p - b), CVM_E_IO_FORMAT,
                               "DataArray without </DataArray> (truncated file?)");
            if ((s = data_array(ps, p, te, te + 1, ce)))
                return s;
            p = ce + 1;
            continue;
        } else {
            for (k = 0; k < sizeof secs / sizeof secs[0]; k++)
                if (is_tag(q, secs[k].name))
                    ps->section = closing || te[-1] == '/' ? SEC_NONE : secs[k].sec;
        }
        p = te + 1;
    }
    if (!seen_file)
        return fail_at(ps, ps->n, CVM_E_IO_FORMAT, "no <VTKFile type=\"UnstructuredGrid\">");
    if (!ps->have_piece || !ps->xyz || !ps->conn || !ps->off || !ps->types)
        return fail_at(ps, ps->n, CVM_E_IO_FORMAT, "%s", !ps->have_piece ? "no <Piece>" :
                       !ps->xyz ? "no Points" : "Cells need connectivity, offsets and types");
    return CVM_OK;
}

/* Cells -> triangles and lines of out. */
static cvm_status build_cells(vparser *ps, cvm__vtu_mesh *out)
{
    size_t c, nt = 0, nl = 0, prev = 0, k;
    cvm__ctx *ctx = ps->ctx;
    for (c = 0; c < (size_t)ps->nc; c++) {
        long long t = ps->types[c], o = ps->off[c], need = t == 5 ? 3 : t == 3 ? 2 : 1;
        if (t != 5 && t != 3 && t != 1)
            return fail_at(ps, entry_at(ps, ps->at_types, c), CVM_E_UNSUPPORTED,
                           "cell %lld has VTK type %lld (only triangles 5, lines 3 and vertices 1 "
                           "are read)", (long long)c, t);
        if (o < 0 || (size_t)o > ps->nconn || (size_t)o < prev || (size_t)o - prev != (size_t)need)
            return fail_at(ps, entry_at(ps, ps->at_off, c), CVM_E_IO_FORMAT,
                           "cell %lld: offset %lld does not fit its type and the connectivity",
                           (long long)c, o);
        for (k = prev; k < (size_t)o; k++)
            if (ps->conn[k] < 0 || ps->conn[k] >= ps->np)
                return fail_at(ps, entry_at(ps, ps->at_conn, k), CVM_E_IO_FORMAT,
                               "cell %lld names point %lld, which does not exist (points are "
                               "numbered 0..%lld)", (long long)c, ps->conn[k], ps->np - 1);
        prev = (size_t)o;
        nt += t == 5;
        nl += t == 3;
    }
    if (prev != ps->nconn)
        return fail_at(ps, entry_at(ps, ps->at_conn, prev), CVM_E_IO_FORMAT,
                       "connectivity has %lld values, offsets end at %lld", (long long)ps->nconn,
                       (long long)prev);
    out->tri = cvm__malloc(ctx, (3 * nt + 1) * sizeof *out->tri);
    out->tattr = ps->cattr ? cvm__malloc(ctx, (nt + 1) * sizeof *out->tattr) : NULL;
    out->p.seg = cvm__malloc(ctx, (2 * nl + 1) * sizeof *out->p.seg);
    out->p.smark = ps->cmark ? cvm__malloc(ctx, (nl + 1) * sizeof *out->p.smark) : NULL;
    if (!out->tri || (ps->cattr && !out->tattr) || !out->p.seg || (ps->cmark && !out->p.smark))
        return cvm__nomem(ctx);
    prev = 0;
    for (c = 0; c < (size_t)ps->nc; c++) {
        size_t o = (size_t)ps->off[c];
        if (ps->types[c] == 5) {
            for (k = 0; k < 3; k++)
                out->tri[3 * out->nt + k] = (int32_t)ps->conn[prev + k];
            if (out->tattr)
                out->tattr[out->nt] = ps->cattr[c];
            out->nt++;
        } else if (ps->types[c] == 3) {
            out->p.seg[2 * out->p.nseg] = (int32_t)ps->conn[prev];
            out->p.seg[2 * out->p.nseg + 1] = (int32_t)ps->conn[prev + 1];
            if (out->p.smark)
                out->p.smark[out->p.nseg] = (int32_t)ps->cmark[c];
            out->p.nseg++;
        }
        prev = o;
    }
    out->has_lines = nl > 0;
    return CVM_OK;
}

/* Points and point data -> out. */
static cvm_status build_points(vparser *ps, cvm__vtu_mesh *out)
{
    size_t v, np = (size_t)ps->np, nc = ps->ncomp_xyz;
    cvm__ctx *ctx = ps->ctx;
    out->p.xy = cvm__malloc(ctx, (2 * np + 1) * sizeof *out->p.xy);
    out->p.pmark = ps->pmark ? cvm__malloc(ctx, (np + 1) * sizeof *out->p.pmark) : NULL;
    if (!out->p.xy || (ps->pmark && !out->p.pmark))
        return cvm__nomem(ctx);
    for (v = 0; v < np; v++) {
        if (nc == 3 && ps->xyz[3 * v + 2] != 0)
            return fail_at(ps, entry_at(ps, ps->at_xyz, 3 * v + 2), CVM_E_IO_FORMAT,
                           "point %lld has z != 0 (only planar meshes are read)", (long long)v);
        out->p.xy[2 * v] = ps->xyz[nc * v];
        out->p.xy[2 * v + 1] = ps->xyz[nc * v + 1];
        if (out->p.pmark)
            out->p.pmark[v] = (int32_t)ps->pmark[v];
    }
    out->p.np = np;
    out->p.pattr = ps->pattr;
    out->p.nattr = ps->pattr ? ps->nattr : 0;
    ps->pattr = NULL;
    out->w = ps->w;
    ps->w = NULL;
    return CVM_OK;
}

void cvm__vtu_mesh_free(cvm__ctx *ctx, cvm__vtu_mesh *vm)
{
    cvm__pslg_free(ctx, &vm->p);
    cvm__free(ctx, vm->tri);
    cvm__free(ctx, vm->w);
    cvm__free(ctx, vm->tattr);
    memset(vm, 0, sizeof *vm);
}

cvm_status cvm__read_vtu(cvm__ctx *ctx, cvm__reader *r, const char *name, cvm__vtu_mesh *out)
{
    vparser ps;
    cvm_status s;
    memset(&ps, 0, sizeof ps);
    memset(out, 0, sizeof *out);
    ps.ctx = ctx;
    ps.name = name;
    if (!(s = slurp(&ps, r)) && !(s = scan_tags(&ps)) && !(s = build_cells(&ps, out)))
        s = build_points(&ps, out);
    cvm__free(ctx, ps.buf);
    cvm__free(ctx, ps.xyz);
    cvm__free(ctx, ps.conn);
    cvm__free(ctx, ps.off);
    cvm__free(ctx, ps.types);
    cvm__free(ctx, ps.cmark);
    cvm__free(ctx, ps.pmark);
    cvm__free(ctx, ps.w);
    cvm__free(ctx, ps.pattr);
    cvm__free(ctx, ps.cattr);
    if (s)
        cvm__vtu_mesh_free(ctx, out);
    return s;
}

cvm_status cvm__read_vtu_file(cvm__ctx *ctx, const char *path, cvm__vtu_mesh *out)
{
    cvm__reader r;
    cvm_status s = cvm__file_reader_open(ctx, &r, path);
    memset(out, 0, sizeof *out);
    if (s)
        return s;
    s = cvm__read_vtu(ctx, &r, path, out);
    cvm__file_reader_close(&r);
    return s;
}
