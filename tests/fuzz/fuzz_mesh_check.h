/* fuzz_mesh_check.h - fuzz_require_read_mesh(m): the contract of a mesh that
 * cvm_mesh_read() returned with CVM_OK, as after cvm_mesh_set_weights(): it
 * passes cvm_mesh_check(), or it keeps vertices whose power cell is empty
 * (CVM_MEASURE_VANISHED_VERTICES > 0) beside the illegal edges no flip can
 * fix, which the check reports (CVM_E_INTERNAL). Include after
 * fuzz_require.h. */
#ifndef CVM_FUZZ_MESH_CHECK_H
#define CVM_FUZZ_MESH_CHECK_H

#include <string.h>

#include "cvmesh.h"

static void fuzz_require_read_mesh(cvm_mesh *m)
{
    char msg[600];
    double vanished = 0;
    cvm_status c = cvm_mesh_check(m);
    if (c == CVM_OK)
        return;
    strncpy(msg, cvm_mesh_errmsg(m), sizeof msg - 1);
    msg[sizeof msg - 1] = '\0';
    FUZZ_REQUIRE(c == CVM_E_INTERNAL &&
                     cvm_mesh_get_measure(&vanished, m, CVM_MEASURE_VANISHED_VERTICES) == CVM_OK &&
                     vanished > 0,
                 "cvm_mesh_check: %s", msg);
}

#endif
