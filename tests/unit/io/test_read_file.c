/* test_read_file.c - reading by file name: extensions, a .poly whose points live in its .node, bad files, OOM. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/io_tests.h"

static cvmtest_alloc g_a;
static cvm__ctx g_ctx;

static void setup(void)
{
    cvmtest_alloc_init(&g_a, 0, 0);
    iotest_ctx(&g_ctx, &g_a);
}

static cvm_status read_data(const char *name, cvm__pslg *p)
{
    char path[4096];
    iotest_path(path, sizeof path, iotest_data_dir(), name);
    return cvm__read_file(&g_ctx, path, p);
}

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    ck_assert_ptr_nonnull(f);
    fputs(text, f);
    ck_assert_int_eq(fclose(f), 0);
}

START_TEST(poly_without_points_reads_its_node_file)
{
    static const int32_t seg[] = {0, 1, 1, 2, 2, 3, 3, 0};
    cvm__pslg p;
    ck_assert_msg(read_data("points_in_node_file.poly", &p) == CVM_OK, "%s", g_ctx.errmsg);
    ck_assert_uint_eq(p.np, 4);
    ck_assert(p.xy[2] == 2.0 && p.xy[5] == 1.0);
    ck_assert_int_eq(p.pmark[0], 5);
    ck_assert_int_eq(p.pmark[3], 6);
    ck_assert_uint_eq(p.nseg, 4);
    ck_assert_int_eq(memcmp(p.seg, seg, sizeof seg), 0);
    ck_assert_int_eq(p.smark[3], 6);
    cvm__pslg_free(&g_ctx, &p);
    ck_assert_int_eq((int)g_a.live_blocks, 0);
}
END_TEST

START_TEST(node_extension_reads_a_point_set)
{
    cvm__pslg p;
    ck_assert_int_eq(read_data("cocircular_octagon_and_centre.node", &p), CVM_OK);
    ck_assert_uint_eq(p.np, 9);
    ck_assert_uint_eq(p.nseg, 0);
    cvm__pslg_free(&g_ctx, &p);
}
END_TEST

START_TEST(unknown_extension_is_unsupported)
{
    cvm__pslg p;
    ck_assert_int_eq(cvm__read_file(&g_ctx, "mesh.off", &p), CVM_E_UNSUPPORTED);
    ck_assert_ptr_nonnull(strstr(g_ctx.errmsg, "mesh.off"));
    ck_assert_int_eq(cvm__read_file(&g_ctx, "poly", &p), CVM_E_UNSUPPORTED);
}
END_TEST

START_TEST(extension_ignores_case_and_missing_file_is_io_open)
{
    char *dir = iotest_tmpdir(), path[4096];
    cvm__pslg p;
    snprintf(path, sizeof path, "%s/UPPER.POLY", dir);
    write_text(path, "3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n0\n0\n");
    ck_assert_int_eq(cvm__read_file(&g_ctx, path, &p), CVM_OK);
    ck_assert_uint_eq(p.np, 3);
    cvm__pslg_free(&g_ctx, &p);
    snprintf(path, sizeof path, "%s/missing.poly", dir);
    ck_assert_int_eq(cvm__read_file(&g_ctx, path, &p), CVM_E_IO_OPEN);
    ck_assert_ptr_nonnull(strstr(g_ctx.errmsg, "missing.poly"));
    iotest_rmdir(dir);
    free(dir);
}
END_TEST

START_TEST(poly_without_points_and_without_node_names_both)
{
    char *dir = iotest_tmpdir(), path[4096];
    cvm__pslg p;
    snprintf(path, sizeof path, "%s/lonely.poly", dir);
    write_text(path, "0 2 0 0\n1 0\n1 1 2\n0\n");
    ck_assert_int_eq(cvm__read_file(&g_ctx, path, &p), CVM_E_IO_OPEN);
    ck_assert_ptr_nonnull(strstr(g_ctx.errmsg, "lonely.poly has no points"));
    ck_assert_ptr_nonnull(strstr(g_ctx.errmsg, "lonely.node"));
    ck_assert_int_eq((int)g_a.live_blocks, 0);
    iotest_rmdir(dir);
    free(dir);
}
END_TEST

START_TEST(poly_segments_are_checked_against_node_points)
{
    char *dir = iotest_tmpdir(), path[4096];
    cvm__pslg p;
    snprintf(path, sizeof path, "%s/two.node", dir);
    write_text(path, "2 2 0 0\n0 0 0\n1 1 0\n");
    snprintf(path, sizeof path, "%s/two.poly", dir);
    write_text(path, "# points in two.node\n0 2 0 0\n1 0\n0 0 2\n0\n");
    ck_assert_int_eq(cvm__read_file(&g_ctx, path, &p), CVM_E_IO_FORMAT);
    ck_assert_ptr_nonnull(strstr(g_ctx.errmsg, "two.poly:4:"));
    ck_assert_ptr_nonnull(strstr(g_ctx.errmsg, "numbered 0..1"));
    ck_assert_int_eq((int)g_a.live_blocks, 0);
    iotest_rmdir(dir);
    free(dir);
}
END_TEST

START_TEST(bad_data_files_name_their_line)
{
    static const struct {
        const char *name;
        cvm_status s;
        const char *line;
    } bad[] = {
        {"bad_truncated_points.poly", CVM_E_IO_FORMAT, "bad_truncated_points.poly:4:"},
        {"bad_nan_coordinate.poly", CVM_E_INPUT_NONFINITE, "bad_nan_coordinate.poly:3:"},
        {"bad_segment_index.poly", CVM_E_IO_FORMAT, "bad_segment_index.poly:7:"},
        {"bad_point_count_too_small.poly", CVM_E_IO_FORMAT, "bad_point_count_too_small.poly:6:"},
        {"bad_binary_garbage.poly", CVM_E_IO_FORMAT, "bad_binary_garbage.poly:3:"},
    };
    size_t i;
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        cvm__pslg p;
        cvm_status s = read_data(bad[i].name, &p);
        ck_assert_msg(s == bad[i].s, "%s: %d %s", bad[i].name, (int)s, g_ctx.errmsg);
        ck_assert_msg(strstr(g_ctx.errmsg, bad[i].line) != NULL, "%s", g_ctx.errmsg);
        ck_assert_int_eq((int)g_a.live_blocks, 0);
    }
}
END_TEST

START_TEST(read_file_runs_out_of_memory_cleanly)
{
    char path[4096];
    long k;
    iotest_path(path, sizeof path, iotest_data_dir(), "points_in_node_file.poly");
    for (k = 1;; k++) {
        cvm__pslg p;
        cvm_status s;
        cvmtest_alloc_init(&g_a, k, 0);
        s = cvm__read_file(&g_ctx, path, &p);
        if (s == CVM_OK) {
            ck_assert_uint_eq(p.np, 4);
            cvm__pslg_free(&g_ctx, &p);
            ck_assert_int_eq((int)g_a.live_blocks, 0);
            break;
        }
        ck_assert_msg(s == CVM_E_NOMEM, "k=%ld: %d %s", k, (int)s, g_ctx.errmsg);
        ck_assert_int_eq((int)g_a.live_blocks, 0);
        ck_assert(k < 1000);
    }
}
END_TEST

static int g_read_polls;

static int stop_reading(void *payload, cvm_stage stage, double fraction)
{
    (void)payload;
    ck_assert_int_eq((int)stage, (int)CVM_STAGE_READ);
    ck_assert(fraction >= 0 && fraction <= 1);
    g_read_polls++;
    return g_read_polls >= 2;
}

/* A file of several 64 KiB chunks: the progress callback is asked between
 * chunks and can stop the reading, which then leaves nothing allocated. */
START_TEST(a_long_read_can_be_cancelled)
{
    char *dir = iotest_tmpdir(), path[4096];
    cvm__pslg p;
    cvm__vtu_mesh vm;
    FILE *f;
    int i;
    snprintf(path, sizeof path, "%s/big.node", dir);
    f = fopen(path, "w");
    ck_assert_ptr_nonnull(f);
    fprintf(f, "20000 2 0 0\n");
    for (i = 0; i < 20000; i++)
        fprintf(f, "%d %d.25 %d.5\n", i, i % 141, i / 141);
    ck_assert_int_eq(fclose(f), 0);
    ck_assert_int_eq(cvm__read_file(&g_ctx, path, &p), CVM_OK); /* no callback: read whole */
    ck_assert_uint_eq(p.np, 20000);
    cvm__pslg_free(&g_ctx, &p);
    g_ctx.progress_fn = stop_reading;
    g_ctx.progress_every = 1;
    g_read_polls = 0;
    ck_assert_int_eq(cvm__read_file(&g_ctx, path, &p), CVM_INCOMPLETE_CANCELLED);
    ck_assert_int_eq(g_read_polls, 2);
    ck_assert_ptr_nonnull(strstr(g_ctx.errmsg, "cancelled"));
    ck_assert_ptr_null(p.xy);
    ck_assert_int_eq((int)g_a.live_blocks, 0);
    /* the .vtu reader too (the cancellation comes before any parsing) */
    snprintf(path, sizeof path, "%s/big.vtu", dir);
    f = fopen(path, "w");
    ck_assert_ptr_nonnull(f);
    for (i = 0; i < 20000; i++)
        fprintf(f, "<!-- padding line %d of a file longer than two chunks -->\n", i);
    ck_assert_int_eq(fclose(f), 0);
    g_read_polls = 0;
    ck_assert_int_eq(cvm__read_vtu_file(&g_ctx, path, &vm), CVM_INCOMPLETE_CANCELLED);
    ck_assert_int_eq(g_read_polls, 2);
    ck_assert_int_eq((int)g_a.live_blocks, 0);
    g_ctx.progress_fn = NULL;
    g_ctx.progress_every = 0;
    iotest_rmdir(dir);
    free(dir);
}
END_TEST

TCase *io_read_file_tcase(void)
{
    TCase *tc = tcase_create("read_file");
    tcase_add_checked_fixture(tc, setup, NULL);
    tcase_add_test(tc, poly_without_points_reads_its_node_file);
    tcase_add_test(tc, a_long_read_can_be_cancelled);
    tcase_add_test(tc, node_extension_reads_a_point_set);
    tcase_add_test(tc, unknown_extension_is_unsupported);
    tcase_add_test(tc, extension_ignores_case_and_missing_file_is_io_open);
    tcase_add_test(tc, poly_without_points_and_without_node_names_both);
    tcase_add_test(tc, poly_segments_are_checked_against_node_points);
    tcase_add_test(tc, bad_data_files_name_their_line);
    tcase_add_test(tc, read_file_runs_out_of_memory_cleanly);
    return tc;
}
