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
 * skipped. Data arrays are ASCII, inline binary (base64) or appended (raw or
 * base64), optionally zlib-compressed, of any integer or float type
 * (vtu_data.c decodes them). This is a small tolerant tag scanner, not a
 * general XML parser: comments, processing instructions and any attribute
 * order are understood; entities and CDATA are not. Every error names
 * file:line (or the byte offset in raw appended data).
 */
#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "io_text.h"
#include "vtu_data.h"

#define MAX_COUNT ((long long)INT32_MAX / 4)
#define MAX_COMP 10000
#define ATTR_LEN CVM__VTU_ATTR_LEN

enum { SEC_NONE, SEC_POINTDATA, SEC_CELLDATA, SEC_POINTS, SEC_CELLS };

/* The arrays read: found while the tags are scanned, decoded after (appended
 * data follows every tag). */
enum { R_XYZ, R_CONN, R_OFF, R_TYPES, R_W, R_PMARK, R_PATTR, R_CMARK, R_CATTR, R_N };
static const struct role {
    const char *what;
    int integer;
} k_roles[R_N] = {{"Points", 0},       {"connectivity", 1},    {"offsets", 1},
                  {"types", 1},        {"weight", 0},          {"point marker", 1},
                  {"point attribute", 0}, {"cell marker", 1}, {"cell attribute", 0}};

typedef struct vparser {
    cvm__ctx *ctx;
    const char *name; /* file name for messages */
    char *buf;        /* the whole file, NUL-terminated */
    size_t n, pos;
    cvm__vtu_file f;  /* buf and the file-wide encoding */
    cvm__vtu_array arr[R_N];
    long long ncomp[R_N]; /* 0: array not seen */
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
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    return cvm__vtu_fail(&ps->f, at, st, "%s", what);
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
    ps->f.buf = ps->buf;
    ps->f.n = ps->n;
    return CVM_OK;
}

/* A count attribute of the tag at [s, e). */
static cvm_status count_attr(vparser *ps, const char *s, const char *e, const char *key,
                             long long *out)
{
    char v[ATTR_LEN];
    int r;
    if (!cvm__vtu_attr(s, e, key, v))
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

/* Note array [ts, te) [cs, ce) in role r, refusing a second one. */
static cvm_status take(vparser *ps, const char *ts, const char *te, const char *cs, const char *ce,
                       int r, long long nc)
{
    if (ps->ncomp[r])
        return fail_at(ps, (size_t)(ts - ps->buf), CVM_E_IO_FORMAT, "a second %s array",
                       k_roles[r].what);
    ps->ncomp[r] = nc;
    ps->arr[r].ts = (size_t)(ts - ps->buf);
    ps->arr[r].te = (size_t)(te - ps->buf);
    ps->arr[r].cs = (size_t)(cs - ps->buf);
    ps->arr[r].ce = (size_t)(ce - ps->buf);
    return CVM_OK;
}

/* A <DataArray> whose start tag is [ts, te) and content [cs, ce). */
static cvm_status data_array(vparser *ps, const char *ts, const char *te, const char *cs,
                             const char *ce)
{
    char name[ATTR_LEN] = "", fmt[ATTR_LEN] = "", comp[ATTR_LEN] = "1";
    long long nc = 1;
    size_t at = (size_t)(ts - ps->buf);
    cvm__vtu_attr(ts, te, "Name", name);
    cvm__vtu_attr(ts, te, "NumberOfComponents", comp);
    if (!cvm__vtu_attr(ts, te, "format", fmt))
        return fail_at(ps, at, CVM_E_IO_FORMAT, "DataArray '%s' has no format", name);
    if (cvm__parse_long(comp, 1, MAX_COMP, &nc))
        return fail_at(ps, at, CVM_E_IO_FORMAT, "DataArray '%s': bad NumberOfComponents", name);
    if (!ps->have_piece)
        return fail_at(ps, at, CVM_E_IO_FORMAT, "DataArray '%s' outside a <Piece>", name);
    switch (ps->section) {
    case SEC_POINTS:
        if (nc != 3 && nc != 2)
            return fail_at(ps, at, CVM_E_IO_FORMAT, "Points have %lld components (need 3)", nc);
        return take(ps, ts, te, cs, ce, R_XYZ, nc);
    case SEC_CELLS:
        if (strcmp(name, "connectivity") == 0)
            return take(ps, ts, te, cs, ce, R_CONN, 1);
        if (strcmp(name, "offsets") == 0)
            return take(ps, ts, te, cs, ce, R_OFF, 1);
        if (strcmp(name, "types") == 0)
            return take(ps, ts, te, cs, ce, R_TYPES, 1);
        return CVM_OK;
    case SEC_POINTDATA:
        if (strcmp(name, "weight") == 0 && nc == 1)
            return take(ps, ts, te, cs, ce, R_W, 1);
        if (strcmp(name, "marker") == 0 && nc == 1)
            return take(ps, ts, te, cs, ce, R_PMARK, 1);
        if (strcmp(name, "attribute") == 0)
            return take(ps, ts, te, cs, ce, R_PATTR, nc);
        return CVM_OK;
    case SEC_CELLDATA:
        if (strcmp(name, "marker") == 0 && nc == 1)
            return take(ps, ts, te, cs, ce, R_CMARK, 1);
        if (strcmp(name, "attribute") == 0 && nc == 1)
            return take(ps, ts, te, cs, ce, R_CATTR, 1);
        return CVM_OK;
    default:
        return CVM_OK; /* e.g. FieldData */
    }
}

/* The attributes of <VTKFile> [p, te): type, byte order, header type, compressor. */
static cvm_status file_tag(vparser *ps, const char *p, const char *te)
{
    char v[ATTR_LEN];
    size_t at = (size_t)(p - ps->buf);
    if (!cvm__vtu_attr(p, te, "type", v) || strcmp(v, "UnstructuredGrid") != 0)
        return fail_at(ps, at, CVM_E_UNSUPPORTED, "not a VTK UnstructuredGrid file");
    if (cvm__vtu_attr(p, te, "byte_order", v)) {
        if (strcmp(v, "BigEndian") != 0 && strcmp(v, "LittleEndian") != 0)
            return fail_at(ps, at, CVM_E_IO_FORMAT, "byte_order=\"%s\" (LittleEndian or BigEndian)", v);
        ps->f.big_endian = v[0] == 'B';
    }
    if (cvm__vtu_attr(p, te, "header_type", v)) {
        if (strcmp(v, "UInt32") != 0 && strcmp(v, "UInt64") != 0)
            return fail_at(ps, at, CVM_E_UNSUPPORTED, "header_type=\"%s\" is not read (UInt32 or "
                           "UInt64)", v);
        ps->f.header64 = v[4] == '6';
    }
    if (cvm__vtu_attr(p, te, "compressor", v)) {
        if (strcmp(v, "vtkZLibDataCompressor") != 0)
            return fail_at(ps, at, CVM_E_UNSUPPORTED, "compressor=\"%s\" is not read (only "
                           "vtkZLibDataCompressor)", v);
        ps->f.zlib = 1;
    }
    return CVM_OK;
}

/* <AppendedData encoding=...> [p, te): its data starts after the '_'. */
static cvm_status appended_tag(vparser *ps, const char *p, const char *te)
{
    char v[ATTR_LEN] = "";
    const char *u = te + 1, *end = ps->buf + ps->n;
    if (!cvm__vtu_attr(p, te, "encoding", v) || (strcmp(v, "raw") != 0 && strcmp(v, "base64") != 0))
        return fail_at(ps, (size_t)(p - ps->buf), CVM_E_IO_FORMAT,
                       "<AppendedData> needs encoding=\"raw\" or \"base64\"");
    while (u < end && (*u == ' ' || *u == '\t' || *u == '\n' || *u == '\r'))
        u++;
    if (u >= end || *u != '_')
        return fail_at(ps, (size_t)(u - ps->buf), CVM_E_IO_FORMAT,
                       "<AppendedData> data must start with '_'");
    ps->f.appended = (size_t)(u + 1 - ps->buf);
    ps->f.appended_raw = v[0] == 'r';
    return CVM_OK;
}

/* Tag name at p (after '<' and an optional '/') equals name. */
static int is_tag(const char *p, const char *name)
{
    size_t k = strlen(name);
    return strncmp(p, name, k) == 0 &&
           (p[k] == ' ' || p[k] == '>' || p[k] == '/' || p[k] == '\t' || p[k] == '\n' || p[k] == '\r');
}

/* Walk every tag of the file up to byte lim (a NUL byte, or the end). */
static cvm_status walk_tags(vparser *ps, size_t lim)
{
    static const struct { const char *name; int sec; } secs[] = {
        {"PointData", SEC_POINTDATA}, {"CellData", SEC_CELLDATA}, {"Points", SEC_POINTS},
        {"Cells", SEC_CELLS}};
    const char *b = ps->buf, *p = b, *end = b + lim;
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
            if ((s = file_tag(ps, p, te)))
                return s;
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
            if ((s = appended_tag(ps, p, te)))
                return s;
            break; /* the rest is data */
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
    return CVM_OK;
}

/* After decoding: the arrays every file needs are there. */
static cvm_status complete(vparser *ps)
{
    if (!ps->have_piece || !ps->ncomp[R_XYZ] || !ps->ncomp[R_CONN] || !ps->ncomp[R_OFF] ||
        !ps->ncomp[R_TYPES])
        return fail_at(ps, ps->n, CVM_E_IO_FORMAT, "%s", !ps->have_piece ? "no <Piece>" :
                       !ps->ncomp[R_XYZ] ? "no Points" : "Cells need connectivity, offsets and types");
    return CVM_OK;
}

/* Walk the tags; a NUL byte may only appear in appended data. */
static cvm_status scan_tags(vparser *ps)
{
    const char *nul = memchr(ps->buf, '\0', ps->n);
    size_t lim = nul ? (size_t)(nul - ps->buf) : ps->n;
    cvm_status s = walk_tags(ps, lim);
    if (lim < ps->n && (s == CVM_E_IO_FORMAT || !s) && (!ps->f.appended || ps->f.appended > lim))
        return fail_at(ps, lim, CVM_E_IO_FORMAT, "NUL byte (not a text file?)");
    return s;
}

/* Decode every array noted by scan_tags(). */
static cvm_status decode_arrays(vparser *ps)
{
    void **slot[R_N];
    long long want[R_N];
    size_t got = 0;
    int r;
    cvm_status s;
    slot[R_XYZ] = (void **)&ps->xyz;
    slot[R_CONN] = (void **)&ps->conn;
    slot[R_OFF] = (void **)&ps->off;
    slot[R_TYPES] = (void **)&ps->types;
    slot[R_W] = (void **)&ps->w;
    slot[R_PMARK] = (void **)&ps->pmark;
    slot[R_PATTR] = (void **)&ps->pattr;
    slot[R_CMARK] = (void **)&ps->cmark;
    slot[R_CATTR] = (void **)&ps->cattr;
    for (r = 0; r < R_N; r++) {
        int cells = r == R_OFF || r == R_TYPES || r == R_CMARK || r == R_CATTR;
        want[r] = r == R_CONN ? -1 : ps->ncomp[r] * (cells ? ps->nc : ps->np);
    }
    for (;;) { /* in file order, so the first bad value in the file is the one named */
        int next = -1;
        for (r = 0; r < R_N; r++)
            if (ps->ncomp[r] && !*slot[r] && (next < 0 || ps->arr[r].ts < ps->arr[next].ts))
                next = r;
        if (next < 0)
            break;
        if ((s = cvm__vtu_decode(&ps->f, &ps->arr[next], k_roles[next].what, k_roles[next].integer,
                                 want[next], slot[next], next == R_CONN ? &got : NULL)))
            return s;
    }
    ps->nconn = got;
    ps->ncomp_xyz = (size_t)ps->ncomp[R_XYZ];
    ps->nattr = (size_t)ps->ncomp[R_PATTR];
    ps->at_xyz = ps->arr[R_XYZ].cs;
    ps->at_conn = ps->arr[R_CONN].cs;
    ps->at_off = ps->arr[R_OFF].cs;
    ps->at_types = ps->arr[R_TYPES].cs;
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
    cvm__free(ctx, vm->names);
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
    ps.f.ctx = ctx;
    ps.f.name = name;
    if (!(s = slurp(&ps, r)) && !(s = scan_tags(&ps)) && !(s = decode_arrays(&ps)) &&
        !(s = complete(&ps)) && !(s = build_cells(&ps, out)))
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
