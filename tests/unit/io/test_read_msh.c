/* test_read_msh.c - the Gmsh .msh reader: 2.2 and 4.1 files meshio wrote, physical tags and names, malformed files, read faults, OOM. */
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
    cvmtest_reader_init(&tr, &r, text, len, 5, -1);
    return cvm__read_msh(&g_ctx, &r, "t.msh", vm);
}

static void interop_path(char *path, size_t n, const char *name)
{
    char dir[512];
    iotest_path(dir, sizeof dir, iotest_data_dir(), "interop");
    iotest_path(path, n, dir, name);
}

START_TEST(msh_files_of_meshio_are_read_with_tags_and_names)
{
    static const char *const files[] = {"square_meshio_22.msh", "square_meshio_22b.msh",
                                        "square_meshio_41.msh", "square_meshio_41b.msh"};
    static const int32_t tri[12] = {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
    size_t i, k;
    for (i = 0; i < 4; i++) {
        char path[600];
        size_t len;
        char *text;
        cvm__vtu_mesh vm;
        long n;
        interop_path(path, sizeof path, files[i]);
        text = iotest_slurp(path, &len);
        ck_assert_ptr_nonnull(text);
        for (n = 1;; n++) {
            cvm_status s;
            cvmtest_alloc_init(&g_a, n, 0);
            s = parse(text, len, &vm);
            if (s == CVM_OK)
                break;
            ck_assert_msg(s == CVM_E_NOMEM, "%s: %s", files[i], g_ctx.errmsg);
            ck_assert_int_eq((int)g_a.live_blocks, 0);
        }
        ck_assert_uint_eq(vm.p.np, 5);
        ck_assert_uint_eq(vm.nt, 4);
        for (k = 0; k < 12; k++)
            ck_assert_int_eq(vm.tri[k], tri[k]);
        ck_assert(vm.p.xy[8] == 0.5 && vm.p.xy[9] == 0.5 && vm.p.xy[2] == 1);
        ck_assert_uint_eq(vm.p.nseg, 4);
        for (k = 0; k < 4; k++) {
            ck_assert_int_eq(vm.p.seg[2 * k], (int32_t)k);
            /* 2.2 keeps each line's physical tag; meshio's 4.1 writer puts
               every line in curve 1, whose physical group is 1 */
            ck_assert_int_eq(vm.p.smark[k], i < 2 ? (int32_t)k + 1 : 1);
        }
        ck_assert(vm.tattr != NULL && vm.tattr[0] == 7 && vm.tattr[3] == 7);
        ck_assert_uint_eq(vm.nnames, 5);
        ck_assert_str_eq(vm.names[0].name, "bottom");
        ck_assert(vm.names[0].dim == 1 && vm.names[0].tag == 1);
        ck_assert_str_eq(vm.names[4].name, "inside");
        ck_assert(vm.names[4].dim == 2 && vm.names[4].tag == 7);
        cvm__vtu_mesh_free(&g_ctx, &vm);
        ck_assert_int_eq((int)g_a.live_blocks, 0);
        cvmtest_alloc_init(&g_a, 0, 0);
        for (n = 1; n < (long)len; n += 1 + n / 30) {
            cvm_status s = parse(text, (size_t)n, &vm);
            if (s == CVM_OK)
                cvm__vtu_mesh_free(&g_ctx, &vm);
            else
                ck_assert_msg(g_ctx.errmsg[0] && vm.tri == NULL, "%s cut at %ld", files[i], n);
            ck_assert_int_eq((int)g_a.live_blocks, 0);
        }
        free(text);
    }
}
END_TEST

START_TEST(msh_domain_of_lines_and_points_is_read_by_extension)
{
    static const char *const files[] = {"domain_meshio_22.msh", "domain_meshio_22b.msh"};
    size_t i;
    for (i = 0; i < 2; i++) {
        char path[600];
        cvm__vtu_mesh vm;
        interop_path(path, sizeof path, files[i]);
        ck_assert_msg(cvm__read_mesh_file(&g_ctx, path, &vm) == CVM_OK, "%s", g_ctx.errmsg);
        ck_assert_uint_eq(vm.nt, 0);
        ck_assert_uint_eq(vm.p.np, 5);
        ck_assert_uint_eq(vm.p.nseg, 4);
        ck_assert_int_eq(vm.p.smark[3], 4);
        ck_assert_ptr_nonnull(vm.p.pmark);
        ck_assert(vm.p.pmark[4] == 9 && vm.p.pmark[0] == 0);
        cvm__vtu_mesh_free(&g_ctx, &vm);
    }
    {
        cvm__vtu_mesh vm;
        ck_assert_int_eq(cvm__read_mesh_file(&g_ctx, "x.stl", &vm), CVM_E_UNSUPPORTED);
    }
    ck_assert_ptr_nonnull(strstr(g_ctx.errmsg, "x.stl"));
    ck_assert_int_eq((int)g_a.live_blocks, 0);
}
END_TEST

static const char k_good[] =
    "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
    "$PhysicalNames\n1\n1 5 \"wall\"\n$EndPhysicalNames\n"
    "$Nodes\n4\n"
    "10 0 0 0\n20 1 0 0\n30 1 1 0\n40 0 1 0\n"
    "$EndNodes\n"
    "$Elements\n3\n"
    "1 1 2 5 1 10 20\n"
    "2 2 2 0 1 10 20 30\n"
    "3 2 0 10 30 40\n"
    "$EndElements\n"
    "$NodeData\nwhatever\n$EndNodeData\n";

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
    ck_assert_msg(strncmp(g_ctx.errmsg, "t.msh", 5) == 0, "'%s' names no file", g_ctx.errmsg);
    ck_assert_ptr_null(vm.tri);
    ck_assert_int_eq((int)g_a.live_blocks, 0);
    free(text);
}

START_TEST(msh_sparse_node_tags_are_mapped)
{
    cvm__vtu_mesh vm;
    ck_assert_msg(parse(k_good, strlen(k_good), &vm) == CVM_OK, "%s", g_ctx.errmsg);
    ck_assert_uint_eq(vm.nt, 2);
    ck_assert(vm.tri[3] == 0 && vm.tri[4] == 2 && vm.tri[5] == 3);
    ck_assert(vm.p.nseg == 1 && vm.p.smark[0] == 5);
    ck_assert_ptr_null(vm.tattr); /* no triangle has a physical tag */
    ck_assert_str_eq(vm.names[0].name, "wall");
    cvm__vtu_mesh_free(&g_ctx, &vm);
    ck_assert_int_eq((int)g_a.live_blocks, 0);
}
END_TEST

START_TEST(msh_malformed_files_are_named)
{
    expect_bad("20 1 0 0", "20 1 x 0", CVM_E_IO_FORMAT, "t.msh:11: a node coordinate is 'x', not a number");
    expect_bad("20 1 0 0", "20 1 nan 0", CVM_E_INPUT_NONFINITE, "t.msh:11: a node coordinate is 'nan', not a finite number");
    expect_bad("20 1 0 0", "20 1 0 3", CVM_E_IO_FORMAT, "t.msh: node 20 has z = 3");
    expect_bad("20 1 0 0", "10 1 0 0", CVM_E_IO_FORMAT, "t.msh: node tag 10 appears twice");
    expect_bad("3 2 0 10 30 40", "3 2 0 10 30 41", CVM_E_IO_FORMAT, "element 3 names node 41, which does not exist");
    expect_bad("3 2 0 10 30 40", "3 3 0 10 30 40 20", CVM_E_UNSUPPORTED, "t.msh:19: element 3 has Gmsh type 3");
    expect_bad("2.2 0 8", "3.0 0 8", CVM_E_UNSUPPORTED, "MSH version 3.0 is not read");
    expect_bad("$EndNodes", "$EndNode", CVM_E_IO_FORMAT, "$Nodes has no $EndNodes");
    expect_bad("\"wall\"", "wall", CVM_E_IO_FORMAT, "physical name 0 is not in double quotes");
    expect_bad("$MeshFormat\n", "$Mesh\n", CVM_E_IO_FORMAT, "t.msh:1: not a Gmsh file");
    expect_bad("$Elements\n3\n", "$Elements\n4\n", CVM_E_IO_FORMAT, "an element tag is '$EndElements'");
}
END_TEST

TCase *io_read_msh_tcase(void)
{
    TCase *tc = tcase_create("read_msh");
    tcase_add_checked_fixture(tc, setup, NULL);
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, msh_files_of_meshio_are_read_with_tags_and_names);
    tcase_add_test(tc, msh_domain_of_lines_and_points_is_read_by_extension);
    tcase_add_test(tc, msh_sparse_node_tags_are_mapped);
    tcase_add_test(tc, msh_malformed_files_are_named);
    return tc;
}
