/* oom_sweep.c - out of memory at every allocation of a library call (see oom_sweep.h). */
#include <check.h>

#include "support/failing_alloc.h"
#include "support/oom_sweep.h"

void cvmtest_oom_sweep(void (*setup)(cvm_mesh *m, void *arg), cvm_status (*run)(cvm_mesh *m, void *arg),
                       void (*check)(cvm_mesh *m, void *arg), void *arg)
{
    int persistent;
    for (persistent = 0; persistent <= 1; persistent++) {
        long i;
        for (i = 1; i < 100000; i++) {
            cvmtest_alloc a;
            cvm_mesh *m;
            cvm_status st;
            long failed;
            cvmtest_alloc_init(&a, 0, 0);
            ck_assert_int_eq(cvmtest_mesh_create(&m, &a), CVM_OK);
            setup(m, arg);
            cvmtest_alloc_arm(&a, i, persistent); /* counts from 0 again */
            st = run(m, arg);
            failed = a.n_failed;
            cvmtest_alloc_arm(&a, 0, 0);
            ck_assert_msg(st == CVM_OK || st == CVM_E_NOMEM, "allocation %ld: %s", i, cvm_status_str(st));
            if (cvm_mesh_check(m) != CVM_E_STATE) {
                ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "allocation %ld: %s", i, cvm_mesh_errmsg(m));
                if (check)
                    check(m, arg);
            }
            cvm_mesh_free(m);
            ck_assert_int_eq(a.live_blocks, 0);
            if (failed == 0) {
                ck_assert_int_eq(st, CVM_OK);
                break;
            }
        }
        ck_assert_msg(i > 20 && i < 100000, "%ld allocations", i);
    }
}
