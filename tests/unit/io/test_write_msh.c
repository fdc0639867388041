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

/* Segments 0-1 and 1-2 have marker 7, 2-3 has 9: two curves. Vertex 1 lies
 * inside curve 7; vertices 0, 2 (where the curves meet) and 3 end chains, so
 * they are point entities; the centre belongs to the surface. */
START_TEST(msh_groups_segments_by_marker)
{
    static const char want[] =
        "$MeshFormat\n"
        "4.1 0 8\n"
        "$EndMeshFormat\n"
        "$PhysicalNames\n"
        "3\n"
        "1 7 \"marker_7\"\n"
        "1 9 \"marker_9\"\n"
        "2 1 \"domain\"\n"
        "$EndPhysicalNames\n"
        "$Entities\n"
        "3 2 1 0\n"
        "1 0 0 0 0\n"
        "2 1 1 0 0\n"
        "3 0.1 0.3333333333333333 0 0\n"
        "1 0 0 0 1 1 0 1 7 0\n"
        "2 0.1 0.3333333333333333 0 1 1 0 1 9 0\n"
        "1 0 0 0 1 1 0 1 1 2 1 2\n"
        "$EndEntities\n"
        "$Nodes\n"
        "5 5 1 5\n"
        "0 1 0 1\n"
        "1\n"
        "0 0 0\n"
        "0 2 0 1\n"
        "3\n"
        "1 1 0\n"
        "0 3 0 1\n"
        "4\n"
        "0.1 0.3333333333333333 0\n"
        "1 1 0 1\n"
        "2\n"
        "1 0 0\n"
        "2 1 0 1\n"
        "5\n"
        "0.5000000000000001 0.4999999999999999 0\n"
        "$EndNodes\n"
        "$Elements\n"
        "3 7 1 7\n"
        "1 1 1 2\n"
        "1 1 2\n"
        "2 2 3\n"
        "1 2 1 1\n"
        "3 3 4\n"
        "2 1 2 4\n"
        "4 1 2 5\n"
        "5 2 3 5\n"
        "6 3 4 5\n"
        "7 4 1 5\n"
        "$EndElements\n";
    cvm__mesh_out mo;
    char *t;
    iotest_mesh_out(&mo);
    mo.tattr = NULL;
    t = write_msh(&mo);
    ck_assert_str_eq(t, want);
    free(t);
}
END_TEST

/* One surface per regional attribute, increasing, named region_A, each bounded
 * by the curves among its triangles' edges; triangles keep their element tags
 * (lines first) inside the blocks of their surfaces; a node belongs to the
 * surface of its lowest-numbered triangle. */
START_TEST(msh_one_surface_per_region)
{
    static const char want[] =
        "$MeshFormat\n"
        "4.1 0 8\n"
        "$EndMeshFormat\n"
        "$PhysicalNames\n"
        "6\n"
        "1 7 \"marker_7\"\n"
        "1 9 \"marker_9\"\n"
        "2 1 \"region_-7\"\n"
        "2 2 \"region_0.30000000000000004\"\n"
        "2 3 \"region_1\"\n"
        "2 4 \"region_2\"\n"
        "$EndPhysicalNames\n"
        "$Entities\n"
        "3 2 4 0\n"
        "1 0 0 0 0\n"
        "2 1 1 0 0\n"
        "3 0.1 0.3333333333333333 0 0\n"
        "1 0 0 0 1 1 0 1 7 0\n"
        "2 0.1 0.3333333333333333 0 1 1 0 1 9 0\n"
        "1 0 0 0 0.5000000000000001 0.4999999999999999 0 1 1 0\n"
        "2 0.1 0.3333333333333333 0 1 1 0 1 2 1 2\n"
        "3 0 0 0 1 0.4999999999999999 0 1 3 1 1\n"
        "4 0.5000000000000001 0 0 1 1 0 1 4 1 1\n"
        "$EndEntities\n"
        "$Nodes\n"
        "5 5 1 5\n"
        "0 1 0 1\n"
        "1\n"
        "0 0 0\n"
        "0 2 0 1\n"
        "3\n"
        "1 1 0\n"
        "0 3 0 1\n"
        "4\n"
        "0.1 0.3333333333333333 0\n"
        "1 1 0 1\n"
        "2\n"
        "1 0 0\n"
        "2 3 0 1\n"
        "5\n"
        "0.5000000000000001 0.4999999999999999 0\n"
        "$EndNodes\n"
        "$Elements\n"
        "6 7 1 7\n"
        "1 1 1 2\n"
        "1 1 2\n"
        "2 2 3\n"
        "1 2 1 1\n"
        "3 3 4\n"
        "2 1 2 1\n"
        "7 4 1 5\n"
        "2 2 2 1\n"
        "6 3 4 5\n"
        "2 3 2 1\n"
        "4 1 2 5\n"
        "2 4 2 1\n"
        "5 2 3 5\n"
        "$EndElements\n";
    cvm__mesh_out mo;
    char *t;
    iotest_mesh_out(&mo); /* triangle attributes 1, 2, 0.30000000000000004, -7 */
    t = write_msh(&mo);
    ck_assert_str_eq(t, want);
    free(t);
}
END_TEST

START_TEST(msh_markers_below_one_get_no_physical_group)
{
    static const int32_t smark[] = {0, 0, -2};
    cvm__mesh_out mo;
    char *t;
    iotest_mesh_out(&mo);
    mo.tattr = NULL;
    mo.smark = smark;
    t = write_msh(&mo);
    ck_assert_ptr_nonnull(strstr(t, "$PhysicalNames\n1\n2 1 \"domain\"\n"));
    ck_assert_ptr_nonnull(strstr(t, "$Entities\n3 2 1 0\n"));
    ck_assert_ptr_nonnull(strstr(t, "1 0.1 0.3333333333333333 0 1 1 0 0 0\n"));
    ck_assert_ptr_nonnull(strstr(t, "$Elements\n3 7 1 7\n1 1 1 1\n1 3 4\n1 2 1 2\n2 1 2\n3 2 3\n"));
    free(t);
}
END_TEST

START_TEST(msh_without_segments_has_one_surface)
{
    static const char want[] =
        "$MeshFormat\n"
        "4.1 0 8\n"
        "$EndMeshFormat\n"
        "$PhysicalNames\n"
        "1\n"
        "2 1 \"domain\"\n"
        "$EndPhysicalNames\n"
        "$Entities\n"
        "0 0 1 0\n"
        "1 0 0 0 1 1 0 1 1 0\n"
        "$EndEntities\n"
        "$Nodes\n"
        "1 5 1 5\n"
        "2 1 0 5\n"
        "1\n"
        "2\n"
        "3\n"
        "4\n"
        "5\n"
        "0 0 0\n"
        "1 0 0\n"
        "1 1 0\n"
        "0.1 0.3333333333333333 0\n"
        "0.5000000000000001 0.4999999999999999 0\n"
        "$EndNodes\n"
        "$Elements\n"
        "1 4 1 4\n"
        "2 1 2 4\n"
        "1 1 2 5\n"
        "2 2 3 5\n"
        "3 3 4 5\n"
        "4 4 1 5\n"
        "$EndElements\n";
    cvm__mesh_out mo;
    char *t;
    iotest_mesh_out(&mo);
    mo.tattr = NULL;
    mo.nseg = 0;
    mo.seg = NULL;
    mo.smark = NULL;
    t = write_msh(&mo);
    ck_assert_str_eq(t, want);
    free(t);
}
END_TEST

TCase *io_write_msh_tcase(void)
{
    TCase *tc = tcase_create("write_msh");
    tcase_add_test(tc, msh_groups_segments_by_marker);
    tcase_add_test(tc, msh_one_surface_per_region);
    tcase_add_test(tc, msh_markers_below_one_get_no_physical_group);
    tcase_add_test(tc, msh_without_segments_has_one_surface);
    return tc;
}
