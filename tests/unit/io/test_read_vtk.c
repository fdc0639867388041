/* test_read_vtk.c - the legacy .vtk reader: files VTK and meshio wrote, malformed files named by line or byte, read faults, OOM. */
#include <stdlib.h>
#include <string.h>

#include "io/io_tests.h"
#include "support/failing_reader.h"

static cvmtest_alloc g_a;
static cvm__ctx g_ctx;

static void setup(void)
{
    cvmtest_alloc_init(&g_a, 0, 0);
    iotest_ctx(&g_ctx, &g_a);
}

static cvm_status parse(const char *text, size_t len, cvm__vtu_mesh *vm)
{
    cvmtest_reader tr;
    cvm__reader r;
    cvmtest_reader_init(&tr, &r, text, len, 7, -1);
    return cvm__read_vtk(&g_ctx, &r, "t.vtk", vm);
}

static char *interop(const char *name, size_t *len)
{
    char dir[512], path[600];
    char *text;
    iotest_path(dir, sizeof dir, iotest_data_dir(), "interop");
    iotest_path(path, sizeof path, dir, name);
    text = iotest_slurp(path, len);
    ck_assert_msg(text != NULL, "cannot read %s", path);
    return text;
}

static const char *const k_files[] = {"square_meshio_ascii.vtk", "square_meshio_binary.vtk",
                                      "square_vtk_ascii.vtk", "square_vtk_binary.vtk",
                                      "square_vtk_polydata.vtk"};

START_TEST(vtk_files_of_vtk_and_meshio_are_read)
{
    static const int32_t tri[12] = {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
    size_t i, k;
    for (i = 0; i < sizeof k_files / sizeof k_files[0]; i++) {
        int poly = strstr(k_files[i], "polydata") != NULL;
        size_t len;
        char *text = interop(k_files[i], &len);
        cvm__vtu_mesh vm;
        long n;
        /* every allocation failing in turn, then success */
        for (n = 1;; n++) {
            cvm_status s;
            cvmtest_alloc_init(&g_a, n, 0);
            s = parse(text, len, &vm);
            if (s == CVM_OK)
                break;
            ck_assert_msg(s == CVM_E_NOMEM, "%s: %s", k_files[i], g_ctx.errmsg);
            ck_assert_int_eq((int)g_a.live_blocks, 0);
        }
        ck_assert_uint_eq(vm.p.np, 5);
        ck_assert_uint_eq(vm.nt, 4);
        for (k = 0; k < 12; k++)
            ck_assert_int_eq(vm.tri[k], tri[k]);
        ck_assert(vm.p.xy[8] == 0.5 && vm.p.xy[9] == 0.5 && vm.p.xy[4] == 1);
        if (!poly) {
            ck_assert_uint_eq(vm.p.nseg, 4);
            ck_assert_ptr_nonnull(vm.p.smark);
            for (k = 0; k < 4; k++)
                ck_assert_int_eq(vm.p.smark[k], (int32_t)k + 1);
            ck_assert(vm.w != NULL && vm.w[4] == 0.01);
        }
        cvm__vtu_mesh_free(&g_ctx, &vm);
        ck_assert_int_eq((int)g_a.live_blocks, 0);
        cvmtest_alloc_init(&g_a, 0, 0);
        for (n = 1; n < (long)len; n += 1 + n / 30) { /* truncated: a status, no leak */
            cvm_status s = parse(text, (size_t)n, &vm);
            if (s == CVM_OK)
                cvm__vtu_mesh_free(&g_ctx, &vm);
            else
                ck_assert_msg(g_ctx.errmsg[0] && vm.tri == NULL, "%s cut at %ld", k_files[i], n);
            ck_assert_int_eq((int)g_a.live_blocks, 0);
        }
        free(text);
    }
}
END_TEST

static const char k_good[] =
    "# vtk DataFile Version 3.0\n"
    "hand made, old cell layout\n"
    "ASCII\n"
    "DATASET UNSTRUCTURED_GRID\n"
    "FIELD FieldData 1\n"
    "TIME 1 1 double\n"
    "2.5\n"
    "POINTS 4 double\n"
    "0 0 0 1 0 0 1 1 0 0 1 0\n"
    "CELLS 3 12\n"
    "3 0 1 2\n"
    "3 0 2 3\n"
    "3 1 2 3\n"
    "CELL_TYPES 3\n"
    "5 5 4\n"
    "CELL_DATA 3\n"
    "SCALARS marker int 1\n"
    "LOOKUP_TABLE default\n"
    "0 0 6\n"
    "POINT_DATA 4\n"
    "VECTORS velocity float\n"
    "1 2 3 4 5 6 7 8 9 10 11 12\n"
    "SCALARS attribute double 2\n"
    "LOOKUP_TABLE default\n"
    "1 2 3 4 5 6 7 8\n";

static void expect_bad(const char *from, const char *to, cvm_status want, const char *msg)
{
    char *text = malloc(sizeof k_good + strlen(to) + 1), *p;
    cvm__vtu_mesh vm;
    cvm_status s;
    ck_assert_ptr_nonnull(text);
    p = strstr(k_good, from);
    ck_assert_msg(p != NULL, "fixture lacks '%s'", from);
    memcpy(text, k_good, (size_t)(p - k_good));
    strcpy(text + (p - k_good), to);
    strcat(text, p + strlen(from));
    s = parse(text, strlen(text), &vm);
    ck_assert_msg(s == want, "'%s' -> '%s': status %d, want %d (%s)", from, to, s, want, g_ctx.errmsg);
    ck_assert_msg(strstr(g_ctx.errmsg, msg) != NULL, "message '%s' lacks '%s'", g_ctx.errmsg, msg);
    ck_assert_msg(strncmp(g_ctx.errmsg, "t.vtk", 5) == 0, "'%s' names no file", g_ctx.errmsg);
    ck_assert_ptr_null(vm.tri);
    ck_assert_int_eq((int)g_a.live_blocks, 0);
    free(text);
}

START_TEST(vtk_old_layout_polylines_and_data_are_read)
{
    cvm__vtu_mesh vm;
    ck_assert_msg(parse(k_good, strlen(k_good), &vm) == CVM_OK, "%s", g_ctx.errmsg);
    ck_assert_uint_eq(vm.nt, 2);
    ck_assert_uint_eq(vm.p.nseg, 2); /* the polyline 1-2-3 is two line cells */
    ck_assert(vm.p.seg[0] == 1 && vm.p.seg[1] == 2 && vm.p.seg[2] == 2 && vm.p.seg[3] == 3);
    ck_assert(vm.p.smark[0] == 6 && vm.p.smark[1] == 6);
    ck_assert_uint_eq(vm.p.nattr, 2);
    ck_assert(vm.p.pattr[7] == 8);
    cvm__vtu_mesh_free(&g_ctx, &vm);
    ck_assert_int_eq((int)g_a.live_blocks, 0);
}
END_TEST

START_TEST(vtk_malformed_files_are_named)
{
    expect_bad("0 0 0 1 0 0", "0 0 0 1 x 0", CVM_E_IO_FORMAT, "t.vtk:9: POINTS: entry 4 (from 0) is 'x', not a number");
    expect_bad("0 0 0 1 0 0", "0 0 0 1 nan 0", CVM_E_INPUT_NONFINITE, "t.vtk:9: POINTS: entry 4 (from 0) is 'nan', not a finite number");
    expect_bad("0 0 0 1 0 0", "0 0 0 1 0 2", CVM_E_IO_FORMAT, "point 1 has z = 2");
    expect_bad("3 0 2 3\n", "3 0 2 9\n", CVM_E_IO_FORMAT, "cell 1 names point 9, which does not exist");
    expect_bad("3 0 2 3\n", "4 0 2 3\n", CVM_E_IO_FORMAT, "t.vtk:10: CELLS: 3 cells use 11 of the 12 values");
    expect_bad("5 5 4", "5 9 4", CVM_E_UNSUPPORTED, "cell 1 has VTK type 9");
    expect_bad("CELL_DATA 3", "CELL_DATA 4", CVM_E_IO_FORMAT, "t.vtk:16: CELL_DATA 4, but the file has 3");
    expect_bad("POINTS 4 double", "POINTS 4 string", CVM_E_UNSUPPORTED, "POINTS: data type 'string' is not read");
    expect_bad("POINTS 4 double", "POINTS 99999999999 double", CVM_E_TOO_LARGE, "exceeds 536870911");
    expect_bad("POINTS 4 double", "POINTS 400000 double", CVM_E_IO_FORMAT, "values do not fit in the rest of the file");
    expect_bad("DATASET UNSTRUCTURED_GRID", "DATASET STRUCTURED_POINTS", CVM_E_UNSUPPORTED, "DATASET STRUCTURED_POINTS is not read");
    expect_bad("ASCII", "TEXT", CVM_E_IO_FORMAT, "t.vtk:3: line 3 must be ASCII or BINARY");
    expect_bad("# vtk", "# vtx", CVM_E_IO_FORMAT, "not a legacy VTK file");
    expect_bad("VECTORS velocity float", "BLOB velocity float", CVM_E_UNSUPPORTED, "t.vtk:21: keyword 'BLOB' is not read");
    expect_bad("1 2 3 4 5 6 7 8\n", "1 2 3 4 5 6 7\n", CVM_E_IO_FORMAT, "the file ends after 7 of 8 values");
}
END_TEST

/* Binary: a truncated array, a NaN coordinate, an index out of range. */
START_TEST(vtk_malformed_binary_is_named_by_byte)
{
    size_t len, at;
    char *text = interop("square_vtk_binary.vtk", &len), *p;
    cvm__vtu_mesh vm;
    p = strstr(text, "POINTS 5 float\n");
    ck_assert_ptr_nonnull(p);
    at = (size_t)(p - text) + strlen("POINTS 5 float\n");
    memcpy(text + at + 4, "\x7f\xc0\x00\x00", 4); /* big-endian float NaN as y of point 0 */
    ck_assert_int_eq(parse(text, len, &vm), CVM_E_INPUT_NONFINITE);
    ck_assert_msg(strstr(g_ctx.errmsg, "t.vtk: byte ") && strstr(g_ctx.errmsg, "POINTS: entry 1 (from 0) is not a finite number"),
                  "%s", g_ctx.errmsg);
    free(text);
    text = interop("square_vtk_binary.vtk", &len);
    ck_assert_int_eq(parse(text, at + 10, &vm), CVM_E_IO_FORMAT);
    ck_assert_msg(strstr(g_ctx.errmsg, "POINTS: 15 binary values of float do not fit"), "%s", g_ctx.errmsg);
    ck_assert_int_eq((int)g_a.live_blocks, 0);
    free(text);
}
END_TEST

TCase *io_read_vtk_tcase(void)
{
    TCase *tc = tcase_create("read_vtk");
    tcase_add_checked_fixture(tc, setup, NULL);
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, vtk_files_of_vtk_and_meshio_are_read);
    tcase_add_test(tc, vtk_old_layout_polylines_and_data_are_read);
    tcase_add_test(tc, vtk_malformed_files_are_named);
    tcase_add_test(tc, vtk_malformed_binary_is_named_by_byte);
    return tc;
}
