/*
 * g3_near.c - the near field (modified advancing front): surface triangles
 * are paired across shared edges by a maximum-cardinality matching (the
 * blossom solver of lib/quad), and each pair ABC / BDC gets one point
 *   x = 0.5 (c_ABC + c_BDC + delta (n_ABC + n_BDC)),  delta = 1.1 max(R_ABC, R_BDC),
 * c the circumcentre, R the circumradius, n the inward unit normal; an
 * unmatched triangle gets c + 1.1 R n. Rejection distance dm = 0.5 delta.
 * A point is not placed when it lies closer than wallf delta (CVM__G3_NEAR_WALL,
 * 0.7) to any surface triangle: a triangle at a convex edge whose circumcentre
 * lies on or near that edge (a right triangle's hypotenuse) sends its point
 * along the face next to it, a hair inside the other face, which makes slivers
 * and tetrahedra no optimisation repairs (measurements: docs/benchmarks.md).
 * A pair on one plane keeps delta from it, so only such points go.
 *
 * Pairs whose well-centred regions may not intersect are dropped before the
 * matching, by a cheap sufficient test of intersection: the pair is kept when
 * its own point x lies in both regions, i.e. the circumcentres of ABCx and
 * BDCx lie in those tetrahedra (closed, within 10^-6 of the volume, plain
 * doubles: a placement choice, not a topological one). The test misses
 * pairs whose regions meet only away from x.
 * Among maximum matchings the solver prefers pairs whose circumcentres are
 * close (weight 1 - |c1 - c2| / (R1 + R2)): two right triangles of a square
 * pair across their hypotenuse.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "generate3/generate3.h"
#include "geom/geom_internal.h"
#include "geom/measure3.h"
#include "quad/matching.h"

typedef struct face_geo {
    double c[3], n[3], R;
} face_geo;

typedef struct edge_rec {
    int32_t v0, v1, face, opp; /* v0 < v1; opp: the face's corner not on the edge */
} edge_rec;

static int cmp_edge(const void *pa, const void *pb)
{
    const edge_rec *a = pa, *b = pb;
    if (a->v0 != b->v0)
        return a->v0 < b->v0 ? -1 : 1;
    if (a->v1 != b->v1)
        return a->v1 < b->v1 ? -1 : 1;
    return (a->face > b->face) - (a->face < b->face);
}

static void geometry(const double *a, const double *b, const double *c, face_geo *g)
{
    cvm__tri3_circle(a, b, c, g->c, &g->R, g->n);
    g->R = sqrt(g->R);
}

static double dist2(const double *a, const double *b)
{
    double x = a[0] - b[0], y = a[1] - b[1], z = a[2] - b[2];
    return x * x + y * y + z * z;
}

static double vol6(const double *a, const double *b, const double *c, const double *d)
{
    double u[3], v[3], w[3];
    int k;
    for (k = 0; k < 3; k++) {
        u[k] = b[k] - a[k];
        v[k] = c[k] - a[k];
        w[k] = d[k] - a[k];
    }
    return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
           u[2] * (v[0] * w[1] - v[1] * w[0]);
}

/* The circumcentre of the tetrahedron (a, b, c, x) in it or within 10^-6 of its
 * volume from it, in plain doubles: x is in the triangle's well-centred region
 * (closed, so that the two right triangles of a square, whose tetrahedra share
 * their circumsphere, qualify). */
static int well_centred(const double *a, const double *b, const double *c, const double *x)
{
    double o[3], v = vol6(a, b, c, x), tol;
    if (cvm__tet_power_centre(a, b, c, x, NULL, o) != 0 || v == 0)
        return 0;
    tol = -1e-6 * fabs(v);
    if (v < 0)
        return 0; /* x on the outer side */
    return vol6(o, b, c, x) >= tol && vol6(a, o, c, x) >= tol && vol6(a, b, o, x) >= tol &&
           vol6(a, b, c, o) >= tol;
}

/* The pair's point, rejection distance and weight; 0 when the pair is dropped.
 * b, c: the shared edge; a, d: the far corners. */
static int pair_point(const face_geo *g1, const face_geo *g2, const double *a, const double *b,
                      const double *c, const double *d, double *x, double *dm, double *q)
{
    double delta = 1.1 * (g1->R > g2->R ? g1->R : g2->R);
    int k;
    for (k = 0; k < 3; k++)
        x[k] = 0.5 * (g1->c[k] + g2->c[k] + delta * (g1->n[k] + g2->n[k]));
    *dm = 0.5 * delta;
    /* orientation: (a, b, c) has its right-hand normal out of the domain, so
     * (a, c, b, x) is positive for x inside; likewise (d, b, c, x) */
    if (!well_centred(a, c, b, x) || !well_centred(d, b, c, x))
        return 0;
    *q = 1 - sqrt(dist2(g1->c, g2->c)) / (g1->R + g2->R);
    if (!(*q > 0))
        *q = 0;
    return 1;
}

#define P3(i) (s->xyz + 3 * (size_t)(i))

cvm_status cvm__g3_near_field(cvm__ctx *ctx, const cvm__g3_surface *s, const cvm__g3_inside *in,
                              double wallf, cvm__g3_points *P, cvm__g3_report *rep)
{
    face_geo *geo = NULL;
    edge_rec *er = NULL;
    cvm_index *ends = NULL, *mate = NULL;
    int64_t *w = NULL;
    cvm__g3_grid *grid = NULL;
    cvm__g3_trigrid *tg = NULL;
    size_t f, i, m = 0, ne = 3 * s->nt;
    double dmax = 0;
    cvm_status st = CVM_OK;
    geo = cvm__malloc(ctx, (s->nt + 1) * sizeof *geo);
    er = cvm__malloc(ctx, (ne + 1) * sizeof *er);
    ends = cvm__malloc(ctx, (ne + 1) * sizeof *ends);
    w = cvm__malloc(ctx, (ne / 2 + 1) * sizeof *w);
    mate = cvm__malloc(ctx, (s->nt + 1) * sizeof *mate);
    if (!geo || !er || !ends || !w || !mate) {
        st = cvm__nomem(ctx);
        goto done;
    }
    for (f = 0; f < s->nt; f++) {
        const int32_t *t = s->tri + 3 * f;
        int j;
        geometry(s->xyz + 3 * t[0], s->xyz + 3 * t[1], s->xyz + 3 * t[2], &geo[f]);
        if (1.1 * geo[f].R * 0.5 > dmax)
            dmax = 1.1 * geo[f].R * 0.5;
        for (j = 0; j < 3; j++) {
            edge_rec *e = er + 3 * f + j;
            int32_t a = t[j], b = t[(j + 1) % 3];
            e->v0 = a < b ? a : b;
            e->v1 = a < b ? b : a;
            e->face = (int32_t)f;
            e->opp = t[(j + 2) % 3];
        }
    }
    qsort(er, ne, sizeof *er, cmp_edge);
    for (i = 0; i < ne;) {
        size_t j = i;
        while (j < ne && er[j].v0 == er[i].v0 && er[j].v1 == er[i].v1)
            j++;
        if (j - i != 2) {
            st = cvm__error(ctx, CVM_E_UNSUPPORTED, CVM_ENT_NONE, -1,
                            "surface edge (points %ld, %ld) has %lu triangles: unsupported in this "
                            "version, mesh generation handles closed 2-manifold surfaces only (no "
                            "internal facets between regions)",
                            (long)er[i].v0, (long)er[i].v1, (unsigned long)(j - i));
            goto done;
        }
        {
            const edge_rec *e1 = &er[i], *e2 = &er[i + 1];
            double x[3], dm, q;
            if (!pair_point(&geo[e1->face], &geo[e2->face], P3(e1->opp), P3(e1->v0),
                            P3(e1->v1), P3(e2->opp), x, &dm, &q) &&
                !pair_point(&geo[e1->face], &geo[e2->face], P3(e1->opp), P3(e1->v1),
                            P3(e1->v0), P3(e2->opp), x, &dm, &q)) {
                rep->pairs_rejected++;
            } else {
                ends[2 * m] = e1->face;
                ends[2 * m + 1] = e2->face;
                w[m] = cvm__match_scale(q);
                m++;
            }
        }
        i = j;
    }
    if (m) {
        if ((st = cvm__matching_solve(mate, NULL, ctx, s->nt, m, ends, w, CVM__MATCH_MAX_CARDINALITY)))
            goto done;
    } else {
        for (f = 0; f < s->nt; f++)
            mate[f] = -1;
    }
    if ((st = cvm__g3_grid_create(&grid, ctx, dmax)))
        goto done;
    if (wallf > 0 && (st = cvm__g3_trigrid_create(&tg, ctx, s, 2 * wallf * dmax)))
        goto done;
    for (i = 0; i < P->n; i++)
        if ((st = cvm__g3_grid_add(grid, P->xyz, (int32_t)i)))
            goto done;
    for (f = 0; f < s->nt; f++) {
        double x[3], dm;
        int k;
        if (mate[f] >= 0) {
            cvm_index e = mate[f], o = ends[2 * e] == (cvm_index)f ? ends[2 * e + 1] : ends[2 * e];
            if ((size_t)o < f)
                continue;
            /* the pair passed above: only the point is wanted here */
            {
                double delta = 1.1 * (geo[f].R > geo[o].R ? geo[f].R : geo[o].R);
                for (k = 0; k < 3; k++)
                    x[k] = 0.5 * (geo[f].c[k] + geo[o].c[k] + delta * (geo[f].n[k] + geo[o].n[k]));
                dm = 0.5 * delta;
            }
            rep->matched_pairs++;
        } else {
            for (k = 0; k < 3; k++)
                x[k] = geo[f].c[k] + 1.1 * geo[f].R * geo[f].n[k];
            dm = 0.5 * 1.1 * geo[f].R;
            rep->unmatched_faces++;
        }
        if (!cvm__g3_is_inside(in, x) || cvm__g3_grid_near(grid, P->xyz, x, dm) ||
            (tg && cvm__g3_trigrid_near(tg, x, 2 * wallf * dm))) {
            rep->near_rejected++;
            continue;
        }
        if ((st = cvm__g3_points_push(ctx, P, x, dm)) ||
            (st = cvm__g3_grid_add(grid, P->xyz, (int32_t)(P->n - 1))))
            goto done;
        rep->near_points++;
    }
done:
    cvm__g3_trigrid_free(tg);
    cvm__g3_grid_free(grid);
    cvm__free(ctx, geo);
    cvm__free(ctx, er);
    cvm__free(ctx, ends);
    cvm__free(ctx, w);
    cvm__free(ctx, mate);
    return st;
}
