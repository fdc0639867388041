/*
 * test_oom.c - out-of-memory injection: for k = 1, 2, ... allocation k fails
 * (once, or from k on) during create + set input + triangulate + insert of a
 * square with a hole. Each run must report CVM_E_NOMEM (or CVM_OK once k
 * passes the last allocation), leak nothing, and leave the handle reusable:
 * a retry without failures gives the reference mesh (SQLite malloc.test).
 */
#include <stdlib.h>
#include <string.h>

#include "api/api_tests.h"
#include "cvmesh.h"
#include "support/failing_alloc.h"
#include "support/fixtures.h"
#include "support/mesh_oracle.h"

typedef struct result {
    size_t nv, nt;
    double *xy;
    cvm_index *tri;
    cvm_index ids[3];
} result;

static void result_free(result *r)
{
    free(r->xy);
    free(r->tri);
    memset(r, 0, sizeof *r);
}

/* Points inserted after the triangulation: inside, inside, in the hole. */
static const double k_extra[] = {0.5, 0.5, 2.5, 1.25, 1.5, 1.5};

/* The whole sequence on m; results copied into r (test memory, not the handle's). */
static cvm_status run_sequence(cvm_mesh *m, result *r)
{
    cvm_status s;
    memset(r, 0, sizeof *r);
    s = cvmtest_pslg_set(m, &cvmtest_square_with_hole);
    if (s == CVM_OK)
        s = cvm_mesh_set_option(m, CVM_OPT_SEED, 7);
    if (s == CVM_OK)
        s = cvm_mesh_triangulate(m);
    if (s == CVM_OK) /* min_dist > 0 in a constrained mesh: the walk near each point too */
        s = cvm_mesh_insert_points(r->ids, m, k_extra, 3, 0.01);
    if (s == CVM_OK)
        s = cvm_mesh_count(&r->nv, m, CVM_ENT_VERTEX);
    if (s == CVM_OK)
        s = cvm_mesh_count(&r->nt, m, CVM_ENT_TRIANGLE);
    if (s != CVM_OK)
        return s;
    r->xy = (double *)malloc(2 * r->nv * sizeof(double) + 1);
    r->tri = (cvm_index *)malloc(3 * r->nt * sizeof(cvm_index) + 1);
    ck_assert(r->xy && r->tri);
    s = cvm_mesh_copy_points(r->xy, 2 * r->nv, m);
    if (s == CVM_OK)
        s = cvm_mesh_copy_cells(r->tri, 3 * r->nt, m, CVM_ENT_TRIANGLE);
    return s;
}

static void assert_same(const result *a, const result *b, long k)
{
    ck_assert_msg(a->nv == b->nv && a->nt == b->nt, "k=%ld: %zu/%zu vertices/triangles, reference "
                  "%zu/%zu", k, b->nv, b->nt, a->nv, a->nt);
    ck_assert_msg(memcmp(a->xy, b->xy, 2 * a->nv * sizeof(double)) == 0, "k=%ld: points differ", k);
    ck_assert_msg(memcmp(a->tri, b->tri, 3 * a->nt * sizeof(cvm_index)) == 0,
                  "k=%ld: triangles differ from the reference", k);
    ck_assert_msg(memcmp(a->ids, b->ids, sizeof a->ids) == 0, "k=%ld: inserted ids differ", k);
}

/* Reference run with a counting allocator that never fails; returns its allocation count. */
static long reference(result *ref)
{
    cvmtest_alloc a;
    cvm_mesh *m = NULL;
    long n_calls;
    cvmtest_alloc_init(&a, 0, 0);
    ck_assert_int_eq(cvmtest_mesh_create(&m, &a), CVM_OK);
    ck_assert_msg(run_sequence(m, ref) == CVM_OK, "reference run: %s", cvm_mesh_errmsg(m));
    ck_assert_int_ne(ref->ids[0], CVM_REJECTED);
    ck_assert_int_ne(ref->ids[1], CVM_REJECTED);
    ck_assert_int_eq(ref->ids[2], CVM_REJECTED); /* in the hole */
    n_calls = a.n_calls; /* before the checks below, which allocate too */
    cvmtest_assert_valid(m);
    cvm_mesh_free(m);
    ck_assert_int_eq(a.live_blocks, 0);
    ck_assert_uint_eq(a.live_bytes, 0);
    ck_assert_int_gt(n_calls, 0);
    return n_calls;
}

static void inject(int persistent)
{
    result ref, r;
    long n_alloc = reference(&ref), k, n_nomem = 0;
    for (k = 1; k <= n_alloc + 1; k++) {
        cvmtest_alloc a;
        cvm_mesh *m = (cvm_mesh *)&a;
        cvm_status s;
        cvmtest_alloc_init(&a, k, persistent);
        s = cvmtest_mesh_create(&m, &a);
        if (s != CVM_OK) {
            ck_assert_msg(s == CVM_E_NOMEM, "k=%ld: create returned %d", k, (int)s);
            ck_assert_ptr_null(m);
            ck_assert_msg(a.live_blocks == 0, "k=%ld: create leaked %ld blocks", k, a.live_blocks);
            n_nomem++;
            continue;
        }
        s = run_sequence(m, &r);
        if (a.n_failed == 0) {
            ck_assert_msg(s == CVM_OK, "k=%ld: no allocation failed, yet %s: %s", k,
                          cvm_status_str(s), cvm_mesh_errmsg(m));
            ck_assert_msg(k == n_alloc + 1, "k=%ld: only %ld allocations (reference %ld): the "
                          "allocation count is not deterministic", k, a.n_calls, n_alloc);
        } else {
            ck_assert_msg(s == CVM_E_NOMEM || s == CVM_OK, "k=%ld: failed allocation gave %d (%s)",
                          k, (int)s, cvm_mesh_errmsg(m));
            if (s == CVM_E_NOMEM) {
                n_nomem++;
                ck_assert_msg(cvm_mesh_errmsg(m)[0] != '\0', "k=%ld: NOMEM without a message", k);
            } else {
                assert_same(&ref, &r, k);
            }
        }
        result_free(&r);
        /* Reusable: retry everything with no failure. */
        cvmtest_alloc_arm(&a, 0, 0);
        s = run_sequence(m, &r);
        ck_assert_msg(s == CVM_OK, "k=%ld: retry after NOMEM failed: %s", k, cvm_mesh_errmsg(m));
        ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "k=%ld: retry mesh invalid: %s", k,
                      cvm_mesh_errmsg(m));
        assert_same(&ref, &r, k);
        result_free(&r);
        cvm_mesh_free(m);
        ck_assert_msg(a.live_blocks == 0 && a.live_bytes == 0,
                      "k=%ld: %ld blocks (%zu bytes) leaked", k, a.live_blocks, a.live_bytes);
    }
    ck_assert_int_gt(n_nomem, 0);
    result_free(&ref);
}

START_TEST(every_failed_allocation_gives_nomem_no_leak_and_a_reusable_handle)
{
    inject(0);
}
END_TEST

START_TEST(persistent_allocation_failure_gives_nomem_no_leak_and_a_reusable_handle)
{
    inject(1);
}
END_TEST

START_TEST(free_right_after_a_failed_triangulate_leaks_nothing)
{
    long k;
    for (k = 2; k < 400; k += 7) {
        cvmtest_alloc a;
        cvm_mesh *m = NULL;
        cvmtest_alloc_init(&a, 0, 0);
        ck_assert_int_eq(cvmtest_mesh_create(&m, &a), CVM_OK);
        ck_assert_int_eq(cvmtest_pslg_set(m, &cvmtest_square_with_hole), CVM_OK);
        cvmtest_alloc_arm(&a, k, 1);
        (void)cvm_mesh_triangulate(m);
        cvm_mesh_free(m);
        ck_assert_msg(a.live_blocks == 0, "k=%ld: %ld blocks leaked", k, a.live_blocks);
    }
}
END_TEST

TCase *api_oom_tcase(void)
{
    TCase *tc = tcase_create("oom");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, every_failed_allocation_gives_nomem_no_leak_and_a_reusable_handle);
    tcase_add_test(tc, persistent_allocation_failure_gives_nomem_no_leak_and_a_reusable_handle);
    tcase_add_test(tc, free_right_after_a_failed_triangulate_leaks_nothing);
    return tc;
}
