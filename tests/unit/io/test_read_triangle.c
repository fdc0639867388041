/* test_read_triangle.c - the .node/.poly parser: good files, numbering, and every kind of malformed input with its line. */
#include <dirent.h>
#include <stdio.h>
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

static void teardown_check_no_leak(cvm__pslg *p)
{
    cvm__pslg_free(&g_ctx, p);
    ck_assert_int_eq((int)g_a.live_blocks, 0);
}

/* Parse a file through the file reader. */
static cvm_status parse_file(const char *dir, const char *name, int is_poly, cvm__pslg *p)
{
    char path[4096];
    cvm__reader r;
    cvm_status s;
    iotest_path(path, sizeof path, dir, name);
    s = cvm__file_reader_open(&g_ctx, &r, path);
    if (s)
        return s;
    s = cvm__read_triangle_format(&g_ctx, &r, path, is_poly, p);
    cvm__file_reader_close(&r);
    return s;
}

START_TEST(read_domains_with_their_counts)
{
    static const struct {
        const char *name;
        size_t np, nseg, nholes;
        int32_t first_smark, last_smark;
    } files[] = {
        {"square.poly", 4, 4, 0, 1, 1},
        {"channel.poly", 4, 4, 0, 1, 2},
        {"annulus.poly", 192, 192, 1, -1, -1},
        {"cylinder.poly", 100, 100, 1, -1, -1},
        {"naca0012.poly", 264, 264, 1, -1, -1},
    };
    char dir[4096];
    size_t i, k;
    snprintf(dir, sizeof dir, "%s", iotest_domain_dir());
    for (i = 0; i < sizeof files / sizeof files[0]; i++) {
        cvm__pslg p;
        cvm_status s = parse_file(dir, files[i].name, 1, &p);
        ck_assert_msg(s == CVM_OK, "%s: %s", files[i].name, g_ctx.errmsg);
        ck_assert_uint_eq(p.np, files[i].np);
        ck_assert_uint_eq(p.nseg, files[i].nseg);
        ck_assert_uint_eq(p.nholes, files[i].nholes);
        ck_assert_uint_eq(p.nregions, 0);
        ck_assert_ptr_nonnull(p.pmark);
        ck_assert_ptr_nonnull(p.smark);
        for (k = 0; k < 2 * p.nseg; k++)
            ck_assert(p.seg[k] >= 0 && (size_t)p.seg[k] < p.np);
        if (files[i].first_smark >= 0) {
            ck_assert_int_eq(p.smark[0], files[i].first_smark);
            ck_assert_int_eq(p.smark[p.nseg - 1], files[i].last_smark);
        }
        /* 1-based files: segment "1 1 2" is 0-1 */
        ck_assert_int_eq(p.seg[0], 0);
        ck_assert_int_eq(p.seg[1], 1);
        teardown_check_no_leak(&p);
    }
}
END_TEST

START_TEST(read_every_domain)
{
    char dir[4096];
    DIR *dp;
    struct dirent *e;
    int n = 0;
    snprintf(dir, sizeof dir, "%s", iotest_domain_dir());
    dp = opendir(dir);
    ck_assert_msg(dp != NULL, "cannot list %s (set CVM_DATA_DIR)", dir);
    while ((e = readdir(dp)) != NULL) {
        size_t len = strlen(e->d_name);
        cvm__pslg p;
        cvm_status s;
        if (len < 6 || strcmp(e->d_name + len - 5, ".poly") != 0)
            continue;
        s = parse_file(dir, e->d_name, 1, &p);
        ck_assert_msg(s == CVM_OK, "%s: %s", e->d_name, g_ctx.errmsg);
        ck_assert_msg(p.np >= 3 && p.nseg >= 3, "%s: %lu points, %lu segments", e->d_name,
                      (unsigned long)p.np, (unsigned long)p.nseg);
        teardown_check_no_leak(&p);
        n++;
    }
    closedir(dp);
    ck_assert_int_ge(n, 5);
}
END_TEST

START_TEST(read_zero_based_file_with_comments)
{
    cvm__pslg p;
    ck_assert_int_eq(parse_file(iotest_data_dir(), "zero_based_with_comments.poly", 1, &p), CVM_OK);
    ck_assert_uint_eq(p.np, 8);
    ck_assert(p.xy[2] == 3.0 && p.xy[3] == 0.0);
    ck_assert_int_eq(p.pmark[4], 2);
    ck_assert_uint_eq(p.nseg, 8);
    ck_assert_int_eq(p.seg[0], 0);
    ck_assert_int_eq(p.seg[1], 1);
    ck_assert_int_eq(p.seg[14], 7);
    ck_assert_int_eq(p.seg[15], 4);
    ck_assert_int_eq(p.smark[7], 2);
    ck_assert_uint_eq(p.nholes, 1);
    ck_assert(p.holes[0] == 1.5 && p.holes[1] == 1.5);
    teardown_check_no_leak(&p);
}
END_TEST

START_TEST(read_one_based_attributes_and_regions)
{
    cvm__pslg p;
    ck_assert_int_eq(parse_file(iotest_data_dir(), "one_based_attributes_regions.poly", 1, &p), CVM_OK);
    ck_assert_uint_eq(p.np, 6);
    ck_assert_uint_eq(p.nattr, 2);
    ck_assert_ptr_null(p.pmark);
    ck_assert(p.pattr[0] == 10 && p.pattr[1] == -1 && p.pattr[10] == 15 && p.pattr[11] == -3.5);
    ck_assert_uint_eq(p.nseg, 7);
    ck_assert_ptr_null(p.smark);
    ck_assert_int_eq(p.seg[12], 1);
    ck_assert_int_eq(p.seg[13], 4);
    ck_assert_uint_eq(p.nholes, 0);
    ck_assert_uint_eq(p.nregions, 2);
    ck_assert(p.regions[0] == 0.5 && p.regions[1] == 0.5 && p.regions[2] == 7 && p.regions[3] == 0.01);
    ck_assert(p.regions[4] == 1.5 && p.regions[6] == 9 && p.regions[7] == 0);
    teardown_check_no_leak(&p);
}
END_TEST

START_TEST(read_node_file_with_attribute)
{
    cvm__pslg p;
    ck_assert_int_eq(parse_file(iotest_data_dir(), "cocircular_octagon_and_centre.node", 0, &p), CVM_OK);
    ck_assert_uint_eq(p.np, 9);
    ck_assert_uint_eq(p.nattr, 1);
    ck_assert(p.pattr[8] == 1.0);
    ck_assert(p.xy[8] == 0.6 && p.xy[9] == 0.8);
    ck_assert_uint_eq(p.nseg, 0);
    teardown_check_no_leak(&p);
}
END_TEST

START_TEST(numbering_base_follows_first_point)
{
    cvm__pslg p;
    static const char zero[] = "3 2\n0 0 0\n1 1 0\n2 0 1\n1\n0 0 2\n0\n";
    static const char one[] = "3 2\n1 0 0\n2 1 0\n3 0 1\n1\n1 1 3\n0\n";
    ck_assert_int_eq(iotest_parse(&g_ctx, zero, 0, 1, &p), CVM_OK);
    ck_assert_int_eq(p.seg[0], 0);
    ck_assert_int_eq(p.seg[1], 2);
    teardown_check_no_leak(&p);
    ck_assert_int_eq(iotest_parse(&g_ctx, one, 0, 1, &p), CVM_OK);
    ck_assert_int_eq(p.seg[0], 0);
    ck_assert_int_eq(p.seg[1], 2);
    teardown_check_no_leak(&p);
}
END_TEST

/* Each item remembers its number and line in the file, for later messages;
 * a region's maximum area of -1 is Triangle's "no constraint" and is read. */
START_TEST(items_remember_their_file_numbers_and_lines)
{
    cvm__pslg p;
    int64_t num, line;
    static const char text[] = "# 1-based, with comments between points\n"
                               "4 2 0 0\n1 0 0\n2 1 0\n# gap\n\n3 1 1\n4 0 1\n"
                               "2 0\n7 1 2\n9 3 4\n"
                               "1\n5 0.5 0.5\n1\n3 0.1 0.1 1 -1\n";
    ck_assert_int_eq(iotest_parse(&g_ctx, text, 0, 1, &p), CVM_OK);
    ck_assert(cvm__item_src_get(&p.src_point, 0, &num, &line) && num == 1 && line == 3);
    ck_assert(cvm__item_src_get(&p.src_point, 1, &num, &line) && num == 2 && line == 4);
    ck_assert(cvm__item_src_get(&p.src_point, 2, &num, &line) && num == 3 && line == 7);
    ck_assert(cvm__item_src_get(&p.src_point, 3, &num, &line) && num == 4 && line == 8);
    ck_assert_uint_eq(p.src_point.nrun, 2);
    ck_assert(!cvm__item_src_get(&p.src_point, 7, &num, &line) && num == 8 && line == 0);
    ck_assert(cvm__item_src_get(&p.src_segment, 0, &num, &line) && num == 7 && line == 10);
    ck_assert(cvm__item_src_get(&p.src_segment, 1, &num, &line) && num == 9 && line == 11);
    ck_assert(cvm__item_src_get(&p.src_hole, 0, &num, &line) && num == 5 && line == 13);
    ck_assert(cvm__item_src_get(&p.src_region, 0, &num, &line) && num == 3 && line == 15);
    ck_assert_str_eq(p.src_region.file, "t.poly");
    ck_assert(p.regions[3] == -1.0);
    teardown_check_no_leak(&p);
}
END_TEST

START_TEST(header_fields_after_the_count_are_optional)
{
    cvm__pslg p;
    ck_assert_int_eq(iotest_parse(&g_ctx, "2\n0 1 2\n1 3 4\n", 0, 0, &p), CVM_OK);
    ck_assert_uint_eq(p.np, 2);
    ck_assert_uint_eq(p.nattr, 0);
    ck_assert_ptr_null(p.pmark);
    ck_assert(p.xy[3] == 4.0);
    teardown_check_no_leak(&p);
    ck_assert_int_eq(iotest_parse(&g_ctx, "0 2 0 0\n", 0, 0, &p), CVM_OK);
    ck_assert_uint_eq(p.np, 0);
    teardown_check_no_leak(&p);
}
END_TEST

/* A malformed input: the status, the ":LINE:" of the message, and a phrase it must contain. */
typedef struct bad_case {
    const char *what;
    const char *text;
    size_t len;  /* 0: strlen */
    int is_poly;
    cvm_status status;
    const char *line;
    const char *phrase;
} bad_case;

#define TRI3 "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n"
#define SEG3 "3 0\n1 1 2\n2 2 3\n3 3 1\n"

static const bad_case k_bad[] = {
    {"empty file", "", 0, 1, CVM_E_IO_FORMAT, "t.poly:1:", "end of file"},
    {"only comments", "# a\n\n# b\n", 0, 1, CVM_E_IO_FORMAT, "t.poly:3:", "point count line"},
    {"garbage header", "hello world\n", 0, 1, CVM_E_IO_FORMAT, "t.poly:1:", "expected an integer"},
    {"header too long", "3 2 0 0 7\n", 0, 1, CVM_E_IO_FORMAT, "t.poly:1:", "at most 4 fields"},
    {"negative point count", "-3 2 0 0\n", 0, 1, CVM_E_IO_FORMAT, "t.poly:1:", "negative point count"},
    {"huge point count", "99999999999 2 0 0\n", 0, 1, CVM_E_TOO_LARGE, "t.poly:1:", "exceeds"},
    {"hugely negative point count", "-99999999999999999999 2 0 0\n", 0, 1, CVM_E_IO_FORMAT,
     "t.poly:1:", "negative point count -99999999999999999999"},
    {"dimension 3", "3 3 0 0\n", 0, 1, CVM_E_IO_FORMAT, "t.poly:1:", "dimension 3"},
    {"marker flag 2", "3 2 0 2\n", 0, 1, CVM_E_IO_FORMAT, "t.poly:1:", "out of range"},
    {"too many attributes", "3 2 100000 0\n", 0, 1, CVM_E_TOO_LARGE, "t.poly:1:", "attributes"},
    {"truncated points", "4 2 0 0\n1 0 0\n# c\n2 1 0\n", 0, 1, CVM_E_IO_FORMAT, "t.poly:4:",
     "point 3 of 4"},
    {"point line too short", "3 2 0 1\n1 0 0\n", 0, 1, CVM_E_IO_FORMAT, "t.poly:2:",
     "expected 4 fields"},
    {"point line too long", "3 2 0 0\n1 0 0 1\n", 0, 1, CVM_E_IO_FORMAT, "t.poly:2:",
     "expected 3 fields"},
    {"first number 2", "3 2 0 0\n2 0 0\n", 0, 1, CVM_E_IO_FORMAT, "t.poly:2:", "must be 0 or 1"},
    {"numbers out of sequence", "3 2 0 0\n1 0 0\n3 1 0\n", 0, 1, CVM_E_IO_FORMAT, "t.poly:3:",
     "out of sequence"},
    {"letter in x", "3 2 0 0\n1 0 0\n2 1a 0\n", 0, 1, CVM_E_IO_FORMAT, "t.poly:3:",
     "point 2: expected a decimal number, found '1a'"},
    {"hexadecimal x", "3 2 0 0\n1 0 0\n2 0x1p3 0\n", 0, 1, CVM_E_IO_FORMAT, "t.poly:3:",
     "point 2: expected a decimal number, found '0x1p3' (hexadecimal floats are not read)"},
    {"hexadecimal region area", TRI3 SEG3 "0\n1\n1 0.2 0.2 1 0X1P-3\n", 0, 1, CVM_E_IO_FORMAT,
     "t.poly:11:", "region 1: expected a decimal number, found '0X1P-3'"},
    {"control bytes echoed escaped", "3 2 0 0\n1 0 0\n2 \033]0;t\007 0\n", 0, 1, CVM_E_IO_FORMAT,
     "t.poly:3:", "found '\\x1b]0;t\\x07'"},
    {"nan y", "3 2 0 0\n1 0 0\n2 1 nan\n", 0, 1, CVM_E_INPUT_NONFINITE, "t.poly:3:", "non-finite"},
    {"inf x", "3 2 0 0\n1 0 0\n2 -inf 0\n", 0, 1, CVM_E_INPUT_NONFINITE, "t.poly:3:", "point 2"},
    {"overflowing x", "3 2 0 0\n1 1e999 0\n", 0, 1, CVM_E_INPUT_NONFINITE, "t.poly:2:", "1e999"},
    {"nan attribute", "2 2 1 0\n1 0 0 0\n2 1 0 nan\n", 0, 0, CVM_E_INPUT_NONFINITE, "t.node:3:",
     "attribute"},
    {"marker not integer", "2 2 0 1\n1 0 0 1.5\n", 0, 0, CVM_E_IO_FORMAT, "t.node:2:",
     "expected an integer"},
    {"marker beyond int32", "2 2 0 1\n1 0 0 4294967296\n", 0, 0, CVM_E_IO_FORMAT, "t.node:2:",
     "out of range"},
    {"point count too small", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n4 1 1\n" SEG3 "0\n", 0, 1,
     CVM_E_IO_FORMAT, "t.poly:5:", "segment count line"},
    {"node file with extra point", "2 2 0 0\n1 0 0\n2 1 0\n3 1 1\n", 0, 0, CVM_E_IO_FORMAT,
     "t.node:4:", "unexpected content"},
    {"missing segment count", TRI3, 0, 1, CVM_E_IO_FORMAT, "t.poly:4:", "segment count line"},
    {"negative segment count", TRI3 "-1 0\n", 0, 1, CVM_E_IO_FORMAT, "t.poly:5:",
     "negative segment count"},
    {"truncated segments", TRI3 "3 0\n1 1 2\n", 0, 1, CVM_E_IO_FORMAT, "t.poly:6:",
     "segment 2 of 3"},
    {"segment endpoint too large", TRI3 "3 0\n1 1 2\n2 2 4\n3 3 1\n0\n", 0, 1, CVM_E_IO_FORMAT,
     "t.poly:7:", "numbered 1..3"},
    {"segment endpoint 0 in 1-based file", TRI3 "1 0\n1 0 2\n0\n", 0, 1, CVM_E_IO_FORMAT,
     "t.poly:6:", "names point 0"},
    {"segment endpoint not integer", TRI3 "1 0\n1 1 x\n0\n", 0, 1, CVM_E_IO_FORMAT, "t.poly:6:",
     "endpoint of segment 1"},
    {"segment without its marker", TRI3 "1 1\n1 1 2\n0\n", 0, 1, CVM_E_IO_FORMAT, "t.poly:6:",
     "expected 4 fields"},
    {"segment count too small", TRI3 "2 0\n1 1 2\n2 2 3\n3 3 1\n0\n", 0, 1, CVM_E_IO_FORMAT,
     "t.poly:8:", "hole count line"},
    {"missing hole count", TRI3 SEG3, 0, 1, CVM_E_IO_FORMAT, "t.poly:8:", "hole count line"},
    {"truncated holes", TRI3 SEG3 "2\n1 0.2 0.2\n", 0, 1, CVM_E_IO_FORMAT, "t.poly:10:",
     "hole 2 of 2"},
    {"nan hole", TRI3 SEG3 "1\n1 nan 0.2\n", 0, 1, CVM_E_INPUT_NONFINITE, "t.poly:10:", "hole 1"},
    {"garbage after holes", TRI3 SEG3 "0\nfoo\n", 0, 1, CVM_E_IO_FORMAT, "t.poly:10:",
     "region count: expected an integer"},
    {"truncated regions", TRI3 SEG3 "0\n2\n1 0.2 0.2 1 0\n", 0, 1, CVM_E_IO_FORMAT, "t.poly:11:",
     "region 2 of 2"},
    {"region too short", TRI3 SEG3 "0\n1\n1 0.2 0.2\n", 0, 1, CVM_E_IO_FORMAT, "t.poly:11:",
     "5 or 4 fields"},
    {"nan region attribute", TRI3 SEG3 "0\n1\n1 0.2 0.2 nan\n", 0, 1, CVM_E_INPUT_NONFINITE,
     "t.poly:11:", "region 1"},
    {"content after regions", TRI3 SEG3 "0\n1\n1 0.2 0.2 1 0\n7\n", 0, 1, CVM_E_IO_FORMAT,
     "t.poly:12:", "unexpected content after the last region"},
    {"binary garbage", "3 2 0 0\n1 0 0\n\x01\x02\xff garbage\n", 0, 1, CVM_E_IO_FORMAT,
     "t.poly:3:", "expected 3 fields"},
    {"nul byte", "3 2 0 0\n1 0\0 0\n", 15, 1, CVM_E_IO_FORMAT, "t.poly:2:", "NUL byte"},
};

START_TEST(malformed_input_names_its_line)
{
    const bad_case *c = &k_bad[_i];
    cvm__pslg p;
    cvm_status s = iotest_parse(&g_ctx, c->text, c->len, c->is_poly, &p);
    ck_assert_msg(s == c->status, "%s: status %d (%s), expected %d", c->what, (int)s, g_ctx.errmsg,
                  (int)c->status);
    ck_assert_msg(strstr(g_ctx.errmsg, c->line) == g_ctx.errmsg, "%s: message '%s' lacks '%s'",
                  c->what, g_ctx.errmsg, c->line);
    ck_assert_msg(strstr(g_ctx.errmsg, c->phrase) != NULL, "%s: message '%s' lacks '%s'", c->what,
                  g_ctx.errmsg, c->phrase);
    ck_assert_int_eq(g_ctx.err_kind, CVM_ENT_FILE_LINE);
    ck_assert_int_eq((int)g_ctx.err_index, atoi(strchr(c->line, ':') + 1));
    /* on error the pslg is zeroed and nothing leaks */
    ck_assert_ptr_null(p.xy);
    ck_assert_uint_eq(p.np, 0);
    ck_assert_int_eq((int)g_a.live_blocks, 0);
}
END_TEST

START_TEST(overlong_line_is_rejected)
{
    size_t n = 100000;
    char *text = malloc(n + 1);
    cvm__pslg p;
    memset(text, '7', n);
    text[n] = '\0';
    ck_assert_int_eq(iotest_parse(&g_ctx, text, n, 1, &p), CVM_E_IO_FORMAT);
    ck_assert_ptr_nonnull(strstr(g_ctx.errmsg, "t.poly:1:"));
    ck_assert_int_eq((int)g_a.live_blocks, 0);
    free(text);
}
END_TEST

START_TEST(zero_point_poly_keeps_file_numbers_without_node)
{
    cvm__pslg p;
    ck_assert_int_eq(iotest_parse(&g_ctx, "0 2 0 0\n1 0\n1 5 9\n0\n", 0, 1, &p), CVM_OK);
    ck_assert_uint_eq(p.np, 0);
    ck_assert_int_eq(p.seg[0], 5);
    ck_assert_int_eq(p.seg[1], 9);
    teardown_check_no_leak(&p);
}
END_TEST

START_TEST(read_runs_out_of_memory_cleanly)
{
    static const char text[] = "5 2 2 1\n1 0 0 1 2 3\n2 1 0 1 2 3\n3 1 1 1 2 3\n4 0 1 1 2 3\n"
                               "5 0.5 0.5 1 2 3\n4 1\n1 1 2 7\n2 2 3 7\n3 3 4 7\n4 4 1 7\n"
                               "1\n1 0.5 0.25\n1\n1 0.25 0.5 3 0.1\n";
    long k;
    int persistent;
    for (persistent = 0; persistent <= 1; persistent++) {
        for (k = 1;; k++) {
            cvm__pslg p;
            cvm_status s;
            cvmtest_alloc_init(&g_a, k, persistent);
            s = iotest_parse(&g_ctx, text, 0, 1, &p);
            if (s == CVM_OK) {
                ck_assert_uint_eq(p.np, 5);
                ck_assert_uint_eq(p.nregions, 1);
                teardown_check_no_leak(&p);
                ck_assert_int_eq((int)g_a.n_failed, 0);
                break;
            }
            ck_assert_msg(s == CVM_E_NOMEM, "k=%ld: %d %s", k, (int)s, g_ctx.errmsg);
            ck_assert_ptr_null(p.xy);
            ck_assert_int_eq((int)g_a.live_blocks, 0);
            ck_assert(k < 1000);
        }
    }
}
END_TEST

TCase *io_read_triangle_tcase(void)
{
    TCase *tc = tcase_create("read_triangle");
    tcase_add_checked_fixture(tc, setup, NULL);
    tcase_add_test(tc, read_domains_with_their_counts);
    tcase_add_test(tc, read_every_domain);
    tcase_add_test(tc, read_zero_based_file_with_comments);
    tcase_add_test(tc, read_one_based_attributes_and_regions);
    tcase_add_test(tc, read_node_file_with_attribute);
    tcase_add_test(tc, numbering_base_follows_first_point);
    tcase_add_test(tc, header_fields_after_the_count_are_optional);
    tcase_add_test(tc, items_remember_their_file_numbers_and_lines);
    tcase_add_loop_test(tc, malformed_input_names_its_line, 0, (int)(sizeof k_bad / sizeof k_bad[0]));
    tcase_add_test(tc, overlong_line_is_rejected);
    tcase_add_test(tc, zero_point_poly_keeps_file_numbers_without_node);
    tcase_add_test(tc, read_runs_out_of_memory_cleanly);
    return tc;
}
