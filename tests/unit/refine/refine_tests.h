/* refine_tests.h - the TCases of the refine suite and their shared helpers. */
#ifndef CVMTEST_REFINE_TESTS_H
#define CVMTEST_REFINE_TESTS_H
#include <check.h>
#include <stddef.h>
#include "cvmesh.h"

TCase *refine_sizing_tcase(void);
TCase *refine_sizing_batch_tcase(void);
TCase *refine_bad_queue_tcase(void);
TCase *refine_delaunay_tcase(void);
TCase *refine_frontal_tcase(void);
TCase *refine_aflr_tcase(void);
TCase *refine_swap_smooth_tcase(void);
TCase *refine_report_tcase(void);
TCase *refine_random_domains_tcase(void);
TCase *refine_regions_tcase(void);
TCase *refine_march_tcase(void);
TCase *refine_resample_tcase(void);

/* Path of an example domain: $CVM_DATA_DIR/name, default examples/data/name. */
void rtest_data_path(char *buf, size_t len, const char *name);

/* The segments of a .poly file as 0-based input point ids (own parser, so the
 * test does not trust the library's reader for what it checks); caller frees. */
cvm_index *rtest_poly_segments(const char *path, size_t *nseg);

/* Points (2 per vertex) and triangles (3 ids each) of m in fresh arrays; caller frees. */
void rtest_fetch(cvm_mesh *m, double **xy, size_t *nv, cvm_index **tri, size_t *nt);

/* Quality of a mesh measured from its coordinates by the test's own code. */
typedef struct rtest_quality {
    size_t nv, nt;
    double min_angle;       /* degrees */
    double max_edge;
    double max_circumradius;
} rtest_quality;
void rtest_measure(cvm_mesh *m, rtest_quality *q);

/* Minimum angle (degrees) over triangles that have no vertex within dist of
 * any of the napex points apex (2 doubles each). */
double rtest_min_angle_away(cvm_mesh *m, const double *apex, size_t napex, double dist);

/* Assert that two meshes have bit-identical points and triangles. */
void rtest_assert_identical(cvm_mesh *a, cvm_mesh *b);

/* Refine m (already triangulated) with a uniform size; returns the status. */
cvm_status rtest_refine_uniform(cvm_mesh *m, double h, cvm_algorithm algo);

/* Refine a shared geometry (name.poly) at uniform size h with algo and assert,
 * by the test's own measurements: status CVM_OK, a valid mesh keeping every
 * input segment (mesh oracle, Euler characteristic euler), every angle >= 30
 * degrees, every circumradius <= h, a triangle count in [1e3, 2e4], the
 * report consistent, and a second run bit-identical. */
void rtest_shared_geometry(const char *name, double h, long euler, cvm_algorithm algo);

/* Assert, by the test's own measurements, that refined mesh m (what names it in
 * messages) is valid and keeps the nseg input segments segs (mesh oracle; also
 * constrained Delaunay when delaunay is set; Euler characteristic euler), has
 * every angle >= 30 degrees and every circumradius <= h; its measures in *q. */
void rtest_assert_refined(cvm_mesh *m, const char *what, const cvm_index *segs, size_t nseg,
                          int delaunay, long euler, double h, rtest_quality *q);

/* The unit square (4 points, 4 segments) as the PSLG of m, triangulated. */
void rtest_set_unit_square(cvm_mesh *m);

/* A 3-degree wedge and a jagged star polygon (seeded) as PSLGs on m. */
void rtest_set_wedge(cvm_mesh *m, double angle_deg);
void rtest_set_star(cvm_mesh *m, size_t spikes, unsigned long seed);

#endif
