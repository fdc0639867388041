/* test_bad_queue.c - the bad-triangle heap (lib/refine/bad_queue.c): order by (class, key, vertex ids), never by slot. */
#include <stdlib.h>

#include "refine/refine_tests.h"
#include "refine/refine_internal.h"

/* A fake triangulation holding n triangles with the given vertex ids. */
static void fake_tri(cvm__tri2 *T, cvm__ctx *ctx, const int32_t *tv, size_t n)
{
    cvm__tri2_init(T, ctx);
    T->tv = (int32_t *)tv;
    T->tf = calloc(n, 1);
    T->nt = n;
}

START_TEST(pops_by_class_then_key_then_vertex_ids)
{
    /* slots 0..4; rotation to the smallest id must not change the identity */
    static const int32_t tv[] = {5, 1, 9, 2, 3, 4, 7, 8, 6, 10, 11, 12, 13, 14, 15};
    cvm__ctx ctx;
    cvm__tri2 T;
    cvm__bad_queue q;
    cvm__bad_entry e;
    cvm__ctx_init_default(&ctx);
    fake_tri(&T, &ctx, tv, 5);
    cvm__bq_init(&q, &ctx);
    ck_assert_int_eq(cvm__bq_push(&q, &T, 0, 1, 0.5), CVM_OK);
    ck_assert_int_eq(cvm__bq_push(&q, &T, 1, 1, 0.5), CVM_OK);
    ck_assert_int_eq(cvm__bq_push(&q, &T, 2, 0, -3.0), CVM_OK);
    ck_assert_int_eq(cvm__bq_push(&q, &T, 3, 1, 0.1), CVM_OK);
    ck_assert_int_eq(cvm__bq_push(&q, &T, 4, 0, -1.0), CVM_OK);
    ck_assert(cvm__bq_pop(&q, &e));
    ck_assert_int_eq(e.t, 2); /* class 0, largest size ratio first */
    ck_assert_int_eq(e.v[0], 6);
    ck_assert_int_eq(e.v[1], 7);
    ck_assert_int_eq(e.v[2], 8);
    ck_assert(cvm__bq_pop(&q, &e));
    ck_assert_int_eq(e.t, 4);
    ck_assert(cvm__bq_pop(&q, &e));
    ck_assert_int_eq(e.t, 3); /* class 1, worst shape first */
    ck_assert(cvm__bq_pop(&q, &e));
    ck_assert_int_eq(e.t, 0); /* equal keys: (1, 9, 5) before (2, 3, 4) */
    ck_assert_int_eq(e.v[0], 1);
    ck_assert(cvm__bq_pop(&q, &e));
    ck_assert_int_eq(e.t, 1);
    ck_assert(!cvm__bq_pop(&q, &e));
    cvm__bq_destroy(&q);
    free(T.tf);
}
END_TEST

START_TEST(many_entries_come_out_sorted)
{
    enum { N = 2000 };
    int32_t *tv = malloc(3 * N * sizeof *tv);
    cvm__ctx ctx;
    cvm__tri2 T;
    cvm__bad_queue q;
    cvm__bad_entry e, prev;
    unsigned long x = 12345;
    size_t i, n = 0;
    cvm__ctx_init_default(&ctx);
    for (i = 0; i < 3 * N; i++)
        tv[i] = (int32_t)i;
    fake_tri(&T, &ctx, tv, N);
    cvm__bq_init(&q, &ctx);
    for (i = 0; i < N; i++) {
        x = x * 6364136223846793005ul + 1442695040888963407ul;
        ck_assert_int_eq(cvm__bq_push(&q, &T, (int32_t)i, (int32_t)(x >> 62) & 1,
                                      (double)((x >> 33) % 50)),
                         CVM_OK);
    }
    while (cvm__bq_pop(&q, &e)) {
        if (n++)
            ck_assert(prev.cls < e.cls || (prev.cls == e.cls && (prev.key < e.key ||
                      (prev.key == e.key && prev.v[0] < e.v[0]))));
        prev = e;
    }
    ck_assert_uint_eq(n, N);
    cvm__bq_destroy(&q);
    free(T.tf);
    free(tv);
}
END_TEST

TCase *refine_bad_queue_tcase(void)
{
    TCase *tc = tcase_create("bad_queue");
    tcase_add_test(tc, pops_by_class_then_key_then_vertex_ids);
    tcase_add_test(tc, many_entries_come_out_sorted);
    return tc;
}
