/* suite.c - the generate3 suite: 3D co-volume mesh generation (cvm_mesh_generate3). */
#include "suites.h"
#include "generate3/generate3_tests.h"

Suite *generate3_suite(void)
{
    Suite *s = suite_create("generate3");
    suite_add_tcase(s, generate3_cube_tcase());
    suite_add_tcase(s, generate3_api_tcase());
    suite_add_tcase(s, generate3_sized_tcase());
    suite_add_tcase(s, generate3_surface_tcase());
    suite_add_tcase(s, generate3_remesh_tcase());
    suite_add_tcase(s, generate3_octree_tcase());
    suite_add_tcase(s, generate3_refine_tcase());
    return s;
}
