/*
 * read_tetpoly.c - parses TetGen's 3D .poly, .smesh and .node text into a cvm__surf3.
 *
 * Format (H. Si, TetGen 1.5 user's manual, section 5.2):
 *   points   <#points> [<dimension = 3> [<#attributes> [<#markers 0|1>]]]
 *            <number> <x> <y> <z> [attributes...] [marker]
 *   .poly    <#facets> [<#markers 0|1>]
 *            per facet: <#polygons> [<#holes> [<marker>]]
 *                       <#corners> <p1> ... <pn>            (#polygons lines)
 *                       <number> <x> <y> <z>                (#holes lines: facet holes)
 *   .smesh   <#facets> [<#markers 0|1>]
 *            per facet: <#corners> <p1> ... <pn> [<marker>]
 *   then     <#holes>, <number> <x> <y> <z>                  (volume holes)
 *            optionally <#regions>, <number> <x> <y> <z> <attribute> [<max volume>]
 * Points are numbered from 0 or 1, as the first point says; facets use the same
 * numbering. Attributes of points are checked to be numbers and dropped. A
 * missing facet marker is 0; a missing max volume is -1 (none). As with the 2D
 * reader, every line must have the fields its header announces and nothing may
 * follow the last section; errors name file:line and the item's file number.
 */
#include <limits.h>
#include <stdio.h>
#include <string.h>

#include "surf3_io.h"

#define MAX_ATTR 10000

typedef struct tp_parser {
    cvm__scan sc;
    cvm__ctx *ctx;
    cvm__surf3 *s;
    int is_smesh;
    long long base;            /* first point number, -1 until known */
    long long np;              /* points the facets may name */
    int32_t *idx;
    size_t cap_idx;
} tp_parser;

static cvm_status read_points(tp_parser *ps)
{
    long long np, dim = 3, nattr = 0, nmark = 0, i, k, num;
    size_t n;
    double v[3], a;
    cvm_status s;
    if ((s = cvm__s3_need_line(&ps->sc, "the point count line")))
        return s;
    n = ps->sc.nfields;
    if (n > 4)
        return cvm__scan_error(&ps->sc, CVM_E_IO_FORMAT,
                               "point count line: expected at most 4 fields (points, dimension, "
                               "attributes, markers), found %lu", (unsigned long)n);
    if ((s = cvm__s3_count(&ps->sc, "point count", &np)) ||
        (n > 1 && (s = cvm__s3_int(&ps->sc, "dimension", LLONG_MIN, LLONG_MAX, &dim))))
        return s;
    if (dim != 3)
        return cvm__scan_error(&ps->sc, CVM_E_IO_FORMAT, "dimension %lld: a 3D file needs 3", dim);
    if ((n > 2 && (s = cvm__s3_count(&ps->sc, "attribute count", &nattr))) ||
        (n > 3 && (s = cvm__s3_int(&ps->sc, "point marker count", 0, 1, &nmark))))
        return s;
    if (nattr > MAX_ATTR)
        return cvm__scan_error(&ps->sc, CVM_E_TOO_LARGE, "%lld attributes per point: at most %d",
                               nattr, MAX_ATTR);
    for (i = 0; i < np; i++) {
        char what[64];
        snprintf(what, sizeof what, "point %lld of %lld", i + 1, np);
        if ((s = cvm__s3_need_line(&ps->sc, what)) ||
            (s = cvm__s3_want_fields(&ps->sc, (size_t)(4 + nattr + nmark), (size_t)(4 + nattr + nmark),
                                     what, nmark ? "number, x, y, z, attributes, marker"
                                                 : "number, x, y, z, attributes")) ||
            (s = cvm__s3_int(&ps->sc, "point number", LLONG_MIN, LLONG_MAX, &num)))
            return s;
        if (i == 0) {
            if (num != 0 && num != 1)
                return cvm__scan_error(&ps->sc, CVM_E_IO_FORMAT,
                                       "the first point is numbered %lld: it must be 0 or 1", num);
            ps->base = num;
        } else if (num != ps->base + i) {
            return cvm__scan_error(&ps->sc, CVM_E_IO_FORMAT, "point number %lld out of sequence: expected %lld",
                                   num, ps->base + i);
        }
        for (k = 0; k < 3; k++)
            if ((s = cvm__s3_real(&ps->sc, "point", num, &v[k])))
                return s;
        for (k = 0; k < nattr; k++)
            if ((s = cvm__s3_real(&ps->sc, "attribute of point", num, &a)))
                return s;
        if (nmark && (s = cvm__s3_int(&ps->sc, "point marker", INT32_MIN, INT32_MAX, &k)))
            return s;
        if ((s = cvm__surf3_add_point(ps->ctx, ps->s, v[0], v[1], v[2])))
            return s;
    }
    ps->np = np;
    return CVM_OK;
}

/* Corners of a polygon of facet fnum from the current field on: n indices. */
static cvm_status read_corners(tp_parser *ps, long long fnum, long long n)
{
    long long j, v;
    if (cvm__grow(ps->ctx, (void **)&ps->idx, &ps->cap_idx, (size_t)(n ? n : 1), sizeof(int32_t)))
        return cvm__nomem(ps->ctx);
    for (j = 0; j < n; j++) {
        const char *f = cvm__scan_field(&ps->sc);
        int r = cvm__parse_long(f, LLONG_MIN, LLONG_MAX, &v);
        if (r == 1)
            return cvm__scan_error(&ps->sc, CVM_E_IO_FORMAT,
                                   "facet %lld: corner %lld: expected an integer, found '%.40s'", fnum,
                                   j + 1, f);
        if (ps->np == 0)
            return cvm__scan_error(&ps->sc, CVM_E_IO_FORMAT, "facet %lld names point %.40s, but there are no points",
                                   fnum, f);
        if (r || v < ps->base || v >= ps->base + ps->np)
            return cvm__scan_error(&ps->sc, CVM_E_IO_FORMAT,
                                   "facet %lld names point %.40s, but points are numbered %lld..%lld", fnum,
                                   f, ps->base, ps->base + ps->np - 1);
        ps->idx[j] = (int32_t)(v - ps->base);
    }
    return cvm__surf3_add_polygon(ps->ctx, ps->s, ps->idx, (size_t)n);
}

static cvm_status check_total(tp_parser *ps)
{
    if (ps->s->npoly && (size_t)ps->s->poff[ps->s->npoly] > CVM__SURF3_MAX_COUNT)
        return cvm__scan_error(&ps->sc, CVM_E_TOO_LARGE, "more than %lu polygon corners in all",
                               (unsigned long)CVM__SURF3_MAX_COUNT);
    return CVM_OK;
}

/* One .poly facet: header line, polygons, facet holes. */
static cvm_status read_poly_facet(tp_parser *ps, long long fnum, long long nf, int marked)
{
    long long npoly, nhole = 0, mark = 0, k, n, num;
    char what[80];
    double h[3];
    cvm_status s;
    snprintf(what, sizeof what, "facet %lld of %lld", fnum, nf);
    if ((s = cvm__s3_need_line(&ps->sc, what)) ||
        (s = cvm__s3_want_fields(&ps->sc, 1, marked ? 3 : 2, what,
                                 marked ? "polygons[, holes[, marker]]" : "polygons[, holes]")) ||
        (s = cvm__s3_count(&ps->sc, "polygon count", &npoly)) ||
        (ps->sc.nfields > 1 && (s = cvm__s3_count(&ps->sc, "facet hole count", &nhole))) ||
        (ps->sc.nfields > 2 && (s = cvm__s3_int(&ps->sc, "facet marker", INT32_MIN, INT32_MAX, &mark))))
        return s;
    if ((s = cvm__surf3_add_facet(ps->ctx, ps->s, (int32_t)mark)))
        return s;
    for (k = 0; k < npoly; k++) {
        snprintf(what, sizeof what, "polygon %lld of facet %lld", k + 1, fnum);
        if ((s = cvm__s3_need_line(&ps->sc, what)) ||
            (s = cvm__s3_int(&ps->sc, "corner count", 1, (long long)CVM__SURF3_MAX_COUNT, &n)))
            return s;
        if ((size_t)n + 1 != ps->sc.nfields)
            return cvm__scan_error(&ps->sc, CVM_E_IO_FORMAT,
                                   "polygon %lld of facet %lld: %lld corners need %lld fields, found %lu",
                                   k + 1, fnum, n, n + 1, (unsigned long)ps->sc.nfields);
        if ((s = read_corners(ps, fnum, n)) || (s = check_total(ps)))
            return s;
    }
    for (k = 0; k < nhole; k++) {
        snprintf(what, sizeof what, "hole %lld of facet %lld", k + 1, fnum);
        if ((s = cvm__s3_need_line(&ps->sc, what)) ||
            (s = cvm__s3_want_fields(&ps->sc, 4, 4, what, "number, x, y, z")) ||
            (s = cvm__s3_int(&ps->sc, "hole number", LLONG_MIN, LLONG_MAX, &num)) ||
            (s = cvm__s3_real(&ps->sc, "facet hole", num, &h[0])) ||
            (s = cvm__s3_real(&ps->sc, "facet hole", num, &h[1])) ||
            (s = cvm__s3_real(&ps->sc, "facet hole", num, &h[2])) ||
            (s = cvm__surf3_add_facet_hole(ps->ctx, ps->s, h)))
            return s;
    }
    return CVM_OK;
}

/* One .smesh facet: <#corners> <p1> ... <pn> [marker]. */
static cvm_status read_smesh_facet(tp_parser *ps, long long fnum, long long nf, int marked)
{
    long long n, mark = 0;
    char what[80];
    cvm_status s;
    snprintf(what, sizeof what, "facet %lld of %lld", fnum, nf);
    if ((s = cvm__s3_need_line(&ps->sc, what)) ||
        (s = cvm__s3_int(&ps->sc, "corner count", 1, (long long)CVM__SURF3_MAX_COUNT, &n)))
        return s;
    if ((size_t)n + 1 + (size_t)marked != ps->sc.nfields && (size_t)n + 1 != ps->sc.nfields)
        return cvm__scan_error(&ps->sc, CVM_E_IO_FORMAT, "facet %lld: %lld corners need %lld fields%s, found %lu",
                               fnum, n, n + 1, marked ? " (and a marker)" : "",
                               (unsigned long)ps->sc.nfields);
    if ((s = cvm__surf3_add_facet(ps->ctx, ps->s, 0)) || (s = read_corners(ps, fnum, n)) ||
        (s = check_total(ps)))
        return s;
    if (ps->sc.nfields == (size_t)n + 2 &&
        (s = cvm__s3_int(&ps->sc, "facet marker", INT32_MIN, INT32_MAX, &mark)))
        return s;
    ps->s->fmark[ps->s->nfacet - 1] = (int32_t)mark;
    return CVM_OK;
}

static cvm_status read_facets(tp_parser *ps)
{
    long long nf, marked = 0, k;
    cvm_status s;
    if ((s = cvm__s3_need_line(&ps->sc, "the facet count line")) ||
        (s = cvm__s3_want_fields(&ps->sc, 1, 2, "facet count line",
                                 "facets[, markers]; does the point count match the point lines?")) ||
        (s = cvm__s3_count(&ps->sc, "facet count", &nf)) ||
        (ps->sc.nfields > 1 && (s = cvm__s3_int(&ps->sc, "facet marker count", 0, 1, &marked))))
        return s;
    for (k = 0; k < nf; k++) {
        long long fnum = ps->base < 0 ? k : ps->base + k;
        if ((s = ps->is_smesh ? read_smesh_facet(ps, fnum, nf, (int)marked)
                              : read_poly_facet(ps, fnum, nf, (int)marked)))
            return s;
    }
    return CVM_OK;
}

/* Hole points, then the optional regions. */
static cvm_status read_holes_regions(tp_parser *ps)
{
    long long n, k, num;
    double v[5];
    int got, j;
    char what[64];
    cvm_status s;
    if ((s = cvm__s3_need_line(&ps->sc, "the hole count line")) ||
        (s = cvm__s3_want_fields(&ps->sc, 1, 1, "hole count line", "holes; does the facet count match the facets?")) ||
        (s = cvm__s3_count(&ps->sc, "hole count", &n)))
        return s;
    for (k = 0; k < n; k++) {
        snprintf(what, sizeof what, "hole %lld of %lld", k + 1, n);
        if ((s = cvm__s3_need_line(&ps->sc, what)) || (s = cvm__s3_want_fields(&ps->sc, 4, 4, what, "number, x, y, z")) ||
            (s = cvm__s3_int(&ps->sc, "hole number", LLONG_MIN, LLONG_MAX, &num)))
            return s;
        for (j = 0; j < 3; j++)
            if ((s = cvm__s3_real(&ps->sc, "hole", num, &v[j])))
                return s;
        if ((s = cvm__surf3_add_hole(ps->ctx, ps->s, v)))
            return s;
    }
    if ((s = cvm__scan_line(&ps->sc, &got)) || !got)
        return s;
    if ((s = cvm__s3_want_fields(&ps->sc, 1, 1, "region count line", "regions; does the hole count match the holes?")) ||
        (s = cvm__s3_count(&ps->sc, "region count", &n)))
        return s;
    for (k = 0; k < n; k++) {
        snprintf(what, sizeof what, "region %lld of %lld", k + 1, n);
        if ((s = cvm__s3_need_line(&ps->sc, what)) ||
            (s = cvm__s3_want_fields(&ps->sc, 5, 6, what, "number, x, y, z, attribute[, max volume]")) ||
            (s = cvm__s3_int(&ps->sc, "region number", LLONG_MIN, LLONG_MAX, &num)))
            return s;
        v[4] = -1.0;
        for (j = 0; j < (int)ps->sc.nfields - 1; j++)
            if ((s = cvm__s3_real(&ps->sc, "region", num, &v[j])))
                return s;
        if ((s = cvm__surf3_add_region(ps->ctx, ps->s, v)))
            return s;
    }
    return cvm__s3_expect_end(&ps->sc, "last region");
}

static void start(tp_parser *ps, cvm__ctx *ctx, cvm__reader *r, const char *name, cvm__surf3 *out)
{
    cvm__surf3_init(out);
    memset(ps, 0, sizeof *ps);
    cvm__scan_init(&ps->sc, ctx, r, name);
    ps->ctx = ctx;
    ps->s = out;
    ps->base = -1;
}

static cvm_status finish(tp_parser *ps, cvm_status s, const char *name)
{
    if (s == CVM_OK)
        s = cvm__surf3_set_file(ps->ctx, ps->s, name);
    cvm__scan_free(&ps->sc);
    cvm__free(ps->ctx, ps->idx);
    if (s) {
        cvm__surf3_free(ps->ctx, ps->s);
        return s;
    }
    ps->s->point_base = (int32_t)(ps->base < 0 ? 0 : ps->base);
    ps->s->facet_base = ps->s->point_base;
    return CVM_OK;
}

cvm_status cvm__read_tetpoly(cvm__ctx *ctx, cvm__reader *r, const char *name, int is_smesh,
                             const cvm__surf3_ext_points *ext, cvm__surf3 *out)
{
    tp_parser ps;
    cvm_status s;
    start(&ps, ctx, r, name, out);
    ps.is_smesh = is_smesh;
    s = read_points(&ps);
    if (!s && ps.np == 0 && ext) {
        size_t i;
        ps.base = ext->base;
        ps.np = (long long)ext->np;
        for (i = 0; i < ext->np && !s; i++)
            s = cvm__surf3_add_point(ctx, out, ext->xyz[3 * i], ext->xyz[3 * i + 1], ext->xyz[3 * i + 2]);
    }
    if (!s)
        s = read_facets(&ps);
    if (!s)
        s = read_holes_regions(&ps);
    return finish(&ps, s, name);
}

cvm_status cvm__read_tetnode(cvm__ctx *ctx, cvm__reader *r, const char *name, cvm__surf3 *out)
{
    tp_parser ps;
    cvm_status s;
    start(&ps, ctx, r, name, out);
    s = read_points(&ps);
    if (!s)
        s = cvm__s3_expect_end(&ps.sc, "last point");
    return finish(&ps, s, name);
}
