/* test_par3.c - parallel insertion, Delaunay and regular: 1, 2, 3 and 4 threads give the same bytes, the same point fates and a valid store. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay3/delaunay3_tests.h"
#include "support/failing_alloc.h"

/* What a build hands out, to compare across thread counts. */
typedef struct par3_out {
    int32_t *tets;
    size_t nt;
    uint8_t *fate;
    int32_t *into;
    size_t n_dup;
    int64_t dup_first[2];
    size_t n_red;
    int64_t red_first;
    size_t n_par; /* points settled by parallel passes */
} par3_out;

static par3_out build_w(const double *xyz, const double *w, size_t n, int threads, size_t par_min,
                        uint64_t seed, int check)
{
    par3_out o;
    cvm__ctx ctx;
    cvm__tet3 T;
    cvm_status s;
    cvm__ctx_init_default(&ctx);
    cvm__tet3_init(&T, &ctx);
    T.threads = threads;
    T.par_min = par_min;
    s = cvm__tet3_build(&T, xyz, w, n, seed);
    ck_assert_msg(s == CVM_OK, "%d threads: status %d: %s", threads, (int)s, ctx.errmsg);
    s = check ? cvm__tet3_check(&T) : CVM_OK;
    ck_assert_msg(s == CVM_OK, "%d threads: check: %s", threads, ctx.errmsg);
    o.nt = T.n_finite;
    o.tets = malloc(4 * (o.nt + 1) * sizeof *o.tets);
    o.fate = malloc(n);
    o.into = malloc(n * sizeof *o.into);
    ck_assert(o.tets && o.fate && o.into);
    ck_assert_int_eq(cvm__tet3_copy_tets(&T, o.tets), CVM_OK);
    cvm__tet3_point_fates(&T, o.fate, o.into);
    o.n_dup = T.n_dup;
    o.dup_first[0] = T.dup_first[0], o.dup_first[1] = T.dup_first[1];
    o.n_red = T.n_redundant, o.red_first = T.redundant_first;
    o.n_par = T.n_par_done;
    cvm__tet3_free(&T);
    return o;
}

static par3_out build_with(const double *xyz, size_t n, int threads, size_t par_min, uint64_t seed,
                           int check)
{
    return build_w(xyz, NULL, n, threads, par_min, seed, check);
}

static void out_free(par3_out *o)
{
    free(o->tets);
    free(o->fate);
    free(o->into);
}

/* Threads 1 (the serial path), 2, 4 and, when odd, 3 (parallel rounds from
 * par_min points) give byte-identical tetrahedra, identical fates and
 * duplicate reports, and a store that passes cvm__tet3_check(). */
static void same_for_every_thread_count_w(const double *xyz, const double *w, size_t n,
                                          size_t par_min, int odd)
{
    static const int counts[] = { 2, 4, 3 };
    par3_out ref = build_w(xyz, w, n, 1, par_min, 5, 1);
    int i;
    ck_assert_uint_eq(ref.n_par, 0);
    for (i = 0; i < (odd ? 3 : 2); i++) {
        int k = counts[i];
        par3_out o = build_w(xyz, w, n, k, par_min, 5, 1);
        /* the parallel passes ran (most points go through them; merged duplicates do not) */
        ck_assert_msg(o.n_par > n / 3, "%d threads: %zu of %zu points in parallel", k, o.n_par, n);
        ck_assert_msg(o.nt == ref.nt, "%d threads: %zu tetrahedra, 1 thread %zu", k, o.nt, ref.nt);
        ck_assert_msg(memcmp(o.tets, ref.tets, 4 * o.nt * sizeof *o.tets) == 0,
                      "%d threads: other tetrahedra", k);
        ck_assert(memcmp(o.fate, ref.fate, n) == 0);
        ck_assert(memcmp(o.into, ref.into, n * sizeof *o.into) == 0);
        ck_assert_uint_eq(o.n_dup, ref.n_dup);
        ck_assert(o.dup_first[0] == ref.dup_first[0] && o.dup_first[1] == ref.dup_first[1]);
        ck_assert_uint_eq(o.n_red, ref.n_red);
        ck_assert(o.red_first == ref.red_first);
        out_free(&o);
    }
    out_free(&ref);
}

static void same_for_every_thread_count(const double *xyz, size_t n, size_t par_min, int odd)
{
    same_for_every_thread_count_w(xyz, NULL, n, par_min, odd);
}

START_TEST(par_uniform_same_bytes_for_1_2_4_threads)
{
    const size_t n = 200000;
    double *xyz = malloc(3 * n * sizeof *xyz);
    par3_out a, b, c;
    ck_assert_ptr_nonnull(xyz);
    d3test_random(xyz, n, 71);
    a = build_with(xyz, n, 1, CVM__T3_PAR_MIN, 5, 0); /* (the serial path has its own tests) */
    b = build_with(xyz, n, 2, CVM__T3_PAR_MIN, 5, 1);
    c = build_with(xyz, n, 4, CVM__T3_PAR_MIN, 5, 1);
    ck_assert(a.nt == b.nt && a.nt == c.nt);
    ck_assert(memcmp(a.tets, b.tets, 4 * a.nt * sizeof *a.tets) == 0);
    ck_assert(memcmp(a.tets, c.tets, 4 * a.nt * sizeof *a.tets) == 0);
    out_free(&a);
    out_free(&b);
    out_free(&c);
    free(xyz);
}
END_TEST

START_TEST(par_small_rounds_many_passes)
{
    const size_t n = 10000;
    double *xyz = malloc(3 * n * sizeof *xyz);
    ck_assert_ptr_nonnull(xyz);
    d3test_random(xyz, n, 72);
    same_for_every_thread_count(xyz, n, 256, 1);
    free(xyz);
}
END_TEST

START_TEST(par_bcc_exact_and_perturbed)
{
    double *xyz = malloc(3 * 22 * 22 * 22 * 2 * sizeof *xyz), *jit;
    size_t n, i;
    ck_assert_ptr_nonnull(xyz);
    n = d3test_bcc(xyz, 22);
    same_for_every_thread_count(xyz, n, 2048, 0); /* every point co-spherical with 7 others */
    jit = malloc(3 * n * sizeof *jit);
    ck_assert_ptr_nonnull(jit);
    d3test_random(jit, n, 73);
    for (i = 0; i < 3 * n; i++)
        xyz[i] += 1e-9 * (jit[i] - 0.5);
    same_for_every_thread_count(xyz, n, 2048, 0);
    free(jit);
    free(xyz);
}
END_TEST

START_TEST(par_duplicates_merge_into_the_lowest_index)
{
    const size_t base = 10000, n = 15000;
    double *xyz = malloc(3 * n * sizeof *xyz);
    uint64_t s = 99;
    size_t i;
    ck_assert_ptr_nonnull(xyz);
    d3test_random(xyz, n, 74);
    /* points base.. copy random earlier ones, and each copy then swaps places with a
     * random point, so a group's lowest index is anywhere in the input */
    for (i = base; i < n; i++) {
        size_t j, k;
        double t[3];
        s = s * 6364136223846793005u + 1442695040888963407u;
        j = (size_t)(s >> 33) % i;
        memcpy(xyz + 3 * i, xyz + 3 * j, sizeof t);
        s = s * 6364136223846793005u + 1442695040888963407u;
        k = (size_t)(s >> 33) % (i + 1);
        memcpy(t, xyz + 3 * k, sizeof t);
        memcpy(xyz + 3 * k, xyz + 3 * i, sizeof t);
        memcpy(xyz + 3 * i, t, sizeof t);
    }
    xyz[3 * 17] = -0.0, xyz[3 * 17 + 1] = 0.5, xyz[3 * 17 + 2] = 0.5; /* -0 duplicates +0 */
    xyz[3 * 18] = 0.0, xyz[3 * 18 + 1] = 0.5, xyz[3 * 18 + 2] = 0.5;
    same_for_every_thread_count(xyz, n, 1024, 1);
    free(xyz);
}
END_TEST

/* Out of memory at every allocation, transient then persistent, of a 2-thread build
 * of the n points xyz (weights w, or NULL) with parallel rounds, and of its output;
 * with weights the parallel passes and the hidden points are also asserted. */
static void par_oom_sweep(const double *xyz, const double *w, size_t n)
{
    long at;
    int persistent;
    for (persistent = 0; persistent < 2; persistent++)
        for (at = 1;; at++) {
            cvmtest_alloc a;
            cvm__ctx ctx;
            cvm__tet3 T;
            cvm_status s;
            long failed;
            cvmtest_alloc_init(&a, at, persistent);
            cvm__ctx_init_default(&ctx);
            ctx.alloc_fn = cvmtest_malloc, ctx.realloc_fn = cvmtest_realloc;
            ctx.free_fn = cvmtest_free, ctx.payload = &a;
            cvm__tet3_init(&T, &ctx);
            T.threads = 2;
            T.par_min = 128;
            s = cvm__tet3_build(&T, xyz, w, n, 3);
            ck_assert_msg(s == CVM_OK || s == CVM_E_NOMEM, "fail at %ld: status %d", at, (int)s);
            if (s == CVM_OK) { /* the parallel output too (8 par_min slots and more) */
                int32_t *tets = malloc(4 * T.n_finite * sizeof *tets + 16);
                ck_assert_ptr_nonnull(tets);
                if (w) {
                    ck_assert_uint_gt(T.n_par_done, 0);
                    ck_assert_uint_gt(T.n_redundant, 0);
                }
                s = cvm__tet3_copy_tets(&T, tets);
                ck_assert(s == CVM_OK || s == CVM_E_NOMEM);
                free(tets);
            }
            failed = a.n_failed;
            cvmtest_alloc_arm(&a, 0, 0); /* the store is reusable once memory is back */
            if (s == CVM_E_NOMEM)
                ck_assert_int_eq(cvm__tet3_build(&T, xyz, w, n, 3), CVM_OK);
            ck_assert_int_eq(cvm__tet3_check(&T), CVM_OK);
            cvm__tet3_free(&T);
            ck_assert_int_eq(a.live_blocks, 0);
            if (failed == 0) {
                ck_assert(s == CVM_OK);
                break;
            }
        }
}

/* Out of memory at every allocation of a 2-thread build with parallel rounds
 * and of its parallel output. */
START_TEST(par_oom_at_every_allocation)
{
    double xyz[3 * 800];
    d3test_random(xyz, 800, 75);
    par_oom_sweep(xyz, NULL, 800);
}
END_TEST

/* Weights of the order of the squared spacing, one point in five ten times
 * larger: about 1.4% of the points hide or vanish. */
static double *spacing_weights(size_t n, uint64_t seed)
{
    double *w = malloc(n * sizeof *w + 1), *r = malloc(3 * (n / 3 + 1) * sizeof *r),
           h2 = pow((double)n, -2.0 / 3.0);
    size_t i;
    ck_assert(w && r);
    d3test_random(r, n / 3 + 1, seed); /* (3 numbers per call's point) */
    for (i = 0; i < n; i++)
        w[i] = h2 * (r[i] - 0.3) * ((i % 5) ? 0.1 : 1.0);
    free(r);
    return w;
}

START_TEST(par_weighted_random_same_bytes_for_1_2_4_threads)
{
    const size_t n = 100000;
    double *xyz = malloc(3 * n * sizeof *xyz), *w = spacing_weights(n, 81);
    ck_assert_ptr_nonnull(xyz);
    d3test_random(xyz, n, 80);
    same_for_every_thread_count_w(xyz, w, n, CVM__T3_PAR_MIN, 0);
    free(w);
    free(xyz);
}
END_TEST

/* The BCC lattice with equal weights (every power test among neighbours an
 * exact tie) is its Delaunay tetrahedralisation, byte for byte; with weights
 * in {0, 0.5, 1} and every 7th point at -3 (its cell, if any, is decided by
 * exact ties: 3 is its squared distance to the nearest lattice points) and
 * every 11th at -4, points hide and vanish; both are the same for 1, 2 and 4 threads. */
START_TEST(par_weighted_bcc_ties)
{
    double *xyz = malloc(3 * 22 * 22 * 22 * 2 * sizeof *xyz), *w;
    size_t n, i;
    par3_out plain, eq;
    ck_assert_ptr_nonnull(xyz);
    n = d3test_bcc(xyz, 22);
    w = malloc(n * sizeof *w);
    ck_assert_ptr_nonnull(w);
    for (i = 0; i < n; i++)
        w[i] = 1.0;
    same_for_every_thread_count_w(xyz, w, n, 2048, 0);
    plain = build_with(xyz, n, 2, 2048, 5, 0);
    eq = build_w(xyz, w, n, 2, 2048, 5, 0);
    ck_assert_uint_eq(eq.nt, plain.nt);
    ck_assert(memcmp(eq.tets, plain.tets, 4 * eq.nt * sizeof *eq.tets) == 0);
    ck_assert_uint_eq(eq.n_red, 0);
    out_free(&plain);
    out_free(&eq);
    for (i = 0; i < n; i++) {
        const double *p = xyz + 3 * i;
        w[i] = 0.5 * (double)(((int)p[0] + 2 * (int)p[1] + 3 * (int)p[2]) % 3);
        if (i % 7 == 3)
            w[i] = -3.0;
        if (i % 11 == 5)
            w[i] = -4.0;
    }
    eq = build_w(xyz, w, n, 1, 2048, 5, 0);
    ck_assert_uint_gt(eq.n_red, 0);
    out_free(&eq);
    same_for_every_thread_count_w(xyz, w, n, 2048, 0);
    free(w);
    free(xyz);
}
END_TEST

/* Hidden points of every kind, with small rounds (many passes, 3 threads
 * too): points swallowed by a heavy neighbour, copies of a point with the
 * same weight (duplicates, of vertices and of hidden points), with a lower
 * weight (hidden under it) and with a higher one (the original vanishes).
 * The fates are the same for every thread count, every point is either a
 * vertex of some tetrahedron or reported (redundant or duplicate), and a
 * redundant one is in no tetrahedron. */
START_TEST(par_weighted_hidden_points_are_reported)
{
    const size_t base = 20000, n = 24000;
    double *xyz = malloc(3 * n * sizeof *xyz), *w = spacing_weights(n, 91);
    uint8_t *seen = calloc(n, 1);
    par3_out o;
    size_t i, nred = 0, ndup = 0;
    uint64_t s = 17;
    ck_assert(xyz && seen);
    d3test_random(xyz, n, 90);
    for (i = 0; i < base; i += 50) /* heavy points swallow their neighbours */
        w[i] = 4.0 * pow((double)n, -2.0 / 3.0);
    for (i = base; i < n; i++) {
        size_t j;
        s = s * 6364136223846793005u + 1442695040888963407u;
        j = i % 4 == 3 ? i - 2 : (size_t)(s >> 33) % base;
        memcpy(xyz + 3 * i, xyz + 3 * j, 3 * sizeof *xyz);
        switch (i % 4) {
        case 1: w[i] = w[j] - 1e-4; break; /* hidden under j */
        case 2: w[i] = w[j] + 1e-5; break; /* j vanishes */
        default: w[i] = w[j]; break;       /* a duplicate (3: of a hidden point) */
        }
        if (i % 8 == 3) { /* the copy listed first, so the group's lowest index moves */
            double t[3], tw;
            memcpy(t, xyz + 3 * i, sizeof t), tw = w[i];
            memcpy(xyz + 3 * i, xyz + 3 * (i - base), sizeof t), w[i] = w[i - base];
            memcpy(xyz + 3 * (i - base), t, sizeof t), w[i - base] = tw;
        }
    }
    same_for_every_thread_count_w(xyz, w, n, 512, 1);
    o = build_w(xyz, w, n, 2, 512, 5, 1);
    for (i = 0; i < 4 * o.nt; i++)
        seen[o.tets[i]] = 1;
    for (i = 0; i < n; i++) {
        ck_assert_msg(seen[i] == (o.fate[i] == CVM__T3_VERTEX), "point %zu: fate %d, %s", i,
                      (int)o.fate[i], seen[i] ? "in a tetrahedron" : "in none");
        nred += o.fate[i] == CVM__T3_REDUNDANT;
        ndup += o.fate[i] == CVM__T3_DUPLICATE;
        if (o.fate[i] == CVM__T3_DUPLICATE)
            ck_assert_int_eq(o.fate[o.into[i]], CVM__T3_VERTEX);
    }
    ck_assert_uint_eq(nred, o.n_red);
    ck_assert_uint_eq(ndup, o.n_dup);
    ck_assert_uint_gt(nred, 1000);
    ck_assert_uint_gt(ndup, 500);
    out_free(&o);
    free(seen);
    free(w);
    free(xyz);
}
END_TEST

/* Out of memory at every allocation of a weighted 2-thread build with
 * parallel rounds, hidden points and duplicates, and of its output. */
START_TEST(par_weighted_oom_at_every_allocation)
{
    const size_t n = 800;
    double xyz[3 * 800], w[800], r[3 * 267];
    size_t i;
    d3test_random(xyz, n, 76);
    d3test_random(r, 267, 77);
    for (i = 0; i < n; i++)
        w[i] = 0.01 * (r[i] - 0.3) * ((i % 5) ? 0.1 : 1.0);
    for (i = 700; i + 1 < n; i += 3) { /* a duplicate and a hidden twin */
        memcpy(xyz + 3 * i, xyz + 3 * (i - 700), 3 * sizeof *xyz), w[i] = w[i - 700];
        memcpy(xyz + 3 * i + 3, xyz + 3 * (i - 699), 3 * sizeof *xyz), w[i + 1] = w[i - 699] - 1.0;
    }
    par_oom_sweep(xyz, w, n);
}
END_TEST

TCase *delaunay3_par_tcase(void)
{
    TCase *tc = tcase_create("par3");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, par_uniform_same_bytes_for_1_2_4_threads);
    tcase_add_test(tc, par_small_rounds_many_passes);
    tcase_add_test(tc, par_bcc_exact_and_perturbed);
    tcase_add_test(tc, par_duplicates_merge_into_the_lowest_index);
    tcase_add_test(tc, par_oom_at_every_allocation);
    tcase_add_test(tc, par_weighted_random_same_bytes_for_1_2_4_threads);
    tcase_add_test(tc, par_weighted_bcc_ties);
    tcase_add_test(tc, par_weighted_hidden_points_are_reported);
    tcase_add_test(tc, par_weighted_oom_at_every_allocation);
    return tc;
}
