/*
 * mesh_read_vtu.c - cvm_mesh_read of a mesh file (.vtu, .vtk, .msh): rebuilds
 * the triangulated, weighted mesh it holds and proves it is the same mesh.
 * Points become input points (a point in no triangle must lie outside the
 * domain, located through mesh_read_grid.c); line cells and boundary edges of
 * triangles become segments (no line cells: first tried as the Delaunay
 * triangulation of the points). The PSLG is triangulated, regions without a
 * file triangle get hole points, weights are set. When that misses the file's
 * triangles (empty power cells make the result depend on the start), the
 * file's inner edges become temporary constraints, are dropped, and the Lawson
 * flips of cvm_mesh_set_weights() must leave its triangles alone. Slots are
 * then reordered to the file's order, so writing reproduces the file. All is
 * built in engine structures (struct rebuild) that replace the handle's mesh
 * only on success.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "output_internal.h"
#include "mesh_read_grid.h"
#include "geom/geom_internal.h"

/* The mesh being rebuilt: the parts of a cvm_mesh that a read replaces, built
 * with the kernel (lib/delaunay) as cvm_mesh_triangulate() and
 * cvm_mesh_set_weights() would build them from the same input and options,
 * and moved into the handle (adopt()) only once they hold the file's mesh.
 * in.xy, in.pmark, in.pattr are the file's arrays (owned by the
 * cvm__vtu_mesh until adopt() takes them); in.seg, in.smark, in.holes and the
 * rest are owned here. */
typedef struct rebuild {
    cvm__ctx ctx;        /* the handle's allocator; no progress callback and no time
                            limit (a read is not cut short); the message of a failure */
    cvm__cdt_input opt;  /* the handle's options for cvm__cdt_build() */
    cvm__pslg in;        /* the input of the current attempt */
    cvm__tri2 tri;
    cvm__cdt_out out;    /* input map, markers and attributes of the vertices */
} rebuild;

/* A triangle as its sorted vertex ids, and where it comes from. */
typedef struct tkey {
    int32_t v[3];
    int32_t src;
} tkey;

static int cmp_key(const void *pa, const void *pb)
{
    const tkey *a = pa, *b = pb;
    int k;
    for (k = 0; k < 3; k++)
        if (a->v[k] != b->v[k])
            return a->v[k] < b->v[k] ? -1 : 1;
    return a->src < b->src ? -1 : a->src > b->src;
}

static void make_key(tkey *k, int32_t a, int32_t b, int32_t c, int32_t src)
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

/* Sorted keys of the domain slots of T. */
static tkey *slot_keys(cvm__ctx *ctx, const cvm__tri2 *T, size_t *n_out)
{
    size_t t, n = 0;
    tkey *k = cvm__malloc(ctx, (cvm__domain_triangles(T) + 1) * sizeof *k);
    if (!k)
        return NULL;
    for (t = 0; t < T->nt; t++)
        if (cvm__tri2_in_domain(T, (int32_t)t))
            make_key(&k[n++], T->tv[3 * t], T->tv[3 * t + 1], T->tv[3 * t + 2], (int32_t)t);
    qsort(k, n, sizeof *k, cmp_key);
    *n_out = n;
    return k;
}

static int cmp_v(const int32_t *a, const int32_t *b)
{
    int k;
    for (k = 0; k < 3; k++)
        if (a[k] != b[k])
            return a[k] < b[k] ? -1 : 1;
    return 0;
}

/* src of an entry of keys (sorted) with the vertex set of key, or -1. */
static int32_t find_slot(const tkey *keys, size_t n, const tkey *key)
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

/* A point that is no triangle's corner must lie outside the file's domain
 * (exact test): cvm_mesh_triangulate() leaves such vertices (ends of segments
 * bounding no region) where it carved, and the rebuild carves them again. */
static cvm_status unused_points(cvm_mesh *m, const char *path, const cvm__vtu_mesh *vm,
                                const uint8_t *used)
{
    cvm__file_grid g;
    size_t i;
    cvm_status s = CVM_OK;
    memset(&g, 0, sizeof g);
    for (i = 0; i < vm->p.np && used[i]; i++)
        ;
    if (i < vm->p.np && cvm__file_grid_build(&m->ctx, vm, &g))
        return cvm__nomem(&m->ctx);
    for (; i < vm->p.np && !s; i++) {
        const double *p = vm->p.xy + 2 * i;
        if (!used[i] && cvm__file_grid_in_domain(vm, &g, p))
            s = cvm__error(&m->ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_INPUT_POINT, (int64_t)i,
                           "%s: point %lu at (%.17g, %.17g) lies in the mesh but is a corner of "
                           "no triangle", path, (unsigned long)i, p[0], p[1]);
    }
    cvm__file_grid_free(&m->ctx, &g);
    return s;
}

/* Check the file's triangles: distinct corners, no unused point inside; collect
 * the edges used by one triangle only (boundary) into *bnd and those used by
 * two (inner) into *inner (2 ids per edge). */
static cvm_status file_checks(cvm_mesh *m, const char *path, const cvm__vtu_mesh *vm,
                              int32_t **bnd, size_t *nbnd, int32_t **inner, size_t *ninner)
{
    size_t k, n = 0, ni = 0, i, ne = 3 * vm->nt;
    uint8_t *used = cvm__calloc(&m->ctx, vm->p.np + 1, 1);
    tkey *e = cvm__malloc(&m->ctx, (ne + 1) * sizeof *e);
    int32_t *b = cvm__malloc(&m->ctx, (2 * ne + 1) * sizeof *b);
    int32_t *in = cvm__malloc(&m->ctx, (ne + 1) * sizeof *in);
    cvm_status s = CVM_OK;
    *bnd = NULL;
    *inner = NULL;
    if (!used || !e || !b || !in) {
        s = cvm__nomem(&m->ctx);
        goto out;
    }
    if (vm->nt == 0) {
        s = cvm__error(&m->ctx, CVM_E_INPUT_EMPTY, CVM_ENT_NONE, -1, "%s has no triangle cells", path);
        goto out;
    }
    for (k = 0; k < vm->nt; k++) {
        const int32_t *t = vm->tri + 3 * k;
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
            s = cvm__error(&m->ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_TRIANGLE, (int64_t)k,
                           "%s: triangle %lu (points %ld %ld %ld) repeats a point", path,
                           (unsigned long)k, (long)t[0], (long)t[1], (long)t[2]);
            goto out;
        }
        for (i = 0; i < 3; i++) {
            int32_t a = t[i], c = t[(i + 1) % 3];
            const double *pa = vm->p.xy + 2 * (size_t)a, *pc = vm->p.xy + 2 * (size_t)c;
            /* said here in the file's terms: the rebuild would only see a
               zero-length boundary segment the file does not have */
            if (pa[0] == pc[0] && pa[1] == pc[1]) {
                s = cvm__error(&m->ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_TRIANGLE, (int64_t)k,
                               "%s: triangle %lu (points %ld %ld %ld) is degenerate: points %ld "
                               "and %ld are both at (%.17g, %.17g)", path, (unsigned long)k,
                               (long)t[0], (long)t[1], (long)t[2], (long)a, (long)c, pa[0], pa[1]);
                goto out;
            }
            used[a] = 1;
            /* edge key: (lo, hi, -1) with src = triangle */
            make_key(&e[3 * k + i], a < c ? a : c, a < c ? c : a, INT32_MAX, (int32_t)k);
        }
    }
    for (k = 0; k < vm->p.nseg; k++) {
        const int32_t *l = vm->p.seg + 2 * k;
        const double *pa = vm->p.xy + 2 * (size_t)l[0], *pb = vm->p.xy + 2 * (size_t)l[1];
        if (pa[0] == pb[0] && pa[1] == pb[1]) {
            s = cvm__error(&m->ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_NONE, -1,
                           "%s: line cell %lu (points %ld-%ld) has zero length: both ends are at "
                           "(%.17g, %.17g)", path, (unsigned long)k, (long)l[0], (long)l[1],
                           pa[0], pa[1]);
            goto out;
        }
    }
    if ((s = unused_points(m, path, vm, used)))
        goto out;
    qsort(e, ne, sizeof *e, cmp_key);
    for (k = 0; k < ne; k = i) {
        for (i = k + 1; i < ne && e[i].v[0] == e[k].v[0] && e[i].v[1] == e[k].v[1]; i++)
            ;
        if (i - k > 2) {
            s = cvm__error(&m->ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_TRIANGLE, (int64_t)e[k + 2].src,
                           "%s: edge %ld-%ld has more than two triangles (triangle %ld is one)",
                           path, (long)e[k].v[0], (long)e[k].v[1], (long)e[k + 2].src);
            goto out;
        }
        if (i - k == 1) {
            b[2 * n] = e[k].v[0];
            b[2 * n + 1] = e[k].v[1];
            n++;
        } else {
            in[2 * ni] = e[k].v[0];
            in[2 * ni + 1] = e[k].v[1];
            ni++;
        }
    }
    *bnd = b;
    b = NULL;
    *nbnd = n;
    *inner = in;
    in = NULL;
    *ninner = ni;
out:
    cvm__free(&m->ctx, used);
    cvm__free(&m->ctx, e);
    cvm__free(&m->ctx, b);
    cvm__free(&m->ctx, in);
    return s;
}

/* Segments: the file's lines, then each boundary edge that is not a line
 * (*nreal_out of them), then each inner edge that is not a line (the
 * temporary constraints of a forced rebuild, marker 0). */
static cvm_status segments(cvm_mesh *m, const cvm__vtu_mesh *vm, const int32_t *bnd, size_t nbnd,
                           const int32_t *inner, size_t ninner, int32_t **seg_out,
                           int32_t **mark_out, size_t *n_out, size_t *nreal_out)
{
    size_t nl = vm->p.nseg, n = 0, k;
    int32_t *seg = cvm__malloc(&m->ctx, (2 * (nl + nbnd + ninner) + 1) * sizeof *seg);
    int32_t *mark = cvm__malloc(&m->ctx, (nl + nbnd + ninner + 1) * sizeof *mark);
    tkey *lines = cvm__malloc(&m->ctx, (nl + 1) * sizeof *lines);
    if (!seg || !mark || !lines) {
        cvm__free(&m->ctx, seg);
        cvm__free(&m->ctx, mark);
        cvm__free(&m->ctx, lines);
        return cvm__nomem(&m->ctx);
    }
    for (k = 0; k < nl; k++) {
        int32_t a = vm->p.seg[2 * k], b = vm->p.seg[2 * k + 1];
        seg[2 * n] = a;
        seg[2 * n + 1] = b;
        mark[n++] = vm->p.smark ? vm->p.smark[k] : 1;
        make_key(&lines[k], a < b ? a : b, a < b ? b : a, INT32_MAX, 0);
    }
    qsort(lines, nl, sizeof *lines, cmp_key);
    for (k = 0; k < nbnd; k++) {
        tkey key;
        make_key(&key, bnd[2 * k], bnd[2 * k + 1], INT32_MAX, 0);
        if (find_slot(lines, nl, &key) >= 0)
            continue;
        seg[2 * n] = bnd[2 * k];
        seg[2 * n + 1] = bnd[2 * k + 1];
        mark[n++] = 1;
    }
    *nreal_out = n;
    for (k = 0; k < ninner; k++) { /* temporary constraints (forced rebuild) */
        tkey key;
        make_key(&key, inner[2 * k], inner[2 * k + 1], INT32_MAX, 0);
        if (find_slot(lines, nl, &key) >= 0)
            continue;
        seg[2 * n] = inner[2 * k];
        seg[2 * n + 1] = inner[2 * k + 1];
        mark[n++] = 0;
    }
    cvm__free(&m->ctx, lines);
    *seg_out = seg;
    *mark_out = mark;
    *n_out = n;
    return CVM_OK;
}

/* File triangle keys in vertex ids (through rb's input map), sorted. */
static tkey *file_keys(rebuild *rb, const cvm__vtu_mesh *vm)
{
    tkey *k = cvm__malloc(&rb->ctx, (vm->nt + 1) * sizeof *k);
    size_t i;
    const int32_t *map = rb->out.input_map;
    if (!k)
        return NULL;
    for (i = 0; i < vm->nt; i++)
        make_key(&k[i], map[vm->tri[3 * i]], map[vm->tri[3 * i + 1]], map[vm->tri[3 * i + 2]],
                 (int32_t)i);
    qsort(k, vm->nt, sizeof *k, cmp_key);
    return k;
}

/* Hole seeds: the centroid of one triangle of each connected set of domain
 * triangles (across unconstrained edges) none of which is a file triangle
 * and whose seed lies in no file triangle. After the weights are set, a set
 * inside the file's domain is triangulated as in the file when the file is
 * valid, and a triangle outside the domain cannot have the vertex set of a
 * file triangle (the two would coincide). *n_out = 0 when there is none. */
static cvm_status hole_seeds(rebuild *rb, const cvm__vtu_mesh *vm, double **out, size_t *n_out)
{
    const cvm__tri2 *T = &rb->tri;
    tkey *fk = file_keys(rb, vm);
    uint8_t *state = cvm__calloc(&rb->ctx, T->nt + 1, 1); /* 1 unvisited, 2 visited, 0 other */
    uint8_t *member = cvm__calloc(&rb->ctx, T->nt + 1, 1);
    int32_t *stack = cvm__malloc(&rb->ctx, (T->nt + 1) * sizeof *stack);
    double *h = cvm__malloc(&rb->ctx, (2 * T->nt + 2) * sizeof *h);
    cvm__file_grid g;
    int have_grid = 0;
    size_t s, n = 0;
    int j;
    cvm_status st = CVM_OK;
    memset(&g, 0, sizeof g);
    *out = NULL;
    *n_out = 0;
    if (!fk || !state || !member || !stack || !h) {
        st = cvm__nomem(&rb->ctx);
        goto out;
    }
    for (s = 0; s < T->nt; s++) {
        tkey key;
        if (!cvm__tri2_in_domain(T, (int32_t)s))
            continue;
        make_key(&key, T->tv[3 * s], T->tv[3 * s + 1], T->tv[3 * s + 2], 0);
        member[s] = find_slot(fk, vm->nt, &key) >= 0;
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
                if (cvm__file_grid_build(&rb->ctx, vm, &g)) {
                    st = cvm__nomem(&rb->ctx);
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
            n += !cvm__file_grid_in_domain(vm, &g, h + 2 * n);
        }
    }
    *out = h;
    h = NULL;
    *n_out = n;
out:
    cvm__file_grid_free(&rb->ctx, &g);
    cvm__free(&rb->ctx, fk);
    cvm__free(&rb->ctx, state);
    cvm__free(&rb->ctx, member);
    cvm__free(&rb->ctx, stack);
    cvm__free(&rb->ctx, h);
    return st;
}

/* Compare rb's domain triangles with the file's; on a match put them in the
 * file's order. *bad receives the first file triangle not reproduced, or -1. */
static cvm_status match(rebuild *rb, const cvm__vtu_mesh *vm, int64_t *bad)
{
    size_t nk = 0, k;
    tkey *sk = slot_keys(&rb->ctx, &rb->tri, &nk);
    int32_t *slot = cvm__malloc(&rb->ctx, (vm->nt + 1) * sizeof *slot);
    uint8_t *rot = cvm__malloc(&rb->ctx, vm->nt + 1), *taken = cvm__calloc(&rb->ctx, rb->tri.nt + 1, 1);
    cvm_status s = CVM_OK;
    *bad = -1;
    if (!sk || !slot || !rot || !taken) {
        s = cvm__nomem(&rb->ctx);
        goto out;
    }
    for (k = 0; k < vm->nt && *bad < 0; k++) {
        const int32_t *f = vm->tri + 3 * k, *map = rb->out.input_map;
        tkey key;
        int32_t sl;
        make_key(&key, map[f[0]], map[f[1]], map[f[2]], 0);
        sl = find_slot(sk, nk, &key);
        if (sl < 0 || taken[sl]) {
            *bad = (int64_t)k;
            break;
        }
        taken[sl] = 1;
        slot[k] = sl;
        rot[k] = (uint8_t)(rb->tri.tv[3 * (size_t)sl] == map[f[0]] ? 0
                           : rb->tri.tv[3 * (size_t)sl + 1] == map[f[0]] ? 1 : 2);
    }
    if (*bad < 0 && nk != vm->nt)
        *bad = (int64_t)vm->nt; /* the triangulation has more triangles than the file */
    if (*bad < 0 && cvm__tri2_reorder(&rb->tri, slot, rot, vm->nt))
        s = cvm__nomem(&rb->ctx);
out:
    cvm__free(&rb->ctx, sk);
    cvm__free(&rb->ctx, slot);
    cvm__free(&rb->ctx, rot);
    cvm__free(&rb->ctx, taken);
    return s;
}

/* ---- the rebuild: cvm_mesh_triangulate() of the attempt's input, on rb ---- */

static void rb_init(rebuild *rb, const cvm_mesh *m, const cvm__vtu_mesh *vm)
{
    memset(rb, 0, sizeof *rb);
    rb->ctx = m->ctx;
    rb->ctx.progress_fn = NULL;
    rb->ctx.progress_payload = NULL;
    rb->ctx.progress_every = 0;
    cvm__clear_error(&rb->ctx);
    cvm__run_begin(&rb->ctx, 0);
    rb->in.xy = vm->p.xy;
    rb->in.np = vm->p.np;
    rb->in.pmark = vm->p.pmark;
    rb->in.pattr = vm->p.pattr;
    rb->in.nattr = vm->p.pattr ? vm->p.nattr : 0;
    cvm__tri2_init(&rb->tri, &rb->ctx);
    cvm__mesh_cdt_input(&rb->opt, m, &rb->in);
    rb->opt.keep_hull = 0; /* the file's boundary edges are segments: its domain is inside them */
}

/* Free what rb owns (not the file's point arrays). */
static void rb_free(rebuild *rb)
{
    cvm__tri2_destroy(&rb->tri);
    cvm__free(&rb->ctx, rb->out.input_map);
    cvm__free(&rb->ctx, rb->out.vmark);
    cvm__free(&rb->ctx, rb->out.vattr);
    cvm__free(&rb->ctx, rb->in.seg);
    cvm__free(&rb->ctx, rb->in.smark);
    cvm__free(&rb->ctx, rb->in.holes);
}

/* Triangulate rb's input with the first nseg of in.seg as segments and the
 * given hole points: what cvm_mesh_triangulate() makes of it. */
static cvm_status build(rebuild *rb, size_t nseg, const double *holes, size_t nholes)
{
    cvm__cdt_input in;
    cvm__cdt_fault f;
    cvm_status s;
    size_t n = rb->in.np;
    cvm__tri2_clear(&rb->tri);
    cvm__free(&rb->ctx, rb->out.input_map);
    rb->out.input_map = NULL;
    rb->out.n_dup = 0;
    rb->in.nseg = nseg;
    cvm__free(&rb->ctx, rb->in.holes);
    rb->in.holes = NULL;
    rb->in.nholes = 0;
    if (nholes) {
        if (!(rb->in.holes = cvm__malloc(&rb->ctx, 2 * nholes * sizeof *holes)))
            return cvm__nomem(&rb->ctx);
        memcpy(rb->in.holes, holes, 2 * nholes * sizeof *holes);
        rb->in.nholes = nholes;
    }
    if (n > (size_t)INT32_MAX / 4)
        return cvm__error(&rb->ctx, CVM_E_TOO_LARGE, CVM_ENT_INPUT_POINT, -1,
                          "%lu points exceed the limit of %ld", (unsigned long)n,
                          (long)(INT32_MAX / 4));
    in = rb->opt;
    in.seg = rb->in.seg;
    in.nseg = nseg;
    in.smark = rb->in.smark;
    in.holes = rb->in.holes;
    in.nholes = nholes;
    s = cvm__cdt_build(&rb->tri, &in, &rb->out, &f);
    return s ? cvm__cdt_fault_message(&rb->ctx, &rb->in, s, &f) : CVM_OK;
}

/* Weights of the file (per input point) onto rb's vertices. forced: rb holds
 * the file's triangles already; the weights are set without flips, then the
 * Lawson flips of cvm_mesh_set_weights() run, which change nothing in the
 * domain exactly when the file's mesh is what cvm_mesh_set_weights() keeps
 * (regular, or its illegal edges unflippable: vanished vertices). Not
 * forced: the flips of cvm_mesh_set_weights() from the (constrained)
 * Delaunay triangulation. */
static cvm_status weights(rebuild *rb, const cvm__vtu_mesh *vm, int forced)
{
    cvm__tri2 *T = &rb->tri;
    size_t i, nv = T->nv;
    double *w;
    if (!vm->w && !forced)
        return CVM_OK;
    w = cvm__calloc(&rb->ctx, (T->cap_v > nv ? T->cap_v : nv) + 1, sizeof *w);
    if (!w)
        return cvm__nomem(&rb->ctx);
    for (i = 0; vm->w && i < vm->p.np; i++)
        w[rb->out.input_map[i]] = vm->w[i];
    cvm__free(&rb->ctx, T->w);
    T->w = vm->w ? w : NULL;
    if (!vm->w)
        cvm__free(&rb->ctx, w);
    return cvm__tri2_make_regular(T, NULL) ? cvm__nomem(&rb->ctx) : CVM_OK;
}

/* Forget the temporary constraints (segment ids nreal and up) of a forced rebuild. */
static void drop_temporary(rebuild *rb, size_t nreal)
{
    cvm__tri2 *T = &rb->tri;
    size_t k;
    if (rb->in.nseg <= nreal)
        return;
    for (k = 0; T->te && k < 3 * T->nt; k++)
        if (T->te[k] >= (int32_t)nreal)
            T->te[k] = -1;
    rb->in.nseg = nreal;
}

/* One attempt with the first nseg segments of rb->in.seg, of which the first
 * nreal are kept (nseg > nreal: a forced rebuild, see weights()); nseg = 0
 * tries the plain triangulation of the points (files without lines). *bad as
 * in match(). */
static cvm_status attempt(rebuild *rb, const cvm__vtu_mesh *vm, size_t nseg, size_t nreal,
                          int64_t *bad)
{
    double *holes = NULL;
    size_t nholes = 0;
    int forced = nseg > nreal;
    cvm_status s = build(rb, nseg, NULL, 0);
    if (s)
        return s;
    drop_temporary(rb, nreal);
    if ((s = weights(rb, vm, forced)))
        return s;
    if (nseg) {
        if ((s = hole_seeds(rb, vm, &holes, &nholes)))
            return s;
        if (nholes && !(s = build(rb, nseg, holes, nholes))) {
            drop_temporary(rb, nreal);
            s = weights(rb, vm, forced);
        }
        cvm__free(&rb->ctx, holes);
        if (s)
            return s;
    }
    if ((s = match(rb, vm, bad)) || *bad >= 0)
        return s;
    if (vm->tattr) {
        size_t k;
        if (cvm__tri2_enable_attributes(&rb->tri))
            return cvm__nomem(&rb->ctx);
        for (k = 0; k < vm->nt; k++)
            rb->tri.ta[k] = vm->tattr[k];
    }
    return CVM_OK;
}

static cvm_status run(cvm_mesh *m, rebuild *rb, const char *path, const cvm__vtu_mesh *vm)
{
    int32_t *bnd = NULL, *inner = NULL;
    size_t nbnd = 0, ninner = 0, nseg = 0, nreal = 0;
    int64_t bad = -1;
    cvm_status s;
    if ((s = file_checks(m, path, vm, &bnd, &nbnd, &inner, &ninner)))
        return s;
    s = segments(m, vm, bnd, nbnd, inner, ninner, &rb->in.seg, &rb->in.smark, &nseg, &nreal);
    cvm__free(&m->ctx, bnd);
    cvm__free(&m->ctx, inner);
    if (s)
        return s;
    /* 1. no lines: the Delaunay (regular) triangulation of the points */
    if (!vm->has_lines)
        s = attempt(rb, vm, 0, 0, &bad);
    /* 2. the constrained one, with the boundary as segments and hole seeds */
    if (!s && (vm->has_lines || bad >= 0)) {
        bad = -1;
        s = attempt(rb, vm, nreal, nreal, &bad);
    }
    /* 3. every file edge forced, then checked by the flips (weights the
       regular triangulation does not reach from the CDT: vanished vertices) */
    if (!s && bad >= 0 && nseg > nreal) {
        bad = -1;
        s = attempt(rb, vm, nseg, nreal, &bad);
    }
    if (s)
        return cvm__error(&m->ctx, rb->ctx.status, rb->ctx.err_kind, rb->ctx.err_index,
                          "%s: rebuilding the mesh: %s", path, rb->ctx.errmsg);
    if (bad >= 0) {
        const int32_t *f = vm->tri + 3 * (bad < (int64_t)vm->nt ? bad : 0);
        if (bad == (int64_t)vm->nt)
            return cvm__error(&m->ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_NONE, -1,
                              "%s: the triangulation of its points and segments has more "
                              "triangles than the file (%lu): the file's mesh is not a "
                              "constrained regular triangulation", path, (unsigned long)vm->nt);
        return cvm__error(&m->ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_TRIANGLE, bad,
                          "%s: triangle %ld (points %ld %ld %ld) is not reproduced by the "
                          "constrained regular triangulation of the file's points, segments and "
                          "weights", path, (long)bad, (long)f[0], (long)f[1], (long)f[2]);
    }
    return CVM_OK;
}

/* Move the rebuilt mesh into m, part by part: its input and triangulation
 * replace m's (which are freed, with the reports of m's earlier runs); m's
 * context, options, front markers and staged writes stay. Takes the file's
 * point arrays from vm. Cannot fail. */
static void adopt(cvm_mesh *m, rebuild *rb, cvm__vtu_mesh *vm)
{
    cvm__mesh_drop_output(m);
    cvm__pslg_free(&m->ctx, &m->in);
    if (rb->in.nseg == 0) { /* read as the triangulation of the points */
        cvm__free(&rb->ctx, rb->in.seg);
        cvm__free(&rb->ctx, rb->in.smark);
        rb->in.seg = NULL;
        rb->in.smark = NULL;
    }
    m->in = rb->in;
    memset(&rb->in, 0, sizeof rb->in);
    vm->p.xy = NULL; /* now m->in's */
    vm->p.pmark = NULL;
    vm->p.pattr = NULL;
    cvm__tri2_destroy(&m->tri);
    m->tri = rb->tri;
    m->tri.ctx = &m->ctx;
    cvm__tri2_init(&rb->tri, &rb->ctx);
    m->input_map = rb->out.input_map;
    m->n_dup = rb->out.n_dup;
    cvm__free(&m->ctx, m->vmark);
    cvm__free(&m->ctx, m->vattr);
    m->vmark = rb->out.vmark;
    m->vattr = rb->out.vattr;
    m->cap_vmark = rb->out.cap_vmark;
    m->cap_vattr = rb->out.cap_vattr;
    memset(&rb->out, 0, sizeof rb->out);
    m->triangulated = 1;
    m->nv_triangulated = m->tri.nv;
}

cvm_status cvm__mesh_read_vtu(cvm_mesh *m, const char *path)
{
    cvm__vtu_mesh vm;
    rebuild rb;
    cvm_status s = cvm__read_mesh_file(&m->ctx, path, &vm);
    if (s)
        return s;
    if (vm.nt == 0 && !cvm__path_has_ext(path, ".vtu")) { /* a domain: points and lines */
        cvm__mesh_drop_output(m);
        cvm__pslg_free(&m->ctx, &m->in);
        m->in = vm.p;
        memset(&vm.p, 0, sizeof vm.p);
        cvm__vtu_mesh_free(&m->ctx, &vm);
        return CVM_OK;
    }
    rb_init(&rb, m, &vm);
    if (!(s = run(m, &rb, path, &vm)))
        adopt(m, &rb, &vm);
    rb_free(&rb);
    cvm__vtu_mesh_free(&m->ctx, &vm);
    return s;
}
