/* test_version.c - version macros against the linked library, and the status code table. */
#include <stdio.h>
#include <string.h>

#include "api/api_tests.h"
#include "cvmesh.h"

static const cvm_status k_all_status[] = {
    CVM_OK, CVM_E_NULL_ARG, CVM_E_ARGUMENT, CVM_E_OPTION_KEY, CVM_E_OPTION_RANGE, CVM_E_STATE,
    CVM_E_UNSUPPORTED, CVM_E_INPUT_NONFINITE, CVM_E_INPUT_INDEX, CVM_E_INPUT_DUPLICATE,
    CVM_E_INPUT_DEGENERATE, CVM_E_INPUT_INTERSECTING, CVM_E_INPUT_NOT_CLOSED, CVM_E_INPUT_EMPTY,
    CVM_E_INPUT_OUTSIDE, CVM_E_IO_OPEN, CVM_E_IO_READ, CVM_E_IO_WRITE, CVM_E_IO_FORMAT,
    CVM_E_NOMEM, CVM_E_BUFFER_TOO_SMALL, CVM_E_TOO_LARGE, CVM_E_INTERNAL,
    CVM_INCOMPLETE_TIME_LIMIT, CVM_INCOMPLETE_CANCELLED, CVM_INCOMPLETE_STEINER_LIMIT};
#define N_STATUS (sizeof k_all_status / sizeof k_all_status[0])

START_TEST(version_macro_equals_linked_library)
{
    char buf[64];
    ck_assert_int_eq(CVM_VERSION_NUMBER, cvm_version_number());
    ck_assert_int_eq(CVM_VERSION_NUMBER,
                     CVM_VERSION_MAJOR * 10000 + CVM_VERSION_MINOR * 100 + CVM_VERSION_PATCH);
    snprintf(buf, sizeof buf, "%d.%d.%d", CVM_VERSION_MAJOR, CVM_VERSION_MINOR, CVM_VERSION_PATCH);
    ck_assert_ptr_nonnull(cvm_version_string());
    ck_assert_str_eq(cvm_version_string(), buf);
    /* the build string starts with the version and names the licence of the build */
    ck_assert_ptr_nonnull(cvm_build_string());
    ck_assert(strncmp(cvm_build_string(), "cvmesh ", 7) == 0);
    ck_assert(strncmp(cvm_build_string() + 7, buf, strlen(buf)) == 0);
    ck_assert(strstr(cvm_build_string(), "AGPL-3+ build") || strstr(cvm_build_string(), "BSD-3-Clause build"));
}
END_TEST

START_TEST(status_codes_keep_their_numbers)
{
    /* Released values never change (include/cvmesh.h). */
    ck_assert_int_eq(CVM_OK, 0);
    ck_assert_int_eq(CVM_E_NULL_ARG, 1);
    ck_assert_int_eq(CVM_E_OPTION_RANGE, 4);
    ck_assert_int_eq(CVM_E_INPUT_NONFINITE, 10);
    ck_assert_int_eq(CVM_E_INPUT_OUTSIDE, 17);
    ck_assert_int_eq(CVM_E_IO_OPEN, 30);
    ck_assert_int_eq(CVM_E_IO_FORMAT, 33);
    ck_assert_int_eq(CVM_E_NOMEM, 40);
    ck_assert_int_eq(CVM_E_TOO_LARGE, 42);
    ck_assert_int_eq(CVM_E_INTERNAL, 99);
    ck_assert_int_eq(CVM_INCOMPLETE_TIME_LIMIT, 100);
    ck_assert_int_eq(CVM_INCOMPLETE_STEINER_LIMIT, 102);
}
END_TEST

START_TEST(status_strings_are_distinct_and_never_null)
{
    size_t i, j;
    const char *unknown = cvm_status_str((cvm_status)77);
    ck_assert_ptr_nonnull(unknown);
    ck_assert_str_eq(unknown, "unknown status");
    ck_assert_str_eq(cvm_status_str((cvm_status)1000), "unknown status");
    for (i = 0; i < N_STATUS; i++) {
        const char *s = cvm_status_str(k_all_status[i]);
        ck_assert_msg(s != NULL && s[0] != '\0', "status %d has no text", (int)k_all_status[i]);
        ck_assert_msg(strcmp(s, unknown) != 0, "status %d reads as unknown", (int)k_all_status[i]);
        for (j = 0; j < i; j++)
            ck_assert_msg(strcmp(s, cvm_status_str(k_all_status[j])) != 0,
                          "statuses %d and %d share the text \"%s\"", (int)k_all_status[i],
                          (int)k_all_status[j], s);
    }
}
END_TEST

START_TEST(status_is_error_covers_exactly_1_to_99)
{
    int v;
    for (v = 0; v < 300; v++)
        ck_assert_int_eq(cvm_status_is_error((cvm_status)v), v >= 1 && v <= 99);
    ck_assert_int_eq(cvm_status_is_error(CVM_OK), 0);
    ck_assert_int_eq(cvm_status_is_error(CVM_E_NOMEM), 1);
    ck_assert_int_eq(cvm_status_is_error(CVM_INCOMPLETE_CANCELLED), 0);
}
END_TEST

TCase *api_version_tcase(void)
{
    TCase *tc = tcase_create("version_status");
    tcase_add_test(tc, version_macro_equals_linked_library);
    tcase_add_test(tc, status_codes_keep_their_numbers);
    tcase_add_test(tc, status_strings_are_distinct_and_never_null);
    tcase_add_test(tc, status_is_error_covers_exactly_1_to_99);
    return tc;
}
