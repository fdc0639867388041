/* test_output.c - counts, copies and views of the output (lib/api/output.c, domain.c). */
#include <stdlib.h>
#include <string.h>

#include "api/api_tests.h"
#include "support/failing_alloc.h"
#include "support/fixtures.h"

static cvm_mesh *square_with_hole(void)
{
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvmtest_pslg_set(m, &cvmtest_square_with_hole), CVM_OK);
    ck_assert_msg(cvm_mesh_triangulate(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    return m;
}

static size_t count(const cvm_mesh *m, cvm_entity kind)
{
    size_t n = 12345;
    ck_assert_int_eq(cvm_mesh_count(&n, m, kind), CVM_OK);
    return n;
}

START_TEST(counts_of_square_with_hole)
{
    cvm_mesh *m = square_with_hole();
    ck_assert_uint_eq(count(m, CVM_ENT_VERTEX), 8);
    ck_assert_uint_eq(count(m, CVM_ENT_TRIANGLE), 8);
    ck_assert_uint_eq(count(m, CVM_ENT_EDGE), 16);
    ck_assert_uint_eq(count(m, CVM_ENT_SEGMENT), 8);
    ck_assert_uint_eq(count(m, CVM_ENT_INPUT_POINT), 8);
    ck_assert_uint_eq(count(m, CVM_ENT_INPUT_SEGMENT), 8);
    ck_assert_uint_eq(count(m, CVM_ENT_HOLE), 1);
    ck_assert_uint_eq(count(m, CVM_ENT_REGION), 0);
    ck_assert_uint_eq(count(m, CVM_ENT_DUPLICATE), 0);
    {
        size_t n;
        ck_assert_int_eq(cvm_mesh_count(&n, m, CVM_ENT_FILE_LINE), CVM_E_ARGUMENT);
        ck_assert_int_eq(cvm_mesh_count(&n, m, (cvm_entity)99), CVM_E_ARGUMENT);
        ck_assert_int_eq(cvm_mesh_count(NULL, m, CVM_ENT_VERTEX), CVM_E_NULL_ARG);
        ck_assert_int_eq(cvm_mesh_count(&n, NULL, CVM_ENT_VERTEX), CVM_E_NULL_ARG);
    }
    cvm_mesh_free(m);
}
END_TEST

START_TEST(nothing_before_triangulation)
{
    cvm_mesh *m;
    cvm_index buf[4];
    const double *xy = (const double *)1;
    size_t n = 7;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvmtest_pslg_set(m, &cvmtest_unit_square), CVM_OK);
    ck_assert_uint_eq(count(m, CVM_ENT_VERTEX), 0);
    ck_assert_uint_eq(count(m, CVM_ENT_TRIANGLE), 0);
    ck_assert_uint_eq(count(m, CVM_ENT_EDGE), 0);
    ck_assert_uint_eq(count(m, CVM_ENT_INPUT_POINT), 4);
    ck_assert_int_eq(cvm_mesh_copy_cells(buf, 4, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(NULL, 0, m, CVM_ENT_EDGE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_input_map(buf, 4, m), CVM_E_STATE);
    ck_assert_int_eq(cvm_mesh_view_points(&xy, &n, m), CVM_OK);
    ck_assert_uint_eq(n, 0);
    ck_assert_ptr_null(xy);
    cvm_mesh_free(m);
}
END_TEST

static int cmp_edge(const cvm_index *a, const cvm_index *b)
{
    return a[0] != b[0] ? (a[0] < b[0] ? -1 : 1) : a[1] != b[1] ? (a[1] < b[1] ? -1 : 1) : 0;
}

START_TEST(edges_are_unique_sorted_and_cover_every_triangle)
{
    cvm_mesh *m = square_with_hole();
    size_t nt = count(m, CVM_ENT_TRIANGLE), ne = count(m, CVM_ENT_EDGE), t, k, e;
    cvm_index *tri = malloc(3 * nt * sizeof *tri), *edges = malloc(2 * ne * sizeof *edges);
    ck_assert_int_eq(cvm_mesh_copy_cells(tri, 3 * nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(edges, 2 * ne, m, CVM_ENT_EDGE), CVM_OK);
    for (e = 0; e < ne; e++) {
        ck_assert_int_lt(edges[2 * e], edges[2 * e + 1]);
        if (e)
            ck_assert_int_lt(cmp_edge(edges + 2 * (e - 1), edges + 2 * e), 0);
    }
    for (t = 0; t < nt; t++)
        for (k = 0; k < 3; k++) {
            cvm_index a = tri[3 * t + k], b = tri[3 * t + (k + 1) % 3];
            cvm_index key[2];
            int found = 0;
            key[0] = a < b ? a : b;
            key[1] = a < b ? b : a;
            for (e = 0; e < ne; e++)
                found += cmp_edge(edges + 2 * e, key) == 0;
            ck_assert_int_eq(found, 1);
        }
    free(tri);
    free(edges);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(neighbours_are_symmetric_and_share_the_opposite_edge)
{
    cvm_mesh *m = square_with_hole();
    size_t nt = count(m, CVM_ENT_TRIANGLE), t, boundary = 0;
    int k;
    cvm_index *tri = malloc(3 * nt * sizeof *tri), *nb = malloc(3 * nt * sizeof *nb);
    ck_assert_int_eq(cvm_mesh_copy_cells(tri, 3 * nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_neighbors(nb, 3 * nt, m), CVM_OK);
    for (t = 0; t < nt; t++)
        for (k = 0; k < 3; k++) {
            cvm_index u = nb[3 * t + k], a = tri[3 * t + (k + 1) % 3], b = tri[3 * t + (k + 2) % 3];
            int j, back = 0;
            if (u < 0) {
                boundary++;
                continue;
            }
            ck_assert_int_lt(u, (int)nt);
            for (j = 0; j < 3; j++)
                if (nb[3 * u + j] == (cvm_index)t) {
                    /* edge j of u is b-a */
                    ck_assert_int_eq(tri[3 * u + (j + 1) % 3], b);
                    ck_assert_int_eq(tri[3 * u + (j + 2) % 3], a);
                    back++;
                }
            ck_assert_int_eq(back, 1);
        }
    ck_assert_uint_eq(boundary, 8);
    free(tri);
    free(nb);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(segments_carry_their_markers)
{
    static const int32_t smark[] = {11, 12, 13, 14, 21, 22, 23, 24};
    static const int32_t pmark[] = {1, 1, 1, 1, 0, 0, 0, 2};
    const cvmtest_pslg *p = &cvmtest_square_with_hole;
    cvm_mesh *m;
    cvm_index seg[16], map[8];
    int32_t mk[16], vm[8];
    size_t k, j;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvmtest_pslg_set(m, p), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segment_markers(m, smark, 8), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_point_markers(m, pmark, 8), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(seg, 16, m, CVM_ENT_SEGMENT), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_markers(mk, 8, m, CVM_ENT_SEGMENT), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_input_map(map, 8, m), CVM_OK);
    for (k = 0; k < 8; k++) {
        int found = 0;
        for (j = 0; j < 8; j++) {
            cvm_index a = map[p->seg[2 * j]], b = map[p->seg[2 * j + 1]];
            if ((seg[2 * k] == a && seg[2 * k + 1] == b) || (seg[2 * k] == b && seg[2 * k + 1] == a)) {
                ck_assert_int_eq(mk[k], smark[j]);
                found = 1;
            }
        }
        ck_assert(found);
    }
    ck_assert_int_eq(cvm_mesh_copy_markers(vm, 8, m, CVM_ENT_VERTEX), CVM_OK);
    for (k = 0; k < 8; k++) /* a 0 marker on a segment takes the segment's (as Triangle) */
        if (pmark[k])
            ck_assert_int_eq(vm[map[k]], pmark[k]);
    ck_assert_int_eq(cvm_mesh_copy_markers(vm, 8, m, CVM_ENT_TRIANGLE), CVM_E_ARGUMENT);
    /* without segment markers every segment has marker 1 */
    ck_assert_int_eq(cvm_mesh_set_segment_markers(m, NULL, 0), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_markers(mk, 8, m, CVM_ENT_SEGMENT), CVM_OK);
    for (k = 0; k < 8; k++)
        ck_assert_int_eq(mk[k], 1);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(duplicates_map_to_their_first_occurrence)
{
    static const double xy[] = {0, 0, 1, 0, 0, 1, 1, 0, 1, 1};
    cvm_mesh *m;
    cvm_index map[5];
    double pts[8];
    const double *view;
    size_t n;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 5, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_uint_eq(count(m, CVM_ENT_DUPLICATE), 1);
    ck_assert_uint_eq(count(m, CVM_ENT_VERTEX), 4);
    ck_assert_int_eq(cvm_mesh_copy_input_map(map, 5, m), CVM_OK);
    ck_assert_int_eq(map[3], map[1]);
    ck_assert_int_eq(cvm_mesh_copy_points(pts, 8, m), CVM_OK);
    ck_assert(pts[2 * map[4]] == 1 && pts[2 * map[4] + 1] == 1);
    ck_assert_int_eq(cvm_mesh_view_points(&view, &n, m), CVM_OK);
    ck_assert_uint_eq(n, 4);
    ck_assert_int_eq(memcmp(view, pts, sizeof pts), 0);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(attributes_of_triangles_and_points)
{
    static const double xy[] = {0, 0, 2, 0, 2, 1, 0, 1, 1, 0, 1, 1};
    static const cvm_index seg[] = {0, 4, 4, 1, 1, 2, 2, 5, 5, 3, 3, 0, 4, 5};
    static const double regions[] = {0.5, 0.5, 7, 0, 1.5, 0.5, 9, 0};
    static const double pattr[] = {1, 10, 2, 20, 3, 30, 4, 40, 5, 50, 6, 60};
    cvm_mesh *m;
    double ta[16], pa[12];
    cvm_index tri[48], map[6];
    size_t nt, k, na;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 6, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, seg, 7), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_regions(m, regions, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_point_attributes(m, pattr, 6, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    nt = count(m, CVM_ENT_TRIANGLE);
    ck_assert_uint_eq(nt, 4);
    ck_assert_int_eq(cvm_mesh_copy_cells(tri, 3 * nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_triangle_attributes(ta, nt, m), CVM_OK);
    for (k = 0; k < nt; k++) {
        double cx = 0;
        int j;
        for (j = 0; j < 3; j++) {
            double p[12];
            ck_assert_int_eq(cvm_mesh_copy_points(p, 12, m), CVM_OK);
            cx += p[2 * tri[3 * k + j]];
        }
        ck_assert(ta[k] == (cx / 3 < 1 ? 7.0 : 9.0));
    }
    ck_assert_int_eq(cvm_mesh_copy_point_attributes(pa, 12, &na, m), CVM_OK);
    ck_assert_uint_eq(na, 2);
    ck_assert_int_eq(cvm_mesh_copy_input_map(map, 6, m), CVM_OK);
    for (k = 0; k < 6; k++) {
        ck_assert(pa[2 * map[k]] == pattr[2 * k]);
        ck_assert(pa[2 * map[k] + 1] == pattr[2 * k + 1]);
    }
    ck_assert_int_eq(cvm_mesh_copy_point_attributes(pa, 11, &na, m), CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_point_attributes(pa, 12, NULL, m), CVM_E_NULL_ARG);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(short_buffers_are_left_untouched)
{
    cvm_mesh *m = square_with_hole();
    cvm_index ib[64];
    double db[64];
    int32_t mb[64];
    size_t i;
    for (i = 0; i < 64; i++) {
        ib[i] = -77;
        db[i] = -77;
        mb[i] = -77;
    }
    ck_assert_int_eq(cvm_mesh_copy_points(db, 15, m), CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_cells(ib, 23, m, CVM_ENT_TRIANGLE), CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_cells(ib, 31, m, CVM_ENT_EDGE), CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_cells(ib, 15, m, CVM_ENT_SEGMENT), CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_cells(ib, 64, m, CVM_ENT_VERTEX), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_mesh_copy_neighbors(ib, 23, m), CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_markers(mb, 7, m, CVM_ENT_VERTEX), CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_markers(mb, 7, m, CVM_ENT_SEGMENT), CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_triangle_attributes(db, 7, m), CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_input_map(ib, 7, m), CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_cells(NULL, 5, m, CVM_ENT_TRIANGLE), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_cells(NULL, 0, m, CVM_ENT_TRIANGLE), CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_cells(ib, 64, NULL, CVM_ENT_TRIANGLE), CVM_E_NULL_ARG);
    for (i = 0; i < 64; i++) {
        ck_assert_int_eq(ib[i], -77);
        ck_assert(db[i] == -77);
        ck_assert_int_eq(mb[i], -77);
    }
    cvm_mesh_free(m);
}
END_TEST

START_TEST(copies_that_allocate_report_out_of_memory)
{
    cvmtest_alloc a;
    cvm_mesh *m;
    cvm_index buf[64];
    int32_t mk[16];
    long live;
    cvmtest_alloc_init(&a, 0, 0);
    ck_assert_int_eq(cvmtest_mesh_create(&m, &a), CVM_OK);
    ck_assert_int_eq(cvmtest_pslg_set(m, &cvmtest_square_with_hole), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    live = a.live_blocks;
    cvmtest_alloc_arm(&a, 1, 1);
    ck_assert_int_eq(cvm_mesh_copy_cells(buf, 64, m, CVM_ENT_EDGE), CVM_E_NOMEM);
    ck_assert_int_eq(cvm_mesh_copy_cells(buf, 64, m, CVM_ENT_SEGMENT), CVM_E_NOMEM);
    ck_assert_int_eq(cvm_mesh_copy_neighbors(buf, 64, m), CVM_E_NOMEM);
    ck_assert_int_eq(cvm_mesh_copy_markers(mk, 16, m, CVM_ENT_SEGMENT), CVM_E_NOMEM);
    ck_assert_int_eq((int)a.live_blocks, (int)live);
    cvmtest_alloc_arm(&a, 0, 0);
    ck_assert_int_eq(cvm_mesh_copy_cells(buf, 64, m, CVM_ENT_EDGE), CVM_OK);
    ck_assert_int_eq((int)a.live_blocks, (int)live);
    cvm_mesh_free(m);
    ck_assert_int_eq((int)a.live_blocks, 0);
}
END_TEST

TCase *api_output_tcase(void)
{
    TCase *tc = tcase_create("output");
    tcase_add_test(tc, counts_of_square_with_hole);
    tcase_add_test(tc, nothing_before_triangulation);
    tcase_add_test(tc, edges_are_unique_sorted_and_cover_every_triangle);
    tcase_add_test(tc, neighbours_are_symmetric_and_share_the_opposite_edge);
    tcase_add_test(tc, segments_carry_their_markers);
    tcase_add_test(tc, duplicates_map_to_their_first_occurrence);
    tcase_add_test(tc, attributes_of_triangles_and_points);
    tcase_add_test(tc, short_buffers_are_left_untouched);
    tcase_add_test(tc, copies_that_allocate_report_out_of_memory);
    return tc;
}
