/* test_validate.c - surface validation: the generated surfaces pass; open, flipped, self-intersecting, degenerate and non-manifold surfaces fail with their status and a message naming the faces; out of memory at every allocation. */
#include <stdlib.h>
#include <string.h>

#include "geom/geom_internal.h"
#include "surface3/surface3_tests.h"

#define TET_PTS "1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n"

typedef struct bad_surface {
    const char *what, *off;
    cvm_status status;
    const char *msg1, *msg2;
} bad_surface;

static const bad_surface k_bad[] = {
    {"open", "OFF\n4 3 0\n" TET_PTS "3 0 1 2\n3 0 2 3\n3 0 3 1\n", CVM_E_INPUT_NOT_CLOSED,
     "belongs to one face only", "face 0 (points 0, 1, 2)"},
    {"flipped face", "OFF\n4 4 0\n" TET_PTS "3 0 1 2\n3 0 2 3\n3 0 3 1\n3 1 2 3\n", CVM_E_INPUT_NOT_CLOSED,
     "flipped", "face 3 (points 1, 2, 3)"},
    {"self-intersecting pair",
     "OFF\n8 8 0\n" TET_PTS "1.5 1 1\n1.5 -1 -1\n-0.5 1 -1\n-0.5 -1 1\n3 0 1 2\n3 0 2 3\n3 0 3 1\n3 1 3 2\n"
     "3 4 5 6\n3 4 6 7\n3 4 7 5\n3 5 7 6\n", CVM_E_INPUT_INTERSECTING, "intersect", "face 0 (points 0, 1, 2)"},
    {"degenerate face", "OFF\n4 4 0\n0 0 0\n1 0 0\n2 0 0\n0 1 0\n3 0 1 2\n3 0 2 3\n3 0 3 1\n3 1 3 2\n",
     CVM_E_INPUT_DEGENERATE, "face 0 (points 0, 1, 2)", "collinear"},
    {"repeated corner", "OFF\n4 4 0\n" TET_PTS "3 0 1 1\n3 0 2 3\n3 0 3 1\n3 1 3 2\n", CVM_E_INPUT_DEGENERATE,
     "face 0", "the same point"},
    {"non-manifold edge",
     "OFF\n6 8 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n0 -1 0\n0 0 -1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"
     "3 0 1 4\n3 0 5 1\n3 0 4 5\n3 1 5 4\n", CVM_E_INPUT_INTERSECTING, "non-manifold edge",
     "between points 0 and 1"},
    {"non-manifold vertex",
     "OFF\n7 8 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n-1 0 0\n0 -1 0\n0 0 -1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"
     "3 0 5 4\n3 0 4 6\n3 0 6 5\n3 4 5 6\n", CVM_E_INPUT_INTERSECTING, "point 0 is a non-manifold vertex",
     "face 4"},
    {"non-convex polygon", "OFF\n5 1 0\n0 0 0\n2 0 0\n2 2 0\n1 0.5 0\n0 2 0\n5 0 1 2 3 4\n", CVM_E_UNSUPPORTED,
     "face 0", "not strictly convex"},
    {"non-planar polygon", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 1e-12\n4 0 1 2 3\n", CVM_E_INPUT_DEGENERATE,
     "face 0", "not planar"},
};

START_TEST(bad_surfaces_are_named)
{
    const bad_surface *c = &k_bad[_i];
    cvmtest_alloc a;
    cvm__ctx ctx;
    cvm__surf3 s;
    cvm__surf3_tris t;
    cvm_status st;
    cvmtest_alloc_init(&a, 0, 0);
    s3test_ctx(&ctx, &a);
    ck_assert_int_eq(s3test_parse(&ctx, "bad.off", c->off, 0, &s), CVM_OK);
    st = cvm__surf3_validate(&ctx, &s, 0, &t);
    ck_assert_msg(st == c->status, "%s: status %d, expected %d (%s)", c->what, (int)st, (int)c->status,
                  ctx.errmsg);
    ck_assert_msg(strstr(ctx.errmsg, "bad.off: ") && strstr(ctx.errmsg, c->msg1) && strstr(ctx.errmsg, c->msg2),
                  "%s: '%s'", c->what, ctx.errmsg);
    ck_assert_ptr_null(t.tri);
    cvm__surf3_free(&ctx, &s);
    ck_assert_int_eq(a.live_blocks, 0);
}
END_TEST

/* A triangle pierced by another that shares no corner (general position). */
START_TEST(pair_tests_agree_with_hand_cases)
{
    static const double a[3] = {0, 0, 0}, b[3] = {4, 0, 0}, c[3] = {0, 4, 0};
    static const double d[3] = {1, 1, -1}, e[3] = {1, 1, 1}, f[3] = {5, 5, 1};
    static const double g[3] = {1, 1, 0}, h[3] = {1, 1, 5}, far[3] = {9, 9, 9};
    static const int32_t i0[3] = {0, 1, 2}, i1[3] = {3, 4, 5}, i2[3] = {0, 6, 7}, i3[3] = {0, 1, 8};
    /* pierced */
    ck_assert_int_eq(cvm__tri_tri_improper(a, b, c, d, e, f, i0, i1), 1);
    /* touching at one point without sharing it: g lies inside abc */
    ck_assert_int_eq(cvm__tri_tri_improper(a, b, c, g, h, far, i0, i1), 1);
    /* apart */
    ck_assert_int_eq(cvm__tri_tri_improper(a, b, c, h, far, f, i0, i1), 0);
    /* shared corner a, the other triangle standing up outside the angle: proper */
    {
        static const double p[3] = {-1, -1, 0}, q[3] = {-1, -1, 3};
        ck_assert_int_eq(cvm__tri_tri_improper(a, b, c, a, p, q, i0, i2), 0);
    }
    /* shared corner a, a side of the other inside abc's angle, in its plane: improper */
    {
        static const double p[3] = {1, 1, 0}, q[3] = {1, 1, 3};
        ck_assert_int_eq(cvm__tri_tri_improper(a, b, c, a, p, q, i0, i2), 1);
    }
    /* shared edge ab, folded onto the same side: improper; opposite side: proper */
    {
        static const double up[3] = {1, 2, 0}, down[3] = {1, -2, 0};
        ck_assert_int_eq(cvm__tri_tri_improper(a, b, c, a, b, up, i0, i3), 1);
        ck_assert_int_eq(cvm__tri_tri_improper(a, b, c, a, b, down, i0, i3), 0);
    }
}
END_TEST

START_TEST(generated_surfaces_are_valid)
{
    static const char *names[] = {"cube.off", "sphere_in_box.poly", "wing_slab.stl", "tetra.poly",
                                  "cube_binary.stl"};
    static const size_t shells[] = {1, 2, 2, 1, 1};
    cvm__ctx ctx;
    cvm__surf3 s;
    cvm__surf3_tris t;
    cvm__ctx_init_default(&ctx);
    s3test_read(&ctx, names[_i], &s);
    ck_assert_msg(cvm__surf3_validate(&ctx, &s, 0, &t) == CVM_OK, "%s: %s", names[_i], ctx.errmsg);
    ck_assert_uint_eq(t.nt, s.npoly);
    ck_assert_uint_eq(t.nshell, shells[_i]);
    cvm__surf3_tris_free(&ctx, &t);
    cvm__surf3_free(&ctx, &s);
}
END_TEST

/* two_cubes: three faces meet at the edges of the shared face. */
START_TEST(internal_facets_need_the_flag)
{
    cvm__ctx ctx;
    cvm__surf3 s;
    cvm__surf3_tris t;
    cvm__ctx_init_default(&ctx);
    s3test_read(&ctx, "two_cubes.poly", &s);
    ck_assert_int_eq(cvm__surf3_validate(&ctx, &s, 0, &t), CVM_E_INPUT_INTERSECTING);
    ck_assert_ptr_nonnull(strstr(ctx.errmsg, "non-manifold edge"));
    ck_assert_ptr_nonnull(strstr(ctx.errmsg, "facet "));
    ck_assert_int_eq(cvm__surf3_validate(&ctx, &s, CVM__SURF3_ALLOW_INTERNAL, &t), CVM_OK);
    ck_assert_uint_eq(t.nshell, 1);
    cvm__surf3_tris_free(&ctx, &t);
    cvm__surf3_free(&ctx, &s);
}
END_TEST

/* A convex quad facet is fanned into two triangles of the same orientation. */
START_TEST(convex_polygons_are_fanned)
{
    const char *text = "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                       "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";
    cvm__ctx ctx;
    cvm__surf3 s;
    cvm__surf3_tris t;
    size_t i;
    double v = 0;
    cvm__ctx_init_default(&ctx);
    ck_assert_int_eq(s3test_parse(&ctx, "box.off", text, 0, &s), CVM_OK);
    ck_assert_msg(cvm__surf3_validate(&ctx, &s, 0, &t) == CVM_OK, "%s", ctx.errmsg);
    ck_assert_uint_eq(t.nt, 12);
    for (i = 0; i < t.nt; i++) {
        static const double o[3] = {0.5, 0.5, 0.5};
        /* outward: the centre lies below every face (orient3d > 0) */
        ck_assert(cvm__orient3d(s.xyz + 3 * t.tri[3 * i], s.xyz + 3 * t.tri[3 * i + 1],
                                s.xyz + 3 * t.tri[3 * i + 2], o) > 0);
    }
    v = s3test_volume(&s);
    ck_assert_double_eq_tol(v, 1.0, 1e-15);
    cvm__surf3_tris_free(&ctx, &t);
    cvm__surf3_free(&ctx, &s);
}
END_TEST

START_TEST(validation_survives_out_of_memory)
{
    cvm__ctx ctx0;
    cvm__surf3 s;
    long i;
    cvm__ctx_init_default(&ctx0);
    s3test_read(&ctx0, "two_cubes.poly", &s);
    for (i = 1;; i++) {
        cvmtest_alloc a;
        cvm__ctx ctx;
        cvm__surf3_tris t;
        cvm_status st;
        cvmtest_alloc_init(&a, i, 0);
        s3test_ctx(&ctx, &a);
        st = cvm__surf3_validate(&ctx, &s, CVM__SURF3_ALLOW_INTERNAL, &t);
        if (a.n_failed == 0) {
            ck_assert_int_eq(st, CVM_OK);
            cvm__surf3_tris_free(&ctx, &t);
            ck_assert_int_eq(a.live_blocks, 0);
            ck_assert_int_gt(i, 4);
            break;
        }
        ck_assert_int_eq(st, CVM_E_NOMEM);
        ck_assert_int_eq(a.live_blocks, 0);
    }
    cvm__surf3_free(&ctx0, &s);
}
END_TEST

TCase *surface3_validate_tcase(void)
{
    TCase *tc = tcase_create("validate");
    tcase_set_timeout(tc, 60);
    tcase_add_loop_test(tc, bad_surfaces_are_named, 0, (int)(sizeof k_bad / sizeof k_bad[0]));
    tcase_add_test(tc, pair_tests_agree_with_hand_cases);
    tcase_add_loop_test(tc, generated_surfaces_are_valid, 0, 5);
    tcase_add_test(tc, internal_facets_need_the_flag);
    tcase_add_test(tc, convex_polygons_are_fanned);
    tcase_add_test(tc, validation_survives_out_of_memory);
    return tc;
}
