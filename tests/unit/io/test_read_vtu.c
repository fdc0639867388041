/* test_read_vtu.c - the .vtu reader: foreign layouts, malformed files named by line, read faults, OOM. */
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

/* Two triangles of the unit square, a line, weights; written by "another
 * tool": Float32, attributes in another order, comments, a self-closing
 * empty array, a vertex cell and an unknown array. */
static const char k_good[] =
    "<?xml version=\"1.0\"?>\n"
    "<!-- made by hand -->\n"
    "<VTKFile byte_order=\"LittleEndian\" type=\"UnstructuredGrid\" version=\"1.0\">\n"
    "<UnstructuredGrid>\n"
    "<Piece NumberOfCells=\"4\" NumberOfPoints=\"4\">\n"
    "<PointData>\n"
    "  <DataArray format=\"ascii\" Name=\"weight\" type=\"Float32\">0 0.5 0 0.25</DataArray>\n"
    "  <DataArray type=\"Float64\" Name=\"velocity\" NumberOfComponents=\"2\" format=\"ascii\">\n"
    "    1 2 3 4 5 6 7 8\n"
    "  </DataArray>\n"
    "  <DataArray type=\"Int32\" Name=\"empty\" format=\"ascii\"/>\n"
    "</PointData>\n"
    "<CellData>\n"
    "  <DataArray type=\"Int32\" Name=\"marker\" format=\"ascii\">0 0 5 0</DataArray>\n"
    "</CellData>\n"
    "<Points>\n"
    "  <DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">\n"
    "    0 0 0  1 0 0\n"
    "    1 1 0  0 1 0\n"
    "  </DataArray>\n"
    "</Points>\n"
    "<Cells>\n"
    "  <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">0 1 2 0 2 3 1 2 3</DataArray>\n"
    "  <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">3 6 8 9</DataArray>\n"
    "  <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">5 5 3 1</DataArray>\n"
    "</Cells>\n"
    "</Piece>\n"
    "</UnstructuredGrid>\n"
    "</VTKFile>\n";

static cvm_status parse(const char *text, size_t len, cvm__vtu_mesh *vm)
{
    cvmtest_reader tr;
    cvm__reader r;
    cvmtest_reader_init(&tr, &r, text, len ? len : strlen(text), 7, -1);
    return cvm__read_vtu(&g_ctx, &r, "t.vtu", vm);
}

START_TEST(vtu_foreign_layout_is_read)
{
    cvm__vtu_mesh vm;
    ck_assert_msg(parse(k_good, 0, &vm) == CVM_OK, "%s", g_ctx.errmsg);
    ck_assert_uint_eq(vm.p.np, 4);
    ck_assert_uint_eq(vm.nt, 2);
    ck_assert_int_eq(vm.tri[3], 0);
    ck_assert_int_eq(vm.tri[5], 3);
    ck_assert_uint_eq(vm.p.nseg, 1);
    ck_assert_int_eq(vm.p.seg[0], 1);
    ck_assert_int_eq(vm.p.smark[0], 5);
    ck_assert_int_eq(vm.has_lines, 1);
    ck_assert_ptr_nonnull(vm.w);
    ck_assert(vm.w[1] == 0.5 && vm.w[3] == 0.25);
    ck_assert(vm.p.xy[4] == 1 && vm.p.xy[7] == 1);
    ck_assert_ptr_null(vm.p.pattr);
    ck_assert_ptr_null(vm.p.pmark);
    cvm__vtu_mesh_free(&g_ctx, &vm);
    ck_assert_int_eq((int)g_a.live_blocks, 0);
}
END_TEST

/* Replace the first occurrence of from by to in k_good; parse; check the
 * status and that the message contains want. */
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
    s = parse(text, 0, &vm);
    ck_assert_msg(s == want, "'%s' -> '%s': status %d, want %d (%s)", from, to, s, want, g_ctx.errmsg);
    ck_assert_msg(strstr(g_ctx.errmsg, msg) != NULL, "message '%s' lacks '%s'", g_ctx.errmsg, msg);
    ck_assert_msg(strncmp(g_ctx.errmsg, "t.vtu", 5) == 0, "message '%s' does not name the file", g_ctx.errmsg);
    ck_assert_ptr_null(vm.tri);
    ck_assert_int_eq((int)g_a.live_blocks, 0);
    free(text);
}

START_TEST(vtu_malformed_files_are_named_by_line)
{
    expect_bad("1 1 0  0 1 0", "1 1 0  0 1x 0", CVM_E_IO_FORMAT, "t.vtu:19: Points: entry 10 (from 0) is '1x', not a number");
    expect_bad("1 1 0  0 1 0", "1 1 0  0 nan 0", CVM_E_INPUT_NONFINITE, "t.vtu:19: Points: entry 10 (from 0) is 'nan', not a finite number");
    expect_bad("1 1 0  0 1 0", "1 1 0  0 inf 0", CVM_E_INPUT_NONFINITE, ":19:");
    expect_bad("1 1 0  0 1 0", "1 1 0  0 1", CVM_E_IO_FORMAT, "Points: 11 values, expected 12");
    expect_bad("1 1 0  0 1 0", "1 1 0  0 1 0 7", CVM_E_IO_FORMAT, "more than the 12 values");
    expect_bad("1 1 0  0 1 0", "1 1 0  0 1 2", CVM_E_IO_FORMAT, "t.vtu:19: point 3 has z != 0");
    expect_bad("0 1 2 0 2 3 1 2 3", "0 1 2 0 2 9 1 2 3", CVM_E_IO_FORMAT,
               "t.vtu:23: cell 1 names point 9, which does not exist (points are numbered 0..3)");
    expect_bad("0 1 2 0 2 3 1 2 3", "0 1 2 0 2 3.5 1 2 3", CVM_E_IO_FORMAT,
               "t.vtu:23: connectivity: entry 5 (from 0) is '3.5', not an integer in "
               "[-2147483647, 2147483647]");
    expect_bad("0 1 2 0 2 3 1 2 3", "0 1 2 0 2 -1 1 2 3", CVM_E_IO_FORMAT, "cell 1 names point -1");
    expect_bad("3 6 8 9", "3 6 7 9", CVM_E_IO_FORMAT, "t.vtu:24: cell 2: offset 7");
    expect_bad("5 5 3 1", "5 9 3 1", CVM_E_UNSUPPORTED, "t.vtu:25: cell 1 has VTK type 9");
    expect_bad("0.5 0 0.25", "0.5 0 0.25 1", CVM_E_IO_FORMAT, "weight: more than the 4 values");
    expect_bad("NumberOfPoints=\"4\"", "NumberOfPoints=\"x\"", CVM_E_IO_FORMAT,
               "t.vtu:5: NumberOfPoints=\"x\" is not a non-negative integer");
    expect_bad("NumberOfPoints=\"4\"", "NumberOfPoints=\"99999999999\"", CVM_E_TOO_LARGE,
               "NumberOfPoints=\"99999999999\" exceeds 536870911");
    expect_bad("NumberOfPoints=\"4\"", "NumberOfPoints=\"-4\"", CVM_E_IO_FORMAT,
               "t.vtu:5: NumberOfPoints=\"-4\" is negative");
    expect_bad("NumberOfPoints=\"4\"", "NumberOfPoints=\"-99999999999999999999\"", CVM_E_IO_FORMAT,
               "t.vtu:5: NumberOfPoints=\"-99999999999999999999\" is negative");
    expect_bad("format=\"ascii\" Name=\"weight\"", "format=\"binary\" Name=\"weight\"", CVM_E_IO_FORMAT,
               "t.vtu:7: weight: '.' is not a base64 character");
    expect_bad("type=\"UnstructuredGrid\"", "type=\"PolyData\"", CVM_E_UNSUPPORTED, "not a VTK UnstructuredGrid");
    expect_bad("5 5 3 1</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n", "5 5 3 1\n",
               CVM_E_IO_FORMAT, "t.vtu:25: DataArray without </DataArray>");
    expect_bad("<Cells>", "<Cellz>", CVM_E_IO_FORMAT, "Cells need connectivity");
    expect_bad("<!-- made by hand -->", "<!-- made by hand", CVM_E_IO_FORMAT, "t.vtu:2: unterminated comment");
    expect_bad("</Piece>", "</Piece><Piece NumberOfPoints=\"0\" NumberOfCells=\"0\">", CVM_E_UNSUPPORTED,
               "more than one <Piece>");
    expect_bad("<Points>", "<AppendedData encoding=\"raw\">", CVM_E_IO_FORMAT,
               "t.vtu:17: <AppendedData> data must start with '_'");
    /* control bytes of an echoed field are escaped, never passed to a terminal */
    expect_bad("format=\"ascii\" Name=\"weight\"", "format=\"\033]0;x\007\" Name=\"weight\"",
               CVM_E_UNSUPPORTED, "t.vtu:7: weight: format=\"\\x1b]0;x\\x07\" is not read");
    expect_bad("0 0 0  1 0 0", "0 0 0  1 \033]0;x\007 0", CVM_E_IO_FORMAT,
               "t.vtu:18: Points: entry 4 (from 0) is '\\x1b]0;x\\x07', not a number");
}
END_TEST

/* Every truncation of a good file: a status, never a crash or a leak. */
START_TEST(vtu_truncated_anywhere_gives_a_status)
{
    size_t n = strlen(k_good), len;
    const char *last = "5 5 3 1</DataArray"; /* the closing ">" is not needed */
    size_t complete = (size_t)(strstr(k_good, last) - k_good) + strlen(last);
    for (len = 0; len < n; len++) {
        cvm__vtu_mesh vm;
        cvm_status s = parse(k_good, len == 0 ? 1 : len, &vm);
        if (s == CVM_OK)
            cvm__vtu_mesh_free(&g_ctx, &vm);
        else
            ck_assert_ptr_null(vm.tri);
        ck_assert_msg(len >= complete || s != CVM_OK, "truncated at %lu read fine", (unsigned long)len);
        ck_assert_int_eq((int)g_a.live_blocks, 0);
    }
}
END_TEST

START_TEST(vtu_read_faults_and_oom)
{
    size_t n = strlen(k_good);
    long k;
    for (k = 0; k < (long)n; k += 37) {
        cvmtest_reader tr;
        cvm__reader r;
        cvm__vtu_mesh vm;
        cvmtest_reader_init(&tr, &r, k_good, n, 64, k);
        ck_assert_int_eq(cvm__read_vtu(&g_ctx, &r, "t.vtu", &vm), CVM_E_IO_READ);
        ck_assert_ptr_nonnull(strstr(g_ctx.errmsg, "t.vtu: read error"));
        ck_assert_int_eq((int)g_a.live_blocks, 0);
    }
    for (k = 1;; k++) {
        cvm__vtu_mesh vm;
        cvm_status s;
        cvmtest_alloc_init(&g_a, k, 0);
        s = parse(k_good, 0, &vm);
        if (s == CVM_OK) {
            cvm__vtu_mesh_free(&g_ctx, &vm);
            ck_assert_int_eq((int)g_a.live_blocks, 0);
            break;
        }
        ck_assert_int_eq(s, CVM_E_NOMEM);
        ck_assert_int_eq((int)g_a.live_blocks, 0);
    }
    ck_assert(k > 5);
}
END_TEST

TCase *io_read_vtu_tcase(void)
{
    TCase *tc = tcase_create("read_vtu");
    tcase_add_checked_fixture(tc, setup, NULL);
    tcase_add_test(tc, vtu_foreign_layout_is_read);
    tcase_add_test(tc, vtu_malformed_files_are_named_by_line);
    tcase_add_test(tc, vtu_truncated_anywhere_gives_a_status);
    tcase_add_test(tc, vtu_read_faults_and_oom);
    return tc;
}
