/* spatial_sort.h - insertion order for incremental Delaunay construction. */
#ifndef CVM_SPATIAL_SORT_H
#define CVM_SPATIAL_SORT_H

#include "common/common_internal.h"

/* Fill order[0..n) with a permutation of 0..n-1: random rounds of doubling
 * size (BRIO), each sorted along a Hilbert curve over the bounding box.
 * Deterministic for a given seed. Returns CVM_OK or CVM_E_NOMEM. */
cvm_status cvm__brio_order(cvm__ctx *ctx, const double *xy, size_t n, uint64_t seed,
                           int32_t *order);

#endif
