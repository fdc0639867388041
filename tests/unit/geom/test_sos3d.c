/* test_sos3d.c - the index perturbation of insphere/power3d is derived right and globally consistent on cospherical lattices. */
#include <stdint.h>

#include "geom/geom_internal.h"
#include "geom/geom_tests.h"

/* The perturbation made concrete: point of rank r (0 = largest index) gets
 * weight -2^(-20 (r + 1)), i.e. its lift raised by that much. For integer
 * coordinates of magnitude <= 8 the cofactors are integers below 2^15, so on
 * an exact tie the sign of this determinant is that of the first nonzero
 * derivative in order of decreasing index: what the _sos tests claim. */
static int hierarchical_sign(double (*p)[3], const int64_t *idx, const double *w0)
{
    double w[5];
    int j, k;
    for (j = 0; j < 5; j++) {
        int rank = 0;
        for (k = 0; k < 5; k++)
            rank += idx[k] > idx[j];
        w[j] = w0[j] - ldexp(1.0, -20 * (rank + 1));
    }
    return oracle_power3d(p[0], p[1], p[2], p[3], p[4], w[0], w[1], w[2], w[3], w[4]);
}

static int isp_sos(double (*p)[3], const int64_t *i)
{
    return cvm__insphere_sos(p[0], p[1], p[2], p[3], p[4], i[0], i[1], i[2], i[3], i[4]);
}

/* Points of the body-centred cubic lattice (integer corners and half-integer
 * centres, doubled to integers) in a small box: full of cospherical sets. */
static int bcc_points(double (*p)[3], int n)
{
    int x, y, z, m = 0;
    for (x = 0; x < n; x++)
        for (y = 0; y < n; y++)
            for (z = 0; z < n; z++) {
                p[m][0] = 2 * x, p[m][1] = 2 * y, p[m][2] = 2 * z, m++;
                if (x + 1 < n && y + 1 < n && z + 1 < n)
                    p[m][0] = 2 * x + 1, p[m][1] = 2 * y + 1, p[m][2] = 2 * z + 1, m++;
            }
    return m;
}

START_TEST(insphere_sos_matches_explicit_perturbation_on_bcc)
{
    double lat[64][3], p[5][3], w0[5] = { 0, 0, 0, 0, 0 };
    int64_t idx[5];
    geomtest_rng r = { 401 };
    int n = bcc_points(lat, 3), i, j, k, ties = 0;
    for (i = 0; i < 40000; i++) {
        int pick[5];
        for (j = 0; j < 5; j++) {
            int again;
            do {
                pick[j] = (int)(geomtest_u64(&r) % (uint64_t)n);
                again = 0;
                for (k = 0; k < j; k++)
                    again |= pick[k] == pick[j];
            } while (again);
            for (k = 0; k < 3; k++)
                p[j][k] = lat[pick[j]][k];
            idx[j] = (int64_t)(geomtest_u64(&r) % 1000000);
            for (k = 0; k < j; k++)
                if (idx[k] == idx[j])
                    idx[j] += 1000000 * (j + 1);
        }
        if (cvm__orient3d(p[0], p[1], p[2], p[3]) == 0.0)
            continue;
        if (cvm__insphere(p[0], p[1], p[2], p[3], p[4]) == 0.0)
            ties++;
        ck_assert_int_eq(isp_sos(p, idx), hierarchical_sign(p, idx, w0));
        ck_assert_int_eq(cvm__power3d_sos(p[0], p[1], p[2], p[3], p[4], 0, 0, 0, 0, 0, idx[0],
                                          idx[1], idx[2], idx[3], idx[4]),
                         isp_sos(p, idx));
    }
    ck_assert_int_gt(ties, 500);
}
END_TEST

/* Weighted ties: the same check for power3d_sos with integer weights. */
START_TEST(power3d_sos_matches_explicit_perturbation)
{
    geomtest_rng r = { 402 };
    int i, j, k, ties = 0;
    for (i = 0; i < 20000; i++) {
        double p[5][3], w[5];
        int64_t idx[5];
        int got;
        for (j = 0; j < 5; j++) {
            for (k = 0; k < 3; k++)
                p[j][k] = geomtest_int(&r, -2, 2);
            w[j] = geomtest_int(&r, -2, 2);
            idx[j] = 10 * j + (int64_t)(geomtest_u64(&r) % 10);
        }
        if (cvm__orient3d(p[0], p[1], p[2], p[3]) == 0.0)
            continue;
        ties += cvm__power3d(p[0], p[1], p[2], p[3], p[4], w[0], w[1], w[2], w[3], w[4]) == 0.0;
        got = cvm__power3d_sos(p[0], p[1], p[2], p[3], p[4], w[0], w[1], w[2], w[3], w[4], idx[0],
                               idx[1], idx[2], idx[3], idx[4]);
        ck_assert_int_eq(got, hierarchical_sign(p, idx, w));
    }
    ck_assert_int_gt(ties, 100);
}
END_TEST

/* Swapping two (point, index) pairs negates the answer, also on ties. */
START_TEST(insphere_sos_is_alternating)
{
    double lat[64][3], p[5][3], q[5][3];
    int64_t idx[5], jdx[5];
    geomtest_rng r = { 403 };
    int n = bcc_points(lat, 3), i, j, k, a, b;
    for (i = 0; i < 20000; i++) {
        for (j = 0; j < 5; j++) {
            int pick = (int)(geomtest_u64(&r) % (uint64_t)n);
            for (k = 0; k < 3; k++)
                p[j][k] = lat[pick][k];
            idx[j] = pick;
        }
        for (j = 0; j < 5; j++)
            for (k = 0; k < j; k++)
                if (idx[j] == idx[k])
                    goto next;
        a = (int)(geomtest_u64(&r) % 5), b = (a + 1 + (int)(geomtest_u64(&r) % 4)) % 5;
        for (j = 0; j < 5; j++) {
            int s = j == a ? b : j == b ? a : j;
            for (k = 0; k < 3; k++)
                q[j][k] = p[s][k];
            jdx[j] = idx[s];
        }
        /* the 5x5 sign is what is alternating: convert via the orientation */
        {
            int s1 = isp_sos(p, idx), s2 = isp_sos(q, jdx);
            double o1 = cvm__orient3d(p[0], p[1], p[2], p[3]);
            double o2 = cvm__orient3d(q[0], q[1], q[2], q[3]);
            if (o1 != 0.0 && o2 != 0.0)
                ck_assert_int_eq(s1, -s2);
        }
    next:;
    }
}
END_TEST

TCase *geom_sos3d_tcase(void)
{
    TCase *tc = tcase_create("sos3d");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, insphere_sos_matches_explicit_perturbation_on_bcc);
    tcase_add_test(tc, power3d_sos_matches_explicit_perturbation);
    tcase_add_test(tc, insphere_sos_is_alternating);
    return tc;
}
