/*
 * failing_alloc.h - a counting allocator for cvm_mesh_create_with_allocator()
 * that fails the k-th allocation on demand and tracks live blocks and bytes,
 * so tests can inject out-of-memory at every allocation and detect leaks
 * (SQLite test/malloc_common.tcl; libgit2 cl_alloc_limit).
 *
 * An "allocation" is any call of cvmtest_malloc or cvmtest_realloc (a realloc
 * may fail too). Frees are never counted and never fail.
 */
#ifndef CVMTEST_FAILING_ALLOC_H
#define CVMTEST_FAILING_ALLOC_H

#include <stddef.h>
#include "cvmesh.h"

typedef struct cvmtest_alloc {
    long fail_at;        /* 1-based number of the allocation to fail; 0 = never fail */
    int persistent;      /* 0: only allocation fail_at fails (transient); 1: it and all later ones */
    long n_calls;        /* allocations attempted so far */
    long n_failed;       /* allocations refused so far */
    long live_blocks;    /* blocks allocated and not yet freed */
    size_t live_bytes;   /* bytes in those blocks */
    size_t peak_bytes;   /* largest live_bytes seen */
} cvmtest_alloc;

/* Reset all counters; fail_at 0 never fails. */
void cvmtest_alloc_init(cvmtest_alloc *a, long fail_at, int persistent);

/* Re-arm the failure point, keeping the live counters (for retries on the same handle). */
void cvmtest_alloc_arm(cvmtest_alloc *a, long fail_at, int persistent);

/* The hooks: payload is a cvmtest_alloc *. */
void *cvmtest_malloc(void *payload, size_t size);
void *cvmtest_realloc(void *payload, void *ptr, size_t size);
void cvmtest_free(void *payload, void *ptr);

/* cvm_mesh_create_with_allocator() with the three hooks above and payload a. */
cvm_status cvmtest_mesh_create(cvm_mesh **out, cvmtest_alloc *a);

#endif
