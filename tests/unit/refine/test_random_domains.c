/* test_random_domains.c - every refiner on random polygons with holes: terminates, keeps every segment, meets the bounds, reproducible. */
#include <math.h>
#include <stdlib.h>

#include "refine/refine_tests.h"
#include "support/mesh_oracle.h"

#define PI 3.14159265358979323846

typedef struct rdomain {
    double xy[2 * 64];
    cvm_index seg[2 * 64];
    double holes[2 * 3];
    size_t np, nseg, nholes;
    double area;
    double apex[2 * 64]; /* input vertices with an angle below 60 degrees */
    size_t napex;
} rdomain;

static double rnd(unsigned long *s)
{
    *s = *s * 6364136223846793005UL + 1442695040888963407UL;
    return (double)((*s >> 11) & ((1UL << 53) - 1)) / 9007199254740992.0;
}

/* A closed star-shaped loop of n vertices around (cx, cy) with radii in
 * [r0, r1], counter-clockwise (sign 1) or clockwise (-1); returns its signed area. */
static double add_loop(rdomain *d, double cx, double cy, double r0, double r1, size_t n, int sign,
                       unsigned long *s)
{
    size_t first = d->np, k;
    double area = 0;
    for (k = 0; k < n; k++) {
        double a = sign * 2 * PI * ((double)k + 0.3 * rnd(s)) / (double)n;
        double r = r0 + (r1 - r0) * rnd(s);
        d->xy[2 * d->np] = cx + r * cos(a);
        d->xy[2 * d->np + 1] = cy + r * sin(a);
        d->seg[2 * d->nseg] = (cvm_index)(first + k);
        d->seg[2 * d->nseg + 1] = (cvm_index)(first + (k + 1) % n);
        d->np++;
        d->nseg++;
    }
    for (k = 0; k < n; k++) {
        const double *p = d->xy + 2 * (first + k), *q = d->xy + 2 * (first + (k + 1) % n);
        const double *o = d->xy + 2 * (first + (k + n - 1) % n);
        double ux = o[0] - p[0], uy = o[1] - p[1], wx = q[0] - p[0], wy = q[1] - p[1];
        double ang = atan2(fabs(ux * wy - uy * wx), ux * wx + uy * wy) * 180 / PI;
        area += 0.5 * (p[0] * q[1] - q[0] * p[1]);
        if (ang < 60) {
            d->apex[2 * d->napex] = p[0];
            d->apex[2 * d->napex + 1] = p[1];
            d->napex++;
        }
    }
    return area;
}

/* Outer loop of radius 0.7..1 with 12-20 vertices and 1-3 holes of radius
 * 0.05..0.12 centred on a circle of radius 0.4, far enough apart. */
static void make_domain(rdomain *d, unsigned long seed)
{
    unsigned long s = seed * 2654435761UL + 1;
    size_t k;
    double phase;
    d->np = d->nseg = d->nholes = d->napex = 0;
    d->area = add_loop(d, 0, 0, 0.7, 1.0, 12 + (size_t)(9 * rnd(&s)), 1, &s);
    d->nholes = 1 + (size_t)(3 * rnd(&s));
    phase = 2 * PI * rnd(&s);
    for (k = 0; k < d->nholes; k++) {
        double a = phase + 2 * PI * (double)k / (double)d->nholes;
        double cx = 0.4 * cos(a), cy = 0.4 * sin(a);
        d->area += add_loop(d, cx, cy, 0.05, 0.12, 5 + (size_t)(4 * rnd(&s)), -1, &s);
        d->holes[2 * k] = cx;
        d->holes[2 * k + 1] = cy;
    }
}

static cvm_mesh *refined(const rdomain *d, cvm_algorithm algo, double h, cvm_status *st)
{
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, d->xy, d->np, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, d->seg, d->nseg), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_holes(m, d->holes, d->nholes), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    *st = rtest_refine_uniform(m, h, algo);
    return m;
}

static void check_algo(cvm_algorithm algo)
{
    unsigned long seed;
    for (seed = 1; seed <= 6; seed++) {
        rdomain d;
        cvm_mesh *m, *m2;
        cvm_status st;
        cvmtest_expect e;
        rtest_quality q;
        const double h = 0.06;
        make_domain(&d, seed);
        m = refined(&d, algo, h, &st);
        ck_assert_msg(st == CVM_OK, "seed %lu: %s", seed, cvm_mesh_errmsg(m));
        cvmtest_expect_init(&e);
        e.segs = d.seg;
        e.nseg = d.nseg;
        e.check_euler = 1;
        e.euler = 1 - (long)d.nholes;
        e.check_area = 1;
        e.area = d.area;
        e.area_rel_tol = 1e-9;
        cvmtest_assert_valid_ex(m, &e);
        rtest_measure(m, &q);
        ck_assert_msg(q.max_circumradius <= h * (1 + 1e-9), "seed %lu: circumradius %g > %g", seed,
                      q.max_circumradius, h);
        /* 30 degrees everywhere except beside input angles below 60 */
        ck_assert_msg(rtest_min_angle_away(m, d.apex, d.napex, 2 * h) >= 30 - 1e-9,
                      "seed %lu: angle below 30 away from small input angles", seed);
        m2 = refined(&d, algo, h, &st);
        ck_assert_int_eq(st, CVM_OK);
        rtest_assert_identical(m, m2);
        cvm_mesh_free(m2);
        cvm_mesh_free(m);
    }
}

START_TEST(delaunay_on_random_polygons_with_holes)
{
    check_algo(CVM_ALGO_DELAUNAY);
}
END_TEST

START_TEST(frontal_on_random_polygons_with_holes)
{
    check_algo(CVM_ALGO_FRONTAL);
}
END_TEST

START_TEST(aflr_on_random_polygons_with_holes)
{
    check_algo(CVM_ALGO_AFLR);
}
END_TEST

TCase *refine_random_domains_tcase(void)
{
    TCase *tc = tcase_create("random_domains");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, delaunay_on_random_polygons_with_holes);
    tcase_add_test(tc, frontal_on_random_polygons_with_holes);
    tcase_add_test(tc, aflr_on_random_polygons_with_holes);
    return tc;
}
