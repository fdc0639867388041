/* test_measure.c - measure.c: the one-atan2 smallest angle equals the minimum of the three corner angles, bit for bit. */
#include <math.h>
#include <stdint.h>

#include "geom/geom_tests.h"
#include "geom/measure.h"

static double uniform(uint64_t *s)
{
    uint64_t z = (*s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return (double)((z ^ (z >> 31)) >> 11) / 9007199254740992.0;
}

static double three_corners(const double *a, const double *b, const double *c)
{
    double d, x = cvm__corner_angle_deg_safe(a, b, c, &d), y = cvm__corner_angle_deg_safe(b, c, a, &d);
    double z = cvm__corner_angle_deg_safe(c, a, b, &d), m = x < y ? x : y;
    return m < z ? m : z;
}

/* Random, near-isosceles (ulps apart), needle, cap, collinear and
 * far-range triangles. */
START_TEST(min_angle_matches_three_corners_bitwise)
{
    static const double scale[] = {1.0, 1e-300, 1e300, 0x1p-510, 0x1p+505};
    uint64_t rng = 12345;
    int i, s;
    for (s = 0; s < 5; s++)
        for (i = 0; i < 200000; i++) {
            double a[2], b[2], c[2], got, want;
            int kind = i % 5;
            a[0] = uniform(&rng);
            a[1] = uniform(&rng);
            b[0] = uniform(&rng);
            b[1] = uniform(&rng);
            if (kind == 0) { /* random */
                c[0] = uniform(&rng);
                c[1] = uniform(&rng);
            } else if (kind == 1) { /* apex on the bisector, a few ulps off */
                double mx = 0.5 * (a[0] + b[0]), my = 0.5 * (a[1] + b[1]), h = uniform(&rng);
                c[0] = nextafter(mx - h * (b[1] - a[1]), (i & 8) ? 2.0 : -2.0);
                c[1] = my + h * (b[0] - a[0]);
            } else if (kind == 2) { /* needle */
                c[0] = b[0] + 1e-9 * uniform(&rng);
                c[1] = b[1] + 1e-9 * uniform(&rng);
            } else if (kind == 3) { /* cap: c close to the middle of a-b */
                double t = uniform(&rng);
                c[0] = a[0] + t * (b[0] - a[0]) + 1e-12 * uniform(&rng);
                c[1] = a[1] + t * (b[1] - a[1]);
            } else { /* collinear */
                c[0] = 2 * b[0] - a[0];
                c[1] = 2 * b[1] - a[1];
            }
            a[0] *= scale[s];
            a[1] *= scale[s];
            b[0] *= scale[s];
            b[1] *= scale[s];
            c[0] *= scale[s];
            c[1] *= scale[s];
            got = cvm__min_angle_deg(a, b, c);
            want = three_corners(a, b, c);
            ck_assert_msg(got == want || (got != got && want != want),
                          "scale %g kind %d case %d: %.17g != %.17g", scale[s], kind, i, got, want);
        }
}
END_TEST

TCase *geom_measure_tcase(void)
{
    TCase *tc = tcase_create("measure");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, min_angle_matches_three_corners_bitwise);
    return tc;
}
