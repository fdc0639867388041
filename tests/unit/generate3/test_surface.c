/*
 * test_surface.c - CVM_OPT_GEN3_SURFACE = CVM_GEN3_SURFACE_REMESH_PLANAR: the
 * cube's six planar faces re-meshed (counts reported), the mesh's boundary a
 * closed, consistently oriented surface whose every triangle lies exactly in
 * a face of the cube and has no angle below 25 degrees, the volume kept to
 * 1e-12; the sphere in a box keeps its sphere and its volume; the same bytes
 * on every run; option bounds and the internal-facet status; OOM at every
 * allocation.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "generate3/g3_util.h"
#include "generate3/generate3_tests.h"
#include "support/oom_sweep.h"
#include "support/skip.h"

static cvm_mesh *read_remesh(const char *name, int remesh)
{
    cvm_mesh *m;
    char path[1024];
    g3_data3d(path, sizeof path, name);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_msg(cvm_mesh_read(m, path) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_GEN3_SURFACE,
                                         remesh ? CVM_GEN3_SURFACE_REMESH_PLANAR
                                                : CVM_GEN3_SURFACE_AS_GIVEN), CVM_OK);
    return m;
}

static double min_angle_deg(const double *a, const double *b, const double *c)
{
    const double *p[3];
    double best = 180;
    int k;
    p[0] = a, p[1] = b, p[2] = c;
    for (k = 0; k < 3; k++) {
        const double *o = p[k], *q = p[(k + 1) % 3], *r = p[(k + 2) % 3];
        double u[3], v[3], uv = 0, uu = 0, vv = 0, ang;
        int j;
        for (j = 0; j < 3; j++) {
            u[j] = q[j] - o[j], v[j] = r[j] - o[j];
            uv += u[j] * v[j], uu += u[j] * u[j], vv += v[j] * v[j];
        }
        ang = acos(uv / sqrt(uu * vv)) * 180 / 3.14159265358979323846;
        if (ang < best)
            best = ang;
    }
    return best;
}

START_TEST(cube_faces_remeshed_closed_exact_and_volume_kept)
{
    cvm_mesh *m = read_remesh("cube.off", 1);
    double facets, before, after, v;
    g3_mesh g;
    size_t f;
    cvm_status s = cvm_mesh_generate3(m, 0.125);
    if (!g3_with_tetgen()) {
        /* the re-meshed faces' points are cospherical in places: no recovery, no mesh */
        ck_assert(s == CVM_OK || s == CVM_E_UNSUPPORTED);
        cvm_mesh_free(m);
        CVMTEST_SKIP("needs TetGen (a TETGEN=1 build)");
    }
    ck_assert_msg(s == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_get_report(&facets, m, CVM_REPORT_GEN3_FACETS_REMESHED), CVM_OK);
    ck_assert_int_eq(cvm_mesh_get_report(&before, m, CVM_REPORT_GEN3_SURFACE_TRIS_BEFORE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_get_report(&after, m, CVM_REPORT_GEN3_SURFACE_TRIS_AFTER), CVM_OK);
    ck_assert_double_eq(facets, 6);
    ck_assert_double_eq(before, 768);
    g3_mesh_get(&g, m);
    ck_assert_double_eq(after, (double)g.nf);
    ck_assert_uint_eq(g.nf, g.nbnd);
    g3_assert_closed_oriented(&g);
    v = g3_tet_volume(&g);
    ck_assert_msg(fabs(v - 1) <= 1e-12, "volume %.17g", v);
    for (f = 0; f < g.nf; f++) {
        const double *p[3];
        int k, axis, in_face = 0;
        for (k = 0; k < 3; k++)
            p[k] = g.xyz + 3 * g.face[3 * f + (size_t)k];
        /* exactly in a face of the cube: one coordinate 0 (or 1) at all three corners */
        for (axis = 0; axis < 3; axis++)
            in_face |= (p[0][axis] == 0 && p[1][axis] == 0 && p[2][axis] == 0) ||
                       (p[0][axis] == 1 && p[1][axis] == 1 && p[2][axis] == 1);
        ck_assert_msg(in_face, "boundary face %lu leaves the cube's faces", (unsigned long)f);
        ck_assert_double_ge(min_angle_deg(p[0], p[1], p[2]), 25);
    }
    g3_mesh_free(&g);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(sphere_kept_box_remeshed_volume_equal)
{
    cvm_mesh *m0 = read_remesh("sphere_in_box.off", 0), *m1 = read_remesh("sphere_in_box.off", 1);
    double facets, before, after, v0, v1;
    g3_mesh g0, g1;
    cvm_status s0 = cvm_mesh_generate3(m0, 1.0), s1 = cvm_mesh_generate3(m1, 1.0);
    if (!g3_with_tetgen() && (s0 || s1)) {
        cvm_mesh_free(m0);
        cvm_mesh_free(m1);
        CVMTEST_SKIP("needs TetGen (a TETGEN=1 build)");
    }
    ck_assert_msg(s0 == CVM_OK, "%s", cvm_mesh_errmsg(m0));
    ck_assert_msg(s1 == CVM_OK, "%s", cvm_mesh_errmsg(m1));
    ck_assert_int_eq(cvm_mesh_get_report(&facets, m1, CVM_REPORT_GEN3_FACETS_REMESHED), CVM_OK);
    ck_assert_int_eq(cvm_mesh_get_report(&before, m1, CVM_REPORT_GEN3_SURFACE_TRIS_BEFORE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_get_report(&after, m1, CVM_REPORT_GEN3_SURFACE_TRIS_AFTER), CVM_OK);
    ck_assert_double_eq(facets, 6); /* the box's faces; no two sphere triangles are coplanar */
    ck_assert_double_gt(after, before);
    /* as given: the counts say so */
    ck_assert_int_eq(cvm_mesh_get_report(&facets, m0, CVM_REPORT_GEN3_FACETS_REMESHED), CVM_OK);
    ck_assert_double_eq(facets, 0);
    ck_assert_int_eq(cvm_mesh_get_report(&after, m0, CVM_REPORT_GEN3_SURFACE_TRIS_AFTER), CVM_OK);
    ck_assert_int_eq(cvm_mesh_get_report(&before, m0, CVM_REPORT_GEN3_SURFACE_TRIS_BEFORE), CVM_OK);
    ck_assert_double_eq(after, before);
    g3_mesh_get(&g0, m0);
    g3_mesh_get(&g1, m1);
    g3_assert_closed_oriented(&g1);
    v0 = g3_tet_volume(&g0);
    v1 = g3_tet_volume(&g1);
    ck_assert_msg(fabs(v1 - v0) <= 1e-12 * v0, "volume %.17g, as given %.17g", v1, v0);
    g3_mesh_free(&g0);
    g3_mesh_free(&g1);
    cvm_mesh_free(m0);
    cvm_mesh_free(m1);
}
END_TEST

static void run_copy(double seed, double **xyz, size_t *nv, cvm_index **tet, size_t *nt)
{
    cvm_mesh *m = read_remesh("cube.off", 1);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_SEED, seed), CVM_OK);
    ck_assert_msg(cvm_mesh_generate3(m, 0.25) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_count(nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(nt, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    *xyz = malloc(3 * *nv * sizeof **xyz);
    *tet = malloc(4 * *nt * sizeof **tet);
    ck_assert_int_eq(cvm_mesh_copy_points_nd(*xyz, 3 * *nv, 3, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(*tet, 4 * *nt, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    cvm_mesh_free(m);
}

START_TEST(remeshed_cube_same_bytes_every_run)
{
    double *x0, *x1;
    cvm_index *t0, *t1;
    size_t nv0, nt0, nv1, nt1;
    int r;
    if (!g3_with_tetgen())
        CVMTEST_SKIP("needs TetGen (a TETGEN=1 build)");
    run_copy(1, &x0, &nv0, &t0, &nt0);
    for (r = 0; r < 2; r++) {
        run_copy(r ? 7 : 1, &x1, &nv1, &t1, &nt1);
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

START_TEST(surface_option_bounds_and_statuses)
{
    cvm_mesh *m = read_remesh("tetra.off", 1);
    cvm_bounds b;
    double v;
    ck_assert_int_eq(cvm_option_bounds(&b, CVM_OPT_GEN3_SURFACE), CVM_OK);
    ck_assert_double_eq(b.def, CVM_GEN3_SURFACE_AS_GIVEN);
    ck_assert_double_eq(b.hi, CVM_GEN3_SURFACE_REMESH_ALL);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_GEN3_SURFACE, 3), CVM_E_OPTION_RANGE);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_GEN3_SURFACE, 0.5), CVM_E_OPTION_RANGE);
    /* the tetrahedron has no two coplanar faces: nothing to re-mesh, the surface as given */
    ck_assert_msg(cvm_mesh_generate3(m, 0.5) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_get_report(&v, m, CVM_REPORT_GEN3_FACETS_REMESHED), CVM_OK);
    ck_assert_double_eq(v, 0);
    ck_assert_int_eq(cvm_mesh_get_report(&v, m, CVM_REPORT_GEN3_SURFACE_TRIS_AFTER), CVM_OK);
    ck_assert_double_eq(v, 4);
    ck_assert_int_eq(cvm_mesh_generate3(m, 0), CVM_E_ARGUMENT);
    cvm_mesh_free(m);
    /* internal facets: the same status as the surface as given */
    m = read_remesh("two_cubes.off", 1);
    ck_assert_int_eq(cvm_mesh_generate3(m, 0.5), CVM_E_UNSUPPORTED);
    cvm_mesh_free(m);
}
END_TEST

static void oom_setup(cvm_mesh *m, void *arg)
{
    char path[1024];
    g3_data3d(path, sizeof path, (const char *)arg);
    ck_assert_int_eq(cvm_mesh_read(m, path), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_GEN3_SURFACE, CVM_GEN3_SURFACE_REMESH_PLANAR),
                     CVM_OK);
}

static cvm_status oom_run(cvm_mesh *m, void *arg)
{
    (void)arg;
    return cvm_mesh_generate3(m, 0.5);
}

START_TEST(remesh_oom_at_every_allocation)
{
    /* the cube at 0.5: 6 facets re-meshed (TetGen's own new/delete are not the
     * handle's allocator); without TetGen the tetrahedron, whose surface stays */
    cvmtest_oom_sweep(oom_setup, oom_run, NULL, (void *)(g3_with_tetgen() ? "cube.off" : "tetra.off"));
}
END_TEST

TCase *generate3_surface_tcase(void)
{
    TCase *tc = tcase_create("surface");
    tcase_set_timeout(tc, 300);
    tcase_add_test(tc, cube_faces_remeshed_closed_exact_and_volume_kept);
    tcase_add_test(tc, sphere_kept_box_remeshed_volume_equal);
    tcase_add_test(tc, remeshed_cube_same_bytes_every_run);
    tcase_add_test(tc, surface_option_bounds_and_statuses);
    tcase_add_test(tc, remesh_oom_at_every_allocation);
    return tc;
}
