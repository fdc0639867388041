/*
 * g3_lattice.c - the free space: body-centred cubic lattices, one per level
 * k (cube edge a_k = h / 2^k: corners lo + a_k (i, j, k) and centres lo +
 * a_k (i + 1/2, j + 1/2, k + 1/2), lo the surface's bounding-box corner; edges
 * a_k and 0.866 a_k, every tetrahedron of the lattice with its circumcentre
 * inside). A candidate of level k is kept when its size falls in (a_k / 2,
 * a_k] (the finest level takes everything below), it lies farther than its
 * rejection distance dm from every point so far (surface, near field,
 * coarser levels), and it is strictly inside the domain (exact).
 *
 * Level 0 covers the bounding box; a finer level only the boxes around the
 * surface triangles where the size can reach a_k (l(f) + g d <= a_k), each
 * candidate visited once (a hash set of lattice indices).
 */
#include <math.h>
#include <string.h>

#include "delaunay3/delaunay3_internal.h"
#include "generate3/generate3.h"

#define MAX_LEVELS 24
#define AXIS_BITS 20
/* Rejection distance of a lattice point over its size. Half the near-field
 * offset of an equilateral triangle would be 0.5 x 1.1 / sqrt 3 = 0.32; 0.55
 * keeps fine-level points further from coarser ones and from the near field:
 * measured on the sphere in a box (size 0.5, grading 0.3), boundary
 * tetrahedra with their circumcentre outside 14.4 -> 5.7 %, smallest dihedral
 * 0.9 -> 5.0 degrees (0.45: 6.9 %, 0.9; 0.65: 5.7 %, 1.2). It stays below
 * the lattice's shortest edge, 0.866 a >= 0.866 size. Behind a re-meshed
 * surface (near-equilateral triangles, so a near field in one layer at 2/3
 * of the size) the lattice uses CVM__G3_DM_REMESHED instead (g3_params). */
#define G3_DM_FACTOR 0.55

double cvm__g3_lattice_dm(double hs)
{
    return G3_DM_FACTOR * hs;
}

typedef struct seen_set {
    uint64_t *key; /* 0: empty */
    size_t cap, used;
} seen_set;

static size_t slot_of(uint64_t key, size_t cap)
{
    key ^= key >> 33;
    key *= UINT64_C(0xff51afd7ed558ccd);
    key ^= key >> 33;
    return (size_t)key & (cap - 1);
}

/* 1: newly added; 0: seen before; -1: out of memory. */
static int seen_add(cvm__ctx *ctx, seen_set *S, uint64_t key)
{
    size_t h;
    if (2 * (S->used + 1) > S->cap) {
        size_t i, cap = S->cap ? 2 * S->cap : 4096;
        uint64_t *t = cvm__calloc(ctx, cap, sizeof *t);
        if (!t)
            return -1;
        for (i = 0; i < S->cap; i++)
            if (S->key[i]) {
                size_t g = slot_of(S->key[i], cap);
                while (t[g])
                    g = (g + 1) & (cap - 1);
                t[g] = S->key[i];
            }
        cvm__free(ctx, S->key);
        S->key = t;
        S->cap = cap;
    }
    h = slot_of(key, S->cap);
    while (S->key[h] && S->key[h] != key)
        h = (h + 1) & (S->cap - 1);
    if (S->key[h])
        return 0;
    S->key[h] = key;
    S->used++;
    return 1;
}

typedef struct lat_ctx {
    cvm__ctx *ctx;
    const cvm__g3_size *z;
    const cvm__g3_inside *in;
    cvm__g3_points *P;
    cvm__g3_grid *grid;
    double lo[3], a, h;
    double dmf;     /* rejection distance over size */
    int level, last;
    int small;      /* a candidate's size fell below this level's range */
    size_t kept;
} lat_ctx;

/* Candidate (i, j, k) of sublattice sub (0 corners, 1 centres). */
static cvm_status candidate(lat_ctx *L, int64_t i, int64_t j, int64_t k, int sub)
{
    double x[3], hs, dm, off = sub ? 0.5 : 0.0;
    x[0] = L->lo[0] + L->a * ((double)i + off);
    x[1] = L->lo[1] + L->a * ((double)j + off);
    x[2] = L->lo[2] + L->a * ((double)k + off);
    if (cvm__g3_size_at(L->z, x, &hs))
        return L->ctx->status;
    if (!(hs <= L->a))
        return CVM_OK;
    if (!L->last && hs <= 0.5 * L->a) {
        L->small = 1;
        return CVM_OK;
    }
    dm = L->dmf * hs;
    if (cvm__g3_grid_near(L->grid, L->P->xyz, x, dm) || !cvm__g3_is_inside(L->in, x))
        return CVM_OK;
    if (L->P->n >= CVM__T3_MAX_POINTS)
        return cvm__error(L->ctx, CVM_E_TOO_LARGE, CVM_ENT_NONE, -1,
                          "the lattice passes the 3D limit of %lu points: use a larger size or "
                          "grading", (unsigned long)CVM__T3_MAX_POINTS);
    L->kept++;
    if (cvm__g3_points_push(L->ctx, L->P, x, dm))
        return CVM_E_NOMEM;
    return cvm__g3_grid_add(L->grid, L->P->xyz, (int32_t)(L->P->n - 1));
}

/* The lattice index box of level L around triangle f where the size can
 * reach L->a (l(f) + g d <= a_k, plus a cell); 0 when l(f) > a_k. */
static int face_box(const cvm__g3_surface *s, size_t f, const lat_ctx *L, const int64_t *n,
                    int64_t *b0, int64_t *b1)
{
    const int32_t *t = s->tri + 3 * f;
    double c[3], l = 0, r;
    int ax, q;
    for (ax = 0; ax < 3; ax++)
        c[ax] = (s->xyz[3 * t[0] + ax] + s->xyz[3 * t[1] + ax] + s->xyz[3 * t[2] + ax]) / 3;
    for (q = 0; q < 3; q++) {
        const double *p0 = s->xyz + 3 * t[q], *p1 = s->xyz + 3 * t[(q + 1) % 3];
        l += sqrt((p0[0] - p1[0]) * (p0[0] - p1[0]) + (p0[1] - p1[1]) * (p0[1] - p1[1]) +
                  (p0[2] - p1[2]) * (p0[2] - p1[2])) / 3;
    }
    if (l > L->a)
        return 0;
    r = (L->a - l) / cvm__g3_size_grading(L->z) + L->a;
    for (ax = 0; ax < 3; ax++) {
        double lo = floor((c[ax] - r - L->lo[ax]) / L->a) - 1,
               up = ceil((c[ax] + r - L->lo[ax]) / L->a) + 1;
        b0[ax] = lo < 0 ? 0 : (int64_t)lo;
        b1[ax] = up > (double)n[ax] ? n[ax] : (int64_t)up;
    }
    return 1;
}

/* The lattice index boxes of level L (6 per box, b0 then b1) where the size
 * can reach L->a: one per surface triangle (when the size follows the
 * surface), then the user sizing's boxes; their count. bx holds room for
 * s->nt + CVM__SIZING_MAX_BOXES3 boxes. */
static size_t level_boxes(const cvm__g3_surface *s, const lat_ctx *L, const int64_t *n,
                          int64_t *bx, double *ubox)
{
    const cvm_sizing *u = cvm__g3_size_user(L->z);
    size_t f, nb = 0, nu, q;
    int ax;
    if (cvm__g3_size_follows(L->z))
        for (f = 0; f < s->nt; f++)
            if (face_box(s, f, L, n, bx + 6 * nb, bx + 6 * nb + 3))
                nb++;
    if (!u)
        return nb;
    nu = cvm__sizing_boxes3(u, L->a, ubox);
    for (q = 0; q < nu; q++) {
        int64_t *b0 = bx + 6 * nb, *b1 = b0 + 3;
        int empty = 0;
        for (ax = 0; ax < 3; ax++) {
            double lo = floor((ubox[6 * q + ax] - L->lo[ax]) / L->a) - 1,
                   up = ceil((ubox[6 * q + 3 + ax] - L->lo[ax]) / L->a) + 1;
            if (lo > (double)n[ax] || up < 0) {
                empty = 1;
                break;
            }
            b0[ax] = lo < 0 ? 0 : (int64_t)lo;
            b1[ax] = up > (double)n[ax] ? n[ax] : (int64_t)up;
        }
        nb += !empty;
    }
    return nb;
}

static uint64_t lattice_key(int64_t i, int64_t j, int64_t k, int sub)
{
    uint64_t m = ((uint64_t)1 << AXIS_BITS) - 1;
    return (((uint64_t)i & m) << (2 * AXIS_BITS + 1) | ((uint64_t)j & m) << (AXIS_BITS + 1) |
            ((uint64_t)k & m) << 1 | (uint64_t)sub) + 1;
}

cvm_status cvm__g3_lattice(cvm__ctx *ctx, const cvm__g3_surface *s, const cvm__g3_size *z,
                           double h, double dmf, const cvm__g3_inside *in, cvm__g3_points *P,
                           cvm__g3_report *rep)
{
    lat_ctx L;
    seen_set S = {NULL, 0, 0};
    double hi[3], ext = 0, lmin = cvm__g3_size_min(z), *ubox = NULL;
    int levels = 1, lv, ax, open_ended = 0;
    int64_t *bx = NULL;
    const cvm_sizing *user = cvm__g3_size_user(z);
    size_t f;
    cvm_status st = CVM_OK;
    L.ctx = ctx;
    L.z = z;
    L.in = in;
    L.P = P;
    L.grid = NULL;
    L.h = h;
    L.dmf = dmf > 0 ? dmf : G3_DM_FACTOR;
    if (s->np == 0 || s->nt == 0)
        return CVM_OK;
    for (ax = 0; ax < 3; ax++)
        L.lo[ax] = hi[ax] = s->xyz[ax];
    for (f = 0; f < s->np; f++)
        for (ax = 0; ax < 3; ax++) {
            double v = s->xyz[3 * f + ax];
            L.lo[ax] = v < L.lo[ax] ? v : L.lo[ax];
            hi[ax] = v > hi[ax] ? v : hi[ax];
        }
    for (ax = 0; ax < 3; ax++)
        ext = hi[ax] - L.lo[ax] > ext ? hi[ax] - L.lo[ax] : ext;
    /* levels h, h/2, ... until a level holds the smallest size; the indices of
     * every level fit AXIS_BITS */
    while (levels < MAX_LEVELS && lmin <= ldexp(h, -levels) &&
           ext / ldexp(h, -levels) < (double)((int64_t)1 << (AXIS_BITS - 1)))
        levels++;
    if (user) {
        /* a callback has no known least size: levels go on while one meets
         * sizes below its range, within the same limits */
        int most = levels;
        open_ended = user->fn_nd != NULL;
        while (open_ended && most < MAX_LEVELS &&
               ext / ldexp(h, -most) < (double)((int64_t)1 << (AXIS_BITS - 1)))
            most++;
        bx = cvm__malloc(ctx, 6 * (s->nt + CVM__SIZING_MAX_BOXES3(user)) * sizeof *bx);
        ubox = cvm__malloc(ctx, 6 * CVM__SIZING_MAX_BOXES3(user) * sizeof *ubox);
        if (!bx || !ubox) {
            cvm__free(ctx, bx);
            cvm__free(ctx, ubox);
            return cvm__nomem(ctx);
        }
        if (open_ended) {
            open_ended = levels; /* the levels the sources alone ask for */
            levels = most;
        }
    }
    if (ext / h >= (double)((int64_t)1 << (AXIS_BITS - 1)))
        return cvm__error(ctx, CVM_E_TOO_LARGE, CVM_ENT_NONE, -1,
                          "size %.17g is too small for the surface's extent %.17g (more than "
                          "2^%d lattice cells along an axis)",
                          h, ext, AXIS_BITS - 1);
    {
        /* the coarsest level alone visits 2 (extent / h)^3 candidates */
        double cand = 2;
        for (ax = 0; ax < 3; ax++)
            cand *= (hi[ax] - L.lo[ax]) / h + 1;
        if (cand > 4.0 * (double)CVM__T3_MAX_POINTS)
            return cvm__error(ctx, CVM_E_TOO_LARGE, CVM_ENT_NONE, -1,
                              "size %.17g is too small for the surface's bounding box: its "
                              "lattice has %.3g candidate points, above the 3D limit of %lu "
                              "points",
                              h, cand, (unsigned long)CVM__T3_MAX_POINTS);
    }
    for (lv = 0; lv < levels && !st; lv++) {
        int64_t n[3], i, j, k;
        int sub;
        L.a = ldexp(h, -lv);
        L.level = lv;
        L.last = lv == levels - 1;
        L.kept = 0;
        L.small = 0;
        if ((st = cvm__g3_grid_create(&L.grid, ctx, L.dmf * L.a)))
            break;
        for (f = 0; f < P->n && !st; f++)
            st = cvm__g3_grid_add(L.grid, P->xyz, (int32_t)f);
        for (ax = 0; ax < 3; ax++)
            n[ax] = (int64_t)ceil((hi[ax] - L.lo[ax]) / L.a);
        if (lv == 0) {
            for (k = 0; k <= n[2] && !st; k++)
                for (j = 0; j <= n[1] && !st; j++)
                    for (i = 0; i <= n[0] && !st; i++)
                        for (sub = 0; sub < 2 && !st; sub++)
                            if (!sub || (i < n[0] && j < n[1] && k < n[2]))
                                st = candidate(&L, i, j, k, sub);
        } else {
            /* only where some triangle can bring the size down to a_k: the union
             * of the triangles' boxes when it holds fewer candidates than the
             * boxes together, else box by box, each candidate once */
            int64_t u0[3] = {n[0], n[1], n[2]}, u1[3] = {0, 0, 0}, b0[3], b1[3];
            double sum = 0, uni = 1;
            size_t nb = 0, q;
            if (user)
                nb = level_boxes(s, &L, n, bx, ubox);
            for (q = 0, f = 0; user ? q < nb : f < s->nt; q++, f++) {
                const int64_t *c0 = b0, *c1 = b1;
                double c = 1;
                if (user) {
                    c0 = bx + 6 * q;
                    c1 = c0 + 3;
                } else if (!face_box(s, f, &L, n, b0, b1))
                    continue;
                for (ax = 0; ax < 3; ax++) {
                    c *= (double)(c1[ax] - c0[ax] + 1);
                    u0[ax] = c0[ax] < u0[ax] ? c0[ax] : u0[ax];
                    u1[ax] = c1[ax] > u1[ax] ? c1[ax] : u1[ax];
                }
                sum += c;
            }
            for (ax = 0; ax < 3; ax++)
                uni *= u1[ax] >= u0[ax] ? (double)(u1[ax] - u0[ax] + 1) : 0;
            if (user && 2 * (uni < sum ? uni : sum) > 4.0 * (double)CVM__T3_MAX_POINTS) {
                st = cvm__error(ctx, CVM_E_TOO_LARGE, CVM_ENT_NONE, -1,
                                "lattice level %d (cube edge %.17g) has %.3g candidate points "
                                "where the sizing reaches its size, above the 3D limit of %lu "
                                "points: use larger sizes or growths",
                                lv, L.a, 2 * (uni < sum ? uni : sum),
                                (unsigned long)CVM__T3_MAX_POINTS);
            } else if (uni <= sum) {
                for (k = u0[2]; k <= u1[2] && !st; k++)
                    for (j = u0[1]; j <= u1[1] && !st; j++)
                        for (i = u0[0]; i <= u1[0] && !st; i++)
                            for (sub = 0; sub < 2 && !st; sub++)
                                if (!sub || (i < n[0] && j < n[1] && k < n[2]))
                                    st = candidate(&L, i, j, k, sub);
            } else {
                S.used = 0;
                if (S.key)
                    memset(S.key, 0, S.cap * sizeof *S.key);
                for (q = 0, f = 0; (user ? q < nb : f < s->nt) && !st; q++, f++) {
                    const int64_t *c0 = b0, *c1 = b1;
                    if (user) {
                        c0 = bx + 6 * q;
                        c1 = c0 + 3;
                    } else if (!face_box(s, f, &L, n, b0, b1))
                        continue;
                    for (k = c0[2]; k <= c1[2] && !st; k++)
                        for (j = c0[1]; j <= c1[1] && !st; j++)
                            for (i = c0[0]; i <= c1[0] && !st; i++)
                                for (sub = 0; sub < 2 && !st; sub++) {
                                    int r2;
                                    if (sub && (i >= n[0] || j >= n[1] || k >= n[2]))
                                        continue;
                                    r2 = seen_add(ctx, &S, lattice_key(i, j, k, sub));
                                    if (r2 < 0)
                                        st = cvm__nomem(ctx);
                                    else if (r2)
                                        st = candidate(&L, i, j, k, sub);
                                }
                }
            }
        }
        if (st == CVM_E_NOMEM)
            st = cvm__nomem(ctx);
        cvm__g3_grid_free(L.grid);
        L.grid = NULL;
        rep->lattice_points += L.kept;
        rep->lattice_levels += L.kept > 0;
        if (open_ended && lv + 1 >= open_ended && !L.small)
            break; /* no finer size met, and the sources ask for no more levels */
    }
    cvm__free(ctx, S.key);
    cvm__free(ctx, bx);
    cvm__free(ctx, ubox);
    return st;
}
