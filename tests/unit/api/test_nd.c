/* test_nd.c - the dimension-generic mesh calls (lib/api/mesh_nd.c), cells of several types
 * (lib/api/cells.c) and the reports of the last run (cvm_mesh_get_report). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "api/api_tests.h"
#include "support/fixtures.h"
#include "support/oom_sweep.h"

#define SENTINEL (-7)

static cvm_mesh *square_with_hole(void)
{
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvmtest_pslg_set(m, &cvmtest_square_with_hole), CVM_OK);
    ck_assert_msg(cvm_mesh_triangulate(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    return m;
}

/* The square with its hole given through cvm_mesh_set_holes_nd(), refined to
 * many triangles so that neighbours and regions have something to show. */
static cvm_mesh *refined_square_nd(void)
{
    const cvmtest_pslg *p = &cvmtest_square_with_hole;
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, p->xy, p->np, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, p->seg, p->nseg), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_holes_nd(m, p->holes, p->nholes, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_MAX_AREA, 0.05), CVM_OK);
    ck_assert_msg(cvm_mesh_triangulate(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_msg(cvm_mesh_refine(m, NULL, CVM_ALGO_DELAUNAY) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    return m;
}

static size_t count(const cvm_mesh *m, cvm_entity kind)
{
    size_t n = 12345;
    ck_assert_int_eq(cvm_mesh_count(&n, m, kind), CVM_OK);
    return n;
}

START_TEST(every_mesh_is_2d)
{
    cvm_mesh *m;
    int32_t d = -1;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_dim(&d, m), CVM_OK);
    ck_assert_int_eq(d, 2);
    ck_assert_int_eq(cvm_mesh_dim(NULL, m), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_dim(&d, NULL), CVM_E_NULL_ARG);
    cvm_mesh_free(m);
    m = square_with_hole();
    d = -1;
    ck_assert_int_eq(cvm_mesh_dim(&d, m), CVM_OK);
    ck_assert_int_eq(d, 2);
    cvm_mesh_free(m);
}
END_TEST

/* Setters: dim 3 is CVM_E_UNSUPPORTED saying why, another dim CVM_E_ARGUMENT;
 * either way the previous input stays. */
START_TEST(setters_refuse_other_dimensions_and_keep_input)
{
    static const double hole[] = {1.5, 1.5, 0};
    static const double region[] = {0.5, 0.5, 7, 0, 0};
    cvm_mesh *m = square_with_hole();
    ck_assert_int_eq(cvm_mesh_set_holes_nd(m, hole, 1, 3), CVM_E_UNSUPPORTED);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "3D kernel"));
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "cvm_mesh_set_holes_nd"));
    ck_assert_int_eq(cvm_mesh_set_holes_nd(m, hole, 1, 1), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "got 1"));
    ck_assert_int_eq(cvm_mesh_set_holes_nd(m, NULL, 1, 2), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_set_holes_nd(NULL, hole, 1, 2), CVM_E_NULL_ARG);
    ck_assert_uint_eq(count(m, CVM_ENT_HOLE), 1);
    ck_assert_uint_eq(count(m, CVM_ENT_TRIANGLE), 8); /* the mesh was not dropped */

    ck_assert_int_eq(cvm_mesh_set_regions_nd(m, region, 1, 3), CVM_E_UNSUPPORTED);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "3D kernel"));
    ck_assert_int_eq(cvm_mesh_set_regions_nd(m, region, 1, 0), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_mesh_set_regions_nd(m, NULL, 1, 2), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_set_regions_nd(NULL, region, 1, 2), CVM_E_NULL_ARG);
    ck_assert_uint_eq(count(m, CVM_ENT_REGION), 0);
    ck_assert_uint_eq(count(m, CVM_ENT_TRIANGLE), 8);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(nonfinite_hole_and_region_name_the_item)
{
    double hole[4] = {1.5, 1.5, 0, 0};
    double region[8] = {0.5, 0.5, 7, 0, 2.5, 2.5, 3, 0};
    cvm_mesh *m = square_with_hole();
    cvm_entity kind;
    int64_t index;
    hole[3] = NAN;
    ck_assert_int_eq(cvm_mesh_set_holes_nd(m, hole, 2, 2), CVM_E_INPUT_NONFINITE);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "hole 1"));
    ck_assert_int_eq(cvm_mesh_error_item(&kind, &index, m), CVM_OK);
    ck_assert_int_eq(kind, CVM_ENT_HOLE);
    ck_assert_int_eq(index, 1);
    ck_assert_uint_eq(count(m, CVM_ENT_HOLE), 1);
    region[6] = INFINITY;
    ck_assert_int_eq(cvm_mesh_set_regions_nd(m, region, 2, 2), CVM_E_INPUT_NONFINITE);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "region 1"));
    cvm_mesh_free(m);
}
END_TEST

/* The 2D calls and the _nd calls with dim 2 give the same mesh, byte for byte. */
START_TEST(nd_input_gives_the_mesh_of_the_2d_calls)
{
    static const double region[] = {0.5, 0.5, 7, 0.02};
    static const double extra[] = {0.25, 0.75, 2.5, 2.75, 1.5, 1.5};
    const cvmtest_pslg *p = &cvmtest_square_with_hole;
    cvm_mesh *a, *b;
    cvm_index ida[3], idb[3];
    size_t nv, nt;
    double *xa, *xb;
    cvm_index *ta, *tb;
    ck_assert_int_eq(cvm_mesh_create(&a), CVM_OK);
    ck_assert_int_eq(cvm_mesh_create(&b), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(a, p->xy, p->np, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(b, p->xy, p->np, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(a, p->seg, p->nseg), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(b, p->seg, p->nseg), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_holes(a, p->holes, p->nholes), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_holes_nd(b, p->holes, p->nholes, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_regions(a, region, 1), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_regions_nd(b, region, 1, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(a), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(b), CVM_OK);
    ck_assert_int_eq(cvm_mesh_refine(a, NULL, CVM_ALGO_DELAUNAY), CVM_OK);
    ck_assert_int_eq(cvm_mesh_refine(b, NULL, CVM_ALGO_DELAUNAY), CVM_OK);
    ck_assert_int_eq(cvm_mesh_insert_points(ida, a, extra, 3, 0.0), CVM_OK);
    ck_assert_int_eq(cvm_mesh_insert_points_nd(idb, b, extra, 3, 2, 0.0), CVM_OK);
    ck_assert_mem_eq(ida, idb, sizeof ida);
    ck_assert_int_eq(idb[2], CVM_REJECTED); /* in the hole */
    ck_assert_int_ge(idb[0], 0);
    nv = count(a, CVM_ENT_VERTEX);
    nt = count(a, CVM_ENT_TRIANGLE);
    ck_assert_uint_eq(count(b, CVM_ENT_VERTEX), nv);
    ck_assert_uint_eq(count(b, CVM_ENT_TRIANGLE), nt);
    ck_assert_uint_gt(nt, 8); /* the region's area bound refined its part */
    xa = malloc(2 * nv * sizeof *xa);
    xb = malloc(2 * nv * sizeof *xb);
    ta = malloc(3 * nt * sizeof *ta);
    tb = malloc(3 * nt * sizeof *tb);
    ck_assert(xa && xb && ta && tb);
    ck_assert_int_eq(cvm_mesh_copy_points(xa, 2 * nv, a), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_points_nd(xb, 2 * nv, 2, b), CVM_OK);
    ck_assert_mem_eq(xa, xb, 2 * nv * sizeof *xa);
    ck_assert_int_eq(cvm_mesh_copy_cells(ta, 3 * nt, a, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(tb, 3 * nt, b, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_mem_eq(ta, tb, 3 * nt * sizeof *ta);
    /* the region's attribute reached its triangles */
    {
        double *attr = malloc(nt * sizeof *attr);
        size_t k, n7 = 0;
        ck_assert_ptr_nonnull(attr);
        ck_assert_int_eq(cvm_mesh_copy_cell_attributes(attr, nt, b, CVM_ENT_CELL), CVM_OK);
        for (k = 0; k < nt; k++) {
            ck_assert(attr[k] == 0 || attr[k] == 7);
            n7 += attr[k] == 7;
        }
        ck_assert_uint_eq(n7, nt); /* one region, the whole connected domain */
        free(attr);
    }
    free(xa);
    free(xb);
    free(ta);
    free(tb);
    cvm_mesh_free(a);
    cvm_mesh_free(b);
}
END_TEST

START_TEST(insert_points_nd_refuses_other_dimensions)
{
    static const double pt[] = {0.5, 0.5, 0.5};
    cvm_index id = 99;
    cvm_mesh *m = square_with_hole();
    ck_assert_int_eq(cvm_mesh_insert_points_nd(&id, m, pt, 1, 3, 0.0), CVM_E_UNSUPPORTED);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "3D kernel"));
    ck_assert_int_eq(cvm_mesh_insert_points_nd(&id, m, pt, 1, 4, 0.0), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_mesh_insert_points_nd(&id, m, NULL, 1, 2, 0.0), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_insert_points_nd(&id, NULL, pt, 1, 2, 0.0), CVM_E_NULL_ARG);
    ck_assert_int_eq(id, 99);
    ck_assert_uint_eq(count(m, CVM_ENT_VERTEX), 8);
    cvm_mesh_free(m);
}
END_TEST

/* Const readers: dim 3 CVM_E_UNSUPPORTED, other dims CVM_E_ARGUMENT, short buffers
 * CVM_E_BUFFER_TOO_SMALL; nothing written in any case. */
START_TEST(nd_copies_check_dim_and_room)
{
    cvm_mesh *m = square_with_hole();
    double buf[64];
    size_t k;
    for (k = 0; k < 64; k++)
        buf[k] = SENTINEL;
    ck_assert_int_eq(cvm_mesh_copy_points_nd(buf, 64, 3, m), CVM_E_UNSUPPORTED);
    ck_assert_int_eq(cvm_mesh_copy_points_nd(buf, 64, 1, m), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_mesh_copy_points_nd(buf, 15, 2, m), CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_points_nd(NULL, 16, 2, m), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_points_nd(buf, 16, 2, NULL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_dual_vertices_nd(buf, 64, 3, m), CVM_E_UNSUPPORTED);
    ck_assert_int_eq(cvm_mesh_copy_dual_vertices_nd(buf, 64, -2, m), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_mesh_copy_dual_vertices_nd(buf, 15, 2, m), CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_dual_vertices_nd(NULL, 16, 2, m), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_dual_vertices_nd(buf, 16, 2, NULL), CVM_E_NULL_ARG);
    for (k = 0; k < 64; k++)
        ck_assert(buf[k] == SENTINEL);
    /* and the right size gives the 2D copy */
    {
        double a[16], b[16];
        ck_assert_int_eq(cvm_mesh_copy_dual_vertices(a, 16, m), CVM_OK);
        ck_assert_int_eq(cvm_mesh_copy_dual_vertices_nd(b, 16, 2, m), CVM_OK);
        ck_assert_mem_eq(a, b, sizeof a);
    }
    cvm_mesh_free(m);
}
END_TEST

START_TEST(view_points_nd_is_the_2d_view_with_its_dim)
{
    cvm_mesh *m = square_with_hole();
    const double *p = NULL, *q = NULL;
    size_t n = 0, n2 = 0;
    int32_t d = 0;
    ck_assert_int_eq(cvm_mesh_view_points(&p, &n, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_view_points_nd(&q, &n2, &d, m), CVM_OK);
    ck_assert_ptr_eq(p, q);
    ck_assert_uint_eq(n, n2);
    ck_assert_uint_eq(n, 8);
    ck_assert_int_eq(d, 2);
    ck_assert_int_eq(cvm_mesh_view_points_nd(NULL, &n2, &d, m), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_view_points_nd(&q, NULL, &d, m), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_view_points_nd(&q, &n2, NULL, m), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_view_points_nd(&q, &n2, &d, NULL), CVM_E_NULL_ARG);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(mixed_cells_are_the_triangles_with_offsets_and_types)
{
    cvm_mesh *m = refined_square_nd();
    size_t nc = 0, nconn = 0, nt = count(m, CVM_ENT_TRIANGLE), c;
    cvm_index *off, *conn, *tri;
    int32_t *types;
    ck_assert_int_eq(cvm_mesh_count_cells_mixed(&nc, &nconn, m, CVM_ENT_CELL), CVM_OK);
    ck_assert_uint_eq(nc, nt);
    ck_assert_uint_eq(nconn, 3 * nt);
    off = malloc((nc + 1) * sizeof *off);
    types = malloc(nc * sizeof *types);
    conn = malloc(nconn * sizeof *conn);
    tri = malloc(nconn * sizeof *tri);
    ck_assert(off && types && conn && tri);
    ck_assert_int_eq(cvm_mesh_copy_cells_mixed(off, nc + 1, types, nc, conn, nconn, m, CVM_ENT_CELL),
                     CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(tri, nconn, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_mem_eq(conn, tri, nconn * sizeof *conn);
    ck_assert_int_eq(off[0], 0);
    for (c = 0; c < nc; c++) {
        ck_assert_int_eq(types[c], CVM_CELL_TRIANGLE);
        ck_assert_int_eq(off[c + 1] - off[c], 3);
    }
    ck_assert_int_eq(off[nc], (cvm_index)nconn);
    ck_assert_int_eq(CVM_CELL_TRIANGLE, 5); /* VTK_TRIANGLE */
    ck_assert_int_eq(CVM_CELL_QUAD, 9);     /* VTK_QUAD */
    ck_assert_int_eq(CVM_CELL_TETRAHEDRON, 10);
    free(off);
    free(types);
    free(conn);
    free(tri);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(mixed_cells_check_every_buffer_before_writing)
{
    cvm_mesh *m = square_with_hole(); /* 8 triangles */
    cvm_index off[9], conn[24];
    int32_t types[8];
    size_t nc, nconn, k;
    for (k = 0; k < 9; k++)
        off[k] = SENTINEL;
    for (k = 0; k < 8; k++)
        types[k] = SENTINEL;
    for (k = 0; k < 24; k++)
        conn[k] = SENTINEL;
    ck_assert_int_eq(cvm_mesh_copy_cells_mixed(off, 8, types, 8, conn, 24, m, CVM_ENT_CELL),
                     CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_cells_mixed(off, 9, types, 7, conn, 24, m, CVM_ENT_CELL),
                     CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_cells_mixed(off, 9, types, 8, conn, 23, m, CVM_ENT_CELL),
                     CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_cells_mixed(NULL, 9, types, 8, conn, 24, m, CVM_ENT_CELL),
                     CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_cells_mixed(off, 9, NULL, 8, conn, 24, m, CVM_ENT_CELL),
                     CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_cells_mixed(off, 9, types, 8, NULL, 24, m, CVM_ENT_CELL),
                     CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_cells_mixed(off, 9, types, 8, conn, 24, NULL, CVM_ENT_CELL),
                     CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_cells_mixed(off, 9, types, 8, conn, 24, m, CVM_ENT_TRIANGLE),
                     CVM_E_ARGUMENT);
    for (k = 0; k < 9; k++)
        ck_assert_int_eq(off[k], SENTINEL);
    for (k = 0; k < 8; k++)
        ck_assert_int_eq(types[k], SENTINEL);
    for (k = 0; k < 24; k++)
        ck_assert_int_eq(conn[k], SENTINEL);
    ck_assert_int_eq(cvm_mesh_count_cells_mixed(NULL, &nconn, m, CVM_ENT_CELL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_count_cells_mixed(&nc, NULL, m, CVM_ENT_CELL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_count_cells_mixed(&nc, &nconn, NULL, CVM_ENT_CELL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_count_cells_mixed(&nc, &nconn, m, CVM_ENT_EDGE), CVM_E_ARGUMENT);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(mixed_cells_before_triangulation_are_empty)
{
    cvm_mesh *m;
    size_t nc = 9, nconn = 9;
    cvm_index off[1] = {SENTINEL};
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count_cells_mixed(&nc, &nconn, m, CVM_ENT_CELL), CVM_OK);
    ck_assert_uint_eq(nc, 0);
    ck_assert_uint_eq(nconn, 0);
    ck_assert_int_eq(cvm_mesh_copy_cells_mixed(off, 0, NULL, 0, NULL, 0, m, CVM_ENT_CELL),
                     CVM_E_BUFFER_TOO_SMALL); /* offsets always need nc + 1 */
    ck_assert_int_eq(cvm_mesh_copy_cells_mixed(off, 1, NULL, 0, NULL, 0, m, CVM_ENT_CELL), CVM_OK);
    ck_assert_int_eq(off[0], 0);
    cvm_mesh_free(m);
}
END_TEST

/* Across face k of cell c lies d: then c is a neighbour of d, and the two
 * share exactly the face (the two vertices of c other than vertex k). */
START_TEST(cell_neighbours_are_symmetric_and_share_the_face)
{
    cvm_mesh *m = refined_square_nd();
    size_t nt = count(m, CVM_ENT_TRIANGLE), c;
    cvm_index *nb = malloc(3 * nt * sizeof *nb), *nb2 = malloc(3 * nt * sizeof *nb2);
    cvm_index *tri = malloc(3 * nt * sizeof *tri);
    size_t boundary = 0;
    int k;
    ck_assert(nb && nb2 && tri);
    ck_assert_int_eq(cvm_mesh_copy_cell_neighbors(nb, 3 * nt, m, CVM_ENT_CELL), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cell_neighbors(nb2, 3 * nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_mem_eq(nb, nb2, 3 * nt * sizeof *nb);
    ck_assert_int_eq(cvm_mesh_copy_neighbors(nb2, 3 * nt, m), CVM_OK);
    ck_assert_mem_eq(nb, nb2, 3 * nt * sizeof *nb);
    ck_assert_int_eq(cvm_mesh_copy_cells(tri, 3 * nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    for (c = 0; c < nt; c++)
        for (k = 0; k < 3; k++) {
            cvm_index d = nb[3 * c + (size_t)k];
            cvm_index a = tri[3 * c + (size_t)(k + 1) % 3], b = tri[3 * c + (size_t)(k + 2) % 3];
            int j, back = 0, shared = 0;
            if (d < 0) {
                boundary++;
                continue;
            }
            ck_assert_int_lt(d, (cvm_index)nt);
            for (j = 0; j < 3; j++) {
                cvm_index v = tri[3 * (size_t)d + (size_t)j];
                back += nb[3 * (size_t)d + (size_t)j] == (cvm_index)c;
                shared += v == a || v == b;
            }
            ck_assert_int_eq(back, 1);
            ck_assert_int_eq(shared, 2);
        }
    ck_assert_uint_eq(boundary, count(m, CVM_ENT_SEGMENT)); /* each boundary face is a segment */
    free(nb);
    free(nb2);
    free(tri);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(cell_neighbours_and_attributes_check_their_arguments)
{
    cvm_mesh *m = square_with_hole();
    cvm_index nb[24];
    double at[8], at2[8];
    size_t k;
    for (k = 0; k < 24; k++)
        nb[k] = SENTINEL;
    ck_assert_int_eq(cvm_mesh_copy_cell_neighbors(nb, 24, m, CVM_ENT_TETRAHEDRON), CVM_E_UNSUPPORTED);
    ck_assert_int_eq(cvm_mesh_copy_cell_neighbors(nb, 24, m, CVM_ENT_VERTEX), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_mesh_copy_cell_neighbors(nb, 23, m, CVM_ENT_CELL), CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_cell_neighbors(NULL, 24, m, CVM_ENT_CELL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_cell_neighbors(nb, 24, NULL, CVM_ENT_CELL), CVM_E_NULL_ARG);
    for (k = 0; k < 24; k++)
        ck_assert_int_eq(nb[k], SENTINEL);
    for (k = 0; k < 8; k++)
        at[k] = SENTINEL;
    ck_assert_int_eq(cvm_mesh_copy_cell_attributes(at, 8, m, CVM_ENT_EDGE), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_mesh_copy_cell_attributes(at, 7, m, CVM_ENT_CELL), CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_cell_attributes(NULL, 8, m, CVM_ENT_CELL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_cell_attributes(at, 8, NULL, CVM_ENT_CELL), CVM_E_NULL_ARG);
    for (k = 0; k < 8; k++)
        ck_assert(at[k] == SENTINEL);
    ck_assert_int_eq(cvm_mesh_copy_cell_attributes(at, 8, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_triangle_attributes(at2, 8, m), CVM_OK);
    ck_assert_mem_eq(at, at2, sizeof at);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(reports_equal_the_measures_of_the_same_number)
{
    static const cvm_report refine[] = {
        CVM_REPORT_REFINE_STEINER, CVM_REPORT_REFINE_UNMET_ANGLE, CVM_REPORT_REFINE_UNMET_SIZE,
        CVM_REPORT_REFINE_SMALL_INPUT_ANGLE, CVM_REPORT_REFINE_REQUESTED_ANGLE,
        CVM_REPORT_REFINE_MET_ANGLE};
    cvm_mesh *m = refined_square_nd();
    double r, v;
    size_t k;
    int w;
    for (k = 0; k < sizeof refine / sizeof refine[0]; k++) {
        ck_assert_int_eq(cvm_mesh_get_report(&r, m, refine[k]), CVM_OK);
        ck_assert_int_eq(cvm_mesh_get_measure(&v, m, (cvm_measure)refine[k]), CVM_OK);
        ck_assert(r == v);
    }
    ck_assert_int_eq(cvm_mesh_get_report(&r, m, CVM_REPORT_REFINE_STEINER), CVM_OK);
    ck_assert(r > 0);
    ck_assert_int_eq(cvm_mesh_get_report(&r, m, CVM_REPORT_REFINE_REQUESTED_ANGLE), CVM_OK);
    ck_assert(r == 30); /* the default CVM_OPT_MIN_ANGLE_DEG */
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL_MAX_SWEEPS, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL_MAXMIN_ROUNDS, 0), CVM_OK);
    ck_assert_int_lt(cvm_mesh_optimise_dual(m, NULL), 40); /* OK or incomplete */
    for (w = CVM_REPORT_DUAL_OPT_SWEEPS; w <= CVM_REPORT_DUAL_OPT_REMOVED_MAXMIN; w++) {
        ck_assert_int_eq(cvm_mesh_get_report(&r, m, (cvm_report)w), CVM_OK);
        ck_assert_int_eq(cvm_mesh_get_measure(&v, m, (cvm_measure)w), CVM_OK);
        if (w != CVM_REPORT_DUAL_OPT_SECONDS)
            ck_assert(r == v);
    }
    /* measures of the mesh are not reports */
    ck_assert_int_eq(cvm_mesh_get_report(&r, m, (cvm_report)CVM_MEASURE_MIN_ANGLE_DEG), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_mesh_get_report(&r, m, (cvm_report)CVM_MEASURE_DUAL_MERGED_PCT),
                     CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_mesh_get_report(&r, m, (cvm_report)700), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_mesh_get_report(NULL, m, CVM_REPORT_REFINE_STEINER), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_get_report(&r, NULL, CVM_REPORT_REFINE_STEINER), CVM_E_NULL_ARG);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(reports_are_zero_before_any_run)
{
    cvm_mesh *m;
    double r = -1;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_get_report(&r, m, CVM_REPORT_REFINE_STEINER), CVM_OK);
    ck_assert(r == 0);
    r = -1;
    ck_assert_int_eq(cvm_mesh_get_report(&r, m, CVM_REPORT_DUAL_OPT_SWEEPS), CVM_OK);
    ck_assert(r == 0);
    cvm_mesh_free(m);
}
END_TEST

static int metric_identity(void *payload, const double *x, int dim, double *g, double *dg)
{
    (void)payload;
    (void)x;
    (void)dim;
    (void)dg;
    g[0] = 1;
    g[1] = 0;
    g[2] = 1;
    return 0;
}

/* A metric is never ignored: the refiners and the dual optimiser refuse it. */
START_TEST(refine_and_optimise_refuse_a_metric)
{
    cvm_mesh *m = square_with_hole();
    cvm_sizing *s;
    size_t nv = count(m, CVM_ENT_VERTEX);
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_metric_fn(s, metric_identity, 0, NULL), CVM_OK);
    ck_assert_int_eq(cvm_mesh_refine(m, s, CVM_ALGO_FRONTAL), CVM_E_UNSUPPORTED);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "metric"));
    ck_assert_uint_eq(count(m, CVM_ENT_VERTEX), nv);
    ck_assert_int_eq(cvm_mesh_optimise_dual(m, s), CVM_E_UNSUPPORTED);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "cvm_mesh_optimise_dual"));
    /* with scalar sources beside it, still refused */
    ck_assert_int_eq(cvm_sizing_set_uniform(s, 0.3), CVM_OK);
    ck_assert_int_eq(cvm_mesh_refine(m, s, CVM_ALGO_DELAUNAY), CVM_E_UNSUPPORTED);
    ck_assert_uint_eq(count(m, CVM_ENT_VERTEX), nv);
    /* removed: the scalar sizing refines */
    ck_assert_int_eq(cvm_sizing_set_metric_fn(s, NULL, 0, NULL), CVM_OK);
    ck_assert_int_eq(cvm_mesh_refine(m, s, CVM_ALGO_DELAUNAY), CVM_OK);
    ck_assert_uint_gt(count(m, CVM_ENT_VERTEX), nv);
    cvm_sizing_free(s);
    cvm_mesh_free(m);
}
END_TEST

/* Out of memory at every allocation of the _nd input calls, a triangulation
 * and the neighbour copy (which allocates a map): a status, no leak. */
static void nd_oom_setup(cvm_mesh *m, void *arg)
{
    const cvmtest_pslg *p = &cvmtest_square_with_hole;
    (void)arg;
    ck_assert_int_eq(cvm_mesh_set_points(m, p->xy, p->np, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, p->seg, p->nseg), CVM_OK);
}

static cvm_status nd_oom_run(cvm_mesh *m, void *arg)
{
    static const double region[] = {0.5, 0.5, 3, 0.1};
    static const double extra[] = {0.25, 0.75, 2.5, 2.75};
    const cvmtest_pslg *p = &cvmtest_square_with_hole;
    cvm_index ids[2], nb[256];
    size_t nt;
    cvm_status s;
    (void)arg;
    if ((s = cvm_mesh_set_holes_nd(m, p->holes, p->nholes, 2)) ||
        (s = cvm_mesh_set_regions_nd(m, region, 1, 2)) || (s = cvm_mesh_triangulate(m)) ||
        (s = cvm_mesh_insert_points_nd(ids, m, extra, 2, 2, 0.0)))
        return s;
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_uint_le(3 * nt, 256);
    return cvm_mesh_copy_cell_neighbors(nb, 256, m, CVM_ENT_CELL);
}

START_TEST(nd_calls_out_of_memory_is_a_status)
{
    cvmtest_oom_sweep(nd_oom_setup, nd_oom_run, NULL, NULL);
}
END_TEST

TCase *api_nd_tcase(void)
{
    TCase *tc = tcase_create("nd");
    tcase_add_test(tc, every_mesh_is_2d);
    tcase_add_test(tc, setters_refuse_other_dimensions_and_keep_input);
    tcase_add_test(tc, nonfinite_hole_and_region_name_the_item);
    tcase_add_test(tc, nd_input_gives_the_mesh_of_the_2d_calls);
    tcase_add_test(tc, insert_points_nd_refuses_other_dimensions);
    tcase_add_test(tc, nd_copies_check_dim_and_room);
    tcase_add_test(tc, view_points_nd_is_the_2d_view_with_its_dim);
    tcase_add_test(tc, mixed_cells_are_the_triangles_with_offsets_and_types);
    tcase_add_test(tc, mixed_cells_check_every_buffer_before_writing);
    tcase_add_test(tc, mixed_cells_before_triangulation_are_empty);
    tcase_add_test(tc, cell_neighbours_are_symmetric_and_share_the_face);
    tcase_add_test(tc, cell_neighbours_and_attributes_check_their_arguments);
    tcase_add_test(tc, reports_equal_the_measures_of_the_same_number);
    tcase_add_test(tc, reports_are_zero_before_any_run);
    tcase_add_test(tc, refine_and_optimise_refuse_a_metric);
    tcase_add_test(tc, nd_calls_out_of_memory_is_a_status);
    return tc;
}
