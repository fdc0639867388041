/* test_read.c - the 3D surface readers on the generated surfaces: counts, markers, holes, regions and volumes agree across .off, .stl and .poly. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "surface3/surface3_tests.h"

typedef struct expect {
    const char *name;
    size_t np, nt;
    int nmark;         /* distinct markers in .stl and .poly */
    size_t nholes, nregions;
} expect;

static const expect k_surf[] = {
    {"cube", 386, 768, 1, 0, 1},
    {"sphere_in_box", 2948, 5888, 2, 1, 1},
    {"wing_slab", 1586, 3164, 2, 1, 1},
    {"tetra", 4, 4, 1, 0, 1},
    {"two_cubes", 12, 22, 2, 0, 2},
};

static int max_marker(const cvm__surf3 *s)
{
    size_t f;
    int m = 0;
    for (f = 0; f < s->nfacet; f++)
        m = s->fmark[f] > m ? s->fmark[f] : m;
    return m;
}

/* Every surface reads from .off, .stl and .poly with the same counts and the same volume. */
START_TEST(readers_agree_on_every_generated_surface)
{
    const expect *e = &k_surf[_i];
    static const char *ext[] = {".off", ".stl", ".poly"};
    double vol[3];
    int k;
    for (k = 0; k < 3; k++) {
        cvm__ctx ctx;
        cvm__surf3 s;
        char name[64];
        cvm__ctx_init_default(&ctx);
        snprintf(name, sizeof name, "%s%s", e->name, ext[k]);
        s3test_read(&ctx, name, &s);
        ck_assert_uint_eq(s.np, e->np);
        ck_assert_uint_eq(s.npoly, e->nt);
        ck_assert_uint_eq(s.nfacet, e->nt);
        ck_assert_int_eq(s.poff[s.npoly], (int32_t)(3 * e->nt));
        ck_assert_int_eq(max_marker(&s), k == 0 ? 1 : e->nmark);
        ck_assert_uint_eq(s.nholes, k == 2 ? e->nholes : 0);
        ck_assert_uint_eq(s.nregions, k == 2 ? e->nregions : 0);
        ck_assert_int_eq(s.point_base, k == 2 ? 1 : 0);
        vol[k] = s3test_volume(&s);
        cvm__surf3_free(&ctx, &s);
    }
    /* the same triangles in the same order: the same floating-point sums */
    ck_assert_double_eq(vol[0], vol[1]);
    ck_assert_double_eq(vol[0], vol[2]);
}
END_TEST

START_TEST(volumes_are_the_enclosed_volumes)
{
    cvm__ctx ctx;
    cvm__surf3 s;
    double v, ball = 4.0 / 3.0 * 3.14159265358979323846 * 0.125;
    cvm__ctx_init_default(&ctx);
    s3test_read(&ctx, "cube.off", &s);
    ck_assert_double_eq_tol(s3test_volume(&s), 1.0, 1e-13);
    cvm__surf3_free(&ctx, &s);
    s3test_read(&ctx, "tetra.poly", &s);
    ck_assert_double_eq_tol(s3test_volume(&s), 8.0 / 3.0, 1e-13);
    cvm__surf3_free(&ctx, &s);
    /* box minus an inscribed icosphere: a little more than 64 - the ball */
    s3test_read(&ctx, "sphere_in_box.stl", &s);
    v = s3test_volume(&s);
    ck_assert(v > 64.0 - ball && v < 64.0 - 0.99 * ball);
    cvm__surf3_free(&ctx, &s);
}
END_TEST

/* Binary STL: float coordinates, vertices merged exactly, the same surface as the ASCII cube. */
START_TEST(binary_stl_merges_vertices_like_ascii)
{
    cvm__ctx ctx;
    cvm__surf3 a, b;
    size_t i;
    cvm__ctx_init_default(&ctx);
    s3test_read(&ctx, "cube.stl", &a);
    s3test_read(&ctx, "cube_binary.stl", &b);
    ck_assert_uint_eq(a.np, b.np);
    ck_assert_uint_eq(a.npoly, b.npoly);
    ck_assert_int_eq(b.points_numbered, 0);
    ck_assert_int_eq(b.facet_base, 1);
    for (i = 0; i < 3 * a.np; i++)
        ck_assert_double_eq(a.xyz[i], b.xyz[i]);
    for (i = 0; i < 3 * a.npoly; i++)
        ck_assert_int_eq(a.pidx[i], b.pidx[i]);
    cvm__surf3_free(&ctx, &a);
    cvm__surf3_free(&ctx, &b);
}
END_TEST

START_TEST(stl_solids_are_markers_and_minus_zero_merges)
{
    cvm__ctx ctx;
    cvm__surf3 s;
    const char *text = "solid a\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
                       "endloop\nendfacet\nendsolid a\nsolid b\n  facet normal 1 0 0\n outer loop\n"
                       "vertex -0 0 0\nvertex 0 1 0\nvertex 0 0 1\nendloop\nendfacet\nendsolid\n";
    cvm__ctx_init_default(&ctx);
    ck_assert_int_eq(s3test_parse(&ctx, "t.stl", text, 0, &s), CVM_OK);
    ck_assert_uint_eq(s.np, 4);
    ck_assert_uint_eq(s.nfacet, 2);
    ck_assert_int_eq(s.fmark[0], 1);
    ck_assert_int_eq(s.fmark[1], 2);
    ck_assert_int_eq(s.pidx[3], 0);
    ck_assert_int_eq(s.pidx[4], 2);
    cvm__surf3_free(&ctx, &s);
}
END_TEST

/* TetGen .poly with polygons, facet holes, 0-based numbering and regions without max volume. */
START_TEST(tetpoly_reads_polygons_facet_holes_and_regions)
{
    cvm__ctx ctx;
    cvm__surf3 s;
    const char *text = "# a square facet with a hole, and a triangle\n4 3 0 1\n0 0 0 0 5\n1 1 0 0 5\n"
                       "2 1 1 0 5\n3 0 1 0 5\n2 1\n2 1 7\n4 0 1 2 3\n3 0 1 2\n1 0.5 0.5 0\n1 0 -3\n"
                       "3 0 1 3\n1\n1 0 0 9\n2\n1 .2 .2 .2 4\n2 .3 .3 .3 5 0.01\n";
    cvm__ctx_init_default(&ctx);
    ck_assert_msg(s3test_parse(&ctx, "t.poly", text, 0, &s) == CVM_OK, "%s", ctx.errmsg);
    ck_assert_uint_eq(s.np, 4);
    ck_assert_uint_eq(s.nfacet, 2);
    ck_assert_uint_eq(s.npoly, 3);
    ck_assert_int_eq(s.pfacet[1], 0);
    ck_assert_int_eq(s.pfacet[2], 1);
    ck_assert_int_eq(s.fmark[0], 7);
    ck_assert_int_eq(s.fmark[1], -3);
    ck_assert_int_eq(s.fhole_off[1], 1);
    ck_assert_int_eq(s.fhole_off[2], 1);
    ck_assert_double_eq(s.fhole[0], 0.5);
    ck_assert_uint_eq(s.nholes, 1);
    ck_assert_double_eq(s.holes[2], 9.0);
    ck_assert_uint_eq(s.nregions, 2);
    ck_assert_double_eq(s.regions[3], 4.0);
    ck_assert_double_eq(s.regions[4], -1.0);
    ck_assert_double_eq(s.regions[9], 0.01);
    ck_assert_int_eq(s.point_base, 0);
    cvm__surf3_free(&ctx, &s);
}
END_TEST

START_TEST(smesh_and_poly_give_the_same_surface)
{
    static const char *names[] = {"tetra", "two_cubes"};
    cvm__ctx ctx;
    cvm__surf3 a, b;
    char n1[64], n2[64];
    size_t i;
    cvm__ctx_init_default(&ctx);
    snprintf(n1, sizeof n1, "%s.poly", names[_i]);
    snprintf(n2, sizeof n2, "%s.smesh", names[_i]);
    s3test_read(&ctx, n1, &a);
    s3test_read(&ctx, n2, &b);
    ck_assert_uint_eq(a.npoly, b.npoly);
    for (i = 0; i < 3 * a.npoly; i++)
        ck_assert_int_eq(a.pidx[i], b.pidx[i]);
    for (i = 0; i < a.nfacet; i++)
        ck_assert_int_eq(a.fmark[i], b.fmark[i]);
    ck_assert_uint_eq(a.nregions, b.nregions);
    cvm__surf3_free(&ctx, &a);
    cvm__surf3_free(&ctx, &b);
}
END_TEST

START_TEST(off_accepts_counts_on_the_keyword_line_and_colours)
{
    cvm__ctx ctx;
    cvm__surf3 s;
    const char *text = "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 255 0 0\n";
    cvm__ctx_init_default(&ctx);
    ck_assert_int_eq(s3test_parse(&ctx, "t.off", text, 0, &s), CVM_OK);
    ck_assert_uint_eq(s.npoly, 1);
    ck_assert_int_eq(s.fmark[0], 1);
    cvm__surf3_free(&ctx, &s);
}
END_TEST

TCase *surface3_read_tcase(void)
{
    TCase *tc = tcase_create("read");
    tcase_set_timeout(tc, 60);
    tcase_add_loop_test(tc, readers_agree_on_every_generated_surface, 0,
                        (int)(sizeof k_surf / sizeof k_surf[0]));
    tcase_add_test(tc, volumes_are_the_enclosed_volumes);
    tcase_add_test(tc, binary_stl_merges_vertices_like_ascii);
    tcase_add_test(tc, stl_solids_are_markers_and_minus_zero_merges);
    tcase_add_test(tc, tetpoly_reads_polygons_facet_holes_and_regions);
    tcase_add_loop_test(tc, smesh_and_poly_give_the_same_surface, 0, 2);
    tcase_add_test(tc, off_accepts_counts_on_the_keyword_line_and_colours);
    return tc;
}
