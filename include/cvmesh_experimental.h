/*
 * cvmesh_experimental.h - the experimental part of the cvmesh API: names whose
 * meaning may change, or that may go away, in any later version. Everything in
 * include/cvmesh.h is stable; what is here is not.
 *
 * Define CVM_EXPERIMENTAL before including this header, and link cvmesh
 * statically when you use it, so that a shared library of another version
 * cannot change what a program built against this one gets. Experimental
 * option keys are numbered from 1000 (cvm_option); experimental values of
 * stable options are named here.
 */
#ifndef CVMESH_EXPERIMENTAL_H
#define CVMESH_EXPERIMENTAL_H

#ifndef CVM_EXPERIMENTAL
#error "cvmesh_experimental.h declares unstable API: define CVM_EXPERIMENTAL to use it"
#endif

#include "cvmesh.h"

/**
 * Value of CVM_OPT_DUAL_TOPOLOGY: the degree repair of the dual optimiser (see
 * that option). It tends to lower the minimum angle; its rules may change.
 */
#define CVM_DUAL_TOPOLOGY_DEGREE_REPAIR 2

#endif /* CVMESH_EXPERIMENTAL_H */
