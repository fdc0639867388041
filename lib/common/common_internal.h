/*
 * common_internal.h - the per-handle context shared by every module: allocator
 * hooks, the last error (status, message, offending item) and run control
 * (progress callback, time limit, cancellation).
 */
#ifndef CVM_COMMON_INTERNAL_H
#define CVM_COMMON_INTERNAL_H

#include <stddef.h>
#include <stdint.h>
#include "cvmesh.h"

#define CVM__ERRMSG_LEN 512

#if defined(__GNUC__)
#  define CVM__PRINTF(f, a) __attribute__((format(printf, f, a)))
#else
#  define CVM__PRINTF(f, a)
#endif

/* Context owned by a handle; never shared between handles. */
typedef struct cvm__ctx {
    cvm_malloc_fn alloc_fn;
    cvm_realloc_fn realloc_fn;
    cvm_free_fn free_fn;
    void *payload;

    cvm_status status;          /* status of the last failing call */
    cvm_entity err_kind;        /* item named by the last error */
    int64_t err_index;
    char errmsg[CVM__ERRMSG_LEN];

    cvm_progress_fn progress_fn;
    void *progress_payload;
    int64_t progress_every;     /* < 1: no callback */
    int64_t ops;                /* operations since the last check */
    double deadline;            /* monotonic seconds; 0 = none */
} cvm__ctx;

/* Initialise with the C library allocator (payload ignored). */
void cvm__ctx_init_default(cvm__ctx *ctx);

/* Allocation through the handle's hooks. Each returns NULL on failure and
 * never sets an error itself; callers return cvm__nomem(ctx). A size of 0
 * allocates 1 byte so that NULL always means failure. */
void *cvm__malloc(cvm__ctx *ctx, size_t size);
void *cvm__calloc(cvm__ctx *ctx, size_t n, size_t size);
void *cvm__realloc(cvm__ctx *ctx, void *p, size_t size);
void cvm__free(cvm__ctx *ctx, void *p);
/* Multiply n*size with overflow check; returns 0 on overflow. */
int cvm__mul_ok(size_t n, size_t size, size_t *out);
/* Grow *p (of element size elem) so that it holds at least need elements; the
 * capacity *cap grows geometrically. Returns CVM_OK or CVM_E_NOMEM (and *p,
 * *cap unchanged). */
cvm_status cvm__grow(cvm__ctx *ctx, void **p, size_t *cap, size_t need, size_t elem);

/* Record an error (or incomplete status) with a message naming item
 * (kind, index); returns s so that callers can write return cvm__error(...). */
cvm_status cvm__error(cvm__ctx *ctx, cvm_status s, cvm_entity kind, int64_t index,
                      const char *fmt, ...) CVM__PRINTF(5, 6);
/* Copy the text src into dst (cap bytes, always NUL-terminated), writing
 * every byte that is a control character (C0, DEL, the C1 range in UTF-8) or
 * not part of well-formed UTF-8 as \xHH; text that does not fit is cut at a
 * character boundary. cvm__error() passes every message through it. */
void cvm__escape_text(char *dst, size_t cap, const char *src);
/* Out of memory with a standard message. */
cvm_status cvm__nomem(cvm__ctx *ctx);
/* The dim argument of the dimension-generic (_nd) call named call: CVM_OK for 2 (the only
 * kernel yet), else an error with a message: CVM_E_UNSUPPORTED for 3 (the 3D kernel is not
 * in this version), CVM_E_ARGUMENT for anything else. */
cvm_status cvm__check_dim(cvm__ctx *ctx, int dim, const char *call);
/* Forget the last error: called at the start of every public call. */
void cvm__clear_error(cvm__ctx *ctx);

/* Monotonic clock, seconds. */
double cvm__now(void);

/* Arm run control for one long call: time_limit_s 0 = none. */
void cvm__run_begin(cvm__ctx *ctx, double time_limit_s);
/* Count n elementary operations; every progress_every operations (1024 when
 * no callback) call the callback and check the clock. Returns CVM_OK, or
 * CVM_INCOMPLETE_CANCELLED / CVM_INCOMPLETE_TIME_LIMIT (without a message;
 * the caller says what the stop left). */
cvm_status cvm__tick(cvm__ctx *ctx, int64_t n, cvm_stage stage, double fraction);
/* Ask the progress callback, if any, whether to go on: CVM_OK, or
 * CVM_INCOMPLETE_CANCELLED (no message). The time limit is not checked: for
 * work that cannot stop half-way and has no valid partial result (a write). */
cvm_status cvm__poll_cancel(cvm__ctx *ctx, cvm_stage stage, double fraction);

/* Smallest-norm point d (nd = 1 or 2 components) of the convex hull of the
 * gradients g + nd * act[k], k < na: the shortest of the hull's vertices and of
 * the origin's projections on its edges that has d . g_i >= |d|^2 (1 - 1e-9)
 * for every active i (Freitag and Ollivier's search direction of max-min
 * optimisation). Returns 0 when there is none: a max-min point to first order. */
int cvm__minnorm_hull(const double *g, int nd, const size_t *act, size_t na, double *d);

/* Small deterministic random stream (xoshiro256** seeded by splitmix64). */
typedef struct cvm__rng { uint64_t s[4]; } cvm__rng;
void cvm__rng_seed(cvm__rng *r, uint64_t seed);
uint64_t cvm__rng_next(cvm__rng *r);
/* Uniform in [0, n). */
uint64_t cvm__rng_below(cvm__rng *r, uint64_t n);
/* Uniform double in [0, 1). */
double cvm__rng_uniform(cvm__rng *r);
/* Standard normal (Box-Muller, two uniforms). */
double cvm__rng_gauss(cvm__rng *r);
/* A Levy-stable step of index 1.5 (Mantegna's algorithm, two normals). */
double cvm__rng_levy(cvm__rng *r);
/* order[0..n) := 0..n-1 sorted by the double at byte offset i * stride from key,
 * ties by index (insertion sort: for small n, deterministic). */
void cvm__order_small(const double *key, size_t stride, int *order, int n);

/* ---- insertion order (brio.c): biased randomised rounds (BRIO, Amenta, Choi
 * and Rote 2003) with a space-filling curve inside each round; both kernels
 * build their keys as (round << curve bits) | curve index and sort them. ---- */
typedef struct cvm__brio {
    cvm__rng rng;
    int rounds;
} cvm__brio;
/* rounds = the smallest r with (n >> r) <= first_round_max, at most 15. */
void cvm__brio_init(cvm__brio *b, size_t n, size_t first_round_max, uint64_t seed);
/* The round of the next point: rounds less the trailing zero bits of a random
 * word (at most rounds), so the last round holds about half the points, the
 * one before a quarter, ... One random word per call. */
int cvm__brio_next_round(cvm__brio *b);
/* Lower corner lo and scale sc = cells / extent per axis of n points of dim
 * (<= 3) coordinates; sc 0 on an axis without extent or with an infinite scale. */
void cvm__bbox_scale(const double *x, size_t n, int dim, double cells, double *lo, double *sc);
/* order[i] = i, then sorted stably by the low `bits` bits of key[] (LSD radix,
 * 12 bits a pass); key[] ends sorted too. CVM_E_NOMEM leaves order unspecified. */
cvm_status cvm__sort_by_key(cvm__ctx *ctx, uint64_t *key, int32_t *order, size_t n, int bits);

#endif
