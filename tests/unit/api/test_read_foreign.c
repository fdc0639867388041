/* test_read_foreign.c - cvm_mesh_read of the .vtu, .vtk and .msh files VTK and meshio wrote (tests/data/interop). */
#include <stdio.h>
#include <string.h>

#include "api/api_tests.h"
#include "io/io_tests.h"

static void interop_path(char *path, size_t n, const char *name)
{
    char dir[512];
    iotest_path(dir, sizeof dir, iotest_data_dir(), "interop");
    iotest_path(path, n, dir, name);
}

/* Each mesh file gives the file's 4 triangles, exactly, and a valid mesh. */
START_TEST(read_foreign_meshes_rebuild_the_file)
{
    static const char *const files[] = {
        "square_meshio_zlib.vtu", "square_vtk_appended_raw.vtu", "square_vtk_appended_zlib_h32_be.vtu",
        "square_meshio_ascii.vtk", "square_vtk_binary.vtk",    "square_vtk_polydata.vtk",
        "square_meshio_22.msh",    "square_meshio_22b.msh",    "square_meshio_41b.msh"};
    size_t i;
    for (i = 0; i < sizeof files / sizeof files[0]; i++) {
        char path[600];
        cvm_mesh *m;
        size_t nt, nv;
        int32_t tri[12];
        interop_path(path, sizeof path, files[i]);
        ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
        ck_assert_msg(cvm_mesh_read(m, path) == CVM_OK, "%s: %s", files[i], cvm_mesh_errmsg(m));
        ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
        ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE), CVM_OK);
        ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
        ck_assert_msg(nt == 4 && nv == 5, "%s: %lu triangles, %lu vertices", files[i],
                      (unsigned long)nt, (unsigned long)nv);
        ck_assert_int_eq(cvm_mesh_copy_cells(tri, 12, m, CVM_ENT_TRIANGLE), CVM_OK);
        ck_assert_msg(tri[0] == 0 && tri[1] == 1 && tri[2] == 4 && tri[9] == 3, "%s: order", files[i]);
        cvm_mesh_free(m);
    }
}
END_TEST

/* A .msh with lines and points only is a domain: read, triangulated, checked;
 * its physical tags are the segment and point markers. */
START_TEST(read_foreign_msh_domain_is_an_input)
{
    char path[600];
    cvm_mesh *m;
    size_t nseg, nt, k;
    int32_t mark[16];
    interop_path(path, sizeof path, "domain_meshio_22b.msh");
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_msg(cvm_mesh_read(m, path) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_uint_eq(nt, 0);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&nseg, m, CVM_ENT_SEGMENT), CVM_OK);
    ck_assert_uint_eq(nseg, 4);
    ck_assert_int_eq(cvm_mesh_copy_markers(mark, 16, m, CVM_ENT_SEGMENT), CVM_OK);
    for (k = 0; k < nseg; k++)
        ck_assert(mark[k] >= 1 && mark[k] <= 4);
    ck_assert_int_eq(cvm_mesh_copy_markers(mark, 16, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_int_eq(mark[4], 9);
    cvm_mesh_free(m);
}
END_TEST

TCase *api_read_foreign_tcase(void)
{
    TCase *tc = tcase_create("read_foreign");
    tcase_add_test(tc, read_foreign_meshes_rebuild_the_file);
    tcase_add_test(tc, read_foreign_msh_domain_is_an_input);
    return tc;
}
