/* test_sizing_batch.c - the batch sizing callback (cvm_sizing_set_batch_callback, sizing.c). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "refine/refine_tests.h"

static double size_at(double x, double y)
{
    return 0.02 + 0.05 * x + 0.02 * y * y;
}

static double scalar_cb(void *payload, double x, double y)
{
    (void)payload;
    return size_at(x, y);
}

/* Records the size of each batch it is asked for. */
typedef struct batch_log {
    size_t calls, points, largest, first;
    int fail;           /* non-zero: return it */
    double bad;         /* non-zero: the size of every point */
} batch_log;

static int batch_cb(void *payload, const double *xy, size_t n, double *h)
{
    batch_log *log = payload;
    size_t i;
    if (log->calls++ == 0)
        log->first = n;
    log->points += n;
    if (n > log->largest)
        log->largest = n;
    if (log->fail)
        return log->fail;
    for (i = 0; i < n; i++)
        h[i] = log->bad != 0 ? log->bad : size_at(xy[2 * i], xy[2 * i + 1]);
    return 0;
}

/* 3000 random points in the unit square, triangulated, refined with sizing s. */
static cvm_mesh *refined_cloud(cvm_sizing *s, cvm_status *st)
{
    double *xy = malloc(2 * 3000 * sizeof *xy);
    unsigned long r = 12345;
    cvm_mesh *m;
    size_t i;
    ck_assert_ptr_nonnull(xy);
    for (i = 0; i < 2 * 3000; i++) {
        r = r * 6364136223846793005UL + 1442695040888963407UL;
        xy[i] = (double)(r >> 11) / 9007199254740992.0;
    }
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 3000, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    *st = cvm_mesh_refine(m, s, CVM_ALGO_DELAUNAY);
    free(xy);
    return m;
}

START_TEST(batch_callback_gives_the_mesh_of_the_scalar_one)
{
    cvm_sizing *scalar, *batch;
    batch_log log;
    cvm_mesh *a, *b;
    cvm_status sa, sb;
    double *xa, *xb;
    cvm_index *ta, *tb;
    size_t na, nb, ma, mb;
    memset(&log, 0, sizeof log);
    ck_assert_int_eq(cvm_sizing_create(&scalar), CVM_OK);
    ck_assert_int_eq(cvm_sizing_create(&batch), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_callback(scalar, scalar_cb, NULL), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_batch_callback(batch, batch_cb, &log), CVM_OK);
    a = refined_cloud(scalar, &sa);
    b = refined_cloud(batch, &sb);
    ck_assert_int_eq(sa, CVM_OK);
    ck_assert_int_eq(sb, CVM_OK);
    rtest_fetch(a, &xa, &na, &ta, &ma);
    rtest_fetch(b, &xb, &nb, &tb, &mb);
    ck_assert_uint_gt(na, 3000);
    ck_assert_uint_eq(na, nb);
    ck_assert_uint_eq(ma, mb);
    ck_assert_int_eq(memcmp(xa, xb, 2 * na * sizeof *xa), 0);   /* bit for bit */
    ck_assert_int_eq(memcmp(ta, tb, 3 * ma * sizeof *ta), 0);
    /* the 3000 starting vertices came in batches of 1024, 1024 and 952; then
     * one call per Steiner point */
    ck_assert_uint_eq(log.first, 1024);
    ck_assert_uint_eq(log.largest, 1024);
    ck_assert_uint_eq(log.points - 3000, log.calls - 3);
    ck_assert_int_eq(cvm_mesh_check(b), CVM_OK);
    free(xa);
    free(xb);
    free(ta);
    free(tb);
    cvm_mesh_free(a);
    cvm_mesh_free(b);
    cvm_sizing_free(scalar);
    cvm_sizing_free(batch);
}
END_TEST

START_TEST(batch_callback_errors_stop_and_are_named)
{
    cvm_sizing *s;
    batch_log log;
    cvm_mesh *m;
    cvm_status st;
    double h;
    memset(&log, 0, sizeof log);
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_batch_callback(s, batch_cb, &log), CVM_OK);
    log.fail = 7;
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 0.5, 0.25), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "sizing callback failed (returned 7)"));
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "(0.5, 0.25)"));
    m = refined_cloud(s, &st);
    ck_assert_int_eq(st, CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "batch of 1024 points"));
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    cvm_mesh_free(m);
    log.fail = 0;
    log.bad = -1;
    m = refined_cloud(s, &st);
    ck_assert_int_eq(st, CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "sizing callback returned size -1"));
    cvm_mesh_free(m);
    log.bad = NAN;
    m = refined_cloud(s, &st);
    ck_assert_int_eq(st, CVM_E_INPUT_NONFINITE);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "non-finite size"));
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    cvm_mesh_free(m);
    cvm_sizing_free(s);
}
END_TEST

static double nd_cb(void *payload, const double *x, int dim)
{
    (void)payload;
    (void)dim;
    return 3 + x[0];
}

START_TEST(one_user_function_per_handle)
{
    cvm_sizing *s;
    batch_log log;
    double h, p[2] = {1, 0};
    memset(&log, 0, sizeof log);
    ck_assert_int_eq(cvm_sizing_set_batch_callback(NULL, batch_cb, &log), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_callback(s, scalar_cb, NULL), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_batch_callback(s, batch_cb, &log), CVM_OK);
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 1, 0), CVM_OK);   /* the batch one, n = 1 */
    ck_assert_uint_eq(log.calls, 1);
    ck_assert_uint_eq(log.first, 1);
    ck_assert(h == size_at(1, 0));
    ck_assert_int_eq(cvm_sizing_set_callback_nd(s, nd_cb, NULL), CVM_OK);
    ck_assert_int_eq(cvm_sizing_eval_nd(&h, s, p, 2), CVM_OK);
    ck_assert(h == 4);
    ck_assert_uint_eq(log.calls, 1);                           /* replaced */
    ck_assert_int_eq(cvm_sizing_set_batch_callback(s, batch_cb, &log), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_uniform(s, 0.05), CVM_OK);
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 1, 0), CVM_OK);   /* minimum with the sources */
    ck_assert(h == 0.05);
    ck_assert_int_eq(cvm_sizing_set_batch_callback(s, NULL, NULL), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_uniform(s, 1), CVM_OK);
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 1, 0), CVM_OK);
    ck_assert(h == 1);
    ck_assert_uint_eq(log.calls, 2);
    cvm_sizing_free(s);
}
END_TEST

TCase *refine_sizing_batch_tcase(void)
{
    TCase *tc = tcase_create("sizing_batch");
    tcase_add_test(tc, batch_callback_gives_the_mesh_of_the_scalar_one);
    tcase_add_test(tc, batch_callback_errors_stop_and_are_named);
    tcase_add_test(tc, one_user_function_per_handle);
    tcase_set_timeout(tc, 60);
    return tc;
}
