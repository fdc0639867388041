/*
 * test_mesh3.c - a handle given 3D points (lib/api/mesh3*.c): Delaunay and
 * regular tetrahedralisations checked by the exact predicates, counts, Euler
 * characteristic, volumes, cells, duplicates and degenerate input, surfaces
 * read and tetrahedralised, 2D-only calls refused, OOM at every allocation.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api/api_tests.h"
#include "io/io_tests.h"
#include "support/failing_alloc.h"

/* xorshift points in [0, 1)^3, the same for every run. */
static double *random_points(size_t n, uint64_t seed)
{
    double *p = malloc(3 * n * sizeof *p);
    size_t i;
    ck_assert_ptr_nonnull(p);
    for (i = 0; i < 3 * n; i++) {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        p[i] = (double)(seed >> 11) / 9007199254740992.0;
    }
    return p;
}

/* The body-centred cubic lattice on [0, k]^3: (k+1)^3 corners and k^3 centres,
 * entirely cospherical (every cube's eight corners and the centres around). */
static double *bcc(int k, size_t *n)
{
    double *p = malloc(3 * (size_t)((k + 1) * (k + 1) * (k + 1) + k * k * k) * sizeof *p);
    int x, y, z;
    *n = 0;
    for (x = 0; x <= k; x++)
        for (y = 0; y <= k; y++)
            for (z = 0; z <= k; z++) {
                p[3 * *n] = x;
                p[3 * *n + 1] = y;
                p[3 * *n + 2] = z;
                ++*n;
                if (x < k && y < k && z < k) {
                    p[3 * *n] = x + 0.5;
                    p[3 * *n + 1] = y + 0.5;
                    p[3 * *n + 2] = z + 0.5;
                    ++*n;
                }
            }
    return p;
}

/* V - E + F - T of the tetrahedra (edges and faces counted by sorting). */
static int cmp_i64(const void *a, const void *b)
{
    int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;
    return (x > y) - (x < y);
}

static long euler(const cvm_index *tet, size_t nt, size_t nv)
{
    int64_t *e = malloc(6 * nt * sizeof *e), *f = malloc(4 * nt * sizeof *f);
    size_t i, ne = 0, nf = 0, k;
    static const int ep[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
    for (i = 0; i < nt; i++) {
        const cvm_index *t = tet + 4 * i;
        for (k = 0; k < 6; k++) {
            int64_t a = t[ep[k][0]], b = t[ep[k][1]];
            e[6 * i + k] = a < b ? a * (int64_t)nv + b : b * (int64_t)nv + a;
        }
        for (k = 0; k < 4; k++) {
            int64_t c[3], tmp;
            int j = 0, a, b;
            for (a = 0; a < 4; a++)
                if (a != (int)k)
                    c[j++] = t[a];
            for (a = 0; a < 3; a++)
                for (b = a + 1; b < 3; b++)
                    if (c[b] < c[a]) {
                        tmp = c[a];
                        c[a] = c[b];
                        c[b] = tmp;
                    }
            f[4 * i + k] = (c[0] * (int64_t)nv + c[1]) * (int64_t)nv + c[2];
        }
    }
    qsort(e, 6 * nt, sizeof *e, cmp_i64);
    qsort(f, 4 * nt, sizeof *f, cmp_i64);
    for (i = 0; i < 6 * nt; i++)
        ne += i == 0 || e[i] != e[i - 1];
    for (i = 0; i < 4 * nt; i++)
        nf += i == 0 || f[i] != f[i - 1];
    free(e);
    free(f);
    return (long)nv - (long)ne + (long)nf - (long)nt;
}

static double tet_volume(const double *p, const cvm_index *t)
{
    const double *a = p + 3 * t[0], *b = p + 3 * t[1], *c = p + 3 * t[2], *d = p + 3 * t[3];
    double u[3], v[3], w[3];
    int k;
    for (k = 0; k < 3; k++) {
        u[k] = a[k] - d[k];
        v[k] = b[k] - d[k];
        w[k] = c[k] - d[k];
    }
    return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
            u[2] * (v[0] * w[1] - v[1] * w[0])) / 6.0;
}

/* Triangulate, check exactly, and verify Euler characteristic 1 (a ball), the
 * volume and the mixed cells; returns the number of tetrahedra. */
static size_t mesh_and_verify(cvm_mesh *m, double want_volume)
{
    size_t nv, nt, nc, nconn, i;
    cvm_index *tet, *off;
    int32_t *types, dim;
    double *p, vol = 0, measured;
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_dim(&dim, m), CVM_OK);
    ck_assert_int_eq(dim, 3);
    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    tet = malloc(4 * nt * sizeof *tet);
    p = malloc(3 * nv * sizeof *p);
    ck_assert_int_eq(cvm_mesh_copy_cells(tet, 4 * nt, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_points_nd(p, 3 * nv, 3, m), CVM_OK);
    for (i = 0; i < nt; i++) {
        double v = tet_volume(p, tet + 4 * i);
        ck_assert_msg(v > 0, "tetrahedron %lu has volume %g", (unsigned long)i, v);
        vol += v;
    }
    ck_assert_msg(fabs(vol - want_volume) <= 1e-9 * want_volume, "volume %.17g, want %.17g", vol,
                  want_volume);
    ck_assert_int_eq(cvm_mesh_get_measure(&measured, m, CVM_MEASURE_VOLUME), CVM_OK);
    ck_assert(fabs(measured - vol) <= 1e-12 * vol);
    ck_assert_int_eq(euler(tet, nt, nv), 1);
    ck_assert_int_eq(cvm_mesh_count_cells_mixed(&nc, &nconn, m, CVM_ENT_CELL), CVM_OK);
    ck_assert_int_eq(nc, nt);
    ck_assert_int_eq(nconn, 4 * nt);
    off = malloc((nc + 1) * sizeof *off);
    types = malloc(nc * sizeof *types);
    ck_assert_int_eq(cvm_mesh_copy_cells_mixed(off, nc + 1, types, nc, tet, 4 * nt, m, CVM_ENT_CELL),
                     CVM_OK);
    ck_assert_int_eq(off[nc], (cvm_index)(4 * nt));
    ck_assert_int_eq(types[0], CVM_CELL_TETRAHEDRON);
    free(off);
    free(types);
    free(tet);
    free(p);
    return nt;
}

/* The unit cube's corners plus random points inside: hull volume exactly 1. */
START_TEST(random_points_give_an_exact_delaunay_ball)
{
    size_t n = 20000, k;
    double *p = random_points(n, 42);
    static const double corners[24] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0,
                                       0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1};
    cvm_mesh *m;
    memcpy(p, corners, sizeof corners);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, p, n, 3), CVM_OK);
    k = mesh_and_verify(m, 1.0);
    ck_assert_uint_gt(k, 5 * n);
    cvm_mesh_free(m);
    free(p);
}
END_TEST

/* A BCC lattice is entirely degenerate (cospherical): symbolic perturbation
 * decides, the result is a valid Delaunay tetrahedralisation filling the cube. */
START_TEST(bcc_lattice_is_tetrahedralised_exactly)
{
    size_t n;
    double *p = bcc(8, &n);
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, p, n, 3), CVM_OK);
    mesh_and_verify(m, 512.0);
    cvm_mesh_free(m);
    free(p);
}
END_TEST

/* CVM_OPT_THREADS 1, 2, 4 (parallel insertion from 2^13 points) give the same
 * bytes, duplicates included. */
START_TEST(output_does_not_depend_on_the_thread_count)
{
    size_t n = 20000, nt[3], i;
    double *p = random_points(n, 8);
    cvm_index *t[3];
    cvm_mesh *m;
    int k;
    for (i = 0; i < 200; i++) /* exact duplicates, some listed before their twin */
        memcpy(p + 3 * (i * 97 % n), p + 3 * (i * 31 % n + 1), 3 * sizeof *p);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, p, n, 3), CVM_OK);
    for (k = 0; k < 3; k++) {
        ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_THREADS, k == 0 ? 1 : 2 * k), CVM_OK);
        ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
        ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
        ck_assert_int_eq(cvm_mesh_count(&nt[k], m, CVM_ENT_TETRAHEDRON), CVM_OK);
        t[k] = malloc(4 * nt[k] * sizeof *t[k]);
        ck_assert_ptr_nonnull(t[k]);
        ck_assert_int_eq(cvm_mesh_copy_cells(t[k], 4 * nt[k], m, CVM_ENT_TETRAHEDRON), CVM_OK);
    }
    for (k = 1; k < 3; k++) {
        ck_assert_uint_eq(nt[k], nt[0]);
        ck_assert(memcmp(t[k], t[0], 4 * nt[0] * sizeof *t[0]) == 0);
    }
    for (k = 0; k < 3; k++)
        free(t[k]);
    free(p);
    cvm_mesh_free(m);
}
END_TEST

/* Weighted: CVM_OPT_THREADS 1, 2, 4 give the same regular tetrahedralisation
 * (exact power check), the same bytes and the same vanished vertices. */
START_TEST(weighted_output_does_not_depend_on_the_thread_count)
{
    size_t n = 20000, nv, nt[3], i;
    double *p = random_points(n, 9), *w, van[3];
    cvm_index *t[3];
    cvm_mesh *m;
    int k;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, p, n, 3), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    w = malloc(nv * sizeof *w);
    ck_assert_ptr_nonnull(w);
    for (i = 0; i < nv; i++) /* the squared spacing is about 1.4e-3 */
        w[i] = 1e-4 * (double)(i % 7) - (i % 13 == 0 ? 2e-3 : 0.0);
    for (k = 0; k < 3; k++) {
        ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_THREADS, k == 0 ? 1 : 2 * k), CVM_OK);
        ck_assert_int_eq(cvm_mesh_set_weights(m, w, nv), CVM_OK);
        ck_assert_int_eq(cvm_mesh_get_measure(&van[k], m, CVM_MEASURE_VANISHED_VERTICES), CVM_OK);
        ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "%d: %s", k, cvm_mesh_errmsg(m));
        ck_assert_int_eq(cvm_mesh_count(&nt[k], m, CVM_ENT_TETRAHEDRON), CVM_OK);
        t[k] = malloc(4 * nt[k] * sizeof *t[k]);
        ck_assert_ptr_nonnull(t[k]);
        ck_assert_int_eq(cvm_mesh_copy_cells(t[k], 4 * nt[k], m, CVM_ENT_TETRAHEDRON), CVM_OK);
    }
    ck_assert(van[0] > 10);
    for (k = 1; k < 3; k++) {
        ck_assert(van[k] == van[0]);
        ck_assert_uint_eq(nt[k], nt[0]);
        ck_assert(memcmp(t[k], t[0], 4 * nt[0] * sizeof *t[0]) == 0);
    }
    for (k = 0; k < 3; k++)
        free(t[k]);
    free(w);
    free(p);
    cvm_mesh_free(m);
}
END_TEST

/* The same input gives the same bytes, whatever the seed. */
START_TEST(output_does_not_depend_on_the_seed)
{
    size_t n = 3000, nt1, nt2;
    double *p = random_points(n, 7);
    cvm_index *a, *b;
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, p, n, 3), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&nt1, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    a = malloc(4 * nt1 * sizeof *a);
    ck_assert_int_eq(cvm_mesh_copy_cells(a, 4 * nt1, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_SEED, 12345), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&nt2, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    ck_assert_int_eq(nt1, nt2);
    b = malloc(4 * nt2 * sizeof *b);
    ck_assert_int_eq(cvm_mesh_copy_cells(b, 4 * nt2, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    ck_assert(memcmp(a, b, 4 * nt1 * sizeof *a) == 0);
    free(a);
    free(b);
    free(p);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(duplicates_merge_and_degenerate_input_is_refused)
{
    static const double tet_dup[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 0};
    static const double flat[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0.5, 0.5, 0};
    double bad[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    size_t nv, ndup;
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, tet_dup, 5, 3), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&ndup, m, CVM_ENT_DUPLICATE), CVM_OK);
    ck_assert_int_eq(nv, 4);
    ck_assert_int_eq(ndup, 1);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_REJECT_DUPLICATES, 1), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_E_INPUT_DUPLICATE);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "point 4"));
    ck_assert_int_eq(cvm_mesh_set_points(m, flat, 5, 3), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_E_INPUT_DEGENERATE);
    bad[7] = NAN;
    ck_assert_int_eq(cvm_mesh_set_points(m, bad, 4, 3), CVM_E_INPUT_NONFINITE);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "point 2"));
    cvm_mesh_free(m);
}
END_TEST

/* Weights: a regular tetrahedralisation, checked by the exact power test; a
 * vertex whose power cell vanishes is counted, not dropped silently. */
START_TEST(weights_give_a_regular_tetrahedralisation)
{
    size_t n = 2000, nv, i;
    double *p = random_points(n, 99), *w, vanished;
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, p, n, 3), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    w = calloc(nv, sizeof *w);
    for (i = 0; i < nv; i++)
        w[i] = 1e-4 * (double)(i % 7);
    w[nv / 2] = -1.0; /* deep below its neighbours: its cell vanishes */
    ck_assert_int_eq(cvm_mesh_set_weights(m, w, nv - 1), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_mesh_set_weights(m, w, nv), CVM_OK);
    ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_get_measure(&vanished, m, CVM_MEASURE_VANISHED_VERTICES), CVM_OK);
    ck_assert(vanished >= 1);
    free(w);
    free(p);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(two_dimensional_calls_are_refused_on_a_3d_mesh)
{
    size_t n = 50;
    double *p = random_points(n, 3), buf[8];
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, p, n, 3), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_refine(m, NULL, CVM_ALGO_DELAUNAY), CVM_E_UNSUPPORTED);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "cvm_mesh_refine"));
    ck_assert_int_eq(cvm_mesh_optimise_dual(m, NULL), CVM_E_UNSUPPORTED);
    ck_assert_int_eq(cvm_mesh_copy_points(buf, 8, m), CVM_E_UNSUPPORTED);
    ck_assert_int_eq(cvm_mesh_copy_points_nd(buf, 8, 2, m), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_mesh_insert_points(NULL, m, p, 1, 0), CVM_E_UNSUPPORTED);
    ck_assert_int_eq(cvm_mesh_get_measure(buf, m, CVM_MEASURE_REGULAR_PCT), CVM_E_ARGUMENT);
    /* 2D points make it 2D again */
    ck_assert_int_eq(cvm_mesh_set_points(m, p, n, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    free(p);
    cvm_mesh_free(m);
}
END_TEST

static void data3d(char *buf, size_t len, const char *name)
{
    const char *d = getenv("CVM_DATA3D_DIR");
    snprintf(buf, len, "%s/%s", d && *d ? d : "examples/data3d", name);
}

/* Surfaces: the unit cube and two cubes with two regions; with TetGen the
 * boundary is recovered, without it the cube's triangles must be Delaunay
 * faces, or the call says which one is not. */
START_TEST(surfaces_are_tetrahedralised_or_refused_clearly)
{
    char path[4096];
    cvm_mesh *m;
    cvm_status s;
    size_t nf;
    int with_tetgen = strstr(cvm_build_string(), "TetGen 1.5") != NULL;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    data3d(path, sizeof path, "two_cubes.poly");
    ck_assert_msg(cvm_mesh_read(m, path) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_count(&nf, m, CVM_ENT_FACET), CVM_OK);
    ck_assert_uint_gt(nf, 0);
    s = cvm_mesh_triangulate(m);
    if (with_tetgen || s == CVM_OK) {
        double vol;
        ck_assert_msg(s == CVM_OK, "%s", cvm_mesh_errmsg(m));
        ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
        ck_assert_int_eq(cvm_mesh_get_measure(&vol, m, CVM_MEASURE_VOLUME), CVM_OK);
        ck_assert(fabs(vol - 2.0) < 1e-12);
    } else {
        ck_assert_int_eq(s, CVM_E_UNSUPPORTED);
        ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "TETGEN=1"));
    }
    data3d(path, sizeof path, "tetra.off");
    ck_assert_int_eq(cvm_mesh_read(m, path), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK); /* 4 faces: Delaunay either way */
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&nf, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    ck_assert_int_eq(nf, 1);
    cvm_mesh_free(m);
}
END_TEST

/* Allocation k fails, for every k: CVM_E_NOMEM, nothing leaks, and the handle
 * goes on to give the same tetrahedralisation. */
START_TEST(every_failed_allocation_gives_nomem_and_the_handle_goes_on)
{
    size_t n = 200, nt_ref = 0, nt;
    double *p = random_points(n, 5);
    cvmtest_alloc a;
    cvm_mesh *m;
    long k;
    cvmtest_alloc_init(&a, 0, 0);
    ck_assert_int_eq(cvmtest_mesh_create(&m, &a), CVM_OK);
    for (k = 1;; k++) {
        cvm_status s;
        cvmtest_alloc_arm(&a, k, 0);
        s = cvm_mesh_set_points(m, p, n, 3);
        if (s == CVM_OK)
            s = cvm_mesh_triangulate(m);
        if (s == CVM_OK)
            s = cvm_mesh_check(m);
        if (s == CVM_OK)
            break;
        ck_assert_msg(s == CVM_E_NOMEM, "k=%ld: %s", k, cvm_mesh_errmsg(m));
        ck_assert(k < 500);
    }
    cvmtest_alloc_arm(&a, 0, 0);
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    {
        cvm_mesh *r;
        ck_assert_int_eq(cvm_mesh_create(&r), CVM_OK);
        ck_assert_int_eq(cvm_mesh_set_points(r, p, n, 3), CVM_OK);
        ck_assert_int_eq(cvm_mesh_triangulate(r), CVM_OK);
        ck_assert_int_eq(cvm_mesh_count(&nt_ref, r, CVM_ENT_TETRAHEDRON), CVM_OK);
        cvm_mesh_free(r);
    }
    ck_assert_int_eq(nt, nt_ref);
    cvm_mesh_free(m);
    ck_assert_int_eq((int)a.live_blocks, 0);
    free(p);
}
END_TEST

START_TEST(files_are_written_in_each_format)
{
    size_t n = 100;
    double *p = random_points(n, 11);
    char *dir = iotest_tmpdir(), path[4096], *text;
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, p, n, 3), CVM_OK);
    snprintf(path, sizeof path, "%s/t.vtu", dir);
    ck_assert_int_eq(cvm_mesh_write(m, path), CVM_E_STATE);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_write(m, path), CVM_OK);
    text = iotest_slurp(path, NULL);
    ck_assert_ptr_nonnull(strstr(text, "NumberOfPoints=\"100\""));
    ck_assert_ptr_nonnull(strstr(text, "10 10 10"));
    free(text);
    snprintf(path, sizeof path, "%s/t.msh", dir);
    ck_assert_int_eq(cvm_mesh_write(m, path), CVM_OK);
    text = iotest_slurp(path, NULL);
    ck_assert_ptr_nonnull(strstr(text, "3 1 \"domain\""));
    free(text);
    snprintf(path, sizeof path, "%s/t.node", dir);
    ck_assert_int_eq(cvm_mesh_write(m, path), CVM_OK);
    snprintf(path, sizeof path, "%s/t.face", dir);
    text = iotest_slurp(path, NULL);
    ck_assert_ptr_nonnull(text);
    free(text);
    snprintf(path, sizeof path, "%s/t.svg", dir);
    ck_assert_int_eq(cvm_mesh_write(m, path), CVM_E_UNSUPPORTED);
    { /* a weighted mesh carries its weights: .vtu point data, .node attribute */
        double w[100];
        size_t i;
        for (i = 0; i < n; i++)
            w[i] = 0.25 * (double)(i % 4) * 1e-3;
        ck_assert_int_eq(cvm_mesh_set_weights(m, w, n), CVM_OK);
        snprintf(path, sizeof path, "%s/w.vtu", dir);
        ck_assert_int_eq(cvm_mesh_write(m, path), CVM_OK);
        text = iotest_slurp(path, NULL);
        ck_assert_ptr_nonnull(strstr(text, "<PointData Scalars=\"weight\">"));
        ck_assert_ptr_nonnull(strstr(text, "\n0.00075\n"));
        free(text);
        snprintf(path, sizeof path, "%s/w.node", dir);
        ck_assert_int_eq(cvm_mesh_write(m, path), CVM_OK);
        text = iotest_slurp(path, NULL);
        ck_assert_msg(strncmp(text, "100 3 1 0\n", 10) == 0, "%.40s", text);
        free(text);
    }
    cvm_mesh_free(m);
    iotest_rmdir(dir);
    free(dir);
    free(p);
}
END_TEST

/* 3D holes and regions through the _nd setters: copied whole, or not at all. */
START_TEST(holes_and_regions_of_dimension_3)
{
    static const double pts[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
    double hole[3] = {0.2, 0.2, 0.2}, region[10] = {0.1, 0.1, 0.1, 7, 0, 0.3, 0.3, 0.3, 8, 0};
    size_t n;
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_holes_nd(m, hole, 1, 3), CVM_E_UNSUPPORTED); /* still 2D */
    ck_assert_int_eq(cvm_mesh_set_points(m, pts, 5, 3), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_holes_nd(m, hole, 1, 3), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_regions_nd(m, region, 2, 3), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&n, m, CVM_ENT_HOLE), CVM_OK);
    ck_assert_int_eq(n, 1);
    ck_assert_int_eq(cvm_mesh_count(&n, m, CVM_ENT_REGION), CVM_OK);
    ck_assert_int_eq(n, 2);
    region[8] = NAN;
    ck_assert_int_eq(cvm_mesh_set_regions_nd(m, region, 2, 3), CVM_E_INPUT_NONFINITE);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "region 1"));
    ck_assert_int_eq(cvm_mesh_count(&n, m, CVM_ENT_REGION), CVM_OK);
    ck_assert_int_eq(n, 2); /* the previous regions stay */
    ck_assert_int_eq(cvm_mesh_set_holes_nd(m, hole, 1, 2), CVM_E_ARGUMENT);
    /* a point set ignores them: the tetrahedralisation of the 5 points */
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    cvm_mesh_free(m);
}
END_TEST

/* Without hole points the orientation tells a hole: a small tetrahedron whose triangles face
 * into it, inside a large one facing out, is left empty; facing out as well, it tells nothing
 * (the shells contradict each other) and both are meshed. Either way recovery needs nothing:
 * every triangle is a Delaunay face. */
START_TEST(a_shell_facing_inwards_bounds_a_hole)
{
    static const char *const faces[2] = {"3 4 6 5\n3 4 7 6\n3 4 5 7\n3 5 6 7\n",
                                         "3 4 5 6\n3 4 6 7\n3 4 7 5\n3 5 7 6\n"};
    char *dir = iotest_tmpdir(), path[4096];
    int inward;
    for (inward = 0; inward <= 1; inward++) {
        cvm_mesh *m;
        double vol;
        size_t nv;
        FILE *f;
        snprintf(path, sizeof path, "%s/shells.off", dir);
        f = fopen(path, "w");
        ck_assert_ptr_nonnull(f);
        fprintf(f, "OFF\n8 8 0\n10 10 10\n10 -10 -10\n-10 10 -10\n-10 -10 10\n"
                   "1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n"
                   "3 0 1 2\n3 0 2 3\n3 0 3 1\n3 1 3 2\n%s",
                faces[inward ? 0 : 1]);
        fclose(f);
        ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
        ck_assert_msg(cvm_mesh_read(m, path) == CVM_OK, "%s", cvm_mesh_errmsg(m));
        ck_assert_msg(cvm_mesh_triangulate(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
        ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
        ck_assert_int_eq(cvm_mesh_get_measure(&vol, m, CVM_MEASURE_VOLUME), CVM_OK);
        ck_assert_msg(fabs(vol - (inward ? 7992.0 / 3 : 8000.0 / 3)) < 1e-9, "volume %.17g", vol);
        ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
        ck_assert_int_eq(nv, 8);
        cvm_mesh_free(m);
    }
    { /* allocation k fails, for every k: CVM_E_NOMEM, no leak, then the same volume */
        cvmtest_alloc a;
        cvm_mesh *m;
        long k;
        double vol = 0;
        cvmtest_alloc_init(&a, 0, 0);
        ck_assert_int_eq(cvmtest_mesh_create(&m, &a), CVM_OK);
        for (k = 1;; k++) {
            cvm_status s;
            cvmtest_alloc_arm(&a, k, 0);
            s = cvm_mesh_read(m, path); /* the last file: the hole */
            if (s == CVM_OK)
                s = cvm_mesh_triangulate(m);
            if (s == CVM_OK)
                break;
            ck_assert_msg(s == CVM_E_NOMEM, "k=%ld: %s", k, cvm_mesh_errmsg(m));
            ck_assert(k < 2000);
        }
        cvmtest_alloc_arm(&a, 0, 0);
        ck_assert_int_eq(cvm_mesh_get_measure(&vol, m, CVM_MEASURE_VOLUME), CVM_OK);
        ck_assert(fabs(vol - 7992.0 / 3) < 1e-9);
        cvm_mesh_free(m);
        ck_assert_int_eq((int)a.live_blocks, 0);
    }
    iotest_rmdir(dir);
    free(dir);
}
END_TEST

TCase *api_mesh3_tcase(void)
{
    TCase *tc = tcase_create("mesh3");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, random_points_give_an_exact_delaunay_ball);
    tcase_add_test(tc, bcc_lattice_is_tetrahedralised_exactly);
    tcase_add_test(tc, output_does_not_depend_on_the_seed);
    tcase_add_test(tc, output_does_not_depend_on_the_thread_count);
    tcase_add_test(tc, duplicates_merge_and_degenerate_input_is_refused);
    tcase_add_test(tc, weights_give_a_regular_tetrahedralisation);
    tcase_add_test(tc, weighted_output_does_not_depend_on_the_thread_count);
    tcase_add_test(tc, two_dimensional_calls_are_refused_on_a_3d_mesh);
    tcase_add_test(tc, surfaces_are_tetrahedralised_or_refused_clearly);
    tcase_add_test(tc, every_failed_allocation_gives_nomem_and_the_handle_goes_on);
    tcase_add_test(tc, files_are_written_in_each_format);
    tcase_add_test(tc, holes_and_regions_of_dimension_3);
    tcase_add_test(tc, a_shell_facing_inwards_bounds_a_hole);
    return tc;
}
