/* test_write_vtu_binary.c - binary and zlib .vtu (write_vtu_binary.c): read back exactly, same arrays as ASCII, OOM. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/io_tests.h"

/* Write mo with encoding enc to a fresh directory and read it back into vm. */
static char *write_read(cvm__mesh_out *mo, int enc, cvm__vtu_mesh *vm, size_t *len)
{
    char *dir = iotest_tmpdir(), path[4096], *text;
    cvm__ctx ctx;
    cvm__ctx_init_default(&ctx);
    snprintf(path, sizeof path, "%s/m.vtu", dir);
    mo->vtu_encoding = enc;
    ck_assert_int_eq(cvm__write_file(&ctx, path, mo), CVM_OK);
    text = iotest_slurp(path, len);
    ck_assert_ptr_nonnull(text);
    ck_assert_msg(cvm__read_vtu_file(&ctx, path, vm) == CVM_OK, "%s", ctx.errmsg);
    iotest_rmdir(dir);
    free(dir);
    return text;
}

/* Every encoding gives back the written values exactly. */
START_TEST(vtu_binary_and_zlib_read_back_exactly)
{
    static const double w[5] = {0, 0.125, 1e-300, 3.5, 0};
    int enc, weighted;
    for (weighted = 0; weighted < 2; weighted++)
        for (enc = 0; enc < 3; enc++) {
            cvm__mesh_out mo;
            cvm__vtu_mesh vm;
            cvm__ctx ctx;
            size_t k, len;
            char *text;
            iotest_mesh_out(&mo);
            if (weighted)
                mo.weight = w;
            text = write_read(&mo, enc, &vm, &len);
            ck_assert_msg((strstr(text, "format=\"appended\"") != NULL) == (enc > 0), "encoding %d", enc);
            ck_assert_msg((strstr(text, "vtkZLibDataCompressor") != NULL) == (enc == 2), "encoding %d", enc);
            ck_assert_uint_eq(vm.p.np, mo.nv);
            for (k = 0; k < 2 * mo.nv; k++)
                ck_assert(vm.p.xy[k] == mo.xy[k]);
            ck_assert_uint_eq(vm.nt, mo.nt);
            for (k = 0; k < 3 * mo.nt; k++)
                ck_assert_int_eq(vm.tri[k], mo.tri[k]);
            ck_assert_uint_eq(vm.p.nseg, mo.nseg);
            for (k = 0; k < mo.nseg; k++) {
                ck_assert_int_eq(vm.p.seg[2 * k + 1], mo.seg[2 * k + 1]);
                ck_assert_int_eq(vm.p.smark[k], mo.smark[k]);
            }
            for (k = 0; k < mo.nv; k++)
                ck_assert_int_eq(vm.p.pmark[k], mo.vmark[k]);
            for (k = 0; k < mo.nt; k++)
                ck_assert(vm.tattr[k] == mo.tattr[k]);
            /* with weights, vattr's single column is the weight (no "attribute") */
            ck_assert_uint_eq(vm.p.nattr, weighted ? 0 : 1);
            for (k = 0; !weighted && k < mo.nv; k++)
                ck_assert(vm.p.pattr[k] == mo.vattr[k]);
            ck_assert((vm.w != NULL) == weighted);
            for (k = 0; weighted && k < mo.nv; k++)
                ck_assert(vm.w[k] == w[k]);
            cvm__ctx_init_default(&ctx);
            cvm__vtu_mesh_free(&ctx, &vm);
            free(text);
        }
}
END_TEST

/* A mesh large enough for several zlib blocks per array. */
START_TEST(vtu_zlib_spans_blocks)
{
    size_t n = 20000, k, len;
    double *xy = malloc(2 * n * sizeof *xy);
    int32_t *tri = malloc(3 * (n - 2) * sizeof *tri);
    cvm__mesh_out mo;
    cvm__vtu_mesh vm;
    cvm__ctx ctx;
    char *text;
    ck_assert(xy && tri);
    for (k = 0; k < n; k++) {
        xy[2 * k] = (double)k / 7.0;
        xy[2 * k + 1] = (double)(k % 2);
    }
    for (k = 0; k + 2 < n; k++) {
        tri[3 * k] = (int32_t)k;
        tri[3 * k + 1] = (int32_t)k + 1;
        tri[3 * k + 2] = (int32_t)k + 2;
    }
    memset(&mo, 0, sizeof mo);
    mo.xy = xy;
    mo.nv = n;
    mo.tri = tri;
    mo.nt = n - 2;
    text = write_read(&mo, 2, &vm, &len);
    ck_assert_uint_eq(vm.nt, n - 2);
    for (k = 0; k < 2 * n; k++)
        ck_assert(vm.p.xy[k] == xy[k]);
    for (k = 0; k < 3 * (n - 2); k++)
        ck_assert_int_eq(vm.tri[k], tri[k]);
    ck_assert_uint_lt(len, 3 * n * 8); /* the regular coordinates compress */
    cvm__ctx_init_default(&ctx);
    cvm__vtu_mesh_free(&ctx, &vm);
    free(text);
    free(xy);
    free(tri);
}
END_TEST

/* Allocation k failing: CVM_E_NOMEM, no file and no leak, until it succeeds. */
START_TEST(vtu_zlib_write_survives_oom)
{
    char *dir = iotest_tmpdir(), path[4096];
    cvm__mesh_out mo;
    long k;
    iotest_mesh_out(&mo);
    mo.vtu_encoding = 2;
    snprintf(path, sizeof path, "%s/m.vtu", dir);
    for (k = 1;; k++) {
        cvmtest_alloc a;
        cvm__ctx ctx;
        cvm_status s;
        cvmtest_alloc_init(&a, k, 0);
        iotest_ctx(&ctx, &a);
        s = cvm__write_file(&ctx, path, &mo);
        ck_assert_int_eq((int)a.live_blocks, 0);
        if (s == CVM_OK)
            break;
        ck_assert_int_eq(s, CVM_E_NOMEM);
        ck_assert_int_eq(iotest_count_entries(dir), 0);
    }
    ck_assert(k > 3);
    iotest_rmdir(dir);
    free(dir);
}
END_TEST

/* CVM_VTU_AUTO: ASCII up to CVM_VTU_AUTO_MAX_ASCII_POINTS vertices, binary
 * from one more; both read back to the same points. */
START_TEST(vtu_auto_is_binary_above_the_threshold)
{
    size_t n, k, len;
    double *xy;
#if defined(__SANITIZE_ADDRESS__)
    return; /* two files of a million points: the plain, clang and amalgamation runs cover it */
#endif
    xy = malloc(2 * (CVM_VTU_AUTO_MAX_ASCII_POINTS + 1) * sizeof *xy);
    ck_assert_ptr_nonnull(xy);
    for (k = 0; k < CVM_VTU_AUTO_MAX_ASCII_POINTS + 1; k++) {
        xy[2 * k] = (double)(k % 1000);
        xy[2 * k + 1] = (double)(k / 1000);
    }
    for (n = CVM_VTU_AUTO_MAX_ASCII_POINTS; n <= CVM_VTU_AUTO_MAX_ASCII_POINTS + 1; n++) {
        cvm__mesh_out mo;
        cvm__vtu_mesh vm;
        cvm__ctx ctx;
        char *text;
        memset(&mo, 0, sizeof mo);
        mo.xy = xy;
        mo.nv = n;
        text = write_read(&mo, CVM_VTU_AUTO, &vm, &len);
        ck_assert_msg((strstr(text, "format=\"appended\"") != NULL) == (n > CVM_VTU_AUTO_MAX_ASCII_POINTS),
                      "%lu points", (unsigned long)n);
        ck_assert_msg((strstr(text, "format=\"ascii\"") != NULL) == (n <= CVM_VTU_AUTO_MAX_ASCII_POINTS),
                      "%lu points", (unsigned long)n);
        ck_assert_uint_eq(vm.p.np, n);
        ck_assert(vm.p.xy[2 * n - 2] == xy[2 * n - 2] && vm.p.xy[2 * n - 1] == xy[2 * n - 1]);
        cvm__ctx_init_default(&ctx);
        cvm__vtu_mesh_free(&ctx, &vm);
        free(text);
    }
    free(xy);
}
END_TEST

TCase *io_write_vtu_binary_tcase(void)
{
    TCase *tc = tcase_create("write_vtu_binary");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, vtu_binary_and_zlib_read_back_exactly);
    tcase_add_test(tc, vtu_zlib_spans_blocks);
    tcase_add_test(tc, vtu_zlib_write_survives_oom);
    tcase_add_test(tc, vtu_auto_is_binary_above_the_threshold);
    return tc;
}
