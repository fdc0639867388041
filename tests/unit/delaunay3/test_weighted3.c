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

/* Integer grid with weights in {0, 1, 2}: power ties everywhere, decided by
 * power3d_sos; regular by the exact check and the same bytes for any seed. */
START_TEST(weighted_lattice_ties_are_consistent)
{
    int g = 8, x, y, z;
    size_t n = 0, nt1, nt2, red;
    double xyz[3 * 512], w[512];
    uint64_t seed;
    int32_t *a, *b;
    cvm__ctx ctx;
    cvm__tet3 T;
    cvm__ctx_init_default(&ctx);
    for (x = 0; x < g; x++)
        for (y = 0; y < g; y++)
            for (z = 0; z < g; z++) {
                xyz[3 * n] = x, xyz[3 * n + 1] = y, xyz[3 * n + 2] = z;
                w[n] = (double)((x + 2 * y + 3 * z) % 3);
                n++;
            }
    a = d3test_build(&T, &ctx, xyz, w, n, 1, &nt1);
    red = T.n_redundant;
    cvm__tet3_free(&T);
    for (seed = 2; seed < 6; seed++) {
        b = d3test_build(&T, &ctx, xyz, w, n, seed, &nt2);
        ck_assert_uint_eq(T.n_redundant, red);
        ck_assert_uint_eq(nt1, nt2);
        ck_assert(memcmp(a, b, 4 * nt1 * sizeof *a) == 0);
        cvm__tet3_free(&T);
        free(b);
    }
    ck_assert_int_eq(d3test_euler(a, nt1), 1);
    free(a);
}
END_TEST

/* Tiny weighted inputs on a 4x4x4 grid with weights in {0, 1, 2}: the exact
 * check passes and two seeds and the input scaled by 2^-3 (weights 2^-6)
 * agree byte for byte, redundant counts included. */
START_TEST(tiny_weighted_inputs_agree_across_seeds_and_scales)
{
    uint64_t r = 777;
    int trial;
    for (trial = 0; trial < 300; trial++) {
        double xyz[3 * 64], sc[3 * 64], w[64], ws[64];
        size_t n, i, nt[3], red[3];
        int32_t *out[3];
        int k, ok = 1;
        r = r * 6364136223846793005u + 1442695040888963407u;
        n = 5 + (size_t)((r >> 33) % 50);
        for (i = 0; i < 3 * n; i++) {
            r = r * 6364136223846793005u + 1442695040888963407u;
            xyz[i] = (double)((r >> 40) % 4);
            sc[i] = xyz[i] * 0.125;
        }
        for (i = 0; i < n; i++) {
            r = r * 6364136223846793005u + 1442695040888963407u;
            w[i] = (double)((r >> 40) % 3);
            ws[i] = w[i] / 64.0;
        }
        for (k = 0; k < 3 && ok; k++) {
            cvm__ctx ctx;
            cvm__tet3 T;
            cvm_status s;
            cvm__ctx_init_default(&ctx);
            cvm__tet3_init(&T, &ctx);
            s = cvm__tet3_build(&T, k == 2 ? sc : xyz, k == 2 ? ws : w, n, k == 1 ? 7 : 1);
            if (s == CVM_E_INPUT_DEGENERATE) {
                ck_assert_int_eq(k, 0);
                ok = 0;
            } else {
                ck_assert_msg(s == CVM_OK, "trial %d: %s", trial, ctx.errmsg);
                ck_assert_msg(cvm__tet3_check(&T) == CVM_OK, "trial %d path %d: %s", trial, k,
                              ctx.errmsg);
                out[k] = malloc(4 * T.n_finite * sizeof(int32_t) + 16);
                ck_assert_int_eq(cvm__tet3_copy_tets(&T, out[k]), CVM_OK);
                nt[k] = T.n_finite;
                red[k] = T.n_redundant;
            }
            cvm__tet3_free(&T);
        }
        if (!ok)
            continue;
        for (k = 1; k < 3; k++) {
            ck_assert_uint_eq(nt[k], nt[0]);
            ck_assert_uint_eq(red[k], red[0]);
            ck_assert_msg(memcmp(out[0], out[k], 4 * nt[0] * sizeof(int32_t)) == 0,
                          "trial %d: path %d differs", trial, k);
        }
        for (k = 0; k < 3; k++)
            free(out[k]);
    }
}
END_TEST

TCase *delaunay3_weighted_tcase(void)
{
    TCase *tc = tcase_create("weighted3");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, swallowed_vertex_is_reported_for_every_order);
    tcase_add_test(tc, random_weights_are_regular_and_seed_independent);
    tcase_add_test(tc, weighted_twins_follow_the_power_rule);
    tcase_add_test(tc, weighted_lattice_ties_are_consistent);
    tcase_add_test(tc, tiny_weighted_inputs_agree_across_seeds_and_scales);
    return tc;
}
