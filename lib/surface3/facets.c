/*
 * facets.c - splits the polygons of a surface into triangles, refusing
 * degenerate, non-planar and (for now) non-convex polygons, all by exact
 * predicates; and names polygons in the file's numbering for messages.
 *
 * A polygon of more than 3 corners is fanned from its first corner when it is
 * planar (orient3d 0 for every corner against three non-collinear ones) and
 * strictly convex (in a faithful coordinate projection, every turn and every
 * fan triangle has the same strict orientation, which also rules out star
 * polygons). Non-convex polygons would need an exact ear-clipper; they get
 * CVM_E_UNSUPPORTED with a message instead.
 */
#include <stdio.h>
#include <string.h>

#include "geom/geom_internal.h"
#include "surface3_internal.h"

void cvm__surf3_name_poly(const cvm__surf3 *s, size_t poly, char *buf, size_t cap)
{
    size_t f = (size_t)s->pfacet[poly], n = (size_t)(s->poff[poly + 1] - s->poff[poly]), k, len;
    const int32_t *idx = s->pidx + s->poff[poly];
    long long fnum = (long long)f + s->facet_base;
    int multi = (poly > 0 && (size_t)s->pfacet[poly - 1] == f) ||
                (poly + 1 < s->npoly && (size_t)s->pfacet[poly + 1] == f);
    if (multi) {
        size_t first = poly;
        while (first > 0 && (size_t)s->pfacet[first - 1] == f)
            first--;
        len = (size_t)snprintf(buf, cap, "polygon %lu of %s %lld", (unsigned long)(poly - first + 1),
                               s->facet_word, fnum);
    } else {
        len = (size_t)snprintf(buf, cap, "%s %lld", s->facet_word, fnum);
    }
    if (len >= cap || n == 0)
        return;
    if (!s->points_numbered) {
        const double *p = s->xyz + 3 * idx[0];
        snprintf(buf + len, cap - len, " (first corner at %.17g, %.17g, %.17g)", p[0], p[1], p[2]);
        return;
    }
    len += (size_t)snprintf(buf + len, cap - len, " (points");
    for (k = 0; k < n && k < 5 && len < cap; k++)
        len += (size_t)snprintf(buf + len, cap - len, "%s %lld", k ? "," : "",
                                (long long)idx[k] + s->point_base);
    if (len < cap)
        snprintf(buf + len, cap - len, "%s)", n > 5 ? ", ..." : "");
}

static int sgn(double x)
{
    return (x > 0) - (x < 0);
}

static int o2(const double *a, const double *b, const double *c, int axis)
{
    int u = axis == 0 ? 1 : 0, v = axis == 2 ? 1 : 2;
    double pa[2], pb[2], pc[2];
    pa[0] = a[u], pa[1] = a[v];
    pb[0] = b[u], pb[1] = b[v];
    pc[0] = c[u], pc[1] = c[v];
    return sgn(cvm__orient2d(pa, pb, pc));
}

static cvm_status poly_error(cvm__ctx *ctx, const cvm__surf3 *s, size_t poly, cvm_status st,
                             const char *what)
{
    char name[160];
    cvm__surf3_name_poly(s, poly, name, sizeof name);
    return cvm__error(ctx, st, CVM_ENT_FACET, s->pfacet[poly], "%s%s%s: %s", s->file ? s->file : "",
                      s->file ? ": " : "", name, what);
}

/* Check polygon k of n corners (n > 3): planar and strictly convex. */
static cvm_status check_big_polygon(cvm__ctx *ctx, const cvm__surf3 *s, size_t k)
{
    const int32_t *idx = s->pidx + s->poff[k];
    size_t n = (size_t)(s->poff[k + 1] - s->poff[k]), i, c = 0;
    const double *p0 = s->xyz + 3 * idx[0], *p1 = s->xyz + 3 * idx[1];
    int axis = -1, turn;
    for (i = 2; i < n && axis < 0; i++) {
        int a;
        for (a = 2; a >= 0 && axis < 0; a--)
            if (o2(p0, p1, s->xyz + 3 * idx[i], a) != 0)
                axis = a, c = i;
    }
    if (axis < 0)
        return poly_error(ctx, s, k, CVM_E_INPUT_DEGENERATE, "all its corners are collinear");
    for (i = 2; i < n; i++)
        if (cvm__orient3d(p0, p1, s->xyz + 3 * idx[c], s->xyz + 3 * idx[i]) != 0.0) {
            char what[96];
            snprintf(what, sizeof what, "corner %lu is not in the plane of the others (not planar)",
                     (unsigned long)i + 1);
            return poly_error(ctx, s, k, CVM_E_INPUT_DEGENERATE, what);
        }
    turn = o2(s->xyz + 3 * idx[n - 1], p0, p1, axis);
    for (i = 0; i < n; i++) {
        const double *a = s->xyz + 3 * idx[i], *b = s->xyz + 3 * idx[(i + 1) % n],
                     *cc = s->xyz + 3 * idx[(i + 2) % n];
        if (turn == 0 || o2(a, b, cc, axis) != turn ||
            (i + 2 < n && o2(p0, s->xyz + 3 * idx[i + 1], s->xyz + 3 * idx[i + 2], axis) != turn))
            return poly_error(ctx, s, k, CVM_E_UNSUPPORTED,
                              "polygon is not strictly convex (non-convex faces and straight "
                              "corners are not split yet)");
    }
    return CVM_OK;
}

static cvm_status check_polygon(cvm__ctx *ctx, const cvm__surf3 *s, size_t k)
{
    const int32_t *idx = s->pidx + s->poff[k];
    size_t n = (size_t)(s->poff[k + 1] - s->poff[k]), i, j;
    if (n < 3)
        return poly_error(ctx, s, k, CVM_E_UNSUPPORTED,
                          "polygons of 1 or 2 corners (points and segments in a facet) are not supported");
    for (i = 0; i < n; i++)
        for (j = i + 1; j < n; j++)
            if (idx[i] == idx[j]) {
                char what[96];
                snprintf(what, sizeof what, "corners %lu and %lu are the same point",
                         (unsigned long)i + 1, (unsigned long)j + 1);
                return poly_error(ctx, s, k, CVM_E_INPUT_DEGENERATE, what);
            }
    if (n == 3) {
        if (cvm__collinear3(s->xyz + 3 * idx[0], s->xyz + 3 * idx[1], s->xyz + 3 * idx[2]))
            return poly_error(ctx, s, k, CVM_E_INPUT_DEGENERATE, "its corners are collinear (zero area)");
        return CVM_OK;
    }
    return check_big_polygon(ctx, s, k);
}

void cvm__surf3_tris_free(cvm__ctx *ctx, cvm__surf3_tris *t)
{
    cvm__free(ctx, t->tri);
    cvm__free(ctx, t->tpoly);
    memset(t, 0, sizeof *t);
}

cvm_status cvm__surf3_triangulate(cvm__ctx *ctx, const cvm__surf3 *s, cvm__surf3_tris *out)
{
    size_t k, nt = 0, f;
    cvm_status st;
    memset(out, 0, sizeof *out);
    for (f = 0; f < s->nfacet; f++)
        if (s->fhole_off[f + 1] > s->fhole_off[f])
            return cvm__error(ctx, CVM_E_UNSUPPORTED, CVM_ENT_FACET, (int64_t)f,
                              "%s%s%s %lld has holes: facets with holes are not validated yet",
                              s->file ? s->file : "", s->file ? ": " : "", s->facet_word,
                              (long long)f + s->facet_base);
    for (k = 0; k < s->npoly; k++) {
        if ((st = check_polygon(ctx, s, k)))
            return st;
        nt += (size_t)(s->poff[k + 1] - s->poff[k]) - 2;
    }
    out->tri = cvm__calloc(ctx, nt ? 3 * nt : 1, sizeof(int32_t));
    out->tpoly = cvm__calloc(ctx, nt ? nt : 1, sizeof(int32_t));
    if (!out->tri || !out->tpoly) {
        cvm__surf3_tris_free(ctx, out);
        return cvm__nomem(ctx);
    }
    for (k = 0; k < s->npoly; k++) {
        const int32_t *idx = s->pidx + s->poff[k];
        size_t n = (size_t)(s->poff[k + 1] - s->poff[k]), i;
        for (i = 1; i + 1 < n; i++) {
            out->tri[3 * out->nt] = idx[0];
            out->tri[3 * out->nt + 1] = idx[i];
            out->tri[3 * out->nt + 2] = idx[i + 1];
            out->tpoly[out->nt++] = (int32_t)k;
        }
    }
    return CVM_OK;
}
