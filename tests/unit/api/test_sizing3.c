/* test_sizing3.c - the sizing handle in 3D (lib/sizing/sizing3.c, sizing_background3.c): each
 * source's size at points where it has a closed form, the triangle source in 2D, errors that
 * name the source, one dimension per handle, atomic failures. */
#include <math.h>
#include <string.h>

#include "api/api_tests.h"
#include "cvmesh.h"

static double eval3(cvm_sizing *s, double x, double y, double z)
{
    double p[3], h = -1;
    p[0] = x;
    p[1] = y;
    p[2] = z;
    ck_assert_msg(cvm_sizing_eval_nd(&h, s, p, 3) == CVM_OK, "%s", cvm_sizing_errmsg(s));
    return h;
}

START_TEST(point_line_and_triangle_sources_in_3d)
{
    static const double p[] = {1, 2, 3}, ends[] = {0, 0, 0, 2, 0, 0},
                        tri[] = {0, 0, 0, 4, 0, 0, 0, 4, 0},
                        flat[] = {0, 0, 0, 1, 0, 0, 2, 0, 0};
    cvm_sizing *s;
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_add_point_source_nd(s, p, 3, 0.1, 0.5), CVM_OK);
    ck_assert(eval3(s, 1, 2, 3) == 0.1);
    ck_assert(eval3(s, 4, 6, 3) == 0.1 + 0.5 * 5); /* a 3-4-5 distance */
    ck_assert(eval3(s, 1, 2, -2) == 0.1 + 0.5 * 5);
    cvm_sizing_free(s);

    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_add_line_source_nd(s, ends, 3, 0.2, 0.25), CVM_OK);
    ck_assert(eval3(s, 1, 3, 4) == 0.2 + 0.25 * 5);  /* beside the segment */
    ck_assert(eval3(s, 5, 4, 0) == 0.2 + 0.25 * 5);  /* beyond the end (2, 0, 0) */
    ck_assert(eval3(s, -3, 0, 4) == 0.2 + 0.25 * 5); /* beyond the start */
    ck_assert(eval3(s, 0.5, 0, 0) == 0.2);
    cvm_sizing_free(s);

    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_add_triangle_source_nd(s, tri, 3, 0.1, 0.5), CVM_OK);
    ck_assert(eval3(s, 1, 1, 0) == 0.1);            /* on the triangle */
    ck_assert(eval3(s, 1, 1, 3) == 0.1 + 0.5 * 3);  /* above its interior */
    ck_assert(eval3(s, 1, 1, -2) == 0.1 + 0.5 * 2); /* below */
    ck_assert(eval3(s, -3, -4, 0) == 0.1 + 0.5 * 5); /* nearest: the corner (0, 0, 0) */
    ck_assert(eval3(s, 2, -3, 4) == 0.1 + 0.5 * 5);  /* nearest: the edge y = 0 */
    /* nearest: the hypotenuse's midpoint (2, 2, 0), at distance sqrt(34) */
    ck_assert_double_eq_tol(eval3(s, 5, 5, 4), 0.1 + 0.5 * sqrt(34.0), 1e-14);
    cvm_sizing_free(s);

    /* collinear corners: the union of the edges, the segment (0,0,0)-(2,0,0) */
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_add_triangle_source_nd(s, flat, 3, 0.2, 0.25), CVM_OK);
    ck_assert(eval3(s, 1, 3, 4) == 0.2 + 0.25 * 5);
    ck_assert(eval3(s, 5, 4, 0) == 0.2 + 0.25 * 5);
    cvm_sizing_free(s);
}
END_TEST

START_TEST(sources_combine_by_the_minimum_in_3d)
{
    static const double a[] = {0, 0, 0}, b[] = {10, 0, 0};
    cvm_sizing *s;
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_add_point_source_nd(s, a, 3, 0.1, 0.5), CVM_OK);
    ck_assert_int_eq(cvm_sizing_add_point_source_nd(s, b, 3, 0.2, 0.5), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_uniform(s, 1.5), CVM_OK);
    ck_assert(eval3(s, 0, 3, 4) == 1.5); /* the point source gives 2.6: the uniform size */
    ck_assert(eval3(s, 0, 0, 1) == 0.1 + 0.5);
    ck_assert(eval3(s, 10, 0, 1) == 0.2 + 0.5);
    ck_assert(eval3(s, 2, 0, 0) == 0.1 + 0.5 * 2); /* 1.1 against 4.2 and 1.5 */
    ck_assert(eval3(s, 5, 30, 0) == 1.5);
    cvm_sizing_free(s);
}
END_TEST

START_TEST(triangle_source_in_2d)
{
    static const double tri[] = {0, 0, 4, 0, 0, 4};
    double h, x[2];
    cvm_sizing *s;
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_add_triangle_source_nd(s, tri, 2, 0.1, 0.5), CVM_OK);
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 1, 1), CVM_OK);
    ck_assert(h == 0.1); /* inside: the source's size */
    ck_assert_int_eq(cvm_sizing_eval(&h, s, -3, -4), CVM_OK);
    ck_assert(h == 0.1 + 0.5 * 5);
    x[0] = 2;
    x[1] = -3;
    ck_assert_int_eq(cvm_sizing_eval_nd(&h, s, x, 2), CVM_OK);
    ck_assert(h == 0.1 + 0.5 * 3);
    cvm_sizing_free(s);
}
END_TEST

typedef struct cb3 {
    int calls, bad_dim;
    double value;
} cb3;

static double size3(void *payload, const double *x, int dim)
{
    cb3 *c = payload;
    c->calls++;
    c->bad_dim += dim != 3;
    return c->value != 0 ? c->value : 0.25 + fabs(x[2]);
}

static double size_xy(void *payload, double x, double y)
{
    (void)payload;
    (void)x;
    (void)y;
    return 1;
}

START_TEST(callback_in_3d_gets_the_point_and_dim_3)
{
    cvm_sizing *s;
    cb3 c = {0, 0, 0};
    double h, x[3] = {1, 2, -0.5};
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_callback_nd(s, size3, &c), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_uniform(s, 0.5), CVM_OK);
    ck_assert(eval3(s, 1, 2, -0.125) == 0.375);
    ck_assert(eval3(s, 1, 2, 3) == 0.5);
    ck_assert_int_eq(c.calls, 2);
    ck_assert_int_eq(c.bad_dim, 0);
    c.value = -1;
    ck_assert_int_eq(cvm_sizing_eval_nd(&h, s, x, 3), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "sizing callback"));
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "-0.5"));
    c.value = NAN;
    ck_assert_int_eq(cvm_sizing_eval_nd(&h, s, x, 3), CVM_E_INPUT_NONFINITE);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "sizing callback"));
    /* a 2D callback cannot be asked in 3D */
    ck_assert_int_eq(cvm_sizing_set_callback(s, size_xy, NULL), CVM_OK);
    ck_assert_int_eq(cvm_sizing_eval_nd(&h, s, x, 3), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "cvm_sizing_set_callback_nd"));
    x[0] = NAN;
    ck_assert_int_eq(cvm_sizing_eval_nd(&h, s, x, 3), CVM_E_INPUT_NONFINITE);
    cvm_sizing_free(s);
}
END_TEST

START_TEST(background_tetrahedra_interpolate_linearly)
{
    /* one tetrahedron, sizes 1, 2, 3, 4 at its corners (the two orientations) */
    static const double xh[] = {0, 0, 0, 1, 1, 0, 0, 2, 0, 1, 0, 3, 0, 0, 1, 4};
    static const cvm_index tet[] = {0, 1, 2, 3}, tet_neg[] = {0, 2, 1, 3};
    static const cvm_index bad_index[] = {0, 1, 2, 4}, flat[] = {0, 1, 2, 0};
    double bad[16];
    cvm_sizing *s;
    int pass;
    for (pass = 0; pass < 2; pass++) {
        ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
        ck_assert_int_eq(cvm_sizing_set_background_nd(s, xh, 4, 3, pass ? tet_neg : tet, 1),
                         CVM_OK);
        ck_assert_double_eq_tol(eval3(s, 0.25, 0.25, 0.25), 2.5, 1e-13);
        ck_assert_double_eq_tol(eval3(s, 0.5, 0.25, 0.125), 2.375, 1e-13);
        ck_assert(eval3(s, 0, 0, 0) == 1);
        ck_assert(eval3(s, 0, 0, 1) == 4);
        ck_assert(isinf(eval3(s, 0.5, 0.5, 0.5))); /* outside the tetrahedron */
        ck_assert(isinf(eval3(s, 2, 2, 2)));
        cvm_sizing_free(s);
    }
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_background_nd(s, xh, 4, 3, bad_index, 1), CVM_E_INPUT_INDEX);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "tetrahedron 0"));
    ck_assert_int_eq(cvm_sizing_set_background_nd(s, xh, 4, 3, flat, 1), CVM_E_INPUT_DEGENERATE);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "tetrahedron 0"));
    memcpy(bad, xh, sizeof bad);
    bad[11] = -3;
    ck_assert_int_eq(cvm_sizing_set_background_nd(s, bad, 4, 3, tet, 1), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "node 2"));
    bad[11] = 3;
    bad[13] = INFINITY;
    ck_assert_int_eq(cvm_sizing_set_background_nd(s, bad, 4, 3, tet, 1), CVM_E_INPUT_NONFINITE);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "node 3"));
    ck_assert_int_eq(cvm_sizing_set_background_nd(s, xh, 4, 4, tet, 1), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_sizing_set_background_nd(s, NULL, 4, 3, tet, 1), CVM_E_NULL_ARG);
    /* nothing was installed by the failures; then set and removed again */
    ck_assert(isinf(eval3(s, 0.25, 0.25, 0.25)));
    ck_assert_int_eq(cvm_sizing_set_background_nd(s, xh, 4, 3, tet, 1), CVM_OK);
    ck_assert_double_eq_tol(eval3(s, 0.25, 0.25, 0.25), 2.5, 1e-13);
    ck_assert_int_eq(cvm_sizing_set_background_nd(s, NULL, 0, 3, NULL, 0), CVM_OK);
    ck_assert(isinf(eval3(s, 0.25, 0.25, 0.25)));
    /* with no source left the handle takes 2D sources again */
    ck_assert_int_eq(cvm_sizing_add_point_source(s, 0, 0, 1, 0), CVM_OK);
    cvm_sizing_free(s);
}
END_TEST

START_TEST(bad_sources_name_the_source_and_change_nothing)
{
    static const double p[] = {0, 0, 0}, tri[] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    double badp[3] = {0, NAN, 0}, badt[9], h;
    cvm_sizing *s;
    memcpy(badt, tri, sizeof badt);
    badt[7] = INFINITY;
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_add_point_source_nd(s, p, 3, 0.5, 0.1), CVM_OK);
    ck_assert_int_eq(cvm_sizing_add_point_source_nd(s, p, 3, -1, 0), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "point source 1"));
    ck_assert_int_eq(cvm_sizing_add_point_source_nd(s, p, 3, 0.1, -0.5), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "point source 1"));
    ck_assert_int_eq(cvm_sizing_add_point_source_nd(s, badp, 3, 0.1, 0), CVM_E_INPUT_NONFINITE);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "point source 1"));
    ck_assert_int_eq(cvm_sizing_add_point_source_nd(s, p, 3, INFINITY, 0), CVM_E_INPUT_NONFINITE);
    badt[4] = NAN; /* the second end of a line source */
    ck_assert_int_eq(cvm_sizing_add_line_source_nd(s, badt, 3, 0.1, 0), CVM_E_INPUT_NONFINITE);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "line source 0"));
    ck_assert_int_eq(cvm_sizing_add_triangle_source_nd(s, badt, 3, 0.1, 0), CVM_E_INPUT_NONFINITE);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "triangle source 0"));
    ck_assert_int_eq(cvm_sizing_add_triangle_source_nd(s, tri, 3, 0, 0), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "triangle source 0"));
    ck_assert_int_eq(cvm_sizing_add_triangle_source_nd(s, tri, 3, 0.1, NAN), CVM_E_INPUT_NONFINITE);
    ck_assert_int_eq(cvm_sizing_add_triangle_source_nd(s, tri, 4, 0.1, 0), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_sizing_add_triangle_source_nd(s, NULL, 3, 0.1, 0), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_sizing_add_triangle_source_nd(NULL, tri, 3, 0.1, 0), CVM_E_NULL_ARG);
    /* one dimension per handle: a 2D source after a 3D one, named with both */
    ck_assert_int_eq(cvm_sizing_add_point_source(s, 5, 5, 0.01, 0), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "point source 1"));
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "3D"));
    ck_assert_int_eq(cvm_sizing_add_triangle_source_nd(s, tri, 2, 0.01, 0), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "triangle source 0"));
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 0, 0), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_sizing_eval_nd(&h, s, p, 2), CVM_E_ARGUMENT);
    /* after every failure the handle holds the first source alone */
    ck_assert(eval3(s, 0, 0, 0) == 0.5);
    ck_assert(eval3(s, 0, 0, 10) == 0.5 + 0.1 * 10);
    ck_assert_str_eq(cvm_sizing_errmsg(s), "");
    cvm_sizing_free(s);
    /* and the other way: 2D first */
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_add_line_source(s, 0, 0, 1, 1, 0.5, 0), CVM_OK);
    ck_assert_int_eq(cvm_sizing_add_point_source_nd(s, p, 3, 0.1, 0), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "line source 0"));
    ck_assert_int_eq(cvm_sizing_eval_nd(&h, s, p, 3), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "2D"));
    cvm_sizing_free(s);
}
END_TEST

START_TEST(refine_refuses_a_3d_sizing)
{
    static const double xy[] = {0, 0, 1, 0, 1, 1, 0, 1}, p[] = {0, 0, 0};
    cvm_mesh *m;
    cvm_sizing *s;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 4, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_add_point_source_nd(s, p, 3, 0.1, 0.2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_refine(m, s, CVM_ALGO_DELAUNAY), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "3D sources"));
    ck_assert_int_eq(cvm_mesh_optimise_dual(m, s), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    cvm_sizing_free(s);
    cvm_mesh_free(m);
}
END_TEST

TCase *api_sizing3_tcase(void)
{
    TCase *tc = tcase_create("sizing3");
    tcase_add_test(tc, point_line_and_triangle_sources_in_3d);
    tcase_add_test(tc, sources_combine_by_the_minimum_in_3d);
    tcase_add_test(tc, triangle_source_in_2d);
    tcase_add_test(tc, callback_in_3d_gets_the_point_and_dim_3);
    tcase_add_test(tc, background_tetrahedra_interpolate_linearly);
    tcase_add_test(tc, bad_sources_name_the_source_and_change_nothing);
    tcase_add_test(tc, refine_refuses_a_3d_sizing);
    return tc;
}
