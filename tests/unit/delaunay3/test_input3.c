/* test_input3.c - duplicates merged and reported, degenerate and non-finite input refused with the item named, corruption caught by the check. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay3/delaunay3_tests.h"

/* Duplicates appended after the points, and one placed before its twin:
 * merged into the lowest index, counted, first pair reported, and the
 * tetrahedra are those of the points without duplicates. */
START_TEST(duplicates_are_merged_and_reported)
{
    size_t n = 2000, extra = 150, i, nt1, nt2;
    double *xyz = malloc(3 * (n + extra + 1) * sizeof *xyz);
    uint8_t *fate = malloc(n + extra + 1);
    int32_t *into = malloc((n + extra + 1) * sizeof *into), *a, *b;
    cvm__ctx ctx;
    cvm__tet3 T;
    cvm__ctx_init_default(&ctx);
    d3test_random(xyz, n, 21);
    a = d3test_build(&T, &ctx, xyz, NULL, n, 4, &nt1);
    cvm__tet3_free(&T);
    for (i = 0; i < extra; i++) /* point n + i repeats point (7 i) mod n */
        memcpy(xyz + 3 * (n + i), xyz + 3 * ((7 * i) % n), 3 * sizeof *xyz);
    b = d3test_build(&T, &ctx, xyz, NULL, n + extra, 4, &nt2);
    ck_assert_uint_eq(T.n_dup, extra);
    ck_assert_int_eq(T.dup_first[0], 0);
    ck_assert_int_eq(T.dup_first[1], (int64_t)n);
    cvm__tet3_point_fates(&T, fate, into);
    for (i = 0; i < extra; i++) {
        ck_assert_int_eq(fate[n + i], CVM__T3_DUPLICATE);
        ck_assert_int_eq(into[n + i], (int32_t)((7 * i) % n));
    }
    ck_assert_int_eq(fate[0], CVM__T3_VERTEX);
    ck_assert_uint_eq(nt1, nt2);
    ck_assert(memcmp(a, b, 4 * nt1 * sizeof *a) == 0);
    cvm__tet3_free(&T);
    free(b);
    /* a twin of point 5 at index 0 (point 0 moved to the end): 0 is kept, 5 merged */
    memcpy(xyz + 3 * n, xyz, 3 * sizeof *xyz);
    memcpy(xyz, xyz + 15, 3 * sizeof *xyz);
    b = d3test_build(&T, &ctx, xyz, NULL, n + 1, 4, &nt2);
    ck_assert_uint_eq(T.n_dup, 1);
    ck_assert_int_eq(T.dup_first[0], 0);
    ck_assert_int_eq(T.dup_first[1], 5);
    cvm__tet3_point_fates(&T, fate, into);
    ck_assert_int_eq(fate[5], CVM__T3_DUPLICATE);
    ck_assert_int_eq(into[5], 0);
    cvm__tet3_free(&T);
    free(a);
    free(b);
    free(into);
    free(fate);
    free(xyz);
}
END_TEST

static void expect_refused(const double *xyz, size_t n, cvm_status want, const char *needle)
{
    cvm__ctx ctx;
    cvm__tet3 T;
    cvm_status s;
    cvm__ctx_init_default(&ctx);
    cvm__tet3_init(&T, &ctx);
    s = cvm__tet3_build(&T, xyz, NULL, n, 1);
    ck_assert_int_eq(s, want);
    ck_assert_msg(strstr(ctx.errmsg, needle) != NULL, "message \"%s\" lacks \"%s\"", ctx.errmsg,
                  needle);
    cvm__tet3_free(&T);
}

START_TEST(degenerate_input_is_refused_with_a_message)
{
    double p[3 * 64];
    size_t i;
    for (i = 0; i < 64; i++) /* the plane z = x + 2y, exactly */
        p[3 * i] = (double)(i % 8), p[3 * i + 1] = (double)(i / 8),
        p[3 * i + 2] = p[3 * i] + 2 * p[3 * i + 1];
    expect_refused(p, 64, CVM_E_INPUT_DEGENERATE, "plane");
    for (i = 0; i < 64; i++) /* the line (i, 2i, -3i) */
        p[3 * i] = (double)i, p[3 * i + 1] = 2.0 * i, p[3 * i + 2] = -3.0 * i;
    expect_refused(p, 64, CVM_E_INPUT_DEGENERATE, "line");
    for (i = 0; i < 3 * 64; i++)
        p[i] = 0.5;
    expect_refused(p, 64, CVM_E_INPUT_DEGENERATE, "same point");
    d3test_random(p, 3, 1);
    expect_refused(p, 3, CVM_E_INPUT_DEGENERATE, "3 points");
    expect_refused(p, 0, CVM_E_INPUT_DEGENERATE, "0 points");
}
END_TEST

START_TEST(non_finite_input_names_the_point)
{
    double p[3 * 20];
    cvm__ctx ctx;
    cvm__tet3 T;
    double w[20] = { 0 };
    d3test_random(p, 20, 2);
    p[3 * 7 + 1] = NAN;
    expect_refused(p, 20, CVM_E_INPUT_NONFINITE, "point 7");
    p[3 * 7 + 1] = 0.5;
    p[3 * 12 + 2] = -INFINITY;
    expect_refused(p, 20, CVM_E_INPUT_NONFINITE, "point 12");
    p[3 * 12 + 2] = 0.5;
    w[3] = INFINITY;
    cvm__ctx_init_default(&ctx);
    cvm__tet3_init(&T, &ctx);
    ck_assert_int_eq(cvm__tet3_build(&T, p, w, 20, 1), CVM_E_INPUT_NONFINITE);
    ck_assert_ptr_nonnull(strstr(ctx.errmsg, "point 3 has a non-finite weight"));
    cvm__tet3_free(&T);
}
END_TEST

/* The check is a real oracle: each corruption is found and named. */
START_TEST(check_names_a_corrupted_tetrahedron)
{
    size_t n = 300, nt, t;
    double xyz[3 * 300];
    cvm__ctx ctx;
    cvm__tet3 T;
    int32_t *tets, x;
    cvm__ctx_init_default(&ctx);
    d3test_random(xyz, n, 8);
    tets = d3test_build(&T, &ctx, xyz, NULL, n, 1, &nt);
    for (t = 0; T.tt[8 * t] == CVM__T3_DEAD || T.tt[8 * t + 3] == CVM__T3_GHOST; t++)
        ;
    /* inverted orientation */
    x = T.tt[8 * t], T.tt[8 * t] = T.tt[8 * t + 1], T.tt[8 * t + 1] = x;
    ck_assert_int_eq(cvm__tet3_check(&T), CVM_E_INTERNAL);
    ck_assert_ptr_nonnull(strstr(ctx.errmsg, "tetrahedron"));
    x = T.tt[8 * t], T.tt[8 * t] = T.tt[8 * t + 1], T.tt[8 * t + 1] = x;
    ck_assert_int_eq(cvm__tet3_check(&T), CVM_OK);
    /* a broken neighbour link */
    x = CVM__T3_TN(&T, 4 * t);
    CVM__T3_TN(&T, 4 * t) = CVM__T3_TN(&T, 4 * t + 1);
    ck_assert_int_eq(cvm__tet3_check(&T), CVM_E_INTERNAL);
    ck_assert_ptr_nonnull(strstr(ctx.errmsg, "not shared back"));
    CVM__T3_TN(&T, 4 * t) = x;
    /* a point moved into a circumsphere: no longer Delaunay */
    {
        int32_t v = T.tt[8 * t];
        const int32_t *q = T.tt + 8 * t;
        double c[3] = { 0, 0, 0 }, keep[3];
        int k, j;
        for (k = 0; k < 4; k++)
            for (j = 0; j < 3; j++)
                c[j] += 0.25 * T.xyz[3 * q[k] + j];
        for (k = 0; k < (int)T.np; k++) {
            if (k == q[0] || k == q[1] || k == q[2] || k == q[3] || T.fate[k] != CVM__T3_VERTEX)
                continue;
            memcpy(keep, T.xyz + 3 * k, sizeof keep);
            memcpy(T.xyz + 3 * k, c, sizeof c); /* vertex k now sits at the centroid of t */
            ck_assert_int_eq(cvm__tet3_check(&T), CVM_E_INTERNAL);
            memcpy(T.xyz + 3 * k, keep, sizeof keep);
            break;
        }
        (void)v;
    }
    ck_assert_int_eq(cvm__tet3_check(&T), CVM_OK);
    cvm__tet3_free(&T);
    free(tets);
}
END_TEST

TCase *delaunay3_input_tcase(void)
{
    TCase *tc = tcase_create("input3");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, duplicates_are_merged_and_reported);
    tcase_add_test(tc, degenerate_input_is_refused_with_a_message);
    tcase_add_test(tc, non_finite_input_names_the_point);
    tcase_add_test(tc, check_names_a_corrupted_tetrahedron);
    return tc;
}
