/*
 * rebuild_cells.c - what a mesh file's cells say before they are rebuilt
 * (rebuild.h): checks of its triangles and line cells, and the segments
 * they give (line cells, boundary edges, inner edges).
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "rebuild.h"
#include "cell_grid.h"

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
    cvm__cell_grid g;
    size_t i, np = in->cdt.np;
    cvm_status s = CVM_OK;
    memset(&g, 0, sizeof g);
    for (i = 0; i < np && used[i]; i++)
        ;
    if (i < np && cvm__cell_grid_build(rb->ctx, &g, in->cdt.xy, np, in->tri, in->nt))
        return cvm__nomem(rb->ctx);
    for (; i < np && !s; i++) {
        const double *p = in->cdt.xy + 2 * i;
        if (!used[i] && cvm__cell_grid_contains(&g, p))
            s = cvm__error(rb->ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_INPUT_POINT, (int64_t)i,
                           "point %lu at (%.17g, %.17g) lies in the mesh but is a corner of "
                           "no triangle", (unsigned long)i, p[0], p[1]);
    }
    cvm__cell_grid_free(rb->ctx, &g);
    return s;
}

/* Check the triangles: distinct corners, no unused point inside; collect the
 * edges used by one triangle only (boundary) into *bnd and those used by two
 * (inner) into *inner (2 ids per edge). */
static cvm_status file_checks(cvm__rebuild *rb, const cvm__rebuild_input *in, int32_t **bnd,
                              size_t *nbnd, int32_t **inner, size_t *ninner)
{
    cvm__ctx *ctx = rb->ctx;
    const double *xy = in->cdt.xy;
    size_t k, n = 0, ni = 0, i, ne = 3 * in->nt;
    uint8_t *used = cvm__calloc(ctx, in->cdt.np + 1, 1);
    cvm__rb_key *e = cvm__malloc(ctx, (ne + 1) * sizeof *e);
    int32_t *b = cvm__malloc(ctx, (2 * ne + 1) * sizeof *b);
    int32_t *inn = cvm__malloc(ctx, (ne + 1) * sizeof *inn);
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
            n++;
        } else {
            inn[2 * ni] = e[k].v[0];
            inn[2 * ni + 1] = e[k].v[1];
            ni++;
        }
    }
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

/* Segments: the file's lines, then each boundary edge that is not a line
 * (*nreal_out of them), then each inner edge that is not a line (the
 * temporary constraints of a forced rebuild, marker 0). */
static cvm_status segments(cvm__rebuild *rb, const cvm__rebuild_input *in, const int32_t *bnd,
                           size_t nbnd, const int32_t *inner, size_t ninner, size_t *n_out,
                           size_t *nreal_out)
{
    cvm__ctx *ctx = rb->ctx;
    size_t nl = in->nlines, n = 0, k;
    int32_t *seg = cvm__malloc(ctx, (2 * (nl + nbnd + ninner) + 1) * sizeof *seg);
    int32_t *mark = cvm__malloc(ctx, (nl + nbnd + ninner + 1) * sizeof *mark);
    cvm__rb_key *lines = cvm__malloc(ctx, (nl + 1) * sizeof *lines);
    if (!seg || !mark || !lines) {
        cvm__free(ctx, seg);
        cvm__free(ctx, mark);
        cvm__free(ctx, lines);
        return cvm__nomem(ctx);
    }
    for (k = 0; k < nl; k++) {
        int32_t a = in->lines[2 * k], b = in->lines[2 * k + 1];
        seg[2 * n] = a;
        seg[2 * n + 1] = b;
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
        mark[n++] = 1;
    }
    *nreal_out = n;
    for (k = 0; k < ninner; k++) { /* temporary constraints (forced rebuild) */
        cvm__rb_key key;
        cvm__rb_make_key(&key, inner[2 * k], inner[2 * k + 1], INT32_MAX, 0);
        if (cvm__rb_find(lines, nl, &key) >= 0)
            continue;
        seg[2 * n] = inner[2 * k];
        seg[2 * n + 1] = inner[2 * k + 1];
        mark[n++] = 0;
    }
    cvm__free(ctx, lines);
    rb->seg = seg;
    rb->smark = mark;
    *n_out = n;
    return CVM_OK;
}

cvm_status cvm__rb_cells(cvm__rebuild *rb, const cvm__rebuild_input *in, size_t *nreal,
                         size_t *nall)
{
    int32_t *bnd = NULL, *inner = NULL;
    size_t nbnd = 0, ninner = 0;
    cvm_status s;
    *nreal = *nall = 0;
    if ((s = file_checks(rb, in, &bnd, &nbnd, &inner, &ninner)))
        return s;
    s = segments(rb, in, bnd, nbnd, inner, ninner, nall, nreal);
    cvm__free(rb->ctx, bnd);
    cvm__free(rb->ctx, inner);
    return s;
}
