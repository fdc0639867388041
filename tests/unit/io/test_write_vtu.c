/* test_write_vtu.c - the VTK XML writer: structure, counts, cell types and data arrays. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/io_tests.h"

static char *write_vtu(cvm__mesh_out *mo)
{
    char *dir = iotest_tmpdir(), path[4096], *text;
    cvm__ctx ctx;
    cvm__ctx_init_default(&ctx);
    snprintf(path, sizeof path, "%s/m.vtu", dir);
    ck_assert_int_eq(cvm__write_file(&ctx, path, mo), CVM_OK);
    text = iotest_slurp(path, NULL);
    ck_assert_ptr_nonnull(text);
    iotest_rmdir(dir);
    free(dir);
    return text;
}

START_TEST(vtu_has_points_cells_and_data)
{
    cvm__mesh_out mo;
    char *t;
    iotest_mesh_out(&mo);
    t = write_vtu(&mo);
    ck_assert_ptr_nonnull(strstr(t, "<VTKFile type=\"UnstructuredGrid\""));
    /* 4 triangles, then the 3 segments as lines */
    ck_assert_ptr_nonnull(strstr(t, "<Piece NumberOfPoints=\"5\" NumberOfCells=\"7\">"));
    ck_assert_ptr_nonnull(strstr(t, "Name=\"connectivity\" format=\"ascii\">\n0 1 4\n1 2 4\n"));
    ck_assert_ptr_nonnull(strstr(t, "3 0 4\n0 1\n1 2\n2 3\n"));
    ck_assert_ptr_nonnull(strstr(t, "Name=\"offsets\" format=\"ascii\">\n3 6 9 12 14 16 18\n"));
    ck_assert_ptr_nonnull(strstr(t, "Name=\"types\" format=\"ascii\">\n5 5 5 5 3 3 3\n"));
    ck_assert_ptr_nonnull(strstr(t, "Name=\"marker\" format=\"ascii\">\n1 2 3 -4 0\n"));
    ck_assert_ptr_nonnull(strstr(t, "Name=\"marker\" format=\"ascii\">\n0 0 0 0 7 7 9\n"));
    ck_assert_ptr_nonnull(strstr(t, "Name=\"min_angle_deg\""));
    ck_assert_ptr_nonnull(strstr(t, "<CellData>"));
    ck_assert_ptr_null(strstr(t, "Name=\"weight\""));
    ck_assert_ptr_nonnull(strstr(t, "0.1 0.3333333333333333 0\n"));
    ck_assert_uint_eq(iotest_count(t, "<DataArray"), iotest_count(t, "</DataArray>"));
    ck_assert_uint_eq(iotest_count(t, "<DataArray"), 9);
    ck_assert_ptr_nonnull(strstr(t, "</VTKFile>\n"));
    free(t);
}
END_TEST

START_TEST(vtu_without_optional_data)
{
    cvm__mesh_out mo;
    char *t;
    iotest_mesh_out(&mo);
    mo.vmark = NULL;
    mo.vattr = NULL;
    mo.tattr = NULL;
    mo.tquality = NULL;
    mo.nseg = 0;
    t = write_vtu(&mo);
    ck_assert_ptr_null(strstr(t, "<CellData>"));
    ck_assert_ptr_nonnull(strstr(t, "Name=\"marker\" format=\"ascii\">\n0 0 0 0 0\n"));
    ck_assert_uint_eq(iotest_count(t, "<DataArray"), 5);
    free(t);
}
END_TEST

TCase *io_write_vtu_tcase(void)
{
    TCase *tc = tcase_create("write_vtu");
    tcase_add_test(tc, vtu_has_points_cells_and_data);
    tcase_add_test(tc, vtu_without_optional_data);
    return tc;
}
