/*
 * matching.h - maximum-weight matching on a general sparse graph: Edmonds'
 * blossom method in its primal-dual weighted form (Galil 1986, "Efficient
 * algorithms for finding maximum matching in graphs", section 4; Gabow 1976),
 * with the practical devices of Kolmogorov's Blossom V paper (2009): a greedy
 * warm start, alternating trees grown from every free vertex at once and kept
 * across augmentations, and priority queues that give the next dual update.
 *
 * Weights are integers, so every dual update is exact and the result carries
 * a checkable optimality certificate (cvm__match_duals). Callers with real
 * weights scale and round them: cvm__match_scale() documents the rule the
 * quad recombination uses.
 */
#ifndef CVM_QUAD_MATCHING_H
#define CVM_QUAD_MATCHING_H

#include <stddef.h>
#include <stdint.h>
#include "common/common_internal.h"

/* Largest edge weight accepted: duals then stay below 2^43 and every sum the
 * solver forms fits int64 with room to spare. */
#define CVM__MATCH_WEIGHT_MAX ((int64_t)1 << 40)

typedef enum cvm__match_mode {
    /* a matching of maximum total weight (its size is whatever that gives) */
    CVM__MATCH_MAX_WEIGHT = 0,
    /* among the matchings of maximum cardinality (perfect when the graph has
     * one), one of maximum total weight */
    CVM__MATCH_MAX_CARDINALITY = 1
} cvm__match_mode;

/*
 * The optimality certificate of a CVM__MATCH_MAX_WEIGHT result, in units of
 * four times the weights: for every edge e = (i, j) of weight w,
 *   y[i] + y[j] + sum of z[b] over the blossoms b holding both i and j >= 4 w,
 * with equality on matched edges; y >= 0 and y = 0 on unmatched vertices;
 * z >= 0, and a blossom with z > 0 holds (size - 1) / 2 matched edges. These
 * are the complementary-slackness conditions of Edmonds' odd-set linear
 * program, so a matching that meets them has maximum weight. Blossom b holds
 * the vertices verts[off[b] .. off[b+1]-1]; the blossoms form a laminar family.
 * In CVM__MATCH_MAX_CARDINALITY mode the same conditions hold for the
 * weights w + shift, shift = (n / 2) * (largest weight) + 1, for which every
 * maximum-weight matching has maximum cardinality; shift is 0 otherwise.
 */
typedef struct cvm__match_duals {
    int64_t shift;       /* added to every weight (see above) */
    int64_t *y;          /* n entries */
    size_t nblossom;
    int64_t *z;          /* nblossom entries */
    size_t *off;         /* nblossom + 1 entries */
    cvm_index *verts;    /* off[nblossom] entries */
} cvm__match_duals;

/*
 * Solve the matching problem of mode on the graph with n vertices and m
 * edges: edge e joins ends[2e] and ends[2e+1] and weighs w[e].
 *
 * mate_out  n entries: the edge matched at each vertex, or -1.
 * duals_out NULL, or receives the certificate (arrays allocated through ctx;
 *           release with cvm__match_duals_free()). Untouched on error.
 * Parallel edges are allowed. The result is deterministic (ties go to the
 * lower index). Time: near O(m log m) per augmentation in the worst case;
 * on the dual graphs of triangulations the warm start leaves few.
 * Returns CVM_OK; CVM_E_INPUT_INDEX (an end outside [0, n), message gives the
 * edge), CVM_E_INPUT_DEGENERATE (an edge joins a vertex to itself),
 * CVM_E_ARGUMENT (a weight outside [0, CVM__MATCH_WEIGHT_MAX], or an unknown
 * mode), CVM_E_TOO_LARGE (n or m beyond INT32_MAX / 2; in maximum-cardinality
 * mode also n / 2 times the largest weight beyond 2^56), CVM_E_NOMEM, or
 * CVM_E_INTERNAL (a failed consistency check: a bug). On error mate_out is
 * unspecified and nothing is leaked.
 */
cvm_status cvm__matching_solve(cvm_index *mate_out, cvm__match_duals *duals_out, cvm__ctx *ctx,
                               size_t n, size_t m, const cvm_index *ends, const int64_t *w,
                               cvm__match_mode mode);

/*
 * The greedy matching: edges by decreasing weight (ties by index), each taken
 * when both its ends are still free. At least half the optimum weight; for
 * comparison with the exact solver. Same arguments and errors as
 * cvm__matching_solve() (no mode, no certificate).
 */
cvm_status cvm__matching_greedy(cvm_index *mate_out, cvm__ctx *ctx, size_t n, size_t m,
                                const cvm_index *ends, const int64_t *w);

/* Free the arrays of d (which may be zeroed or partly filled); d is zeroed. */
void cvm__match_duals_free(cvm__ctx *ctx, cvm__match_duals *d);

/*
 * Real weight q in [0, 1] as the solver's integer: round(q * 2^20). Two pairs
 * whose qualities differ by less than 2^-21 may then tie; a matching optimal
 * for the rounded weights is within n * 2^-21 of optimal for the real ones.
 */
int64_t cvm__match_scale(double q);

#endif
