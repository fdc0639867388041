/*
 * g3_octree.c - the free space as the centroids of a 2:1-balanced octree.
 *
 * The root is the surface's bounding cube (corner at the bounding box's lower
 * corner, edge its largest extent). An octant of edge e splits while e exceeds
 * OCT_SPLIT times the size at its centre (or may, by a user source's reach),
 * down to the level where the field's smallest size is met (OCT_MAX_LEVEL with
 * a callback). The tree is then
 * balanced: two leaves that share a face (with balance 26: a face, an edge or
 * a corner) differ by at most one level, the finest leaves first so that one
 * sweep per level suffices (a split only makes leaves coarser than the level
 * in hand). Measured on the sphere in a box (size 0.5, grading 0.3): balance
 * 26 gives 4 % more tetrahedra and 19.5 % non-compliant after merging against
 * 20.4 % with 6; around a point source both gave the same tree.
 * Optionally (split_hanging) every leaf with a split octant of its own level
 * across a face, whose children's corners hang on the leaf's face, is then
 * split once (all such leaves found before any split, so nothing cascades)
 * and the tree balanced again.
 *
 * One candidate per leaf, at its centroid, level by level from the root down:
 * kept when it lies farther than its rejection distance dm (the lattice's
 * rule, cvm__g3_lattice_dm() of the least of its size and the leaf's edge)
 * from every point so far (surface, near field, coarser leaves) and from every
 * surface triangle, and strictly inside the domain (exact). The triangles
 * count because the root cube is not aligned with the surface: without them a
 * plane of centroids can sit a hair inside a wall between its points, which
 * gives slivers (and, on the wing slab, an assertion inside TetGen 1.5).
 *
 * Corners are not candidates: where the tree is uniform the centroids form a
 * cubic lattice, eight cospherical points per cube whose Delaunay tetrahedra
 * share one circumcentre on their common faces, a cell the dual merge joins
 * into one (lib/dual3/d3_merge.c). Measured around a point source (size 0.1,
 * growth 0.2, in the box [-8, 8]^3, tetrahedra within 1 of it): none is
 * non-compliant after merging (four sources tried); with the centre rule alone
 * (no sources' boxes) centroids gave 0.7 %, centroids and corners 11 %, and
 * centroids moved by 1e-12 of the edge 25 %: the cubes must be exact.
 *
 * Nodes live in one array in creation order (the order of every output), with
 * an open-addressing table from (level, i, j, k) to node for the neighbour
 * lookups; the table is never iterated.
 */
#include <math.h>
#include <string.h>

#include "delaunay3/delaunay3_internal.h"
#include "generate3/generate3.h"

#define OCT_MAX_LEVEL 19 /* 19 index bits per axis and 5 for the level fit a key */
#define OCT_AXIS_BITS 19
/* An octant splits while its edge exceeds OCT_SPLIT times the size at its
 * centre: 2^(2/3), so that a leaf's volume per point, e^3 with e in
 * (OCT_SPLIT h / 2, OCT_SPLIT h], matches the lattice's at the same size h
 * (a^3 / 2 with a in [h, 2 h)). */
#define OCT_SPLIT 1.5874010519681994

typedef struct oct_tree {
    cvm__ctx *ctx;
    uint64_t *key;  /* per node: level << 57 | i << 38 | j << 19 | k */
    uint8_t *leaf;  /* per node: 1 while a leaf; 2: a leaf within its dm of the surface */
    double *hs;     /* per node: the size at its centre (after build_tree) */
    size_t n, cap, limit;
    uint32_t *slot; /* node + 1, 0 empty; capacity a power of two */
    size_t scap;
} oct_tree;

static uint64_t oct_key(int lv, uint64_t i, uint64_t j, uint64_t k)
{
    return (uint64_t)lv << (3 * OCT_AXIS_BITS) | i << (2 * OCT_AXIS_BITS) | j << OCT_AXIS_BITS | k;
}

static void oct_unkey(uint64_t key, int *lv, uint64_t *ijk)
{
    uint64_t m = ((uint64_t)1 << OCT_AXIS_BITS) - 1;
    *lv = (int)(key >> (3 * OCT_AXIS_BITS));
    ijk[0] = key >> (2 * OCT_AXIS_BITS) & m;
    ijk[1] = key >> OCT_AXIS_BITS & m;
    ijk[2] = key & m;
}

static size_t oct_hash(uint64_t key, size_t cap)
{
    key ^= key >> 31;
    key *= UINT64_C(0xbf58476d1ce4e5b9);
    key ^= key >> 27;
    return (size_t)key & (cap - 1);
}

/* The node of key, or -1. */
static long oct_find(const oct_tree *T, uint64_t key)
{
    size_t h = oct_hash(key, T->scap);
    while (T->slot[h]) {
        if (T->key[T->slot[h] - 1] == key)
            return (long)T->slot[h] - 1;
        h = (h + 1) & (T->scap - 1);
    }
    return -1;
}

static void oct_place(uint32_t *slot, size_t scap, uint64_t key, uint32_t v)
{
    size_t h = oct_hash(key, scap);
    while (slot[h])
        h = (h + 1) & (scap - 1);
    slot[h] = v;
}

/* Append a leaf of key. */
static cvm_status oct_add(oct_tree *T, uint64_t key)
{
    if (T->n >= T->limit)
        return cvm__error(T->ctx, CVM_E_TOO_LARGE, CVM_ENT_NONE, -1,
                          "the octree passes the 3D limit of %lu points: use a larger size or "
                          "grading", (unsigned long)T->limit);
    if (T->n == T->cap) {
        size_t cap = T->cap ? 2 * T->cap : 1024;
        uint64_t *k = cvm__realloc(T->ctx, T->key, cap * sizeof *k);
        uint8_t *l;
        double *k2;
        if (!k)
            return cvm__nomem(T->ctx);
        T->key = k;
        if (!(l = cvm__realloc(T->ctx, T->leaf, cap)))
            return cvm__nomem(T->ctx);
        T->leaf = l;
        T->cap = cap;
        if (!(k2 = cvm__realloc(T->ctx, T->hs, cap * sizeof *k2)))
            return cvm__nomem(T->ctx);
        T->hs = k2;
    }
    if (2 * (T->n + 1) > T->scap) {
        size_t scap = T->scap ? 2 * T->scap : 2048, i;
        uint32_t *s = cvm__calloc(T->ctx, scap, sizeof *s);
        if (!s)
            return cvm__nomem(T->ctx);
        for (i = 0; i < T->n; i++)
            oct_place(s, scap, T->key[i], (uint32_t)(i + 1));
        cvm__free(T->ctx, T->slot);
        T->slot = s;
        T->scap = scap;
    }
    T->key[T->n] = key;
    T->leaf[T->n] = 1;
    T->hs[T->n] = 0;
    oct_place(T->slot, T->scap, key, (uint32_t)(T->n + 1));
    T->n++;
    return CVM_OK;
}

/* Split leaf v into its eight children (x fastest). */
static cvm_status oct_split(oct_tree *T, size_t v)
{
    uint64_t ijk[3];
    int lv, c;
    cvm_status st = CVM_OK;
    oct_unkey(T->key[v], &lv, ijk);
    T->leaf[v] = 0;
    for (c = 0; c < 8 && !st; c++)
        st = oct_add(T, oct_key(lv + 1, 2 * ijk[0] + (c & 1), 2 * ijk[1] + (c >> 1 & 1),
                                2 * ijk[2] + (c >> 2 & 1)));
    return st;
}

typedef struct oct_run {
    cvm__ctx *ctx;
    const cvm__g3_size *z;
    const cvm__g3_surface *s;
    double lo[3], edge; /* root cube */
} oct_run;

static void centre_of(const oct_run *R, int lv, const uint64_t *ijk, double *x)
{
    double e = ldexp(R->edge, -lv);
    int ax;
    for (ax = 0; ax < 3; ax++)
        x[ax] = R->lo[ax] + e * ((double)ijk[ax] + 0.5);
}

/* Make the leaves next to leaf v (across its faces, or every face, edge and
 * corner with balance 26) at most one level coarser than v. */
static cvm_status balance_leaf(oct_tree *T, size_t v, int balance)
{
    uint64_t ijk[3];
    int lv, d;
    oct_unkey(T->key[v], &lv, ijk);
    if (lv < 2)
        return CVM_OK;
    for (d = 0; d < 27; d++) {
        int64_t o[3] = {d % 3 - 1, d / 3 % 3 - 1, d / 9 - 1}, q[3];
        int ax, nz = 0, l;
        long w = -1;
        for (ax = 0; ax < 3; ax++) {
            q[ax] = (int64_t)ijk[ax] + o[ax];
            nz += o[ax] != 0;
        }
        if (nz == 0 || (balance == 6 && nz != 1))
            continue;
        for (ax = 0; ax < 3; ax++)
            if (q[ax] < 0 || q[ax] >= (int64_t)1 << lv)
                break;
        if (ax < 3)
            continue;
        /* the deepest existing node at level lv - 1 or above over q */
        for (l = lv - 1; l >= 0 && w < 0; l--)
            w = oct_find(T, oct_key(l, (uint64_t)q[0] >> (lv - l), (uint64_t)q[1] >> (lv - l),
                                    (uint64_t)q[2] >> (lv - l)));
        /* l + 1 is w's level; split down to lv - 1 */
        for (l = l + 1; l < lv - 1; l++) {
            cvm_status st = oct_split(T, (size_t)w);
            if (st)
                return st;
            w = oct_find(T, oct_key(l + 1, (uint64_t)q[0] >> (lv - l - 1),
                                    (uint64_t)q[1] >> (lv - l - 1), (uint64_t)q[2] >> (lv - l - 1)));
        }
    }
    return CVM_OK;
}

/* Balance every leaf, the finest first, so that one sweep per level suffices. */
static cvm_status balance_all(oct_tree *T, int balance, int maxlv)
{
    size_t v;
    int lv;
    cvm_status st = CVM_OK;
    for (lv = maxlv; lv >= 2 && !st; lv--)
        for (v = 0; v < T->n && !st; v++)
            if (T->leaf[v] && (int)(T->key[v] >> (3 * OCT_AXIS_BITS)) == lv)
                st = balance_leaf(T, v, balance);
    return st;
}

/* 1 when the octant of node v has a split octant of its own level across a
 * face: finer leaves, whose corners hang on v's face. */
static int hanging_face(const oct_tree *T, size_t v)
{
    uint64_t ijk[3];
    int lv, d;
    oct_unkey(T->key[v], &lv, ijk);
    for (d = 0; d < 6; d++) {
        int64_t q[3] = {(int64_t)ijk[0], (int64_t)ijk[1], (int64_t)ijk[2]};
        long w;
        q[d >> 1] += (d & 1) ? 1 : -1;
        if (q[d >> 1] < 0 || q[d >> 1] >= (int64_t)1 << lv)
            continue;
        w = oct_find(T, oct_key(lv, (uint64_t)q[0], (uint64_t)q[1], (uint64_t)q[2]));
        if (w >= 0 && !T->leaf[w])
            return 1;
    }
    return 0;
}

/* Mark (leaf 2) the leaves whose centroid lies within its dm of triangle f:
 * down the tree through the nodes whose cube, grown by 0.55 of its edge (no
 * leaf below has a larger dm), meets the triangle's bounding box. */
static cvm_status mark_near(oct_tree *T, const oct_run *R, size_t f)
{
    const int32_t *t = R->s->tri + 3 * f;
    const double *a = R->s->xyz + 3 * t[0], *b = R->s->xyz + 3 * t[1], *c = R->s->xyz + 3 * t[2];
    double blo[3], bhi[3];
    size_t stack[8 * (OCT_MAX_LEVEL + 1)], top = 0;
    int ax;
    for (ax = 0; ax < 3; ax++) {
        blo[ax] = a[ax] < b[ax] ? a[ax] : b[ax];
        blo[ax] = c[ax] < blo[ax] ? c[ax] : blo[ax];
        bhi[ax] = a[ax] > b[ax] ? a[ax] : b[ax];
        bhi[ax] = c[ax] > bhi[ax] ? c[ax] : bhi[ax];
    }
    stack[top++] = 0;
    while (top > 0) {
        size_t v = stack[--top];
        uint64_t ijk[3];
        double e, g, x[3];
        int lv, ch;
        oct_unkey(T->key[v], &lv, ijk);
        e = ldexp(R->edge, -lv);
        g = cvm__g3_lattice_dm(e);
        for (ax = 0; ax < 3; ax++) {
            double lo = R->lo[ax] + e * (double)ijk[ax];
            if (lo - g > bhi[ax] || lo + e + g < blo[ax])
                break;
        }
        if (ax < 3)
            continue;
        if (T->leaf[v]) {
            double dm = cvm__g3_lattice_dm(T->hs[v] < e ? T->hs[v] : e);
            centre_of(R, lv, ijk, x);
            if (cvm__g3_tri_dist2(x, a, b, c) < dm * dm)
                T->leaf[v] = 2;
            continue;
        }
        for (ch = 0; ch < 8; ch++) {
            long w = oct_find(T, oct_key(lv + 1, 2 * ijk[0] + (uint64_t)(ch & 1),
                                         2 * ijk[1] + (uint64_t)(ch >> 1 & 1),
                                         2 * ijk[2] + (uint64_t)(ch >> 2 & 1)));
            if (w < 0)
                return cvm__error(T->ctx, CVM_E_INTERNAL, CVM_ENT_NONE, -1,
                                  "octree node %lu has a missing child", (unsigned long)v);
            stack[top++] = (size_t)w;
        }
    }
    return CVM_OK;
}

/* 1 when the octant (lv, ijk) meets one of the nb finite boxes of box. */
static int meets_box(const oct_run *R, int lv, const uint64_t *ijk, const double *box, size_t nb)
{
    double e = ldexp(R->edge, -lv);
    size_t q;
    int ax;
    for (q = 0; q < nb; q++) {
        const double *b = box + 6 * q;
        for (ax = 0; ax < 3; ax++) {
            double lo = R->lo[ax] + e * (double)ijk[ax];
            if (!(b[ax] > -HUGE_VAL && b[3 + ax] < HUGE_VAL) || lo > b[3 + ax] || lo + e < b[ax])
                break;
        }
        if (ax == 3)
            return 1;
    }
    return 0;
}

/* Refine by the size, then balance. An octant splits while its edge e exceeds
 * OCT_SPLIT times the size at its centre or, with a user sizing, while it
 * meets a bounded box where a point, line or triangle source can reach
 * e / OCT_SPLIT (cvm__sizing_boxes3(): a source inside an octant whose centre
 * it does not reach is still met; a background mesh and a callback are read at
 * the centres only). Nodes come in level order, so the boxes are made once
 * per level. */
static cvm_status build_tree(oct_tree *T, const oct_run *R, int balance, int split_hanging,
                             int maxlv)
{
    const cvm_sizing *u = cvm__g3_size_user(R->z);
    double *box = NULL;
    size_t v, nb = 0;
    int lv, boxes_lv = -1;
    cvm_status st = oct_add(T, oct_key(0, 0, 0, 0));
    if (u && !st && !(box = cvm__malloc(T->ctx, 6 * CVM__SIZING_MAX_BOXES3(u) * sizeof *box)))
        st = cvm__nomem(T->ctx);
    for (v = 0; v < T->n && !st; v++) {
        uint64_t ijk[3];
        double x[3], hs, e;
        oct_unkey(T->key[v], &lv, ijk);
        e = ldexp(R->edge, -lv);
        centre_of(R, lv, ijk, x);
        if (cvm__g3_size_at(R->z, x, &hs)) {
            cvm__free(T->ctx, box);
            return R->ctx->status;
        }
        T->hs[v] = hs;
        if (lv >= maxlv)
            continue;
        if (box && boxes_lv != lv) {
            nb = cvm__sizing_boxes3(u, e / OCT_SPLIT, box);
            /* the last is a background mesh's whole box once its least size is met:
             * that would refine all of it to its least size (read at centres instead) */
            if (nb > 0 && u->bg3 && cvm__background3_min(u->bg3) <= e / OCT_SPLIT)
                nb--;
            boxes_lv = lv;
        }
        if (e > OCT_SPLIT * hs || (box && meets_box(R, lv, ijk, box, nb)))
            st = oct_split(T, v);
    }
    cvm__free(T->ctx, box);
    if (!st)
        st = balance_all(T, balance, maxlv);
    if (split_hanging && !st) {
        /* the leaves with a finer neighbour across a face, all found first (so
         * that a split does not cascade), split once; then balanced again */
        size_t n0 = T->n;
        uint8_t *hang = cvm__calloc(T->ctx, n0 + 1, 1);
        if (!hang)
            return cvm__nomem(T->ctx);
        for (v = 0; v < n0; v++)
            hang[v] = T->leaf[v] && hanging_face(T, v);
        for (v = 0; v < n0 && !st; v++)
            if (hang[v])
                st = oct_split(T, v);
        cvm__free(T->ctx, hang);
        if (!st)
            st = balance_all(T, balance, maxlv);
    }
    /* the sizes of the nodes the balance made */
    for (v = 0; v < T->n && !st; v++) {
        uint64_t ijk[3];
        double x[3];
        if (T->hs[v] > 0)
            continue;
        oct_unkey(T->key[v], &lv, ijk);
        centre_of(R, lv, ijk, x);
        if (cvm__g3_size_at(R->z, x, T->hs + v))
            return R->ctx->status;
    }
    return st;
}

/* The candidates of the leaves of level lv. */
static cvm_status place_level(const oct_tree *T, const oct_run *R, int lv,
                              const cvm__g3_inside *in, cvm__g3_points *P, cvm__g3_report *rep)
{
    cvm__g3_grid *grid = NULL;
    double e = ldexp(R->edge, -lv);
    size_t v;
    cvm_status st = cvm__g3_grid_create(&grid, R->ctx, cvm__g3_lattice_dm(e));
    for (v = 0; v < P->n && !st; v++)
        st = cvm__g3_grid_add(grid, P->xyz, (int32_t)v);
    for (v = 0; v < T->n && !st; v++) {
        uint64_t ijk[3];
        double x[3], hs, dm;
        int l;
        if (T->leaf[v] != 1)
            continue;
        oct_unkey(T->key[v], &l, ijk);
        if (l != lv)
            continue;
        centre_of(R, lv, ijk, x);
        hs = T->hs[v];
        dm = cvm__g3_lattice_dm(hs < e ? hs : e);
        if (cvm__g3_grid_near(grid, P->xyz, x, dm) || !cvm__g3_is_inside(in, x))
            continue;
        if (P->n >= CVM__T3_MAX_POINTS) {
            st = cvm__error(R->ctx, CVM_E_TOO_LARGE, CVM_ENT_NONE, -1,
                            "the octree passes the 3D limit of %lu points: use a larger size "
                            "or grading", (unsigned long)CVM__T3_MAX_POINTS);
            break;
        }
        if ((st = cvm__g3_points_push(R->ctx, P, x, dm)))
            break;
        rep->octree_points++;
        st = cvm__g3_grid_add(grid, P->xyz, (int32_t)(P->n - 1));
    }
    cvm__g3_grid_free(grid);
    return st == CVM_E_NOMEM ? cvm__nomem(R->ctx) : st;
}

cvm_status cvm__g3_octree(cvm__ctx *ctx, const cvm__g3_surface *s, const cvm__g3_size *z,
                          double h, int balance, int split_hanging, const cvm__g3_inside *in,
                          cvm__g3_points *P, cvm__g3_report *rep)
{
    oct_tree T;
    oct_run R;
    double hi[3], cells;
    size_t v;
    int ax, lv, maxlv = 0;
    cvm_status st = CVM_OK;
    if (s->np == 0 || s->nt == 0)
        return CVM_OK;
    memset(&T, 0, sizeof T);
    T.ctx = ctx;
    R.ctx = ctx;
    R.z = z;
    R.s = s;
    R.edge = 0;
    for (ax = 0; ax < 3; ax++)
        R.lo[ax] = hi[ax] = s->xyz[ax];
    for (v = 0; v < s->np; v++)
        for (ax = 0; ax < 3; ax++) {
            double c = s->xyz[3 * v + ax];
            R.lo[ax] = c < R.lo[ax] ? c : R.lo[ax];
            hi[ax] = c > hi[ax] ? c : hi[ax];
        }
    for (ax = 0; ax < 3; ax++)
        R.edge = hi[ax] - R.lo[ax] > R.edge ? hi[ax] - R.lo[ax] : R.edge;
    if (!(R.edge > 0))
        return CVM_OK;
    /* the size never exceeds h, so a leaf's edge is at most OCT_SPLIT h, and the
     * leaves number at least (edge / (OCT_SPLIT h))^3 */
    cells = R.edge / (OCT_SPLIT * h);
    if (cells * cells * cells > (double)CVM__T3_MAX_POINTS)
        return cvm__error(ctx, CVM_E_TOO_LARGE, CVM_ENT_NONE, -1,
                          "size %.17g is too small for the surface's extent %.17g: its octree "
                          "has %.3g leaves or more, above the 3D limit of %lu points",
                          h, R.edge, cells * cells * cells, (unsigned long)CVM__T3_MAX_POINTS);
    {
        /* as deep as the smallest size asks (a callback: as deep as keys allow) */
        double lmin = cvm__g3_size_min(z);
        const cvm_sizing *u = cvm__g3_size_user(z);
        while (maxlv < OCT_MAX_LEVEL &&
               ((u && u->fn_nd) || ldexp(R.edge, -maxlv) > OCT_SPLIT * lmin))
            maxlv++;
    }
    T.limit = CVM__T3_MAX_POINTS;
    st = build_tree(&T, &R, balance, split_hanging, maxlv);
    for (v = 0; v < s->nt && !st; v++)
        st = mark_near(&T, &R, v);
    for (v = 0; v < T.n && !st; v++)
        rep->octree_leaves += T.leaf[v] != 0;
    for (lv = 0; lv <= maxlv && !st; lv++)
        st = place_level(&T, &R, lv, in, P, rep);
    cvm__free(ctx, T.key);
    cvm__free(ctx, T.leaf);
    cvm__free(ctx, T.hs);
    cvm__free(ctx, T.slot);
    return st;
}
