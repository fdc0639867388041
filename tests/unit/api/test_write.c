/* test_write.c - cvm_mesh_write (lib/api/mesh_write.c): formats, state, failures, OOM, round trip. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "api/api_tests.h"
#include "support/failing_alloc.h"
#include "support/fixtures.h"
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

static void in_dir(char *buf, size_t len, const char *name)
{
    snprintf(buf, len, "%s/%s", g_dir, name);
}

START_TEST(write_needs_a_triangulation_and_a_known_extension)
{
    cvm_mesh *m;
    char path[4096];
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    in_dir(path, sizeof path, "m.vtu");
    ck_assert_int_eq(cvm_mesh_write(m, path), CVM_E_STATE);
    ck_assert_int_eq(cvmtest_pslg_set(m, &cvmtest_square_with_hole), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    in_dir(path, sizeof path, "m.obj");
    ck_assert_int_eq(cvm_mesh_write(m, path), CVM_E_UNSUPPORTED);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "m.obj"));
    ck_assert_int_eq(cvm_mesh_write(m, NULL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_write(NULL, path), CVM_E_NULL_ARG);
    in_dir(path, sizeof path, "missing/m.vtu");
    ck_assert_int_eq(cvm_mesh_write(m, path), CVM_E_IO_OPEN);
    ck_assert_int_eq(iotest_count_entries(g_dir), 0);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(node_output_reads_back_and_matches_the_triangles)
{
    cvm_mesh *m, *r;
    char path[4096];
    double xy[16], back[16];
    cvm_index tri[24];
    size_t nv, nt, k;
    long n, i, a, b, c;
    FILE *f;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvmtest_pslg_set(m, &cvmtest_square_with_hole), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    in_dir(path, sizeof path, "m.node");
    ck_assert_msg(cvm_mesh_write(m, path) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(iotest_count_entries(g_dir), 3);
    ck_assert_int_eq(cvm_mesh_create(&r), CVM_OK);
    ck_assert_msg(cvm_mesh_read(r, path) == CVM_OK, "%s", cvm_mesh_errmsg(r));
    ck_assert_int_eq(cvm_mesh_count(&nv, r, CVM_ENT_INPUT_POINT), CVM_OK);
    ck_assert_uint_eq(nv, 8);
    ck_assert_int_eq(cvm_mesh_triangulate(r), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_points(back, 16, r), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_points(xy, 16, m), CVM_OK);
    ck_assert_int_eq(memcmp(xy, back, sizeof xy), 0);
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(tri, 3 * nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    in_dir(path, sizeof path, "m.ele");
    f = fopen(path, "r");
    ck_assert_ptr_nonnull(f);
    ck_assert_int_eq(fscanf(f, "%ld %ld %ld", &n, &a, &b), 3);
    ck_assert_int_eq((int)n, (int)nt);
    for (k = 0; k < nt; k++) {
        ck_assert_int_eq(fscanf(f, "%ld %ld %ld %ld", &i, &a, &b, &c), 4);
        ck_assert(a == tri[3 * k] && b == tri[3 * k + 1] && c == tri[3 * k + 2]);
    }
    fclose(f);
    cvm_mesh_free(r);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(write_runs_out_of_memory_and_the_handle_goes_on)
{
    static const char *const names[] = {"m.vtu", "m.msh", "m.node", "m.svg"};
    cvmtest_alloc a;
    cvm_mesh *m;
    char path[4096];
    size_t i;
    long live;
    cvmtest_alloc_init(&a, 0, 0);
    ck_assert_int_eq(cvmtest_mesh_create(&m, &a), CVM_OK);
    ck_assert_int_eq(cvmtest_pslg_set(m, &cvmtest_square_with_hole), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    live = a.live_blocks;
    for (i = 0; i < 4; i++) {
        long k;
        in_dir(path, sizeof path, names[i]);
        for (k = 1;; k++) {
            cvm_status s;
            cvmtest_alloc_arm(&a, k, 0);
            s = cvm_mesh_write(m, path);
            ck_assert_int_eq((int)a.live_blocks, (int)live);
            if (s == CVM_OK)
                break;
            ck_assert_msg(s == CVM_E_NOMEM, "%s k=%ld: %s", names[i], k, cvm_mesh_errmsg(m));
            ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "out of memory"));
            ck_assert(k < 200);
        }
    }
    ck_assert_int_eq(iotest_count_entries(g_dir), 6);
    cvm_mesh_free(m);
    ck_assert_int_eq((int)a.live_blocks, 0);
}
END_TEST

TCase *api_write_tcase(void)
{
    TCase *tc = tcase_create("write");
    tcase_add_checked_fixture(tc, setup, teardown);
    tcase_add_test(tc, write_needs_a_triangulation_and_a_known_extension);
    tcase_add_test(tc, node_output_reads_back_and_matches_the_triangles);
    tcase_add_test(tc, write_runs_out_of_memory_and_the_handle_goes_on);
    return tc;
}
