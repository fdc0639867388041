/*
 * matching_solver.h - the state of the blossom solver of matching.c, shared
 * with matching_blossom.c (blossom shrinking, expansion and augmentation).
 * Private to lib/quad/matching*.c. The method is described in matching.c.
 */
#ifndef CVM_QUAD_MATCHING_SOLVER_H
#define CVM_QUAD_MATCHING_SOLVER_H

#include "quad/matching.h"

#define NONE (-1)
enum { FREE = 0, LAB_S = 1, LAB_T = 2 };
enum { Q_ZERO = 0, Q_GROW = 1, Q_SS = 2, Q_EXPAND = 3, NQ = 4 };
#define T_INF INT64_MAX

typedef struct heap_ent { int64_t key; int64_t id; } heap_ent;
typedef struct heap { heap_ent *a; size_t n, cap; } heap;
typedef struct tl_ent { cvm_index node, next; } tl_ent;

typedef struct solver {
    cvm__ctx *ctx;
    cvm_index n;
    size_t m;
    const cvm_index *ends;
    const int64_t *w;
    int64_t yfloor;            /* an S vertex at this dual ends its tree (0, or -2C) */
    int64_t t;                 /* the clock: total dual step so far */
    size_t *adj_off;           /* vertex -> its edges (CSR) */
    cvm_index *adj;
    cvm_index *mate;           /* vertex -> matched vertex or NONE */
    cvm_index *anc;            /* node -> an ancestor blossom (path-compressed), valid */
    int32_t *ancg;             /* while that blossom lives with generation ancg */
    int32_t *gen;              /* blossom id -> how often it was reused */
    cvm_index *next_leaf;      /* vertex -> next vertex of the same blossom */
    /* per node (vertices 0..n-1, blossoms n..2n-1) */
    cvm_index *parent, *nxt, *prv;   /* blossom cycle; nxt/prv among siblings */
    cvm_index *lfrom, *lto;          /* edge to nxt: lfrom in node, lto in nxt */
    cvm_index *base, *base_child, *first, *last;
    cvm_index *labfrom, *labto, *tree;  /* label edge: labfrom outside, labto inside */
    unsigned char *label, *alive;
    int64_t *d0, *dt;          /* dual d0 at clock dt; the rate follows the label */
    cvm_index *mark;
    cvm_index stamp;
    cvm_index *free_ids;
    cvm_index nfree;
    cvm_index *work;           /* 2n scratch: augmentation tasks, blossom paths */
    heap q[NQ];
    cvm_index *tl_head;        /* tree (root vertex) -> list of its top nodes */
    tl_ent *tl;
    size_t tl_n, tl_cap;
    cvm_index tl_free;
} solver;

static inline cvm_index other_end(const solver *s, size_t e, cvm_index v)
{
    return s->ends[2 * e] == v ? s->ends[2 * e + 1] : s->ends[2 * e];
}

/* The top-level blossom holding node v (v itself when none): follows ancestor
 * links, falls back on parent links where a link names an expanded (or
 * reused) blossom, and compresses the path. Blossoms are only ever added
 * above a top-level node or removed from the top, so every live link is an
 * ancestor; this keeps shrinking a blossom O(children) instead of O(size). */
static inline cvm_index top_of(solver *s, cvm_index v)
{
    cvm_index x = v, r;
    for (;;) {
        cvm_index a = s->anc[x];
        if (a == NONE || !s->alive[a] || s->gen[a] != s->ancg[x]) {
            a = s->parent[x];
            if (a == NONE)
                break;
            s->anc[x] = a;
            s->ancg[x] = s->gen[a];
        }
        x = a;
    }
    r = x;
    for (x = v; x != r;) {
        cvm_index next = s->anc[x];
        s->anc[x] = r;
        s->ancg[x] = s->gen[r];
        x = next;
    }
    return r;
}

/* The node's dual now: vertices follow the label of their top blossom, a
 * blossom its own label while it is top-level (constant below). */
static inline int64_t dual(solver *s, cvm_index x)
{
    int64_t dt = s->t - s->dt[x];
    if (x < s->n) {
        int lab = s->label[top_of(s, x)];
        return s->d0[x] + (lab == LAB_S ? -dt : lab == LAB_T ? dt : 0);
    }
    if (s->parent[x] != NONE)
        return s->d0[x];
    return s->d0[x] + (s->label[x] == LAB_S ? 2 * dt : s->label[x] == LAB_T ? -2 * dt : 0);
}

static inline void flush(solver *s, cvm_index x)
{
    s->d0[x] = dual(s, x);
    s->dt[x] = s->t;
}

static inline void flush_leaves(solver *s, cvm_index x)
{
    cvm_index v;
    for (v = s->first[x];; v = s->next_leaf[v]) {
        flush(s, v);
        if (v == s->last[x])
            break;
    }
}

/* Relabel the top-level node x, fixing its duals at the old rate first. */
static inline void set_label(solver *s, cvm_index x, int lab)
{
    flush_leaves(s, x);
    if (x >= s->n)
        flush(s, x);
    s->label[x] = (unsigned char)lab;
}

static inline int64_t slack(solver *s, size_t e)
{
    return dual(s, s->ends[2 * e]) + dual(s, s->ends[2 * e + 1]) - 4 * s->w[e];
}


/* matching.c: queues, tree lists and label bookkeeping */
cvm_status cvm__mt_heap_push(solver *s, int k, int64_t key, int64_t id);
cvm_status cvm__mt_tree_add(solver *s, cvm_index tree, cvm_index node);
cvm_status cvm__mt_become_s(solver *s, cvm_index x);
cvm_status cvm__mt_become_free(solver *s, cvm_index x);
cvm_status cvm__mt_dissolve(solver *s, cvm_index tree);

/* matching_blossom.c: the primal steps */
void cvm__mt_augment_to_root(solver *s, cvm_index v, cvm_index u);
cvm_status cvm__mt_grow(solver *s, cvm_index v, cvm_index u);
cvm_status cvm__mt_make_blossom(solver *s, cvm_index v, cvm_index u);
cvm_status cvm__mt_expand(solver *s, cvm_index b);

/* Heap order: by key, ties by id (deterministic). */
static inline int ent_less(const heap_ent *a, const heap_ent *b)
{
    return a->key < b->key || (a->key == b->key && a->id < b->id);
}

#endif
