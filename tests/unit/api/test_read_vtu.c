/* test_read_vtu.c - cvm_mesh_read of .vtu (lib/api/mesh_read_vtu.c): round trips, meshes that cannot be rebuilt, OOM. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api/api_tests.h"
#include "support/failing_alloc.h"
#include "support/fixtures.h"
#include "io/io_tests.h"

static char *g_dir;

static void setup(void)
{
    g_dir = iotest_tmpdir();
}

static void teardown(void)
{
    iotest_rmdir(g_dir);
    free(g_dir);
}

static void in_dir(char *buf, size_t len, const char *name)
{
    snprintf(buf, len, "%s/%s", g_dir, name);
}

static double uniform(uint64_t *s)
{
    uint64_t z = (*s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return (double)((z ^ (z >> 31)) >> 11) / 9007199254740992.0;
}

/* Square with a square hole, refined, optionally with random weights and a
 * region attribute and point markers. */
static void fill_holed(cvm_mesh *m, int weighted)
{
    static const double region[4] = {0.5, 0.5, 7.0, 0.0};
    cvm_sizing *sz;
    size_t nv, v;
    ck_assert_int_eq(cvmtest_pslg_set(m, &cvmtest_square_with_hole), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_regions(m, region, 1), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_sizing_create(&sz), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_uniform(sz, 0.3), CVM_OK);
    ck_assert_int_eq(cvm_mesh_refine(m, sz, CVM_ALGO_FRONTAL), CVM_OK);
    cvm_sizing_free(sz);
    if (weighted) {
        uint64_t rng = 17;
        double *w;
        ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
        w = malloc(nv * sizeof *w);
        ck_assert_ptr_nonnull(w);
        for (v = 0; v < nv; v++)
            w[v] = (weighted == 2 ? 3.0 : 0.2) * 0.09 * uniform(&rng);
        ck_assert_int_eq(cvm_mesh_set_weights(m, w, nv), CVM_OK);
        free(w);
    }
    if (weighted == 2) { /* weights large enough to empty some power cells */
        double vanished;
        ck_assert_int_eq(cvm_mesh_get_measure(&vanished, m, CVM_MEASURE_VANISHED_VERTICES), CVM_OK);
        ck_assert(vanished > 0);
    }
}

static cvm_mesh *holed_mesh(int weighted)
{
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    fill_holed(m, weighted);
    return m;
}

/* Equal counts and arrays of kind through the public API. */
static void assert_same_mesh(cvm_mesh *a, cvm_mesh *b)
{
    static const cvm_entity kinds[3] = {CVM_ENT_TRIANGLE, CVM_ENT_EDGE, CVM_ENT_SEGMENT};
    size_t na, nb, k;
    double *xa, *xb;
    cvm_index *ca, *cb;
    ck_assert_int_eq(cvm_mesh_count(&na, a, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&nb, b, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_uint_eq(na, nb);
    xa = malloc(2 * na * sizeof *xa);
    xb = malloc(2 * na * sizeof *xb);
    ck_assert(xa && xb);
    ck_assert_int_eq(cvm_mesh_copy_points(xa, 2 * na, a), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_points(xb, 2 * na, b), CVM_OK);
    ck_assert(memcmp(xa, xb, 2 * na * sizeof *xa) == 0);
    ck_assert_int_eq(cvm_mesh_copy_weights(xa, na, a), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_weights(xb, na, b), CVM_OK);
    ck_assert(memcmp(xa, xb, na * sizeof *xa) == 0);
    free(xa);
    free(xb);
    for (k = 0; k < 3; k++) {
        ck_assert_int_eq(cvm_mesh_count(&na, a, kinds[k]), CVM_OK);
        ck_assert_int_eq(cvm_mesh_count(&nb, b, kinds[k]), CVM_OK);
        ck_assert_uint_eq(na, nb);
        ca = malloc((3 * na + 1) * sizeof *ca);
        cb = malloc((3 * na + 1) * sizeof *cb);
        ck_assert(ca && cb);
        ck_assert_int_eq(cvm_mesh_copy_cells(ca, 3 * na, a, kinds[k]), CVM_OK);
        ck_assert_int_eq(cvm_mesh_copy_cells(cb, 3 * na, b, kinds[k]), CVM_OK);
        ck_assert_msg(memcmp(ca, cb, (kinds[k] == CVM_ENT_TRIANGLE ? 3 : 2) * na * sizeof *ca) == 0,
                      "entity %d differs", (int)kinds[k]);
        free(ca);
        free(cb);
    }
}

static void round_trip(int weighted)
{
    char a[4096], b[4096];
    char *ta, *tb;
    size_t la, lb;
    cvm_mesh *m = holed_mesh(weighted), *r;
    in_dir(a, sizeof a, "a.vtu");
    in_dir(b, sizeof b, "b.vtu");
    ck_assert_int_eq(cvm_mesh_write(m, a), CVM_OK);
    ck_assert_int_eq(cvm_mesh_create(&r), CVM_OK);
    ck_assert_msg(cvm_mesh_read(r, a) == CVM_OK, "%s", cvm_mesh_errmsg(r));
    {
        double flips = -1;
        ck_assert_int_eq(cvm_mesh_get_report(&flips, r, CVM_REPORT_READ_FLIPS), CVM_OK);
        ck_assert(flips == 0); /* the file's own triangles */
    }
    if (weighted < 2) /* with vanished vertices the check reports their illegal edges */
        ck_assert_msg(cvm_mesh_check(r) == CVM_OK, "%s", cvm_mesh_errmsg(r));
    assert_same_mesh(m, r);
    ck_assert_int_eq(cvm_mesh_write(r, b), CVM_OK);
    ta = iotest_slurp(a, &la);
    tb = iotest_slurp(b, &lb);
    ck_assert(ta && tb);
    ck_assert_uint_eq(la, lb);
    ck_assert_msg(memcmp(ta, tb, la) == 0, "the rewritten .vtu differs");
    ck_assert_ptr_nonnull(strstr(ta, "Name=\"attribute\""));
    ck_assert((weighted != 0) == (strstr(ta, "Name=\"weight\"") != NULL));
    free(ta);
    free(tb);
    cvm_mesh_free(m);
    cvm_mesh_free(r);
}

START_TEST(vtu_round_trip_is_byte_identical)
{
    round_trip(0);
}
END_TEST

/* A mesh with many holes reads back as the same mesh and rewrites to the same
 * bytes: every hole of the file is found again (the file's 6H + 2 triangles,
 * Euler characteristic 1 - H). */
START_TEST(vtu_round_trip_of_a_hole_grid)
{
    char a[4096], b[4096];
    char *ta, *tb;
    size_t la, lb, nt, nv, ne;
    cvmtest_pslg *g = cvmtest_hole_grid(12);
    cvm_mesh *m, *r;
    ck_assert_ptr_nonnull(g);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvmtest_pslg_set(m, g), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    in_dir(a, sizeof a, "grid.vtu");
    in_dir(b, sizeof b, "grid2.vtu");
    ck_assert_int_eq(cvm_mesh_write(m, a), CVM_OK);
    ck_assert_int_eq(cvm_mesh_create(&r), CVM_OK);
    ck_assert_msg(cvm_mesh_read(r, a) == CVM_OK, "%s", cvm_mesh_errmsg(r));
    ck_assert_msg(cvm_mesh_check(r) == CVM_OK, "%s", cvm_mesh_errmsg(r));
    assert_same_mesh(m, r);
    ck_assert_int_eq(cvm_mesh_count(&nt, r, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&nv, r, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&ne, r, CVM_ENT_EDGE), CVM_OK);
    ck_assert_uint_eq(nt, 6 * 144 + 2);
    ck_assert_int_eq((long)nv - (long)ne + (long)nt, g->euler);
    ck_assert_int_eq(cvm_mesh_write(r, b), CVM_OK);
    ta = iotest_slurp(a, &la);
    tb = iotest_slurp(b, &lb);
    ck_assert(ta && tb);
    ck_assert_uint_eq(la, lb);
    ck_assert_msg(memcmp(ta, tb, la) == 0, "the rewritten .vtu differs");
    free(ta);
    free(tb);
    cvm_mesh_free(m);
    cvm_mesh_free(r);
    cvmtest_pslg_free(g);
}
END_TEST

/* Segments crossing near (1e6, 1e6) (tests/data/crossings_near_large_offset.poly):
 * carving keeps only the regions they enclose, so the written file holds
 * points of no triangle (ends of segments outside every region). They lie
 * outside the file's domain: the file reads back ("point 0 lies in no
 * triangle" before) to the same points and triangles, passes the check and
 * rewrites to the same bytes. */
START_TEST(vtu_points_outside_the_domain_read_back)
{
    char poly[4096], a[4096], b[4096];
    char *ta, *tb;
    size_t la, lb, nv, nt, nv2, nt2;
    cvm_index *c1, *c2;
    cvm_mesh *m, *r;
    iotest_path(poly, sizeof poly, iotest_data_dir(), "crossings_near_large_offset.poly");
    in_dir(a, sizeof a, "cross.vtu");
    in_dir(b, sizeof b, "cross2.vtu");
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_msg(cvm_mesh_read(m, poly) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_write(m, a), CVM_OK);
    ck_assert_int_eq(cvm_mesh_create(&r), CVM_OK);
    ck_assert_msg(cvm_mesh_read(r, a) == CVM_OK, "%s", cvm_mesh_errmsg(r));
    ck_assert_msg(cvm_mesh_check(r) == CVM_OK, "%s", cvm_mesh_errmsg(r));
    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&nv2, r, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_uint_eq(nv, nv2);
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&nt2, r, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_uint_eq(nt, nt2);
    c1 = malloc((3 * nt + 1) * sizeof *c1);
    c2 = malloc((3 * nt + 1) * sizeof *c2);
    ck_assert(c1 && c2);
    ck_assert_int_eq(cvm_mesh_copy_cells(c1, 3 * nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(c2, 3 * nt, r, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert(memcmp(c1, c2, 3 * nt * sizeof *c1) == 0);
    ck_assert_int_eq(cvm_mesh_write(r, b), CVM_OK);
    ta = iotest_slurp(a, &la);
    tb = iotest_slurp(b, &lb);
    ck_assert(ta && tb);
    ck_assert_uint_eq(la, lb);
    ck_assert_msg(memcmp(ta, tb, la) == 0, "the rewritten .vtu differs");
    free(ta);
    free(tb);
    free(c1);
    free(c2);
    cvm_mesh_free(m);
    cvm_mesh_free(r);
}
END_TEST

START_TEST(vtu_round_trip_keeps_weights)
{
    round_trip(1);
}
END_TEST

/* Vertices with empty power cells: the regular triangulation reached from
 * the CDT differs, so the reader forces the file's edges and checks that the
 * flips of cvm_mesh_set_weights() leave them. */
START_TEST(vtu_round_trip_with_vanished_vertices)
{
    round_trip(2);
}
END_TEST

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    ck_assert_ptr_nonnull(f);
    fputs(text, f);
    fclose(f);
}

/* A parallelogram split along its long diagonal 0-2, which is not
 * Delaunay (the angles at 1 and 3 are 135 degrees). */
static const char k_bad_diagonal[] =
    "<VTKFile type=\"UnstructuredGrid\"><UnstructuredGrid>"
    "<Piece NumberOfPoints=\"4\" NumberOfCells=\"2\"><Points>"
    "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">"
    "0 0 0 3 0 0 4 1 0 1 1 0</DataArray></Points><Cells>"
    "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0 1 2 0 2 3</DataArray>"
    "<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">3 6</DataArray>"
    "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">5 5</DataArray>"
    "</Cells></Piece></UnstructuredGrid></VTKFile>\n";

static const char k_inverted[] =
    "<VTKFile type=\"UnstructuredGrid\"><UnstructuredGrid>"
    "<Piece NumberOfPoints=\"4\" NumberOfCells=\"2\"><Points>"
    "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">"
    "0 0 0 3 0 0 4 1 0 2 -1 0</DataArray></Points><Cells>"
    "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0 1 2 0 2 3</DataArray>"
    "<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">3 6</DataArray>"
    "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">5 5</DataArray>"
    "</Cells></Piece></UnstructuredGrid></VTKFile>\n";

static double read_flips(cvm_mesh *m)
{
    double f = -1;
    ck_assert_int_eq(cvm_mesh_get_report(&f, m, CVM_REPORT_READ_FLIPS), CVM_OK);
    ck_assert_int_eq(cvm_mesh_get_measure(&f, m, CVM_MEASURE_READ_FLIPS), CVM_OK);
    return f;
}

/* The non-Delaunay diagonal is flipped (one flip, its boundary kept as
 * segments); the Delaunay one reads as it is (no flip, no segment); an
 * inverted triangle is refused by name and keeps the mesh read before. */
START_TEST(vtu_non_delaunay_diagonal_is_flipped)
{
    char path[4096], good[4096];
    cvm_mesh *m = holed_mesh(0);
    size_t n;
    cvm_index tri[6];
    cvm_entity kind;
    int64_t idx;
    char *t = malloc(sizeof k_bad_diagonal);
    ck_assert_ptr_nonnull(t);
    in_dir(path, sizeof path, "bad.vtu");
    write_text(path, k_bad_diagonal);
    ck_assert_msg(cvm_mesh_read(m, path) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert(read_flips(m) == 1);
    ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_count(&n, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_uint_eq(n, 2);
    ck_assert_int_eq(cvm_mesh_copy_cells(tri, 6, m, CVM_ENT_TRIANGLE), CVM_OK);
    /* both triangles now use the diagonal 1-3, in the file's slots */
    ck_assert((tri[0] == 1 || tri[1] == 1 || tri[2] == 1) && (tri[0] == 3 || tri[1] == 3 || tri[2] == 3));
    ck_assert((tri[3] == 1 || tri[4] == 1 || tri[5] == 1) && (tri[3] == 3 || tri[4] == 3 || tri[5] == 3));
    ck_assert_int_eq(cvm_mesh_count(&n, m, CVM_ENT_SEGMENT), CVM_OK);
    ck_assert_uint_eq(n, 4); /* the boundary edges */
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert(read_flips(m) == 0); /* a report of the last read only */
    /* the other diagonal is the Delaunay one: read as it is */
    in_dir(good, sizeof good, "good.vtu");
    strcpy(t, k_bad_diagonal);
    memcpy(strstr(t, "0 1 2 0 2 3"), "0 1 3 1 2 3", 11);
    write_text(good, t);
    ck_assert_msg(cvm_mesh_read(m, good) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert(read_flips(m) == 0);
    ck_assert_int_eq(cvm_mesh_count(&n, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_uint_eq(n, 2);
    ck_assert_int_eq(cvm_mesh_count(&n, m, CVM_ENT_SEGMENT), CVM_OK);
    ck_assert_uint_eq(n, 0); /* convex: read as the Delaunay triangulation, no segments */
    /* point 3 moved to (2, -1), below the diagonal 0-2: triangle 1 (0 2 3)
       now lies on the same side of it as triangle 0, folded over it */
    write_text(path, k_inverted);
    ck_assert_int_eq(cvm_mesh_read(m, path), CVM_E_INPUT_DEGENERATE);
    ck_assert_msg(strstr(cvm_mesh_errmsg(m), "triangle 1 (points 0 2 3) is inverted") != NULL, "%s",
                  cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_error_item(&kind, &idx, m), CVM_OK);
    ck_assert_int_eq(kind, CVM_ENT_TRIANGLE);
    ck_assert_int_eq(idx, 1);
    ck_assert_int_eq(cvm_mesh_count(&n, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_uint_eq(n, 2); /* the previous mesh is kept */
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    free(t);
    cvm_mesh_free(m);
}
END_TEST

/* An n x n structured grid as a legacy .vtk, each square split by its
 * diagonal (i, j)-(i+1, j+1), sheared (x += 0.8 y) and squeezed (y *= 0.5):
 * every diagonal is the long one of its square, not Delaunay. */
static void write_sheared_grid(const char *path, int n)
{
    FILE *f = fopen(path, "w");
    int i, j;
    ck_assert_ptr_nonnull(f);
    fprintf(f, "# vtk DataFile Version 3.0\nsheared grid\nASCII\nDATASET UNSTRUCTURED_GRID\n");
    fprintf(f, "POINTS %d double\n", (n + 1) * (n + 1));
    for (j = 0; j <= n; j++)
        for (i = 0; i <= n; i++)
            fprintf(f, "%.17g %.17g 0\n", i + 0.8 * j, 0.5 * j);
    fprintf(f, "CELLS %d %d\n", 2 * n * n, 8 * n * n);
    for (j = 0; j < n; j++)
        for (i = 0; i < n; i++) {
            int a = j * (n + 1) + i, b = a + 1, c = b + n + 1, d = a + n + 1;
            fprintf(f, "3 %d %d %d\n3 %d %d %d\n", a, b, c, a, c, d);
        }
    fprintf(f, "CELL_TYPES %d\n", 2 * n * n);
    for (i = 0; i < 2 * n * n; i++)
        fprintf(f, "5\n");
    fclose(f);
}

/* Bring your own mesh: the sheared grid is read, its boundary becomes
 * segments and every diagonal is flipped (n^2 flips) to the Delaunay
 * triangulation, which the exact check accepts; written and read again it
 * needs no flip and rewrites to the same bytes. */
START_TEST(vtk_sheared_grid_is_flipped_to_delaunay)
{
    enum { N = 6 };
    char path[4096], a[4096], b[4096];
    char *ta, *tb;
    size_t la, lb, nt, nv, ne, ns;
    cvm_mesh *m, *r;
    in_dir(path, sizeof path, "grid.vtk");
    in_dir(a, sizeof a, "grid.vtu");
    in_dir(b, sizeof b, "grid2.vtu");
    write_sheared_grid(path, N);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_msg(cvm_mesh_read(m, path) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert(read_flips(m) == N * N);
    ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&ne, m, CVM_ENT_EDGE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&ns, m, CVM_ENT_SEGMENT), CVM_OK);
    ck_assert_uint_eq(nt, 2 * N * N);
    ck_assert_uint_eq(nv, (N + 1) * (N + 1));
    ck_assert_int_eq((long)nv - (long)ne + (long)nt, 1);
    ck_assert_uint_eq(ns, 4 * N);
    ck_assert_int_eq(cvm_mesh_write(m, a), CVM_OK);
    ck_assert_int_eq(cvm_mesh_create(&r), CVM_OK);
    ck_assert_msg(cvm_mesh_read(r, a) == CVM_OK, "%s", cvm_mesh_errmsg(r));
    ck_assert(read_flips(r) == 0);
    ck_assert_msg(cvm_mesh_check(r) == CVM_OK, "%s", cvm_mesh_errmsg(r));
    ck_assert_int_eq(cvm_mesh_write(r, b), CVM_OK);
    ta = iotest_slurp(a, &la);
    tb = iotest_slurp(b, &lb);
    ck_assert(ta && tb);
    ck_assert_uint_eq(la, lb);
    ck_assert_msg(memcmp(ta, tb, la) == 0, "the rewritten .vtu differs");
    free(ta);
    free(tb);
    cvm_mesh_free(m);
    cvm_mesh_free(r);
}
END_TEST

/* Out of memory at each allocation of the read that flips: CVM_E_NOMEM, an
 * empty handle and no leak, until the read succeeds with every flip. */
START_TEST(vtk_sheared_grid_read_out_of_memory_at_every_allocation)
{
    enum { N = 4 };
    char path[4096];
    cvm_mesh *m;
    cvmtest_alloc al;
    long k;
    size_t nt;
    in_dir(path, sizeof path, "oom_grid.vtk");
    write_sheared_grid(path, N);
    for (k = 1;; k++) {
        cvm_status s;
        cvmtest_alloc_init(&al, k, 0);
        if (cvmtest_mesh_create(&m, &al) != CVM_OK) {
            ck_assert_int_eq((int)al.live_blocks, 0);
            continue;
        }
        s = cvm_mesh_read(m, path);
        if (s == CVM_OK) {
            cvmtest_alloc_arm(&al, 0, 0);
            ck_assert(read_flips(m) == N * N);
            ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
            cvm_mesh_free(m);
            ck_assert_int_eq((int)al.live_blocks, 0);
            break;
        }
        ck_assert_msg(s == CVM_E_NOMEM, "allocation %ld: status %d (%s)", k, s, cvm_mesh_errmsg(m));
        ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE), CVM_OK);
        ck_assert_uint_eq(nt, 0);
        cvm_mesh_free(m);
        ck_assert_int_eq((int)al.live_blocks, 0);
    }
    ck_assert(k > 20);
}
END_TEST

/* The sheared grid as a Gmsh 2.2 file: bottom lines with physical tag 7,
 * the other boundary lines 8, the triangles of the left half region 1 and
 * of the right half region 2. */
static void write_sheared_msh(const char *path, int n)
{
    FILE *f = fopen(path, "w");
    int i, j, id = 1;
    ck_assert_ptr_nonnull(f);
    fprintf(f, "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n", (n + 1) * (n + 1));
    for (j = 0; j <= n; j++)
        for (i = 0; i <= n; i++)
            fprintf(f, "%d %.17g %.17g 0\n", j * (n + 1) + i + 1, i + 0.8 * j, 0.5 * j);
    fprintf(f, "$EndNodes\n$Elements\n%d\n", 4 * n + 2 * n * n);
    for (i = 0; i < n; i++) {
        int b = i + 1, t = n * (n + 1) + i + 1, l = i * (n + 1) + 1, r = l + n;
        fprintf(f, "%d 1 2 7 1 %d %d\n", id++, b, b + 1);
        fprintf(f, "%d 1 2 8 1 %d %d\n", id++, t, t + 1);
        fprintf(f, "%d 1 2 8 1 %d %d\n", id++, l, l + n + 1);
        fprintf(f, "%d 1 2 8 1 %d %d\n", id++, r, r + n + 1);
    }
    for (j = 0; j < n; j++)
        for (i = 0; i < n; i++) {
            int a = j * (n + 1) + i + 1, b = a + 1, c = b + n + 1, d = a + n + 1;
            int reg = i < n / 2 ? 1 : 2;
            fprintf(f, "%d 2 2 %d 1 %d %d %d\n", id++, reg, a, b, c);
            fprintf(f, "%d 2 2 %d 1 %d %d %d\n", id++, reg, a, c, d);
        }
    fprintf(f, "$EndElements\n");
    fclose(f);
}

/* A Gmsh mesh that is not Delaunay: its lines keep their physical tags as
 * segment markers, the border between its two regions becomes segments
 * (marker 0) that no flip crosses, and the rest is flipped to the
 * constrained Delaunay triangulation that cvm_mesh_check() accepts. */
START_TEST(msh_regions_keep_their_border_when_flipped)
{
    enum { N = 6 };
    char path[4096];
    size_t ns, k, count[3] = {0, 0, 0};
    int32_t mk[8 * N];
    cvm_mesh *m;
    in_dir(path, sizeof path, "grid.msh");
    write_sheared_msh(path, N);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_msg(cvm_mesh_read(m, path) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert(read_flips(m) == N * N); /* every square's diagonal: none is on the border */
    ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_count(&ns, m, CVM_ENT_SEGMENT), CVM_OK);
    ck_assert_uint_eq(ns, 4 * N + N);
    ck_assert_int_eq(cvm_mesh_copy_markers(mk, ns, m, CVM_ENT_SEGMENT), CVM_OK);
    for (k = 0; k < ns; k++) {
        ck_assert(mk[k] == 0 || mk[k] == 7 || mk[k] == 8);
        count[mk[k] == 0 ? 0 : mk[k] == 7 ? 1 : 2]++;
    }
    ck_assert_uint_eq(count[0], N);
    ck_assert_uint_eq(count[1], N);
    ck_assert_uint_eq(count[2], 3 * N);
    cvm_mesh_free(m);
}
END_TEST

/* Two triangles that overlap without sharing an edge: with crossings split
 * the rebuild cannot reproduce them, with crossings refused their crossing
 * edges are named; both name a triangle. */
START_TEST(vtu_overlapping_triangles_are_named)
{
    static const char k_overlap[] =
        "<VTKFile type=\"UnstructuredGrid\"><UnstructuredGrid>"
        "<Piece NumberOfPoints=\"6\" NumberOfCells=\"2\"><Points>"
        "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">"
        "0 0 0 2 0 0 0 2 0 0.5 0.5 0 3 0.5 0 0.5 3 0</DataArray></Points><Cells>"
        "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0 1 2 3 4 5</DataArray>"
        "<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">3 6</DataArray>"
        "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">5 5</DataArray>"
        "</Cells></Piece></UnstructuredGrid></VTKFile>\n";
    char path[4096];
    cvm_mesh *m;
    cvm_entity kind;
    int64_t idx;
    in_dir(path, sizeof path, "overlap.vtu");
    write_text(path, k_overlap);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_read(m, path), CVM_E_INPUT_DEGENERATE);
    ck_assert_msg(strstr(cvm_mesh_errmsg(m), "is not a triangle of the constrained triangulation") &&
                      strstr(cvm_mesh_errmsg(m), "not a conforming triangulation"),
                  "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_error_item(&kind, &idx, m), CVM_OK);
    ck_assert_int_eq(kind, CVM_ENT_TRIANGLE);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_SPLIT_INTERSECTIONS, 0), CVM_OK);
    ck_assert_int_eq(cvm_mesh_read(m, path), CVM_E_INPUT_INTERSECTING);
    ck_assert_msg(strstr(cvm_mesh_errmsg(m), "overlaps triangle") != NULL, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_error_item(&kind, &idx, m), CVM_OK);
    ck_assert_int_eq(kind, CVM_ENT_TRIANGLE);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(vtu_unused_point_and_bad_cells_are_named)
{
    char path[4096], *t = malloc(sizeof k_bad_diagonal + 16);
    cvm_mesh *m;
    ck_assert_ptr_nonnull(t);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    in_dir(path, sizeof path, "x.vtu");
    /* point 3 moved onto the side 0-1 of the one triangle left: inside the
     * domain, yet no triangle's corner (outside, a point may be unused) */
    strcpy(t, k_bad_diagonal);
    memcpy(strstr(t, "0 1 2 0 2 3"), "0 1 2 0 2 1", 11);
    memcpy(strstr(t, "1 1 0</DataArray>"), "2 0 0", 5);
    write_text(path, t);
    ck_assert_int_eq(cvm_mesh_read(m, path), CVM_E_INPUT_DEGENERATE);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "point 3 at (2, 0) lies in the mesh but is a corner of no triangle"));
    strcpy(t, k_bad_diagonal);
    memcpy(strstr(t, "0 1 2 0 2 3"), "0 1 3 1 1 3", 11);
    write_text(path, t);
    ck_assert_int_eq(cvm_mesh_read(m, path), CVM_E_INPUT_DEGENERATE);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "triangle 1 (points 1 1 3) repeats a point"));
    strcpy(t, k_bad_diagonal);
    memcpy(strstr(t, "0 1 2 0 2 3"), "0 1 3 1 2 7", 11);
    write_text(path, t);
    ck_assert_int_eq(cvm_mesh_read(m, path), CVM_E_IO_FORMAT);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "cell 1 names point 7"));
    in_dir(path, sizeof path, "missing.vtu");
    ck_assert_int_eq(cvm_mesh_read(m, path), CVM_E_IO_OPEN);
    free(t);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(vtu_read_out_of_memory_at_every_allocation)
{
    char path[4096];
    cvm_mesh *src = holed_mesh(1), *m;
    cvmtest_alloc a;
    long k;
    size_t nt;
    in_dir(path, sizeof path, "oom.vtu");
    ck_assert_int_eq(cvm_mesh_write(src, path), CVM_OK);
    cvm_mesh_free(src);
    for (k = 1;; k++) {
        cvm_status s;
        cvmtest_alloc_init(&a, k, 0);
        if (cvmtest_mesh_create(&m, &a) != CVM_OK) {
            ck_assert_int_eq((int)a.live_blocks, 0);
            continue; /* the handle itself */
        }
        s = cvm_mesh_read(m, path);
        if (s == CVM_OK) {
            cvmtest_alloc_arm(&a, 0, 0);
            ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
            cvm_mesh_free(m);
            ck_assert_int_eq((int)a.live_blocks, 0);
            break;
        }
        ck_assert_msg(s == CVM_E_NOMEM, "allocation %ld: status %d (%s)", k, s, cvm_mesh_errmsg(m));
        ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE), CVM_OK);
        ck_assert_uint_eq(nt, 0);
        cvm_mesh_free(m);
        ck_assert_int_eq((int)a.live_blocks, 0);
    }
    ck_assert(k > 20);
}
END_TEST

/* The mesh of m as the bytes of a .vtu (points, markers, attributes,
 * weights, triangles, segments) and its input counts. */
static char *snapshot(cvm_mesh *m, const char *name, size_t *len, size_t *counts)
{
    char path[4096];
    char *t;
    in_dir(path, sizeof path, name);
    ck_assert_msg(cvm_mesh_write(m, path) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    t = iotest_slurp(path, len);
    ck_assert_ptr_nonnull(t);
    ck_assert_int_eq(cvm_mesh_count(&counts[0], m, CVM_ENT_INPUT_POINT), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&counts[1], m, CVM_ENT_INPUT_SEGMENT), CVM_OK);
    return t;
}

static void assert_unchanged(cvm_mesh *m, const char *before, size_t len, const size_t *counts)
{
    size_t l2, c2[2];
    char *after = snapshot(m, "after.vtu", &l2, c2);
    ck_assert_uint_eq(l2, len);
    ck_assert_msg(memcmp(before, after, len) == 0, "the previous mesh changed");
    ck_assert_uint_eq(c2[0], counts[0]);
    ck_assert_uint_eq(c2[1], counts[1]);
    ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    free(after);
}

/* The Delaunay diagonal 1-3 of the parallelogram above, and both diagonals
 * as line cells: they cross. */
static const char k_crossing_lines[] =
    "<VTKFile type=\"UnstructuredGrid\"><UnstructuredGrid>"
    "<Piece NumberOfPoints=\"4\" NumberOfCells=\"4\"><Points>"
    "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">"
    "0 0 0 3 0 0 4 1 0 1 1 0</DataArray></Points><Cells>"
    "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0 1 3 1 2 3 0 2 1 3</DataArray>"
    "<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">3 6 8 10</DataArray>"
    "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">5 5 3 3</DataArray>"
    "</Cells></Piece></UnstructuredGrid></VTKFile>\n";

/* Every way a read can fail - the file is missing, malformed, fails the
 * checks of its cells (an inverted triangle, a repeated point) or cannot be
 * rebuilt (crossing lines refused) - leaves the previous mesh of the handle
 * as it was, to the byte, with its input. */
START_TEST(vtu_failed_read_keeps_the_previous_mesh)
{
    static const struct { const char *from, *to; cvm_status want; const char *msg; } bad[] = {
        {NULL, NULL, CVM_E_IO_OPEN, "cannot open"},
        {"0 1 2 0 2 3", "0 1 3 1 2 7", CVM_E_IO_FORMAT, "cell 1 names point 7"},
        {"0 1 2 0 2 3", "0 1 2 0 2 1", CVM_E_INPUT_DEGENERATE, "triangle 1 (points 0 2 1) is inverted"},
        {"0 1 2 0 2 3", "0 1 2 1 2 1", CVM_E_INPUT_DEGENERATE, "repeats a point"},
        {"", "", CVM_E_INPUT_INTERSECTING,
         "rebuilding the mesh: segment 1 (points 1-3) crosses segment 0 (points 0-2)"},
    };
    cvm_mesh *m = holed_mesh(1);
    size_t len, counts[2], k;
    char *before = snapshot(m, "before.vtu", &len, counts), path[4096];
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_SPLIT_INTERSECTIONS, 0), CVM_OK);
    for (k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        char *t = malloc(sizeof k_crossing_lines + sizeof k_bad_diagonal);
        ck_assert_ptr_nonnull(t);
        strcpy(t, bad[k].want == CVM_E_INPUT_INTERSECTING ? k_crossing_lines : k_bad_diagonal);
        if (bad[k].from) {
            char *at = strstr(t, bad[k].from);
            ck_assert_ptr_nonnull(at);
            memmove(at + strlen(bad[k].to), at + strlen(bad[k].from), strlen(at + strlen(bad[k].from)) + 1);
            memcpy(at, bad[k].to, strlen(bad[k].to));
            in_dir(path, sizeof path, "bad.vtu");
            write_text(path, t);
        } else {
            in_dir(path, sizeof path, "missing.vtu");
        }
        free(t);
        ck_assert_int_eq(cvm_mesh_read(m, path), bad[k].want);
        ck_assert_msg(strstr(cvm_mesh_errmsg(m), bad[k].msg) != NULL, "case %lu: %s",
                      (unsigned long)k, cvm_mesh_errmsg(m));
        assert_unchanged(m, before, len, counts);
    }
    free(before);
    cvm_mesh_free(m);
}
END_TEST

/* Out of memory at each allocation of a read into a handle that holds a
 * mesh: CVM_E_NOMEM and the previous mesh unchanged, until the read succeeds
 * and gives the file's mesh. */
START_TEST(vtu_read_out_of_memory_keeps_the_previous_mesh)
{
    char path[4096];
    cvm_mesh *src = holed_mesh(2), *m;
    cvmtest_alloc a;
    size_t len, counts[2], l2, c2[2];
    char *before, *want, *got;
    long k;
    in_dir(path, sizeof path, "next.vtu");
    ck_assert_int_eq(cvm_mesh_write(src, path), CVM_OK);
    cvm_mesh_free(src);
    want = iotest_slurp(path, &l2);
    ck_assert_ptr_nonnull(want);
    cvmtest_alloc_init(&a, 0, 0);
    ck_assert_int_eq(cvmtest_mesh_create(&m, &a), CVM_OK);
    fill_holed(m, 1);
    before = snapshot(m, "before.vtu", &len, counts);
    for (k = 1;; k++) {
        cvm_status s;
        cvmtest_alloc_arm(&a, a.n_calls + k, 1);
        s = cvm_mesh_read(m, path);
        cvmtest_alloc_arm(&a, 0, 0);
        if (s == CVM_OK)
            break;
        ck_assert_msg(s == CVM_E_NOMEM, "allocation %ld: status %d (%s)", k, s, cvm_mesh_errmsg(m));
        assert_unchanged(m, before, len, counts);
    }
    ck_assert(k > 20);
    got = snapshot(m, "got.vtu", &len, c2);
    ck_assert_uint_eq(len, l2);
    ck_assert_msg(memcmp(want, got, len) == 0, "the mesh read differs from the file");
    free(before);
    free(want);
    free(got);
    cvm_mesh_free(m);
    ck_assert_int_eq((int)a.live_blocks, 0);
}
END_TEST

TCase *api_read_vtu_tcase(void)
{
    TCase *tc = tcase_create("read_vtu");
    tcase_set_timeout(tc, 120);
    tcase_add_checked_fixture(tc, setup, teardown);
    tcase_add_test(tc, vtu_round_trip_is_byte_identical);
    tcase_add_test(tc, vtu_round_trip_keeps_weights);
    tcase_add_test(tc, vtu_points_outside_the_domain_read_back);
    tcase_add_test(tc, vtu_round_trip_of_a_hole_grid);
    tcase_add_test(tc, vtu_round_trip_with_vanished_vertices);
    tcase_add_test(tc, vtu_non_delaunay_diagonal_is_flipped);
    tcase_add_test(tc, vtk_sheared_grid_is_flipped_to_delaunay);
    tcase_add_test(tc, vtk_sheared_grid_read_out_of_memory_at_every_allocation);
    tcase_add_test(tc, msh_regions_keep_their_border_when_flipped);
    tcase_add_test(tc, vtu_overlapping_triangles_are_named);
    tcase_add_test(tc, vtu_unused_point_and_bad_cells_are_named);
    tcase_add_test(tc, vtu_read_out_of_memory_at_every_allocation);
    tcase_add_test(tc, vtu_failed_read_keeps_the_previous_mesh);
    tcase_add_test(tc, vtu_read_out_of_memory_keeps_the_previous_mesh);
    return tc;
}
