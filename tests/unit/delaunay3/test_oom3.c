/* test_oom3.c - out of memory at every allocation of a 3D build and its output: a status, no leak, a reusable store. */
#include <stdlib.h>

#include "delaunay3/delaunay3_tests.h"
#include "support/failing_alloc.h"

static void sweep(const double *xyz, const double *w, size_t n)
{
    long at;
    int persistent;
    for (persistent = 0; persistent < 2; persistent++) {
        for (at = 1;; at++) {
            cvmtest_alloc a;
            cvm__ctx ctx;
            cvm__tet3 T;
            cvm_status s;
            int32_t *tets;
            long failed;
            cvmtest_alloc_init(&a, at, persistent);
            cvm__ctx_init_default(&ctx);
            ctx.alloc_fn = cvmtest_malloc, ctx.realloc_fn = cvmtest_realloc;
            ctx.free_fn = cvmtest_free, ctx.payload = &a;
            cvm__tet3_init(&T, &ctx);
            s = cvm__tet3_build(&T, xyz, w, n, 3);
            ck_assert_msg(s == CVM_OK || s == CVM_E_NOMEM, "fail at %ld: status %d", at, (int)s);
            if (s == CVM_OK) {
                tets = malloc(4 * T.n_finite * sizeof *tets + 16);
                s = cvm__tet3_copy_tets(&T, tets);
                ck_assert(s == CVM_OK || s == CVM_E_NOMEM);
                if (s == CVM_OK)
                    s = cvm__tet3_check(&T);
                ck_assert(s == CVM_OK || s == CVM_E_NOMEM);
                free(tets);
            }
            failed = a.n_failed;
            if (s == CVM_E_NOMEM) { /* the store is reusable once memory is back */
                cvmtest_alloc_arm(&a, 0, 0);
                ck_assert_int_eq(cvm__tet3_build(&T, xyz, w, n, 3), CVM_OK);
                ck_assert_int_eq(cvm__tet3_check(&T), CVM_OK);
            }
            cvm__tet3_free(&T);
            ck_assert_int_eq(a.live_blocks, 0);
            if (failed == 0) {
                ck_assert_msg(s == CVM_OK, "no failure at %ld (persistent %d) but status %d", at,
                              persistent, (int)s);
                ck_assert_int_gt(a.n_calls, 20);
                break;
            }
        }
    }
}

START_TEST(oom_at_every_allocation_of_a_build)
{
    double xyz[3 * 400], w[400];
    size_t i;
    d3test_random(xyz, 400, 51);
    sweep(xyz, NULL, 400);
    d3test_random(w, 400, 52);
    for (i = 0; i < 400; i++)
        w[i] *= 0.01;
    sweep(xyz, w, 400);
}
END_TEST

TCase *delaunay3_oom_tcase(void)
{
    TCase *tc = tcase_create("oom3");
    tcase_set_timeout(tc, 300);
    tcase_add_test(tc, oom_at_every_allocation_of_a_build);
    return tc;
}
