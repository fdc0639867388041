/* test_support.c - the support suite: the mesh oracle and the failing allocator catch what they must. */
#include <string.h>

#include "suites.h"
#include "support/failing_alloc.h"
#include "support/mesh_oracle.h"

static char g_msg[512];

/* Unit square split along 0-2: cocircular, so either diagonal is Delaunay. */
static const double k_sq_xy[] = {0, 0, 1, 0, 1, 1, 0, 1};
static const cvm_index k_sq_tri[] = {0, 1, 2, 0, 2, 3};

START_TEST(oracle_accepts_square_with_expectations)
{
    cvmtest_expect e;
    cvmtest_expect_init(&e);
    e.convex = 1;
    e.check_euler = 1;
    e.euler = 1;
    e.check_area = 1;
    e.area = 1.0;
    ck_assert_msg(cvmtest_oracle(g_msg, sizeof g_msg, k_sq_xy, 4, k_sq_tri, 2, NULL, 0, NULL, 0, &e),
                  "%s", g_msg);
}
END_TEST

START_TEST(oracle_rejects_clockwise_triangle)
{
    static const cvm_index tri[] = {0, 2, 1, 0, 2, 3};
    ck_assert(!cvmtest_oracle(g_msg, sizeof g_msg, k_sq_xy, 4, tri, 2, NULL, 0, NULL, 0, NULL));
    ck_assert_ptr_nonnull(strstr(g_msg, "triangle 0"));
}
END_TEST

START_TEST(oracle_rejects_wrong_euler_and_area)
{
    cvmtest_expect e;
    cvmtest_expect_init(&e);
    e.check_euler = 1;
    e.euler = 0;
    ck_assert(!cvmtest_oracle(g_msg, sizeof g_msg, k_sq_xy, 4, k_sq_tri, 2, NULL, 0, NULL, 0, &e));
    ck_assert_ptr_nonnull(strstr(g_msg, "Euler"));
    cvmtest_expect_init(&e);
    e.check_area = 1;
    e.area = 1.5;
    ck_assert(!cvmtest_oracle(g_msg, sizeof g_msg, k_sq_xy, 4, k_sq_tri, 2, NULL, 0, NULL, 0, &e));
    ck_assert_ptr_nonnull(strstr(g_msg, "area"));
}
END_TEST

/* a(0,0) b(4,0) c(2,1) d(2,-1): d lies inside the circumcircle of a, b, c. */
static const double k_kite_xy[] = {0, 0, 4, 0, 2, 1, 2, -1};
static const cvm_index k_kite_tri[] = {0, 1, 2, 1, 0, 3};

START_TEST(oracle_rejects_non_delaunay_edge_unless_constrained)
{
    static const cvm_index cons[] = {0, 1};
    ck_assert(!cvmtest_oracle(g_msg, sizeof g_msg, k_kite_xy, 4, k_kite_tri, 2, NULL, 0, NULL, 0,
                              NULL));
    ck_assert_ptr_nonnull(strstr(g_msg, "Delaunay"));
    ck_assert_msg(cvmtest_oracle(g_msg, sizeof g_msg, k_kite_xy, 4, k_kite_tri, 2, cons, 1, NULL, 0,
                                 NULL), "%s", g_msg);
}
END_TEST

START_TEST(oracle_rejects_missing_segment_and_constraint)
{
    static const cvm_index cons[] = {2, 3};
    static const cvm_index segs[] = {2, 3};
    cvmtest_expect e;
    ck_assert(!cvmtest_oracle(g_msg, sizeof g_msg, k_kite_xy, 4, k_kite_tri, 2, cons, 1, NULL, 0,
                              NULL));
    ck_assert_ptr_nonnull(strstr(g_msg, "not an edge"));
    cvmtest_expect_init(&e);
    e.delaunay = 0;
    e.segs = segs;
    e.nseg = 1;
    ck_assert(!cvmtest_oracle(g_msg, sizeof g_msg, k_kite_xy, 4, k_kite_tri, 2, NULL, 0, NULL, 0,
                              &e));
    ck_assert_ptr_nonnull(strstr(g_msg, "input segment 0"));
}
END_TEST

START_TEST(oracle_rejects_overlapping_triangles)
{
    static const cvm_index tri[] = {0, 1, 2, 0, 1, 3};
    ck_assert(!cvmtest_oracle(g_msg, sizeof g_msg, k_sq_xy, 4, tri, 2, NULL, 0, NULL, 0, NULL));
    ck_assert_ptr_nonnull(strstr(g_msg, "same direction"));
}
END_TEST

START_TEST(oracle_rejects_doubly_wound_vertex)
{
    /* Centre vertex 0 with a fan that goes twice around it: 6 triangles over 3 rim vertices
     * would repeat edges, so use 6 rim vertices at angles 0, 240, 120 (x2 turns). */
    static const double xy[] = {0, 0,  2, 0,  -1, -1.7,  -1, 1.7,  2, 0.1,  -1, -1.6,  -1, 1.6};
    static const cvm_index tri[] = {0, 1, 3, 0, 3, 2, 0, 2, 4, 0, 4, 6, 0, 6, 5, 0, 5, 1};
    cvmtest_expect e;
    cvmtest_expect_init(&e);
    e.delaunay = 0;
    ck_assert(!cvmtest_oracle(g_msg, sizeof g_msg, xy, 7, tri, 6, NULL, 0, NULL, 0, &e));
}
END_TEST

/* 0(0,0) 1(1,0) 2(2,0) 3(1,1) 4(1,-1): segment 0-2 runs through vertex 1. */
START_TEST(oracle_walks_collinear_segment_chain)
{
    static const double xy[] = {0, 0, 1, 0, 2, 0, 1, 1, 1, -1};
    static const cvm_index tri[] = {0, 1, 3, 1, 2, 3, 0, 4, 1, 1, 4, 2};
    static const cvm_index segs[] = {0, 2};
    static const cvm_index cons[] = {0, 1, 1, 2};
    static const cvm_index bad_cons[] = {0, 1};
    cvmtest_expect e;
    cvmtest_expect_init(&e);
    e.segs = segs;
    e.nseg = 1;
    e.check_euler = 1;
    e.euler = 1;
    e.check_area = 1;
    e.area = 2.0;
    ck_assert_msg(cvmtest_oracle(g_msg, sizeof g_msg, xy, 5, tri, 4, NULL, 0, NULL, 0, &e), "%s",
                  g_msg);
    ck_assert_msg(cvmtest_oracle(g_msg, sizeof g_msg, xy, 5, tri, 4, cons, 2, NULL, 0, &e), "%s",
                  g_msg);
    /* With output segments given, every piece of the chain must be one of them. */
    ck_assert(!cvmtest_oracle(g_msg, sizeof g_msg, xy, 5, tri, 4, bad_cons, 1, NULL, 0, &e));
}
END_TEST

/* Input segment 0-1 split by two rounded intersections that share x = 2. */
START_TEST(oracle_walks_steiner_points_sharing_a_coordinate)
{
    static const double xy[] = {0, 0, 4, 0, 2, 1e-12, 2, -1e-12, 2, 2, 2, -2};
    static const cvm_index tri[] = {0, 2, 4, 2, 1, 4, 0, 3, 2, 3, 1, 2, 0, 5, 3, 3, 5, 1};
    static const cvm_index map[] = {0, 1};
    static const cvm_index segs[] = {0, 1};
    static const cvm_index cons[] = {0, 2, 2, 3, 3, 1};
    cvmtest_expect e;
    cvmtest_expect_init(&e);
    e.delaunay = 0;
    e.segs = segs;
    e.nseg = 1;
    e.check_euler = 1;
    e.euler = 1;
    ck_assert_msg(cvmtest_oracle(g_msg, sizeof g_msg, xy, 6, tri, 6, cons, 3, map, 2, &e), "%s",
                  g_msg);
}
END_TEST

/* Segment 0-1 carried by input points 2 (an ulp-scale 1e-12 off the line) and
 * 3 (exactly on it) at the same x: the chain 0-2-3-1 steps sideways from 2
 * back onto the line, which the rule of cvm_mesh_triangulate() allows (every
 * chain vertex within 2^-40 (M + L) of the segment); edge 0-3, on the line but
 * not an output segment, is beside the chain, not part of it. */
START_TEST(oracle_walks_sideways_step_back_onto_the_line)
{
    static const double xy[] = {0, 0, 4, 0, 2, 1e-12, 2, 0, 2, 2, 2, -2};
    static const cvm_index tri[] = {0, 2, 4, 2, 1, 4, 0, 3, 2, 3, 1, 2, 0, 5, 3, 3, 5, 1};
    static const cvm_index segs[] = {0, 1};
    static const cvm_index cons[] = {0, 2, 2, 3, 3, 1};
    static const cvm_index gap[] = {0, 2, 3, 1};
    cvmtest_expect e;
    cvmtest_expect_init(&e);
    e.delaunay = 0;
    e.segs = segs;
    e.nseg = 1;
    e.check_euler = 1;
    e.euler = 1;
    ck_assert_msg(cvmtest_oracle(g_msg, sizeof g_msg, xy, 6, tri, 6, cons, 3, NULL, 0, &e), "%s",
                  g_msg);
    /* without the sideways piece 2-3 the chain is broken */
    ck_assert(!cvmtest_oracle(g_msg, sizeof g_msg, xy, 6, tri, 6, gap, 2, NULL, 0, &e));
}
END_TEST

START_TEST(failing_alloc_fails_kth_and_counts_live_blocks)
{
    cvmtest_alloc a;
    void *p, *q, *r;
    cvmtest_alloc_init(&a, 2, 0);
    p = cvmtest_malloc(&a, 10);
    ck_assert_ptr_nonnull(p);
    ck_assert_ptr_null(cvmtest_malloc(&a, 10));
    q = cvmtest_realloc(&a, p, 100);
    ck_assert_ptr_nonnull(q);
    ck_assert_int_eq(a.live_blocks, 1);
    ck_assert_uint_eq(a.live_bytes, 100);
    r = cvmtest_realloc(&a, NULL, 5);
    ck_assert_int_eq(a.live_blocks, 2);
    cvmtest_free(&a, q);
    cvmtest_free(&a, r);
    cvmtest_free(&a, NULL);
    ck_assert_int_eq(a.live_blocks, 0);
    ck_assert_uint_eq(a.live_bytes, 0);
    ck_assert_int_eq(a.n_calls, 4);
    ck_assert_int_eq(a.n_failed, 1);

    cvmtest_alloc_init(&a, 1, 1);
    ck_assert_ptr_null(cvmtest_malloc(&a, 1));
    ck_assert_ptr_null(cvmtest_malloc(&a, 1));
    ck_assert_int_eq(a.n_failed, 2);
}
END_TEST

Suite *support_suite(void)
{
    Suite *s = suite_create("support");
    TCase *tc = tcase_create("mesh_oracle");
    tcase_add_test(tc, oracle_accepts_square_with_expectations);
    tcase_add_test(tc, oracle_rejects_clockwise_triangle);
    tcase_add_test(tc, oracle_rejects_wrong_euler_and_area);
    tcase_add_test(tc, oracle_rejects_non_delaunay_edge_unless_constrained);
    tcase_add_test(tc, oracle_rejects_missing_segment_and_constraint);
    tcase_add_test(tc, oracle_rejects_overlapping_triangles);
    tcase_add_test(tc, oracle_rejects_doubly_wound_vertex);
    tcase_add_test(tc, oracle_walks_collinear_segment_chain);
    tcase_add_test(tc, oracle_walks_steiner_points_sharing_a_coordinate);
    tcase_add_test(tc, oracle_walks_sideways_step_back_onto_the_line);
    suite_add_tcase(s, tc);
    tc = tcase_create("failing_alloc");
    tcase_add_test(tc, failing_alloc_fails_kth_and_counts_live_blocks);
    suite_add_tcase(s, tc);
    return s;
}
