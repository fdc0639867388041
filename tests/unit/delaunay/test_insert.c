/* test_insert.c - point insertion into an existing triangulation (cvm_mesh_insert_points; cvm__tri2_insert_in_cavity). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay/delaunay_tests.h"
#include "delaunay/delaunay_internal.h"
#include "support/mesh_oracle.h"

static cvm_mesh *unit_square(void)
{
    double xy[] = {0, 0, 1, 0, 1, 1, 0, 1};
    cvm_index segs[] = {0, 1, 1, 2, 2, 3, 3, 0};
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 4, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, segs, 4), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    return m;
}

START_TEST(insert_returns_ids_and_rejects)
{
    cvm_mesh *m = unit_square();
    double pts[] = {0.5, 0.5, 2.0, 2.0, 0.5, 0.5, 0.52, 0.5, 0.5, 0.0, 0.25, 0.75};
    cvm_index ids[6];
    size_t nv;
    ck_assert_int_eq(cvm_mesh_insert_points(ids, m, pts, 6, 0.05), CVM_OK);
    ck_assert_int_eq(ids[0], 4);
    ck_assert_int_eq(ids[1], CVM_REJECTED); /* outside the domain */
    ck_assert_int_eq(ids[2], CVM_REJECTED); /* duplicate */
    ck_assert_int_eq(ids[3], CVM_REJECTED); /* closer than 0.05 */
    ck_assert_int_eq(ids[4], 5);            /* on the boundary segment: splits it */
    ck_assert_int_eq(ids[5], 6);
    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_uint_eq(nv, 7);
    cvmtest_assert_valid(m);
    cvm_mesh_free(m);
}
END_TEST

/* min_dist counts every vertex, also one behind a segment: the square [0, 10]^2
 * cut by the segment y = 5, a vertex at (5, 4.9) below it; the point (5, 5.1)
 * above is 0.2 from it, though its cavity (above the segment) does not hold it. */
START_TEST(insert_min_dist_sees_a_vertex_behind_a_segment)
{
    double xy[] = {0, 0, 10, 0, 10, 10, 0, 10, 0, 5, 10, 5, 5, 4.9};
    cvm_index segs[] = {0, 1, 1, 5, 5, 2, 2, 3, 3, 4, 4, 0, 4, 5};
    double p[] = {5, 5.1, 5, 5.6};
    cvm_index ids[2];
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 7, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, segs, 7), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_insert_points(ids, m, p, 2, 0.5), CVM_OK);
    ck_assert_int_eq(ids[0], CVM_REJECTED); /* 0.2 from vertex 6 across the segment */
    ck_assert_int_eq(ids[1], 7);            /* 0.6 from it: inserted */
    cvmtest_assert_valid(m);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(insert_many_keeps_constrained_delaunay)
{
    cvm_mesh *m = unit_square();
    size_t n = 5000, i, nseg;
    double *xy = malloc(2 * n * sizeof *xy);
    cvm_index *ids = malloc(n * sizeof *ids);
    dtest_random_points(xy, n, 17);
    ck_assert_int_eq(cvm_mesh_insert_points(ids, m, xy, n, 0), CVM_OK);
    for (i = 0; i < n; i++)
        ck_assert_int_ne(ids[i], CVM_REJECTED);
    cvmtest_assert_valid(m);
    ck_assert_int_eq(cvm_mesh_count(&nseg, m, CVM_ENT_SEGMENT), CVM_OK);
    ck_assert_uint_eq(nseg, 4);
    free(xy);
    free(ids);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(insert_bad_arguments)
{
    cvm_mesh *m;
    double p[2] = {NAN, 0};
    cvm_index id;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_insert_points(&id, m, p, 1, 0), CVM_E_STATE);
    cvm_mesh_free(m);
    m = unit_square();
    ck_assert_int_eq(cvm_mesh_insert_points(&id, m, p, 1, 0), CVM_E_INPUT_NONFINITE);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "point 0"));
    p[0] = 0.5;
    ck_assert_int_eq(cvm_mesh_insert_points(&id, m, p, 1, -1), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_mesh_insert_points(&id, m, NULL, 1, 0), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_insert_points(&id, NULL, p, 1, 0), CVM_E_NULL_ARG);
    cvm_mesh_free(m);
}
END_TEST

/* Live real triangles of T in canonical form (as dtest_canonical); caller frees. */
static cvm_index *live_triangles(const cvm__tri2 *T, size_t *nt_out)
{
    cvm_index *tri = malloc((3 * T->nt + 1) * sizeof *tri);
    size_t t, n = 0;
    for (t = 0; t < T->nt; t++) {
        if (!cvm__tri2_is_live(T, (int32_t)t) || cvm__tri2_is_ghost(T, (int32_t)t))
            continue;
        memcpy(tri + 3 * n, T->tv + 3 * t, 3 * sizeof *tri);
        n++;
    }
    dtest_canonical(tri, n);
    *nt_out = n;
    return tri;
}

/* Inserting into a cavity the caller found (here by the test's own search
 * from the containing triangle) gives the triangulation Bowyer-Watson
 * insertion gives, and it passes the exact Delaunay check. */
START_TEST(insert_in_cavity_matches_bowyer_watson)
{
    enum { N0 = 200, N = 1500 };
    double *xy = malloc(2 * N * sizeof *xy);
    int32_t *dup = malloc(N * sizeof *dup), *cav = NULL;
    size_t cap = 0, i, nt1, nt2, inserted = 0;
    cvm_index *tri1, *tri2;
    cvm__ctx ctx;
    cvm__tri2 T1, T2;
    dtest_random_points(xy, N, 29);
    cvm__ctx_init_default(&ctx);
    cvm__tri2_init(&T1, &ctx);
    cvm__tri2_init(&T2, &ctx);
    for (i = 0; i < N0; i++) {
        int32_t id;
        ck_assert_int_eq(cvm__tri2_add_vertex(&T1, xy + 2 * i, &id), CVM_OK);
        ck_assert_int_eq(cvm__tri2_add_vertex(&T2, xy + 2 * i, &id), CVM_OK);
    }
    ck_assert_int_eq(cvm__tri2_build(&T1, 1, dup), CVM_OK);
    ck_assert_int_eq(cvm__tri2_build(&T2, 1, dup), CVM_OK);
    for (i = N0; i < N; i++) {
        int32_t v1, v2, t, other;
        int j;
        size_t ncav = 0, k;
        cvm__ins res;
        ck_assert_int_eq(cvm__tri2_add_vertex(&T1, xy + 2 * i, &v1), CVM_OK);
        ck_assert_int_eq(cvm__tri2_add_vertex(&T2, xy + 2 * i, &v2), CVM_OK);
        if (cvm__tri2_locate(&T2, xy + 2 * i, -1, &t, &j) != CVM__LOC_INSIDE) {
            T1.nv--; /* outside the hull or on an edge: not this function's case */
            T2.nv--;
            continue;
        }
        ck_assert_int_eq(cvm__tri2_insert_vertex(&T1, v1, -1, 0, 0.0, &res, &other), CVM_OK);
        ck_assert_int_eq(res, CVM__INS_DONE);
        /* the cavity: t, then every real neighbour whose circumcircle holds v */
        if (cap < 1) {
            cap = 64;
            cav = malloc(cap * sizeof *cav);
        }
        cav[ncav++] = t;
        for (k = 0; k < ncav; k++) {
            int jj;
            for (jj = 0; jj < 3; jj++) {
                int32_t nb = T2.tn[3 * (size_t)cav[k] + (size_t)jj] / 3;
                size_t q;
                for (q = 0; q < ncav && cav[q] != nb; q++)
                    ;
                if (q < ncav || cvm__tri2_is_ghost(&T2, nb) || cvm__tri2_conflict(&T2, nb, v2) <= 0)
                    continue;
                if (ncav == cap) {
                    cap *= 2;
                    cav = realloc(cav, cap * sizeof *cav);
                }
                cav[ncav++] = nb;
            }
        }
        ck_assert_int_eq(cvm__tri2_insert_in_cavity(&T2, v2, cav, ncav), CVM_OK);
        inserted++;
    }
    ck_assert_uint_gt(inserted, N / 2);
    ck_assert_int_eq(cvm__tri2_check(&T2), CVM_OK);
    tri1 = live_triangles(&T1, &nt1);
    tri2 = live_triangles(&T2, &nt2);
    ck_assert_uint_eq(nt1, nt2);
    ck_assert_int_eq(memcmp(tri1, tri2, 3 * nt1 * sizeof *tri1), 0);
    free(tri1);
    free(tri2);
    free(cav);
    free(xy);
    free(dup);
    cvm__tri2_destroy(&T1);
    cvm__tri2_destroy(&T2);
}
END_TEST

TCase *delaunay_insert_tcase(void)
{
    TCase *tc = tcase_create("insert");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, insert_returns_ids_and_rejects);
    tcase_add_test(tc, insert_min_dist_sees_a_vertex_behind_a_segment);
    tcase_add_test(tc, insert_many_keeps_constrained_delaunay);
    tcase_add_test(tc, insert_bad_arguments);
    tcase_add_test(tc, insert_in_cavity_matches_bowyer_watson);
    return tc;
}
