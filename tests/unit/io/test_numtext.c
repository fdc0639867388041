/* test_numtext.c - number fields: whole-field parsing, non-finite detection, shortest exact output. */
#include <math.h>
#include <string.h>

#include "io/io_tests.h"
#include "io/io_text.h"

START_TEST(parse_double_takes_whole_fields_only)
{
    double v;
    ck_assert_int_eq(cvm__parse_double("1.5", &v), 0);
    ck_assert(v == 1.5);
    ck_assert_int_eq(cvm__parse_double("-2e-3", &v), 0);
    ck_assert(v == -2e-3);
    ck_assert_int_eq(cvm__parse_double("1.5x", &v), 1);
    ck_assert_int_eq(cvm__parse_double("", &v), 1);
    ck_assert_int_eq(cvm__parse_double("abc", &v), 1);
    ck_assert_int_eq(cvm__parse_double("1,5", &v), 1);
}
END_TEST

START_TEST(parse_double_flags_nan_inf_and_overflow)
{
    double v;
    ck_assert_int_eq(cvm__parse_double("nan", &v), 2);
    ck_assert_int_eq(cvm__parse_double("-inf", &v), 2);
    ck_assert_int_eq(cvm__parse_double("Infinity", &v), 2);
    ck_assert_int_eq(cvm__parse_double("1e999", &v), 2);
    ck_assert_int_eq(cvm__parse_double("1e-400", &v), 0); /* underflow to 0 is a number */
}
END_TEST

START_TEST(parse_long_checks_range_and_syntax)
{
    long long v;
    ck_assert_int_eq(cvm__parse_long("42", 0, 100, &v), 0);
    ck_assert_int_eq((int)v, 42);
    ck_assert_int_eq(cvm__parse_long("-1", 0, 100, &v), 2);
    ck_assert_int_eq(cvm__parse_long("101", 0, 100, &v), 2);
    ck_assert_int_eq(cvm__parse_long("4.0", 0, 100, &v), 1);
    ck_assert_int_eq(cvm__parse_long("0x10", 0, 100, &v), 1);
    ck_assert_int_eq(cvm__parse_long(" 4", 0, 100, &v), 1);
    ck_assert_int_eq(cvm__parse_long("99999999999999999999999", 0, 100, &v), 2);
}
END_TEST

START_TEST(format_double_is_short_when_possible)
{
    char buf[CVM__DOUBLE_BUF];
    cvm__format_double(buf, 0.1);
    ck_assert_str_eq(buf, "0.1");
    cvm__format_double(buf, 3.0);
    ck_assert_str_eq(buf, "3");
    cvm__format_double(buf, -0.0);
    ck_assert_str_eq(buf, "-0");
    cvm__format_double(buf, 1e300);
    ck_assert_str_eq(buf, "1e+300");
}
END_TEST

START_TEST(format_double_round_trips_exactly)
{
    static const double vals[] = {1.0 / 3.0, 0.1 + 0.2, 5e-324, 1.7976931348623157e308,
                                  -2.2250738585072014e-308, 0.5000000000000001, 123456789.123456789};
    char buf[CVM__DOUBLE_BUF];
    uint64_t z = 12345;
    size_t i;
    for (i = 0; i < sizeof vals / sizeof vals[0]; i++) {
        double back;
        cvm__format_double(buf, vals[i]);
        ck_assert_int_eq(cvm__parse_double(buf, &back), 0);
        ck_assert_msg(memcmp(&back, &vals[i], sizeof back) == 0, "%s", buf);
    }
    for (i = 0; i < 20000; i++) {
        double x, back;
        z = z * 6364136223846793005ull + 1442695040888963407ull;
        memcpy(&x, &z, sizeof x);
        if (!isfinite(x))
            continue;
        cvm__format_double(buf, x);
        ck_assert_int_eq(cvm__parse_double(buf, &back), 0);
        ck_assert_msg(memcmp(&back, &x, sizeof back) == 0, "%s", buf);
    }
}
END_TEST

TCase *io_numtext_tcase(void)
{
    TCase *tc = tcase_create("numtext");
    tcase_add_test(tc, parse_double_takes_whole_fields_only);
    tcase_add_test(tc, parse_double_flags_nan_inf_and_overflow);
    tcase_add_test(tc, parse_long_checks_range_and_syntax);
    tcase_add_test(tc, format_double_is_short_when_possible);
    tcase_add_test(tc, format_double_round_trips_exactly);
    return tc;
}
