/* test_write_triangle.c - .node/.ele/.edge output: exact round trip of every number, 0-based ids. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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

START_TEST(node_file_reads_back_bit_for_bit)
{
    cvm__mesh_out mo;
    cvm__ctx ctx;
    cvm__pslg p;
    char path[4096];
    cvm__ctx_init_default(&ctx);
    iotest_mesh_out(&mo);
    snprintf(path, sizeof path, "%s/rt.node", g_dir);
    ck_assert_int_eq(cvm__write_file(&ctx, path, &mo), CVM_OK);
    ck_assert_msg(cvm__read_file(&ctx, path, &p) == CVM_OK, "%s", ctx.errmsg);
    ck_assert_uint_eq(p.np, mo.nv);
    ck_assert_int_eq(memcmp(p.xy, mo.xy, 2 * mo.nv * sizeof(double)), 0);
    ck_assert_uint_eq(p.nattr, 1);
    ck_assert_int_eq(memcmp(p.pattr, mo.vattr, mo.nv * sizeof(double)), 0);
    ck_assert_int_eq(memcmp(p.pmark, mo.vmark, mo.nv * sizeof(int32_t)), 0);
    cvm__pslg_free(&ctx, &p);
}
END_TEST

START_TEST(ele_and_edge_files_are_zero_based)
{
    cvm__mesh_out mo;
    cvm__ctx ctx;
    char path[4096];
    FILE *f;
    long n, a, b, c, i, k, mark;
    double attr;
    cvm__ctx_init_default(&ctx);
    iotest_mesh_out(&mo);
    snprintf(path, sizeof path, "%s/rt.node", g_dir);
    ck_assert_int_eq(cvm__write_file(&ctx, path, &mo), CVM_OK);
    snprintf(path, sizeof path, "%s/rt.ele", g_dir);
    f = fopen(path, "r");
    ck_assert_ptr_nonnull(f);
    ck_assert_int_eq(fscanf(f, "%ld %ld %ld", &n, &a, &b), 3);
    ck_assert_int_eq((int)n, 4);
    ck_assert_int_eq((int)a, 3);
    ck_assert_int_eq((int)b, 1);
    for (k = 0; k < n; k++) {
        ck_assert_int_eq(fscanf(f, "%ld %ld %ld %ld %lf", &i, &a, &b, &c, &attr), 5);
        ck_assert_int_eq((int)i, (int)k);
        ck_assert_int_eq((int)a, mo.tri[3 * k]);
        ck_assert_int_eq((int)b, mo.tri[3 * k + 1]);
        ck_assert_int_eq((int)c, mo.tri[3 * k + 2]);
        ck_assert(attr == mo.tattr[k]);
    }
    fclose(f);
    snprintf(path, sizeof path, "%s/rt.edge", g_dir);
    f = fopen(path, "r");
    ck_assert_ptr_nonnull(f);
    ck_assert_int_eq(fscanf(f, "%ld %ld", &n, &a), 2);
    ck_assert_int_eq((int)n, 8);
    ck_assert_int_eq((int)a, 1);
    for (k = 0; k < n; k++) {
        ck_assert_int_eq(fscanf(f, "%ld %ld %ld %ld", &i, &a, &b, &mark), 4);
        ck_assert_int_eq((int)i, (int)k);
        ck_assert_int_eq((int)a, mo.edge[2 * k]);
        ck_assert_int_eq((int)b, mo.edge[2 * k + 1]);
        ck_assert_int_eq((int)mark, mo.emark[k]);
    }
    fclose(f);
}
END_TEST

START_TEST(node_header_and_vertex_without_markers)
{
    cvm__mesh_out mo;
    cvm__ctx ctx;
    char path[4096], *text;
    cvm__ctx_init_default(&ctx);
    iotest_mesh_out(&mo);
    mo.vmark = NULL;
    mo.vattr = NULL;
    mo.tattr = NULL;
    snprintf(path, sizeof path, "%s/plain.node", g_dir);
    ck_assert_int_eq(cvm__write_file(&ctx, path, &mo), CVM_OK);
    text = iotest_slurp(path, NULL);
    ck_assert_ptr_nonnull(strstr(text, "5 2 0 1\n0 0 0 0\n1 1 0 0\n"));
    ck_assert_ptr_nonnull(strstr(text, "\n3 0.1 0.3333333333333333"));
    free(text);
    snprintf(path, sizeof path, "%s/plain.ele", g_dir);
    text = iotest_slurp(path, NULL);
    ck_assert_ptr_nonnull(strstr(text, "4 3 0\n0 0 1 4\n"));
    free(text);
}
END_TEST

TCase *io_write_triangle_tcase(void)
{
    TCase *tc = tcase_create("write_triangle");
    tcase_add_checked_fixture(tc, setup, teardown);
    tcase_add_test(tc, node_file_reads_back_bit_for_bit);
    tcase_add_test(tc, ele_and_edge_files_are_zero_based);
    tcase_add_test(tc, node_header_and_vertex_without_markers);
    return tc;
}
