/* test_marker_names.c - the marker <-> name table (marker_names.c): set, get, list, read from a
 * .msh's $PhysicalNames and written back by the .msh writer. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api/api_tests.h"
#include "io/io_tests.h"
#include "support/failing_alloc.h"

static void interop_path(char *path, size_t n, const char *name)
{
    char dir[512];
    iotest_path(dir, sizeof dir, iotest_data_dir(), "interop");
    iotest_path(path, n, dir, name);
}

START_TEST(marker_names_set_get_list_remove)
{
    cvm_mesh *m;
    size_t n;
    int32_t keys[6];
    char longname[200];
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count_marker_names(&n, m), CVM_OK);
    ck_assert_uint_eq(n, 0);
    ck_assert_ptr_null(cvm_mesh_get_marker_name(m, 1, 3));
    ck_assert_int_eq(cvm_mesh_set_marker_name(m, 1, 3, "inlet"), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_marker_name(m, 2, 7, "fluid"), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_marker_name(m, 1, -2, "wall"), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_marker_name(m, 1, 3, "in"), CVM_OK); /* replaces */
    ck_assert_str_eq(cvm_mesh_get_marker_name(m, 1, 3), "in");
    ck_assert_str_eq(cvm_mesh_get_marker_name(m, 2, 7), "fluid");
    ck_assert_ptr_null(cvm_mesh_get_marker_name(m, 2, 3));
    ck_assert_int_eq(cvm_mesh_count_marker_names(&n, m), CVM_OK);
    ck_assert_uint_eq(n, 3);
    ck_assert_int_eq(cvm_mesh_copy_marker_name_keys(keys, 5, m), CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_marker_name_keys(keys, 6, m), CVM_OK);
    ck_assert(keys[0] == 1 && keys[1] == -2 && keys[2] == 1 && keys[3] == 3 && keys[4] == 2 && keys[5] == 7);
    ck_assert_int_eq(cvm_mesh_set_marker_name(m, 1, -2, NULL), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_marker_name(m, 1, 99, NULL), CVM_OK); /* nothing to remove */
    ck_assert_int_eq(cvm_mesh_count_marker_names(&n, m), CVM_OK);
    ck_assert_uint_eq(n, 2);
    /* bad names and dimensions leave the table as it was */
    ck_assert_int_eq(cvm_mesh_set_marker_name(m, 4, 1, "x"), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_mesh_set_marker_name(m, -1, 1, "x"), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_mesh_set_marker_name(m, 1, 3, ""), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_mesh_set_marker_name(m, 1, 3, "a\"b"), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "double quote"));
    ck_assert_int_eq(cvm_mesh_set_marker_name(m, 1, 3, "a\nb"), CVM_E_ARGUMENT);
    memset(longname, 'x', 128);
    longname[128] = '\0';
    ck_assert_int_eq(cvm_mesh_set_marker_name(m, 1, 3, longname), CVM_E_ARGUMENT);
    longname[127] = '\0';
    ck_assert_int_eq(cvm_mesh_set_marker_name(m, 1, 4, longname), CVM_OK);
    ck_assert_str_eq(cvm_mesh_get_marker_name(m, 1, 3), "in");
    ck_assert_int_eq(cvm_mesh_set_marker_name(NULL, 1, 3, "x"), CVM_E_NULL_ARG);
    ck_assert_ptr_null(cvm_mesh_get_marker_name(NULL, 1, 3));
    ck_assert_int_eq(cvm_mesh_count_marker_names(NULL, m), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_marker_name_keys(NULL, 2, m), CVM_E_NULL_ARG);
    cvm_mesh_free(m);
}
END_TEST

/* Out of memory while the table grows: a status, the table unchanged, no leak. */
START_TEST(marker_names_out_of_memory_is_a_status)
{
    long k;
    for (k = 1;; k++) {
        cvmtest_alloc a;
        cvm_mesh *m;
        cvm_status s1, s2 = CVM_OK;
        size_t n;
        cvmtest_alloc_init(&a, 0, 0);
        ck_assert_int_eq(cvmtest_mesh_create(&m, &a), CVM_OK);
        cvmtest_alloc_arm(&a, k, 0);
        s1 = cvm_mesh_set_marker_name(m, 1, 1, "a");
        if (!s1)
            s2 = cvm_mesh_set_marker_name(m, 1, 2, "b");
        cvmtest_alloc_arm(&a, 0, 0);
        ck_assert(s1 == CVM_OK || s1 == CVM_E_NOMEM);
        ck_assert(s2 == CVM_OK || s2 == CVM_E_NOMEM);
        ck_assert_int_eq(cvm_mesh_count_marker_names(&n, m), CVM_OK);
        ck_assert_uint_eq(n, (size_t)(s1 == CVM_OK) + (s2 == CVM_OK && s1 == CVM_OK));
        cvm_mesh_free(m);
        ck_assert_int_eq(a.live_blocks, 0);
        if (s1 == CVM_OK && s2 == CVM_OK)
            break;
    }
    ck_assert(k > 1);
}
END_TEST

/* A Gmsh domain meshio wrote: its physical names name the markers; the .msh
 * cvmesh writes of the triangulation keeps them; reading that file again
 * gives the same table and the same file. */
START_TEST(marker_names_round_trip_through_msh)
{
    static const char *const want[] = {"1 1 \"bottom\"", "1 2 \"right\"", "1 3 \"top\"", "1 4 \"left\""};
    char in[600], *dir = iotest_tmpdir(), out[600], out2[600], *text, *text2;
    const char *files[2] = {"domain_meshio_22.msh", "domain_meshio_22b.msh"};
    int f;
    size_t i, len, len2, n;
    for (f = 0; f < 2; f++) {
        cvm_mesh *m, *m2;
        interop_path(in, sizeof in, files[f]);
        ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
        ck_assert_int_eq(cvm_mesh_set_marker_name(m, 1, 50, "stale"), CVM_OK);
        ck_assert_msg(cvm_mesh_read(m, in) == CVM_OK, "%s", cvm_mesh_errmsg(m));
        ck_assert_int_eq(cvm_mesh_count_marker_names(&n, m), CVM_OK);
        ck_assert_uint_eq(n, 5); /* the file's, the old one gone */
        ck_assert_str_eq(cvm_mesh_get_marker_name(m, 0, 9), "centre");
        ck_assert_str_eq(cvm_mesh_get_marker_name(m, 1, 3), "top");
        ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
        ck_assert_int_eq(cvm_mesh_set_marker_name(m, 2, 1, "plate"), CVM_OK);
        snprintf(out, sizeof out, "%s/d.msh", dir);
        ck_assert_int_eq(cvm_mesh_write(m, out), CVM_OK);
        text = iotest_slurp(out, &len);
        ck_assert_ptr_nonnull(text);
        for (i = 0; i < 4; i++)
            ck_assert_msg(strstr(text, want[i]) != NULL, "%s: no %s in\n%s", files[f], want[i], text);
        ck_assert_ptr_nonnull(strstr(text, "2 1 \"plate\""));
        ck_assert_ptr_null(strstr(text, "marker_"));
        ck_assert_ptr_null(strstr(text, "centre")); /* no point groups are written */
        /* read back: the same names, the same file */
        ck_assert_int_eq(cvm_mesh_create(&m2), CVM_OK);
        ck_assert_msg(cvm_mesh_read(m2, out) == CVM_OK, "%s", cvm_mesh_errmsg(m2));
        ck_assert_str_eq(cvm_mesh_get_marker_name(m2, 1, 1), "bottom");
        ck_assert_str_eq(cvm_mesh_get_marker_name(m2, 2, 1), "plate");
        snprintf(out2, sizeof out2, "%s/d2.msh", dir);
        ck_assert_int_eq(cvm_mesh_write(m2, out2), CVM_OK);
        text2 = iotest_slurp(out2, &len2);
        ck_assert_ptr_nonnull(text2);
        ck_assert_msg(len == len2 && memcmp(text, text2, len) == 0, "%s written again differs", files[f]);
        /* another format empties the table */
        snprintf(out2, sizeof out2, "%s/d2.vtu", dir);
        ck_assert_int_eq(cvm_mesh_write(m2, out2), CVM_OK);
        ck_assert_int_eq(cvm_mesh_read(m2, out2), CVM_OK);
        ck_assert_int_eq(cvm_mesh_count_marker_names(&n, m2), CVM_OK);
        ck_assert_uint_eq(n, 0);
        free(text);
        free(text2);
        cvm_mesh_free(m);
        cvm_mesh_free(m2);
        remove(out);
        remove(out2);
        snprintf(out2, sizeof out2, "%s/d2.msh", dir);
        remove(out2);
    }
    iotest_rmdir(dir);
    free(dir);
}
END_TEST

/* Triangles in a named physical surface: the region keeps its name. */
START_TEST(marker_names_name_regions)
{
    char in[600], *dir = iotest_tmpdir(), out[600], *text;
    size_t len;
    cvm_mesh *m;
    interop_path(in, sizeof in, "square_meshio_41b.msh");
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_msg(cvm_mesh_read(m, in) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_str_eq(cvm_mesh_get_marker_name(m, 2, 7), "inside");
    snprintf(out, sizeof out, "%s/s.msh", dir);
    ck_assert_int_eq(cvm_mesh_write(m, out), CVM_OK);
    text = iotest_slurp(out, &len);
    ck_assert_ptr_nonnull(text);
    ck_assert_msg(strstr(text, "2 1 \"inside\"") != NULL, "%s", text);
    ck_assert_ptr_nonnull(strstr(text, "1 1 \"bottom\""));
    free(text);
    remove(out);
    cvm_mesh_free(m);
    iotest_rmdir(dir);
    free(dir);
}
END_TEST

TCase *api_marker_names_tcase(void)
{
    TCase *tc = tcase_create("marker_names");
    tcase_add_test(tc, marker_names_set_get_list_remove);
    tcase_add_test(tc, marker_names_out_of_memory_is_a_status);
    tcase_add_test(tc, marker_names_round_trip_through_msh);
    tcase_add_test(tc, marker_names_name_regions);
    return tc;
}
