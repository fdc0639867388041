/* test_read_names.c - errors after cvm_mesh_read() name items in the file's terms (input_names.c). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "api/api_tests.h"
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

/* Write text to DIR/name; path receives the file name. */
static void write_file(char *path, size_t len, const char *name, const char *text)
{
    FILE *f;
    snprintf(path, len, "%s/%s", g_dir, name);
    f = fopen(path, "w");
    ck_assert_ptr_nonnull(f);
    fputs(text, f);
    fclose(f);
}

/* "PREFIX" + rest, for comparing messages that start with a path. */
static void expect_msg(const cvm_mesh *m, const char *path, const char *rest)
{
    char want[8192];
    ck_assert_uint_lt(strlen(path) + strlen(rest), sizeof want);
    strcpy(want, path);
    strcat(want, rest);
    ck_assert_msg(strcmp(cvm_mesh_errmsg(m), want) == 0, "message '%s', expected '%s'",
                  cvm_mesh_errmsg(m), want);
}

START_TEST(node_duplicate_uses_file_numbers_and_lines)
{
    char path[4096];
    cvm_mesh *m;
    cvm_entity kind;
    int64_t idx;
    static const double xy[] = {0, 0, 1, 0, 0, 1, 0, 0};
    write_file(path, sizeof path, "d.node", "4 2 0 0\n1 0 0\n2 1 0\n# c\n3 0 1\n4 0 0\n");
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_REJECT_DUPLICATES, 1), CVM_OK);
    ck_assert_int_eq(cvm_mesh_read(m, path), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_E_INPUT_DUPLICATE);
    expect_msg(m, path, ":6: point 4 at (0, 0) duplicates point 1 (line 2)");
    /* programs still get the 0-based index */
    ck_assert_int_eq(cvm_mesh_error_item(&kind, &idx, m), CVM_OK);
    ck_assert_int_eq(kind, CVM_ENT_INPUT_POINT);
    ck_assert_int_eq(idx, 3);
    /* points set through the API are named by their indices again */
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 4, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_E_INPUT_DUPLICATE);
    ck_assert_str_eq(cvm_mesh_errmsg(m), "point 3 at (0, 0) duplicates point 0");
    cvm_mesh_free(m);
}
END_TEST

START_TEST(poly_segments_holes_use_file_numbers_and_lines)
{
    char path[4096];
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    /* a zero-length segment numbered 2 in a 1-based file */
    write_file(path, sizeof path, "z.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n3 0\n1 1 2\n2 1 1\n3 2 3\n0\n");
    ck_assert_int_eq(cvm_mesh_read(m, path), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_E_INPUT_DEGENERATE);
    expect_msg(m, path, ":7: segment 2 (points 1-1) has zero length");
    /* crossing diagonals of a square, free segment numbers */
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_SPLIT_INTERSECTIONS, 0), CVM_OK);
    write_file(path, sizeof path, "c.poly",
               "4 2 0 0\n1 0 0\n2 4 0\n3 4 4\n4 0 4\n6 0\n10 1 2\n20 2 3\n30 3 4\n40 4 1\n"
               "50 1 3\n\n60 2 4\n0\n");
    ck_assert_int_eq(cvm_mesh_read(m, path), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_E_INPUT_INTERSECTING);
    expect_msg(m, path, ":13: segment 60 (points 2-4) crosses segment 50 (line 11) (points 1-3) in its interior");
    /* a hole inside the only closed loop empties the domain: no open boundary involved */
    write_file(path, sizeof path, "h.poly",
               "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n3 0\n1 1 2\n2 2 3\n3 3 1\n1\n1 0.25 0.25\n");
    ck_assert_int_eq(cvm_mesh_read(m, path), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_E_INPUT_NOT_CLOSED);
    expect_msg(m, path, ":10: hole 1 at (0.25, 0.25) removed every remaining triangle: no closed "
                        "loop of segments separates it from the rest of the domain");
    cvm_mesh_free(m);
}
END_TEST

START_TEST(vtu_coincident_points_are_named_as_in_the_file)
{
    char path[4096];
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    write_file(path, sizeof path, "c.vtu",
               "<VTKFile type=\"UnstructuredGrid\"><UnstructuredGrid>"
               "<Piece NumberOfPoints=\"4\" NumberOfCells=\"2\"><Points>"
               "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">"
               "0 0 0 3 0 0 4 1 0 0 0 0</DataArray></Points><Cells>"
               "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0 1 2 0 2 3</DataArray>"
               "<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">3 6</DataArray>"
               "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">5 5</DataArray>"
               "</Cells></Piece></UnstructuredGrid></VTKFile>\n");
    ck_assert_int_eq(cvm_mesh_read(m, path), CVM_E_INPUT_DEGENERATE);
    expect_msg(m, path, ": triangle 1 (points 0 2 3) is degenerate: points 3 and 0 are both at (0, 0)");
    ck_assert_ptr_null(strstr(cvm_mesh_errmsg(m), "segment"));
    cvm_mesh_free(m);
}
END_TEST

START_TEST(directory_is_named_as_such)
{
    cvm_mesh *m;
    char want[4200];
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_read(m, g_dir), CVM_E_UNSUPPORTED); /* no extension */
    snprintf(want, sizeof want, "%s/sub.poly", g_dir);
    ck_assert_int_eq(mkdir(want, 0700), 0);
    ck_assert_int_eq(cvm_mesh_read(m, want), CVM_E_IO_OPEN);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "sub.poly: it is a directory"));
    ck_assert_int_eq(rmdir(want), 0);
    cvm_mesh_free(m);
}
END_TEST

TCase *api_read_names_tcase(void)
{
    TCase *tc = tcase_create("read_names");
    tcase_add_checked_fixture(tc, setup, teardown);
    tcase_add_test(tc, node_duplicate_uses_file_numbers_and_lines);
    tcase_add_test(tc, poly_segments_holes_use_file_numbers_and_lines);
    tcase_add_test(tc, vtu_coincident_points_are_named_as_in_the_file);
    tcase_add_test(tc, directory_is_named_as_such);
    return tc;
}
