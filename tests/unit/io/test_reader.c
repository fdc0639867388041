/* test_reader.c - the file reader, and read faults injected at every byte of an input. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io/io_tests.h"
#include "support/failing_reader.h"

static const char k_text[] = "# fault injection\n4 2 1 1\n1 0 0 0.5 1\n2 1 0 0.5 1\n3 1 1 0.5 2\n"
                             "4 0 1 0.5 2\n4 1\n1 1 2 3\n2 2 3 3\n3 3 4 4\n4 4 1 4\n1\n1 0.5 0.5\n";

START_TEST(read_fault_at_every_byte_is_io_read_and_leaks_nothing)
{
    size_t len = sizeof k_text - 1, chunk;
    long k;
    for (chunk = 0; chunk <= 7; chunk += 7) {
        for (k = 0; k <= (long)len + 1; k++) {
            cvmtest_alloc a;
            cvm__ctx ctx;
            cvmtest_reader tr;
            cvm__reader r;
            cvm__pslg p;
            cvm_status s;
            cvmtest_alloc_init(&a, 0, 0);
            iotest_ctx(&ctx, &a);
            cvmtest_reader_init(&tr, &r, k_text, len, chunk, k);
            s = cvm__read_triangle_format(&ctx, &r, "f.poly", 1, &p);
            if (k <= (long)len) {
                ck_assert_msg(s == CVM_E_IO_READ, "k=%ld: %d %s", k, (int)s, ctx.errmsg);
                ck_assert_ptr_nonnull(strstr(ctx.errmsg, "f.poly:"));
                ck_assert_ptr_nonnull(strstr(ctx.errmsg, "read error"));
                ck_assert_ptr_null(p.xy);
            } else {
                ck_assert_msg(s == CVM_OK, "k=%ld: %s", k, ctx.errmsg);
                ck_assert_uint_eq(p.np, 4);
                ck_assert_uint_eq(p.nseg, 4);
                cvm__pslg_free(&ctx, &p);
            }
            ck_assert_int_eq((int)a.live_blocks, 0);
        }
    }
}
END_TEST

START_TEST(short_reads_give_the_same_result)
{
    size_t len = sizeof k_text - 1, chunk;
    cvm__pslg ref;
    cvm__ctx ctx;
    cvm__ctx_init_default(&ctx);
    ck_assert_int_eq(iotest_parse(&ctx, k_text, len, 1, &ref), CVM_OK);
    for (chunk = 1; chunk < 20; chunk++) {
        cvmtest_reader tr;
        cvm__reader r;
        cvm__pslg p;
        cvmtest_reader_init(&tr, &r, k_text, len, chunk, -1);
        ck_assert_int_eq(cvm__read_triangle_format(&ctx, &r, "f.poly", 1, &p), CVM_OK);
        ck_assert_uint_eq(p.np, ref.np);
        ck_assert_int_eq(memcmp(p.xy, ref.xy, 2 * p.np * sizeof(double)), 0);
        ck_assert_int_eq(memcmp(p.pattr, ref.pattr, p.np * sizeof(double)), 0);
        ck_assert_int_eq(memcmp(p.pmark, ref.pmark, p.np * sizeof(int32_t)), 0);
        ck_assert_int_eq(memcmp(p.seg, ref.seg, 2 * p.nseg * sizeof(int32_t)), 0);
        ck_assert_int_eq(memcmp(p.smark, ref.smark, p.nseg * sizeof(int32_t)), 0);
        ck_assert_int_eq(memcmp(p.holes, ref.holes, 2 * sizeof(double)), 0);
        cvm__pslg_free(&ctx, &p);
    }
    cvm__pslg_free(&ctx, &ref);
}
END_TEST

START_TEST(file_reader_reports_missing_file)
{
    cvm__ctx ctx;
    cvm__reader r;
    cvm__ctx_init_default(&ctx);
    ck_assert_int_eq(cvm__file_reader_open(&ctx, &r, "/nonexistent/dir/x.poly"), CVM_E_IO_OPEN);
    ck_assert_ptr_nonnull(strstr(ctx.errmsg, "cannot open /nonexistent/dir/x.poly"));
    cvm__file_reader_close(&r);
}
END_TEST

/* fopen() opens a directory on POSIX systems and only the first read fails
 * (EISDIR): the reader refuses it at open, saying what it is. */
START_TEST(file_reader_refuses_a_directory_at_open)
{
    cvm__ctx ctx;
    cvm__reader r;
    cvm__pslg p;
    char path[4096], *dir;
    cvm__ctx_init_default(&ctx);
    ck_assert_int_eq(cvm__file_reader_open(&ctx, &r, "/"), CVM_E_IO_OPEN);
    ck_assert_str_eq(ctx.errmsg, "cannot read /: it is a directory");
    cvm__file_reader_close(&r);
    /* and so does reading an input by name */
    dir = iotest_tmpdir();
    snprintf(path, sizeof path, "%s/d.poly", dir);
    ck_assert_int_eq(mkdir(path, 0700), 0);
    memset(&p, 0, sizeof p);
    ck_assert_int_eq(cvm__read_file(&ctx, path, &p), CVM_E_IO_OPEN);
    ck_assert_ptr_nonnull(strstr(ctx.errmsg, "d.poly: it is a directory"));
    ck_assert_ptr_null(p.xy);
    ck_assert_int_eq(rmdir(path), 0);
    iotest_rmdir(dir);
    free(dir);
}
END_TEST

TCase *io_reader_tcase(void)
{
    TCase *tc = tcase_create("reader");
    tcase_add_test(tc, read_fault_at_every_byte_is_io_read_and_leaks_nothing);
    tcase_add_test(tc, short_reads_give_the_same_result);
    tcase_add_test(tc, file_reader_reports_missing_file);
    tcase_add_test(tc, file_reader_refuses_a_directory_at_open);
    return tc;
}
