/* test_sizing_nd.c - the dimension-generic sizing calls and the metric source
 * (lib/sizing/sizing_nd.c): the same sizes as the 2D calls, dims refused, metric checked. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "api/api_tests.h"
#include "support/fixtures.h"

static const double k_probe[][2] = {{0, 0}, {1, 0.5}, {-3, 2}, {10, 0}, {10.5, 3}, {0.25, -7}};
#define NPROBE (sizeof k_probe / sizeof k_probe[0])

START_TEST(nd_sources_give_the_sizes_of_the_2d_sources)
{
    static const double p[] = {0.0, 0.0}, ends[] = {10, -1, 10, 1};
    cvm_sizing *a, *b;
    size_t k;
    ck_assert_int_eq(cvm_sizing_create(&a), CVM_OK);
    ck_assert_int_eq(cvm_sizing_create(&b), CVM_OK);
    ck_assert_int_eq(cvm_sizing_add_point_source(a, 0, 0, 0.1, 0.5), CVM_OK);
    ck_assert_int_eq(cvm_sizing_add_point_source_nd(b, p, 2, 0.1, 0.5), CVM_OK);
    ck_assert_int_eq(cvm_sizing_add_line_source(a, 10, -1, 10, 1, 0.2, 0.1), CVM_OK);
    ck_assert_int_eq(cvm_sizing_add_line_source_nd(b, ends, 2, 0.2, 0.1), CVM_OK);
    for (k = 0; k < NPROBE; k++) {
        double ha, hb;
        ck_assert_int_eq(cvm_sizing_eval(&ha, a, k_probe[k][0], k_probe[k][1]), CVM_OK);
        ck_assert_int_eq(cvm_sizing_eval_nd(&hb, b, k_probe[k], 2), CVM_OK);
        ck_assert(ha == hb);
    }
    /* at the line source: its size */
    {
        double h, x[2] = {10, 0};
        ck_assert_int_eq(cvm_sizing_eval_nd(&h, b, x, 2), CVM_OK);
        ck_assert_double_eq_tol(h, 0.2, 1e-15);
    }
    cvm_sizing_free(a);
    cvm_sizing_free(b);
}
END_TEST

START_TEST(nd_sources_refuse_bad_arguments_and_keep_the_handle)
{
    static const double x3[] = {0, 0, 0}, ends3[] = {0, 0, 0, 1, 1, 1};
    double bad[4] = {0, 0, 1, 1};
    cvm_sizing *s;
    double h;
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_add_point_source_nd(s, x3, 1, 1, 0), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "got 1"));
    ck_assert_int_eq(cvm_sizing_add_point_source_nd(s, NULL, 2, 1, 0), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_sizing_add_point_source_nd(NULL, x3, 2, 1, 0), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_sizing_add_point_source_nd(s, x3, 2, -1, 0), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "point source 0"));
    ck_assert_int_eq(cvm_sizing_add_line_source_nd(s, ends3, 7, 1, 0), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_sizing_add_line_source_nd(s, NULL, 2, 1, 0), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_sizing_add_line_source_nd(NULL, ends3, 2, 1, 0), CVM_E_NULL_ARG);
    bad[3] = NAN;
    ck_assert_int_eq(cvm_sizing_add_line_source_nd(s, bad, 2, 1, 0), CVM_E_INPUT_NONFINITE);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "line source 0"));
    /* nothing was added: no bound */
    ck_assert_int_eq(cvm_sizing_eval_nd(&h, s, x3, 2), CVM_OK);
    ck_assert(isinf(h) && h > 0);
    ck_assert_int_eq(cvm_sizing_eval_nd(&h, s, x3, 3), CVM_OK); /* no source: no bound */
    ck_assert(isinf(h) && h > 0);
    ck_assert_int_eq(cvm_sizing_eval_nd(&h, s, x3, 0), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_sizing_eval_nd(&h, s, NULL, 2), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_sizing_eval_nd(NULL, s, x3, 2), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_sizing_eval_nd(&h, NULL, x3, 2), CVM_E_NULL_ARG);
    bad[0] = INFINITY;
    ck_assert_int_eq(cvm_sizing_eval_nd(&h, s, bad, 2), CVM_E_INPUT_NONFINITE);
    cvm_sizing_free(s);
}
END_TEST

typedef struct nd_calls {
    int calls, bad_dim;
    double value;
} nd_calls;

static double size_nd(void *payload, const double *x, int dim)
{
    nd_calls *c = payload;
    c->calls++;
    c->bad_dim += dim != 2;
    return c->value > 0 ? c->value : c->value == 0 ? 0.25 + 0.1 * fabs(x[0] - 1.5) : c->value;
}

static double size_xy(void *payload, double x, double y)
{
    (void)payload;
    (void)y;
    return 0.25 + 0.1 * fabs(x - 1.5);
}

START_TEST(nd_callback_is_called_with_the_position_and_dim)
{
    cvm_sizing *s;
    nd_calls c = {0, 0, 0.0};
    double h, x[2] = {3.5, -1};
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_callback_nd(NULL, size_nd, &c), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_sizing_set_callback_nd(s, size_nd, &c), CVM_OK);
    ck_assert_int_eq(cvm_sizing_eval_nd(&h, s, x, 2), CVM_OK);
    ck_assert_double_eq_tol(h, 0.45, 1e-15);
    ck_assert_int_eq(c.calls, 1);
    ck_assert_int_eq(c.bad_dim, 0);
    /* a bad value names the callback and the position */
    c.value = -2;
    ck_assert_int_eq(cvm_sizing_eval_nd(&h, s, x, 2), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "sizing callback"));
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "3.5"));
    c.value = NAN;
    ck_assert_int_eq(cvm_sizing_eval_nd(&h, s, x, 2), CVM_E_INPUT_NONFINITE);
    /* one user function per handle: the 2D setter replaces it, and back */
    c.calls = 0;
    ck_assert_int_eq(cvm_sizing_set_callback(s, size_xy, NULL), CVM_OK);
    ck_assert_int_eq(cvm_sizing_eval_nd(&h, s, x, 2), CVM_OK);
    ck_assert_int_eq(c.calls, 0);
    ck_assert_double_eq_tol(h, 0.45, 1e-15);
    c.value = 0.125;
    ck_assert_int_eq(cvm_sizing_set_callback_nd(s, size_nd, &c), CVM_OK);
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 0, 0), CVM_OK);
    ck_assert(h == 0.125);
    ck_assert_int_eq(c.calls, 1);
    /* removing it leaves no source */
    ck_assert_int_eq(cvm_sizing_set_callback_nd(s, NULL, &c), CVM_OK);
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 0, 0), CVM_OK);
    ck_assert(isinf(h));
    cvm_sizing_free(s);
}
END_TEST

/* The refiners read the _nd callback: the same mesh as the 2D callback. */
START_TEST(refine_with_the_nd_callback_gives_the_2d_callback_mesh)
{
    cvm_mesh *m[2];
    cvm_sizing *s[2];
    nd_calls c = {0, 0, 0.0};
    size_t nv[2], nt[2];
    double *xy[2];
    int i;
    for (i = 0; i < 2; i++) {
        ck_assert_int_eq(cvm_mesh_create(&m[i]), CVM_OK);
        ck_assert_int_eq(cvmtest_pslg_set(m[i], &cvmtest_square_with_hole), CVM_OK);
        ck_assert_int_eq(cvm_mesh_triangulate(m[i]), CVM_OK);
        ck_assert_int_eq(cvm_sizing_create(&s[i]), CVM_OK);
    }
    ck_assert_int_eq(cvm_sizing_set_callback(s[0], size_xy, NULL), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_callback_nd(s[1], size_nd, &c), CVM_OK);
    for (i = 0; i < 2; i++) {
        ck_assert_msg(cvm_mesh_refine(m[i], s[i], CVM_ALGO_FRONTAL) == CVM_OK, "%s",
                      cvm_mesh_errmsg(m[i]));
        ck_assert_int_eq(cvm_mesh_count(&nv[i], m[i], CVM_ENT_VERTEX), CVM_OK);
        ck_assert_int_eq(cvm_mesh_count(&nt[i], m[i], CVM_ENT_TRIANGLE), CVM_OK);
        xy[i] = malloc(2 * nv[i] * sizeof(double));
        ck_assert_ptr_nonnull(xy[i]);
        ck_assert_int_eq(cvm_mesh_copy_points_nd(xy[i], 2 * nv[i], 2, m[i]), CVM_OK);
    }
    ck_assert_int_gt(c.calls, 0);
    ck_assert_int_eq(c.bad_dim, 0);
    ck_assert_uint_eq(nv[0], nv[1]);
    ck_assert_uint_eq(nt[0], nt[1]);
    ck_assert_uint_gt(nv[0], 40); /* sizes of 0.25 .. 0.4 on a 3 x 3 square */
    ck_assert_mem_eq(xy[0], xy[1], 2 * nv[0] * sizeof(double));
    for (i = 0; i < 2; i++) {
        free(xy[i]);
        cvm_sizing_free(s[i]);
        cvm_mesh_free(m[i]);
    }
}
END_TEST

typedef struct metric_case {
    double g[3];
    int refuse, calls, dg_given, bad_dim;
} metric_case;

static int metric_fn(void *payload, const double *x, int dim, double *g, double *dg)
{
    metric_case *c = payload;
    (void)x;
    c->calls++;
    c->dg_given += dg != NULL;
    c->bad_dim += dim != 2;
    if (c->refuse)
        return 1;
    memcpy(g, c->g, sizeof c->g);
    return 0;
}

START_TEST(metric_is_evaluated_and_checked)
{
    cvm_sizing *s;
    metric_case c = {{4, 1, 2}, 0, 0, 0, 0};
    double x[2] = {0.5, -0.25}, g[4] = {-1, -1, -1, -1}, h;
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_eval_metric(g, 4, s, x, 2), CVM_E_STATE);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "no metric"));
    ck_assert_int_eq(cvm_sizing_set_metric_fn(s, metric_fn, 2, &c), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_sizing_eval_metric(g, 4, s, x, 2), CVM_E_STATE); /* unchanged */
    ck_assert_int_eq(cvm_sizing_set_metric_fn(NULL, metric_fn, 0, &c), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_sizing_set_metric_fn(s, metric_fn, 1, &c), CVM_OK);
    ck_assert_int_eq(cvm_sizing_eval_metric(g, 4, s, x, 2), CVM_OK);
    ck_assert(g[0] == 4 && g[1] == 1 && g[2] == 2 && g[3] == -1);
    ck_assert_int_eq(c.calls, 1);
    ck_assert_int_eq(c.dg_given, 0); /* the evaluation asks for no derivatives */
    ck_assert_int_eq(c.bad_dim, 0);
    /* the scalar sizing does not read the metric */
    ck_assert_int_eq(cvm_sizing_eval_nd(&h, s, x, 2), CVM_OK);
    ck_assert(isinf(h));
    ck_assert_int_eq(c.calls, 1);
    /* arguments */
    g[0] = -1;
    ck_assert_int_eq(cvm_sizing_eval_metric(g, 2, s, x, 2), CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_sizing_eval_metric(NULL, 3, s, x, 2), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_sizing_eval_metric(g, 3, NULL, x, 2), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_sizing_eval_metric(g, 3, s, NULL, 2), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_sizing_eval_metric(g, 6, s, x, 3), CVM_E_UNSUPPORTED);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "3D kernel"));
    ck_assert_int_eq(cvm_sizing_eval_metric(g, 6, s, x, 5), CVM_E_ARGUMENT);
    ck_assert(g[0] == -1);
    /* not positive definite: det = 4 * 2 - 3^2 < 0 */
    c.g[1] = 3;
    ck_assert_int_eq(cvm_sizing_eval_metric(g, 3, s, x, 2), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "not positive definite"));
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "(0.5, -0.25)"));
    c.g[1] = 0;
    c.g[0] = 0; /* semi-definite */
    ck_assert_int_eq(cvm_sizing_eval_metric(g, 3, s, x, 2), CVM_E_ARGUMENT);
    c.g[0] = NAN;
    ck_assert_int_eq(cvm_sizing_eval_metric(g, 3, s, x, 2), CVM_E_INPUT_NONFINITE);
    c.g[0] = 1;
    c.refuse = 1;
    ck_assert_int_eq(cvm_sizing_eval_metric(g, 3, s, x, 2), CVM_E_INPUT_OUTSIDE);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "refused"));
    c.refuse = 0;
    x[1] = NAN;
    ck_assert_int_eq(cvm_sizing_eval_metric(g, 3, s, x, 2), CVM_E_INPUT_NONFINITE);
    ck_assert(g[0] == -1); /* nothing written on any failure */
    /* removed again */
    ck_assert_int_eq(cvm_sizing_set_metric_fn(s, NULL, 1, &c), CVM_OK);
    x[1] = 0;
    ck_assert_int_eq(cvm_sizing_eval_metric(g, 3, s, x, 2), CVM_E_STATE);
    cvm_sizing_free(s);
}
END_TEST

TCase *api_sizing_nd_tcase(void)
{
    TCase *tc = tcase_create("sizing_nd");
    tcase_add_test(tc, nd_sources_give_the_sizes_of_the_2d_sources);
    tcase_add_test(tc, nd_sources_refuse_bad_arguments_and_keep_the_handle);
    tcase_add_test(tc, nd_callback_is_called_with_the_position_and_dim);
    tcase_add_test(tc, refine_with_the_nd_callback_gives_the_2d_callback_mesh);
    tcase_add_test(tc, metric_is_evaluated_and_checked);
    return tc;
}
