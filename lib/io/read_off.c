/*
 * read_off.c - parses Object File Format (.off) surfaces into a cvm__surf3.
 *
 * Format (Geomview's OFF): an optional "OFF" keyword, then
 *   <#points> <#faces> <#edges>          (the edge count is read and ignored)
 *   <x> <y> <z>                          (one line per point)
 *   <n> <i1> ... <in> [colour]           (one line per face, 0-based indices;
 *                                         up to 4 colour fields are ignored)
 * '#' starts a comment. Each face is one facet of one polygon, marker 1.
 * Stricter than most readers: every line must have its fields and nothing may
 * follow the last face, so a wrong count is caught where it shows.
 */
#include <limits.h>
#include <stdio.h>
#include <string.h>

#include "surf3_io.h"

typedef struct off_parser {
    cvm__scan sc;
    cvm__ctx *ctx;
    cvm__surf3 *s;
    int32_t *idx;       /* corners of the current face */
    size_t cap_idx;
} off_parser;

static cvm_status read_header(off_parser *ps, long long *np, long long *nf)
{
    long long ne;
    size_t left;
    cvm_status s;
    const char *first;
    if ((s = cvm__s3_need_line(&ps->sc, "the OFF header")))
        return s;
    first = cvm__scan_field(&ps->sc);
    left = ps->sc.nfields - 1;
    if (strcmp(first, "OFF") == 0) {
        if (left == 0) {
            if ((s = cvm__s3_need_line(&ps->sc, "the count line")))
                return s;
            left = ps->sc.nfields;
        }
    } else if (strstr(first, "OFF")) {
        return cvm__scan_error(&ps->sc, CVM_E_UNSUPPORTED,
                               "'%.20s' files are not read: only plain OFF (no colours, normals or "
                               "texture coordinates per point)", first);
    } else {
        ps->sc.cursor = 0; /* no keyword: this line holds the counts */
        left = ps->sc.nfields;
    }
    if (left < 2 || left > 3)
        return cvm__scan_error(&ps->sc, CVM_E_IO_FORMAT,
                               "count line: expected 2 or 3 fields (points, faces[, edges]), found %lu",
                               (unsigned long)left);
    if ((s = cvm__s3_count(&ps->sc, "point count", np)) ||
        (s = cvm__s3_count(&ps->sc, "face count", nf)) ||
        (left == 3 && (s = cvm__s3_count(&ps->sc, "edge count", &ne))))
        return s;
    return CVM_OK;
}

static cvm_status read_points(off_parser *ps, long long np)
{
    long long i;
    char what[64];
    cvm_status s;
    for (i = 0; i < np; i++) {
        double x, y, z;
        snprintf(what, sizeof what, "point %lld of %lld", i, np);
        if ((s = cvm__s3_need_line(&ps->sc, what)) ||
            (s = cvm__s3_want_fields(&ps->sc, 3, 3, what, "x, y, z")) ||
            (s = cvm__s3_real(&ps->sc, "point", i, &x)) || (s = cvm__s3_real(&ps->sc, "point", i, &y)) ||
            (s = cvm__s3_real(&ps->sc, "point", i, &z)))
            return s;
        if ((s = cvm__surf3_add_point(ps->ctx, ps->s, x, y, z)))
            return s;
    }
    return CVM_OK;
}

static cvm_status read_face(off_parser *ps, long long k, long long nf)
{
    long long n, v, j, np = (long long)ps->s->np;
    char what[64];
    cvm_status s;
    snprintf(what, sizeof what, "face %lld of %lld", k, nf);
    if ((s = cvm__s3_need_line(&ps->sc, what)))
        return s;
    snprintf(what, sizeof what, "corner count of face %lld", k);
    if ((s = cvm__s3_int(&ps->sc, what, 3, (long long)CVM__SURF3_MAX_COUNT, &n)))
        return s;
    if ((size_t)n + 1 > ps->sc.nfields || (size_t)n + 5 < ps->sc.nfields)
        return cvm__scan_error(&ps->sc, CVM_E_IO_FORMAT,
                               "face %lld: %lld corners need %lld fields (up to 4 more for a colour), "
                               "found %lu", k, n, n + 1, (unsigned long)ps->sc.nfields);
    if (cvm__grow(ps->ctx, (void **)&ps->idx, &ps->cap_idx, (size_t)n, sizeof(int32_t)))
        return cvm__nomem(ps->ctx);
    for (j = 0; j < n; j++) {
        const char *f = cvm__scan_field(&ps->sc);
        int r = cvm__parse_long(f, LLONG_MIN, LLONG_MAX, &v);
        if (r == 1)
            return cvm__scan_error(&ps->sc, CVM_E_IO_FORMAT,
                                   "face %lld: corner %lld: expected an integer, found '%.40s'", k, j, f);
        if (r || v < 0 || v >= np)
            return cvm__scan_error(&ps->sc, CVM_E_IO_FORMAT,
                                   "face %lld names point %.40s, but points are numbered 0..%lld", k, f,
                                   np - 1);
        ps->idx[j] = (int32_t)v;
    }
    if ((s = cvm__surf3_add_facet(ps->ctx, ps->s, 1)) ||
        (s = cvm__surf3_add_polygon(ps->ctx, ps->s, ps->idx, (size_t)n)))
        return s;
    if ((size_t)ps->s->poff[ps->s->npoly] > CVM__SURF3_MAX_COUNT)
        return cvm__scan_error(&ps->sc, CVM_E_TOO_LARGE, "more than %lu face corners in all",
                               (unsigned long)CVM__SURF3_MAX_COUNT);
    return CVM_OK;
}

static cvm_status parse(off_parser *ps)
{
    long long np, nf, k;
    cvm_status s;
    if ((s = read_header(ps, &np, &nf)) || (s = read_points(ps, np)))
        return s;
    for (k = 0; k < nf; k++)
        if ((s = read_face(ps, k, nf)))
            return s;
    return cvm__s3_expect_end(&ps->sc, nf ? "last face" : "last point");
}

cvm_status cvm__read_off(cvm__ctx *ctx, cvm__reader *r, const char *name, cvm__surf3 *out)
{
    off_parser ps;
    cvm_status s;
    cvm__surf3_init(out);
    memset(&ps, 0, sizeof ps);
    cvm__scan_init(&ps.sc, ctx, r, name);
    ps.ctx = ctx;
    ps.s = out;
    out->facet_word = "face";
    out->point_base = 0;
    out->facet_base = 0;
    s = parse(&ps);
    if (s == CVM_OK)
        s = cvm__surf3_set_file(ctx, out, name);
    cvm__scan_free(&ps.sc);
    cvm__free(ctx, ps.idx);
    if (s)
        cvm__surf3_free(ctx, out);
    return s;
}
