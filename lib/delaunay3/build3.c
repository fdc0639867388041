/* build3.c - tetrahedralisation of a whole point set: input checks, insertion order, first tetrahedron, insertion loop, report of merged and redundant points. */
#include <math.h>
#include <string.h>

#include "delaunay3/delaunay3_internal.h"
#include "geom/geom_internal.h"

#define PT(T, v) ((T)->pt[v].x)

#if defined(__GNUC__)
#define B3_PREFETCH(p) __builtin_prefetch(p)
#else
#define B3_PREFETCH(p) ((void)(p))
#endif

/* Finite input, within the range where the predicates' exact stages cannot
 * underflow (lib/geom/geom_internal.h): every nonzero coordinate (and square
 * root of a weight) at least 2^-100 times the largest. */
static cvm_status check_input(cvm__tet3 *T, const double *xyz, const double *w, size_t n)
{
    double big = 0.0, tiny;
    size_t i;
    int k;
    for (i = 0; i < n; i++) {
        const double *p = xyz + 3 * i;
        if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(p[2]))
            return cvm__error(T->ctx, CVM_E_INPUT_NONFINITE, CVM_ENT_INPUT_POINT, (int64_t)i,
                              "point %zu has a non-finite coordinate (%g, %g, %g)", i, p[0], p[1],
                              p[2]);
        if (w && !isfinite(w[i]))
            return cvm__error(T->ctx, CVM_E_INPUT_NONFINITE, CVM_ENT_INPUT_POINT, (int64_t)i,
                              "point %zu has a non-finite weight %g", i, w[i]);
        for (k = 0; k < 3; k++)
            big = fabs(p[k]) > big ? fabs(p[k]) : big;
        if (w && sqrt(fabs(w[i])) > big)
            big = sqrt(fabs(w[i]));
    }
    tiny = ldexp(big, -100);
    for (i = 0; i < n; i++) {
        const double *p = xyz + 3 * i;
        for (k = 0; k < 4; k++) {
            double c = k < 3 ? fabs(p[k]) : w ? sqrt(fabs(w[i])) : 0.0;
            if (c != 0.0 && c < tiny)
                return cvm__error(T->ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_INPUT_POINT,
                                  (int64_t)i,
                                  "point %zu has a %s of magnitude %g, more than 2^100 below the "
                                  "largest magnitude %g: outside the range of exact arithmetic",
                                  i, k < 3 ? "coordinate" : "weight root", c, big);
        }
    }
    return CVM_OK;
}

static int same_xyz(const double *a, const double *b)
{
    return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

/* Exactly collinear: all three coordinate-plane projections have orient2d 0. */
static int collinear(const double *a, const double *b, const double *c)
{
    int k;
    for (k = 0; k < 3; k++) {
        int i = k, j = (k + 1) % 3;
        double pa[2], pb[2], pc[2];
        pa[0] = a[i], pa[1] = a[j], pb[0] = b[i], pb[1] = b[j], pc[0] = c[i], pc[1] = c[j];
        if (cvm__orient2d(pa, pb, pc) != 0.0)
            return 0;
    }
    return 1;
}

/* The first four affinely independent points in insertion order, or an
 * error naming what the input spans. */
static cvm_status find_first(cvm__tet3 *T, int32_t *f)
{
    size_t n = T->np, i;
    f[0] = 0;
    for (i = 1; i < n && same_xyz(PT(T, 0), PT(T, i)); i++)
        ;
    if (i == n)
        return cvm__error(T->ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_INPUT_POINT, T->orig[0],
                          "all %zu points are the same point as point %d: a 3D triangulation "
                          "needs 4 points not in one plane", n, (int)T->orig[0]);
    f[1] = (int32_t)i;
    for (i = 1; i < n && collinear(PT(T, 0), PT(T, f[1]), PT(T, i)); i++)
        ;
    if (i == n)
        return cvm__error(T->ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_INPUT_POINT, T->orig[f[1]],
                          "all %zu points lie on the line through points %d and %d: a 3D "
                          "triangulation needs 4 points not in one plane",
                          n, (int)T->orig[0], (int)T->orig[f[1]]);
    f[2] = (int32_t)i;
    for (i = 1; i < n && cvm__orient3d(PT(T, 0), PT(T, f[1]), PT(T, f[2]), PT(T, i)) == 0.0; i++)
        ;
    if (i == n)
        return cvm__error(T->ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_INPUT_POINT, T->orig[f[2]],
                          "all %zu points lie in the plane through points %d, %d and %d: a 3D "
                          "triangulation needs 4 points not in one plane",
                          n, (int)T->orig[0], (int)T->orig[f[1]], (int)T->orig[f[2]]);
    f[3] = (int32_t)i;
    return CVM_OK;
}

/* The first tetrahedron, positively oriented, and the four ghosts on its faces. */
static cvm_status make_first(cvm__tet3 *T, int32_t *f)
{
    int32_t t0, k;
    cvm_status s;
    if (cvm__orient3d(PT(T, f[0]), PT(T, f[1]), PT(T, f[2]), PT(T, f[3])) < 0.0) {
        int32_t x = f[0];
        f[0] = f[1], f[1] = x;
    }
    s = cvm__tet3_reserve(T, 5);
    if (s == CVM_OK)
        s = cvm__grow(T->ctx, (void **)&T->bf, &T->bfcap, 4, sizeof *T->bf);
    if (s == CVM_OK)
        s = cvm__tet3_reserve_hash(T, 4);
    if (s != CVM_OK)
        return s;
    t0 = cvm__tet3_take_slot(T);
    memcpy(T->tt + 8 * (size_t)t0, f, 4 * sizeof *f);
    T->nbf = 4;
    for (k = 0; k < 4; k++) {
        cvm__t3_bface *b = &T->bf[k];
        int32_t g = cvm__tet3_take_slot(T), j, m = 0;
        for (j = 0; j < 4; j++)
            if (j != k)
                b->v[m++] = f[j];
        /* the hull face sees the inside point f[k] on its negative side */
        if (cvm__orient3d(PT(T, b->v[0]), PT(T, b->v[1]), PT(T, b->v[2]), PT(T, f[k])) > 0.0) {
            int32_t x = b->v[0];
            b->v[0] = b->v[1], b->v[1] = x;
        }
        b->v[3] = CVM__T3_GHOST;
        b->f = 3;
        b->tet = g;
        memcpy(T->tt + 8 * (size_t)g, b->v, 4 * sizeof *f);
        CVM__T3_TN(T, 4 * (size_t)g + 3) = 4 * t0 + k;
        CVM__T3_TN(T, 4 * (size_t)t0 + k) = 4 * g + 3;
    }
    cvm__tet3_link_around(T);
    T->nbf = 0;
    T->last = t0;
    for (k = 0; k < 4; k++) {
        T->fate[f[k]] = CVM__T3_VERTEX;
        if (T->vtet)
            T->vtet[f[k]] = t0;
    }
    return CVM_OK;
}

/* Output names (lowest input index of each merged group) and the report. */
static void finish(cvm__tet3 *T)
{
    size_t i;
    for (i = 0; i < T->np; i++) /* weighted: a vertex that vanished takes its duplicates along */
        if (T->fate[i] == CVM__T3_DUPLICATE && T->fate[T->merged[i]] == CVM__T3_REDUNDANT)
            T->fate[i] = CVM__T3_REDUNDANT;
    for (i = 0; i < T->np; i++)
        T->outid[i] = T->orig[i];
    for (i = 0; i < T->np; i++)
        if (T->fate[i] == CVM__T3_DUPLICATE && T->orig[i] < T->outid[T->merged[i]])
            T->outid[T->merged[i]] = T->orig[i];
    T->n_dup = T->n_redundant = 0;
    T->dup_first[0] = T->dup_first[1] = T->redundant_first = -1;
    for (i = 0; i < T->np; i++) {
        int32_t g = T->fate[i] == CVM__T3_DUPLICATE ? T->merged[i] : (int32_t)i;
        if (T->fate[i] == CVM__T3_REDUNDANT) {
            T->n_redundant++;
            if (T->redundant_first < 0 || T->orig[i] < T->redundant_first)
                T->redundant_first = T->orig[i];
        } else if (T->fate[i] != CVM__T3_PENDING && T->orig[i] != T->outid[g]) {
            T->n_dup++;
            if (T->dup_first[1] < 0 || T->orig[i] < T->dup_first[1]) {
                T->dup_first[0] = T->outid[g];
                T->dup_first[1] = T->orig[i];
            }
        }
    }
    T->n_finite = 0;
    for (i = 0; i < T->nslot; i++)
        if (T->tt[8 * i] != CVM__T3_DEAD && T->tt[8 * i + 3] != CVM__T3_GHOST)
            T->n_finite++;
}

/* Exact duplicates: the first of a group to be inserted became its vertex and carried its own
 * input index into every perturbed decision, so the result could depend on the insertion order
 * (the seed). Give each group's vertex the group's lowest input index (the points are identical,
 * so this only renames them) and report whether any changed. */
static int lowest_index_first(cvm__tet3 *T)
{
    size_t i;
    int any = 0;
    for (i = 0; i < T->np; i++)
        if (T->fate[i] == CVM__T3_DUPLICATE && T->orig[i] < T->orig[T->merged[i]]) {
            int32_t g = T->merged[i], x = T->orig[i];
            T->orig[i] = T->orig[g];
            T->orig[g] = x;
            any = 1;
        }
    return any;
}

static cvm_status alloc_points(cvm__tet3 *T, const double *xyz, const double *w, size_t n,
                               uint64_t seed)
{
    cvm__ctx *ctx = T->ctx;
    size_t i;
    cvm_status s;
    T->np = n;
    cvm__tet3_alloc_points(T, n);
    T->orig = cvm__malloc(ctx, n * sizeof *T->orig);
    T->merged = cvm__malloc(ctx, n * sizeof *T->merged);
    T->outid = cvm__malloc(ctx, n * sizeof *T->outid);
    T->fate = cvm__calloc(ctx, n, 1);
    T->etab = cvm__calloc(ctx, CVM__T3_ETAB * CVM__T3_ETAB, sizeof *T->etab);
    if (!T->pt || !T->orig || !T->merged || !T->outid || !T->fate || !T->etab)
        return CVM_E_NOMEM;
    if (w) {
        T->w = cvm__malloc(ctx, n * sizeof *T->w);
        T->vseen = cvm__calloc(ctx, n, sizeof *T->vseen);
        T->vkeep = cvm__calloc(ctx, n, sizeof *T->vkeep);
        if (!T->w || !T->vseen || !T->vkeep)
            return CVM_E_NOMEM;
    }
    T->small_int = w == NULL;
    for (i = 0; i < 3 * n && T->small_int; i++)
        T->small_int = fabs(xyz[i]) <= 256.0 && xyz[i] == (double)(int)xyz[i];
    if (cvm__tet3_build_threads(T) > 1 && n >= T->par_min) {
        T->key = cvm__malloc(ctx, n * sizeof *T->key);
        T->vtet = cvm__malloc(ctx, n * sizeof *T->vtet);
        if (!T->key || !T->vtet)
            return CVM_E_NOMEM;
    }
    s = cvm__tet3_brio_keys(ctx, xyz, n, seed, T->orig, T->key);
    if (s != CVM_OK)
        return s;
    for (i = 0; i < n; i++) {
        const double *p = xyz + 3 * (size_t)T->orig[i];
        if (i + 16 < n) /* the input in insertion order: random reads */
            B3_PREFETCH(xyz + 3 * (size_t)T->orig[i + 16]);
        T->pt[i].x[0] = p[0], T->pt[i].x[1] = p[1], T->pt[i].x[2] = p[2];
        if (w)
            T->w[i] = w[T->orig[i]];
        T->merged[i] = -1;
    }
    /* weighted: a copy of a hidden point would otherwise be tested on its own and could
     * come out differently on an exact tie; merged, the group shares one fate whatever
     * the insertion order (the lowest index has the largest perturbed weight, so the
     * others are hidden by it in the perturbed order anyway) */
    if ((T->key || w) && (s = cvm__tet3_merge_duplicates(T)) == CVM_OK)
        lowest_index_first(T);
    return s;
}

/* Insert every pending point in order, from the first tetrahedron. */
static cvm_status insert_all(cvm__tet3 *T, uint64_t seed)
{
    int32_t first[4];
    size_t i;
    cvm_status s = find_first(T, first);
    if (s != CVM_OK)
        return s;
    /* about 6.5 finite tetrahedra per point for uniform input: reserve once (the
     * threads of a parallel build leave some slots free between them) */
    s = cvm__tet3_reserve(T, T->np < 1000 ? 64 + 8 * T->np : T->key ? 15 * T->np / 2 : 7 * T->np);
    if (s == CVM_OK)
        s = make_first(T, first);
    T->walk = (UINT64_C(0x9E3779B97F4A7C15) ^ seed) | 1u; /* xorshift needs a nonzero state */
    if (s == CVM_OK && T->key)
        return cvm__tet3_insert_rounds(T);
    for (i = 0; i < T->np && s == CVM_OK; i++)
        if (T->fate[i] == CVM__T3_PENDING)
            s = cvm__tet3_insert(T, (int32_t)i);
    return s;
}

cvm_status cvm__tet3_build(cvm__tet3 *T, const double *xyz, const double *w, size_t n,
                           uint64_t seed)
{
    size_t i;
    cvm_status s;

    cvm__tet3_free(T);
    if (n > CVM__T3_MAX_POINTS)
        return cvm__error(T->ctx, CVM_E_TOO_LARGE, CVM_ENT_NONE, -1,
                          "%zu points: the 3D kernel takes at most %zu", n, CVM__T3_MAX_POINTS);
    s = check_input(T, xyz, w, n);
    if (s != CVM_OK)
        return s;
    if (n < 4)
        return cvm__error(T->ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_NONE, -1,
                          "%zu points: a 3D triangulation needs 4 points not in one plane", n);
    s = alloc_points(T, xyz, w, n, seed);
    if (s == CVM_OK)
        s = insert_all(T, seed);
    if (s == CVM_OK && lowest_index_first(T)) {
        /* again from scratch, in the same order, under the new names */
        T->nslot = T->nfree = T->ndead = 0;
        T->n_big_cavities = T->n_par_done = 0;
        for (i = 0; i < n; i++) {
            T->fate[i] = CVM__T3_PENDING;
            T->merged[i] = -1;
        }
        s = insert_all(T, seed);
    }
    if (s == CVM_E_NOMEM)
        return cvm__nomem(T->ctx);
    if (s != CVM_OK && T->nslot == 0)
        return s; /* find_first's errors: nothing was built */
    finish(T);
    return s;
}

void cvm__tet3_point_fates(const cvm__tet3 *T, uint8_t *fate_out, int32_t *into_out)
{
    size_t i;
    for (i = 0; i < T->np; i++) {
        int32_t in = T->orig[i], g = T->fate[i] == CVM__T3_DUPLICATE ? T->merged[i] : (int32_t)i;
        uint8_t f = T->fate[i];
        int32_t into = -1;
        if ((f == CVM__T3_VERTEX || f == CVM__T3_DUPLICATE) && T->fate[g] == CVM__T3_VERTEX) {
            f = in == T->outid[g] ? CVM__T3_VERTEX : CVM__T3_DUPLICATE;
            into = f == CVM__T3_DUPLICATE ? T->outid[g] : -1;
        }
        if (fate_out)
            fate_out[in] = f;
        if (into_out)
            into_out[in] = into;
    }
}
