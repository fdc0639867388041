/* test_write_msh.c - the Gmsh 4.1 writer: sections, physical groups per marker, element blocks. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/io_tests.h"

static char *write_msh(cvm__mesh_out *mo)
{
    char *dir = iotest_tmpdir(), path[4096], *text;
    cvm__ctx ctx;
    cvm__ctx_init_default(&ctx);
    snprintf(path, sizeof path, "%s/m.msh", dir);
    ck_assert_int_eq(cvm__write_file(&ctx, path, mo), CVM_OK);
    text = iotest_slurp(path, NULL);
    ck_assert_ptr_nonnull(text);
    iotest_rmdir(dir);
    free(dir);
    return text;
}

START_TEST(msh_groups_segments_by_marker)
{
    cvm__mesh_out mo;
    char *t;
    iotest_mesh_out(&mo); /* segments 0-1 and 1-2 have marker 7, 2-3 has 9 */
    t = write_msh(&mo);
    ck_assert_ptr_eq(strstr(t, "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"), t);
    ck_assert_ptr_nonnull(strstr(t, "$PhysicalNames\n3\n1 7 \"marker_7\"\n1 9 \"marker_9\"\n2 1 \"domain\"\n"));
    ck_assert_ptr_nonnull(strstr(t, "$Entities\n0 2 1 0\n1 0 0 0 1 1 0 1 7 0\n"));
    ck_assert_ptr_nonnull(strstr(t, "0 1 1 2 1 2\n$EndEntities"));
    ck_assert_ptr_nonnull(strstr(t, "$Nodes\n1 5 1 5\n2 1 0 5\n1\n2\n3\n4\n5\n0 0 0\n"));
    ck_assert_ptr_nonnull(strstr(t, "$Elements\n3 7 1 7\n1 1 1 2\n1 1 2\n2 2 3\n1 2 1 1\n3 3 4\n"
                                    "2 1 2 4\n4 1 2 5\n"));
    ck_assert_ptr_nonnull(strstr(t, "7 4 1 5\n$EndElements\n"));
    free(t);
}
END_TEST

START_TEST(msh_markers_below_one_get_no_physical_group)
{
    static const int32_t smark[] = {0, 0, -2};
    cvm__mesh_out mo;
    char *t;
    iotest_mesh_out(&mo);
    mo.smark = smark;
    t = write_msh(&mo);
    ck_assert_ptr_nonnull(strstr(t, "$PhysicalNames\n1\n2 1 \"domain\"\n"));
    ck_assert_ptr_nonnull(strstr(t, "$Entities\n0 2 1 0\n1 0.1 0.3333333333333333 0 1 1 0 0 0\n"));
    ck_assert_ptr_nonnull(strstr(t, "$Elements\n3 7 1 7\n1 1 1 1\n1 3 4\n1 2 1 2\n2 1 2\n3 2 3\n"));
    free(t);
}
END_TEST

START_TEST(msh_without_segments_has_one_surface)
{
    cvm__mesh_out mo;
    char *t;
    iotest_mesh_out(&mo);
    mo.nseg = 0;
    mo.seg = NULL;
    mo.smark = NULL;
    t = write_msh(&mo);
    ck_assert_ptr_nonnull(strstr(t, "$PhysicalNames\n1\n2 1 \"domain\"\n"));
    ck_assert_ptr_nonnull(strstr(t, "$Entities\n0 0 1 0\n"));
    ck_assert_ptr_nonnull(strstr(t, "1 1 0\n$EndEntities"));
    ck_assert_ptr_nonnull(strstr(t, "$Elements\n1 4 1 4\n2 1 2 4\n1 1 2 5\n"));
    free(t);
}
END_TEST

TCase *io_write_msh_tcase(void)
{
    TCase *tc = tcase_create("write_msh");
    tcase_add_test(tc, msh_groups_segments_by_marker);
    tcase_add_test(tc, msh_markers_below_one_get_no_physical_group);
    tcase_add_test(tc, msh_without_segments_has_one_surface);
    return tc;
}
