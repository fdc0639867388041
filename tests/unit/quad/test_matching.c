/* test_matching.c - lib/quad/matching*.c: optimal against brute force and networkx, certified by
 * its duals on large triangulation graphs, nested blossoms, degenerate graphs, bad input, OOM. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "quad/quad_tests.h"

/* Exhaustive optimum of a small graph: best weight, and best (cardinality, weight). */
typedef struct brute { int64_t w, card_w; size_t card; } brute;

static void brute_rec(const qtest_graph *g, size_t e, unsigned char *used, int64_t w, size_t c,
                      brute *b)
{
    cvm_index x, y;
    if (e == g->m) {
        if (w > b->w)
            b->w = w;
        if (c > b->card || (c == b->card && w > b->card_w)) {
            b->card = c;
            b->card_w = w;
        }
        return;
    }
    brute_rec(g, e + 1, used, w, c, b);
    x = g->ends[2 * e];
    y = g->ends[2 * e + 1];
    if (!used[x] && !used[y]) {
        used[x] = used[y] = 1;
        brute_rec(g, e + 1, used, w + g->w[e], c + 1, b);
        used[x] = used[y] = 0;
    }
}

/* Small multigraph number k: up to 10 vertices, 16 edges, parallel edges allowed. */
static void small_graph(qtest_graph *g, uint64_t k)
{
    uint64_t s = k * 2654435761u + 1;
    size_t i;
    s ^= s >> 13;
    g->n = 2 + (size_t)(k % 9);
    g->m = (size_t)((k / 9) % 17);
    g->ends = malloc((2 * g->m + 1) * sizeof *g->ends);
    g->w = malloc((g->m + 1) * sizeof *g->w);
    ck_assert(g->ends && g->w);
    for (i = 0; i < g->m; i++) {
        cvm_index a, b;
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        a = (cvm_index)((s >> 33) % g->n);
        b = (cvm_index)((s >> 45) % (g->n - 1));
        g->ends[2 * i] = a;
        g->ends[2 * i + 1] = b >= a ? b + 1 : b;
        g->w[i] = (int64_t)((s >> 20) % (k % 3 == 0 ? 4 : 50));
    }
}

/* Solve g in mode with a certificate; returns weight and cardinality; tracks nesting. */
static int64_t solve_certified(const qtest_graph *g, cvm__match_mode mode, size_t *card,
                               int *depth)
{
    cvm__ctx ctx;
    cvm__match_duals d;
    cvm_index *mate = malloc((g->n + 1) * sizeof *mate);
    int64_t w;
    int dep;
    ck_assert_ptr_nonnull(mate);
    cvm__ctx_init_default(&ctx);
    ck_assert_int_eq(cvm__matching_solve(mate, &d, &ctx, g->n, g->m, g->ends, g->w, mode),
                     CVM_OK);
    qtest_assert_matching(g, mate, &w, card);
    dep = qtest_assert_certificate(g, mate, &d);
    if (depth && dep > *depth)
        *depth = dep;
    cvm__match_duals_free(&ctx, &d);
    free(mate);
    return w;
}

START_TEST(matching_equals_brute_force_on_small_multigraphs)
{
    uint64_t k;
    int depth = 0;
    for (k = 0; k < 1500; k++) {
        qtest_graph g;
        brute b = {-1, -1, 0};
        unsigned char used[16] = {0};
        size_t card;
        small_graph(&g, k);
        brute_rec(&g, 0, used, 0, 0, &b);
        ck_assert_int_eq(solve_certified(&g, CVM__MATCH_MAX_WEIGHT, &card, &depth), b.w);
        ck_assert_int_eq(solve_certified(&g, CVM__MATCH_MAX_CARDINALITY, &card, &depth),
                         b.card_w);
        ck_assert_uint_eq(card, b.card);
        qtest_graph_free(&g);
    }
    ck_assert_int_ge(depth, 1); /* blossoms were met */
}
END_TEST

static FILE *open_oracle(void)
{
    const char *dir = getenv("CVM_TEST_DATA");
    char path[1024];
    FILE *f;
    snprintf(path, sizeof path, "%s/matching_networkx.txt", dir && *dir ? dir : "tests/data");
    f = fopen(path, "r");
    ck_assert_msg(f != NULL, "cannot open %s", path);
    return f;
}

START_TEST(matching_equals_networkx_on_200_random_graphs)
{
    FILE *f = open_oracle();
    char line[256];
    int ngraph = 0, depth = 0;
    while (fgets(line, sizeof line, f)) {
        long long k, n, m, w0, c1, w1;
        qtest_graph g;
        size_t card;
        if (line[0] == '#')
            continue;
        ck_assert_int_eq(sscanf(line, "%lld %lld %lld %lld %lld %lld", &k, &n, &m, &w0, &c1, &w1),
                         6);
        qtest_random_graph(&g, (uint64_t)k);
        ck_assert_uint_eq(g.n, (size_t)n);
        ck_assert_uint_eq(g.m, (size_t)m);
        ck_assert_int_eq(solve_certified(&g, CVM__MATCH_MAX_WEIGHT, &card, &depth), w0);
        ck_assert_int_eq(solve_certified(&g, CVM__MATCH_MAX_CARDINALITY, &card, &depth), w1);
        ck_assert_uint_eq(card, (size_t)c1);
        qtest_graph_free(&g);
        ngraph++;
    }
    fclose(f);
    ck_assert_int_eq(ngraph, 200);
    ck_assert_int_ge(depth, 2); /* nested blossoms were met */
}
END_TEST

START_TEST(matching_certified_on_triangulation_dual_graphs)
{
    static const int64_t wmax[3] = {3, 1000, 1000000};
    int i, depth = 0;
    for (i = 0; i < 3; i++) {
        qtest_graph g;
        size_t card, card_mc;
        int64_t wt, wt_mc;
        qtest_delaunay_dual(&g, 3000, (uint64_t)(11 + i), wmax[i]);
        wt = solve_certified(&g, CVM__MATCH_MAX_WEIGHT, &card, &depth);
        wt_mc = solve_certified(&g, CVM__MATCH_MAX_CARDINALITY, &card_mc, &depth);
        ck_assert_int_ge(wt, wt_mc);
        ck_assert_uint_ge(card_mc, card);
        qtest_graph_free(&g);
    }
    ck_assert_int_ge(depth, 1);
}
END_TEST

START_TEST(matching_certified_on_dense_random_graphs)
{
    int k, depth = 0;
    for (k = 0; k < 12; k++) {
        qtest_graph g;
        size_t n = 60 + 20 * (size_t)k, i, j, cap = n * (n - 1) / 2 + 1, card;
        uint64_t s = 977u * (uint64_t)k + 5u;
        g.n = n;
        g.m = 0;
        g.ends = malloc(2 * cap * sizeof *g.ends);
        g.w = malloc(cap * sizeof *g.w);
        ck_assert(g.ends && g.w);
        for (i = 0; i < n; i++)
            for (j = i + 1; j < n; j++) {
                s = s * 6364136223846793005ull + 1442695040888963407ull;
                if ((s >> 33) % 100 < (uint64_t)(3 + 4 * (k % 4))) {
                    g.ends[2 * g.m] = (cvm_index)i;
                    g.ends[2 * g.m + 1] = (cvm_index)j;
                    g.w[g.m++] = (int64_t)((s >> 12) % (k % 2 ? 7 : 100000));
                }
            }
        solve_certified(&g, CVM__MATCH_MAX_WEIGHT, &card, &depth);
        solve_certified(&g, CVM__MATCH_MAX_CARDINALITY, &card, &depth);
        qtest_graph_free(&g);
    }
    ck_assert_int_ge(depth, 2);
}
END_TEST

START_TEST(matching_nested_blossom_of_two_triangles_in_a_pentagon)
{
    /* A triangle 0-1-2 inside the odd cycle it forms with 3, 4: the light spokes make
     * the triangle a blossom first, then the pentagon 0,3,4 + blossom nests it;
     * 5 hangs on 4 so that the whole structure must be expanded to reach the optimum. */
    static const cvm_index ends[] = {0, 1, 1, 2, 2, 0, 0, 3, 3, 4, 4, 1, 4, 5, 5, 6};
    static const int64_t w[] = {10, 10, 10, 9, 9, 9, 7, 12};
    qtest_graph g = {7, 8, (cvm_index *)ends, (int64_t *)w};
    brute b = {-1, -1, 0};
    unsigned char used[8] = {0};
    size_t card;
    brute_rec(&g, 0, used, 0, 0, &b);
    ck_assert_int_eq(solve_certified(&g, CVM__MATCH_MAX_WEIGHT, &card, NULL), b.w);
    ck_assert_int_eq(solve_certified(&g, CVM__MATCH_MAX_CARDINALITY, &card, NULL), b.card_w);
}
END_TEST

START_TEST(matching_of_empty_graph_and_isolated_vertices)
{
    cvm__ctx ctx;
    cvm_index mate[5] = {7, 7, 7, 7, 7};
    cvm__match_duals d;
    int v;
    cvm__ctx_init_default(&ctx);
    ck_assert_int_eq(cvm__matching_solve(NULL, NULL, &ctx, 0, 0, NULL, NULL,
                                         CVM__MATCH_MAX_WEIGHT), CVM_OK);
    ck_assert_int_eq(cvm__matching_solve(mate, &d, &ctx, 5, 0, NULL, NULL,
                                         CVM__MATCH_MAX_CARDINALITY), CVM_OK);
    for (v = 0; v < 5; v++)
        ck_assert_int_eq(mate[v], -1);
    ck_assert_uint_eq(d.nblossom, 0);
    cvm__match_duals_free(&ctx, &d);
}
END_TEST

START_TEST(matching_rejects_bad_edges_naming_them)
{
    cvm__ctx ctx;
    cvm_index mate[3];
    static const cvm_index loop[] = {0, 1, 2, 2};
    static const cvm_index out[] = {0, 1, 1, 3};
    static const cvm_index line[] = {0, 1, 1, 2};
    static const int64_t w[] = {1, 1};
    static const int64_t neg[] = {1, -1};
    cvm__ctx_init_default(&ctx);
    ck_assert_int_eq(cvm__matching_solve(mate, NULL, &ctx, 3, 2, loop, w, CVM__MATCH_MAX_WEIGHT),
                     CVM_E_INPUT_DEGENERATE);
    ck_assert_ptr_nonnull(strstr(ctx.errmsg, "edge 1"));
    ck_assert_int_eq(cvm__matching_solve(mate, NULL, &ctx, 3, 2, out, w, CVM__MATCH_MAX_WEIGHT),
                     CVM_E_INPUT_INDEX);
    ck_assert_ptr_nonnull(strstr(ctx.errmsg, "edge 1"));
    ck_assert_int_eq(cvm__matching_solve(mate, NULL, &ctx, 3, 2, out, neg, CVM__MATCH_MAX_WEIGHT),
                     CVM_E_INPUT_INDEX);
    ck_assert_int_eq(cvm__matching_greedy(mate, &ctx, 3, 2, line, neg), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(ctx.errmsg, "edge 1"));
    ck_assert_int_eq(cvm__matching_solve(mate, NULL, &ctx, 3, 2, loop, w, (cvm__match_mode)7),
                     CVM_E_ARGUMENT);
}
END_TEST

START_TEST(matching_greedy_is_a_matching_of_at_least_half_the_optimum)
{
    qtest_graph g;
    cvm__ctx ctx;
    cvm_index *mate;
    int64_t wg, wo;
    size_t card;
    qtest_delaunay_dual(&g, 2000, 5, 1000);
    mate = malloc(g.n * sizeof *mate);
    ck_assert_ptr_nonnull(mate);
    cvm__ctx_init_default(&ctx);
    ck_assert_int_eq(cvm__matching_greedy(mate, &ctx, g.n, g.m, g.ends, g.w), CVM_OK);
    qtest_assert_matching(&g, mate, &wg, &card);
    wo = solve_certified(&g, CVM__MATCH_MAX_WEIGHT, &card, NULL);
    ck_assert_int_le(wg, wo);
    ck_assert_int_ge(2 * wg, wo);
    free(mate);
    qtest_graph_free(&g);
}
END_TEST

START_TEST(matching_out_of_memory_at_every_allocation)
{
    qtest_graph g;
    long i;
    int run;
    qtest_delaunay_dual(&g, 300, 3, 100);
    for (run = 0; run < 4; run++) {
        int mode = run & 1, persistent = run >> 1;
        for (i = 1;; i++) {
            cvmtest_alloc a;
            cvm__ctx ctx;
            cvm__match_duals d;
            cvm_index *mate = malloc(g.n * sizeof *mate);
            cvm_status st;
            cvmtest_alloc_init(&a, i, persistent);
            qtest_ctx(&ctx, &a);
            st = cvm__matching_solve(mate, &d, &ctx, g.n, g.m, g.ends, g.w, (cvm__match_mode)mode);
            free(mate);
            if (st == CVM_OK) {
                cvm__match_duals_free(&ctx, &d);
                ck_assert_int_eq(a.live_blocks, 0);
                ck_assert_int_gt(i, 20);
                break;
            }
            ck_assert_int_eq(st, CVM_E_NOMEM);
            ck_assert_int_eq(a.live_blocks, 0);
        }
    }
    qtest_graph_free(&g);
}
END_TEST

TCase *quad_matching_tcase(void)
{
    TCase *tc = tcase_create("matching");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, matching_equals_brute_force_on_small_multigraphs);
    tcase_add_test(tc, matching_equals_networkx_on_200_random_graphs);
    tcase_add_test(tc, matching_certified_on_triangulation_dual_graphs);
    tcase_add_test(tc, matching_certified_on_dense_random_graphs);
    tcase_add_test(tc, matching_nested_blossom_of_two_triangles_in_a_pentagon);
    tcase_add_test(tc, matching_of_empty_graph_and_isolated_vertices);
    tcase_add_test(tc, matching_rejects_bad_edges_naming_them);
    tcase_add_test(tc, matching_greedy_is_a_matching_of_at_least_half_the_optimum);
    tcase_add_test(tc, matching_out_of_memory_at_every_allocation);
    return tc;
}
