/*
 * test_generate3.c - cvm_mesh_generate3(): every status of its contract, the
 * sphere in a box (graded by the surface) meshed and conforming, the same
 * bytes for every run, seed and thread count, and OOM at every allocation.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "generate3/g3_util.h"
#include "generate3/generate3_tests.h"
#include "support/oom_sweep.h"
#include "support/skip.h"

static cvm_mesh *read3(const char *name)
{
    cvm_mesh *m;
    char path[1024];
    g3_data3d(path, sizeof path, name);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_msg(cvm_mesh_read(m, path) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    return m;
}

START_TEST(bad_sizes_name_the_size)
{
    cvm_mesh *m = read3("tetra.off");
    ck_assert_int_eq(cvm_mesh_generate3(m, 0), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "size"));
    ck_assert_int_eq(cvm_mesh_generate3(m, -1), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "size -1"));
    ck_assert_int_eq(cvm_mesh_generate3(m, NAN), CVM_E_INPUT_NONFINITE);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "size"));
    ck_assert_int_eq(cvm_mesh_generate3(m, INFINITY), CVM_E_INPUT_NONFINITE);
    ck_assert_int_eq(cvm_mesh_generate3(NULL, 1), CVM_E_NULL_ARG);
    /* 1e-300 against an extent of 2: more lattice cells than an axis can index */
    ck_assert_int_eq(cvm_mesh_generate3(m, 1e-300), CVM_E_TOO_LARGE);
    /* 1e-3: 1.6e10 lattice candidates, refused before any is visited */
    ck_assert_int_eq(cvm_mesh_generate3(m, 1e-3), CVM_E_TOO_LARGE);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "limit"));
    cvm_mesh_free(m);
}
END_TEST

START_TEST(options_and_states_are_checked)
{
    cvm_mesh *m;
    double xyz[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}, v;
    cvm_bounds b;
    ck_assert_int_eq(cvm_option_bounds(&b, CVM_OPT_GEN3_GRADING), CVM_OK);
    ck_assert_double_eq(b.def, 0.3);
    ck_assert_int_eq(cvm_option_bounds(&b, CVM_OPT_GEN3_LAYERS), CVM_OK);
    ck_assert_double_eq(b.def, 1);
    /* a 2D handle and a 3D point set hold no surface */
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_generate3(m, 1), CVM_E_STATE);
    ck_assert_int_eq(cvm_mesh_set_points(m, xyz, 4, 3), CVM_OK);
    ck_assert_int_eq(cvm_mesh_generate3(m, 1), CVM_E_STATE);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "surface"));
    /* before any run the report is 0 */
    ck_assert_int_eq(cvm_mesh_get_report(&v, m, CVM_REPORT_GEN3_LATTICE_POINTS), CVM_OK);
    ck_assert_double_eq(v, 0);
    cvm_mesh_free(m);
    m = read3("tetra.off");
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_GEN3_LAYERS, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_generate3(m, 1), CVM_E_UNSUPPORTED);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "unsupported"));
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_GEN3_LAYERS, 1), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_GEN3_GRADING, 0), CVM_E_OPTION_RANGE);
    cvm_mesh_free(m);
    /* internal facets (two regions sharing a face): not in this version */
    m = read3("two_cubes.poly");
    ck_assert_int_eq(cvm_mesh_generate3(m, 0.5), CVM_E_UNSUPPORTED);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "triangles"));
    cvm_mesh_free(m);
}
END_TEST

/* The tetrahedron meshes with or without TetGen: the input is kept, the
 * output is the generated mesh, and a later triangulate meshes the surface alone. */
START_TEST(tetra_meshes_in_every_build)
{
    cvm_mesh *m = read3("tetra.off");
    g3_mesh g;
    double v, lat;
    size_t i, n;
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_GEN3_SIZE_FROM_SURFACE, 0), CVM_OK);
    ck_assert_msg(cvm_mesh_generate3(m, 0.5) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_get_report(&lat, m, CVM_REPORT_GEN3_LATTICE_POINTS), CVM_OK);
    ck_assert_double_gt(lat, 10);
    g3_mesh_get(&g, m);
    ck_assert_uint_eq(g.nf, 4);
    ck_assert_uint_eq(g.nbnd, 4);
    for (i = 0; i < g.nf; i++)
        ck_assert(g3_face_on_boundary(&g, g.face[3 * i], g.face[3 * i + 1], g.face[3 * i + 2]));
    ck_assert_int_eq(g3_euler(&g), 1);
    ck_assert_int_eq(cvm_mesh_get_measure(&v, m, CVM_MEASURE_VOLUME), CVM_OK);
    ck_assert_double_eq_tol(v, 8.0 / 3.0, 1e-12);
    g3_mesh_free(&g);
    ck_assert_int_eq(cvm_mesh_count(&n, m, CVM_ENT_INPUT_POINT), CVM_OK);
    ck_assert_uint_eq(n, 4);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&n, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_uint_eq(n, 4);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(sphere_in_box_meshes_and_conforms)
{
    cvm_mesh *m = read3("sphere_in_box.poly"), *ref;
    g3_mesh g;
    double v, vref, levels;
    size_t i;
    cvm_status s = cvm_mesh_generate3(m, 0.5);
    if (!g3_with_tetgen()) {
        ck_assert_int_eq(s, CVM_E_UNSUPPORTED);
        cvm_mesh_free(m);
        CVMTEST_SKIP("needs TetGen (a TETGEN=1 build)");
    }
    ck_assert_msg(s == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    g3_mesh_get(&g, m);
    ck_assert_uint_eq(g.nf, 5888);
    ck_assert_uint_eq(g.nbnd, 5888);
    for (i = 0; i < g.nf; i++)
        ck_assert(g3_face_on_boundary(&g, g.face[3 * i], g.face[3 * i + 1], g.face[3 * i + 2]));
    /* box minus ball: two boundary spheres, V - E + F - T = 2 */
    ck_assert_int_eq(g3_euler(&g), 2);
    /* the surface's own tetrahedralisation has the same volume */
    ref = read3("sphere_in_box.poly");
    ck_assert_int_eq(cvm_mesh_triangulate(ref), CVM_OK);
    ck_assert_int_eq(cvm_mesh_get_measure(&vref, ref, CVM_MEASURE_VOLUME), CVM_OK);
    ck_assert_int_eq(cvm_mesh_get_measure(&v, m, CVM_MEASURE_VOLUME), CVM_OK);
    ck_assert_double_eq_tol(v, vref, 1e-9 * vref);
    /* graded: the fine sphere (edges about 0.035) pulls in finer lattice levels */
    ck_assert_int_eq(cvm_mesh_get_report(&levels, m, CVM_REPORT_GEN3_LATTICE_LEVELS), CVM_OK);
    ck_assert_double_ge(levels, 3);
    g3_mesh_free(&g);
    cvm_mesh_free(ref);
    cvm_mesh_free(m);
}
END_TEST

static void run_bytes(const char *name, double h, double seed, double threads, double **xyz,
                      size_t *nv, cvm_index **tet, size_t *nt)
{
    cvm_mesh *m = read3(name);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_SEED, seed), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_THREADS, threads), CVM_OK);
    ck_assert_msg(cvm_mesh_generate3(m, h) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_count(nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(nt, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    *xyz = malloc(3 * *nv * sizeof **xyz);
    *tet = malloc(4 * *nt * sizeof **tet);
    ck_assert_int_eq(cvm_mesh_copy_points_nd(*xyz, 3 * *nv, 3, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(*tet, 4 * *nt, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    cvm_mesh_free(m);
}

START_TEST(same_bytes_for_every_run_seed_and_thread_count)
{
    const char *name = g3_with_tetgen() ? "cube.off" : "tetra.off";
    double *x0, *x1;
    cvm_index *t0, *t1;
    size_t nv0, nt0, nv1, nt1;
    double runs[3][2] = {{1, 1}, {1, 2}, {7, 0}};
    int r;
    run_bytes(name, 0.25, 1, 1, &x0, &nv0, &t0, &nt0);
    for (r = 0; r < 3; r++) {
        run_bytes(name, 0.25, runs[r][0], runs[r][1], &x1, &nv1, &t1, &nt1);
        ck_assert_uint_eq(nv0, nv1);
        ck_assert_uint_eq(nt0, nt1);
        ck_assert(memcmp(x0, x1, 3 * nv0 * sizeof *x0) == 0);
        ck_assert(memcmp(t0, t1, 4 * nt0 * sizeof *t0) == 0);
        free(x1);
        free(t1);
    }
    free(x0);
    free(t0);
}
END_TEST

static void oom_setup(cvm_mesh *m, void *arg)
{
    char path[1024];
    g3_data3d(path, sizeof path, (const char *)arg);
    ck_assert_int_eq(cvm_mesh_read(m, path), CVM_OK);
}

static cvm_status oom_run(cvm_mesh *m, void *arg)
{
    (void)arg;
    return cvm_mesh_generate3(m, 0.5);
}

START_TEST(oom_at_every_allocation)
{
    /* the tetrahedron: carve without TetGen; with it, TetGen's own new/delete
     * are not the handle's allocator, so the sweep covers the generation */
    cvmtest_oom_sweep(oom_setup, oom_run, NULL, (void *)"tetra.off");
}
END_TEST

TCase *generate3_api_tcase(void)
{
    TCase *tc = tcase_create("api");
    tcase_set_timeout(tc, 300);
    tcase_add_test(tc, bad_sizes_name_the_size);
    tcase_add_test(tc, options_and_states_are_checked);
    tcase_add_test(tc, tetra_meshes_in_every_build);
    tcase_add_test(tc, sphere_in_box_meshes_and_conforms);
    tcase_add_test(tc, same_bytes_for_every_run_seed_and_thread_count);
    tcase_add_test(tc, oom_at_every_allocation);
    return tc;
}
