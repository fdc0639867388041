/* api_tests.h - TCases of the api suite (tests/unit/api/suite.c assembles them). */
#ifndef CVMTEST_API_TESTS_H
#define CVMTEST_API_TESTS_H
#include <check.h>

TCase *api_version_tcase(void);  /* test_version.c: version numbers and status codes */
TCase *api_options_tcase(void);  /* test_options.c: option keys, bounds, rejection */
TCase *api_args_tcase(void);     /* test_args.c: NULL arguments, call order, short buffers */
TCase *api_oom_tcase(void);      /* test_oom.c: allocation failure k = 1, 2, ... */
TCase *api_threads_tcase(void);  /* test_threads.c: handles on concurrent threads */
TCase *api_output_tcase(void);   /* test_output.c: counts, copies, views (output.c, domain.c) */
TCase *api_quality_tcase(void);  /* test_quality.c: measures and histograms (quality.c) */
TCase *api_write_tcase(void);    /* test_write.c: cvm_mesh_write (mesh_write.c) */
TCase *api_read_vtu_tcase(void); /* test_read_vtu.c: cvm_mesh_read of .vtu (mesh_read_vtu.c) */
TCase *api_read_foreign_tcase(void); /* test_read_foreign.c: cvm_mesh_read of VTK, meshio and Gmsh files */
TCase *api_read_names_tcase(void); /* test_read_names.c: later errors in the file's terms */
TCase *api_marker_names_tcase(void); /* test_marker_names.c: the marker <-> name table, .msh physical names */
TCase *api_nd_tcase(void);        /* test_nd.c: dimension-generic calls, mixed cells, reports */
TCase *api_sizing_nd_tcase(void);
TCase *api_sizing3_tcase(void);   /* test_sizing3.c: the sizing handle in 3D */
TCase *api_mesh3_dual_tcase(void); /* test_mesh3_dual.c: the 3D dual and quality measures */
TCase *api_mesh3_insert_tcase(void); /* test_mesh3_insert.c: 3D point insertion */
TCase *api_mesh3_tcase(void);     /* test_mesh3.c: a handle given 3D points */ /* test_sizing_nd.c: dimension-generic sizing, metric source */

#endif
