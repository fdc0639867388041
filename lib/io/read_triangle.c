/*
 * read_triangle.c - parses Triangle's .node and .poly text into a cvm__pslg.
 *
 * Format (J. R. Shewchuk, Triangle's documentation of .node and .poly files):
 *   .node  <#points> [<dimension = 2> [<#attributes> [<#markers 0|1>]]]
 *          <number> <x> <y> [attributes...] [marker]              (one line per point)
 *   .poly  the same point section (possibly with 0 points: see read_file.c), then
 *          <#segments> [<#markers 0|1>]
 *          <number> <endpoint> <endpoint> [marker]                 (one line per segment)
 *          <#holes>
 *          <number> <x> <y>                                        (one line per hole)
 *          optionally <#regions>
 *          <number> <x> <y> <attribute> [<maximum area>]           (one line per region)
 * '#' starts a comment; blank lines are ignored. Points are numbered from 0
 * or 1, as the number of the first point says (as Triangle does); the
 * segments use the same numbering.
 *
 * Stricter than Triangle, so that a wrong count or column is caught at the
 * line where it shows: every line must have exactly the fields its header
 * announces (a region line may omit the maximum area, which is then 0, "no
 * constraint"); point numbers must be consecutive; numbers must be whole
 * fields; nothing may follow the last section. Every error names file:line.
 */
#include <limits.h>
#include <stdio.h>
#include <string.h>

#include "io_text.h"

#define MAX_COUNT ((long long)INT32_MAX / 4)
#define MAX_ATTR 10000

typedef struct parser {
    cvm__scan sc;
    cvm__ctx *ctx;
    cvm__pslg *p;
    int is_poly;
    const cvm__node_points *ext;
    long long base;         /* first point number, -1 until known */
    size_t cap_xy, cap_pmark, cap_pattr, cap_seg, cap_smark, cap_holes, cap_regions;
} parser;

/* Next line with content; at end of file an error saying what was expected. */
static cvm_status need_line(parser *ps, const char *expected)
{
    int got;
    cvm_status s = cvm__scan_line(&ps->sc, &got);
    if (s)
        return s;
    if (!got)
        return cvm__scan_error(&ps->sc, CVM_E_IO_FORMAT, "unexpected end of file: expected %s",
                               expected);
    return CVM_OK;
}

/* The error for field f that cvm__parse_long() rejected with r (1 or 2). */
static cvm_status int_error(parser *ps, const char *what, const char *f, int r, long long lo, long long hi)
{
    if (r == 1)
        return cvm__scan_error(&ps->sc, CVM_E_IO_FORMAT, "%s: expected an integer, found '%.40s'",
                               what, f);
    return cvm__scan_error(&ps->sc, CVM_E_IO_FORMAT, "%s: %.40s is out of range [%lld, %lld]", what, f,
                           lo, hi);
}

static cvm_status int_field(parser *ps, const char *what, long long lo, long long hi,
                            long long *out)
{
    const char *f = cvm__scan_field(&ps->sc);
    int r = cvm__parse_long(f, lo, hi, out);
    return r ? int_error(ps, what, f, r, lo, hi) : CVM_OK;
}

/* A count: a non-negative integer no larger than MAX_COUNT (else CVM_E_TOO_LARGE). */
static cvm_status count_field(parser *ps, const char *what, long long *out)
{
    const char *f = cvm__scan_field(&ps->sc);
    int r = cvm__parse_long(f, LLONG_MIN, LLONG_MAX, out);
    if (r == 1)
        return cvm__scan_error(&ps->sc, CVM_E_IO_FORMAT, "%s: expected an integer, found '%.40s'",
                               what, f);
    if ((r == 0 && *out < 0) || (r == 2 && f[0] == '-'))
        return cvm__scan_error(&ps->sc, CVM_E_IO_FORMAT, "negative %s %.40s", what, f);
    if (r == 2 || *out > MAX_COUNT)
        return cvm__scan_error(&ps->sc, CVM_E_TOO_LARGE, "%s %.40s exceeds the limit of %lld",
                               what, f, MAX_COUNT);
    return CVM_OK;
}

static cvm_status real_field(parser *ps, const char *what, long long number, double *out)
{
    const char *f = cvm__scan_field(&ps->sc);
    int r = cvm__parse_double(f, out);
    if (r == 1)
        return cvm__scan_error(&ps->sc, CVM_E_IO_FORMAT,
                               "%s %lld: expected a decimal number, found '%.40s'%s", what, number,
                               f, strpbrk(f, "xX") ? " (hexadecimal floats are not read)" : "");
    if (r == 2)
        return cvm__scan_error(&ps->sc, CVM_E_INPUT_NONFINITE,
                               "%s %lld has a non-finite value '%.40s'", what, number, f);
    return CVM_OK;
}

/* The field's name is only formatted for an error: this runs for every line. */
static cvm_status marker_field(parser *ps, const char *what, long long number, int32_t *out)
{
    const char *f = cvm__scan_field(&ps->sc);
    long long v;
    int r = cvm__parse_long(f, INT32_MIN, INT32_MAX, &v);
    if (r) {
        char name[64];
        snprintf(name, sizeof name, "marker of %s %lld", what, number);
        return int_error(ps, name, f, r, INT32_MIN, INT32_MAX);
    }
    *out = (int32_t)v;
    return CVM_OK;
}

/* Fail unless the current line has n fields (or n2 when n2 > 0). */
static cvm_status want_fields(parser *ps, size_t n, size_t n2, const char *what,
                              const char *layout)
{
    size_t got = ps->sc.nfields;
    if (got == n || (n2 && got == n2))
        return CVM_OK;
    if (n2)
        return cvm__scan_error(&ps->sc, CVM_E_IO_FORMAT, "%s: expected %lu or %lu fields (%s), found %lu",
                               what, (unsigned long)n, (unsigned long)n2, layout, (unsigned long)got);
    return cvm__scan_error(&ps->sc, CVM_E_IO_FORMAT, "%s: expected %lu field%s (%s), found %lu", what,
                           (unsigned long)n, n == 1 ? "" : "s", layout, (unsigned long)got);
}

/* Remember that the item just read has number num on the current line. */
static cvm_status note_src(parser *ps, cvm__item_src *src, long long num)
{
    if (cvm__item_src_add(ps->ctx, src, ps->sc.name, (int64_t)num, (int64_t)ps->sc.lineno))
        return cvm__nomem(ps->ctx);
    return CVM_OK;
}

/* The line of item k (0-based) of n items of a kind ("point"), with nf (or
 * nf2 when nf2 > 0) fields laid out as layout says. As need_line() then
 * want_fields(), but the item's name is only formatted for an error: this
 * runs for every line of a file. */
static cvm_status need_item_line(parser *ps, const char *kind, size_t k, long long n, size_t nf,
                                 size_t nf2, const char *layout)
{
    char expected[96];
    int got;
    cvm_status s = cvm__scan_line(&ps->sc, &got);
    if (s)
        return s;
    if (got && (ps->sc.nfields == nf || (nf2 && ps->sc.nfields == nf2)))
        return CVM_OK;
    snprintf(expected, sizeof expected, "%s %lu of %lld", kind, (unsigned long)k + 1, n);
    if (!got)
        return cvm__scan_error(&ps->sc, CVM_E_IO_FORMAT, "unexpected end of file: expected %s",
                               expected);
    return want_fields(ps, nf, nf2, expected, layout);
}

static cvm_status grow(parser *ps, void *pp, size_t *cap, size_t need, size_t elem)
{
    if (cvm__grow(ps->ctx, (void **)pp, cap, need, elem))
        return cvm__nomem(ps->ctx);
    return CVM_OK;
}

/* First line of a .node or .poly: <#points> [2 [<#attributes> [<0|1>]]]. */
static cvm_status read_point_header(parser *ps, long long *np, long long *nattr, long long *nmark)
{
    cvm_status s;
    long long dim = 2;
    size_t n;
    if ((s = need_line(ps, "the point count line")))
        return s;
    n = ps->sc.nfields;
    if (n > 4)
        return cvm__scan_error(&ps->sc, CVM_E_IO_FORMAT,
                               "point count line: expected at most 4 fields (points, dimension, "
                               "attributes, markers), found %lu", (unsigned long)n);
    *nattr = *nmark = 0;
    if ((s = count_field(ps, "point count", np)))
        return s;
    if (n > 1 && (s = int_field(ps, "dimension", LLONG_MIN, LLONG_MAX, &dim)))
        return s;
    if (dim != 2)
        return cvm__scan_error(&ps->sc, CVM_E_IO_FORMAT, "dimension %lld is not supported (only 2)",
                               dim);
    if (n > 2 && (s = count_field(ps, "attribute count", nattr)))
        return s;
    if (*nattr > MAX_ATTR)
        return cvm__scan_error(&ps->sc, CVM_E_TOO_LARGE, "%lld attributes per point: at most %d are supported",
                               *nattr, MAX_ATTR);
    if (n > 3 && (s = int_field(ps, "point marker count", 0, 1, nmark)))
        return s;
    return CVM_OK;
}

static cvm_status read_point(parser *ps, size_t i, long long np, long long nattr, long long nmark,
                             const char *layout)
{
    cvm__pslg *p = ps->p;
    long long num = 0, k; /* set by int_field(); the 0 quiets gcc -O3 in the amalgamation */
    cvm_status s;
    if ((s = need_item_line(ps, "point", i, np, (size_t)(3 + nattr + nmark), 0, layout)))
        return s;
    if ((s = int_field(ps, "point number", LLONG_MIN, LLONG_MAX, &num)))
        return s;
    if (i == 0) {
        if (num != 0 && num != 1)
            return cvm__scan_error(&ps->sc, CVM_E_IO_FORMAT,
                                   "the first point is numbered %lld: it must be 0 or 1", num);
        ps->base = num;
    } else if (num != ps->base + (long long)i) {
        return cvm__scan_error(&ps->sc, CVM_E_IO_FORMAT,
                               "point number %lld out of sequence: expected %lld", num,
                               ps->base + (long long)i);
    }
    if ((s = grow(ps, &p->xy, &ps->cap_xy, 2 * (i + 1), sizeof(double))))
        return s;
    if ((s = real_field(ps, "point", num, &p->xy[2 * i])) ||
        (s = real_field(ps, "point", num, &p->xy[2 * i + 1])))
        return s;
    if (nattr) {
        if ((s = grow(ps, &p->pattr, &ps->cap_pattr, (i + 1) * (size_t)nattr, sizeof(double))))
            return s;
        for (k = 0; k < nattr; k++)
            if ((s = real_field(ps, "attribute of point", num, &p->pattr[i * (size_t)nattr + (size_t)k])))
                return s;
    }
    if (nmark) {
        if ((s = grow(ps, &p->pmark, &ps->cap_pmark, i + 1, sizeof(int32_t))))
            return s;
        if ((s = marker_field(ps, "point", num, &p->pmark[i])))
            return s;
    }
    p->np = i + 1;
    return note_src(ps, &p->src_point, num);
}

static cvm_status read_points(parser *ps)
{
    long long np, nattr, nmark;
    char layout[96];
    size_t i;
    cvm_status s;
    if ((s = read_point_header(ps, &np, &nattr, &nmark)))
        return s;
    if (np == 0)
        return CVM_OK;
    ps->p->nattr = (size_t)nattr;
    snprintf(layout, sizeof layout, "number, x, y%s%s%s", nattr ? ", " : "",
             nattr ? (nattr == 1 ? "1 attribute" : "attributes") : "", nmark ? ", marker" : "");
    for (i = 0; i < (size_t)np; i++)
        if ((s = read_point(ps, i, np, nattr, nmark, layout)))
            return s;
    return CVM_OK;
}

/* One endpoint of segment num, converted to a 0-based index. */
static cvm_status endpoint(parser *ps, long long num, int32_t *out)
{
    long long v, np = (long long)ps->p->np, base = ps->base;
    const char *f = cvm__scan_field(&ps->sc);
    int r = cvm__parse_long(f, LLONG_MIN, LLONG_MAX, &v);
    if (r) {
        char what[64];
        snprintf(what, sizeof what, "endpoint of segment %lld", num);
        return int_error(ps, what, f, r, LLONG_MIN, LLONG_MAX);
    }
    if (ps->p->np == 0 && ps->ext) {
        np = (long long)ps->ext->np;
        base = ps->ext->base;
    } else if (ps->p->np == 0) {
        /* points come from elsewhere; the caller re-reads with them */
        *out = v < INT32_MIN ? INT32_MIN : v > INT32_MAX ? INT32_MAX : (int32_t)v;
        return CVM_OK;
    }
    if (v < base || v >= base + np) {
        if (np == 0)
            return cvm__scan_error(&ps->sc, CVM_E_IO_FORMAT,
                                   "segment %lld names point %lld, but there are no points", num, v);
        return cvm__scan_error(&ps->sc, CVM_E_IO_FORMAT,
                               "segment %lld names point %lld, but points are numbered %lld..%lld",
                               num, v, base, base + np - 1);
    }
    *out = (int32_t)(v - base);
    return CVM_OK;
}

static cvm_status read_segments(parser *ps)
{
    cvm__pslg *p = ps->p;
    long long nseg, nmark = 0, num;
    size_t k, n;
    cvm_status s;
    if ((s = need_line(ps, "the segment count line")))
        return s;
    n = ps->sc.nfields;
    if (n > 2)
        return cvm__scan_error(&ps->sc, CVM_E_IO_FORMAT,
                               "segment count line: expected 1 or 2 fields (segments, markers), "
                               "found %lu (does the point count match the point lines?)",
                               (unsigned long)n);
    if ((s = count_field(ps, "segment count", &nseg)))
        return s;
    if (n > 1 && (s = int_field(ps, "segment marker count", 0, 1, &nmark)))
        return s;
    for (k = 0; k < (size_t)nseg; k++) {
        if ((s = need_item_line(ps, "segment", k, nseg, (size_t)(3 + nmark), 0,
                                nmark ? "number, endpoint, endpoint, marker" : "number, endpoint, endpoint")))
            return s;
        if ((s = int_field(ps, "segment number", LLONG_MIN, LLONG_MAX, &num)))
            return s;
        if ((s = grow(ps, &p->seg, &ps->cap_seg, 2 * (k + 1), sizeof(int32_t))))
            return s;
        if ((s = endpoint(ps, num, &p->seg[2 * k])) || (s = endpoint(ps, num, &p->seg[2 * k + 1])))
            return s;
        if (nmark) {
            if ((s = grow(ps, &p->smark, &ps->cap_smark, k + 1, sizeof(int32_t))))
                return s;
            if ((s = marker_field(ps, "segment", num, &p->smark[k])))
                return s;
        }
        p->nseg = k + 1;
        if ((s = note_src(ps, &p->src_segment, num)))
            return s;
    }
    return CVM_OK;
}

static cvm_status read_holes(parser *ps)
{
    cvm__pslg *p = ps->p;
    long long nh, num;
    size_t k;
    cvm_status s;
    if ((s = need_line(ps, "the hole count line")) ||
        (s = want_fields(ps, 1, 0, "hole count line", "holes; does the segment count match the segment lines?")) ||
        (s = count_field(ps, "hole count", &nh)))
        return s;
    for (k = 0; k < (size_t)nh; k++) {
        if ((s = need_item_line(ps, "hole", k, nh, 3, 0, "number, x, y")) ||
            (s = int_field(ps, "hole number", LLONG_MIN, LLONG_MAX, &num)))
            return s;
        if ((s = grow(ps, &p->holes, &ps->cap_holes, 2 * (k + 1), sizeof(double))))
            return s;
        if ((s = real_field(ps, "hole", num, &p->holes[2 * k])) ||
            (s = real_field(ps, "hole", num, &p->holes[2 * k + 1])))
            return s;
        p->nholes = k + 1;
        if ((s = note_src(ps, &p->src_hole, num)))
            return s;
    }
    return CVM_OK;
}

/* The optional regional attributes section; *got = 0 when the file ended before it. */
static cvm_status read_regions(parser *ps)
{
    cvm__pslg *p = ps->p;
    long long nr, num;
    size_t k;
    int got;
    cvm_status s;
    if ((s = cvm__scan_line(&ps->sc, &got)))
        return s;
    if (!got)
        return CVM_OK;
    if ((s = want_fields(ps, 1, 0, "region count line", "regions; does the hole count match the hole lines?")) ||
        (s = count_field(ps, "region count", &nr)))
        return s;
    for (k = 0; k < (size_t)nr; k++) {
        double *r;
        if ((s = need_item_line(ps, "region", k, nr, 5, 4, "number, x, y, attribute[, maximum area]")) ||
            (s = int_field(ps, "region number", LLONG_MIN, LLONG_MAX, &num)))
            return s;
        if ((s = grow(ps, &p->regions, &ps->cap_regions, 4 * (k + 1), sizeof(double))))
            return s;
        r = p->regions + 4 * k;
        r[3] = 0.0;
        if ((s = real_field(ps, "region", num, &r[0])) || (s = real_field(ps, "region", num, &r[1])) ||
            (s = real_field(ps, "region", num, &r[2])))
            return s;
        if (ps->sc.nfields == 5 && (s = real_field(ps, "region", num, &r[3])))
            return s;
        p->nregions = k + 1;
        if ((s = note_src(ps, &p->src_region, num)))
            return s;
    }
    return CVM_OK;
}

static cvm_status expect_end(parser *ps, const char *after)
{
    int got;
    cvm_status s = cvm__scan_line(&ps->sc, &got);
    if (s)
        return s;
    if (got)
        return cvm__scan_error(&ps->sc, CVM_E_IO_FORMAT,
                               "unexpected content after the %s (does its count match its lines?)",
                               after);
    return CVM_OK;
}

static cvm_status parse(parser *ps)
{
    cvm_status s;
    if ((s = read_points(ps)))
        return s;
    if (!ps->is_poly)
        return expect_end(ps, "last point");
    if ((s = read_segments(ps)) || (s = read_holes(ps)) || (s = read_regions(ps)))
        return s;
    return expect_end(ps, ps->p->nregions ? "last region" : "holes section");
}

cvm_status cvm__read_triangle_ex(cvm__ctx *ctx, cvm__reader *r, const char *name, int is_poly,
                                 const cvm__node_points *ext, cvm__pslg *p, int *base_out)
{
    parser ps;
    cvm_status s;
    memset(p, 0, sizeof *p);
    memset(&ps, 0, sizeof ps);
    cvm__scan_init(&ps.sc, ctx, r, name);
    ps.ctx = ctx;
    ps.p = p;
    ps.is_poly = is_poly;
    ps.ext = ext;
    ps.base = -1;
    s = parse(&ps);
    cvm__scan_free(&ps.sc);
    if (s) {
        cvm__pslg_free(ctx, p);
        return s;
    }
    if (base_out)
        *base_out = (int)ps.base;
    return CVM_OK;
}

cvm_status cvm__read_triangle_format(cvm__ctx *ctx, cvm__reader *r, const char *name,
                                     int is_poly, cvm__pslg *p)
{
    return cvm__read_triangle_ex(ctx, r, name, is_poly, NULL, p, NULL);
}
