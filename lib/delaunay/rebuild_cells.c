/*
 * rebuild_cells.c - what a mesh file's cells say before they are rebuilt
 * (rebuild.h): checks of its triangles and line cells, and the segments
 * they give (line cells, boundary edges, inner edges).
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "rebuild.h"
#include "tri_grid.h"
#include "geom/geom_internal.h"

int cvm__rb_cmp_key(const void *pa, const void *pb)
{
    const cvm__rb_key *a = pa, *b = pb;
    int k;
    for (k = 0; k < 3; k++)
        if (a->v[k] != b->v[k])
            return a->v[k] < b->v[k] ? -1 : 1;
    return a->src < b->src ? -1 : a->src > b->src;
}

void cvm__rb_make_key(cvm__rb_key *k, int32_t a, int32_t b, int32_t c, int32_t src)
{
    int32_t t;
    if (a > b) { t = a; a = b; b = t; }
    if (b > c) { t = b; b = c; c = t; }
    if (a > b) { t = a; a = b; b = t; }
    k->v[0] = a;
    k->v[1] = b;
    k->v[2] = c;
    k->src = src;
}

static int cmp_v(const int32_t *a, const int32_t *b)
{
    int k;
    for (k = 0; k < 3; k++)
        if (a[k] != b[k])
            return a[k] < b[k] ? -1 : 1;
    return 0;
}

int32_t cvm__rb_find(const cvm__rb_key *keys, size_t n, const cvm__rb_key *key)
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        int c = cmp_v(keys[mid].v, key->v);
        if (c == 0)
            return keys[mid].src;
        if (c < 0)
            lo = mid + 1;
        else
            hi = mid;
    }
    return -1;
}

/* A point that is no triangle's corner must lie outside the cells' domain
 * (exact test): cvm__cdt_build() leaves such vertices (ends of segments
 * bounding no region) where it carved, and the rebuild carves them again. */
static cvm_status unused_points(cvm__rebuild *rb, const cvm__rebuild_input *in, const uint8_t *used)
{
    cvm__tri_grid g;
    size_t i, np = in->cdt.np;
    cvm_status s = CVM_OK;
    memset(&g, 0, sizeof g);
    for (i = 0; i < np && used[i]; i++)
        ;
    if (i < np && cvm__tri_grid_build(rb->ctx, &g, in->cdt.xy, np, in->tri, in->nt))
        return cvm__nomem(rb->ctx);
    for (; i < np && !s; i++) {
        const double *p = in->cdt.xy + 2 * i;
        if (!used[i] && cvm__tri_grid_contains(&g, p))
            s = cvm__error(rb->ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_INPUT_POINT, (int64_t)i,
                           "point %lu at (%.17g, %.17g) lies in the mesh but is a corner of "
                           "no triangle", (unsigned long)i, p[0], p[1]);
    }
    cvm__tri_grid_free(rb->ctx, &g);
    return s;
}

/* Sign of the orientation of triangle k of in, as listed. */
static int listed_sign(const cvm__rebuild_input *in, size_t k)
{
    const int32_t *t = in->tri + 3 * k;
    const double *xy = in->cdt.xy;
    double o = cvm__orient2d(xy + 2 * (size_t)t[0], xy + 2 * (size_t)t[1], xy + 2 * (size_t)t[2]);
    return o > 0 ? 1 : o < 0 ? -1 : 0;
}

/* The corner of triangle k of in that is not a or b. */
static int32_t apex_of(const cvm__rebuild_input *in, size_t k, int32_t a, int32_t b)
{
    const int32_t *t = in->tri + 3 * k;
    return t[0] != a && t[0] != b ? t[0] : t[1] != a && t[1] != b ? t[1] : t[2];
}

/* Inner edge a-b of triangles t and u (t < u): their apexes must lie on
 * opposite sides of it (exact), or one of the two is inverted: the one whose
 * listed orientation is the rarer among all triangles (u when both are
 * listed alike). pos: triangles listed counter-clockwise. */
static cvm_status fold_check(cvm__rebuild *rb, const cvm__rebuild_input *in, int32_t a, int32_t b,
                       int32_t t, int32_t u, size_t pos)
{
    const double *xy = in->cdt.xy;
    const double *pa = xy + 2 * (size_t)a, *pb = xy + 2 * (size_t)b;
    double o1 = cvm__orient2d(pa, pb, xy + 2 * (size_t)apex_of(in, (size_t)t, a, b));
    double o2 = cvm__orient2d(pa, pb, xy + 2 * (size_t)apex_of(in, (size_t)u, a, b));
    int st = listed_sign(in, (size_t)t), su = listed_sign(in, (size_t)u);
    int rare = 2 * pos >= in->nt ? -1 : 1;
    int32_t bad = st != su && st == rare ? t : u, other = bad == t ? u : t;
    const int32_t *f = in->tri + 3 * (size_t)bad, *g = in->tri + 3 * (size_t)other;
    if ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0))
        return CVM_OK;
    return cvm__error(rb->ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_TRIANGLE, (int64_t)bad,
                      "triangle %ld (points %ld %ld %ld) is inverted: it lies on the same side of "
                      "its edge %ld-%ld as triangle %ld (points %ld %ld %ld), so the two overlap",
                      (long)bad, (long)f[0], (long)f[1], (long)f[2], (long)a, (long)b,
                      (long)other, (long)g[0], (long)g[1], (long)g[2]);
}

/* Check the triangles: distinct corners not on one line, no unused point
 * inside, at most two triangles on an edge, on opposite sides of it; collect
 * the edges used by one triangle only (boundary) into *bnd (2 ids per edge)
 * and those used by two (inner) into *inner (4 per edge: the ids, then the
 * two triangles). */
static cvm_status file_checks(cvm__rebuild *rb, const cvm__rebuild_input *in, int32_t **bnd,
                              size_t *nbnd, int32_t **inner, size_t *ninner)
{
    cvm__ctx *ctx = rb->ctx;
    const double *xy = in->cdt.xy;
    size_t k, n = 0, ni = 0, i, ne = 3 * in->nt;
    uint8_t *used = cvm__calloc(ctx, in->cdt.np + 1, 1);
    cvm__rb_key *e = cvm__malloc(ctx, (ne + 1) * sizeof *e);
    int32_t *b = cvm__malloc(ctx, (3 * ne + 1) * sizeof *b); /* ids, then triangles */
    int32_t *inn = cvm__malloc(ctx, (2 * ne + 1) * sizeof *inn);
    size_t pos = 0;
    cvm_status s = CVM_OK;
    *bnd = NULL;
    *inner = NULL;
    if (!used || !e || !b || !inn) {
        s = cvm__nomem(ctx);
        goto out;
    }
    if (in->nt == 0) {
        s = cvm__error(ctx, CVM_E_INPUT_EMPTY, CVM_ENT_NONE, -1, "no triangle cells");
        goto out;
    }
    for (k = 0; k < in->nt; k++) {
        const int32_t *t = in->tri + 3 * k;
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
            s = cvm__error(ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_TRIANGLE, (int64_t)k,
                           "triangle %lu (points %ld %ld %ld) repeats a point",
                           (unsigned long)k, (long)t[0], (long)t[1], (long)t[2]);
            goto out;
        }
        for (i = 0; i < 3; i++) {
            int32_t a = t[i], c = t[(i + 1) % 3];
            const double *pa = xy + 2 * (size_t)a, *pc = xy + 2 * (size_t)c;
            /* said here in the file's terms: the rebuild would only see a
               zero-length boundary segment the file does not have */
            if (pa[0] == pc[0] && pa[1] == pc[1]) {
                s = cvm__error(ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_TRIANGLE, (int64_t)k,
                               "triangle %lu (points %ld %ld %ld) is degenerate: points %ld "
                               "and %ld are both at (%.17g, %.17g)", (unsigned long)k,
                               (long)t[0], (long)t[1], (long)t[2], (long)a, (long)c, pa[0], pa[1]);
                goto out;
            }
            used[a] = 1;
            /* edge key: (lo, hi, -1) with src = triangle */
            cvm__rb_make_key(&e[3 * k + i], a < c ? a : c, a < c ? c : a, INT32_MAX, (int32_t)k);
        }
    }
    for (k = 0; k < in->nt; k++) {
        const int32_t *t = in->tri + 3 * k;
        int sg = listed_sign(in, k);
        if (sg == 0) {
            s = cvm__error(ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_TRIANGLE, (int64_t)k,
                           "triangle %lu (points %ld %ld %ld) is degenerate: its corners lie on "
                           "one line", (unsigned long)k, (long)t[0], (long)t[1], (long)t[2]);
            goto out;
        }
        pos += sg > 0;
    }
    for (k = 0; k < in->nlines; k++) {
        const int32_t *l = in->lines + 2 * k;
        const double *pa = xy + 2 * (size_t)l[0], *pb = xy + 2 * (size_t)l[1];
        if (pa[0] == pb[0] && pa[1] == pb[1]) {
            s = cvm__error(ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_NONE, -1,
                           "line cell %lu (points %ld-%ld) has zero length: both ends are at "
                           "(%.17g, %.17g)", (unsigned long)k, (long)l[0], (long)l[1],
                           pa[0], pa[1]);
            goto out;
        }
    }
    if ((s = unused_points(rb, in, used)))
        goto out;
    qsort(e, ne, sizeof *e, cvm__rb_cmp_key);
    for (k = 0; k < ne; k = i) {
        for (i = k + 1; i < ne && e[i].v[0] == e[k].v[0] && e[i].v[1] == e[k].v[1]; i++)
            ;
        if (i - k > 2) {
            s = cvm__error(ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_TRIANGLE, (int64_t)e[k + 2].src,
                           "edge %ld-%ld has more than two triangles (triangle %ld is one)",
                           (long)e[k].v[0], (long)e[k].v[1], (long)e[k + 2].src);
            goto out;
        }
        if (i - k == 1) {
            b[2 * n] = e[k].v[0];
            b[2 * n + 1] = e[k].v[1];
            b[2 * ne + n] = e[k].src;
            n++;
        } else {
            if ((s = fold_check(rb, in, e[k].v[0], e[k].v[1], e[k].src, e[k + 1].src, pos)))
                goto out;
            inn[4 * ni] = e[k].v[0];
            inn[4 * ni + 1] = e[k].v[1];
            inn[4 * ni + 2] = e[k].src;
            inn[4 * ni + 3] = e[k + 1].src;
            ni++;
        }
    }
    memmove(b + 2 * n, b + 2 * ne, n * sizeof *b); /* the triangles after the ids */
    *bnd = b;
    b = NULL;
    *nbnd = n;
    *inner = inn;
    inn = NULL;
    *ninner = ni;
out:
    cvm__free(ctx, used);
    cvm__free(ctx, e);
    cvm__free(ctx, b);
    cvm__free(ctx, inn);
    return s;
}

/* 1 when inner edge k (4 ints each) joins two triangles of different
 * regional attributes. */
static int is_border(const cvm__rebuild_input *in, const int32_t *inner, size_t k)
{
    return in->tattr && in->tattr[inner[4 * k + 2]] != in->tattr[inner[4 * k + 3]];
}

/* Segments: the file's lines, then each boundary edge that is not a line
 * (*nreal_out in all), each region border that is not a line (*nkeep_out in
 * all), then each other inner edge that is not a line (the temporary
 * constraints of a forced rebuild, marker 0). rb->segtri receives a triangle
 * of each segment's edge (-1 for a line). */
static cvm_status segments(cvm__rebuild *rb, const cvm__rebuild_input *in, const int32_t *bnd,
                           size_t nbnd, const int32_t *inner, size_t ninner, size_t *n_out,
                           size_t *nreal_out, size_t *nkeep_out)
{
    cvm__ctx *ctx = rb->ctx;
    size_t nl = in->nlines, n = 0, k;
    int32_t *seg = cvm__malloc(ctx, (2 * (nl + nbnd + ninner) + 1) * sizeof *seg);
    int32_t *mark = cvm__malloc(ctx, (nl + nbnd + ninner + 1) * sizeof *mark);
    int32_t *st = cvm__malloc(ctx, (nl + nbnd + ninner + 1) * sizeof *st);
    cvm__rb_key *lines = cvm__malloc(ctx, (nl + 1) * sizeof *lines);
    int pass;
    if (!seg || !mark || !st || !lines) {
        cvm__free(ctx, seg);
        cvm__free(ctx, mark);
        cvm__free(ctx, st);
        cvm__free(ctx, lines);
        return cvm__nomem(ctx);
    }
    for (k = 0; k < nl; k++) {
        int32_t a = in->lines[2 * k], b = in->lines[2 * k + 1];
        seg[2 * n] = a;
        seg[2 * n + 1] = b;
        st[n] = -1;
        mark[n++] = in->lmark ? in->lmark[k] : 1;
        cvm__rb_make_key(&lines[k], a < b ? a : b, a < b ? b : a, INT32_MAX, 0);
    }
    qsort(lines, nl, sizeof *lines, cvm__rb_cmp_key);
    for (k = 0; k < nbnd; k++) {
        cvm__rb_key key;
        cvm__rb_make_key(&key, bnd[2 * k], bnd[2 * k + 1], INT32_MAX, 0);
        if (cvm__rb_find(lines, nl, &key) >= 0)
            continue;
        seg[2 * n] = bnd[2 * k];
        seg[2 * n + 1] = bnd[2 * k + 1];
        st[n] = bnd[2 * nbnd + k];
        mark[n++] = 1;
    }
    *nreal_out = n;
    /* pass 0: region borders (kept); pass 1: temporary constraints (forced rebuild) */
    for (pass = 0; pass < 2; pass++) {
        for (k = 0; k < ninner; k++) {
            cvm__rb_key key;
            if (is_border(in, inner, k) != !pass)
                continue;
            cvm__rb_make_key(&key, inner[4 * k], inner[4 * k + 1], INT32_MAX, 0);
            if (cvm__rb_find(lines, nl, &key) >= 0)
                continue;
            seg[2 * n] = inner[4 * k];
            seg[2 * n + 1] = inner[4 * k + 1];
            st[n] = inner[4 * k + 2];
            mark[n++] = 0;
        }
        if (pass == 0)
            *nkeep_out = n;
    }
    cvm__free(ctx, lines);
    rb->seg = seg;
    rb->smark = mark;
    rb->segtri = st;
    *n_out = n;
    return CVM_OK;
}

cvm_status cvm__rb_cells(cvm__rebuild *rb, const cvm__rebuild_input *in, size_t *nreal,
                         size_t *nkeep, size_t *nall)
{
    int32_t *bnd = NULL, *inner = NULL;
    size_t nbnd = 0, ninner = 0;
    cvm_status s;
    *nreal = *nkeep = *nall = 0;
    if ((s = file_checks(rb, in, &bnd, &nbnd, &inner, &ninner)))
        return s;
    s = segments(rb, in, bnd, nbnd, inner, ninner, nall, nreal, nkeep);
    cvm__free(rb->ctx, bnd);
    cvm__free(rb->ctx, inner);
    return s;
}
