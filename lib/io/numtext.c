/* numtext.c - number fields read and written with '.' as decimal point, whatever the C locale. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmt_double.h"
#include "io_text.h"

/* The decimal point the C library uses now (LC_NUMERIC), e.g. "." or ",". */
static void locale_point(char *dp, size_t cap)
{
    char tmp[16];
    size_t i, n = 0;
    snprintf(tmp, sizeof tmp, "%.1f", 0.5);
    for (i = 1; tmp[i] && tmp[i] != '5' && n + 1 < cap; i++)
        dp[n++] = tmp[i];
    dp[n] = '\0';
}

/* strtod over the whole field; 1 if it consumed everything. */
static int strtod_whole(const char *field, double *out)
{
    char *end;
    errno = 0;
    *out = strtod(field, &end);
    return end != field && *end == '\0';
}

int cvm__parse_double(const char *field, double *out)
{
    double v;
    int ok;
    /* C99 strtod() also reads hexadecimal floats (0x1p-3); Triangle's files
       and VTK's ASCII arrays are decimal, so such a field is not a number */
    if (strpbrk(field, "xX"))
        return 1;
    ok = strtod_whole(field, &v);
    if (!ok && strchr(field, '.')) {
        /* a locale whose decimal point is not '.': translate and retry */
        char dp[8], buf[128];
        size_t i, n = 0, k, dl;
        locale_point(dp, sizeof dp);
        dl = strlen(dp);
        if (dl == 0 || strcmp(dp, ".") == 0)
            return 1;
        for (i = 0; field[i]; i++) {
            if (field[i] == '.') {
                if (n + dl >= sizeof buf)
                    return 1;
                for (k = 0; k < dl; k++)
                    buf[n++] = dp[k];
            } else {
                if (n + 1 >= sizeof buf)
                    return 1;
                buf[n++] = field[i];
            }
        }
        buf[n] = '\0';
        ok = strtod_whole(buf, &v);
    }
    if (!ok)
        return 1;
    *out = v;
    return isfinite(v) ? 0 : 2;
}

int cvm__parse_long(const char *field, long long lo, long long hi, long long *out)
{
    char *end;
    long long v;
    const char *p = field;
    if (*p == '+' || *p == '-')
        p++;
    if (*p < '0' || *p > '9')
        return 1;
    errno = 0;
    v = strtoll(field, &end, 10);
    if (*end != '\0')
        return 1;
    if (errno == ERANGE || v < lo || v > hi)
        return 2;
    *out = v;
    return 0;
}

/* Replace a locale decimal point (any run of bytes outside the characters of
 * %g output) by '.'; returns the new length. */
static size_t fix_point(char *buf)
{
    size_t i, n = 0;
    int in_dp = 0;
    for (i = 0; buf[i]; i++) {
        char c = buf[i];
        if ((c >= '0' && c <= '9') || c == 'e' || c == 'E' || c == '+' || c == '-' || c == '.') {
            buf[n++] = c;
            in_dp = 0;
        } else if (!in_dp) {
            buf[n++] = '.';
            in_dp = 1;
        }
    }
    buf[n] = '\0';
    return n;
}

size_t cvm__format_double_libc(char *buf, double x)
{
    double back;
    size_t n;
    snprintf(buf, CVM__DOUBLE_BUF, "%.15g", x);
    n = fix_point(buf);
    if (cvm__parse_double(buf, &back) == 0 && back == x)
        return n;
    snprintf(buf, CVM__DOUBLE_BUF, "%.16g", x);
    n = fix_point(buf);
    if (cvm__parse_double(buf, &back) == 0 && back == x)
        return n;
    snprintf(buf, CVM__DOUBLE_BUF, "%.17g", x);
    return fix_point(buf);
}

size_t cvm__format_double(char *buf, double x)
{
    size_t n = cvm__format_double_fast(buf, x);
    return n ? n : cvm__format_double_libc(buf, x);
}

size_t cvm__format_ulong(char *buf, unsigned long long v)
{
    static const char pairs[] = "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
                                "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
                                "8081828384858687888990919293949596979899";
    unsigned long long t = v;
    size_t n = 1, i;
    while (t >= 10) {
        t /= 10;
        n++;
    }
    buf[n] = '\0';
    for (i = n; v >= 100; i -= 2, v /= 100)
        memcpy(buf + i - 2, pairs + 2 * (v % 100), 2);
    if (v >= 10)
        memcpy(buf + i - 2, pairs + 2 * v, 2);
    else
        buf[i - 1] = (char)('0' + v);
    return n;
}

size_t cvm__format_long(char *buf, long long v)
{
    if (v < 0) {
        /* negate in unsigned arithmetic: -LLONG_MIN overflows */
        buf[0] = '-';
        return 1 + cvm__format_ulong(buf + 1, 0ull - (unsigned long long)v);
    }
    return cvm__format_ulong(buf, (unsigned long long)v);
}
