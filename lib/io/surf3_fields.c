/* surf3_fields.c - field parsing with file:line messages for the 3D surface readers. */
#include <limits.h>
#include <string.h>

#include "surf3_io.h"

cvm_status cvm__s3_need_line(cvm__scan *sc, const char *expected)
{
    int got;
    cvm_status s = cvm__scan_line(sc, &got);
    if (s)
        return s;
    if (!got)
        return cvm__scan_error(sc, CVM_E_IO_FORMAT, "unexpected end of file: expected %s", expected);
    return CVM_OK;
}

cvm_status cvm__s3_want_fields(cvm__scan *sc, size_t lo, size_t hi, const char *what,
                               const char *layout)
{
    size_t n = sc->nfields;
    if (n >= lo && n <= hi)
        return CVM_OK;
    if (lo == hi)
        return cvm__scan_error(sc, CVM_E_IO_FORMAT, "%s: expected %lu field%s (%s), found %lu", what,
                               (unsigned long)lo, lo == 1 ? "" : "s", layout, (unsigned long)n);
    return cvm__scan_error(sc, CVM_E_IO_FORMAT, "%s: expected %lu to %lu fields (%s), found %lu",
                           what, (unsigned long)lo, (unsigned long)hi, layout, (unsigned long)n);
}

cvm_status cvm__s3_int(cvm__scan *sc, const char *what, long long lo, long long hi, long long *out)
{
    const char *f = cvm__scan_field(sc);
    int r;
    if (!f)
        return cvm__scan_error(sc, CVM_E_IO_FORMAT, "%s: missing", what);
    r = cvm__parse_long(f, lo, hi, out);
    if (r == 1)
        return cvm__scan_error(sc, CVM_E_IO_FORMAT, "%s: expected an integer, found '%.40s'", what, f);
    if (r == 2)
        return cvm__scan_error(sc, CVM_E_IO_FORMAT, "%s: %.40s is out of range [%lld, %lld]", what,
                               f, lo, hi);
    return CVM_OK;
}

cvm_status cvm__s3_count(cvm__scan *sc, const char *what, long long *out)
{
    const char *f = cvm__scan_field(sc);
    int r;
    if (!f)
        return cvm__scan_error(sc, CVM_E_IO_FORMAT, "%s: missing", what);
    r = cvm__parse_long(f, LLONG_MIN, LLONG_MAX, out);
    if (r == 1)
        return cvm__scan_error(sc, CVM_E_IO_FORMAT, "%s: expected an integer, found '%.40s'", what, f);
    if ((r == 0 && *out < 0) || (r == 2 && f[0] == '-'))
        return cvm__scan_error(sc, CVM_E_IO_FORMAT, "negative %s %.40s", what, f);
    if (r == 2 || (unsigned long long)*out > (unsigned long long)CVM__SURF3_MAX_COUNT)
        return cvm__scan_error(sc, CVM_E_TOO_LARGE, "%s %.40s exceeds the limit of %lu", what, f,
                               (unsigned long)CVM__SURF3_MAX_COUNT);
    return CVM_OK;
}

cvm_status cvm__s3_real(cvm__scan *sc, const char *what, long long number, double *out)
{
    const char *f = cvm__scan_field(sc);
    int r;
    if (!f)
        return cvm__scan_error(sc, CVM_E_IO_FORMAT, "%s %lld: a number is missing", what, number);
    r = cvm__parse_double(f, out);
    if (r == 1)
        return cvm__scan_error(sc, CVM_E_IO_FORMAT, "%s %lld: expected a decimal number, found '%.40s'",
                               what, number, f);
    if (r == 2)
        return cvm__scan_error(sc, CVM_E_INPUT_NONFINITE, "%s %lld has a non-finite value '%.40s'",
                               what, number, f);
    return CVM_OK;
}

cvm_status cvm__s3_expect_end(cvm__scan *sc, const char *after)
{
    int got;
    cvm_status s = cvm__scan_line(sc, &got);
    if (s)
        return s;
    if (got)
        return cvm__scan_error(sc, CVM_E_IO_FORMAT,
                               "unexpected content after the %s (does its count match its lines?)",
                               after);
    return CVM_OK;
}
