/* test_regions.c - regional maximum areas in the refiners, and regional attributes kept through refinement. */
#include <math.h>
#include <stdlib.h>

#include "refine/refine_tests.h"

/* Unit square cut at x = 0.5: region 1 (left, attribute 1) and region 2
 * (right, attribute 2) with the given maximum areas. */
static cvm_mesh *two_regions(double left_area, double right_area)
{
    static const double xy[] = {0, 0, 0.5, 0, 1, 0, 1, 1, 0.5, 1, 0, 1};
    static const cvm_index seg[] = {0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 0, 1, 4};
    double reg[8];
    cvm_mesh *m;
    reg[0] = 0.25, reg[1] = 0.5, reg[2] = 1, reg[3] = left_area;
    reg[4] = 0.75, reg[5] = 0.5, reg[6] = 2, reg[7] = right_area;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 6, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, seg, 7), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_regions(m, reg, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    return m;
}

/* Largest triangle area and triangle count on each side of x = 0.5, and
 * that each side carries its region's attribute. */
static void sides(cvm_mesh *m, double *amax, size_t *count)
{
    double *xy, *attr;
    cvm_index *tri;
    size_t nv, nt, t;
    rtest_fetch(m, &xy, &nv, &tri, &nt);
    attr = malloc((nt + 1) * sizeof *attr);
    ck_assert_int_eq(cvm_mesh_copy_triangle_attributes(attr, nt, m), CVM_OK);
    amax[0] = amax[1] = 0;
    count[0] = count[1] = 0;
    for (t = 0; t < nt; t++) {
        const double *a = xy + 2 * tri[3 * t], *b = xy + 2 * tri[3 * t + 1], *c = xy + 2 * tri[3 * t + 2];
        double ar = 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
        int side = (a[0] + b[0] + c[0]) / 3 > 0.5;
        ck_assert(ar > 0);
        ck_assert_double_eq(attr[t], side ? 2.0 : 1.0);
        if (ar > amax[side])
            amax[side] = ar;
        count[side]++;
    }
    free(xy);
    free(tri);
    free(attr);
}

START_TEST(each_region_meets_its_area)
{
    int algo;
    for (algo = CVM_ALGO_DELAUNAY; algo <= CVM_ALGO_AFLR; algo++) {
        cvm_mesh *m = two_regions(0.001, 0.01);
        double amax[2];
        size_t count[2];
        ck_assert_int_eq(cvm_mesh_refine(m, NULL, (cvm_algorithm)algo), CVM_OK);
        ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
        sides(m, amax, count);
        ck_assert(amax[0] <= 0.001 * (1 + 1e-12));
        ck_assert(amax[1] <= 0.01 * (1 + 1e-12));
        ck_assert(amax[1] > 0.001);          /* the right side stays coarser */
        ck_assert_uint_gt(count[0], 3 * count[1]);
        cvm_mesh_free(m);
    }
}
END_TEST

START_TEST(global_area_caps_every_region)
{
    cvm_mesh *m = two_regions(0.01, 0);
    double amax[2];
    size_t count[2];
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_MAX_AREA, 0.002), CVM_OK);
    ck_assert_int_eq(cvm_mesh_refine(m, NULL, CVM_ALGO_DELAUNAY), CVM_OK);
    sides(m, amax, count);
    ck_assert(amax[0] <= 0.002 * (1 + 1e-12));
    ck_assert(amax[1] <= 0.002 * (1 + 1e-12));
    cvm_mesh_free(m);
}
END_TEST

TCase *refine_regions_tcase(void)
{
    TCase *tc = tcase_create("regions");
    tcase_add_test(tc, each_region_meets_its_area);
    tcase_add_test(tc, global_area_caps_every_region);
    return tc;
}
