/*
 * test_threads.c - no global mutable state: handles triangulating at the same
 * time on two threads give exactly the meshes of a serial run.
 */
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "api/api_tests.h"
#include "cvmesh.h"
#include "support/fixtures.h"

enum { N_RANDOM = 20000, N_PSLG_EXTRA = 2000 };

typedef struct job {
    int kind;            /* 0: Delaunay of random points; 1: CDT of the square with a hole */
    cvm_status status;   /* first failing status */
    cvm_status check;    /* cvm_mesh_check() */
    char msg[256];
    size_t nv, nt;
    double *xy;
    cvm_index *tri;
} job;

static cvm_status set_input(cvm_mesh *m, int kind)
{
    cvm_status s;
    double *xy;
    if (kind == 0) {
        xy = (double *)malloc(2 * N_RANDOM * sizeof(double));
        if (!xy)
            return CVM_E_NOMEM;
        cvmtest_random_points(xy, N_RANDOM, 42);
        s = cvm_mesh_set_points(m, xy, N_RANDOM, 2);
    } else {
        const cvmtest_pslg *p = &cvmtest_square_with_hole;
        size_t i, n = p->np + N_PSLG_EXTRA;
        xy = (double *)malloc(2 * n * sizeof(double));
        if (!xy)
            return CVM_E_NOMEM;
        memcpy(xy, p->xy, 2 * p->np * sizeof(double));
        cvmtest_random_points(xy + 2 * p->np, N_PSLG_EXTRA, 43);
        for (i = 2 * p->np; i < 2 * n; i++)
            xy[i] *= 3.0;
        s = cvm_mesh_set_points(m, xy, n, 2);
        if (s == CVM_OK)
            s = cvm_mesh_set_segments(m, p->seg, p->nseg);
        if (s == CVM_OK)
            s = cvm_mesh_set_holes(m, p->holes, p->nholes);
    }
    free(xy);
    return s;
}

static void *run_job(void *arg)
{
    job *j = (job *)arg;
    cvm_mesh *m = NULL;
    cvm_status s = cvm_mesh_create(&m);
    if (s == CVM_OK)
        s = set_input(m, j->kind);
    if (s == CVM_OK)
        s = cvm_mesh_triangulate(m);
    if (s == CVM_OK)
        s = cvm_mesh_count(&j->nv, m, CVM_ENT_VERTEX);
    if (s == CVM_OK)
        s = cvm_mesh_count(&j->nt, m, CVM_ENT_TRIANGLE);
    if (s == CVM_OK) {
        j->xy = (double *)malloc(2 * j->nv * sizeof(double) + 1);
        j->tri = (cvm_index *)malloc(3 * j->nt * sizeof(cvm_index) + 1);
        s = j->xy && j->tri ? cvm_mesh_copy_points(j->xy, 2 * j->nv, m) : CVM_E_NOMEM;
    }
    if (s == CVM_OK)
        s = cvm_mesh_copy_cells(j->tri, 3 * j->nt, m, CVM_ENT_TRIANGLE);
    j->check = s == CVM_OK ? cvm_mesh_check(m) : s;
    j->status = s;
    strncpy(j->msg, m ? cvm_mesh_errmsg(m) : "create failed", sizeof j->msg - 1);
    cvm_mesh_free(m);
    return NULL;
}

static void job_free(job *j)
{
    free(j->xy);
    free(j->tri);
}

static void assert_job_equal(const job *ref, const job *j)
{
    ck_assert_msg(j->status == CVM_OK, "threaded kind %d: %s", j->kind, j->msg);
    ck_assert_msg(j->check == CVM_OK, "threaded kind %d: check: %s", j->kind, j->msg);
    ck_assert_uint_eq(j->nv, ref->nv);
    ck_assert_uint_eq(j->nt, ref->nt);
    ck_assert_msg(memcmp(j->xy, ref->xy, 2 * ref->nv * sizeof(double)) == 0,
                  "kind %d: points differ from the serial run", j->kind);
    ck_assert_msg(memcmp(j->tri, ref->tri, 3 * ref->nt * sizeof(cvm_index)) == 0,
                  "kind %d: triangles differ from the serial run", j->kind);
}

static void run_pair(int kind_a, int kind_b)
{
    job ref[2], par[2];
    pthread_t th[2];
    int i;
    memset(ref, 0, sizeof ref);
    memset(par, 0, sizeof par);
    ref[0].kind = par[0].kind = kind_a;
    ref[1].kind = par[1].kind = kind_b;
    for (i = 0; i < 2; i++) {
        run_job(&ref[i]);
        ck_assert_msg(ref[i].status == CVM_OK, "serial kind %d: %s", ref[i].kind, ref[i].msg);
        ck_assert_msg(ref[i].check == CVM_OK, "serial kind %d: check: %s", ref[i].kind, ref[i].msg);
    }
    for (i = 0; i < 2; i++)
        ck_assert_int_eq(pthread_create(&th[i], NULL, run_job, &par[i]), 0);
    for (i = 0; i < 2; i++)
        ck_assert_int_eq(pthread_join(th[i], NULL), 0);
    for (i = 0; i < 2; i++) {
        assert_job_equal(&ref[i], &par[i]);
        job_free(&ref[i]);
        job_free(&par[i]);
    }
}

START_TEST(two_threads_same_input_match_serial_run)
{
    run_pair(0, 0);
}
END_TEST

START_TEST(two_threads_different_inputs_match_serial_run)
{
    run_pair(0, 1);
    run_pair(1, 1);
}
END_TEST

TCase *api_threads_tcase(void)
{
    TCase *tc = tcase_create("threads");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, two_threads_same_input_match_serial_run);
    tcase_add_test(tc, two_threads_different_inputs_match_serial_run);
    return tc;
}
