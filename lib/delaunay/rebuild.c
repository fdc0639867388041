/*
 * rebuild.c - a mesh file's cells rebuilt as the kernel's constrained
 * regular triangulation of the same points (rebuild.h): attempts with
 * cvm__cdt_build(), hole points, weights, and the match of the result
 * against the cells.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "rebuild.h"
#include "tri_grid.h"
#include "domain.h"

/* Sorted keys of the domain slots of T. */
static cvm__rb_key *slot_keys(cvm__ctx *ctx, const cvm__tri2 *T, size_t *n_out)
{
    size_t t, n = 0;
    cvm__rb_key *k = cvm__malloc(ctx, (cvm__domain_triangles(T) + 1) * sizeof *k);
    if (!k)
        return NULL;
    for (t = 0; t < T->nt; t++)
        if (cvm__tri2_in_domain(T, (int32_t)t))
            cvm__rb_make_key(&k[n++], T->tv[3 * t], T->tv[3 * t + 1], T->tv[3 * t + 2],
                             (int32_t)t);
    qsort(k, n, sizeof *k, cvm__rb_cmp_key);
    *n_out = n;
    return k;
}

/* File triangle keys in vertex ids (through rb's input map), sorted. */
static cvm__rb_key *file_keys(cvm__rebuild *rb, const cvm__rebuild_input *in)
{
    cvm__rb_key *k = cvm__malloc(rb->ctx, (in->nt + 1) * sizeof *k);
    size_t i;
    const int32_t *map = rb->out.input_map;
    if (!k)
        return NULL;
    for (i = 0; i < in->nt; i++)
        cvm__rb_make_key(&k[i], map[in->tri[3 * i]], map[in->tri[3 * i + 1]],
                         map[in->tri[3 * i + 2]], (int32_t)i);
    qsort(k, in->nt, sizeof *k, cvm__rb_cmp_key);
    return k;
}

/* Hole seeds: the centroid of one triangle of each connected set of domain
 * triangles (across unconstrained edges) none of which is a file triangle
 * and whose seed lies in no file triangle. After the weights are set, a set
 * inside the file's domain is triangulated as in the file when the file is
 * valid, and a triangle outside the domain cannot have the vertex set of a
 * file triangle (the two would coincide). *n_out = 0 when there is none. */
static cvm_status hole_seeds(cvm__rebuild *rb, const cvm__rebuild_input *in, double **out,
                             size_t *n_out)
{
    const cvm__tri2 *T = &rb->tri;
    cvm__rb_key *fk = file_keys(rb, in);
    uint8_t *state = cvm__calloc(rb->ctx, T->nt + 1, 1); /* 1 unvisited, 2 visited, 0 other */
    uint8_t *member = cvm__calloc(rb->ctx, T->nt + 1, 1);
    int32_t *stack = cvm__malloc(rb->ctx, (T->nt + 1) * sizeof *stack);
    double *h = cvm__malloc(rb->ctx, (2 * T->nt + 2) * sizeof *h);
    cvm__tri_grid g;
    int have_grid = 0;
    size_t s, n = 0;
    int j;
    cvm_status st = CVM_OK;
    memset(&g, 0, sizeof g);
    *out = NULL;
    *n_out = 0;
    if (!fk || !state || !member || !stack || !h) {
        st = cvm__nomem(rb->ctx);
        goto out;
    }
    for (s = 0; s < T->nt; s++) {
        cvm__rb_key key;
        if (!cvm__tri2_in_domain(T, (int32_t)s))
            continue;
        cvm__rb_make_key(&key, T->tv[3 * s], T->tv[3 * s + 1], T->tv[3 * s + 2], 0);
        member[s] = cvm__rb_find(fk, in->nt, &key) >= 0;
        state[s] = 1;
    }
    for (s = 0; s < T->nt; s++) {
        size_t top = 0;
        int any = 0;
        if (state[s] != 1)
            continue;
        state[s] = 2;
        stack[top++] = (int32_t)s;
        while (top) {
            int32_t u = stack[--top];
            any |= member[u];
            for (j = 0; j < 3; j++) {
                int32_t a = T->tn[3 * (size_t)u + (size_t)j], x = a < 0 ? -1 : a / 3;
                if (x < 0 || state[x] != 1 || cvm__tri2_edge_seg(T, u, j) >= 0)
                    continue;
                state[x] = 2;
                stack[top++] = x;
            }
        }
        if (!any) {
            const int32_t *v = T->tv + 3 * s;
            if (!have_grid) {
                if (cvm__tri_grid_build(rb->ctx, &g, in->cdt.xy, in->cdt.np, in->tri, in->nt)) {
                    st = cvm__nomem(rb->ctx);
                    goto out;
                }
                have_grid = 1;
            }
            for (j = 0; j < 2; j++)
                h[2 * n + (size_t)j] = (T->xy[2 * (size_t)v[0] + (size_t)j] +
                                        T->xy[2 * (size_t)v[1] + (size_t)j] +
                                        T->xy[2 * (size_t)v[2] + (size_t)j]) / 3.0;
            /* a region inside the file's domain triangulated differently is
               not a hole: leave it for match() to report */
            n += !cvm__tri_grid_contains(&g, h + 2 * n);
        }
    }
    *out = h;
    h = NULL;
    *n_out = n;
out:
    cvm__tri_grid_free(rb->ctx, &g);
    cvm__free(rb->ctx, fk);
    cvm__free(rb->ctx, state);
    cvm__free(rb->ctx, member);
    cvm__free(rb->ctx, stack);
    cvm__free(rb->ctx, h);
    return st;
}

/* Compare rb's domain triangles with the file's; on a match put them in the
 * file's order. *bad receives the first file triangle not reproduced, or -1. */
static cvm_status match(cvm__rebuild *rb, const cvm__rebuild_input *in, int64_t *bad)
{
    size_t nk = 0, k;
    cvm__rb_key *sk = slot_keys(rb->ctx, &rb->tri, &nk);
    int32_t *slot = cvm__malloc(rb->ctx, (in->nt + 1) * sizeof *slot);
    uint8_t *rot = cvm__malloc(rb->ctx, in->nt + 1), *taken = cvm__calloc(rb->ctx, rb->tri.nt + 1, 1);
    cvm_status s = CVM_OK;
    *bad = -1;
    if (!sk || !slot || !rot || !taken) {
        s = cvm__nomem(rb->ctx);
        goto out;
    }
    for (k = 0; k < in->nt && *bad < 0; k++) {
        const int32_t *f = in->tri + 3 * k, *map = rb->out.input_map;
        cvm__rb_key key;
        int32_t sl;
        cvm__rb_make_key(&key, map[f[0]], map[f[1]], map[f[2]], 0);
        sl = cvm__rb_find(sk, nk, &key);
        if (sl < 0 || taken[sl]) {
            *bad = (int64_t)k;
            break;
        }
        taken[sl] = 1;
        slot[k] = sl;
        rot[k] = (uint8_t)(rb->tri.tv[3 * (size_t)sl] == map[f[0]] ? 0
                           : rb->tri.tv[3 * (size_t)sl + 1] == map[f[0]] ? 1 : 2);
    }
    if (*bad < 0 && nk != in->nt)
        *bad = (int64_t)in->nt; /* the triangulation has more triangles than the file */
    if (*bad < 0 && cvm__tri2_reorder(&rb->tri, slot, rot, in->nt))
        s = cvm__nomem(rb->ctx);
out:
    cvm__free(rb->ctx, sk);
    cvm__free(rb->ctx, slot);
    cvm__free(rb->ctx, rot);
    cvm__free(rb->ctx, taken);
    return s;
}

void cvm__rebuild_init(cvm__rebuild *rb, cvm__ctx *ctx)
{
    memset(rb, 0, sizeof *rb);
    rb->ctx = ctx;
    cvm__tri2_init(&rb->tri, ctx);
}

void cvm__rebuild_free(cvm__rebuild *rb)
{
    cvm__tri2_destroy(&rb->tri);
    cvm__free(rb->ctx, rb->out.input_map);
    cvm__free(rb->ctx, rb->out.vmark);
    cvm__free(rb->ctx, rb->out.vattr);
    cvm__free(rb->ctx, rb->seg);
    cvm__free(rb->ctx, rb->smark);
    cvm__free(rb->ctx, rb->holes);
    cvm__free(rb->ctx, rb->segtri);
    memset(&rb->out, 0, sizeof rb->out);
    rb->seg = rb->smark = rb->segtri = NULL;
    rb->holes = NULL;
    rb->nseg = rb->nholes = 0;
}

/* Triangulate the points of in with the first nseg of rb->seg as segments
 * and the given hole points: what cvm_mesh_triangulate() makes of them. */
static cvm_status build(cvm__rebuild *rb, const cvm__rebuild_input *in, size_t nseg,
                        const double *holes, size_t nholes)
{
    cvm__cdt_input cin;
    size_t n = in->cdt.np;
    cvm__tri2_clear(&rb->tri);
    /* a file edge on a line cell (a chain through a vertex) keeps the line's id, not that of
     * the edge's own temporary constraint, which drop_temporary() forgets */
    rb->tri.seg_keep_below = nseg > rb->keep_ids ? (int32_t)rb->keep_ids : 0;
    cvm__free(rb->ctx, rb->out.input_map);
    rb->out.input_map = NULL;
    rb->out.n_dup = 0;
    rb->nseg = nseg;
    cvm__free(rb->ctx, rb->holes);
    rb->holes = NULL;
    rb->nholes = 0;
    if (nholes) {
        if (!(rb->holes = cvm__malloc(rb->ctx, 2 * nholes * sizeof *holes)))
            return cvm__nomem(rb->ctx);
        memcpy(rb->holes, holes, 2 * nholes * sizeof *holes);
        rb->nholes = nholes;
    }
    if (n > (size_t)INT32_MAX / 4)
        return cvm__error(rb->ctx, CVM_E_TOO_LARGE, CVM_ENT_INPUT_POINT, -1,
                          "%lu points exceed the limit of %ld", (unsigned long)n,
                          (long)(INT32_MAX / 4));
    cin = in->cdt;
    cin.seg = rb->seg;
    cin.nseg = nseg;
    cin.smark = rb->smark;
    cin.holes = rb->holes;
    cin.nholes = nholes;
    cin.regions = NULL;
    cin.nregions = 0;
    cin.keep_hull = 0; /* the file's boundary edges are segments: its domain is inside them */
    memset(&rb->fault, 0, sizeof rb->fault);
    return cvm__cdt_build(&rb->tri, &cin, &rb->out, &rb->fault);
}

/* Weights of the file (per input point) onto rb's vertices, then the
 * Lawson flips of cvm_mesh_set_weights() from the (constrained) Delaunay
 * triangulation. */
static cvm_status weights(cvm__rebuild *rb, const cvm__rebuild_input *in)
{
    cvm__tri2 *T = &rb->tri;
    size_t i, nv = T->nv;
    double *w;
    if (!in->w)
        return CVM_OK;
    w = cvm__calloc(rb->ctx, (T->cap_v > nv ? T->cap_v : nv) + 1, sizeof *w);
    if (!w)
        return cvm__nomem(rb->ctx);
    for (i = 0; i < in->cdt.np; i++)
        w[rb->out.input_map[i]] = in->w[i];
    cvm__free(rb->ctx, T->w);
    T->w = w;
    return cvm__tri2_make_regular(T, NULL) ? cvm__nomem(rb->ctx) : CVM_OK;
}

/* Forget the temporary constraints (segment ids nreal and up) of a forced rebuild. */
static void drop_temporary(cvm__rebuild *rb, size_t nreal)
{
    cvm__tri2 *T = &rb->tri;
    size_t k;
    if (rb->nseg <= nreal)
        return;
    for (k = 0; T->te && k < 3 * T->nt; k++)
        if (T->te[k] >= (int32_t)nreal)
            T->te[k] = -1;
    rb->nseg = nreal;
}

/* The regional attributes of the file onto rb's triangles, in the file's order. */
static cvm_status rb_attributes(cvm__rebuild *rb, const cvm__rebuild_input *in)
{
    size_t k;
    if (!in->tattr)
        return CVM_OK;
    if (cvm__tri2_enable_attributes(&rb->tri))
        return cvm__nomem(rb->ctx);
    for (k = 0; k < in->nt; k++)
        rb->tri.ta[k] = in->tattr[k];
    return CVM_OK;
}

/* One attempt with the first nseg segments of rb->seg; nseg = 0 tries the
 * plain triangulation of the points (files without lines). *bad as in
 * match(). */
static cvm_status attempt(cvm__rebuild *rb, const cvm__rebuild_input *in, size_t nseg,
                          int64_t *bad)
{
    double *holes = NULL;
    size_t nholes = 0;
    cvm_status s;
    rb->keep_ids = 0;
    if ((s = build(rb, in, nseg, NULL, 0)))
        return s;
    if ((s = weights(rb, in)))
        return s;
    if (nseg) {
        if ((s = hole_seeds(rb, in, &holes, &nholes)))
            return s;
        if (nholes && !(s = build(rb, in, nseg, holes, nholes)))
            s = weights(rb, in);
        cvm__free(rb->ctx, holes);
        if (s)
            return s;
    }
    if ((s = match(rb, in, bad)) || *bad >= 0)
        return s;
    return rb_attributes(rb, in);
}

/* The last attempt: every file edge constrained, which reproduces the cells
 * exactly when they are a conforming triangulation (the constrained
 * triangulation of a triangulation's edges is that triangulation); *bad as
 * in match() otherwise. Then the inner edges (but region borders) are
 * released and flipped to the constrained Delaunay (regular, with weights)
 * triangulation: rb->nflips counts the flips in the domain. The slots keep
 * the file's order; two triangles a flip made take the slots of the two it
 * replaced. */
static cvm_status rb_forced(cvm__rebuild *rb, const cvm__rebuild_input *in, size_t nall,
                         size_t nkeep, int64_t *bad)
{
    cvm__tri2 *T = &rb->tri;
    double *holes = NULL, *w;
    size_t nholes = 0, i;
    cvm_status s;
    rb->keep_ids = nkeep;
    if ((s = build(rb, in, nall, NULL, 0)))
        return s;
    if ((s = hole_seeds(rb, in, &holes, &nholes)))
        return s;
    if (nholes)
        s = build(rb, in, nall, holes, nholes);
    cvm__free(rb->ctx, holes);
    if (s || (s = match(rb, in, bad)) || *bad >= 0)
        return s;
    drop_temporary(rb, nkeep);
    if ((s = rb_attributes(rb, in)))
        return s;
    if (in->w) {
        if (!(w = cvm__calloc(rb->ctx, (T->cap_v > T->nv ? T->cap_v : T->nv) + 1, sizeof *w)))
            return cvm__nomem(rb->ctx);
        for (i = 0; i < in->cdt.np; i++)
            w[rb->out.input_map[i]] = in->w[i];
        cvm__free(rb->ctx, T->w);
        T->w = w;
    }
    return cvm__tri2_make_regular_count(T, NULL, &rb->nflips) ? cvm__nomem(rb->ctx) : CVM_OK;
}

/* Two file edges cross (rb->fault, in the rebuild with the first nseg
 * segments): when both are triangles' edges, the triangles overlap; say so
 * in the file's terms. Returns s otherwise. */
static cvm_status rb_overlap(cvm__rebuild *rb, const cvm__rebuild_input *in, cvm_status s)
{
    const cvm__cdt_fault *f = &rb->fault;
    int32_t t, u;
    const int32_t *a, *b, *sa, *sb;
    if (s != CVM_E_INPUT_INTERSECTING || f->kind != CVM__CDT_FAULT_CROSSING || f->item >= rb->nseg ||
        f->other >= rb->nseg || (t = rb->segtri[f->item]) < 0 || (u = rb->segtri[f->other]) < 0)
        return s;
    a = in->tri + 3 * (size_t)t;
    b = in->tri + 3 * (size_t)u;
    sa = rb->seg + 2 * f->item;
    sb = rb->seg + 2 * f->other;
    memset(&rb->fault, 0, sizeof rb->fault);
    rb->rebuilding = 0;
    return cvm__error(rb->ctx, s, CVM_ENT_TRIANGLE, t,
                      "triangle %ld (points %ld %ld %ld) overlaps triangle %ld (points %ld %ld "
                      "%ld): their edges %ld-%ld and %ld-%ld cross", (long)t, (long)a[0],
                      (long)a[1], (long)a[2], (long)u, (long)b[0], (long)b[1], (long)b[2],
                      (long)sa[0], (long)sa[1], (long)sb[0], (long)sb[1]);
}

cvm_status cvm__rebuild_cells(cvm__rebuild *rb, const cvm__rebuild_input *in)
{
    size_t nseg = 0, nreal = 0, nkeep = 0;
    int64_t bad = -1;
    cvm_status s;
    rb->rebuilding = 0;
    rb->nflips = 0;
    if ((s = cvm__rb_cells(rb, in, &nreal, &nkeep, &nseg)))
        return s;
    rb->rebuilding = 1;
    /* 1. no lines: the Delaunay (regular) triangulation of the points */
    if (!in->has_lines)
        s = attempt(rb, in, 0, &bad);
    /* 2. the constrained one, with the boundary as segments and hole seeds */
    if (!s && (in->has_lines || bad >= 0)) {
        bad = -1;
        s = attempt(rb, in, nreal, &bad);
    }
    /* 3. every file edge forced, then flipped (a mesh that is not
       constrained Delaunay; weights the regular triangulation does not reach
       from the CDT: vanished vertices) */
    if (!s && bad >= 0) {
        bad = -1;
        s = rb_forced(rb, in, nseg, nkeep, &bad);
    }
    if (s)
        return rb_overlap(rb, in, s);
    rb->rebuilding = 0;
    if (bad >= 0) {
        const int32_t *f = in->tri + 3 * (bad < (int64_t)in->nt ? bad : 0);
        if (bad == (int64_t)in->nt)
            return cvm__error(rb->ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_NONE, -1,
                              "the constrained triangulation of its points and edges has more "
                              "triangles than the file (%lu): the cells are not a conforming "
                              "triangulation (they leave a gap)", (unsigned long)in->nt);
        return cvm__error(rb->ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_TRIANGLE, bad,
                          "triangle %ld (points %ld %ld %ld) is not a triangle of the constrained "
                          "triangulation of the file's points and edges: the cells are not a "
                          "conforming triangulation (they overlap, or a point or line cell lies "
                          "inside a triangle)", (long)bad, (long)f[0], (long)f[1], (long)f[2]);
    }
    return CVM_OK;
}
