/* test_construct.c - circumcentre and segment crossing: exact where representable, clamped always. */
#include <math.h>

#include "geom/geom_internal.h"
#include "geom/geom_tests.h"

START_TEST(circumcenter_is_exact_when_representable)
{
    double a[2] = { 0, 0 }, b[2] = { 4, 0 }, c[2] = { 0, 6 }, o[2];
    double p[2] = { 6, 2 }, q[2] = { 1, 7 }, s[2] = { -4, 2 };
    cvm__circumcenter2d(a, b, c, o);
    ck_assert(o[0] == 2.0 && o[1] == 3.0);
    cvm__circumcenter2d(b, c, a, o); /* any rotation, and clockwise too */
    ck_assert(o[0] == 2.0 && o[1] == 3.0);
    cvm__circumcenter2d(a, c, b, o);
    ck_assert(o[0] == 2.0 && o[1] == 3.0);
    cvm__circumcenter2d(p, q, s, o);
    ck_assert(o[0] == 1.0 && o[1] == 2.0);
}
END_TEST

/* For well-shaped random triangles the centre is equidistant up to a stated
 * 1e-12 relative error (a construction, so a tolerance is the right check). */
START_TEST(circumcenter_is_equidistant_on_random_triangles)
{
    geomtest_rng r = { 81 };
    int i, j, checked = 0;
    for (i = 0; i < 20000; i++) {
        double p[3][2], o[2], d[3];
        for (j = 0; j < 3; j++)
            p[j][0] = geomtest_uniform(&r, -1, 1), p[j][1] = geomtest_uniform(&r, -1, 1);
        if (fabs(cvm__orient2d(p[0], p[1], p[2])) < 0.1)
            continue; /* keep well-shaped ones */
        cvm__circumcenter2d(p[0], p[1], p[2], o);
        for (j = 0; j < 3; j++)
            d[j] = hypot(p[j][0] - o[0], p[j][1] - o[1]);
        ck_assert(fabs(d[0] - d[1]) <= 1e-12 * d[0] && fabs(d[0] - d[2]) <= 1e-12 * d[0]);
        checked++;
    }
    ck_assert_int_gt(checked, 1000);
}
END_TEST

START_TEST(segment_intersection_exact_cases)
{
    double a[2] = { 0, 0 }, b[2] = { 2, 2 }, c[2] = { 0, 2 }, d[2] = { 2, 0 }, o[2];
    double e[2] = { -3, 1 }, f[2] = { 5, 1 }, g[2] = { 1, -4 }, h[2] = { 1, 6 };
    cvm__segment_intersection2d(a, b, c, d, o);
    ck_assert(o[0] == 1.0 && o[1] == 1.0);
    cvm__segment_intersection2d(e, f, g, h, o);
    ck_assert(o[0] == 1.0 && o[1] == 1.0);
    cvm__segment_intersection2d(h, g, f, e, o);
    ck_assert(o[0] == 1.0 && o[1] == 1.0);
}
END_TEST

static int in_box(const double *p, const double *a, const double *b)
{
    return p[0] >= fmin(a[0], b[0]) && p[0] <= fmax(a[0], b[0]) && p[1] >= fmin(a[1], b[1])
           && p[1] <= fmax(a[1], b[1]);
}

/* Nearly parallel, nearly touching crossings: the result always lies in both
 * segments' bounding boxes (an exact check). */
START_TEST(segment_intersection_stays_in_both_boxes)
{
    geomtest_rng r = { 82 };
    int i, tested = 0;
    for (i = 0; i < 50000; i++) {
        double a[2], b[2], c[2], d[2], m[2], o[2], ang = geomtest_uniform(&r, 0, 3.14159);
        double tilt = (i % 2) ? 1e-12 : 1e-3, t = geomtest_uniform(&r, 0.1, 0.9);
        a[0] = geomtest_uniform(&r, -1, 1), a[1] = geomtest_uniform(&r, -1, 1);
        b[0] = a[0] + cos(ang), b[1] = a[1] + sin(ang);
        m[0] = a[0] + t * (b[0] - a[0]), m[1] = a[1] + t * (b[1] - a[1]);
        c[0] = m[0] - 0.3 * cos(ang + tilt), c[1] = m[1] - 0.3 * sin(ang + tilt);
        d[0] = m[0] + 0.4 * cos(ang + tilt), d[1] = m[1] + 0.4 * sin(ang + tilt);
        if (!(cvm__orient2d(a, b, c) * cvm__orient2d(a, b, d) < 0.0
              && cvm__orient2d(c, d, a) * cvm__orient2d(c, d, b) < 0.0))
            continue; /* only proper crossings are in the contract */
        cvm__segment_intersection2d(a, b, c, d, o);
        ck_assert(in_box(o, a, b));
        ck_assert(in_box(o, c, d));
        tested++;
    }
    ck_assert_int_gt(tested, 10000);
}
END_TEST

TCase *geom_construct_tcase(void)
{
    TCase *tc = tcase_create("construct");
    tcase_add_test(tc, circumcenter_is_exact_when_representable);
    tcase_add_test(tc, circumcenter_is_equidistant_on_random_triangles);
    tcase_add_test(tc, segment_intersection_exact_cases);
    tcase_add_test(tc, segment_intersection_stays_in_both_boxes);
    return tc;
}
