/* test_args.c - NULL arguments, calls in the wrong order, bad dims, and buffers that are too short. */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "api/api_tests.h"
#include "cvmesh.h"
#include "support/fixtures.h"
#include "support/mesh_oracle.h"

static cvm_mesh *new_mesh(void)
{
    cvm_mesh *m = NULL;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_ptr_nonnull(m);
    return m;
}

/* The square with a hole, with point and segment markers, 2 attributes per
 * point and one region, triangulated. */
static cvm_mesh *triangulated_mesh(void)
{
    const cvmtest_pslg *p = &cvmtest_square_with_hole;
    cvm_mesh *m = new_mesh();
    int32_t pmark[8], smark[8];
    double attr[16], region[4] = {0.5, 0.5, 7.0, 0.0};
    size_t i;
    for (i = 0; i < 8; i++) {
        pmark[i] = (int32_t)i + 1;
        smark[i] = (int32_t)i < 4 ? 1 : 2;
        attr[2 * i] = p->xy[2 * i];
        attr[2 * i + 1] = -p->xy[2 * i + 1];
    }
    ck_assert_int_eq(cvmtest_pslg_set(m, p), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_point_markers(m, pmark, 8), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_point_attributes(m, attr, 8, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segment_markers(m, smark, 8), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_regions(m, region, 1), CVM_OK);
    ck_assert_msg(cvm_mesh_triangulate(m) == CVM_OK, "triangulate: %s", cvm_mesh_errmsg(m));
    return m;
}

START_TEST(free_and_errmsg_accept_null)
{
    cvm_entity kind;
    int64_t index;
    cvm_mesh *m = new_mesh();
    cvm_mesh_free(NULL);
    ck_assert_ptr_nonnull(cvm_mesh_errmsg(NULL));
    ck_assert_str_eq(cvm_mesh_errmsg(NULL), "no mesh handle");
    ck_assert_str_eq(cvm_mesh_errmsg(m), "");
    ck_assert_int_eq(cvm_mesh_error_item(&kind, &index, m), CVM_OK);
    ck_assert_int_eq(kind, CVM_ENT_NONE);
    ck_assert_int_eq(cvm_mesh_error_item(NULL, &index, m), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_error_item(&kind, NULL, m), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_error_item(&kind, &index, NULL), CVM_E_NULL_ARG);
    cvm_mesh_free(m);
}
END_TEST

static void *dummy_malloc(void *p, size_t n) { (void)p; (void)n; return NULL; }
static void *dummy_realloc(void *p, void *q, size_t n) { (void)p; (void)q; (void)n; return NULL; }
static void dummy_free(void *p, void *q) { (void)p; (void)q; }

START_TEST(create_rejects_null_and_reports_nomem)
{
    cvm_mesh *m = (cvm_mesh *)&m;
    ck_assert_int_eq(cvm_mesh_create(NULL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_create_with_allocator(NULL, dummy_malloc, dummy_realloc, dummy_free,
                                                    NULL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_create_with_allocator(&m, NULL, dummy_realloc, dummy_free, NULL),
                     CVM_E_NULL_ARG);
    ck_assert_ptr_null(m);
    m = (cvm_mesh *)&m;
    ck_assert_int_eq(cvm_mesh_create_with_allocator(&m, dummy_malloc, NULL, dummy_free, NULL),
                     CVM_E_NULL_ARG);
    ck_assert_ptr_null(m);
    m = (cvm_mesh *)&m;
    ck_assert_int_eq(cvm_mesh_create_with_allocator(&m, dummy_malloc, dummy_realloc, NULL, NULL),
                     CVM_E_NULL_ARG);
    ck_assert_ptr_null(m);
    m = (cvm_mesh *)&m;
    ck_assert_int_eq(cvm_mesh_create_with_allocator(&m, dummy_malloc, dummy_realloc, dummy_free,
                                                    NULL), CVM_E_NOMEM);
    ck_assert_ptr_null(m);
}
END_TEST

static int progress_cb(void *payload, cvm_stage stage, double fraction)
{
    (void)payload;
    (void)stage;
    (void)fraction;
    return 0;
}

START_TEST(every_call_rejects_a_null_handle)
{
    static const double xy[] = {0, 0, 1, 0, 0, 1};
    static const cvm_index seg[] = {0, 1};
    static const int32_t mark[] = {1, 2, 3};
    double d[64];
    cvm_index ix[64];
    int32_t i32[64];
    size_t n;
    const double *view;
    ck_assert_int_eq(cvm_mesh_set_points(NULL, xy, 3, 2), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_set_point_markers(NULL, mark, 3), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_set_point_attributes(NULL, xy, 3, 2), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_set_segments(NULL, seg, 1), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_set_segment_markers(NULL, mark, 1), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_set_holes(NULL, xy, 1), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_set_regions(NULL, xy, 1), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_read(NULL, "x.poly"), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_set_progress(NULL, progress_cb, 1, NULL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_triangulate(NULL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_insert_points(ix, NULL, xy, 1, 0.0), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_check(NULL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_count(&n, NULL, CVM_ENT_VERTEX), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_points(d, 64, NULL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_cells(ix, 64, NULL, CVM_ENT_TRIANGLE), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_neighbors(ix, 64, NULL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_markers(i32, 64, NULL, CVM_ENT_VERTEX), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_triangle_attributes(d, 64, NULL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_point_attributes(d, 64, &n, NULL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_input_map(ix, 64, NULL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_view_points(&view, &n, NULL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_write(NULL, "x.vtu"), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_get_measure(d, NULL, CVM_MEASURE_MIN_ANGLE_DEG), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_histogram(d, 18, NULL, CVM_HIST_ANGLE_DEG), CVM_E_NULL_ARG);
}
END_TEST

START_TEST(null_arrays_with_nonzero_counts_are_rejected)
{
    cvm_mesh *m = new_mesh();
    ck_assert_int_eq(cvm_mesh_set_points(m, NULL, 3, 2), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_set_points(m, NULL, 0, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, NULL, 2), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_set_segments(m, NULL, 0), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_holes(m, NULL, 1), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_set_regions(m, NULL, 1), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_read(m, NULL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_write(m, NULL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_count(NULL, m, CVM_ENT_VERTEX), CVM_E_NULL_ARG);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(outputs_reject_null_destinations)
{
    cvm_mesh *m = triangulated_mesh();
    size_t n;
    const double *view;
    double d;
    cvm_index ix[64];
    ck_assert_int_eq(cvm_mesh_copy_points(NULL, 1000, m), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_cells(NULL, 1000, m, CVM_ENT_TRIANGLE), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_neighbors(NULL, 1000, m), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_markers(NULL, 1000, m, CVM_ENT_VERTEX), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_triangle_attributes(NULL, 1000, m), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_input_map(NULL, 1000, m), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_view_points(NULL, &n, m), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_view_points(&view, NULL, m), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_get_measure(NULL, m, CVM_MEASURE_MIN_ANGLE_DEG), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_histogram(NULL, 18, m, CVM_HIST_ANGLE_DEG), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_get_measure(&d, m, (cvm_measure)0), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_mesh_copy_cells(ix, 64, m, CVM_ENT_VERTEX), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_mesh_count(&n, m, CVM_ENT_FILE_LINE), CVM_E_ARGUMENT);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(calls_in_the_wrong_state_are_rejected)
{
    cvm_mesh *m = new_mesh();
    static const double xy[] = {0.5, 0.5};
    cvm_index id;
    double d;
    ck_assert_int_eq(cvm_mesh_check(m), CVM_E_STATE);
    ck_assert_int_eq(cvm_mesh_insert_points(&id, m, xy, 1, 0.0), CVM_E_STATE);
    ck_assert_int_eq(cvm_mesh_write(m, "never_written.vtu"), CVM_E_STATE);
    ck_assert_int_eq(cvm_mesh_get_measure(&d, m, CVM_MEASURE_MIN_ANGLE_DEG), CVM_E_STATE);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_E_INPUT_EMPTY);
    ck_assert_msg(cvm_mesh_errmsg(m)[0] != '\0', "empty input gives no message");
    cvm_mesh_free(m);
}
END_TEST

START_TEST(set_points_checks_dim_and_finiteness)
{
    cvm_mesh *m = new_mesh();
    double xy[] = {0, 0, 1, 0, 0, 1, 1, 1};
    cvm_entity kind;
    int64_t index;
    size_t n = 99;
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 4, 1), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 4, 4), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 2, 3), CVM_OK); /* 3D now (test_mesh3.c) */
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 4, 2), CVM_OK);   /* and 2D again */
    xy[5] = NAN;
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 4, 2), CVM_E_INPUT_NONFINITE);
    ck_assert_msg(strstr(cvm_mesh_errmsg(m), "point 2") != NULL, "message \"%s\" lacks point 2",
                  cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_error_item(&kind, &index, m), CVM_OK);
    ck_assert_int_eq(kind, CVM_ENT_INPUT_POINT);
    ck_assert_int_eq(index, 2);
    /* Atomicity: the previous 4 points are kept. */
    ck_assert_int_eq(cvm_mesh_count(&n, m, CVM_ENT_INPUT_POINT), CVM_OK);
    ck_assert_uint_eq(n, 4);
    xy[5] = INFINITY;
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 4, 2), CVM_E_INPUT_NONFINITE);
    xy[5] = 1;
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_str_eq(cvm_mesh_errmsg(m), "");
    cvmtest_assert_valid(m);
    cvm_mesh_free(m);
}
END_TEST

/* Fill buf with a sentinel byte pattern and return 1 if still untouched. */
#define SENTINEL 0xA5
static union {
    unsigned char b[1 << 16];
    double d;
    int32_t i;
} g_store;
#define g_buf g_store.b

static void arm(void)
{
    memset(g_buf, SENTINEL, sizeof g_buf);
}

static int untouched(void)
{
    size_t i;
    for (i = 0; i < sizeof g_buf; i++)
        if (g_buf[i] != SENTINEL)
            return 0;
    return 1;
}

#define EXPECT_SHORT(call, what)                                                               \
    do {                                                                                       \
        arm();                                                                                 \
        ck_assert_msg((call) == CVM_E_BUFFER_TOO_SMALL, "%s: short buffer not refused", what); \
        ck_assert_msg(untouched(), "%s wrote into a buffer it refused", what);                 \
    } while (0)

START_TEST(short_buffers_are_refused_and_untouched)
{
    cvm_mesh *m = triangulated_mesh();
    double *d = (double *)(void *)&g_store;
    cvm_index *ix = (cvm_index *)(void *)&g_store;
    int32_t *i32 = (int32_t *)(void *)&g_store;
    size_t nv, nt, ne, ns, nin, nattr = 0;

    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&ne, m, CVM_ENT_EDGE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&ns, m, CVM_ENT_SEGMENT), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&nin, m, CVM_ENT_INPUT_POINT), CVM_OK);
    ck_assert_uint_eq(nv, 8);
    ck_assert_uint_eq(nin, 8);
    ck_assert_uint_ge(nt, 8);
    ck_assert_uint_ge(ns, 8);
    ck_assert(nt * 3 * sizeof(double) < sizeof g_buf);

    EXPECT_SHORT(cvm_mesh_copy_points(d, 2 * nv - 1, m), "copy_points");
    EXPECT_SHORT(cvm_mesh_copy_points(d, 0, m), "copy_points(0)");
    EXPECT_SHORT(cvm_mesh_copy_cells(ix, 3 * nt - 1, m, CVM_ENT_TRIANGLE), "copy_cells(triangles)");
    EXPECT_SHORT(cvm_mesh_copy_cells(ix, 2 * ne - 1, m, CVM_ENT_EDGE), "copy_cells(edges)");
    EXPECT_SHORT(cvm_mesh_copy_cells(ix, 2 * ns - 1, m, CVM_ENT_SEGMENT), "copy_cells(segments)");
    EXPECT_SHORT(cvm_mesh_copy_neighbors(ix, 3 * nt - 1, m), "copy_neighbors");
    EXPECT_SHORT(cvm_mesh_copy_markers(i32, nv - 1, m, CVM_ENT_VERTEX), "copy_markers(vertices)");
    EXPECT_SHORT(cvm_mesh_copy_markers(i32, ns - 1, m, CVM_ENT_SEGMENT), "copy_markers(segments)");
    EXPECT_SHORT(cvm_mesh_copy_triangle_attributes(d, nt - 1, m), "copy_triangle_attributes");
    EXPECT_SHORT(cvm_mesh_copy_point_attributes(d, 2 * nv - 1, &nattr, m), "copy_point_attributes");
    EXPECT_SHORT(cvm_mesh_copy_input_map(ix, nin - 1, m), "copy_input_map");
    EXPECT_SHORT(cvm_mesh_copy_histogram(d, 17, m, CVM_HIST_ANGLE_DEG), "copy_histogram(angle)");
    EXPECT_SHORT(cvm_mesh_copy_histogram(d, 15, m, CVM_HIST_DEGREE), "copy_histogram(degree)");

    /* Exact sizes succeed. */
    ck_assert_int_eq(cvm_mesh_copy_points(d, 2 * nv, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(ix, 3 * nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(ix, 2 * ne, m, CVM_ENT_EDGE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(ix, 2 * ns, m, CVM_ENT_SEGMENT), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_neighbors(ix, 3 * nt, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_markers(i32, nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_markers(i32, ns, m, CVM_ENT_SEGMENT), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_triangle_attributes(d, nt, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_point_attributes(d, 2 * nv, &nattr, m), CVM_OK);
    ck_assert_uint_eq(nattr, 2);
    ck_assert_int_eq(cvm_mesh_copy_input_map(ix, nin, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_histogram(d, 18, m, CVM_HIST_ANGLE_DEG), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_histogram(d, 16, m, CVM_HIST_DEGREE), CVM_OK);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(triangulated_square_with_hole_passes_the_oracle)
{
    cvm_mesh *m = triangulated_mesh();
    cvmtest_expect e;
    cvmtest_expect_init(&e);
    e.check_euler = 1;
    e.euler = cvmtest_square_with_hole.euler;
    e.check_area = 1;
    e.area = cvmtest_square_with_hole.area;
    e.segs = cvmtest_square_with_hole.seg;
    e.nseg = cvmtest_square_with_hole.nseg;
    cvmtest_assert_valid_ex(m, &e);
    cvm_mesh_free(m);
}
END_TEST

TCase *api_args_tcase(void)
{
    TCase *tc = tcase_create("arguments");
    tcase_add_test(tc, free_and_errmsg_accept_null);
    tcase_add_test(tc, create_rejects_null_and_reports_nomem);
    tcase_add_test(tc, every_call_rejects_a_null_handle);
    tcase_add_test(tc, null_arrays_with_nonzero_counts_are_rejected);
    tcase_add_test(tc, outputs_reject_null_destinations);
    tcase_add_test(tc, calls_in_the_wrong_state_are_rejected);
    tcase_add_test(tc, set_points_checks_dim_and_finiteness);
    tcase_add_test(tc, short_buffers_are_refused_and_untouched);
    tcase_add_test(tc, triangulated_square_with_hole_passes_the_oracle);
    return tc;
}
