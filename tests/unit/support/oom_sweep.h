/* oom_sweep.h - out of memory at every allocation of a library call, as the unit tests check it. */
#ifndef CVMTEST_OOM_SWEEP_H
#define CVMTEST_OOM_SWEEP_H

#include "cvmesh.h"

/* Out of memory at every allocation of a run, transient and then persistent:
 * for each failure point i = 1, 2, ... a fresh mesh on a failing allocator is
 * built by setup(m, arg), the allocator is armed to fail at the i-th
 * allocation after that, and run(m, arg) must return CVM_OK or CVM_E_NOMEM,
 * leak nothing and leave a mesh that passes cvm_mesh_check() (or says
 * CVM_E_STATE); check(m, arg) (may be NULL) adds checks on such a mesh (the
 * mesh oracle, for instance). The sweep ends at the first run that meets no
 * failure, which must be CVM_OK, and asserts that the run made more than 20
 * allocations. */
void cvmtest_oom_sweep(void (*setup)(cvm_mesh *m, void *arg), cvm_status (*run)(cvm_mesh *m, void *arg),
                       void (*check)(cvm_mesh *m, void *arg), void *arg);

#endif
