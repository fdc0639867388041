/* cavity.h - generic re-triangulation of a cavity. */
#ifndef CVM_CAVITY_H
#define CVM_CAVITY_H

#include "delaunay_internal.h"

/* Remove triangles cav[0..ncav) and add nnew triangles newtri (3 vertex ids
 * each, counter-clockwise) that tile the same region. Adjacency is rebuilt by
 * matching edges; boundary edges keep their segment index, and edge (ca, cb)
 * gets segment cseg (ca = -2 for none). Flags and attribute come from cav[0].
 * Returns CVM_OK or CVM_E_NOMEM (before any change). */
cvm_status cvm__tri2_replace(cvm__tri2 *T, const int32_t *cav, size_t ncav, const int32_t *newtri,
                             size_t nnew, int32_t ca, int32_t cb, int32_t cseg);

#endif
