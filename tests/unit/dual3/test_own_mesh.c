/*
 * test_own_mesh.c - a tetrahedral mesh made elsewhere ("bring your own mesh"):
 * cvm_mesh_set_tetrahedra() and cvm_mesh_read() of a TetGen .ele on a
 * hand-made Kuhn mesh of the unit cube (6 tetrahedra per grid cell, inner
 * points jittered so that it is not Delaunay): counts, volume, orientation,
 * boundary and attribute interfaces, Euler characteristic, every status with
 * the item it names, atomicity on error, the optimiser on it (outside share
 * down, surface and volume kept, a valid mesh), and OOM at every allocation.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dual3/dual3_tests.h"
#include "generate3/g3_util.h"
#include "geom/geom_internal.h"
#include "io/io_tests.h"
#include "support/oom_sweep.h"

#define OWN_N 4 /* cells per side */
#define OWN_NP ((OWN_N + 1) * (OWN_N + 1) * (OWN_N + 1))
#define OWN_NT (6 * OWN_N * OWN_N * OWN_N)

static int own_id(int i, int j, int k)
{
    return (k * (OWN_N + 1) + j) * (OWN_N + 1) + i;
}

/* The grid's points (inner ones moved by up to 0.2 of a cell, deterministically) and
 * the Kuhn split of each cell: the 6 paths from corner 000 to 111 along the axes;
 * every other tetrahedron given negatively oriented. attr: 1 for x < 0.5, else 2. */
static void own_mesh(double *xyz, cvm_index *tet, double *attr)
{
    static const int perm[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    uint64_t x = 0x9E3779B97F4A7C15ULL;
    int i, j, k, p, n = 0;
    for (k = 0; k <= OWN_N; k++)
        for (j = 0; j <= OWN_N; j++)
            for (i = 0; i <= OWN_N; i++) {
                double *q = xyz + 3 * own_id(i, j, k);
                int c, inner = i > 0 && i < OWN_N && j > 0 && j < OWN_N && k > 0 && k < OWN_N;
                q[0] = (double)i / OWN_N, q[1] = (double)j / OWN_N, q[2] = (double)k / OWN_N;
                for (c = 0; c < 3 && inner; c++) {
                    x ^= x << 13, x ^= x >> 7, x ^= x << 17;
                    q[c] += 0.2 / OWN_N * ((double)(x >> 11) / 9007199254740992.0 - 0.5) * 2;
                }
            }
    for (k = 0; k < OWN_N; k++)
        for (j = 0; j < OWN_N; j++)
            for (i = 0; i < OWN_N; i++)
                for (p = 0; p < 6; p++) {
                    int c[3] = {i, j, k}, s, v[4];
                    v[0] = own_id(c[0], c[1], c[2]);
                    for (s = 0; s < 3; s++) {
                        c[perm[p][s]]++;
                        v[s + 1] = own_id(c[0], c[1], c[2]);
                    }
                    if (n % 2) {
                        int t = v[2];
                        v[2] = v[3], v[3] = t;
                    }
                    memcpy(tet + 4 * n, v, sizeof v);
                    if (attr)
                        attr[n] = i < OWN_N / 2 ? 1 : 2;
                    n++;
                }
}

static cvm_mesh *own_handle(const double *xyz)
{
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xyz, OWN_NP, 3), CVM_OK);
    return m;
}

static void check_positive(const cvm_mesh *m)
{
    g3_mesh g;
    size_t t;
    g3_mesh_get(&g, m);
    for (t = 0; t < g.nt; t++) {
        const cvm_index *v = g.tet + 4 * t;
        ck_assert(cvm__orient3d(g.xyz + 3 * v[0], g.xyz + 3 * v[1], g.xyz + 3 * v[2],
                                g.xyz + 3 * v[3]) > 0);
    }
    ck_assert_int_eq(g3_euler(&g), 1); /* a ball */
    g3_mesh_free(&g);
}

START_TEST(kuhn_cube_is_taken_and_optimised)
{
    double xyz[3 * OWN_NP], attr[OWN_NT], v, out0, out1;
    cvm_index tet[4 * OWN_NT];
    size_t n;
    cvm_mesh *m;
    own_mesh(xyz, tet, attr);
    m = own_handle(xyz);
    ck_assert_msg(cvm_mesh_set_tetrahedra(m, tet, OWN_NT, NULL) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_count(&n, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_uint_eq(n, OWN_NP);
    ck_assert_int_eq(cvm_mesh_count(&n, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    ck_assert_uint_eq(n, OWN_NT);
    ck_assert_int_eq(cvm_mesh_count(&n, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_uint_eq(n, 12 * OWN_N * OWN_N); /* 2 per boundary square */
    ck_assert_int_eq(cvm_mesh_get_measure(&v, m, CVM_MEASURE_VOLUME), CVM_OK);
    ck_assert_double_eq_tol(v, 1.0, 1e-13);
    ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    check_positive(m);
    /* the optimiser: fewer tetrahedra outside, the surface, the volume and the points kept */
    ck_assert_int_eq(cvm_mesh_get_measure(&out0, m, CVM_MEASURE_CIRCUMCENTRE_OUTSIDE_PCT), CVM_OK);
    ck_assert_double_gt(out0, 0);
    ck_assert_msg(cvm_mesh_optimise_dual3(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_get_measure(&out1, m, CVM_MEASURE_CIRCUMCENTRE_OUTSIDE_PCT), CVM_OK);
    ck_assert_msg(out1 < out0, "outside %g -> %g %%", out0, out1);
    ck_assert_int_eq(cvm_mesh_get_measure(&v, m, CVM_MEASURE_VOLUME), CVM_OK);
    ck_assert_double_eq_tol(v, 1.0, 1e-12);
    ck_assert_int_eq(cvm_mesh_count(&n, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_uint_eq(n, OWN_NP);
    ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    check_positive(m);
    cvm_mesh_free(m);
    /* with attributes: the interface x = 0.5 (2 triangles per square) is kept as a facet */
    m = own_handle(xyz);
    ck_assert_msg(cvm_mesh_set_tetrahedra(m, tet, OWN_NT, attr) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_count(&n, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_uint_eq(n, 14 * OWN_N * OWN_N);
    ck_assert_msg(cvm_mesh_optimise_dual3(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    {
        g3_mesh g;
        size_t t;
        int ok = 1;
        g3_mesh_get(&g, m);
        for (t = 0; t < g.nf; t++) /* the interface faces are still faces */
            ok &= g3_face_key(&g, g.face[3 * t], g.face[3 * t + 1], g.face[3 * t + 2]) >= 0;
        ck_assert(ok);
        g3_mesh_free(&g);
    }
    cvm_mesh_free(m);
}
END_TEST

/* Status, message and item of one bad mesh; the handle's mesh stays as it was. */
static void expect_bad(const double *xyz, const cvm_index *tet, const double *attr, size_t nt,
                       cvm_status want, cvm_entity kind, int64_t item, const char *words)
{
    cvm_mesh *m = own_handle(xyz);
    cvm_index good[4 * OWN_NT];
    cvm_entity k;
    int64_t idx;
    size_t n;
    own_mesh((double[3 * OWN_NP]){0}, good, NULL); /* the connectivity only */
    ck_assert_int_eq(cvm_mesh_set_tetrahedra(m, good, OWN_NT, NULL), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_tetrahedra(m, tet, nt, attr), want);
    ck_assert_msg(strstr(cvm_mesh_errmsg(m), words) != NULL, "'%s' lacks '%s'",
                  cvm_mesh_errmsg(m), words);
    if (kind != CVM_ENT_NONE) {
        ck_assert_int_eq(cvm_mesh_error_item(&k, &idx, m), CVM_OK);
        ck_assert_int_eq(k, kind);
        ck_assert_int_eq(idx, item);
    }
    ck_assert_int_eq(cvm_mesh_count(&n, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    ck_assert_uint_eq(n, OWN_NT);
    ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    cvm_mesh_free(m);
}

START_TEST(bad_meshes_give_statuses)
{
    double xyz[3 * OWN_NP], attr[OWN_NT];
    cvm_index tet[4 * OWN_NT], bad[4 * OWN_NT + 4];
    cvm_mesh *m;
    own_mesh(xyz, tet, attr);
    ck_assert_int_eq(cvm_mesh_set_tetrahedra(NULL, tet, 1, NULL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_tetrahedra(m, NULL, 1, NULL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_set_tetrahedra(m, tet, OWN_NT, NULL), CVM_E_STATE); /* 2D */
    cvm_mesh_free(m);
    m = own_handle(xyz);
    ck_assert_int_eq(cvm_mesh_set_tetrahedra(m, tet, 0, NULL), CVM_E_INPUT_EMPTY);
    cvm_mesh_free(m);
    memcpy(bad, tet, sizeof tet);
    bad[4 * 7 + 2] = OWN_NP;
    expect_bad(xyz, bad, NULL, OWN_NT, CVM_E_INPUT_INDEX, CVM_ENT_TETRAHEDRON, 7, "names point");
    memcpy(bad, tet, sizeof tet);
    bad[4 * 9 + 3] = bad[4 * 9];
    expect_bad(xyz, bad, NULL, OWN_NT, CVM_E_INPUT_DEGENERATE, CVM_ENT_TETRAHEDRON, 9, "twice");
    /* a flat tetrahedron: four corners of one boundary square */
    memcpy(bad, tet, sizeof tet);
    bad[0] = own_id(0, 0, 0), bad[1] = own_id(1, 0, 0), bad[2] = own_id(0, 1, 0),
    bad[3] = own_id(1, 1, 0);
    expect_bad(xyz, bad, NULL, OWN_NT, CVM_E_INPUT_DEGENERATE, CVM_ENT_TETRAHEDRON, 0, "flat");
    /* the last cell's 6 tetrahedra left out: its far corner is in no tetrahedron */
    expect_bad(xyz, tet, NULL, OWN_NT - 6, CVM_E_INPUT_DEGENERATE, CVM_ENT_INPUT_POINT,
               OWN_NP - 1, "in no tetrahedron");
    /* a tetrahedron given twice: its inner faces have three tetrahedra */
    memcpy(bad, tet, sizeof tet);
    memcpy(bad + 4 * OWN_NT, tet + 4 * 5, 4 * sizeof *tet);
    expect_bad(xyz, bad, NULL, OWN_NT + 1, CVM_E_INPUT_DEGENERATE, CVM_ENT_NONE, 0,
               "shared by 3 tetrahedra");
    attr[3] = NAN;
    expect_bad(xyz, tet, attr, OWN_NT, CVM_E_INPUT_NONFINITE, CVM_ENT_TETRAHEDRON, 3, "attribute");
    {
        /* two tetrahedra on one side of their shared face 0 1 2: they overlap */
        double pts[3 * 5] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0.2, 0.2, 0.5};
        cvm_index two[8] = {0, 1, 2, 3, 0, 1, 2, 4};
        m = own_handle(xyz);
        ck_assert_int_eq(cvm_mesh_set_points(m, pts, 5, 3), CVM_OK);
        ck_assert_int_eq(cvm_mesh_set_tetrahedra(m, two, 2, NULL), CVM_E_INPUT_INTERSECTING);
        ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "overlap"));
        pts[14] = -0.5; /* now on the other side: a valid mesh of two tetrahedra */
        ck_assert_int_eq(cvm_mesh_set_points(m, pts, 5, 3), CVM_OK);
        ck_assert_msg(cvm_mesh_set_tetrahedra(m, two, 2, NULL) == CVM_OK, "%s", cvm_mesh_errmsg(m));
        ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
        cvm_mesh_free(m);
    }
    {
        /* two tetrahedra touching at one vertex only: a non-manifold boundary vertex */
        double pts[3 * 7] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, -1, 0, 0, 0, -1, 0, 0, 0, -1};
        cvm_index two[8] = {0, 1, 2, 3, 0, 4, 6, 5};
        m = own_handle(xyz);
        ck_assert_int_eq(cvm_mesh_set_points(m, pts, 7, 3), CVM_OK);
        ck_assert_int_eq(cvm_mesh_set_tetrahedra(m, two, 2, NULL), CVM_E_INPUT_INTERSECTING);
        ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "boundary"));
        cvm_mesh_free(m);
    }
}
END_TEST

/* CVM_OPT_DUAL3_SLIDE_BOUNDARY 2 on the Kuhn cube turned by an arbitrary rotation (so its
 * sides are oblique planes, which slide 1 keeps fixed): vertices inside the sides move,
 * and stay in their side's plane to rounding; edges and corners stay; the volume stays. */
START_TEST(slide_surface_on_a_rotated_cube)
{
    double xyz[3 * OWN_NP], rot[3 * OWN_NP], R[9], v, *x1;
    cvm_index tet[4 * OWN_NT];
    const double a = 0.5, b = 0.3; /* rotation about z by a, then about x by b */
    size_t i, moved = 0;
    int k;
    cvm_mesh *m;
    own_mesh(xyz, tet, NULL);
    R[0] = cos(a), R[1] = -sin(a), R[2] = 0;
    R[3] = cos(b) * sin(a), R[4] = cos(b) * cos(a), R[5] = -sin(b);
    R[6] = sin(b) * sin(a), R[7] = sin(b) * cos(a), R[8] = cos(b);
    for (i = 0; i < OWN_NP; i++)
        for (k = 0; k < 3; k++)
            rot[3 * i + k] = R[3 * k] * xyz[3 * i] + R[3 * k + 1] * xyz[3 * i + 1] +
                             R[3 * k + 2] * xyz[3 * i + 2];
    m = own_handle(rot);
    ck_assert_int_eq(cvm_mesh_set_tetrahedra(m, tet, OWN_NT, NULL), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL3_SLIDE_BOUNDARY, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL3_MAX_SWEEPS, 6), CVM_OK);
    ck_assert_msg(cvm_mesh_optimise_dual3(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_get_measure(&v, m, CVM_MEASURE_VOLUME), CVM_OK);
    ck_assert_double_eq_tol(v, 1.0, 1e-12);
    x1 = malloc(sizeof rot);
    ck_assert_ptr_nonnull(x1);
    ck_assert_int_eq(cvm_mesh_copy_points_nd(x1, 3 * OWN_NP, 3, m), CVM_OK);
    for (i = 0; i < OWN_NP; i++) {
        const double *p0 = xyz + 3 * i;
        double q[3];
        int nside = 0, c;
        for (c = 0; c < 3; c++) /* the sides of the unrotated cube the point lies on */
            nside += p0[c] == 0 || p0[c] == 1;
        if (memcmp(x1 + 3 * i, rot + 3 * i, 3 * sizeof *x1) == 0)
            continue;
        ck_assert_msg(nside <= 1, "point %lu on an edge or corner moved", (unsigned long)i);
        if (nside == 0)
            continue;
        for (k = 0; k < 3; k++) /* back in the cube's frame: R is orthogonal */
            q[k] = R[k] * x1[3 * i] + R[3 + k] * x1[3 * i + 1] + R[6 + k] * x1[3 * i + 2];
        for (c = 0; c < 3; c++)
            if (p0[c] == 0 || p0[c] == 1)
                ck_assert_msg(fabs(q[c] - p0[c]) <= 1e-12, "point %lu left its side by %g",
                              (unsigned long)i, fabs(q[c] - p0[c]));
        moved++;
    }
    ck_assert_uint_gt(moved, 0);
    free(x1);
    cvm_mesh_free(m);
}
END_TEST

/* The mesh as TetGen files, numbered from 1, with the attribute. */
static void write_files(const char *dir, const double *xyz, const cvm_index *tet, const double *attr)
{
    char path[700];
    FILE *f;
    int i;
    snprintf(path, sizeof path, "%s/own.node", dir);
    f = fopen(path, "w");
    ck_assert_ptr_nonnull(f);
    fprintf(f, "# a jittered cube\n%d 3 0 0\n", OWN_NP);
    for (i = 0; i < OWN_NP; i++)
        fprintf(f, "%d %.17g %.17g %.17g\n", i + 1, xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    fclose(f);
    snprintf(path, sizeof path, "%s/own.ele", dir);
    f = fopen(path, "w");
    ck_assert_ptr_nonnull(f);
    fprintf(f, "%d 4 1\n", OWN_NT);
    for (i = 0; i < OWN_NT; i++)
        fprintf(f, "%d %d %d %d %d %g\n", i + 1, tet[4 * i] + 1, tet[4 * i + 1] + 1,
                tet[4 * i + 2] + 1, tet[4 * i + 3] + 1, attr[i]);
    fclose(f);
}

static cvm_status read_text(const char *dir, const char *ele, cvm_mesh *m)
{
    char path[700];
    FILE *f;
    snprintf(path, sizeof path, "%s/bad.ele", dir);
    f = fopen(path, "w");
    ck_assert_ptr_nonnull(f);
    fputs(ele, f);
    fclose(f);
    snprintf(path, sizeof path, "%s/bad.node", dir);
    f = fopen(path, "w");
    ck_assert_ptr_nonnull(f);
    fputs("5 3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 1\n", f);
    fclose(f);
    snprintf(path, sizeof path, "%s/bad.ele", dir);
    return cvm_mesh_read(m, path);
}

START_TEST(tetgen_ele_is_read)
{
    double xyz[3 * OWN_NP], attr[OWN_NT], *x2;
    cvm_index tet[4 * OWN_NT];
    char *dir = iotest_tmpdir(), path[700];
    cvm_mesh *m, *m2;
    size_t n;
    own_mesh(xyz, tet, attr);
    write_files(dir, xyz, tet, attr);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    snprintf(path, sizeof path, "%s/own.ele", dir);
    ck_assert_msg(cvm_mesh_read(m, path) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_count(&n, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    ck_assert_uint_eq(n, OWN_NT);
    ck_assert_int_eq(cvm_mesh_count(&n, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_uint_eq(n, 14 * OWN_N * OWN_N); /* the attribute's interface included */
    /* the same mesh as cvm_mesh_set_tetrahedra() makes */
    m2 = own_handle(xyz);
    ck_assert_int_eq(cvm_mesh_set_tetrahedra(m2, tet, OWN_NT, attr), CVM_OK);
    {
        cvm_index *a = malloc(4 * OWN_NT * sizeof *a), *b = malloc(4 * OWN_NT * sizeof *b);
        x2 = malloc(3 * OWN_NP * sizeof *x2);
        ck_assert(a && b && x2);
        ck_assert_int_eq(cvm_mesh_copy_cells(a, 4 * OWN_NT, m, CVM_ENT_TETRAHEDRON), CVM_OK);
        ck_assert_int_eq(cvm_mesh_copy_cells(b, 4 * OWN_NT, m2, CVM_ENT_TETRAHEDRON), CVM_OK);
        ck_assert(memcmp(a, b, 4 * OWN_NT * sizeof *a) == 0);
        ck_assert_int_eq(cvm_mesh_copy_points_nd(x2, 3 * OWN_NP, 3, m), CVM_OK);
        ck_assert(memcmp(x2, xyz, sizeof xyz) == 0);
        free(a);
        free(b);
        free(x2);
    }
    cvm_mesh_free(m2);
    /* malformed files: the status, and the handle keeps its mesh */
    ck_assert_int_eq(read_text(dir, "1 4 0\n1 1 2 3 6\n", m), CVM_E_IO_FORMAT);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "names point 6"));
    ck_assert_int_eq(read_text(dir, "1 10 0\n1 1 2 3 4 5 5 5 5 5 5\n", m), CVM_E_UNSUPPORTED);
    ck_assert_int_eq(read_text(dir, "2 4 0\n1 1 2 3 4\n3 5 4 3 2\n", m), CVM_E_IO_FORMAT);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "out of sequence"));
    ck_assert_int_eq(read_text(dir, "2 4 0\n1 1 2 3 4\n", m), CVM_E_IO_FORMAT);
    ck_assert_int_eq(read_text(dir, "1 4 0\n1 1 2 3 4\n2 1 2 3 5\n", m), CVM_E_IO_FORMAT);
    ck_assert_int_eq(read_text(dir, "1 4 1\n1 1 2 3 4 nan\n", m), CVM_E_INPUT_NONFINITE);
    ck_assert_int_eq(read_text(dir, "1 4 0\n1 1 2 3 4\n", m), CVM_E_INPUT_DEGENERATE); /* 5 unused */
    ck_assert_int_eq(cvm_mesh_count(&n, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    ck_assert_uint_eq(n, OWN_NT);
    ck_assert_int_eq(read_text(dir, "2 4 0\n1 1 2 3 4\n2 5 4 3 2\n", m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&n, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    ck_assert_uint_eq(n, 2);
    snprintf(path, sizeof path, "%s/none.ele", dir);
    ck_assert_int_eq(cvm_mesh_read(m, path), CVM_E_IO_OPEN);
    cvm_mesh_free(m);
    iotest_rmdir(dir);
    free(dir);
}
END_TEST

typedef struct own_oom {
    double xyz[3 * OWN_NP], attr[OWN_NT];
    cvm_index tet[4 * OWN_NT];
    char path[700];
} own_oom;

static void oom_setup(cvm_mesh *m, void *arg)
{
    own_oom *o = arg;
    ck_assert_int_eq(cvm_mesh_set_points(m, o->xyz, OWN_NP, 3), CVM_OK);
}

static cvm_status oom_set(cvm_mesh *m, void *arg)
{
    own_oom *o = arg;
    return cvm_mesh_set_tetrahedra(m, o->tet, OWN_NT, o->attr);
}

static cvm_status oom_read(cvm_mesh *m, void *arg)
{
    own_oom *o = arg;
    return cvm_mesh_read(m, o->path);
}

START_TEST(oom_at_every_allocation)
{
    own_oom *o = malloc(sizeof *o);
    char *dir = iotest_tmpdir();
    ck_assert_ptr_nonnull(o);
    own_mesh(o->xyz, o->tet, o->attr);
    write_files(dir, o->xyz, o->tet, o->attr);
    snprintf(o->path, sizeof o->path, "%s/own.ele", dir);
    cvmtest_oom_sweep(oom_setup, oom_set, NULL, o);
    cvmtest_oom_sweep(oom_setup, oom_read, NULL, o);
    iotest_rmdir(dir);
    free(dir);
    free(o);
}
END_TEST

TCase *dual3_own_mesh_tcase(void)
{
    TCase *tc = tcase_create("own_mesh");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, kuhn_cube_is_taken_and_optimised);
    tcase_add_test(tc, bad_meshes_give_statuses);
    tcase_add_test(tc, slide_surface_on_a_rotated_cube);
    tcase_add_test(tc, tetgen_ele_is_read);
    tcase_add_test(tc, oom_at_every_allocation);
    return tc;
}
