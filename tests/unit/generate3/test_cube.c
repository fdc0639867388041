/*
 * test_cube.c - cvm_mesh_generate3() on the unit cube at uniform size 1/8:
 * the surface kept face for face, volume, Euler characteristic, and the BCC
 * lattice reproduced in the interior (valence 14, every tetrahedron there
 * containing its circumcentre, decided exactly in integers).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "generate3/g3_util.h"
#include "generate3/generate3_tests.h"
#include "support/skip.h"

#define CUBE_POINTS 386 /* examples/data3d/cube.off: 8 x 8 right triangles per face */

/* m holds the cube meshed at uniform size h, or NULL when this build cannot
 * recover the cube's surface (no TetGen: its squares are cocircular, and
 * which diagonal the Delaunay tetrahedralisation takes is not the file's). */
static cvm_mesh *cube_mesh(double h)
{
    cvm_mesh *m;
    char path[1024];
    cvm_status s;
    g3_data3d(path, sizeof path, "cube.off");
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_read(m, path), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_GEN3_SIZE_FROM_SURFACE, 0), CVM_OK);
    s = cvm_mesh_generate3(m, h);
    if (!g3_with_tetgen()) {
        ck_assert_int_eq(s, CVM_E_UNSUPPORTED);
        ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "face"));
        cvm_mesh_free(m);
        return NULL;
    }
    ck_assert_msg(s == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    return m;
}

/* Exactly: the circumcentre of the tetrahedron with integer corners P lies
 * strictly inside it. For each face abc and opposite corner d, the centre is
 * on d's side of abc iff d lies outside the sphere with abc's circle as a
 * great circle: |e|^2 |w|^2 > e . (|u|^2 (v x w) + |v|^2 (w x u)), with
 * u = b - a, v = c - a, w = u x v, e = d - a (all in int64 here). */
static void cross(const int64_t *a, const int64_t *b, int64_t *o)
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

static int64_t dot(const int64_t *a, const int64_t *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static int centre_strictly_inside(int64_t P[4][3])
{
    int f;
    for (f = 0; f < 4; f++) {
        const int64_t *a = P[(f + 1) % 4], *b = P[(f + 2) % 4], *c = P[(f + 3) % 4], *d = P[f];
        int64_t u[3], v[3], e[3], w[3], vw[3], wu[3], m[3];
        int k;
        for (k = 0; k < 3; k++) {
            u[k] = b[k] - a[k];
            v[k] = c[k] - a[k];
            e[k] = d[k] - a[k];
        }
        cross(u, v, w);
        cross(v, w, vw);
        cross(w, u, wu);
        for (k = 0; k < 3; k++)
            m[k] = dot(u, u) * vw[k] + dot(v, v) * wu[k];
        if (!(dot(e, e) * dot(w, w) > dot(e, m)))
            return 0;
    }
    return 1;
}

START_TEST(cube_keeps_surface_volume_and_euler)
{
    cvm_mesh *m = cube_mesh(0.125);
    g3_mesh g;
    double vol = 0;
    size_t i;
    if (!m)
        CVMTEST_SKIP("needs TetGen (a TETGEN=1 build)");
    g3_mesh_get(&g, m);
    /* every surface triangle is a boundary face, and nothing else is */
    ck_assert_uint_eq(g.nf, 768);
    ck_assert_uint_eq(g.nbnd, 768);
    for (i = 0; i < g.nf; i++) {
        ck_assert_int_lt(g.face[3 * i], CUBE_POINTS);
        ck_assert_int_lt(g.face[3 * i + 1], CUBE_POINTS);
        ck_assert_int_lt(g.face[3 * i + 2], CUBE_POINTS);
        ck_assert(g3_face_on_boundary(&g, g.face[3 * i], g.face[3 * i + 1], g.face[3 * i + 2]));
    }
    /* a ball: V - E + F - T = 1 */
    ck_assert_int_eq(g3_euler(&g), 1);
    for (i = 0; i < g.nt; i++) {
        const double *a = g.xyz + 3 * g.tet[4 * i], *b = g.xyz + 3 * g.tet[4 * i + 1],
                     *c = g.xyz + 3 * g.tet[4 * i + 2], *d = g.xyz + 3 * g.tet[4 * i + 3];
        double u[3], v[3], w[3];
        int k;
        for (k = 0; k < 3; k++) {
            u[k] = b[k] - a[k];
            v[k] = c[k] - a[k];
            w[k] = d[k] - a[k];
        }
        /* positively oriented in cvm's orient3d: a negative right-hand triple product */
        vol -= (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
                u[2] * (v[0] * w[1] - v[1] * w[0])) / 6;
    }
    ck_assert_msg(fabs(vol - 1) < 1e-12, "volume %.17g", vol);
    /* every generated point strictly inside the cube */
    for (i = CUBE_POINTS; i < g.nv; i++) {
        int k;
        for (k = 0; k < 3; k++)
            ck_assert(g.xyz[3 * i + k] > 0 && g.xyz[3 * i + k] < 1);
    }
    g3_mesh_free(&g);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(cube_interior_is_the_bcc_lattice)
{
    cvm_mesh *m = cube_mesh(0.125);
    g3_mesh g;
    uint8_t *deep;
    size_t i, ndeep = 0, n14 = 0, ntet_in = 0, nwell = 0;
    double near = 0, lat = 0;
    if (!m)
        CVMTEST_SKIP("needs TetGen (a TETGEN=1 build)");
    g3_mesh_get(&g, m);
    ck_assert_int_eq(cvm_mesh_get_report(&near, m, CVM_REPORT_GEN3_NEAR_POINTS), CVM_OK);
    ck_assert_int_eq(cvm_mesh_get_report(&lat, m, CVM_REPORT_GEN3_LATTICE_POINTS), CVM_OK);
    ck_assert_uint_eq(g.nv, CUBE_POINTS + (size_t)near + (size_t)lat);
    /* interior vertices: the lattice's, no edge to the surface */
    deep = calloc(g.nv, 1);
    ck_assert_ptr_nonnull(deep);
    for (i = CUBE_POINTS + (size_t)near; i < g.nv; i++)
        deep[i] = 1;
    for (i = 0; i < g.ne; i++) {
        int64_t a = g.edge[i] / (int64_t)g.nv, b = g.edge[i] % (int64_t)g.nv;
        if (a < CUBE_POINTS)
            deep[b] = 0;
        if (b < CUBE_POINTS)
            deep[a] = 0;
    }
    for (i = 0; i < g.nv; i++)
        if (deep[i]) {
            ndeep++;
            n14 += g.valence[i] == 14;
        }
    ck_assert_uint_gt(ndeep, 300);
    ck_assert_msg(n14 * 100 >= 95 * ndeep, "valence 14 at %lu of %lu interior vertices",
                  (unsigned long)n14, (unsigned long)ndeep);
    /* tetrahedra of interior vertices: corners on the lattice of 1/16, centre inside */
    for (i = 0; i < g.nt; i++) {
        int64_t P[4][3];
        int j, k, all = 1;
        for (j = 0; j < 4; j++)
            all &= deep[g.tet[4 * i + j]];
        if (!all)
            continue;
        ntet_in++;
        for (j = 0; j < 4; j++)
            for (k = 0; k < 3; k++) {
                double x = g.xyz[3 * g.tet[4 * i + j] + k] * 16;
                ck_assert(x == floor(x));
                P[j][k] = (int64_t)x;
            }
        nwell += centre_strictly_inside(P);
    }
    ck_assert_uint_gt(ntet_in, 1000);
    ck_assert_uint_eq(nwell, ntet_in);
    free(deep);
    g3_mesh_free(&g);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(cube_reports_the_matching)
{
    cvm_mesh *m = cube_mesh(0.125);
    double v;
    if (!m)
        CVMTEST_SKIP("needs TetGen (a TETGEN=1 build)");
    /* the 384 squares of the faces: every pair of right triangles across its hypotenuse */
    ck_assert_int_eq(cvm_mesh_get_report(&v, m, CVM_REPORT_GEN3_MATCHED_PAIRS), CVM_OK);
    ck_assert_double_eq(v, 384);
    ck_assert_int_eq(cvm_mesh_get_report(&v, m, CVM_REPORT_GEN3_UNMATCHED_FACES), CVM_OK);
    ck_assert_double_eq(v, 0);
    ck_assert_int_eq(cvm_mesh_get_measure(&v, m, CVM_MEASURE_GEN3_MATCHED_PAIRS), CVM_OK);
    ck_assert_double_eq(v, 384);
    ck_assert_int_eq(cvm_mesh_get_report(&v, m, CVM_REPORT_GEN3_LATTICE_LEVELS), CVM_OK);
    ck_assert_double_eq(v, 1);
    cvm_mesh_free(m);
}
END_TEST

TCase *generate3_cube_tcase(void)
{
    TCase *tc = tcase_create("cube");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, cube_keeps_surface_volume_and_euler);
    tcase_add_test(tc, cube_interior_is_the_bcc_lattice);
    tcase_add_test(tc, cube_reports_the_matching);
    return tc;
}
