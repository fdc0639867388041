/*
 * test_optimise3.c - cvm_mesh_optimise_dual3(): statuses and options; on the
 * generated cube and tetrahedron, the tetrahedra and surface kept, every face
 * that was regular still regular (exact power test), the outside count agreeing
 * with an independent recomputation, the report; the same bytes for two runs
 * and for 1 and 2 threads; a cancelled run leaves a valid mesh; OOM everywhere.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "dual3/dual3_tests.h"
#include "generate3/g3_util.h"
#include "geom/geom_internal.h"
#include "support/oom_sweep.h"
#include "support/skip.h"

static cvm_mesh *generated(const char *name, double h, int uniform)
{
    cvm_mesh *m;
    char path[1024];
    g3_data3d(path, sizeof path, name);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_msg(cvm_mesh_read(m, path) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    if (uniform)
        ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_GEN3_SIZE_FROM_SURFACE, 0), CVM_OK);
    ck_assert_msg(cvm_mesh_generate3(m, h) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    return m;
}

static double *weights_of(const cvm_mesh *m, size_t nv)
{
    double *w = malloc((nv + 1) * sizeof *w);
    ck_assert_ptr_nonnull(w);
    ck_assert_int_eq(cvm_mesh_copy_weights(w, nv, m), CVM_OK);
    return w;
}

/* Interior faces: slot pairs (4 t + f, 4 u + g), from sorting the faces. */
typedef struct d3t_face {
    cvm_index v[3];
    int32_t slot;
} d3t_face;

static int cmp_face(const void *pa, const void *pb)
{
    const d3t_face *a = pa, *b = pb;
    int k;
    for (k = 0; k < 3; k++)
        if (a->v[k] != b->v[k])
            return a->v[k] < b->v[k] ? -1 : 1;
    return (a->slot > b->slot) - (a->slot < b->slot);
}

static void sort3(cvm_index *v)
{
    cvm_index t;
    if (v[0] > v[1]) t = v[0], v[0] = v[1], v[1] = t;
    if (v[1] > v[2]) t = v[1], v[1] = v[2], v[2] = t;
    if (v[0] > v[1]) t = v[0], v[0] = v[1], v[1] = t;
}

/* nbr[4 t + f] = 4 u + g or -1. */
static int32_t *adjacency(const g3_mesh *g)
{
    size_t n = 4 * g->nt, i;
    d3t_face *f = malloc((n + 1) * sizeof *f);
    int32_t *nbr = malloc((n + 1) * sizeof *nbr);
    ck_assert(f && nbr);
    for (i = 0; i < n; i++) {
        int k, j = 0;
        for (k = 0; k < 4; k++)
            if (k != (int)(i % 4))
                f[i].v[j++] = g->tet[4 * (i / 4) + (size_t)k];
        sort3(f[i].v);
        f[i].slot = (int32_t)i;
        nbr[i] = -1;
    }
    qsort(f, n, sizeof *f, cmp_face);
    for (i = 0; i + 1 < n; i++)
        if (memcmp(f[i].v, f[i + 1].v, sizeof f[i].v) == 0) {
            ck_assert_msg(i + 2 >= n || memcmp(f[i].v, f[i + 2].v, sizeof f[i].v) != 0,
                          "a face of three tetrahedra");
            nbr[f[i].slot] = f[i + 1].slot;
            nbr[f[i + 1].slot] = f[i].slot;
            i++;
        }
    free(f);
    return nbr;
}

/* Per interior face (slot i < nbr[i]): 1 when locally regular by the exact,
 * perturbed power test (lifted orient4d), as the kernel decides it. */
static unsigned char *regular_faces(const g3_mesh *g, const double *w, const int32_t *nbr)
{
    size_t i, n = 4 * g->nt;
    unsigned char *ok = calloc(n + 1, 1);
    ck_assert_ptr_nonnull(ok);
    for (i = 0; i < n; i++) {
        const cvm_index *a = g->tet + 4 * (i / 4);
        cvm_index e;
        const double *X = g->xyz;
        if (nbr[i] < 0 || (int32_t)i > nbr[i])
            continue;
        e = g->tet[4 * (size_t)(nbr[i] / 4) + (size_t)(nbr[i] % 4)];
        ok[i] = cvm__power3d_sos(X + 3 * a[0], X + 3 * a[1], X + 3 * a[2], X + 3 * a[3], X + 3 * e,
                                 w[a[0]], w[a[1]], w[a[2]], w[a[3]], w[e], a[0], a[1], a[2], a[3],
                                 e) < 0;
    }
    return ok;
}

/* The outside count recomputed independently: barycentric coordinates of the
 * power vertex in long double. *ties: tetrahedra with a coordinate within
 * 1e-9 of 0 (undecided here). Also the boundary tetrahedra and their count. */
static size_t outside_count(const g3_mesh *g, const double *w, const int32_t *nbr, size_t *ties,
                            size_t *nb, size_t *bout)
{
    size_t t, n = 0;
    *ties = *nb = *bout = 0;
    for (t = 0; t < g->nt; t++) {
        const double *P[4];
        long double A[3][3], r[3], x[3], det, lam[4], vol, scale = 0;
        int i, j, out = 0, tie = 0, bnd = 0;
        for (i = 0; i < 4; i++) {
            P[i] = g->xyz + 3 * (size_t)g->tet[4 * t + (size_t)i];
            bnd |= nbr[4 * t + (size_t)i] < 0;
        }
        /* 2 (P_i - P_0) . x = |P_i - P_0|^2 - (w_i - w_0), x relative to P_0 */
        for (i = 0; i < 3; i++) {
            long double d2 = 0;
            for (j = 0; j < 3; j++) {
                A[i][j] = (long double)P[i + 1][j] - P[0][j];
                d2 += A[i][j] * A[i][j];
            }
            r[i] = 0.5L * (d2 - ((long double)w[g->tet[4 * t + (size_t)i + 1]] -
                                 w[g->tet[4 * t]]));
            scale = d2 > scale ? d2 : scale;
        }
        det = A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) -
              A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
              A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
        ck_assert(det != 0);
        for (i = 0; i < 3; i++) { /* Cramer */
            long double B[3][3];
            memcpy(B, A, sizeof B);
            for (j = 0; j < 3; j++)
                B[j][i] = r[j];
            x[i] = (B[0][0] * (B[1][1] * B[2][2] - B[1][2] * B[2][1]) -
                    B[0][1] * (B[1][0] * B[2][2] - B[1][2] * B[2][0]) +
                    B[0][2] * (B[1][0] * B[2][1] - B[1][1] * B[2][0])) / det;
        }
        /* barycentric: x = sum_{i>=1} lam_i (P_i - P_0): solve A^T lam = x */
        vol = det;
        for (i = 0; i < 3; i++) {
            long double B[3][3];
            for (j = 0; j < 3; j++) {
                int k;
                for (k = 0; k < 3; k++)
                    B[j][k] = A[k][j];
            }
            for (j = 0; j < 3; j++)
                B[j][i] = x[j];
            lam[i + 1] = (B[0][0] * (B[1][1] * B[2][2] - B[1][2] * B[2][1]) -
                          B[0][1] * (B[1][0] * B[2][2] - B[1][2] * B[2][0]) +
                          B[0][2] * (B[1][0] * B[2][1] - B[1][1] * B[2][0])) / vol;
        }
        lam[0] = 1 - lam[1] - lam[2] - lam[3];
        (void)scale;
        for (i = 0; i < 4; i++) {
            if (fabsl(lam[i]) < 1e-9L)
                tie = 1;
            else if (lam[i] < 0)
                out = 1;
        }
        if (tie && !out)
            (*ties)++;
        n += out;
        *nb += bnd;
        *bout += out && bnd;
    }
    return n;
}

START_TEST(statuses_and_options)
{
    cvm_mesh *m;
    cvm_bounds b;
    double xyz[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}, v;
    ck_assert_int_eq(cvm_mesh_optimise_dual3(NULL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_optimise_dual3(m), CVM_E_STATE); /* 2D handle */
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "2D"));
    ck_assert_int_eq(cvm_mesh_set_points(m, xyz, 4, 3), CVM_OK);
    ck_assert_int_eq(cvm_mesh_optimise_dual3(m), CVM_E_STATE); /* not tetrahedralised */
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "no tetrahedral mesh"));
    ck_assert_int_eq(cvm_mesh_get_report(&v, m, CVM_REPORT_DUAL3_SWEEPS), CVM_OK);
    ck_assert_double_eq(v, 0);
    ck_assert_int_eq(cvm_mesh_get_report(&v, m, (cvm_report)749), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL3_MAX_SWEEPS, -1), CVM_E_OPTION_RANGE);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL3_MAX_SWEEPS, 1.5), CVM_E_OPTION_RANGE);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL3_MIN_DIHEDRAL_DEG, 61), CVM_E_OPTION_RANGE);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL3_MIN_DIHEDRAL_DEG, NAN),
                     CVM_E_OPTION_RANGE);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL3_BUDGET, 0), CVM_E_OPTION_RANGE);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL3_MARGIN, 0.5), CVM_E_OPTION_RANGE);
    ck_assert_int_eq(cvm_option_bounds(&b, CVM_OPT_DUAL3_MAX_SWEEPS), CVM_OK);
    ck_assert_double_eq(b.def, 50);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL3_FLIPS, 2), CVM_E_OPTION_RANGE);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL3_SOLVER, 0), CVM_E_OPTION_RANGE);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL3_SOLVER, 4), CVM_E_OPTION_RANGE);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL3_CUCKOO_BUDGET, 39), CVM_E_OPTION_RANGE);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL3_SLIDE_BOUNDARY, 3), CVM_E_OPTION_RANGE);
    ck_assert_int_eq(cvm_option_bounds(&b, CVM_OPT_DUAL3_SOLVER), CVM_OK);
    ck_assert_double_eq(b.def, 1);
    ck_assert_int_eq(cvm_option_bounds(&b, CVM_OPT_DUAL3_FLIPS), CVM_OK);
    ck_assert_double_eq(b.def, 1);
    ck_assert_int_eq(cvm_option_bounds(&b, CVM_OPT_DUAL3_MIN_DIHEDRAL_DEG), CVM_OK);
    ck_assert_double_eq(b.def, 10);
    /* a Delaunay tetrahedralisation of points: one tetrahedron, nothing outside */
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_optimise_dual3(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_get_report(&v, m, CVM_REPORT_DUAL3_OUTSIDE_AFTER_PCT), CVM_OK);
    ck_assert_double_eq(v, 0);
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    cvm_mesh_free(m);
}
END_TEST

/* Interior faces (each once) that are not locally regular: the tetrahedra of a
 * generated mesh with no internal facets, so every interior face is unconstrained. */
static size_t irregular_faces(const g3_mesh *g, const double *w, const int32_t *nbr)
{
    unsigned char *reg = regular_faces(g, w, nbr);
    size_t i, n = 0;
    for (i = 0; i < 4 * g->nt; i++)
        n += nbr[i] >= 0 && (int32_t)i < nbr[i] && !reg[i];
    free(reg);
    return n;
}

/* Interior faces whose far vertex lies strictly inside the tetrahedron's orthosphere
 * (exact, no perturbation: a tie is no violation). */
static size_t strict_violations(const g3_mesh *g, const double *w, const int32_t *nbr)
{
    size_t i, n = 0;
    for (i = 0; i < 4 * g->nt; i++) {
        const cvm_index *a = g->tet + 4 * (i / 4);
        const double *X = g->xyz;
        cvm_index e;
        if (nbr[i] < 0)
            continue;
        e = g->tet[4 * (size_t)(nbr[i] / 4) + (size_t)(nbr[i] % 4)];
        n += cvm__power3d(X + 3 * a[0], X + 3 * a[1], X + 3 * a[2], X + 3 * a[3], X + 3 * e,
                          w[a[0]], w[a[1]], w[a[2]], w[a[3]], w[e]) > 0;
    }
    return n;
}

/* Optimise the generated mesh m and check every promise of the contract; with flips
 * the tetrahedra may change, but the vertices, the surface triangles (as faces), the
 * volume stay, and no face that was regular turns irregular (the irregular ones left
 * can only be faces of the input that no flip could repair). */
static void optimise_and_check(cvm_mesh *m, int sweeps, int slide, int flips)
{
    g3_mesh a, b;
    int32_t *nbr, *nbr1;
    double *w0, *w1, v, before, after, bbefore, bafter;
    unsigned char *reg0, *reg1;
    size_t i, ties0, ties1, nb, bout, out0, out1, nreg0 = 0, lost = 0, moved = 0;
    double vol0;
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL3_MAX_SWEEPS, sweeps), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL3_SLIDE_BOUNDARY, slide), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL3_FLIPS, flips), CVM_OK);
    ck_assert_int_eq(cvm_mesh_get_measure(&vol0, m, CVM_MEASURE_VOLUME), CVM_OK);
    g3_mesh_get(&a, m);
    w0 = weights_of(m, a.nv);
    nbr = adjacency(&a);
    reg0 = regular_faces(&a, w0, nbr);
    out0 = outside_count(&a, w0, nbr, &ties0, &nb, &bout);
    ck_assert_msg(cvm_mesh_optimise_dual3(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    g3_mesh_get(&b, m);
    w1 = weights_of(m, b.nv);
    /* the same vertices, tetrahedra and surface: nothing dropped, every face kept */
    ck_assert_uint_eq(a.nv, b.nv);
    if (!flips) {
        ck_assert_uint_eq(a.nt, b.nt);
        ck_assert(memcmp(a.tet, b.tet, 4 * a.nt * sizeof *a.tet) == 0);
    }
    ck_assert_uint_eq(a.nf, b.nf);
    ck_assert(memcmp(a.face, b.face, 3 * a.nf * sizeof *a.face) == 0);
    for (i = 0; i < b.nv; i++) /* no vertex lost */
        ck_assert_int_gt(b.valence[i], 0);
    for (i = 0; i < a.nf; i++)
        ck_assert(g3_face_on_boundary(&b, b.face[3 * i], b.face[3 * i + 1], b.face[3 * i + 2]));
    /* boundary vertices keep their position, or (slide) stay exactly in their face's
       axis-aligned plane; the domain keeps its volume */
    for (i = 0; i < a.nf; i++) {
        int k, ax;
        for (k = 0; k < 3; k++) {
            cvm_index q = a.face[3 * i + (size_t)k];
            if (!slide)
                ck_assert(memcmp(a.xyz + 3 * q, b.xyz + 3 * q, 3 * sizeof *a.xyz) == 0);
            for (ax = 0; ax < 3; ax++) {
                const cvm_index *f = a.face + 3 * i;
                if (a.xyz[3 * f[0] + ax] == a.xyz[3 * f[1] + ax] &&
                    a.xyz[3 * f[0] + ax] == a.xyz[3 * f[2] + ax])
                    ck_assert(b.xyz[3 * q + ax] == a.xyz[3 * q + ax]);
            }
        }
    }
    ck_assert_int_eq(cvm_mesh_get_measure(&v, m, CVM_MEASURE_VOLUME), CVM_OK);
    ck_assert_double_eq_tol(v, vol0, 1e-12 * vol0);
    for (i = 0; i < a.nv; i++)
        moved += memcmp(a.xyz + 3 * i, b.xyz + 3 * i, 3 * sizeof *a.xyz) != 0 || w0[i] != w1[i];
    ck_assert_uint_gt(moved, 0);
    /* positively oriented, exactly */
    for (i = 0; i < b.nt; i++) {
        const cvm_index *t = b.tet + 4 * i;
        ck_assert(cvm__orient3d(b.xyz + 3 * t[0], b.xyz + 3 * t[1], b.xyz + 3 * t[2],
                                b.xyz + 3 * t[3]) > 0);
    }
    /* every face that was regular (exact perturbed power test) still is */
    nbr1 = flips ? adjacency(&b) : nbr;
    if (!flips) {
        reg1 = regular_faces(&b, w1, nbr);
        for (i = 0; i < 4 * a.nt; i++) {
            nreg0 += reg0[i];
            lost += reg0[i] && !reg1[i];
        }
        ck_assert_uint_eq(lost, 0);
        ck_assert_uint_gt(nreg0, 0);
        free(reg1);
    } else {
        size_t bad0 = irregular_faces(&a, w0, nbr), bad1 = irregular_faces(&b, w1, nbr1);
        ck_assert_msg(bad1 <= bad0, "%lu irregular faces after, %lu before", (unsigned long)bad1,
                      (unsigned long)bad0);
        /* no vertex strictly inside an orthosphere unless one was before */
        ck_assert_uint_le(strict_violations(&b, w1, nbr1), strict_violations(&a, w0, nbr));
        for (i = 0; i < 4 * b.nt; i++) /* a face without neighbour is a surface triangle */
            if (nbr1[i] < 0) {
                cvm_index f[3];
                int k, j = 0;
                for (k = 0; k < 4; k++)
                    if (k != (int)(i % 4))
                        f[j++] = b.tet[4 * (i / 4) + (size_t)k];
                ck_assert(g3_face_on_boundary(&a, f[0], f[1], f[2]));
            }
    }
    /* the report against an independent count */
    out1 = outside_count(&b, w1, nbr1, &ties1, &nb, &bout);
    ck_assert_int_eq(cvm_mesh_get_report(&before, m, CVM_REPORT_DUAL3_OUTSIDE_BEFORE_PCT), CVM_OK);
    ck_assert_int_eq(cvm_mesh_get_report(&after, m, CVM_REPORT_DUAL3_OUTSIDE_AFTER_PCT), CVM_OK);
    ck_assert_int_eq(cvm_mesh_get_report(&bbefore, m, CVM_REPORT_DUAL3_OUTSIDE_BOUNDARY_BEFORE_PCT),
                     CVM_OK);
    ck_assert_int_eq(cvm_mesh_get_report(&bafter, m, CVM_REPORT_DUAL3_OUTSIDE_BOUNDARY_AFTER_PCT),
                     CVM_OK);
    ck_assert(fabs(before * (double)a.nt / 100 - (double)out0) <= (double)ties0 + 1e-6);
    ck_assert(fabs(after * (double)b.nt / 100 - (double)out1) <= (double)ties1 + 1e-6);
    ck_assert(nb == 0 || fabs(bafter * (double)nb / 100 - (double)bout) <= (double)ties1 + 1e-6);
    ck_assert_msg(after < before, "outside %g %% -> %g %%", before, after);
    ck_assert(bafter <= bbefore);
    /* the handle's own measure agrees (it reads the weights) */
    ck_assert_int_eq(cvm_mesh_get_measure(&v, m, CVM_MEASURE_CIRCUMCENTRE_OUTSIDE_PCT), CVM_OK);
    ck_assert_double_eq_tol(v, after, 1e-9);
    ck_assert_int_eq(cvm_mesh_get_report(&v, m, CVM_REPORT_DUAL3_SWEEPS), CVM_OK);
    ck_assert(v >= 1 && v <= sweeps);
    ck_assert_int_eq(cvm_mesh_get_report(&v, m, CVM_REPORT_DUAL3_MOVES), CVM_OK);
    ck_assert(v >= 1);
    ck_assert_int_eq(cvm_mesh_get_measure(&v, m, CVM_MEASURE_MIN_DIHEDRAL_DEG), CVM_OK);
    ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    free(reg0);
    free(w0);
    free(w1);
    if (nbr1 != nbr)
        free(nbr1);
    free(nbr);
    g3_mesh_free(&a);
    g3_mesh_free(&b);
}

START_TEST(cube_keeps_faces_and_regularity)
{
    cvm_mesh *m;
    double v;
    if (!g3_with_tetgen())
        CVMTEST_SKIP("the example cube needs TetGen (cocircular squares)");
    m = generated("cube.poly", 0.25, 1);
    optimise_and_check(m, 3, 1, 0);
    cvm_mesh_free(m);
    m = generated("cube.poly", 0.25, 1);
    optimise_and_check(m, 6, 1, 1);
    ck_assert_int_eq(cvm_mesh_get_report(&v, m, CVM_REPORT_DUAL3_FLIPS), CVM_OK);
    ck_assert_double_gt(v, 0); /* the flip path ran */
    cvm_mesh_free(m);
}
END_TEST

START_TEST(tetra_keeps_faces_and_regularity)
{
    int flips;
    for (flips = 0; flips < 2; flips++) {
        cvm_mesh *m = generated("tetra.off", 0.3, 0);
        optimise_and_check(m, 3, 0, flips);
        cvm_mesh_free(m);
        m = generated("tetra.off", 0.3, 0);
        optimise_and_check(m, 3, 1, flips);
        cvm_mesh_free(m);
    }
}
END_TEST

/* The cuckoo search alone (2) and after the compass search (3): the same exact
 * guarantees, and the same bytes from run to run (streams keyed by seed, sweep,
 * vertex). */
START_TEST(cuckoo_keeps_faces_and_regularity)
{
    int solver;
    for (solver = 2; solver <= 3; solver++) {
        cvm_mesh *m = generated("tetra.off", 0.3, 0), *m2;
        double *w, *w2;
        g3_mesh a, b;
        ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL3_SOLVER, solver), CVM_OK);
        ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL3_CUCKOO_BUDGET, 80), CVM_OK);
        optimise_and_check(m, 3, 1, 1);
        m2 = generated("tetra.off", 0.3, 0);
        ck_assert_int_eq(cvm_mesh_set_option(m2, CVM_OPT_DUAL3_SOLVER, solver), CVM_OK);
        ck_assert_int_eq(cvm_mesh_set_option(m2, CVM_OPT_DUAL3_CUCKOO_BUDGET, 80), CVM_OK);
        ck_assert_int_eq(cvm_mesh_set_option(m2, CVM_OPT_DUAL3_MAX_SWEEPS, 3), CVM_OK);
        ck_assert_int_eq(cvm_mesh_optimise_dual3(m2), CVM_OK);
        g3_mesh_get(&a, m);
        g3_mesh_get(&b, m2);
        w = weights_of(m, a.nv);
        w2 = weights_of(m2, b.nv);
        ck_assert(a.nv == b.nv && a.nt == b.nt);
        ck_assert(memcmp(a.xyz, b.xyz, 3 * a.nv * sizeof *a.xyz) == 0);
        ck_assert(memcmp(w, w2, a.nv * sizeof *w) == 0);
        ck_assert(memcmp(a.tet, b.tet, 4 * a.nt * sizeof *a.tet) == 0);
        free(w);
        free(w2);
        g3_mesh_free(&a);
        g3_mesh_free(&b);
        cvm_mesh_free(m);
        cvm_mesh_free(m2);
    }
}
END_TEST

/* CVM_OPT_DUAL3_ESCALATE: after the first stall the run goes on from where the
 * default run stops (the same sweeps up to there), and no move raises the count
 * outside, so it never ends with more tetrahedra outside; it keeps every exact
 * guarantee of optimise_and_check(). Measured: 29.13 -> 29.07 % outside, 23 -> 33
 * sweeps (the tetrahedron's sharp corners hold the rest). */
START_TEST(escalate_goes_on_after_a_stall)
{
    cvm_mesh *m1 = generated("tetra.off", 0.2, 0), *m8 = generated("tetra.off", 0.2, 0);
    double out1, out8, sw1, sw8;
    cvm_bounds b;
    ck_assert_int_eq(cvm_option_bounds(&b, CVM_OPT_DUAL3_ESCALATE), CVM_OK);
    ck_assert(b.lo == 1 && b.hi == 64 && b.def == 1 && b.is_integer);
    ck_assert_int_eq(cvm_mesh_set_option(m8, CVM_OPT_DUAL3_ESCALATE, 0), CVM_E_OPTION_RANGE);
    ck_assert_int_eq(cvm_mesh_set_option(m8, CVM_OPT_DUAL3_ESCALATE, 8), CVM_OK);
    optimise_and_check(m1, 200, 1, 1);
    optimise_and_check(m8, 200, 1, 1);
    ck_assert_int_eq(cvm_mesh_get_report(&out1, m1, CVM_REPORT_DUAL3_OUTSIDE_AFTER_PCT), CVM_OK);
    ck_assert_int_eq(cvm_mesh_get_report(&out8, m8, CVM_REPORT_DUAL3_OUTSIDE_AFTER_PCT), CVM_OK);
    ck_assert_int_eq(cvm_mesh_get_report(&sw1, m1, CVM_REPORT_DUAL3_SWEEPS), CVM_OK);
    ck_assert_int_eq(cvm_mesh_get_report(&sw8, m8, CVM_REPORT_DUAL3_SWEEPS), CVM_OK);
    ck_assert_double_le(out8, out1);
    ck_assert_double_ge(sw8, sw1);
    cvm_mesh_free(m1);
    cvm_mesh_free(m8);
}
END_TEST

/* The distance from p to the plane of the triangle abc. */
static double plane_dist(const double *p, const double *a, const double *b, const double *c)
{
    double u[3], w[3], n[3], len;
    int k;
    for (k = 0; k < 3; k++)
        u[k] = b[k] - a[k], w[k] = c[k] - a[k];
    n[0] = u[1] * w[2] - u[2] * w[1], n[1] = u[2] * w[0] - u[0] * w[2], n[2] = u[0] * w[1] - u[1] * w[0];
    len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    return fabs(n[0] * (p[0] - a[0]) + n[1] * (p[1] - a[1]) + n[2] * (p[2] - a[2])) / len;
}

/* CVM_OPT_DUAL3_SLIDE_BOUNDARY 2 on the tetrahedron (oblique planar faces, which slide 1
 * keeps fixed): boundary vertices inside a face that move stay in its plane (to
 * rounding); the surface triangles stay faces; the volume stays. */
START_TEST(slide_surface_keeps_vertices_on_the_surface)
{
    cvm_mesh *m;
    g3_mesh a, b;
    double vol0, vol1;
    size_t i, j, moved = 0;
    char path[1024];
    g3_data3d(path, sizeof path, "tetra.off");
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_msg(cvm_mesh_read(m, path) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    /* the faces re-meshed: vertices inside them */
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_GEN3_SURFACE, CVM_GEN3_SURFACE_REMESH_ALL),
                     CVM_OK);
    ck_assert_msg(cvm_mesh_generate3(m, 0.4) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL3_SLIDE_BOUNDARY, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL3_MAX_SWEEPS, 4), CVM_OK);
    g3_mesh_get(&a, m);
    vol0 = g3_tet_volume(&a);
    ck_assert_msg(cvm_mesh_optimise_dual3(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    g3_mesh_get(&b, m);
    vol1 = g3_tet_volume(&b);
    ck_assert_double_eq_tol(vol1, vol0, 1e-12 * vol0);
    ck_assert_uint_eq(a.nf, b.nf);
    for (i = 0; i < a.nf; i++)
        ck_assert(g3_face_on_boundary(&b, a.face[3 * i], a.face[3 * i + 1], a.face[3 * i + 2]));
    for (i = 0; i < a.nv; i++) {
        int on = 0, bnd = 0;
        if (memcmp(a.xyz + 3 * i, b.xyz + 3 * i, 3 * sizeof *a.xyz) == 0)
            continue;
        /* a boundary vertex that moved lies in the plane of every face it had */
        for (j = 0; j < a.nf; j++) {
            const cvm_index *f = a.face + 3 * j;
            if (f[0] != (cvm_index)i && f[1] != (cvm_index)i && f[2] != (cvm_index)i)
                continue;
            bnd = 1;
            on += plane_dist(b.xyz + 3 * i, a.xyz + 3 * f[0], a.xyz + 3 * f[1],
                             a.xyz + 3 * f[2]) <= 1e-12;
            ck_assert(plane_dist(b.xyz + 3 * i, a.xyz + 3 * f[0], a.xyz + 3 * f[1],
                                 a.xyz + 3 * f[2]) <= 1e-12);
        }
        moved += bnd && on;
    }
    (void)moved; /* whether one moves depends on the mesh (with or without TetGen):
                    test_own_mesh.c makes sure on a rotated cube */
    g3_mesh_free(&a);
    g3_mesh_free(&b);
    cvm_mesh_free(m);
}
END_TEST

static void run_bytes(double threads, double **xyz, double **w, size_t *nv, cvm_index **tet,
                      size_t *nt)
{
    cvm_mesh *m = generated("tetra.off", 0.3, 0);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_THREADS, threads), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL3_MAX_SWEEPS, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_optimise_dual3(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(nv, m, CVM_ENT_VERTEX), CVM_OK);
    *xyz = malloc(3 * *nv * sizeof **xyz);
    ck_assert_ptr_nonnull(*xyz);
    ck_assert_int_eq(cvm_mesh_copy_points_nd(*xyz, 3 * *nv, 3, m), CVM_OK);
    *w = weights_of(m, *nv);
    ck_assert_int_eq(cvm_mesh_count(nt, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    *tet = malloc((4 * *nt + 1) * sizeof **tet);
    ck_assert_ptr_nonnull(*tet);
    ck_assert_int_eq(cvm_mesh_copy_cells(*tet, 4 * *nt, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    cvm_mesh_free(m);
}

START_TEST(same_bytes_for_every_run_and_thread_count)
{
    double *x0, *w0, *x1, *w1;
    cvm_index *t0, *t1;
    size_t n0, n1, nt0, nt1;
    int k;
    run_bytes(1, &x0, &w0, &n0, &t0, &nt0);
    for (k = 0; k < 2; k++) {
        run_bytes(k ? 2 : 1, &x1, &w1, &n1, &t1, &nt1);
        ck_assert_uint_eq(n0, n1);
        ck_assert(memcmp(x0, x1, 3 * n0 * sizeof *x0) == 0);
        ck_assert(memcmp(w0, w1, n0 * sizeof *w0) == 0);
        ck_assert_uint_eq(nt0, nt1);
        ck_assert(memcmp(t0, t1, 4 * nt0 * sizeof *t0) == 0);
        free(x1);
        free(w1);
        free(t1);
    }
    free(x0);
    free(w0);
    free(t0);
}
END_TEST

static int cancel_at(void *payload, cvm_stage stage, double fraction)
{
    int *n = payload;
    (void)fraction;
    return stage == CVM_STAGE_OPTIMISE_DUAL && ++*n >= 5;
}

/* Faces regular before and no longer after: none may exist. */
static size_t faces_lost(const g3_mesh *g, const unsigned char *reg0, const cvm_mesh *m,
                         const int32_t *nbr)
{
    g3_mesh b;
    double *w;
    unsigned char *reg;
    size_t i, lost = 0;
    g3_mesh_get(&b, m);
    ck_assert(b.nt == g->nt && memcmp(b.tet, g->tet, 4 * g->nt * sizeof *g->tet) == 0);
    w = weights_of(m, b.nv);
    reg = regular_faces(&b, w, nbr);
    for (i = 0; i < 4 * g->nt; i++)
        lost += reg0[i] && !reg[i];
    free(reg);
    free(w);
    g3_mesh_free(&b);
    return lost;
}

START_TEST(cancel_and_time_limit_leave_a_valid_mesh)
{
    cvm_mesh *m = generated("tetra.off", 0.3, 0);
    g3_mesh g;
    int32_t *nbr;
    double *w;
    unsigned char *reg;
    int calls = 0;
    double v;
    cvm_status s;
    g3_mesh_get(&g, m);
    w = weights_of(m, g.nv);
    nbr = adjacency(&g);
    reg = regular_faces(&g, w, nbr);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL3_FLIPS, 0), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_progress(m, cancel_at, 1, &calls), CVM_OK);
    ck_assert_int_eq(cvm_mesh_optimise_dual3(m), CVM_INCOMPLETE_CANCELLED);
    ck_assert_int_eq(calls, 5);
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    ck_assert_uint_eq(faces_lost(&g, reg, m, nbr), 0);
    ck_assert_int_eq(cvm_mesh_get_report(&v, m, CVM_REPORT_DUAL3_MOVES), CVM_OK);
    ck_assert(v <= 5);
    /* a time limit far below one sweep */
    ck_assert_int_eq(cvm_mesh_set_progress(m, NULL, 0, NULL), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_TIME_LIMIT_S, 1e-9), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL3_MAX_SWEEPS, 1e6), CVM_OK);
    s = cvm_mesh_optimise_dual3(m);
    ck_assert(s == CVM_OK || s == CVM_INCOMPLETE_TIME_LIMIT);
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    ck_assert_uint_eq(faces_lost(&g, reg, m, nbr), 0);
    free(reg);
    free(w);
    free(nbr);
    g3_mesh_free(&g);
    cvm_mesh_free(m);
}
END_TEST

/* With flips: a stop at any point leaves a checked mesh with every surface triangle,
 * every vertex and no face irregular that was regular. */
START_TEST(flips_cancel_and_time_limit_leave_a_valid_mesh)
{
    int stop;
    for (stop = 0; stop < 3; stop++) {
        cvm_mesh *m = generated("tetra.off", 0.3, 0);
        g3_mesh g, b;
        int32_t *nbr, *nbr1;
        double *w, *w1, vol0, vol1;
        int calls = 0;
        size_t i;
        cvm_status s;
        g3_mesh_get(&g, m);
        w = weights_of(m, g.nv);
        nbr = adjacency(&g);
        ck_assert_int_eq(cvm_mesh_get_measure(&vol0, m, CVM_MEASURE_VOLUME), CVM_OK);
        if (stop < 2) {
            int *pc = &calls;
            ck_assert_int_eq(cvm_mesh_set_progress(m, cancel_at, 1, pc), CVM_OK);
            calls = stop ? -40 : 0; /* cancel at the 5th or the 45th vertex */
            ck_assert_int_eq(cvm_mesh_optimise_dual3(m), CVM_INCOMPLETE_CANCELLED);
        } else {
            ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_TIME_LIMIT_S, 1e-4), CVM_OK);
            s = cvm_mesh_optimise_dual3(m);
            ck_assert(s == CVM_OK || s == CVM_INCOMPLETE_TIME_LIMIT);
        }
        ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
        g3_mesh_get(&b, m);
        w1 = weights_of(m, b.nv);
        nbr1 = adjacency(&b);
        ck_assert_uint_le(irregular_faces(&b, w1, nbr1), irregular_faces(&g, w, nbr));
        ck_assert_uint_le(strict_violations(&b, w1, nbr1), strict_violations(&g, w, nbr));
        for (i = 0; i < g.nf; i++)
            ck_assert(g3_face_on_boundary(&b, g.face[3 * i], g.face[3 * i + 1], g.face[3 * i + 2]));
        for (i = 0; i < b.nv; i++)
            ck_assert_int_gt(b.valence[i], 0);
        ck_assert_uint_eq(b.nbnd, g.nbnd);
        ck_assert_int_eq(cvm_mesh_get_measure(&vol1, m, CVM_MEASURE_VOLUME), CVM_OK);
        ck_assert_double_eq_tol(vol1, vol0, 1e-12 * vol0);
        free(w);
        free(w1);
        free(nbr);
        free(nbr1);
        g3_mesh_free(&g);
        g3_mesh_free(&b);
        cvm_mesh_free(m);
    }
}
END_TEST

/* The Delaunay tetrahedralisation of a point set: cvm_mesh_check() tests every
 * interior face by the perturbed power test, so with flips the result must be the
 * regular tetrahedralisation of the weighted points, every point kept. */
START_TEST(flips_keep_a_point_set_regular)
{
    cvm_mesh *m;
    double xyz[3 * 200], v, vol0, vol1;
    uint64_t x = 88172645463325252ULL;
    size_t i, nt;
    g3_mesh g;
    for (i = 0; i < 3 * 200; i++) { /* xorshift: the same points on every platform */
        x ^= x << 13, x ^= x >> 7, x ^= x << 17;
        xyz[i] = (double)(x >> 11) / 9007199254740992.0;
    }
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xyz, 200, 3), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_get_measure(&vol0, m, CVM_MEASURE_VOLUME), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL3_MAX_SWEEPS, 5), CVM_OK);
    ck_assert_msg(cvm_mesh_optimise_dual3(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_get_report(&v, m, CVM_REPORT_DUAL3_FLIPS), CVM_OK);
    ck_assert_double_gt(v, 0);
    ck_assert_int_eq(cvm_mesh_get_measure(&vol1, m, CVM_MEASURE_VOLUME), CVM_OK);
    ck_assert_double_eq_tol(vol1, vol0, 1e-12 * vol0);
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    g3_mesh_get(&g, m);
    ck_assert_uint_eq(g.nv, 200);
    for (i = 0; i < g.nv; i++)
        ck_assert_int_gt(g.valence[i], 0);
    g3_mesh_free(&g);
    cvm_mesh_free(m);
}
END_TEST

static void oom_setup(cvm_mesh *m, void *arg)
{
    char path[1024];
    (void)arg;
    g3_data3d(path, sizeof path, "tetra.off");
    ck_assert_int_eq(cvm_mesh_read(m, path), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL3_MAX_SWEEPS, 1), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL3_BUDGET, 4), CVM_OK);
}

static cvm_status oom_run(cvm_mesh *m, void *arg)
{
    cvm_status s;
    (void)arg;
    if ((s = cvm_mesh_generate3(m, 0.3)))
        return s;
    return cvm_mesh_optimise_dual3(m);
}

START_TEST(oom_at_every_allocation)
{
    cvmtest_oom_sweep(oom_setup, oom_run, NULL, NULL);
}
END_TEST

TCase *dual3_optimise_tcase(void)
{
    TCase *tc = tcase_create("optimise3");
    tcase_set_timeout(tc, 600);
    tcase_add_test(tc, statuses_and_options);
    tcase_add_test(tc, tetra_keeps_faces_and_regularity);
    tcase_add_test(tc, cube_keeps_faces_and_regularity);
    tcase_add_test(tc, same_bytes_for_every_run_and_thread_count);
    tcase_add_test(tc, cuckoo_keeps_faces_and_regularity);
    tcase_add_test(tc, escalate_goes_on_after_a_stall);
    tcase_add_test(tc, slide_surface_keeps_vertices_on_the_surface);
    tcase_add_test(tc, cancel_and_time_limit_leave_a_valid_mesh);
    tcase_add_test(tc, flips_cancel_and_time_limit_leave_a_valid_mesh);
    tcase_add_test(tc, flips_keep_a_point_set_regular);
    tcase_add_test(tc, oom_at_every_allocation);
    return tc;
}
