/* test_scan.c - the line scanner: comments, blank lines, CRLF, line numbers, limits. */
#include <stdlib.h>
#include <string.h>

#include "io/io_tests.h"
#include "io/io_text.h"
#include "support/failing_reader.h"

typedef struct scan_fixture {
    cvmtest_alloc a;
    cvm__ctx ctx;
    cvmtest_reader tr;
    cvm__reader r;
    cvm__scan s;
} scan_fixture;

static void open_text(scan_fixture *f, const char *text, size_t len, size_t chunk)
{
    cvmtest_alloc_init(&f->a, 0, 0);
    iotest_ctx(&f->ctx, &f->a);
    cvmtest_reader_init(&f->tr, &f->r, text, len, chunk, -1);
    cvm__scan_init(&f->s, &f->ctx, &f->r, "x.txt");
}

static void close_text(scan_fixture *f)
{
    cvm__scan_free(&f->s);
    ck_assert_int_eq((int)f->a.live_blocks, 0);
}

START_TEST(scan_skips_comments_blank_lines_and_counts_lines)
{
    static const char text[] = "# head\n\n  \t\n1 2 # c\r\n# x\n  3\t4  5 \r\n";
    scan_fixture f;
    int got;
    const char *fl;
    size_t chunk;
    for (chunk = 0; chunk < 5; chunk++) {
        open_text(&f, text, sizeof text - 1, chunk);
        ck_assert_int_eq(cvm__scan_line(&f.s, &got), CVM_OK);
        ck_assert_int_eq(got, 1);
        ck_assert_int_eq((int)f.s.lineno, 4);
        ck_assert_int_eq((int)f.s.nfields, 2);
        ck_assert_str_eq(cvm__scan_field(&f.s), "1");
        ck_assert_str_eq(cvm__scan_field(&f.s), "2");
        ck_assert_ptr_null(cvm__scan_field(&f.s));
        ck_assert_int_eq(cvm__scan_line(&f.s, &got), CVM_OK);
        ck_assert_int_eq((int)f.s.lineno, 6);
        ck_assert_int_eq((int)f.s.nfields, 3);
        fl = cvm__scan_field(&f.s);
        ck_assert_str_eq(fl, "3");
        ck_assert_str_eq(cvm__scan_field(&f.s), "4");
        ck_assert_str_eq(cvm__scan_field(&f.s), "5");
        ck_assert_int_eq(cvm__scan_line(&f.s, &got), CVM_OK);
        ck_assert_int_eq(got, 0);
        ck_assert_int_eq((int)f.s.lineno, 6);
        close_text(&f);
    }
}
END_TEST

START_TEST(scan_last_line_without_newline)
{
    scan_fixture f;
    int got;
    open_text(&f, "a\nb c", 5, 0);
    ck_assert_int_eq(cvm__scan_line(&f.s, &got), CVM_OK);
    ck_assert_int_eq(cvm__scan_line(&f.s, &got), CVM_OK);
    ck_assert_int_eq(got, 1);
    ck_assert_int_eq((int)f.s.lineno, 2);
    ck_assert_int_eq((int)f.s.nfields, 2);
    ck_assert_int_eq(cvm__scan_line(&f.s, &got), CVM_OK);
    ck_assert_int_eq(got, 0);
    close_text(&f);
}
END_TEST

START_TEST(scan_rejects_nul_byte_with_line)
{
    static const char text[] = "1 2\n3 \0 4\n";
    scan_fixture f;
    int got;
    open_text(&f, text, sizeof text - 1, 0);
    ck_assert_int_eq(cvm__scan_line(&f.s, &got), CVM_OK);
    ck_assert_int_eq(cvm__scan_line(&f.s, &got), CVM_E_IO_FORMAT);
    ck_assert_ptr_nonnull(strstr(f.ctx.errmsg, "x.txt:2:"));
    ck_assert_int_eq(f.ctx.err_kind, CVM_ENT_FILE_LINE);
    ck_assert_int_eq((int)f.ctx.err_index, 2);
    close_text(&f);
}
END_TEST

START_TEST(scan_rejects_overlong_line)
{
    size_t n = CVM__LINE_MAX + 10;
    char *text = malloc(n);
    scan_fixture f;
    int got;
    memset(text, 'x', n);
    open_text(&f, text, n, 0);
    ck_assert_int_eq(cvm__scan_line(&f.s, &got), CVM_E_IO_FORMAT);
    ck_assert_ptr_nonnull(strstr(f.ctx.errmsg, "x.txt:1: line longer than"));
    close_text(&f);
    free(text);
}
END_TEST

START_TEST(scan_reports_read_error)
{
    scan_fixture f;
    int got;
    open_text(&f, "1 2\n3 4\n", 8, 0);
    f.tr.fail_after = 5;
    ck_assert_int_eq(cvm__scan_line(&f.s, &got), CVM_OK);
    ck_assert_int_eq(cvm__scan_line(&f.s, &got), CVM_E_IO_READ);
    ck_assert_ptr_nonnull(strstr(f.ctx.errmsg, "x.txt:2: read error"));
    close_text(&f);
}
END_TEST

TCase *io_scan_tcase(void)
{
    TCase *tc = tcase_create("scan");
    tcase_add_test(tc, scan_skips_comments_blank_lines_and_counts_lines);
    tcase_add_test(tc, scan_last_line_without_newline);
    tcase_add_test(tc, scan_rejects_nul_byte_with_line);
    tcase_add_test(tc, scan_rejects_overlong_line);
    tcase_add_test(tc, scan_reports_read_error);
    return tc;
}
