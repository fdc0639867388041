/* generate3_tests.h - TCases of the generate3 suite (tests/unit/generate3/suite.c). */
#ifndef CVMTEST_GENERATE3_TESTS_H
#define CVMTEST_GENERATE3_TESTS_H
#include <check.h>

TCase *generate3_cube_tcase(void); /* test_cube.c: the unit cube at uniform size */
TCase *generate3_api_tcase(void);  /* test_generate3.c: statuses, sphere in a box, determinism, OOM */
TCase *generate3_sized_tcase(void); /* test_sized.c: cvm_mesh_generate3_sized() */
TCase *generate3_surface_tcase(void); /* test_surface.c: planar facets re-meshed (CVM_OPT_GEN3_SURFACE) */
TCase *generate3_remesh_tcase(void);  /* test_remesh.c: the whole surface re-meshed */
TCase *generate3_octree_tcase(void);  /* test_octree.c: the octree free space */
TCase *generate3_refine_tcase(void);  /* test_refine.c: the Delaunay-refinement free space */

#endif
