/* test_sos.c - the index perturbation of incircle/power2d is derived right and globally consistent. */
#include <stdint.h>

#include "geom/geom_internal.h"
#include "geom/geom_tests.h"

/* The lifted derivatives sos.c relies on, checked in exact integers: lifting
 * point i by +1 changes the determinant by exactly the claimed orient2d. */
START_TEST(sos_lift_derivatives_match_integer_determinants)
{
    geomtest_rng r = { 91 };
    int i, j;
    for (i = 0; i < 50000; i++) {
        double p[4][2], w[4];
        int64_t base, claimed[4];
        for (j = 0; j < 4; j++)
            p[j][0] = geomtest_int(&r, -50, 50), p[j][1] = geomtest_int(&r, -50, 50);
        base = intdet_incircle(p[0], p[1], p[2], p[3]);
        claimed[0] = intdet_orient2d(p[3], p[1], p[2]);
        claimed[1] = intdet_orient2d(p[0], p[3], p[2]);
        claimed[2] = intdet_orient2d(p[0], p[1], p[3]);
        claimed[3] = -intdet_orient2d(p[0], p[1], p[2]);
        for (j = 0; j < 4; j++) {
            w[0] = w[1] = w[2] = w[3] = 0.0;
            w[j] = -1.0; /* lift z_j = |p_j|^2 - w_j up by one */
            ck_assert(intdet_power2d(p[0], p[1], p[2], p[3], w[0], w[1], w[2], w[3]) - base
                      == claimed[j]);
        }
    }
}
END_TEST

/* The 24 lattice points on x^2 + y^2 = 325 around (3, -7), counter-clockwise. */
static int circle_points(double (*p)[2])
{
    static const int q[6][2] = { { 18, 1 }, { 17, 6 }, { 15, 10 }, { 10, 15 }, { 6, 17 }, { 1, 18 } };
    int k, j, n = 0;
    for (k = 0; k < 4; k++) /* quarter turns */
        for (j = 0; j < 6; j++) {
            int x = q[j][0], y = q[j][1], t;
            int m;
            for (m = 0; m < k; m++)
                t = x, x = -y, y = t;
            p[n][0] = 3.0 + x, p[n][1] = -7.0 + y, n++;
        }
    return n;
}

/* Sign of the determinant with point i lifted by B^rank(i), B = 2^14, ranks by
 * increasing index, from the integer determinant itself (no derivatives). */
static int explicit_perturbation(double (*p)[2], const double *w, const int64_t *idx)
{
    double pw[4];
    int i, j, rank;
    for (i = 0; i < 4; i++) {
        for (j = 0, rank = 0; j < 4; j++)
            rank += idx[j] < idx[i];
        pw[i] = w[i] - (double)((int64_t)1 << (14 * rank));
    }
    return geomtest_sign64(intdet_power2d(p[0], p[1], p[2], p[3], pw[0], pw[1], pw[2], pw[3]));
}

static void random_indices(geomtest_rng *r, int64_t *idx)
{
    int i, j, dup;
    do {
        for (i = 0; i < 4; i++) {
            uint64_t u = geomtest_u64(r);
            idx[i] = (int64_t)(u % 40) - (((u >> 32) & 1u) ? (int64_t)1 << 40 : 0);
        }
        for (dup = 0, i = 0; i < 4; i++)
            for (j = i + 1; j < 4; j++)
                dup |= idx[i] == idx[j];
    } while (dup);
}

START_TEST(incircle_sos_matches_an_explicit_integer_perturbation)
{
    double c[24][2], q[4][2], zero[4] = { 0, 0, 0, 0 };
    geomtest_rng r = { 92 };
    int n = circle_points(c), i, j, k;
    ck_assert_int_eq(n, 24);
    for (i = 0; i < 20000; i++) {
        int64_t idx[4];
        int pick[4], s;
        for (j = 0; j < 4; j++) { /* four distinct points in random order */
            int again;
            do {
                pick[j] = (int)(geomtest_u64(&r) % 24);
                for (again = 0, k = 0; k < j; k++)
                    again |= pick[k] == pick[j];
            } while (again);
            q[j][0] = c[pick[j]][0], q[j][1] = c[pick[j]][1];
        }
        random_indices(&r, idx);
        ck_assert(cvm__incircle(q[0], q[1], q[2], q[3]) == 0.0);
        s = cvm__incircle_sos(q[0], q[1], q[2], q[3], idx[0], idx[1], idx[2], idx[3]);
        ck_assert_int_eq(s, explicit_perturbation(q, zero, idx));
        ck_assert_int_eq(cvm__power2d_sos(q[0], q[1], q[2], q[3], 0, 0, 0, 0, idx[0], idx[1],
                                          idx[2], idx[3]),
                         s);
        ck_assert_int_eq(cvm__power2d_sos(q[0], q[1], q[2], q[3], 7, 7, 7, 7, idx[0], idx[1],
                                          idx[2], idx[3]),
                         s);
    }
}
END_TEST

static int parity(const int *perm)
{
    int i, j, inv = 0;
    for (i = 0; i < 4; i++)
        for (j = i + 1; j < 4; j++)
            inv += perm[i] > perm[j];
    return (inv % 2) ? -1 : 1;
}

/* One global perturbation means the perturbed determinant is alternating:
 * permuting the (point, index) pairs multiplies the answer by the parity. */
START_TEST(incircle_sos_is_alternating_under_all_permutations)
{
    double c[24][2];
    geomtest_rng r = { 93 };
    int i, a, b, cc, d;
    circle_points(c);
    for (i = 0; i < 500; i++) {
        int base[4], perm[4], s0 = 0, first = 1;
        int64_t idx[4];
        base[0] = (int)(geomtest_u64(&r) % 24);
        do base[1] = (int)(geomtest_u64(&r) % 24); while (base[1] == base[0]);
        do base[2] = (int)(geomtest_u64(&r) % 24); while (base[2] == base[0] || base[2] == base[1]);
        do
            base[3] = (int)(geomtest_u64(&r) % 24);
        while (base[3] == base[0] || base[3] == base[1] || base[3] == base[2]);
        random_indices(&r, idx);
        for (a = 0; a < 4; a++)
            for (b = 0; b < 4; b++)
                for (cc = 0; cc < 4; cc++)
                    for (d = 0; d < 4; d++) {
                        int s;
                        if (a == b || a == cc || a == d || b == cc || b == d || cc == d)
                            continue;
                        perm[0] = a, perm[1] = b, perm[2] = cc, perm[3] = d;
                        s = cvm__incircle_sos(c[base[a]], c[base[b]], c[base[cc]], c[base[d]],
                                              idx[a], idx[b], idx[cc], idx[d]);
                        ck_assert(s == 1 || s == -1);
                        if (first)
                            s0 = s * parity(perm), first = 0;
                        ck_assert_int_eq(s, parity(perm) * s0);
                    }
    }
}
END_TEST

/* For a convex cocircular quadrilateral p0 p1 p2 p3 (counter-clockwise), exactly
 * one diagonal is locally Delaunay under the perturbation, and when the fourth
 * point has the largest index it counts as outside. */
START_TEST(incircle_sos_picks_exactly_one_diagonal)
{
    double c[24][2];
    geomtest_rng r = { 94 };
    int i, j;
    circle_points(c);
    for (i = 0; i < 20000; i++) {
        int v[4];
        int64_t idx[4];
        int diag02, diag13;
        do { /* increasing positions around the circle keep the order counter-clockwise */
            for (j = 0; j < 4; j++)
                v[j] = (int)(geomtest_u64(&r) % 24);
        } while (!(v[0] < v[1] && v[1] < v[2] && v[2] < v[3]));
        random_indices(&r, idx);
        ck_assert(cvm__orient2d(c[v[0]], c[v[1]], c[v[2]]) > 0.0);
        diag02 = cvm__incircle_sos(c[v[0]], c[v[1]], c[v[2]], c[v[3]], idx[0], idx[1], idx[2],
                                   idx[3])
                 < 0;
        diag13 = cvm__incircle_sos(c[v[1]], c[v[2]], c[v[3]], c[v[0]], idx[1], idx[2], idx[3],
                                   idx[0])
                 < 0;
        ck_assert_int_eq(diag02 + diag13, 1);
        if (idx[3] > idx[0] && idx[3] > idx[1] && idx[3] > idx[2])
            ck_assert_int_eq(cvm__incircle_sos(c[v[0]], c[v[1]], c[v[2]], c[v[3]], idx[0],
                                               idx[1], idx[2], idx[3]),
                             -1);
    }
}
END_TEST

/* Off the tie the perturbation never overrides the exact sign. */
START_TEST(incircle_sos_keeps_nonzero_signs)
{
    geomtest_rng r = { 95 };
    int i, j;
    for (i = 0; i < 50000; i++) {
        double p[4][2];
        int64_t want;
        for (j = 0; j < 4; j++)
            p[j][0] = geomtest_int(&r, -6, 6), p[j][1] = geomtest_int(&r, -6, 6);
        want = intdet_incircle(p[0], p[1], p[2], p[3]);
        if (want == 0)
            continue;
        ck_assert_int_eq(cvm__incircle_sos(p[0], p[1], p[2], p[3], 3, 2, 1, 0),
                         geomtest_sign64(want));
        ck_assert_int_eq(cvm__incircle_sos(p[0], p[1], p[2], p[3], 0, 1, 2, 3),
                         geomtest_sign64(want));
    }
}
END_TEST

/* A weighted tie that is not a cocircularity: d at the orthocentre with weight
 * equal to its power. */
START_TEST(power2d_sos_breaks_weighted_ties_like_the_explicit_perturbation)
{
    double p[4][2] = { { 6, 2 }, { 1, 7 }, { -4, 2 }, { 1, 2 } };
    double w[4] = { 0, 0, 0, -25 };
    geomtest_rng r = { 96 };
    int i;
    ck_assert(cvm__power2d(p[0], p[1], p[2], p[3], w[0], w[1], w[2], w[3]) == 0.0);
    for (i = 0; i < 2000; i++) {
        int64_t idx[4];
        random_indices(&r, idx);
        ck_assert_int_eq(cvm__power2d_sos(p[0], p[1], p[2], p[3], w[0], w[1], w[2], w[3], idx[0],
                                          idx[1], idx[2], idx[3]),
                         explicit_perturbation(p, w, idx));
    }
}
END_TEST

TCase *geom_sos_tcase(void)
{
    TCase *tc = tcase_create("sos");
    tcase_add_test(tc, sos_lift_derivatives_match_integer_determinants);
    tcase_add_test(tc, incircle_sos_matches_an_explicit_integer_perturbation);
    tcase_add_test(tc, incircle_sos_is_alternating_under_all_permutations);
    tcase_add_test(tc, incircle_sos_picks_exactly_one_diagonal);
    tcase_add_test(tc, incircle_sos_keeps_nonzero_signs);
    tcase_add_test(tc, power2d_sos_breaks_weighted_ties_like_the_explicit_perturbation);
    tcase_set_timeout(tc, 60);
    return tc;
}
