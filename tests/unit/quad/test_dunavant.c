/* test_dunavant.c - every Dunavant rule integrates every monomial up to its degree exactly. */
#include <math.h>
#include "quad/quad_tests.h"
#include "quad/quad_internal.h"

static double factorial(int n)
{
    double f = 1;
    while (n > 1)
        f *= n--;
    return f;
}

/* The mean over the reference triangle of x^i y^j is 2 i! j! / (i + j + 2)!; the rule gives it
 * to rounding for i + j <= degree, and misses some monomial of degree + 1 (it is no better). */
START_TEST(dunavant_rules_exact_to_their_degree)
{
    int want;
    for (want = 2; want <= 12; want += 2) {
        size_t n, q;
        int deg, i, j, missed = 0;
        const double (*r)[4] = cvm__dunavant_rule(want, &n, &deg);
        double wsum = 0;
        ck_assert_ptr_nonnull(r);
        ck_assert_int_eq(deg, want);
        for (q = 0; q < n; q++) {
            ck_assert(r[q][3] > 0); /* positive weights, points inside */
            ck_assert(r[q][0] > 0 && r[q][1] > 0 && r[q][2] > 0);
            ck_assert(fabs(r[q][0] + r[q][1] + r[q][2] - 1) < 1e-15);
            wsum += r[q][3];
        }
        ck_assert(fabs(wsum - 1) < 1e-15);
        for (i = 0; i <= deg + 1; i++)
            for (j = 0; i + j <= deg + 1; j++) {
                double s = 0, exact = 2 * factorial(i) * factorial(j) / factorial(i + j + 2);
                for (q = 0; q < n; q++)
                    s += r[q][3] * pow(r[q][1], i) * pow(r[q][2], j);
                if (i + j <= deg)
                    ck_assert_msg(fabs(s - exact) <= 4e-16 * exact * (i + j + 2) + 1e-17,
                                  "degree %d rule: x^%d y^%d gives %.17g, exact %.17g", deg, i, j,
                                  s, exact);
                else if (fabs(s - exact) > 1e-12 * exact)
                    missed = 1;
            }
        ck_assert_msg(missed, "the degree %d rule is exact one degree higher too", deg);
    }
    ck_assert_ptr_null(cvm__dunavant_rule(14, &(size_t){0}, &(int){0}));
}
END_TEST

TCase *quad_dunavant_tcase(void)
{
    TCase *tc = tcase_create("dunavant");
    tcase_add_test(tc, dunavant_rules_exact_to_their_degree);
    return tc;
}
