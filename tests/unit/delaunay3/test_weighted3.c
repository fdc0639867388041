/* test_weighted3.c - regular (weighted) tetrahedralisation: power-exact validity, vanished vertices reported, seed independence. */
#include <stdlib.h>
#include <string.h>

#include "delaunay3/delaunay3_tests.h"
#include "geom/geom_internal.h"

/* The 8 corners of the unit cube and two inner points: X (index 8, weight 0)
 * and Y (index 9) just above it, weight 0.05. Y's weight swallows X's power cell
 * (|x - X|^2 - 0 > |x - Y|^2 - 0.05 wherever z > -1.99), whichever of the
 * two is inserted first: X is reported redundant, never silently dropped. */
START_TEST(swallowed_vertex_is_reported_for_every_order)
{
    double xyz[3 * 11], w[11] = { 0 };
    uint64_t seed;
    int32_t *first = NULL;
    size_t nt0 = 0;
    int i;
    for (i = 0; i < 8; i++)
        xyz[3 * i] = i & 1, xyz[3 * i + 1] = (i >> 1) & 1, xyz[3 * i + 2] = (i >> 2) & 1;
    xyz[24] = 0.5, xyz[25] = 0.5, xyz[26] = 0.5;
    xyz[27] = 0.5, xyz[28] = 0.5, xyz[29] = 0.51, w[9] = 0.05;
    xyz[30] = 0.2, xyz[31] = 0.7, xyz[32] = 0.4, w[10] = -0.01;
    for (seed = 1; seed <= 40; seed++) {
        cvm__ctx ctx;
        cvm__tet3 T;
        size_t nt;
        uint8_t fate[11];
        int32_t *tets;
        cvm__ctx_init_default(&ctx);
        tets = d3test_build(&T, &ctx, xyz, w, 11, seed, &nt);
        ck_assert_uint_eq(T.n_redundant, 1);
        ck_assert_int_eq(T.redundant_first, 8);
        cvm__tet3_point_fates(&T, fate, NULL);
        ck_assert_int_eq(fate[8], CVM__T3_REDUNDANT);
        ck_assert_int_eq(fate[9], CVM__T3_VERTEX);
        for (i = 0; i < 4 * (int)nt; i++)
            ck_assert_int_ne(tets[i], 8);
        if (!first) {
            first = tets, nt0 = nt;
        } else {
            ck_assert_uint_eq(nt, nt0);
            ck_assert(memcmp(first, tets, 4 * nt * sizeof *tets) == 0);
            free(tets);
        }
        cvm__tet3_free(&T);
    }
    free(first);
}
END_TEST

/* Random weights of the order of the squared spacing: many vertices vanish;
 * the result passes the exact regular check and is the same for every seed. */
START_TEST(random_weights_are_regular_and_seed_independent)
{
    size_t n = 3000, i, nt1, nt2, red;
    double *xyz = malloc(3 * n * sizeof *xyz), *w = malloc(n * sizeof *w);
    cvm__ctx ctx;
    cvm__tet3 T;
    int32_t *a, *b;
    cvm__ctx_init_default(&ctx);
    d3test_random(xyz, n, 31);
    d3test_random(w, n / 3, 32);
    for (i = 0; i < n; i++)
        w[i] = 0.02 * (w[i % (n / 3)] - 0.3) * ((i % 5) ? 0.1 : 1.0);
    a = d3test_build(&T, &ctx, xyz, w, n, 1, &nt1);
    red = T.n_redundant;
    ck_assert_uint_gt(red, 0);
    cvm__tet3_free(&T);
    b = d3test_build(&T, &ctx, xyz, w, n, 99, &nt2);
    ck_assert_uint_eq(T.n_redundant, red);
    ck_assert_uint_eq(nt1, nt2);
    ck_assert(memcmp(a, b, 4 * nt1 * sizeof *a) == 0);
    ck_assert_int_eq(d3test_euler(a, nt1), 1);
    cvm__tet3_free(&T);
    free(a);
    free(b);
    free(w);
    free(xyz);
}
END_TEST

/* Equal weights are Delaunay; a point at a vertex with a lower weight is
 * redundant, with the same weight a duplicate, with a higher one it wins. */
START_TEST(weighted_twins_follow_the_power_rule)
{
    size_t n = 500, nt0, nt;
    double *xyz = malloc(3 * (n + 1) * sizeof *xyz), *w = calloc(n + 1, sizeof *w);
    cvm__ctx ctx;
    cvm__tet3 T;
    int32_t *a, *b;
    uint8_t fate[501];
    cvm__ctx_init_default(&ctx);
    d3test_random(xyz, n, 41);
    a = d3test_build(&T, &ctx, xyz, NULL, n, 1, &nt0);
    cvm__tet3_free(&T);
    b = d3test_build(&T, &ctx, xyz, w, n, 1, &nt);
    ck_assert_uint_eq(nt, nt0);
    ck_assert(memcmp(a, b, 4 * nt * sizeof *a) == 0);
    cvm__tet3_free(&T);
    free(b);
    memcpy(xyz + 3 * n, xyz + 3 * 17, 3 * sizeof *xyz);
    w[n] = -1e-3;
    b = d3test_build(&T, &ctx, xyz, w, n + 1, 1, &nt);
    cvm__tet3_point_fates(&T, fate, NULL);
    ck_assert_int_eq(fate[n], CVM__T3_REDUNDANT);
    ck_assert_int_eq(fate[17], CVM__T3_VERTEX);
    cvm__tet3_free(&T);
    free(b);
    w[n] = 0.0;
    b = d3test_build(&T, &ctx, xyz, w, n + 1, 1, &nt);
    ck_assert_uint_eq(T.n_dup, 1);
    cvm__tet3_free(&T);
    free(b);
    w[n] = 1e-6;
    b = d3test_build(&T, &ctx, xyz, w, n + 1, 1, &nt);
    cvm__tet3_point_fates(&T, fate, NULL);
    ck_assert_int_eq(fate[n], CVM__T3_VERTEX);
    ck_assert_int_eq(fate[17], CVM__T3_REDUNDANT);
    ck_assert_uint_eq(T.n_redundant, 1);
    cvm__tet3_free(&T);
    free(b);
    free(a);
    free(w);
    free(xyz);
}
END_TEST

TCase *delaunay3_weighted_tcase(void)
{
    TCase *tc = tcase_create("weighted3");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, swallowed_vertex_is_reported_for_every_order);
    tcase_add_test(tc, random_weights_are_regular_and_seed_independent);
    tcase_add_test(tc, weighted_twins_follow_the_power_rule);
    return tc;
}
