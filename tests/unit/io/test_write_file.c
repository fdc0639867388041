/* test_write_file.c - writing by extension: all files or none, on unknown formats, full disks and OOM. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io/io_tests.h"

static cvmtest_alloc g_a;
static cvm__ctx g_ctx;
static char *g_dir;
static cvm__mesh_out g_mo;

static void setup(void)
{
    cvmtest_alloc_init(&g_a, 0, 0);
    iotest_ctx(&g_ctx, &g_a);
    g_dir = iotest_tmpdir();
    iotest_mesh_out(&g_mo);
}

static void teardown(void)
{
    iotest_rmdir(g_dir);
    free(g_dir);
}

static cvm_status write_name(const char *name)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", g_dir, name);
    return cvm__write_file(&g_ctx, path, &g_mo);
}

START_TEST(format_follows_extension_case_insensitively)
{
    ck_assert_int_eq(cvm__format_of("a.vtu"), CVM__FMT_VTU);
    ck_assert_int_eq(cvm__format_of("a.MSH"), CVM__FMT_MSH);
    ck_assert_int_eq(cvm__format_of("dir.x/a.node"), CVM__FMT_NODE);
    ck_assert_int_eq(cvm__format_of("a.Svg"), CVM__FMT_SVG);
    ck_assert_int_eq(cvm__format_of("a.ele"), CVM__FMT_NONE);
    ck_assert_int_eq(cvm__format_of(".vtu"), CVM__FMT_NONE);
    ck_assert_int_eq(cvm__format_of("vtu"), CVM__FMT_NONE);
}
END_TEST

START_TEST(every_format_writes_its_files)
{
    ck_assert_int_eq(write_name("m.vtu"), CVM_OK);
    ck_assert_int_eq(write_name("m.msh"), CVM_OK);
    ck_assert_int_eq(write_name("m.svg"), CVM_OK);
    ck_assert_int_eq(write_name("m.node"), CVM_OK);
    ck_assert_int_eq(iotest_count_entries(g_dir), 6); /* vtu msh svg node ele edge */
    g_mo.edge = NULL;
    g_mo.ne = 0;
    ck_assert_int_eq(write_name("noedges.node"), CVM_OK);
    ck_assert_int_eq(iotest_count_entries(g_dir), 8);
    ck_assert_int_eq((int)g_a.live_blocks, 0);
}
END_TEST

START_TEST(unknown_extension_writes_nothing)
{
    ck_assert_int_eq(write_name("m.stl"), CVM_E_UNSUPPORTED);
    ck_assert_ptr_nonnull(strstr(g_ctx.errmsg, "m.stl"));
    ck_assert_int_eq(iotest_count_entries(g_dir), 0);
}
END_TEST

START_TEST(missing_directory_writes_nothing)
{
    ck_assert_int_eq(write_name("nowhere/m.node"), CVM_E_IO_OPEN);
    ck_assert_int_eq(write_name("nowhere/m.vtu"), CVM_E_IO_OPEN);
    ck_assert_int_eq(iotest_count_entries(g_dir), 0);
    ck_assert_int_eq((int)g_a.live_blocks, 0);
}
END_TEST

START_TEST(full_disk_on_one_of_three_files_leaves_none)
{
    char path[4096];
    struct stat st;
    /* Linux (and so Debian) always has /dev/full: its absence is a broken
       test machine, not a reason to pass without checking */
    ck_assert_msg(stat("/dev/full", &st) == 0 && S_ISCHR(st.st_mode),
                  "/dev/full is missing or not a character device");
    snprintf(path, sizeof path, "%s/m.ele", g_dir);
    ck_assert_int_eq(symlink("/dev/full", path), 0);
    ck_assert_int_eq(write_name("m.node"), CVM_E_IO_WRITE);
    ck_assert_ptr_nonnull(strstr(g_ctx.errmsg, "m.ele"));
    ck_assert_int_eq(iotest_count_entries(g_dir), 1); /* the link only: no .node, .edge or temporaries */
    snprintf(path, sizeof path, "%s/m.svg", g_dir);
    ck_assert_int_eq(symlink("/dev/full", path), 0);
    ck_assert_int_eq(write_name("m.svg"), CVM_E_IO_WRITE);
    ck_assert_int_eq(iotest_count_entries(g_dir), 2);
    ck_assert_int_eq((int)g_a.live_blocks, 0);
}
END_TEST

START_TEST(writing_runs_out_of_memory_cleanly)
{
    static const char *const names[] = {"m.vtu", "m.msh", "m.svg", "m.node"};
    size_t i;
    for (i = 0; i < 4; i++) {
        long k;
        for (k = 1;; k++) {
            cvm_status s;
            cvmtest_alloc_init(&g_a, k, 0);
            s = write_name(names[i]);
            ck_assert_int_eq((int)g_a.live_blocks, 0);
            if (s == CVM_OK)
                break;
            ck_assert_msg(s == CVM_E_NOMEM, "%s k=%ld: %d %s", names[i], k, (int)s, g_ctx.errmsg);
            ck_assert_int_eq(iotest_count_entries(g_dir), (int)i);
            ck_assert(k < 100);
        }
    }
    ck_assert_int_eq(iotest_count_entries(g_dir), 6);
}
END_TEST

TCase *io_write_file_tcase(void)
{
    TCase *tc = tcase_create("write_file");
    tcase_add_checked_fixture(tc, setup, teardown);
    tcase_add_test(tc, format_follows_extension_case_insensitively);
    tcase_add_test(tc, every_format_writes_its_files);
    tcase_add_test(tc, unknown_extension_writes_nothing);
    tcase_add_test(tc, missing_directory_writes_nothing);
    tcase_add_test(tc, full_disk_on_one_of_three_files_leaves_none);
    tcase_add_test(tc, writing_runs_out_of_memory_cleanly);
    return tc;
}
