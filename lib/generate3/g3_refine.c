/*
 * g3_refine.c - the free space by Delaunay refinement (the baseline the issue
 * sets beside the lattice and the octree): after the near field, round after
 * round, the points so far are tetrahedralised (exact kernel, canonical order)
 * and the circumcentre of every tetrahedron whose circumradius exceeds the
 * size there becomes a candidate; candidates are taken by size band (coarse
 * first, each band with its own range grid, as the lattice's levels), largest
 * radius first within a band, and kept by the lattice's rules: strictly inside
 * the domain (exact), farther than dm = cvm__g3_lattice_dm(size) from every
 * point so far and half that from every surface triangle (a circumcentre near a coarse
 * surface triangle would only make slivers: the surface is never split). A
 * circumcentre outside the domain or at the surface gives way to its
 * tetrahedron's centroid, under the same rules (else the tetrahedra along the
 * surface, whose circumcentres often lie beyond it, would never be refined:
 * classic refinement splits the boundary there instead). The rounds end when no candidate is kept, after REFINE_MAX_ROUNDS, or at the
 * caller's point limit.
 *
 * Each kept point is farther than its dm from every other, so the rounds end
 * (a packing bound). Circumcentres and radii are plain doubles (placements);
 * only the inside test and the tetrahedralisation decide topology, exactly.
 * Deterministic: the tetrahedra come in the kernel's canonical order, which no
 * seed changes, and candidates are sorted on a total key.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay3/delaunay3_internal.h"
#include "generate3/generate3.h"
#include "geom/measure3.h"

#define REFINE_MAX_ROUNDS 100
#define REFINE_MAX_BANDS 40
/* A candidate keeps this fraction of its dm from the surface triangles: with
 * the whole dm, a surface much coarser than the size (the tetrahedron of
 * edge 2.8 at size 0.3) keeps every centroid of the tetrahedra on it away,
 * and the refinement stops after its first point. */
#define REFINE_SURFACE_DM 0.5

double cvm__g3_tri_dist2(const double *p, const double *a, const double *b, const double *c)
{
    double ab[3], ac[3], ap[3], bp[3], cp[3], q[3], d1 = 0, d2 = 0, d3 = 0, d4 = 0, d5 = 0,
                                                       d6 = 0, va, vb, vc, v, w, den;
    int k;
    for (k = 0; k < 3; k++) {
        ab[k] = b[k] - a[k];
        ac[k] = c[k] - a[k];
        ap[k] = p[k] - a[k];
        bp[k] = p[k] - b[k];
        cp[k] = p[k] - c[k];
        d1 += ab[k] * ap[k];
        d2 += ac[k] * ap[k];
        d3 += ab[k] * bp[k];
        d4 += ac[k] * bp[k];
        d5 += ab[k] * cp[k];
        d6 += ac[k] * cp[k];
    }
    vc = d1 * d4 - d3 * d2;
    vb = d5 * d2 - d1 * d6;
    va = d3 * d6 - d5 * d4;
    if (d1 <= 0 && d2 <= 0)
        v = 0, w = 0;
    else if (d3 >= 0 && d4 <= d3)
        v = 1, w = 0;
    else if (d6 >= 0 && d5 <= d6)
        v = 0, w = 1;
    else if (vc <= 0 && d1 >= 0 && d3 <= 0)
        v = d1 / (d1 - d3), w = 0;
    else if (vb <= 0 && d2 >= 0 && d6 <= 0)
        v = 0, w = d2 / (d2 - d6);
    else if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
        w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        v = 1 - w;
    } else {
        den = va + vb + vc;
        if (!(den > 0))
            return cvm__dist2_3(p, a); /* a degenerate triangle: its corner is near enough */
        v = vb / den;
        w = vc / den;
    }
    for (k = 0; k < 3; k++)
        q[k] = a[k] + v * ab[k] + w * ac[k] - p[k];
    return q[0] * q[0] + q[1] * q[1] + q[2] * q[2];
}

/* ---- surface triangles by grid cell, for "is a triangle within r of x" ---- */

typedef struct rf_cellref {
    uint64_t cell;
    int32_t tri;
} rf_cellref;

typedef struct rf_tris {
    const cvm__g3_surface *s;
    double lo[3], hi[3], cell; /* the surface's bounding box; cell edge */
    rf_cellref *ref; /* sorted by cell, then triangle */
    size_t n;
} rf_tris;

static int64_t rf_coord(const rf_tris *G, double x, int ax)
{
    double t = floor((x - G->lo[ax]) / G->cell);
    return t < 0 ? 0 : t > 2097150.0 ? 2097150 : (int64_t)t;
}

static uint64_t rf_key(int64_t i, int64_t j, int64_t k)
{
    return (uint64_t)i << 42 | (uint64_t)j << 21 | (uint64_t)k;
}

static int rf_cmp(const void *pa, const void *pb)
{
    const rf_cellref *a = pa, *b = pb;
    if (a->cell != b->cell)
        return a->cell < b->cell ? -1 : 1;
    return (a->tri > b->tri) - (a->tri < b->tri);
}

/* Each triangle in every cell its bounding box meets; cells of the mean edge
 * length, grown while that would file more than 64 references per triangle. */
static cvm_status rf_tris_build(cvm__ctx *ctx, const cvm__g3_surface *s, rf_tris *G)
{
    size_t f;
    double len = 0, total;
    int ax, pass;
    memset(G, 0, sizeof *G);
    G->s = s;
    for (ax = 0; ax < 3; ax++)
        G->lo[ax] = G->hi[ax] = s->xyz[ax];
    for (f = 0; f < s->np; f++)
        for (ax = 0; ax < 3; ax++) {
            double v = s->xyz[3 * f + ax];
            G->lo[ax] = v < G->lo[ax] ? v : G->lo[ax];
            G->hi[ax] = v > G->hi[ax] ? v : G->hi[ax];
        }
    for (f = 0; f < s->nt; f++)
        len += sqrt(cvm__dist2_3(s->xyz + 3 * s->tri[3 * f], s->xyz + 3 * s->tri[3 * f + 1]));
    G->cell = len / (double)s->nt;
    if (!(G->cell > 0))
        G->cell = 1;
    for (pass = 0; pass < 2; pass++) {
        for (f = 0, total = 0; f < s->nt; f++) {
            int64_t b0[3], b1[3], i, j, k;
            for (ax = 0; ax < 3; ax++) {
                const int32_t *t = s->tri + 3 * f;
                double mn = s->xyz[3 * t[0] + ax], mx = mn;
                int q;
                for (q = 1; q < 3; q++) {
                    double v = s->xyz[3 * t[q] + ax];
                    mn = v < mn ? v : mn;
                    mx = v > mx ? v : mx;
                }
                b0[ax] = rf_coord(G, mn, ax);
                b1[ax] = rf_coord(G, mx, ax);
            }
            if (pass == 0) {
                total += (double)(b1[0] - b0[0] + 1) * (double)(b1[1] - b0[1] + 1) *
                         (double)(b1[2] - b0[2] + 1);
                continue;
            }
            for (k = b0[2]; k <= b1[2]; k++)
                for (j = b0[1]; j <= b1[1]; j++)
                    for (i = b0[0]; i <= b1[0]; i++) {
                        G->ref[G->n].cell = rf_key(i, j, k);
                        G->ref[G->n++].tri = (int32_t)f;
                    }
        }
        if (pass == 0) {
            if (total > (double)(64 * s->nt + 4096)) {
                G->cell *= cbrt(total / (double)(64 * s->nt + 4096)) * 1.01;
                pass = -1; /* count again with the larger cells */
                continue;
            }
            if (!(G->ref = cvm__malloc(ctx, ((size_t)total + 1) * sizeof *G->ref)))
                return cvm__nomem(ctx);
        }
    }
    qsort(G->ref, G->n, sizeof *G->ref, rf_cmp);
    return CVM_OK;
}

/* 1 when some surface triangle lies strictly closer than r to x. */
static int rf_tris_near(const rf_tris *G, const double *x, double r)
{
    int64_t b0[3], b1[3], i, j, k;
    int ax;
    for (ax = 0; ax < 3; ax++) {
        b0[ax] = rf_coord(G, x[ax] - r, ax);
        b1[ax] = rf_coord(G, x[ax] + r, ax);
    }
    for (k = b0[2]; k <= b1[2]; k++)
        for (j = b0[1]; j <= b1[1]; j++)
            for (i = b0[0]; i <= b1[0]; i++) {
                uint64_t key = rf_key(i, j, k);
                size_t lo = 0, hi = G->n;
                while (lo < hi) {
                    size_t mid = lo + (hi - lo) / 2;
                    if (G->ref[mid].cell < key)
                        lo = mid + 1;
                    else
                        hi = mid;
                }
                for (; lo < G->n && G->ref[lo].cell == key; lo++) {
                    const int32_t *t = G->s->tri + 3 * G->ref[lo].tri;
                    if (cvm__g3_tri_dist2(x, G->s->xyz + 3 * t[0], G->s->xyz + 3 * t[1],
                                          G->s->xyz + 3 * t[2]) < r * r)
                        return 1;
                }
            }
    return 0;
}

/* ---- the rounds ---- */

typedef struct rf_cand {
    double r2;   /* squared circumradius */
    double x[3]; /* circumcentre */
    double g[3]; /* centroid: the fallback when the circumcentre is outside */
    double hs;   /* size at the circumcentre */
    int band;    /* floor(log2(h / hs)), capped */
} rf_cand;

static int rf_cand_cmp(const void *pa, const void *pb)
{
    const rf_cand *a = pa, *b = pb;
    int k;
    if (a->band != b->band)
        return a->band < b->band ? -1 : 1;
    if (a->r2 != b->r2)
        return a->r2 > b->r2 ? -1 : 1;
    for (k = 0; k < 3; k++)
        if (a->x[k] != b->x[k])
            return a->x[k] < b->x[k] ? -1 : 1;
    return 0;
}

/* The candidates of one round into *out (count *nout): circumcentres of the
 * tetrahedra of P whose circumradius exceeds the size there. */
static cvm_status rf_candidates(cvm__ctx *ctx, const cvm__g3_points *P, const cvm__g3_size *z,
                                const rf_tris *G, double h, uint64_t seed, rf_cand **out,
                                size_t *nout)
{
    cvm__tet3 T;
    int32_t *tet = NULL;
    rf_cand *c = NULL;
    size_t t, n = 0;
    cvm_status st;
    const cvm_sizing *u = cvm__g3_size_user(z);
    int user_fn = u && u->fn_nd;
    double lmin = cvm__g3_size_min(z);
    *out = NULL;
    *nout = 0;
    cvm__tet3_init(&T, ctx);
    if ((st = cvm__tet3_build(&T, P->xyz, NULL, P->n, seed)))
        goto done;
    tet = cvm__malloc(ctx, (4 * T.n_finite + 1) * sizeof *tet);
    c = cvm__malloc(ctx, (T.n_finite + 1) * sizeof *c);
    if (!tet || !c) {
        st = cvm__nomem(ctx);
        goto done;
    }
    if ((st = cvm__tet3_copy_tets(&T, tet)))
        goto done;
    for (t = 0; t < T.n_finite; t++) {
        const double *a = P->xyz + 3 * (size_t)tet[4 * t];
        rf_cand *q = c + n;
        double r2, band;
        int k;
        if (cvm__tet_power_centre(a, P->xyz + 3 * (size_t)tet[4 * t + 1],
                                  P->xyz + 3 * (size_t)tet[4 * t + 2],
                                  P->xyz + 3 * (size_t)tet[4 * t + 3], NULL, q->x) != 0)
            continue;
        r2 = cvm__dist2_3(q->x, a);
        if (!(r2 < INFINITY) || (!user_fn && r2 <= lmin * lmin))
            continue; /* no size can be that small (a callback's is not bounded) */
        for (k = 0; k < 3; k++)
            q->g[k] = (a[k] + P->xyz[3 * (size_t)tet[4 * t + 1] + (size_t)k] +
                       P->xyz[3 * (size_t)tet[4 * t + 2] + (size_t)k] +
                       P->xyz[3 * (size_t)tet[4 * t + 3] + (size_t)k]) / 4;
        if (q->x[0] < G->lo[0] || q->x[0] > G->hi[0] || q->x[1] < G->lo[1] ||
            q->x[1] > G->hi[1] || q->x[2] < G->lo[2] || q->x[2] > G->hi[2])
            memcpy(q->x, q->g, sizeof q->x); /* outside anyway: the centroid at once */
        if (cvm__g3_size_at(z, q->x, &q->hs)) {
            st = ctx->status;
            goto done;
        }
        if (!(r2 > q->hs * q->hs))
            continue;
        band = floor(log2(h / q->hs));
        q->band = band < 0 ? 0 : band >= REFINE_MAX_BANDS ? REFINE_MAX_BANDS - 1 : (int)band;
        q->r2 = r2;
        n++;
    }
    qsort(c, n, sizeof *c, rf_cand_cmp);
done:
    cvm__tet3_free(&T);
    cvm__free(ctx, tet);
    if (st) {
        cvm__free(ctx, c);
        return st == CVM_E_NOMEM ? cvm__nomem(ctx) : st;
    }
    *out = c;
    *nout = n;
    return CVM_OK;
}

/* Keep the candidates c[0 .. n) of one round by the rules; *kept counts them. */
static cvm_status rf_keep(cvm__ctx *ctx, const rf_cand *c, size_t n, const cvm__g3_size *z,
                          double h,
                          const cvm__g3_inside *in, const rf_tris *G, size_t limit,
                          cvm__g3_points *P, size_t *kept)
{
    cvm__g3_grid *grid = NULL;
    size_t i, v;
    int band = -1;
    cvm_status st = CVM_OK;
    for (i = 0; i < n && !st; i++) {
        double dm = cvm__g3_lattice_dm(c[i].hs);
        const double *x = c[i].x;
        if (c[i].band != band) {
            /* a grid per band, its cells the band's largest dm */
            cvm__g3_grid_free(grid);
            grid = NULL;
            band = c[i].band;
            if ((st = cvm__g3_grid_create(&grid, ctx, cvm__g3_lattice_dm(ldexp(h, -band)))))
                break;
            for (v = 0; v < P->n && !st; v++)
                st = cvm__g3_grid_add(grid, P->xyz, (int32_t)v);
            if (st)
                break;
        }
        if (limit && *kept >= limit)
            break;
        if (cvm__g3_grid_near(grid, P->xyz, x, dm))
            continue;
        if (!cvm__g3_is_inside(in, x) || rf_tris_near(G, x, REFINE_SURFACE_DM * dm)) {
            /* outside, or at the surface, which is never split: the centroid then,
             * when its own size still finds the tetrahedron too large */
            double hg;
            x = c[i].g;
            if (cvm__g3_size_at(z, x, &hg)) {
                st = ctx->status;
                break;
            }
            dm = cvm__g3_lattice_dm(hg);
            if (!(c[i].r2 > hg * hg) || cvm__g3_grid_near(grid, P->xyz, x, dm) ||
                !cvm__g3_is_inside(in, x) || rf_tris_near(G, x, REFINE_SURFACE_DM * dm))
                continue;
        }
        if (P->n >= CVM__T3_MAX_POINTS) {
            st = cvm__error(ctx, CVM_E_TOO_LARGE, CVM_ENT_NONE, -1,
                            "the refinement passes the 3D limit of %lu points: use a larger "
                            "size or grading", (unsigned long)CVM__T3_MAX_POINTS);
            break;
        }
        if ((st = cvm__g3_points_push(ctx, P, x, dm)))
            break;
        (*kept)++;
        st = cvm__g3_grid_add(grid, P->xyz, (int32_t)(P->n - 1));
    }
    cvm__g3_grid_free(grid);
    return st == CVM_E_NOMEM ? cvm__nomem(ctx) : st;
}

cvm_status cvm__g3_refine(cvm__ctx *ctx, const cvm__g3_surface *s, const cvm__g3_size *z,
                          double h, const cvm__g3_inside *in, size_t limit, uint64_t seed,
                          cvm__g3_points *P, cvm__g3_report *rep, int *limited)
{
    rf_tris G;
    size_t round;
    cvm_status st;
    *limited = 0;
    if (s->np == 0 || s->nt == 0)
        return CVM_OK;
    if ((st = rf_tris_build(ctx, s, &G)))
        return st;
    for (round = 0; round < REFINE_MAX_ROUNDS && !st; round++) {
        rf_cand *c = NULL;
        size_t n = 0, kept = 0;
        if ((st = rf_candidates(ctx, P, z, &G, h, seed, &c, &n)))
            break;
        if (n > 0) {
            rep->refine_rounds++;
            st = rf_keep(ctx, c, n, z, h, in, &G,
                         limit ? limit - rep->refine_points : 0, P, &kept);
        }
        cvm__free(ctx, c);
        rep->refine_points += kept;
        if (limit && rep->refine_points >= limit && !st) {
            *limited = 1;
            break;
        }
        if (kept == 0)
            break;
    }
    cvm__free(ctx, G.ref);
    return st;
}
