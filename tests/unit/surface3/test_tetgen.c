/* test_tetgen.c - boundary recovery through TetGen: every input triangle is a boundary face, every tetrahedron is positive by the exact orient3d, the volumes add up, regions keep their attributes; a build without TetGen says so. */
#include <stdlib.h>
#include <string.h>

#include "geom/geom_internal.h"
#include "surface3/surface3_tests.h"
#include "tetgen/tetgen_shim.h"
#include "support/skip.h"

static int cmp3(const void *pa, const void *pb)
{
    const int32_t *a = (const int32_t *)pa, *b = (const int32_t *)pb;
    int k;
    for (k = 0; k < 3; k++)
        if (a[k] != b[k])
            return a[k] < b[k] ? -1 : 1;
    return 0;
}

static void sort3(int32_t *t)
{
    int32_t x;
    if (t[0] > t[1]) x = t[0], t[0] = t[1], t[1] = x;
    if (t[1] > t[2]) x = t[1], t[1] = t[2], t[2] = x;
    if (t[0] > t[1]) x = t[0], t[0] = t[1], t[1] = x;
}

/* The sorted corner triples of n triangles. */
static int32_t *sorted_triples(const int32_t *tri, size_t n)
{
    int32_t *c = malloc((n ? n : 1) * 3 * sizeof *c);
    size_t i;
    ck_assert_ptr_nonnull(c);
    memcpy(c, tri, n * 3 * sizeof *c);
    for (i = 0; i < n; i++)
        sort3(c + 3 * i);
    qsort(c, n, 3 * sizeof *c, cmp3);
    return c;
}

static double tet_volume(const cvm__tet3_out *o, size_t i)
{
    const double *a = o->xyz + 3 * o->tet[4 * i], *b = o->xyz + 3 * o->tet[4 * i + 1],
                 *c = o->xyz + 3 * o->tet[4 * i + 2], *d = o->xyz + 3 * o->tet[4 * i + 3];
    double ax = a[0] - d[0], ay = a[1] - d[1], az = a[2] - d[2], bx = b[0] - d[0], by = b[1] - d[1],
           bz = b[2] - d[2], cx = c[0] - d[0], cy = c[1] - d[1], cz = c[2] - d[2];
    return (ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx)) / 6.0;
}

typedef struct recovery_case {
    const char *file;
    double volume;   /* enclosed volume; 0: the surface's signed volume */
} recovery_case;

static const recovery_case k_cases[] = {
    {"cube.poly", 1.0}, {"sphere_in_box.poly", 0.0}, {"wing_slab.poly", 0.0}, {"two_cubes.poly", 2.0},
    {"cube.stl", 1.0},
};

START_TEST(recovery_keeps_every_input_triangle)
{
    const recovery_case *c = &k_cases[_i];
    cvmtest_alloc a;
    cvm__ctx ctx;
    cvm__surf3 s;
    cvm__surf3_tris t;
    cvm__tet3_out o;
    int32_t *want, *got;
    double vol = 0.0, want_vol;
    size_t i;
    cvm_status st;
    if (!cvm__tetgen_available())
        CVMTEST_SKIP("needs TetGen (a TETGEN=1 build)");
    cvmtest_alloc_init(&a, 0, 0);
    s3test_ctx(&ctx, &a);
    s3test_read(&ctx, c->file, &s);
    ck_assert_int_eq(cvm__surf3_validate(&ctx, &s, s.nregions > 1 ? CVM__SURF3_ALLOW_INTERNAL : 0, &t), CVM_OK);
    st = cvm__tetgen_recover(&ctx, &s, &o);
    ck_assert_msg(st == CVM_OK, "%s: %s", c->file, ctx.errmsg);
    /* points: the input first, then the Steiner points, all counted */
    ck_assert_uint_eq(o.n_input, s.np);
    ck_assert_int_eq(memcmp(o.xyz, s.xyz, 3 * s.np * sizeof(double)), 0);
    ck_assert_uint_eq(o.n_steiner_boundary + o.n_steiner_interior, o.np - o.n_input);
    /* the boundary was kept: the boundary faces are exactly the input triangles */
    ck_assert_int_eq(o.boundary_kept, 1);
    ck_assert_uint_eq(o.n_steiner_boundary, 0);
    ck_assert_uint_eq(o.nface, t.nt);
    want = sorted_triples(t.tri, t.nt);
    got = sorted_triples(o.face, o.nface);
    ck_assert_int_eq(memcmp(want, got, 3 * t.nt * sizeof(int32_t)), 0);
    free(want);
    free(got);
    /* markers follow their facets: every face carries a marker of the input */
    for (i = 0; i < o.nface; i++)
        ck_assert(o.fmark[i] >= 1 && o.fmark[i] <= 2);
    /* positive tetrahedra whose volumes add up to the enclosed volume */
    for (i = 0; i < o.ntet; i++) {
        ck_assert(cvm__orient3d(o.xyz + 3 * o.tet[4 * i], o.xyz + 3 * o.tet[4 * i + 1],
                                o.xyz + 3 * o.tet[4 * i + 2], o.xyz + 3 * o.tet[4 * i + 3]) > 0);
        vol += tet_volume(&o, i);
    }
    want_vol = c->volume > 0 ? c->volume : s3test_volume(&s);
    ck_assert_msg(vol > want_vol * (1 - 1e-12) && vol < want_vol * (1 + 1e-12), "%s: volume %.17g, expected %.17g",
                  c->file, vol, want_vol);
    cvm__tet3_out_free(&ctx, &o);
    cvm__surf3_tris_free(&ctx, &t);
    cvm__surf3_free(&ctx, &s);
    ck_assert_int_eq(a.live_blocks, 0);
}
END_TEST

/* two_cubes: attribute 1 on the left cube, 2 on the right, each of volume 1. */
START_TEST(regions_keep_their_attributes)
{
    cvm__ctx ctx;
    cvm__surf3 s;
    cvm__tet3_out o;
    double v[3] = {0, 0, 0};
    size_t i;
    if (!cvm__tetgen_available())
        CVMTEST_SKIP("needs TetGen (a TETGEN=1 build)");
    cvm__ctx_init_default(&ctx);
    s3test_read(&ctx, "two_cubes.poly", &s);
    ck_assert_msg(cvm__tetgen_recover(&ctx, &s, &o) == CVM_OK, "%s", ctx.errmsg);
    ck_assert_ptr_nonnull(o.tattr);
    for (i = 0; i < o.ntet; i++) {
        int k, attr = (int)o.tattr[i];
        double cx = 0;
        ck_assert(o.tattr[i] == 1.0 || o.tattr[i] == 2.0);
        for (k = 0; k < 4; k++)
            cx += o.xyz[3 * o.tet[4 * i + k]] / 4;
        ck_assert(attr == 1 ? cx < 1.0 : cx > 1.0);
        v[attr] += tet_volume(&o, i);
    }
    ck_assert_double_eq_tol(v[1], 1.0, 1e-14);
    ck_assert_double_eq_tol(v[2], 1.0, 1e-14);
    cvm__tet3_out_free(&ctx, &o);
    cvm__surf3_free(&ctx, &s);
}
END_TEST

START_TEST(build_without_tetgen_says_so)
{
    cvm__ctx ctx;
    cvm__surf3 s;
    cvm__tet3_out o;
    if (cvm__tetgen_available())
        CVMTEST_SKIP("tests the TETGEN=0 build");
    cvm__ctx_init_default(&ctx);
    s3test_read(&ctx, "tetra.poly", &s);
    ck_assert_int_eq(cvm__tetgen_recover(&ctx, &s, &o), CVM_E_UNSUPPORTED);
    ck_assert_ptr_nonnull(strstr(ctx.errmsg, "TetGen"));
    ck_assert_ptr_null(o.tet);
    cvm__surf3_free(&ctx, &s);
}
END_TEST

/* Allocation i of the copy out fails: CVM_E_NOMEM, nothing leaked. */
START_TEST(recovery_survives_out_of_memory)
{
    cvm__ctx ctx0;
    cvm__surf3 s;
    long i;
    if (!cvm__tetgen_available())
        CVMTEST_SKIP("needs TetGen (a TETGEN=1 build)");
    cvm__ctx_init_default(&ctx0);
    s3test_read(&ctx0, "tetra.poly", &s);
    for (i = 1;; i++) {
        cvmtest_alloc a;
        cvm__ctx ctx;
        cvm__tet3_out o;
        cvm_status st;
        cvmtest_alloc_init(&a, i, 1);
        s3test_ctx(&ctx, &a);
        st = cvm__tetgen_recover(&ctx, &s, &o);
        if (a.n_failed == 0) {
            ck_assert_int_eq(st, CVM_OK);
            ck_assert_uint_eq(o.ntet, 1);
            cvm__tet3_out_free(&ctx, &o);
            ck_assert_int_eq(a.live_blocks, 0);
            break;
        }
        ck_assert_int_eq(st, CVM_E_NOMEM);
        ck_assert_int_eq(a.live_blocks, 0);
    }
    cvm__surf3_free(&ctx0, &s);
}
END_TEST

TCase *surface3_tetgen_tcase(void)
{
    TCase *tc = tcase_create("tetgen");
    tcase_set_timeout(tc, 120);
    tcase_add_loop_test(tc, recovery_keeps_every_input_triangle, 0, (int)(sizeof k_cases / sizeof k_cases[0]));
    tcase_add_test(tc, regions_keep_their_attributes);
    tcase_add_test(tc, build_without_tetgen_says_so);
    tcase_add_test(tc, recovery_survives_out_of_memory);
    return tc;
}
