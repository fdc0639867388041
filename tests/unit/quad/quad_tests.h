/* quad_tests.h - the TCases of the quad suites (matching and recombination; metric field,
 * Lp-CVT energy and optimiser), and their helpers (util.c). */
#ifndef CVMTEST_QUAD_TESTS_H
#define CVMTEST_QUAD_TESTS_H
#include <check.h>
#include <stddef.h>
#include <stdint.h>
#include "cvmesh.h"
#include "common/common_internal.h"
#include "quad/matching.h"
#include "quad/quad_internal.h"
#include "support/failing_alloc.h"

TCase *quad_matching_tcase(void);  /* lib/quad/matching*.c */
TCase *quad_recombine_tcase(void); /* lib/quad/recombine.c */

/* A graph given as edge list. */
typedef struct qtest_graph {
    size_t n, m;
    cvm_index *ends; /* 2m */
    int64_t *w;      /* m */
} qtest_graph;

void qtest_graph_free(qtest_graph *g);

/* Random graph number k, the same as random_graph(k) of gen_matching_oracle.py. */
void qtest_random_graph(qtest_graph *g, uint64_t k);

/* The dual graph of a Delaunay triangulation of npts random points (seed):
 * vertices are triangles, edges join neighbours; weights from the stream of seed
 * in [0, wmax]. */
void qtest_delaunay_dual(qtest_graph *g, size_t npts, uint64_t seed, int64_t wmax);

/* Check mate (edge per vertex or -1) is a matching of g; give its weight and size. */
void qtest_assert_matching(const qtest_graph *g, const cvm_index *mate, int64_t *weight,
                           size_t *card);

/* Assert that duals certify mate optimal (matching.h): feasibility, tight matched
 * edges, y >= 0, y = 0 when exposed, z >= 0, full blossoms where z > 0, laminar
 * family. Returns the depth of the deepest blossom nesting (0: no blossom). */
int qtest_assert_certificate(const qtest_graph *g, const cvm_index *mate,
                             const cvm__match_duals *d);

/* A context whose allocations go through a (the failing allocator). */
void qtest_ctx(cvm__ctx *ctx, cvmtest_alloc *a);

TCase *quad_dunavant_tcase(void);
TCase *quad_metric_tcase(void);
TCase *quad_lpcvt_energy_tcase(void);
TCase *quad_lpcvt_optimise_tcase(void);
TCase *quad_quadmesh_tcase(void);  /* lib/api/quadmesh.c, cvm_mesh_quadmesh() */

/* The boundary of the box [x0, x1] x [y0, y1] with n pieces a side, counter-clockwise from
 * (x0, y0), into xy (8 n values). */
void qtest_box(double *xy, double x0, double y0, double x1, double y1, int n);
/* A sizing *s holding the built-in metric b (not copied: it must outlive *s) and mt over the
 * nc corners of the polygon corners; ctx initialised with the default allocator. */
void qtest_metric(cvm_sizing **s, cvm__metric *mt, cvm__ctx *ctx, const cvm__metric_builtin *b,
                  const double *corners, size_t nc);
/* A deterministic uniform double in [0, 1) from *state (splitmix64). */
double qtest_uniform(unsigned long long *state);

#endif
