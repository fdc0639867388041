/* test_sizing.c - the cvm_sizing handle (lib/refine/sizing.c): combination by minimum, invalid sizes named. */
#include <math.h>
#include <string.h>

#include "refine/refine_tests.h"

START_TEST(empty_sizing_has_no_bound)
{
    cvm_sizing *s;
    double h;
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 1, 2), CVM_OK);
    ck_assert(isinf(h) && h > 0);
    cvm_sizing_free(s);
    cvm_sizing_free(NULL);
}
END_TEST

START_TEST(sources_combine_by_minimum)
{
    cvm_sizing *s;
    double h;
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_uniform(s, 1.0), CVM_OK);
    ck_assert_int_eq(cvm_sizing_add_point_source(s, 0, 0, 0.1, 0.5), CVM_OK);
    ck_assert_int_eq(cvm_sizing_add_line_source(s, 10, -1, 10, 1, 0.2, 0.1), CVM_OK);
    /* at the point source */
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 0, 0), CVM_OK);
    ck_assert_double_eq_tol(h, 0.1, 1e-15);
    /* distance 1 from it: 0.1 + 0.5 */
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 0, 1), CVM_OK);
    ck_assert_double_eq_tol(h, 0.6, 1e-15);
    /* far from both sources: the uniform size caps it */
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 0, 8), CVM_OK);
    ck_assert_double_eq_tol(h, 1.0, 1e-15);
    /* near the line source: 0.2 + 0.1 x its distance 0.5 */
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 10.5, 0.5), CVM_OK);
    ck_assert_double_eq_tol(h, 0.25, 1e-15);
    cvm_sizing_free(s);
}
END_TEST

static double cb_half_x(void *payload, double x, double y)
{
    (void)y;
    return *(const double *)payload + 0.5 * x;
}

static double cb_negative(void *payload, double x, double y)
{
    (void)payload;
    (void)x;
    (void)y;
    return -1.0;
}

static double cb_nan(void *payload, double x, double y)
{
    (void)payload;
    (void)x;
    (void)y;
    return NAN;
}

START_TEST(callback_is_called_with_payload)
{
    cvm_sizing *s;
    double base = 0.25, h;
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_callback(s, cb_half_x, &base), CVM_OK);
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 1, 0), CVM_OK);
    ck_assert_double_eq_tol(h, 0.75, 1e-15);
    ck_assert_int_eq(cvm_sizing_set_callback(s, NULL, NULL), CVM_OK);
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 1, 0), CVM_OK);
    ck_assert(isinf(h));
    cvm_sizing_free(s);
}
END_TEST

START_TEST(bad_sizes_are_rejected_and_named)
{
    static const double bad[] = {0.0, -1.0};
    cvm_sizing *s;
    double h;
    size_t i;
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    for (i = 0; i < 2; i++) {
        ck_assert_int_eq(cvm_sizing_set_uniform(s, bad[i]), CVM_E_ARGUMENT);
        ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "uniform size"));
    }
    ck_assert_int_eq(cvm_sizing_set_uniform(s, NAN), CVM_E_INPUT_NONFINITE);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "uniform size"));
    ck_assert_int_eq(cvm_sizing_set_uniform(s, INFINITY), CVM_E_INPUT_NONFINITE);
    /* the handle is unchanged by the failures */
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 0, 0), CVM_OK);
    ck_assert(isinf(h));
    ck_assert_int_eq(cvm_sizing_add_point_source(s, 0, 0, 1, 0), CVM_OK);
    ck_assert_int_eq(cvm_sizing_add_point_source(s, 0, 0, -2, 0), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "point source 1"));
    ck_assert_int_eq(cvm_sizing_add_point_source(s, NAN, 0, 1, 0), CVM_E_INPUT_NONFINITE);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "point source 1"));
    ck_assert_int_eq(cvm_sizing_add_point_source(s, 0, 0, 1, -0.1), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "growth"));
    ck_assert_int_eq(cvm_sizing_add_line_source(s, 0, 0, 1, 1, 0, 0), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "line source 0"));
    ck_assert_int_eq(cvm_sizing_add_line_source(s, 0, 0, 1, 1, NAN, 0), CVM_E_INPUT_NONFINITE);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "line source 0"));
    ck_assert_int_eq(cvm_sizing_eval(&h, s, NAN, 0), CVM_E_INPUT_NONFINITE);
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 0, 0), CVM_OK);
    ck_assert_str_eq(cvm_sizing_errmsg(s), "");
    ck_assert_double_eq(h, 1.0);
    cvm_sizing_free(s);
}
END_TEST

START_TEST(bad_callback_values_stop_eval_and_refine)
{
    static const double sq[] = {0, 0, 1, 0, 1, 1, 0, 1};
    static const cvm_index seg[] = {0, 1, 1, 2, 2, 3, 3, 0};
    cvm_sizing *s;
    cvm_mesh *m;
    double h;
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_callback(s, cb_negative, NULL), CVM_OK);
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 0.5, 0.5), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "sizing callback"));
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, sq, 4, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, seg, 4), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_refine(m, s, CVM_ALGO_DELAUNAY), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "sizing callback"));
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_callback(s, cb_nan, NULL), CVM_OK);
    ck_assert_int_eq(cvm_mesh_refine(m, s, CVM_ALGO_FRONTAL), CVM_E_INPUT_NONFINITE);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "sizing callback"));
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    cvm_mesh_free(m);
    cvm_sizing_free(s);
}
END_TEST

START_TEST(null_arguments_and_unsupported)
{
    cvm_sizing *s;
    double h;
    ck_assert_int_eq(cvm_sizing_create(NULL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_sizing_set_uniform(NULL, 1), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_sizing_add_point_source(NULL, 0, 0, 1, 0), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_sizing_add_line_source(NULL, 0, 0, 1, 0, 1, 0), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_sizing_set_callback(NULL, NULL, NULL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_sizing_set_automatic(NULL, 1, 1), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_sizing_eval(&h, NULL, 0, 0), CVM_E_NULL_ARG);
    ck_assert_str_eq(cvm_sizing_errmsg(NULL), "no sizing handle");
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_eval(NULL, s, 0, 0), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_sizing_set_automatic(s, 2, 0.3), CVM_E_UNSUPPORTED);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "not available"));
    cvm_sizing_free(s);
}
END_TEST

TCase *refine_sizing_tcase(void)
{
    TCase *tc = tcase_create("sizing");
    tcase_add_test(tc, empty_sizing_has_no_bound);
    tcase_add_test(tc, sources_combine_by_minimum);
    tcase_add_test(tc, callback_is_called_with_payload);
    tcase_add_test(tc, bad_sizes_are_rejected_and_named);
    tcase_add_test(tc, bad_callback_values_stop_eval_and_refine);
    tcase_add_test(tc, null_arguments_and_unsupported);
    return tc;
}
