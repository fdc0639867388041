/* test_bad_queue.c - the bad-triangle bucket queue (lib/refine/bad_queue.c): order by (class, quantised key, push order), never by slot. */
#include <math.h>
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

/* The documented quantisation, computed here from frexp rather than from the
 * bit pattern: a non-zero key k = m 2^e (m in [0.5, 1)) falls in band
 * 16 e + floor(16 (2m - 1)); negative keys mirror positive ones, every
 * negative key before every positive one. */
static long rank_of(double k)
{
    int e;
    double m;
    long band;
    m = frexp(fabs(k), &e);
    band = 16L * e + (long)floor(16 * (2 * m - 1));
    return k < 0 ? -band - 1 - 100000L : band + 100000L;
}

START_TEST(pops_by_class_then_key_then_push_order)
{
    /* slots 0..5; rotation to the smallest id must not change the identity */
    static const int32_t tv[] = {5, 1, 9, 2, 3, 4, 7, 8, 6, 10, 11, 12, 13, 14, 15, 16, 17, 18};
    cvm__ctx ctx;
    cvm__tri2 T;
    cvm__bad_queue q;
    cvm__bad_entry e;
    cvm__ctx_init_default(&ctx);
    fake_tri(&T, &ctx, tv, 6);
    cvm__bq_init(&q, &ctx);
    ck_assert_int_eq(cvm__bq_push(&q, &T, 1, 1, 0.51), CVM_OK);
    ck_assert_int_eq(cvm__bq_push(&q, &T, 0, 1, 0.5), CVM_OK); /* same band as 0.51 */
    ck_assert_int_eq(cvm__bq_push(&q, &T, 2, 0, -3.0), CVM_OK);
    ck_assert_int_eq(cvm__bq_push(&q, &T, 3, 1, 0.1), CVM_OK);
    ck_assert_int_eq(cvm__bq_push(&q, &T, 4, 0, -1.0), CVM_OK);
    ck_assert_int_eq(cvm__bq_push(&q, &T, 5, 1, 0.5 * (1 + 1.0 / 16)), CVM_OK); /* next band */
    ck_assert_uint_eq(q.n, 6);
    ck_assert(cvm__bq_pop(&q, &e));
    ck_assert_int_eq(e.t, 2); /* class 0, largest size ratio first */
    ck_assert_int_eq(e.cls, 0);
    ck_assert(e.key == -3.0);
    ck_assert_int_eq(e.v[0], 6);
    ck_assert_int_eq(e.v[1], 7);
    ck_assert_int_eq(e.v[2], 8);
    ck_assert(cvm__bq_pop(&q, &e));
    ck_assert_int_eq(e.t, 4);
    ck_assert(cvm__bq_pop(&q, &e));
    ck_assert_int_eq(e.t, 3); /* class 1, worst shape first */
    ck_assert_int_eq(e.cls, 1);
    ck_assert(cvm__bq_pop(&q, &e));
    ck_assert_int_eq(e.t, 1); /* same band: first pushed first, whatever the exact key */
    ck_assert_int_eq(e.v[0], 2);
    ck_assert(e.key == 0.51);
    ck_assert(cvm__bq_pop(&q, &e));
    ck_assert_int_eq(e.t, 0);
    ck_assert_int_eq(e.v[0], 1); /* (5, 1, 9) rotated to (1, 9, 5) */
    ck_assert_int_eq(e.v[1], 9);
    ck_assert_int_eq(e.v[2], 5);
    ck_assert(cvm__bq_pop(&q, &e));
    ck_assert_int_eq(e.t, 5);
    ck_assert(!cvm__bq_pop(&q, &e));
    ck_assert_uint_eq(q.n, 0);
    /* empty, then reused */
    ck_assert_int_eq(cvm__bq_push(&q, &T, 3, 1, 0.2), CVM_OK);
    cvm__bq_clear(&q);
    ck_assert(!cvm__bq_pop(&q, &e));
    ck_assert_int_eq(cvm__bq_push(&q, &T, 3, 1, 0.2), CVM_OK);
    ck_assert(cvm__bq_pop(&q, &e));
    ck_assert_int_eq(e.t, 3);
    cvm__bq_destroy(&q);
    free(T.tf);
}
END_TEST

/* Pops of n random pushes (interleaved with pops when pop_every > 0) come out
 * in (class, band, push order) among the entries queued at each pop. */
static void random_order(int pop_every)
{
    enum { N = 4000 };
    int32_t *tv = malloc(3 * N * sizeof *tv);
    double *key = malloc(N * sizeof *key);
    long *rank = malloc(N * sizeof *rank);
    int32_t *cls = malloc(N * sizeof *cls);
    char *out = calloc(N, 1);
    cvm__ctx ctx;
    cvm__tri2 T;
    cvm__bad_queue q;
    cvm__bad_entry e;
    unsigned long x = 12345;
    size_t i, j, n = 0, pushed = 0, step;
    cvm__ctx_init_default(&ctx);
    for (i = 0; i < 3 * N; i++)
        tv[i] = (int32_t)i;
    fake_tri(&T, &ctx, tv, N);
    cvm__bq_init(&q, &ctx);
    for (step = 0; n < N; step++) {
        if (pushed < N && (pop_every == 0 || q.n == 0 || step % (size_t)pop_every)) {
            double mag;
            x = x * 6364136223846793005ul + 1442695040888963407ul;
            cls[pushed] = (int32_t)(x >> 62) & 1;
            mag = ldexp(1 + (double)((x >> 20) % 1000) / 1000, (int)((x >> 40) % 41) - 20);
            key[pushed] = (x >> 61) & 1 ? -mag : mag;
            rank[pushed] = rank_of(key[pushed]);
            if (cvm__bq_push(&q, &T, (int32_t)pushed, cls[pushed], key[pushed]) != CVM_OK)
                ck_abort_msg("push failed");
            pushed++;
            continue;
        }
        if (!cvm__bq_pop(&q, &e) || !cvm__bq_valid(&T, &e) || e.cls != cls[e.t] ||
            !(e.key == key[e.t]) || out[e.t])
            ck_abort_msg("pop %lu: wrong entry", (unsigned long)n);
        /* no entry still queued may come before the one popped */
        for (j = 0; j < pushed; j++) {
            if (out[j] || j == (size_t)e.t)
                continue;
            if (!(cls[j] > e.cls ||
                  (cls[j] == e.cls &&
                   (rank[j] > rank[e.t] || (rank[j] == rank[e.t] && j > (size_t)e.t)))))
                ck_abort_msg("entry %lu (class %d key %g) left after entry %ld (class %d key %g)",
                             (unsigned long)j, cls[j], key[j], (long)e.t, e.cls, e.key);
        }
        out[e.t] = 1;
        n++;
    }
    ck_assert(!cvm__bq_pop(&q, &e));
    cvm__bq_destroy(&q);
    free(T.tf);
    free(tv);
    free(key);
    free(rank);
    free(cls);
    free(out);
}

START_TEST(many_entries_come_out_in_documented_order)
{
    random_order(0);
}
END_TEST

START_TEST(interleaved_pushes_and_pops_keep_the_order)
{
    random_order(3);
}
END_TEST

START_TEST(negative_positive_and_zero_keys_are_ordered)
{
    static const double keys[] = {0.25, 0.0, -1e300, 1e-300, -0.0, -2.0, 3.0, -1e-300};
    static const int order[] = {2, 5, 7, 1, 4, 3, 0, 6}; /* ascending; 0 and -0 in push order */
    int32_t tv[3 * 8];
    cvm__ctx ctx;
    cvm__tri2 T;
    cvm__bad_queue q;
    cvm__bad_entry e;
    int i;
    cvm__ctx_init_default(&ctx);
    for (i = 0; i < 3 * 8; i++)
        tv[i] = i;
    fake_tri(&T, &ctx, tv, 8);
    cvm__bq_init(&q, &ctx);
    for (i = 0; i < 8; i++)
        ck_assert_int_eq(cvm__bq_push(&q, &T, i, 0, keys[i]), CVM_OK);
    for (i = 0; i < 8; i++) {
        ck_assert(cvm__bq_pop(&q, &e));
        ck_assert_int_eq(e.t, order[i]);
    }
    cvm__bq_destroy(&q);
    free(T.tf);
}
END_TEST

/* Entries of triangles that died or whose slot now holds other vertices are
 * reported stale; when most of a large queue is stale the pool drops them
 * and the live entries still leave in the documented order. */
START_TEST(stale_entries_are_skipped_and_dropped)
{
    enum { N = 6000 };
    int32_t *tv = malloc(3 * N * sizeof *tv);
    cvm__ctx ctx;
    cvm__tri2 T;
    cvm__bad_queue q;
    cvm__bad_entry e;
    int32_t *seq = malloc(N * sizeof *seq);
    size_t i, live = 0;
    int pass;
    cvm__ctx_init_default(&ctx);
    for (i = 0; i < 3 * N; i++)
        tv[i] = (int32_t)i;
    fake_tri(&T, &ctx, tv, N);
    cvm__bq_init(&q, &ctx);
    /* slot 1 changes its vertices after the push, slot 2 dies */
    ck_assert_int_eq(cvm__bq_push(&q, &T, 1, 1, 0.1), CVM_OK);
    ck_assert_int_eq(cvm__bq_push(&q, &T, 2, 1, 0.1), CVM_OK);
    tv[3] = 100000;
    T.tf[2] = CVM__TF_DEAD;
    ck_assert(cvm__bq_pop(&q, &e));
    ck_assert_int_eq(e.t, 1);
    ck_assert(!cvm__bq_valid(&T, &e));
    ck_assert(cvm__bq_pop(&q, &e));
    ck_assert_int_eq(e.t, 2);
    ck_assert(!cvm__bq_valid(&T, &e));
    tv[3] = 3;
    T.tf[2] = 0;
    /* every slot but each tenth is dead, as after the cavities that killed
     * the triangles pushed before them */
    for (i = 0; i < N; i++) {
        if (i % 10) {
            T.tf[i] = CVM__TF_DEAD;
            T.n_dead++;
        } else {
            live++;
        }
    }
    /* pass 0 pops and checks, pass 1 pops valid entries only: same sequence */
    for (pass = 0; pass < 2; pass++) {
        size_t popped = 0, stale = 0;
        long last_rank = -1;
        int32_t last_t = -1;
        cvm__bq_clear(&q);
        for (i = 0; i < N; i++)
            ck_assert_int_eq(cvm__bq_push(&q, &T, (int32_t)i, 1, (double)(1 + i % 7)), CVM_OK);
        ck_assert_uint_lt(q.cap * CVM__BQ_BLOCK, N); /* stale entries were dropped on the way */
        while (pass ? cvm__bq_pop_valid(&q, &T, NULL, &e) : cvm__bq_pop(&q, &e)) {
            long r = rank_of(e.key);
            if (!cvm__bq_valid(&T, &e)) {
                ck_assert_int_eq(pass, 0);
                stale++;
                continue;
            }
            ck_assert_msg(r > last_rank || (r == last_rank && e.t > last_t),
                          "entry %ld (band %ld) left after entry %ld (band %ld)", (long)e.t, r,
                          (long)last_t, last_rank);
            last_rank = r;
            last_t = e.t;
            if (pass)
                ck_assert_int_eq(e.t, seq[popped]);
            else
                seq[popped] = e.t;
            popped++;
        }
        ck_assert_uint_eq(popped, live);
        ck_assert_uint_lt(stale, N - live);
        ck_assert_uint_eq(q.n, 0);
    }
    free(seq);
    cvm__bq_destroy(&q);
    free(T.tf);
    free(tv);
}
END_TEST

TCase *refine_bad_queue_tcase(void)
{
    TCase *tc = tcase_create("bad_queue");
    tcase_add_test(tc, pops_by_class_then_key_then_push_order);
    tcase_add_test(tc, many_entries_come_out_in_documented_order);
    tcase_add_test(tc, interleaved_pushes_and_pops_keep_the_order);
    tcase_add_test(tc, negative_positive_and_zero_keys_are_ordered);
    tcase_add_test(tc, stale_entries_are_skipped_and_dropped);
    return tc;
}
