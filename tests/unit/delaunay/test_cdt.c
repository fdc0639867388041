/* test_cdt.c - constrained Delaunay triangulation of PSLGs (lib/delaunay/segment.c, cavity.c, carve.c). */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 199309L
#endif
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "delaunay/delaunay_tests.h"
#include "support/fixtures.h"
#include "support/mesh_oracle.h"
#include "api/api_internal.h"
#include "delaunay/tri2_store.h"
#include "geom/geom_internal.h"

static void expect_pslg(cvmtest_expect *e, const cvm_index *segs, size_t nseg, long euler, double area)
{
    cvmtest_expect_init(e);
    e->segs = segs;
    e->nseg = nseg;
    e->check_euler = 1;
    e->euler = euler;
    e->check_area = 1;
    e->area = area;
    e->area_rel_tol = 1e-12;
}

/* Triangulate xy (n points) with segs (ns) keeping the convex hull, and
 * require CVM_OK and a valid mesh. */
static void triangulate_keeping_hull(const double *xy, size_t n, const cvm_index *segs, size_t ns)
{
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, n, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, segs, ns), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_KEEP_CONVEX_HULL, 1), CVM_OK);
    ck_assert_msg(cvm_mesh_triangulate(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    cvmtest_assert_valid(m);
    cvm_mesh_free(m);
}

/* A square [0,4]^2 with a square hole [1,3]^2 and random interior points. */
START_TEST(square_with_hole_is_constrained_delaunay)
{
    double xy[2 * 208];
    cvm_index segs[16] = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4};
    double box[16] = {0, 0, 4, 0, 4, 4, 0, 4, 1, 1, 3, 1, 3, 3, 1, 3};
    double hole[2] = {2, 2};
    cvmtest_expect e;
    cvm_mesh *m;
    size_t i, nseg_out;
    memcpy(xy, box, sizeof box);
    dtest_random_points(xy + 16, 200, 5);
    for (i = 16; i < 2 * 208; i++)
        xy[i] *= 4;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 208, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, segs, 8), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_holes(m, hole, 1), CVM_OK);
    ck_assert_msg(cvm_mesh_triangulate(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    expect_pslg(&e, segs, 8, 0, 16.0 - 4.0);
    cvmtest_assert_valid_ex(m, &e);
    ck_assert_int_eq(cvm_mesh_count(&nseg_out, m, CVM_ENT_SEGMENT), CVM_OK);
    ck_assert_uint_ge(nseg_out, 8);
    cvm_mesh_free(m);
}
END_TEST

/* Long segments across a dense cloud: recovery must cross many triangles. */
START_TEST(long_segments_cross_many_triangles)
{
    size_t n = 3000, i;
    double *xy = malloc(2 * (n + 8) * sizeof *xy);
    cvm_index segs[2 * 6] = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 6, 7};
    double fixed[16] = {0, 0, 1, 0, 1, 1, 0, 1, 0.01, 0.013, 0.99, 0.97, 0.02, 0.95, 0.97, 0.03};
    cvmtest_expect e;
    cvm_mesh *m;
    memcpy(xy, fixed, sizeof fixed);
    dtest_random_points(xy + 16, n, 21);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, n + 8, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, segs, 6), CVM_OK);
    ck_assert_msg(cvm_mesh_triangulate(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    /* the two diagonals cross: split at a new vertex (default) */
    expect_pslg(&e, segs, 6, 1, 1.0);
    cvmtest_assert_valid_ex(m, &e);
    {
        size_t nv;
        ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
        ck_assert_uint_eq(nv, n + 8 + 1);
    }
    cvm_mesh_free(m);
    (void)i;
    free(xy);
}
END_TEST

START_TEST(crossing_segments_rejected_when_asked)
{
    double xy[] = {0, 0, 1, 0, 1, 1, 0, 1};
    cvm_index segs[] = {0, 1, 1, 2, 2, 3, 3, 0, 0, 2, 1, 3};
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 4, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, segs, 6), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_SPLIT_INTERSECTIONS, 0), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_E_INPUT_INTERSECTING);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "segment 5"));
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "segment 4"));
    cvm_mesh_free(m);
}
END_TEST

START_TEST(vertex_on_segment_splits_it)
{
    /* points 4..6 lie exactly on the bottom edge 0-1 and on the diagonal 0-2 */
    double xy[] = {0, 0, 4, 0, 4, 4, 0, 4, 1, 0, 2, 0, 2, 2, 3, 1};
    cvm_index segs[] = {0, 1, 1, 2, 2, 3, 3, 0, 0, 2};
    cvmtest_expect e;
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 8, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, segs, 5), CVM_OK);
    ck_assert_msg(cvm_mesh_triangulate(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    expect_pslg(&e, segs, 5, 1, 16.0);
    cvmtest_assert_valid_ex(m, &e);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(bad_segments_are_named)
{
    double xy[] = {0, 0, 1, 0, 1, 1, 0, 1, 1, 0};
    cvm_index bad_index[] = {0, 1, 1, 7};
    cvm_index zero_len[] = {0, 1, 1, 2, 2, 2};
    cvm_index dup_len[] = {0, 1, 4, 1};
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 5, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, bad_index, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_E_INPUT_INDEX);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "segment 1"));
    ck_assert_int_eq(cvm_mesh_set_segments(m, zero_len, 3), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_E_INPUT_DEGENERATE);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "segment 2"));
    /* point 4 duplicates point 1: segment 1 collapses after merging */
    ck_assert_int_eq(cvm_mesh_set_segments(m, dup_len, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_E_INPUT_DEGENERATE);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "segment 1"));
    cvm_mesh_free(m);
}
END_TEST

START_TEST(open_boundary_is_not_closed)
{
    double xy[] = {0, 0, 1, 0, 1, 1, 0, 1, 0.5, 0.5};
    cvm_index open3[] = {0, 1, 1, 2, 2, 3};
    double hole_out[2] = {5, 5};
    cvm_index closed[] = {0, 1, 1, 2, 2, 3, 3, 0};
    double hole_in[2] = {0.25, 0.5};
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 5, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, open3, 3), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_E_INPUT_NOT_CLOSED);
    ck_assert_int_eq(cvm_mesh_set_segments(m, closed, 4), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_holes(m, hole_out, 1), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_E_INPUT_OUTSIDE);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "hole 0"));
    ck_assert_int_eq(cvm_mesh_set_holes(m, hole_in, 1), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_E_INPUT_NOT_CLOSED);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "hole 0"));
    cvm_mesh_free(m);
}
END_TEST

START_TEST(regions_get_attributes)
{
    /* two unit squares side by side sharing the segment 1-4 */
    double xy[] = {0, 0, 1, 0, 2, 0, 2, 1, 1, 1, 0, 1};
    cvm_index segs[] = {0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 0, 1, 4};
    double regions[] = {0.5, 0.5, 7, 0, 1.5, 0.5, 9, 0};
    double attr[16];
    cvm_index tri[48];
    double pts[12];
    size_t nt, i;
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 6, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, segs, 7), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_regions(m, regions, 2), CVM_OK);
    ck_assert_msg(cvm_mesh_triangulate(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    cvmtest_assert_valid(m);
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_uint_eq(nt, 4);
    ck_assert_int_eq(cvm_mesh_copy_triangle_attributes(attr, 16, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(tri, 48, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_points(pts, 12, m), CVM_OK);
    for (i = 0; i < nt; i++) {
        double cx = (pts[2 * tri[3 * i]] + pts[2 * tri[3 * i + 1]] + pts[2 * tri[3 * i + 2]]) / 3;
        ck_assert(attr[i] == (cx < 1 ? 7.0 : 9.0));
    }
    cvm_mesh_free(m);
}
END_TEST

/* Star-shaped polygon with many nearly collinear, jagged edges and random holes-free interior. */
START_TEST(jagged_star_polygon)
{
    size_t k = 400, i, n;
    double *xy = malloc(2 * (k + 500) * sizeof *xy);
    cvm_index *segs = malloc(2 * k * sizeof *segs);
    cvmtest_expect e;
    cvm_mesh *m;
    double area = 0;
    unsigned long long s = 77;
    for (i = 0; i < k; i++) {
        double a = 6.283185307179586 * (double)i / (double)k, r;
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        r = 0.5 + 0.5 * (double)(s >> 11) / 9007199254740992.0;
        xy[2 * i] = r * cos(a);
        xy[2 * i + 1] = r * sin(a);
        segs[2 * i] = (cvm_index)i;
        segs[2 * i + 1] = (cvm_index)((i + 1) % k);
    }
    for (i = 0; i < k; i++) {
        size_t j = (i + 1) % k;
        area += 0.5 * (xy[2 * i] * xy[2 * j + 1] - xy[2 * j] * xy[2 * i + 1]);
    }
    n = k;
    dtest_random_points(xy + 2 * n, 500, 8);
    for (i = 2 * n; i < 2 * (n + 500); i++)
        xy[i] = 0.9 * (xy[i] - 0.5);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, n + 500, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, segs, k), CVM_OK);
    ck_assert_msg(cvm_mesh_triangulate(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    expect_pslg(&e, segs, k, 1, area);
    e.area_rel_tol = 1e-9;
    cvmtest_assert_valid_ex(m, &e);
    cvm_mesh_free(m);
    free(xy);
    free(segs);
}
END_TEST

/* A grid of 16 x 16 square holes in a square: every hole carved, nothing else.
 * With no interior points every triangle has its corners on the boundary:
 * 4 + 4H vertices, hence 6H + 2 triangles. */
START_TEST(hole_grid_carves_every_hole)
{
    cvmtest_pslg *g = cvmtest_hole_grid(16);
    cvmtest_expect e;
    cvm_mesh *m;
    size_t nt;
    ck_assert_ptr_nonnull(g);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvmtest_pslg_set(m, g), CVM_OK);
    ck_assert_msg(cvm_mesh_triangulate(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_uint_eq(nt, 6 * 256 + 2);
    expect_pslg(&e, g->seg, g->nseg, 1 - 256, 0.75 * 256);
    ck_assert_int_eq(g->euler, 1 - 256);
    cvmtest_assert_valid_ex(m, &e);
    cvm_mesh_free(m);
    cvmtest_pslg_free(g);
}
END_TEST

/* Holes are carved in their order: two points in one hole are one hole; a
 * hole point between the holes removes the domain, and the hole point that
 * removes its last triangle (here the one of the last uncarved hole) is named;
 * a hole point outside the hull is named when it comes first. */
START_TEST(hole_grid_names_the_first_bad_hole)
{
    cvmtest_pslg *g = cvmtest_hole_grid(8);
    double *h = malloc((2 * 64 + 4) * sizeof *h);
    cvm_mesh *m;
    size_t nt;
    ck_assert(g && h);
    memcpy(h, g->holes, 2 * 64 * sizeof *h);
    h[128] = 3.6; /* a second point in hole (3, 3) */
    h[129] = 3.7;
    h[130] = 7.4; /* and one in hole (7, 0) */
    h[131] = 0.3;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvmtest_pslg_set(m, g), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_holes(m, h, 66), CVM_OK);
    ck_assert_msg(cvm_mesh_triangulate(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_uint_eq(nt, 6 * 64 + 2);
    cvmtest_assert_valid(m);
    h[10] = 0.1; /* hole 5 in the domain between the holes, hole 64 in hole (5, 0) */
    h[11] = 0.1;
    h[128] = 5.5;
    h[129] = 0.5;
    ck_assert_int_eq(cvm_mesh_set_holes(m, h, 66), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_E_INPUT_NOT_CLOSED);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "hole 64 at (5.5"));
    h[6] = -1; /* hole 3 outside the hull comes first */
    ck_assert_int_eq(cvm_mesh_set_holes(m, h, 66), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_E_INPUT_OUTSIDE);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "hole 3 at (-1"));
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_uint_eq(nt, 0);
    cvm_mesh_free(m);
    cvmtest_pslg_free(g);
    free(h);
}
END_TEST

typedef struct stop_at {
    cvm_stage stage;   /* the stage to act in */
    double until;      /* > 0: spin there until this monotonic time, then go on */
    int calls;         /* calls in that stage */
} stop_at;

static double mono_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int stop_in_stage(void *payload, cvm_stage stage, double fraction)
{
    stop_at *p = payload;
    (void)fraction;
    if (stage != p->stage)
        return 0;
    p->calls++;
    if (p->until <= 0)
        return 1;
    while (mono_now() < p->until)
        ;
    return 0;
}

/* Carving is a stage the progress callback sees and can cancel: the
 * triangulation then rolls back to empty and says where it stopped. */
START_TEST(carving_can_be_cancelled)
{
    cvmtest_pslg *g = cvmtest_hole_grid(10);
    stop_at st = {CVM_STAGE_CARVE, 0, 0};
    cvm_mesh *m;
    size_t nt = 1;
    ck_assert_ptr_nonnull(g);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvmtest_pslg_set(m, g), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_progress(m, stop_in_stage, 1, &st), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_INCOMPLETE_CANCELLED);
    ck_assert_int_eq(st.calls, 1);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "cancelled while carving"));
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_uint_eq(nt, 0);
    ck_assert_int_eq(cvm_mesh_set_progress(m, NULL, 0, NULL), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_uint_eq(nt, 6 * 100 + 2);
    cvm_mesh_free(m);
    cvmtest_pslg_free(g);
}
END_TEST

/* The time limit is checked while carving too. The callback holds the run in
 * the carving stage past the limit (the insertion of 404 points before it
 * takes far less than the 0.5 s limit), so the stop must come from carving. */
START_TEST(time_limit_stops_carving)
{
    cvmtest_pslg *g = cvmtest_hole_grid(10);
    stop_at st = {CVM_STAGE_CARVE, 0, 0};
    cvm_mesh *m;
    size_t nt = 1;
    ck_assert_ptr_nonnull(g);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvmtest_pslg_set(m, g), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_TIME_LIMIT_S, 0.5), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_progress(m, stop_in_stage, 1, &st), CVM_OK);
    st.until = mono_now() + 0.6;
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_INCOMPLETE_TIME_LIMIT);
    ck_assert_int_eq(st.calls, 1);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "time limit reached while carving"));
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_uint_eq(nt, 0);
    cvm_mesh_free(m);
    cvmtest_pslg_free(g);
}
END_TEST

/* cvm_mesh_check must notice a segment whose edges lost their constraint. */
START_TEST(check_detects_a_lost_segment)
{
    double xy[] = {0, 0, 1, 0, 1, 1, 0, 1};
    cvm_index segs[] = {0, 1, 1, 2, 2, 3, 3, 0, 0, 2};
    cvm_mesh *m;
    size_t k;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 4, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, segs, 5), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    for (k = 0; k < 3 * m->tri.nt; k++)
        if (m->tri.te[k] == 4)
            m->tri.te[k] = -1; /* the diagonal is now an ordinary edge */
    ck_assert_int_eq(cvm_mesh_check(m), CVM_E_INTERNAL);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "input segment 4"));
    cvm_mesh_free(m);
}
END_TEST

/* Segments of length about 0.01 near (1e6, 1e6) that cross many times: their
 * crossing points are rounded at the scale of 1e6, up to about one unit in the
 * last place (1.2e-10, 1e-8 of a segment's length) off the segment, and the
 * piece 11-7 of segment 3-7 is shared with segment 7-11, which carries its
 * index. The mesh is valid under the rule of cvm_mesh_check(); a check that
 * scaled the tolerance by the length alone rejected it. */
START_TEST(crossings_near_large_offset_keep_their_chains)
{
    static const double xy[] = {
        1000000.002, 1000000.003,        1000000.0140000001, 1000000,
        1000000.0150000001, 1000000.007, 1000000.0000000001, 1000000,
        1000000.015, 1000000.007,        1000000.009, 1000000.003,
        1000000, 1000000.015,            1000000.0140000001, 1000000.007,
        1000000.0130000002, 1000000.005, 1000000.003, 1000000.014,
        1000000.0020000001, 1000000.01,  1000000.0100000001, 1000000.005,
        1000000.0120000001, 1000000.004};
    static const cvm_index segs[] = {3, 7, 11, 4, 9, 5, 7, 11, 1, 9, 10, 12, 8, 6, 0, 2};
    const double *p3 = xy + 6, *p7 = xy + 14;
    double len = hypot(p7[0] - p3[0], p7[1] - p3[1]), tol = 0x1p-40 * (1000000.0140000001 + len);
    size_t nv, k, off = 0;
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 13, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, segs, 8), CVM_OK);
    ck_assert_msg(cvm_mesh_triangulate(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    cvmtest_assert_valid(m);
    /* point 11 lies exactly on segment 3-7; vertices on the shared piece
     * 11-7 lie off it by rounding, within the stated bound */
    ck_assert(cvm__orient2d(p3, p7, xy + 22) == 0);
    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    for (k = 0; k < 3 * m->tri.nt; k++) {
        int32_t t = (int32_t)(k / 3), v;
        const double *pv;
        if (m->tri.te[k] != 3 || !cvm__tri2_is_live(&m->tri, t))
            continue;
        v = m->tri.tv[3 * (size_t)t + (k + 1) % 3];
        pv = m->tri.xy + 2 * (size_t)v;
        ck_assert_uint_lt((size_t)v, nv);
        ck_assert(fabs(cvm__orient2d(p3, p7, pv)) <= tol * len);
        off += cvm__orient2d(p3, p7, pv) != 0;
    }
    ck_assert_uint_gt(off, 0);
    cvm_mesh_free(m);
}
END_TEST

/* Segments (15,3)-(2,10), (11,4)-(0,15) and (11,8)-(6,5) of this integer PSLG
 * meet at (8.5, 6.5). The first two cross at a rounded vertex an ulp away;
 * the third then crosses their piece so close to that vertex that its own
 * rounded crossing cannot split the piece: it is routed through the vertex,
 * not refused. */
START_TEST(concurrent_crossings_route_through_the_rounded_crossing)
{
    static const double xy[] = {15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 3, 3, 13, 6, 3,
        6, 5, 14, 13, 14, 11, 12, 4, 14, 1, 7, 13, 6, 9, 8, 4, 8, 14, 6, 5, 8, 14, 9, 15, 2, 10, 5,
        15, 12, 8, 5, 9, 0, 15, 14, 12, 11, 4, 9, 3, 1, 12, 11, 5, 15, 15, 13, 10, 12, 5, 13, 2, 11,
        15, 11, 8, 8, 11, 15, 8, 6, 11, 10, 11, 12, 9, 1, 1};
    static const cvm_index segs[] = {32, 33, 6, 21, 5, 27, 42, 37, 11, 22, 18, 10, 6, 11, 4, 37, 7,
        2, 15, 14, 42, 29, 42, 15, 13, 29, 15, 40, 41, 1, 41, 15, 31, 26, 26, 2, 30, 35, 26, 6, 21,
        26, 29, 41, 27, 25, 13, 33, 6, 32, 13, 18, 40, 23, 7, 22, 36, 18};
    triangulate_keeping_hull(xy, 43, segs, 29);
}
END_TEST

/* Segment 2, (11,0)-(6,15), is crossed at a rounded vertex near (9.27, 5.18),
 * and its piece from there to (6,15) passes within an ulp of the input point
 * (7,12), which lies exactly on the segment. An input point exactly inside a
 * segment splits it (cvm_mesh_triangulate()), so the piece goes through
 * (7,12): a constrained edge of segment 2 ends there. Left beside the piece,
 * it made a sliver that blocked every split of the piece and left a
 * triangle beside it unrefinable (tests/fuzz/corpus/refine/
 * regression_input_point_on_segment_between_rounded_crossings). Segment 3,
 * (0,13)-(15,8), crosses the segment at (7.5, 10.5). (A crossing rounded past
 * a sliver, nudged across the piece: tests/fuzz/corpus/cdt/
 * regression_nudged_crossing_reads_moved_coordinates.) */
START_TEST(point_on_segment_joins_the_piece_from_a_rounded_crossing)
{
    static const double xy[] = {2, 8, 7, 11, 14, 0, 14, 14, 15, 7, 10, 1, 0, 5, 8, 3, 0, 0, 0, 15,
        14, 7, 2, 12, 9, 13, 4, 3, 15, 7, 6, 0, 14, 6, 0, 13, 15, 8, 13, 5, 1, 14, 1, 14, 1, 14, 1,
        14, 1, 14, 1, 14, 1, 14, 1, 14, 1, 14, 7, 12, 13, 1, 3, 8, 11, 0, 7, 11, 14, 12, 9, 0, 2, 1,
        3, 1, 0, 2, 1, 2, 14, 5, 6, 15, 0, 0};
    static const cvm_index segs[] = {3, 40, 39, 10, 32, 41, 17, 18, 18, 0, 31, 0};
    cvm_index map[43];
    size_t k, ends = 0;
    cvm_mesh *m;
    ck_assert(cvm__orient2d(xy + 64, xy + 82, xy + 58) == 0); /* (7,12) on (11,0)-(6,15) */
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 43, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, segs, 6), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_KEEP_CONVEX_HULL, 1), CVM_OK);
    ck_assert_msg(cvm_mesh_triangulate(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    cvmtest_assert_valid(m);
    ck_assert_int_eq(cvm_mesh_copy_input_map(map, 43, m), CVM_OK);
    for (k = 0; k < 3 * m->tri.nt; k++) {
        int32_t t = (int32_t)(k / 3);
        if (m->tri.te[k] == 2 && cvm__tri2_is_live(&m->tri, t) && !cvm__tri2_is_ghost(&m->tri, t) &&
            (m->tri.tv[3 * (size_t)t + (k + 1) % 3] == map[29] ||
             m->tri.tv[3 * (size_t)t + (k + 2) % 3] == map[29]))
            ends++;
    }
    /* two pieces of segment 2 meet at (7,12), each seen from its two sides */
    ck_assert_uint_ge(ends, 2);
    cvm_mesh_free(m);
}
END_TEST

/* Segment (20000,9500)-(15500,500) lies on segment (15500,500)-(23000,15500),
 * and both cross the polygon edge (20125,5375)-(15625,8125) at the same point
 * near (18449.47, 6398.94). Computed from different pieces, the two rounded
 * crossings fall an ulp apart: the second lies within 16 ulps of the end of
 * the piece the first left, so it is that end (cvm_mesh_triangulate()), and no
 * vertex is made an ulp from it. (Two vertices an ulp apart enclosed a flat
 * triangle of constrained edges that sent AFLR's clean-up to the Steiner
 * limit: tests/fuzz/corpus/refine/regression_overlapping_segments_cross_an_edge_an_ulp_apart.) */
START_TEST(overlapping_segments_share_their_rounded_crossing)
{
    static const double xy[] = {15625, 8125, 19625, 10375, 14875, 10500, 14500, 15375, 10125, 11000,
        1375, 11625, 5625, 9250, 2500, 7125, 3875, 5375, 10500, 6250, 10000, 2125, 14000, 2125,
        17625, 3250, 20125, 5375, 15500, 500, 23000, 15500, 20000, 9500, 15500, 500, 23000, 15500,
        23000, 8500};
    static const cvm_index segs[] = {0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 8, 8, 9, 9, 10,
        10, 11, 11, 12, 12, 13, 13, 0, 14, 15, 16, 17, 18, 19};
    double *p;
    size_t nv, i, j;
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 20, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, segs, 17), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_KEEP_CONVEX_HULL, 1), CVM_OK);
    ck_assert_msg(cvm_mesh_triangulate(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    cvmtest_assert_valid(m);
    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    p = malloc(2 * nv * sizeof *p);
    ck_assert_ptr_nonnull(p);
    ck_assert_int_eq(cvm_mesh_copy_points(p, 2 * nv, m), CVM_OK);
    for (i = 0; i < nv; i++)
        for (j = i + 1; j < nv; j++)
            ck_assert_msg(fabs(p[2 * i] - p[2 * j]) + fabs(p[2 * i + 1] - p[2 * j + 1]) > 1e-6,
                          "vertices %zu and %zu at (%.17g, %.17g) and (%.17g, %.17g)", i, j,
                          p[2 * i], p[2 * i + 1], p[2 * j], p[2 * j + 1]);
    free(p);
    cvm_mesh_free(m);
}
END_TEST

/* Segments (15,15)-(7+u,2) and (15+u,15)-(7,2), u one ulp, cross at a tiny
 * angle between two other crossings: the slivers on both sides of the piece
 * they cross are thinner than an ulp there, so no double splits it. The
 * crossing segment is routed through the end of the piece within rounding of
 * its line. */
START_TEST(nearly_coincident_crossing_meets_at_the_piece_end)
{
    double xy[20];
    static const int grid[20] = {15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 8, 12, 11, 9, 7, 2, 7, 2};
    static const cvm_index segs[] = {2, 9, 5, 0, 9, 1, 1, 7, 2, 8, 1, 0, 9, 7,
                                     9, 2, 3, 4, 5, 8, 9, 0, 1, 4, 6, 1};
    cvm_mesh *m;
    int i;
    for (i = 0; i < 20; i++)
        xy[i] = (i % 4 == 2) ? nextafter((double)grid[i], 1e300) : (double)grid[i];
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 10, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, segs, 13), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_KEEP_CONVEX_HULL, 1), CVM_OK);
    ck_assert_msg(cvm_mesh_triangulate(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    cvmtest_assert_valid(m);
    cvm_mesh_free(m);
}
END_TEST

/* Segment (12+u,2)-(3+u,7), u one ulp, crosses (15,6)-(3,7) within an ulp of
 * the end (3,7): it passes through that end, an ulp beyond its own end along
 * its axis, and both cvm_mesh_check() and the oracle walking the segments
 * accept the chain. */
START_TEST(segment_ends_an_ulp_apart_meet_at_one)
{
    double xy[8] = {15, 6, 0, 7, 3, 7, 0, 2};
    static const cvm_index segs[] = {0, 2, 3, 1, 2, 0};
    cvmtest_expect e;
    cvm_mesh *m;
    xy[2] = nextafter(3.0, 4.0);
    xy[6] = nextafter(12.0, 13.0);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 4, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, segs, 3), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_KEEP_CONVEX_HULL, 1), CVM_OK);
    ck_assert_msg(cvm_mesh_triangulate(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    cvmtest_expect_init(&e);
    e.segs = segs;
    e.nseg = 3;
    cvmtest_assert_valid_ex(m, &e);
    cvm_mesh_free(m);
}
END_TEST

TCase *delaunay_cdt_tcase(void)
{
    TCase *tc = tcase_create("cdt");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, square_with_hole_is_constrained_delaunay);
    tcase_add_test(tc, long_segments_cross_many_triangles);
    tcase_add_test(tc, crossing_segments_rejected_when_asked);
    tcase_add_test(tc, vertex_on_segment_splits_it);
    tcase_add_test(tc, bad_segments_are_named);
    tcase_add_test(tc, open_boundary_is_not_closed);
    tcase_add_test(tc, regions_get_attributes);
    tcase_add_test(tc, jagged_star_polygon);
    tcase_add_test(tc, check_detects_a_lost_segment);
    tcase_add_test(tc, hole_grid_carves_every_hole);
    tcase_add_test(tc, hole_grid_names_the_first_bad_hole);
    tcase_add_test(tc, carving_can_be_cancelled);
    tcase_add_test(tc, time_limit_stops_carving);
    tcase_add_test(tc, crossings_near_large_offset_keep_their_chains);
    tcase_add_test(tc, concurrent_crossings_route_through_the_rounded_crossing);
    tcase_add_test(tc, point_on_segment_joins_the_piece_from_a_rounded_crossing);
    tcase_add_test(tc, overlapping_segments_share_their_rounded_crossing);
    tcase_add_test(tc, nearly_coincident_crossing_meets_at_the_piece_end);
    tcase_add_test(tc, segment_ends_an_ulp_apart_meet_at_one);
    return tc;
}
