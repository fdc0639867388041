/*
 * test_merge3.c - merged 3D dual cells (cvm_mesh_copy_dual3_merge_groups(),
 * CVM_OPT_DUAL3_MERGE_TOL, measures 725-728): on a cubic lattice every cube
 * is one kept group and nothing is non-compliant; on a BCC lattice nothing
 * merges and only tetrahedra at the hull are non-compliant; on a perturbed lattice some cubes are no longer convex and are
 * dissolved. Each time the groups, the dissolved count and the percentages are
 * recounted independently (own adjacency, long double centres, own union-find
 * and convexity check). Also: tol 0, bad tolerances, statuses, determinism, OOM.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dual3/dual3_tests.h"
#include "io/io_tests.h"
#include "support/oom_sweep.h"

typedef long double ld;

/* n^3 grid points of spacing 1; bcc adds the (n - 1)^3 cube centres; eps > 0
 * moves the grid point (1, 1, 1) by eps x (-2, -1, 0). */
static double *lattice_points(int n, int bcc, double eps, size_t *np)
{
    size_t cap = (size_t)(n * n * n + (n - 1) * (n - 1) * (n - 1)), k = 0;
    double *p = malloc(3 * cap * sizeof *p);
    int i, j, l;
    ck_assert_ptr_nonnull(p);
    for (i = 0; i < n; i++)
        for (j = 0; j < n; j++)
            for (l = 0; l < n; l++) {
                /* one interior point moved: its 8 cubes lose their planar sides */
                double e = i == 1 && j == 1 && l == 1 ? eps : 0;
                p[3 * k] = i + e * ((i * 7 + j * 3 + l * 5) % 5 - 2);
                p[3 * k + 1] = j + e * ((i * 3 + j * 5 + l * 7 + 1) % 5 - 2);
                p[3 * k + 2] = l + e * ((i * 5 + j * 7 + l * 3 + 2) % 5 - 2);
                k++;
            }
    for (i = 0; bcc && i < n - 1; i++)
        for (j = 0; j < n - 1; j++)
            for (l = 0; l < n - 1; l++) {
                p[3 * k] = i + 0.5, p[3 * k + 1] = j + 0.5, p[3 * k + 2] = l + 0.5;
                k++;
            }
    *np = k;
    return p;
}

static cvm_mesh *lattice(int n, int bcc, double eps)
{
    cvm_mesh *m;
    size_t np;
    double *p = lattice_points(n, bcc, eps, &np);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, p, np, 3), CVM_OK);
    ck_assert_msg(cvm_mesh_triangulate(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    free(p);
    return m;
}

/* The mesh, copied out, and the expected results of the rule. */
typedef struct m3t_ref {
    size_t nv, nt;
    double *xyz;
    cvm_index *tet;
    int32_t *nbr;     /* 4 nt: 4 u + g, or -1 */
    ld *c;            /* 3 nt circumcentres */
    int32_t *group;   /* nt */
    size_t merged, dissolved, nc, nbnd, nbnc;
} m3t_ref;

static ld m3t_orient(const double *a, const double *b, const double *c, const ld *d)
{
    ld ax = a[0] - d[0], ay = a[1] - d[1], az = a[2] - d[2];
    ld bx = b[0] - d[0], by = b[1] - d[1], bz = b[2] - d[2];
    ld cx = c[0] - d[0], cy = c[1] - d[1], cz = c[2] - d[2];
    return ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
}

static ld m3t_orient_p(const double *a, const double *b, const double *c, const double *d)
{
    ld e[3] = {d[0], d[1], d[2]};
    return m3t_orient(a, b, c, e);
}

static int sgnl(ld x)
{
    return (x > 0) - (x < 0);
}

static void centre(const double *a, const double *b, const double *c, const double *d, ld *o)
{
    ld m[3][3], r[3], det;
    int i;
    for (i = 0; i < 3; i++) {
        const double *q = i == 0 ? b : i == 1 ? c : d;
        m[i][0] = (ld)q[0] - a[0], m[i][1] = (ld)q[1] - a[1], m[i][2] = (ld)q[2] - a[2];
        r[i] = 0.5L * (m[i][0] * m[i][0] + m[i][1] * m[i][1] + m[i][2] * m[i][2]);
    }
    det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
          m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
          m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    o[0] = a[0] + (r[0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                   m[0][1] * (r[1] * m[2][2] - m[1][2] * r[2]) +
                   m[0][2] * (r[1] * m[2][1] - m[1][1] * r[2])) / det;
    o[1] = a[1] + (m[0][0] * (r[1] * m[2][2] - m[1][2] * r[2]) -
                   r[0] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                   m[0][2] * (m[1][0] * r[2] - r[1] * m[2][0])) / det;
    o[2] = a[2] + (m[0][0] * (m[1][1] * r[2] - r[1] * m[2][1]) -
                   m[0][1] * (m[1][0] * r[2] - r[1] * m[2][0]) +
                   r[0] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])) / det;
}

static int32_t uf_find(int32_t *g, int32_t x)
{
    while (g[x] != x)
        x = g[x];
    return x;
}

/* The rule recomputed for tol (no weights, no regions, no internal facets). */
static void m3t_recount(m3t_ref *R, const cvm_mesh *m, double tol)
{
    size_t t, i, k, ne = 0;
    double *lsum, *lcnt;
    int32_t *size;
    unsigned char *mf;
    ck_assert_int_eq(cvm_mesh_count(&R->nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&R->nt, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    R->xyz = malloc(3 * R->nv * sizeof *R->xyz);
    R->tet = malloc(4 * R->nt * sizeof *R->tet);
    R->nbr = malloc(4 * R->nt * sizeof *R->nbr);
    R->c = malloc(3 * R->nt * sizeof *R->c);
    R->group = malloc(R->nt * sizeof *R->group);
    lsum = calloc(2 * R->nv, sizeof *lsum);
    size = calloc(R->nt, sizeof *size);
    mf = calloc(4 * R->nt, 1);
    ck_assert(R->xyz && R->tet && R->nbr && R->c && R->group && lsum && size && mf);
    lcnt = lsum + R->nv;
    ck_assert_int_eq(cvm_mesh_copy_points_nd(R->xyz, 3 * R->nv, 3, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(R->tet, 4 * R->nt, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    /* adjacency and edges by brute force over vertex pairs (small meshes) */
    for (i = 0; i < 4 * R->nt; i++) {
        R->nbr[i] = -1;
        for (k = 0; k < 4 * R->nt && R->nbr[i] < 0; k++) {
            int a, b, same = 0;
            if (k / 4 == i / 4)
                continue;
            for (a = 0; a < 4; a++)
                for (b = 0; b < 4; b++)
                    same += a != (int)(i % 4) && b != (int)(k % 4) &&
                            R->tet[4 * (i / 4) + (size_t)a] == R->tet[4 * (k / 4) + (size_t)b];
            if (same == 3)
                R->nbr[i] = (int32_t)k;
        }
    }
    {
        unsigned char *seen = calloc(R->nv * R->nv, 1);
        ck_assert_ptr_nonnull(seen);
        for (t = 0; t < R->nt; t++) {
            int a, b;
            for (a = 0; a < 4; a++)
                for (b = a + 1; b < 4; b++) {
                    cvm_index p = R->tet[4 * t + (size_t)a], q = R->tet[4 * t + (size_t)b];
                    size_t key = p < q ? (size_t)p * R->nv + (size_t)q : (size_t)q * R->nv + (size_t)p;
                    const double *P = R->xyz + 3 * (size_t)p, *Q = R->xyz + 3 * (size_t)q;
                    double len = sqrt((P[0] - Q[0]) * (P[0] - Q[0]) + (P[1] - Q[1]) * (P[1] - Q[1]) +
                                      (P[2] - Q[2]) * (P[2] - Q[2]));
                    if (seen[key])
                        continue;
                    seen[key] = 1;
                    ne++;
                    lsum[p] += len, lsum[q] += len, lcnt[p] += 1, lcnt[q] += 1;
                }
        }
        free(seen);
    }
    ck_assert(ne > 0);
    for (t = 0; t < R->nt; t++) {
        const cvm_index *v = R->tet + 4 * t;
        centre(R->xyz + 3 * (size_t)v[0], R->xyz + 3 * (size_t)v[1], R->xyz + 3 * (size_t)v[2],
               R->xyz + 3 * (size_t)v[3], R->c + 3 * t);
        R->group[t] = (int32_t)t;
    }
    for (i = 0; i < 4 * R->nt; i++) {
        size_t u;
        ld l = 0, d;
        int a;
        if (R->nbr[i] < 0 || !(tol > 0))
            continue;
        u = (size_t)R->nbr[i] / 4;
        for (a = 0; a < 4; a++)
            if (a != (int)(i % 4)) {
                cvm_index q = R->tet[4 * (i / 4) + (size_t)a];
                l += lsum[q] / lcnt[q];
            }
        l /= 3;
        d = sqrtl((R->c[3 * (i / 4)] - R->c[3 * u]) * (R->c[3 * (i / 4)] - R->c[3 * u]) +
                  (R->c[3 * (i / 4) + 1] - R->c[3 * u + 1]) * (R->c[3 * (i / 4) + 1] - R->c[3 * u + 1]) +
                  (R->c[3 * (i / 4) + 2] - R->c[3 * u + 2]) * (R->c[3 * (i / 4) + 2] - R->c[3 * u + 2]));
        /* the lattices keep clear of the threshold: ties are ~0, the rest far */
        if (d < 1e-9L * l || d < tol * 0.38L * l) {
            int32_t ra = uf_find(R->group, (int32_t)(i / 4)), rb = uf_find(R->group, (int32_t)u);
            mf[i] = 1;
            if (ra < rb)
                R->group[rb] = ra;
            else
                R->group[ra] = rb;
        }
    }
    for (t = 0; t < R->nt; t++) {
        R->group[t] = uf_find(R->group, (int32_t)t);
        size[R->group[t]]++;
    }
    /* convexity and star, group by group */
    R->merged = R->dissolved = 0;
    for (t = 0; t < R->nt; t++) {
        size_t s, x;
        int ok = 1;
        if (R->group[t] != (int32_t)t || size[t] < 2)
            continue;
        for (s = 0; s < R->nt && ok; s++) {
            int f;
            if (R->group[s] != (int32_t)t)
                continue;
            for (f = 0; f < 4 && ok; f++) {
                const double *a[3];
                int j, q = 0, in;
                int32_t nb = R->nbr[4 * s + (size_t)f];
                if (nb >= 0 && R->group[nb / 4] == (int32_t)t)
                    continue;
                for (j = 0; j < 4; j++)
                    if (j != f)
                        a[q++] = R->xyz + 3 * (size_t)R->tet[4 * s + (size_t)j];
                in = sgnl(m3t_orient_p(a[0], a[1], a[2], R->xyz + 3 * (size_t)R->tet[4 * s + (size_t)f]));
                if (sgnl(m3t_orient(a[0], a[1], a[2], R->c + 3 * t)) == -in)
                    ok = 0;
                for (x = 0; x < R->nt && ok; x++)
                    if (R->group[x] == (int32_t)t)
                        for (j = 0; j < 4; j++)
                            if (sgnl(m3t_orient_p(a[0], a[1], a[2],
                                                  R->xyz + 3 * (size_t)R->tet[4 * x + (size_t)j])) == -in)
                                ok = 0;
            }
        }
        if (ok) {
            R->merged += (size_t)size[t];
            continue;
        }
        R->dissolved++;
        for (s = 0; s < R->nt; s++)
            if (R->group[s] == (int32_t)t)
                R->group[s] = (int32_t)s, size[s] = 1;
    }
    /* compliance: the centre's barycentric signs */
    R->nc = R->nbnd = R->nbnc = 0;
    for (t = 0; t < R->nt; t++) {
        const cvm_index *v = R->tet + 4 * t;
        int f, bnd = 0, nc = 0, kept = size[R->group[t]] >= 2;
        for (f = 0; f < 4; f++) {
            const double *a[3];
            int j, q = 0, in;
            for (j = 0; j < 4; j++)
                if (j != f)
                    a[q++] = R->xyz + 3 * (size_t)v[j];
            bnd |= R->nbr[4 * t + (size_t)f] < 0;
            in = sgnl(m3t_orient_p(a[0], a[1], a[2], R->xyz + 3 * (size_t)v[f]));
            if (sgnl(m3t_orient(a[0], a[1], a[2], R->c + 3 * t)) == -in &&
                (!kept || !mf[4 * t + (size_t)f]))
                nc = 1;
        }
        R->nbnd += (size_t)bnd;
        R->nc += (size_t)nc;
        R->nbnc += (size_t)(nc && bnd);
    }
    free(lsum);
    free(size);
    free(mf);
}

static void m3t_free(m3t_ref *R)
{
    free(R->xyz);
    free(R->tet);
    free(R->nbr);
    free(R->c);
    free(R->group);
}

static double measure(cvm_mesh *m, cvm_measure which)
{
    double v = -1;
    ck_assert_msg(cvm_mesh_get_measure(&v, m, which) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    return v;
}

/* The library against the recount; the counts checked exactly. */
static void agree(cvm_mesh *m, const m3t_ref *R, int compare_compliance)
{
    cvm_index *g = malloc(R->nt * sizeof *g);
    size_t t;
    ck_assert_ptr_nonnull(g);
    ck_assert_int_eq(cvm_mesh_copy_dual3_merge_groups(g, R->nt, m), CVM_OK);
    for (t = 0; t < R->nt; t++) {
        ck_assert_msg(g[t] == R->group[t], "tet %lu: group %ld, recount %ld", (unsigned long)t,
                      (long)g[t], (long)R->group[t]);
        ck_assert_int_le(g[t], (cvm_index)t);
        ck_assert_int_eq(g[g[t]], g[t]);
    }
    ck_assert_double_eq_tol(measure(m, CVM_MEASURE_DUAL3_MERGED_PCT),
                            100.0 * (double)R->merged / (double)R->nt, 1e-9);
    ck_assert_double_eq(measure(m, CVM_MEASURE_DUAL3_MERGE_DISSOLVED), (double)R->dissolved);
    if (compare_compliance) {
        ck_assert_double_eq_tol(measure(m, CVM_MEASURE_DUAL3_NONCOMPLIANT_PCT),
                                100.0 * (double)R->nc / (double)R->nt, 1e-9);
        ck_assert_double_eq_tol(measure(m, CVM_MEASURE_DUAL3_NONCOMPLIANT_BOUNDARY_PCT),
                                R->nbnd ? 100.0 * (double)R->nbnc / (double)R->nbnd : 0, 1e-9);
    }
    free(g);
}

START_TEST(cubic_lattice_merges_each_cube)
{
    cvm_mesh *m = lattice(4, 0, 0);
    m3t_ref R;
    double out704 = measure(m, CVM_MEASURE_CIRCUMCENTRE_OUTSIDE_PCT);
    m3t_recount(&R, m, 0.1);
    ck_assert_uint_eq(R.merged, R.nt); /* every tetrahedron in its cube's group */
    ck_assert_uint_eq(R.dissolved, 0);
    ck_assert_uint_eq(R.nc, 0);
    agree(m, &R, 1);
    ck_assert_double_eq(measure(m, CVM_MEASURE_DUAL3_MERGED_PCT), 100.0);
    ck_assert_double_eq(measure(m, CVM_MEASURE_DUAL3_NONCOMPLIANT_PCT), 0.0);
    ck_assert_double_eq(measure(m, CVM_MEASURE_DUAL3_NONCOMPLIANT_BOUNDARY_PCT), 0.0);
    ck_assert(out704 >= 0); /* 0 for Kuhn cubes, > 0 for the 5-tetrahedron split */
    {
        /* 27 cubes: 27 groups, each of 5 or 6 tetrahedra */
        cvm_index *g = malloc(R.nt * sizeof *g);
        size_t t, roots = 0;
        ck_assert_ptr_nonnull(g);
        ck_assert_int_eq(cvm_mesh_copy_dual3_merge_groups(g, R.nt, m), CVM_OK);
        for (t = 0; t < R.nt; t++)
            roots += g[t] == (cvm_index)t;
        ck_assert_uint_eq(roots, 27);
        free(g);
    }
    /* tol 0 merges nothing; the non-compliant are then those outside */
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL3_MERGE_TOL, 0), CVM_OK);
    ck_assert_double_eq(measure(m, CVM_MEASURE_DUAL3_MERGED_PCT), 0.0);
    ck_assert_double_eq(measure(m, CVM_MEASURE_DUAL3_NONCOMPLIANT_PCT), out704);
    m3t_free(&R);
    m3t_recount(&R, m, 0);
    agree(m, &R, 1);
    m3t_free(&R);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(bcc_lattice_merges_nothing)
{
    cvm_mesh *m = lattice(4, 1, 0);
    m3t_ref R;
    m3t_recount(&R, m, 0.1);
    agree(m, &R, 1);
    ck_assert_uint_eq(R.merged, 0);
    ck_assert_double_eq(measure(m, CVM_MEASURE_DUAL3_MERGED_PCT), 0.0);
    /* well-centred inside: every non-compliant tetrahedron has a hull face (the
       half-octahedra at the box sides tie, but their centre lies beyond the box
       side: those groups are not star-shaped and are dissolved) */
    ck_assert_uint_gt(R.nc, 0);
    ck_assert_uint_eq(R.nc, R.nbnc);
    /* nothing merged: the non-compliant are exactly those outside */
    ck_assert_double_eq(measure(m, CVM_MEASURE_DUAL3_NONCOMPLIANT_PCT),
                        measure(m, CVM_MEASURE_CIRCUMCENTRE_OUTSIDE_PCT));
    m3t_free(&R);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(perturbed_lattice_dissolves_concave_cubes)
{
    cvm_mesh *m = lattice(4, 0, 1.0 / 128);
    m3t_ref R;
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL3_MERGE_TOL, 1), CVM_OK);
    m3t_recount(&R, m, 1);
    ck_assert_uint_gt(R.dissolved, 0);
    ck_assert_uint_gt(R.merged, 0);
    agree(m, &R, 0);
    m3t_free(&R);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(statuses_options_and_determinism)
{
    cvm_mesh *m, *m2;
    cvm_index g[4], *a, *b;
    size_t nt;
    double v;
    cvm_bounds bd;
    ck_assert_int_eq(cvm_option_bounds(&bd, CVM_OPT_DUAL3_MERGE_TOL), CVM_OK);
    ck_assert_double_eq(bd.lo, 0);
    ck_assert_double_eq(bd.hi, 1);
    ck_assert_double_eq(bd.def, 0.1);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_get_option(&v, m, CVM_OPT_DUAL3_MERGE_TOL), CVM_OK);
    ck_assert_double_eq(v, 0.1);
    ck_assert_int_ne(cvm_mesh_set_option(m, CVM_OPT_DUAL3_MERGE_TOL, NAN), CVM_OK);
    ck_assert_int_ne(cvm_mesh_set_option(m, CVM_OPT_DUAL3_MERGE_TOL, -1), CVM_OK);
    ck_assert_int_ne(cvm_mesh_set_option(m, CVM_OPT_DUAL3_MERGE_TOL, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_get_option(&v, m, CVM_OPT_DUAL3_MERGE_TOL), CVM_OK);
    ck_assert_double_eq(v, 0.1);
    /* a 2D handle, then a 3D one with nothing triangulated */
    ck_assert_int_eq(cvm_mesh_copy_dual3_merge_groups(g, 4, NULL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_dual3_merge_groups(g, 4, m), CVM_E_UNSUPPORTED);
    {
        const double p[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
        ck_assert_int_eq(cvm_mesh_set_points(m, p, 4, 3), CVM_OK);
        ck_assert_int_eq(cvm_mesh_copy_dual3_merge_groups(g, 4, m), CVM_E_STATE);
        ck_assert_int_eq(cvm_mesh_get_measure(&v, m, CVM_MEASURE_DUAL3_MERGED_PCT), CVM_E_STATE);
        ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
        ck_assert_int_eq(cvm_mesh_copy_dual3_merge_groups(NULL, 1, m), CVM_E_NULL_ARG);
        g[0] = 7;
        ck_assert_int_eq(cvm_mesh_copy_dual3_merge_groups(g, 0, m), CVM_E_BUFFER_TOO_SMALL);
        ck_assert_int_eq(g[0], 7);
        ck_assert_int_eq(cvm_mesh_copy_dual3_merge_groups(g, 1, m), CVM_OK);
        ck_assert_int_eq(g[0], 0);
        ck_assert_double_eq(measure(m, CVM_MEASURE_DUAL3_MERGED_PCT), 0);
        /* the corner tetrahedron's circumcentre (1/2, 1/2, 1/2) lies outside */
        ck_assert_double_eq(measure(m, CVM_MEASURE_DUAL3_NONCOMPLIANT_PCT), 100);
        ck_assert_double_eq(measure(m, CVM_MEASURE_DUAL3_NONCOMPLIANT_BOUNDARY_PCT), 100);
    }
    cvm_mesh_free(m);
    /* two runs, two handles: the same groups */
    m = lattice(4, 0, 1.0 / 128);
    m2 = lattice(4, 0, 1.0 / 128);
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    a = malloc(nt * sizeof *a);
    b = malloc(nt * sizeof *b);
    ck_assert(a && b);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL3_MERGE_TOL, 1), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m2, CVM_OPT_DUAL3_MERGE_TOL, 1), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_dual3_merge_groups(a, nt, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_dual3_merge_groups(b, nt, m2), CVM_OK);
    ck_assert_mem_eq(a, b, nt * sizeof *a);
    ck_assert_int_eq(cvm_mesh_copy_dual3_merge_groups(b, nt, m), CVM_OK);
    ck_assert_mem_eq(a, b, nt * sizeof *a);
    ck_assert_double_eq(measure(m, CVM_MEASURE_DUAL3_NONCOMPLIANT_PCT),
                        measure(m2, CVM_MEASURE_DUAL3_NONCOMPLIANT_PCT));
    free(a);
    free(b);
    cvm_mesh_free(m);
    cvm_mesh_free(m2);
}
END_TEST

START_TEST(vtu_with_merged_cells)
{
    cvm_mesh *m = lattice(4, 0, 0);
    char *dir = iotest_tmpdir(), out[600], *text;
    size_t nt;
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    snprintf(out, sizeof out, "%s/merged.vtu", dir);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_VTU_MERGED_CELLS, 1), CVM_OK);
    ck_assert_int_eq(cvm_mesh_write(m, out), CVM_OK);
    text = iotest_slurp(out, NULL);
    ck_assert_ptr_nonnull(text);
    /* the 27 cubes, each one polyhedron of 12 outer triangles (2 per square side) */
    ck_assert_ptr_nonnull(strstr(text, "NumberOfCells=\"27\""));
    ck_assert_ptr_nonnull(strstr(text, "Name=\"faceoffsets\""));
    {
        const char *q = strstr(text, "Name=\"faces\"");
        int c, k;
        ck_assert_ptr_nonnull(q);
        q = strchr(q, '>') + 1;
        for (c = 0; c < 27; c++) {
            char *end;
            long nf = strtol(q, &end, 10);
            ck_assert_int_eq(nf, 12);
            q = end;
            for (k = 0; k < 4 * 12; k++) {
                long x = strtol(q, &end, 10);
                ck_assert_ptr_ne(end, q);
                if (k % 4 == 0)
                    ck_assert_int_eq(x, 3);
                q = end;
            }
        }
    }
    free(text);
    /* tol 0: every tetrahedron a polyhedron of its own 4 faces */
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL3_MERGE_TOL, 0), CVM_OK);
    ck_assert_int_eq(cvm_mesh_write(m, out), CVM_OK);
    text = iotest_slurp(out, NULL);
    ck_assert_ptr_nonnull(text);
    {
        char want[64];
        snprintf(want, sizeof want, "NumberOfCells=\"%lu\"", (unsigned long)nt);
        ck_assert_ptr_nonnull(strstr(text, want));
    }
    free(text);
    /* the option off: tetrahedra as before */
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_VTU_MERGED_CELLS, 0), CVM_OK);
    ck_assert_int_eq(cvm_mesh_write(m, out), CVM_OK);
    text = iotest_slurp(out, NULL);
    ck_assert_ptr_nonnull(text);
    ck_assert_ptr_null(strstr(text, "faceoffsets"));
    free(text);
    remove(out);
    iotest_rmdir(dir);
    free(dir);
    cvm_mesh_free(m);
}
END_TEST

static void oom_setup(cvm_mesh *m, void *arg)
{
    size_t np;
    double *p = lattice_points(3, 0, 0, &np);
    (void)arg;
    ck_assert_int_eq(cvm_mesh_set_points(m, p, np, 3), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_VTU_MERGED_CELLS, 1), CVM_OK);
    free(p);
}

static cvm_status oom_run(cvm_mesh *m, void *arg)
{
    cvm_index g[64];
    size_t nt;
    double v;
    cvm_status s;
    if ((s = cvm_mesh_triangulate(m)))
        return s;
    if ((s = cvm_mesh_get_measure(&v, m, CVM_MEASURE_DUAL3_NONCOMPLIANT_PCT)))
        return s;
    ck_assert_double_eq(v, 0);
    if ((s = cvm_mesh_get_measure(&v, m, CVM_MEASURE_DUAL3_MERGED_PCT)))
        return s;
    ck_assert_double_eq(v, 100);
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    ck_assert_uint_le(nt, 64);
    g[0] = -7;
    s = cvm_mesh_copy_dual3_merge_groups(g, nt, m);
    if (s == CVM_E_NOMEM)
        ck_assert_int_eq(g[0], -7); /* nothing written */
    if (s)
        return s;
    return cvm_mesh_write(m, (const char *)arg); /* the merged cells of a .vtu */
}

START_TEST(oom_at_every_allocation)
{
    char *dir = iotest_tmpdir(), out[600];
    snprintf(out, sizeof out, "%s/oom.vtu", dir);
    cvmtest_oom_sweep(oom_setup, oom_run, NULL, out);
    remove(out);
    iotest_rmdir(dir);
    free(dir);
}
END_TEST

TCase *dual3_merge_tcase(void)
{
    TCase *tc = tcase_create("merge3");
    tcase_set_timeout(tc, 600);
    tcase_add_test(tc, cubic_lattice_merges_each_cube);
    tcase_add_test(tc, bcc_lattice_merges_nothing);
    tcase_add_test(tc, perturbed_lattice_dissolves_concave_cubes);
    tcase_add_test(tc, statuses_options_and_determinism);
    tcase_add_test(tc, vtu_with_merged_cells);
    tcase_add_test(tc, oom_at_every_allocation);
    return tc;
}
