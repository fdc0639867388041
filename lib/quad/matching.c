/*
 * matching.c - the primal-dual weighted blossom method (matching.h) with
 * persistent alternating trees and event queues.
 *
 * Model (Galil 1986, section 4). Every vertex v has a dual y(v), every
 * blossom b a dual z(b), in units where an edge e = (i, j) of weight w is
 * feasible when y(i) + y(j) + z(blossoms holding both) >= 4 w and tight at
 * equality. Matched edges and the edges of every blossom's cycle stay tight.
 * Top-level blossoms (a vertex counts as a trivial blossom) carry a label:
 * S (even, in an alternating tree), T (odd, in a tree) or free.
 *
 * Departures from the textbook stage structure, after Kolmogorov (Blossom V):
 *  - every exposed vertex with y > 0 roots its own tree from the start, and
 *    an augmentation dissolves only the two trees it joins; the others keep
 *    their labels;
 *  - one dual step delta for all trees: S vertices lose delta, T vertices
 *    gain it, S blossoms gain 2 delta, T blossoms lose 2 delta. The step is
 *    applied lazily: a global clock t, and each dual stored as its value at
 *    the time its rate last changed;
 *  - the step that makes something happen comes from four lazy heaps keyed by
 *    clock time: an S vertex reaching y = 0, an S-free edge, an S-S edge
 *    between two top blossoms, a T blossom reaching z = 0. Entries are
 *    re-validated when they reach the top; every label change pushes the
 *    entries it makes relevant;
 *  - a greedy warm start (duals lowered vertex by vertex as in Blossom V's
 *    initialisation) so that exposed vertices no longer share one dual. An S
 *    vertex reaching y = 0 that is not a root then flips the even path to its
 *    root, which leaves it exposed with y = 0 (optimal), as a root would.
 * Integrality: warm-start duals are even; all vertices of all trees share one
 * parity, so S-S slacks are even and every step is an integer.
 */
#include <stdlib.h>
#include <string.h>
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
    cvm_index *top;            /* vertex -> its top-level blossom (or itself) */
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

static cvm_index other_end(const solver *s, size_t e, cvm_index v)
{
    return s->ends[2 * e] == v ? s->ends[2 * e + 1] : s->ends[2 * e];
}

/* The node's dual now: vertices follow the label of their top blossom, a
 * blossom its own label while it is top-level (constant below). */
static int64_t dual(const solver *s, cvm_index x)
{
    int64_t dt = s->t - s->dt[x];
    if (x < s->n) {
        int lab = s->label[s->top[x]];
        return s->d0[x] + (lab == LAB_S ? -dt : lab == LAB_T ? dt : 0);
    }
    if (s->parent[x] != NONE)
        return s->d0[x];
    return s->d0[x] + (s->label[x] == LAB_S ? 2 * dt : s->label[x] == LAB_T ? -2 * dt : 0);
}

static void flush(solver *s, cvm_index x)
{
    s->d0[x] = dual(s, x);
    s->dt[x] = s->t;
}

static void flush_leaves(solver *s, cvm_index x)
{
    cvm_index v;
    for (v = s->first[x];; v = s->next_leaf[v]) {
        flush(s, v);
        if (v == s->last[x])
            break;
    }
}

/* Relabel the top-level node x, fixing its duals at the old rate first. */
static void set_label(solver *s, cvm_index x, int lab)
{
    flush_leaves(s, x);
    if (x >= s->n)
        flush(s, x);
    s->label[x] = (unsigned char)lab;
}

static int64_t slack(const solver *s, size_t e)
{
    return dual(s, s->ends[2 * e]) + dual(s, s->ends[2 * e + 1]) - 4 * s->w[e];
}

/* ---- lazy heaps ---- */

static int ent_less(const heap_ent *a, const heap_ent *b)
{
    return a->key < b->key || (a->key == b->key && a->id < b->id);
}

static cvm_status heap_push(solver *s, int k, int64_t key, int64_t id)
{
    heap *h = &s->q[k];
    size_t i;
    if (h->n == h->cap && cvm__grow(s->ctx, (void **)&h->a, &h->cap, h->n + 1, sizeof *h->a))
        return CVM_E_NOMEM;
    i = h->n++;
    h->a[i].key = key;
    h->a[i].id = id;
    while (i > 0 && ent_less(&h->a[i], &h->a[(i - 1) / 2])) {
        heap_ent tmp = h->a[i];
        h->a[i] = h->a[(i - 1) / 2];
        h->a[(i - 1) / 2] = tmp;
        i = (i - 1) / 2;
    }
    return CVM_OK;
}

static void heap_pop(heap *h)
{
    size_t i = 0;
    h->a[0] = h->a[--h->n];
    for (;;) {
        size_t l = 2 * i + 1, r = l + 1, b = i;
        heap_ent tmp;
        if (l < h->n && ent_less(&h->a[l], &h->a[b]))
            b = l;
        if (r < h->n && ent_less(&h->a[r], &h->a[b]))
            b = r;
        if (b == i)
            return;
        tmp = h->a[i];
        h->a[i] = h->a[b];
        h->a[b] = tmp;
        i = b;
    }
}

/* The key entry (k, id) would have if it were pushed now, or -1 when the
 * entry names no event of its kind any more. */
static int64_t current_key(const solver *s, int k, int64_t id)
{
    if (k == Q_ZERO) {
        cvm_index v = (cvm_index)id;
        return s->label[s->top[v]] == LAB_S ? s->t + dual(s, v) - s->yfloor : -1;
    }
    if (k == Q_EXPAND) {
        cvm_index b = (cvm_index)id;
        if (!s->alive[b] || s->parent[b] != NONE || s->label[b] != LAB_T)
            return -1;
        return s->t + dual(s, b) / 2;
    } else {
        size_t e = (size_t)id;
        cvm_index a = s->top[s->ends[2 * e]], b = s->top[s->ends[2 * e + 1]];
        int la = s->label[a], lb = s->label[b];
        if (a == b)
            return -1;
        if (k == Q_GROW && ((la == LAB_S && lb == FREE) || (la == FREE && lb == LAB_S)))
            return s->t + slack(s, e);
        if (k == Q_SS && la == LAB_S && lb == LAB_S)
            return s->t + slack(s, e) / 2;
        return -1;
    }
}

/* Key of the first valid entry of heap k (stale entries are dropped), or T_INF. */
static int64_t heap_peek(solver *s, int k)
{
    heap *h = &s->q[k];
    while (h->n > 0) {
        if (current_key(s, k, h->a[0].id) == h->a[0].key)
            return h->a[0].key;
        heap_pop(h);
    }
    return T_INF;
}

/* ---- tree lists: the top-level nodes labelled in each tree ---- */

static cvm_status tree_add(solver *s, cvm_index tree, cvm_index node)
{
    cvm_index i = s->tl_free;
    if (i != NONE) {
        s->tl_free = s->tl[i].next;
    } else {
        if (s->tl_n == s->tl_cap && cvm__grow(s->ctx, (void **)&s->tl, &s->tl_cap, s->tl_n + 1,
                                              sizeof *s->tl))
            return CVM_E_NOMEM;
        i = (cvm_index)s->tl_n++;
    }
    s->tl[i].node = node;
    s->tl[i].next = s->tl_head[tree];
    s->tl_head[tree] = i;
    s->tree[node] = tree;
    return CVM_OK;
}

/* Push the events that the vertices of x make relevant now that x is S: its
 * own zero crossing, and its edges to S (S-S) and free (grow) nodes. */
static cvm_status become_s(solver *s, cvm_index x)
{
    cvm_index v;
    for (v = s->first[x];; v = s->next_leaf[v]) {
        size_t k;
        if (heap_push(s, Q_ZERO, s->t + dual(s, v) - s->yfloor, v))
            return CVM_E_NOMEM;
        for (k = s->adj_off[v]; k < s->adj_off[v + 1]; k++) {
            size_t e = (size_t)s->adj[k];
            cvm_index o = s->top[other_end(s, e, v)];
            int64_t sl;
            if (o == s->top[v] || s->label[o] == LAB_T)
                continue;
            sl = slack(s, e);
            if (s->label[o] == LAB_S) {
                if (sl & 1)
                    return cvm__error(s->ctx, CVM_E_INTERNAL, CVM_ENT_NONE, (int64_t)e,
                                      "matching: odd slack on S-S edge %zu", e);
                if (heap_push(s, Q_SS, s->t + sl / 2, (int64_t)e))
                    return CVM_E_NOMEM;
            } else if (heap_push(s, Q_GROW, s->t + sl, (int64_t)e)) {
                return CVM_E_NOMEM;
            }
        }
        if (v == s->last[x])
            break;
    }
    return CVM_OK;
}

/* The vertices of x became free: their edges to S nodes may grow trees. */
static cvm_status become_free(solver *s, cvm_index x)
{
    cvm_index v;
    for (v = s->first[x];; v = s->next_leaf[v]) {
        size_t k;
        for (k = s->adj_off[v]; k < s->adj_off[v + 1]; k++) {
            size_t e = (size_t)s->adj[k];
            if (s->label[s->top[other_end(s, e, v)]] == LAB_S &&
                heap_push(s, Q_GROW, s->t + slack(s, e), (int64_t)e))
                return CVM_E_NOMEM;
        }
        if (v == s->last[x])
            break;
    }
    return CVM_OK;
}

/* Unlabel every node of tree (after an augmentation or a flip through it). */
static cvm_status dissolve(solver *s, cvm_index tree)
{
    cvm_index i, last = NONE;
    for (i = s->tl_head[tree]; i != NONE; i = s->tl[i].next) {
        cvm_index x = s->tl[i].node;
        if (s->parent[x] == NONE && s->label[x] != FREE && s->tree[x] == tree &&
            (x < s->n || s->alive[x]))
            set_label(s, x, FREE);
        else
            s->tl[i].node = NONE; /* stale: skipped below */
        last = i;
    }
    for (i = s->tl_head[tree]; i != NONE; i = s->tl[i].next)
        if (s->tl[i].node != NONE && s->label[s->tl[i].node] == FREE &&
            become_free(s, s->tl[i].node))
            return CVM_E_NOMEM;
    if (last != NONE) {
        s->tl[last].next = s->tl_free;
        s->tl_free = s->tl_head[tree];
    }
    s->tl_head[tree] = NONE;
    return CVM_OK;
}

/* ---- augmentation ---- */

/* Position of child c in the cycle of b, counted from the base child. */
static size_t cycle_pos(const solver *s, cvm_index b, cvm_index c)
{
    size_t i = 0;
    cvm_index x;
    for (x = s->base_child[b]; x != c; x = s->nxt[x])
        i++;
    return i;
}

static cvm_index child_holding(const solver *s, cvm_index b, cvm_index v)
{
    cvm_index c = v;
    while (s->parent[c] != b)
        c = s->parent[c];
    return c;
}

/* Make vertex v the base of blossom b: rematch the even path from v's child
 * to the base child, then each sub-blossom on it, with an explicit task stack
 * (the tasks touch disjoint sub-blossoms, so their order is free). The mate
 * of v itself is the caller's to set. */
static void augment_blossom(solver *s, cvm_index b0, cvm_index v0)
{
    cvm_index *task = s->work;
    size_t nt = 0;
    task[nt++] = b0;
    task[nt++] = v0;
    while (nt > 0) {
        cvm_index v = task[--nt], b = task[--nt];
        cvm_index c = child_holding(s, b, v), x = c, c0 = s->base_child[b];
        int forward = (cycle_pos(s, b, c) & 1) != 0;
        if (c >= s->n) {
            task[nt++] = c;
            task[nt++] = v;
        }
        while (x != c0) {
            cvm_index x1 = forward ? s->nxt[x] : s->prv[x];
            cvm_index x2 = forward ? s->nxt[x1] : s->prv[x1];
            /* the edge x1-x2 becomes matched; a in x1, q in x2 */
            cvm_index a = forward ? s->lfrom[x1] : s->lto[x2];
            cvm_index q = forward ? s->lto[x1] : s->lfrom[x2];
            if (x1 >= s->n) {
                task[nt++] = x1;
                task[nt++] = a;
            }
            if (x2 >= s->n) {
                task[nt++] = x2;
                task[nt++] = q;
            }
            s->mate[a] = q;
            s->mate[q] = a;
            x = x2;
        }
        s->base_child[b] = c;
        s->base[b] = v;
    }
}

/* Rematch from S vertex v up to its tree's root; v gets mate u (NONE: v is
 * left exposed). */
static void augment_to_root(solver *s, cvm_index v, cvm_index u)
{
    for (;;) {
        cvm_index b = s->top[v], tb, sv, tv;
        if (b >= s->n)
            augment_blossom(s, b, v);
        s->mate[v] = u;
        if (s->labfrom[b] == NONE)
            return;
        tb = s->top[s->labfrom[b]];
        sv = s->labfrom[tb];
        tv = s->labto[tb];
        if (tb >= s->n)
            augment_blossom(s, tb, tv);
        s->mate[tv] = sv;
        v = sv;
        u = tv;
    }
}

/* ---- tree growth, blossoms ---- */

static cvm_status grow(solver *s, cvm_index v, cvm_index u)
{
    cvm_index tb = s->top[u], tree = s->tree[s->top[v]], x, sb;
    if (s->mate[s->base[tb]] == NONE) {
        /* a free exposed blossom has y = 0 at its base: augment into it */
        augment_to_root(s, v, u);
        if (tb >= s->n)
            augment_blossom(s, tb, u);
        s->mate[u] = v;
        return dissolve(s, tree);
    }
    set_label(s, tb, LAB_T);
    s->labfrom[tb] = v;
    s->labto[tb] = u;
    if (tree_add(s, tree, tb))
        return CVM_E_NOMEM;
    if (tb >= s->n && heap_push(s, Q_EXPAND, s->t + dual(s, tb) / 2, tb))
        return CVM_E_NOMEM;
    x = s->mate[s->base[tb]];
    sb = s->top[x];
    set_label(s, sb, LAB_S);
    s->labfrom[sb] = s->base[tb];
    s->labto[sb] = x;
    if (tree_add(s, tree, sb))
        return CVM_E_NOMEM;
    return become_s(s, sb);
}

/* The S node above S node x in its tree, or NONE at the root. */
static cvm_index s_parent(const solver *s, cvm_index x)
{
    if (s->labfrom[x] == NONE)
        return NONE;
    return s->top[s->labfrom[s->top[s->labfrom[x]]]];
}

/* Tight edge v-u between two S nodes of one tree: shrink the odd cycle they
 * close into a new S blossom. */
static cvm_status make_blossom(solver *s, cvm_index v, cvm_index u)
{
    cvm_index a = s->top[v], c = s->top[u], lca = NONE, b, i, k, pv = 0, *L = s->work;
    cvm_index x, nc;
    if (++s->stamp == INT32_MAX) {
        for (i = 0; i < 2 * s->n; i++)
            s->mark[i] = 0;
        s->stamp = 1;
    }
    while (lca == NONE) {
        if (a != NONE) {
            if (s->mark[a] == s->stamp)
                lca = a;
            s->mark[a] = s->stamp;
            a = s_parent(s, a);
        }
        x = a;
        a = c;
        c = x;
    }
    /* L = lca, the v side downwards, then the u side upwards */
    L[0] = lca;
    for (x = s->top[v]; x != lca; x = s_parent(s, x))
        pv += 2;
    k = pv;
    for (x = s->top[v]; x != lca; x = s_parent(s, x)) {
        L[k--] = x;
        L[k--] = s->top[s->labfrom[x]];
    }
    nc = pv + 1;
    for (x = s->top[u]; x != lca; x = s_parent(s, x)) {
        L[nc++] = x;
        L[nc++] = s->top[s->labfrom[x]];
    }
    if (s->nfree == 0)
        return cvm__error(s->ctx, CVM_E_INTERNAL, CVM_ENT_NONE, -1, "matching: no blossom id left");
    b = s->free_ids[--s->nfree];
    for (i = 0; i < nc; i++) {
        cvm_index y = L[i], z = L[(i + 1) % nc];
        if (i < pv) {
            s->lfrom[y] = s->labfrom[z];
            s->lto[y] = s->labto[z];
        } else if (i == pv) {
            s->lfrom[y] = v;
            s->lto[y] = u;
        } else {
            s->lfrom[y] = s->labto[y];
            s->lto[y] = s->labfrom[y];
        }
        s->nxt[y] = z;
        s->prv[z] = y;
        if (y >= s->n)
            flush(s, y); /* its z stops changing */
        if (s->label[y] == LAB_T)
            flush_leaves(s, y); /* T -> S */
    }
    for (i = 0; i < nc; i++) {
        s->parent[L[i]] = b;
        s->next_leaf[s->last[L[i]]] = s->first[L[(i + 1) % nc]];
    }
    s->alive[b] = 1;
    s->parent[b] = NONE;
    s->base_child[b] = lca;
    s->base[b] = s->base[lca];
    s->first[b] = s->first[lca];
    s->last[b] = s->last[L[nc - 1]];
    s->label[b] = LAB_S;
    s->labfrom[b] = s->labfrom[lca];
    s->labto[b] = s->labto[lca];
    s->d0[b] = 0;
    s->dt[b] = s->t;
    for (x = s->first[b];; x = s->next_leaf[x]) {
        s->top[x] = b;
        if (x == s->last[b])
            break;
    }
    if (tree_add(s, s->tree[lca], b))
        return CVM_E_NOMEM;
    for (i = 0; i < nc; i++) /* the former T children (labels below the top stay put) */
        if (s->label[L[i]] == LAB_T && become_s(s, L[i]))
            return CVM_E_NOMEM;
    return CVM_OK;
}

static cvm_status label_child(solver *s, cvm_index c, int lab, cvm_index from, cvm_index to,
                              cvm_index tree)
{
    s->label[c] = (unsigned char)lab;
    s->labfrom[c] = from;
    s->labto[c] = to;
    if (tree_add(s, tree, c))
        return CVM_E_NOMEM;
    if (lab == LAB_T && c >= s->n && heap_push(s, Q_EXPAND, s->t + dual(s, c) / 2, c))
        return CVM_E_NOMEM;
    return CVM_OK;
}

/* T blossom b reached z = 0: its children become top-level; the even path
 * from the child it was entered by to its base child stays in the tree
 * (T, S, ..., T), the other children become free. */
static cvm_status expand(solver *s, cvm_index b)
{
    cvm_index c0 = s->base_child[b], ce = child_holding(s, b, s->labto[b]), x, v;
    int forward = (cycle_pos(s, b, ce) & 1) != 0;
    cvm_index tree = s->tree[b];
    flush_leaves(s, b);
    x = c0;
    do {
        s->parent[x] = NONE;
        s->label[x] = FREE;
        if (x >= s->n)
            s->dt[x] = s->t;
        for (v = s->first[x];; v = s->next_leaf[v]) {
            s->top[v] = x;
            if (v == s->last[x])
                break;
        }
        x = s->nxt[x];
    } while (x != c0);
    if (label_child(s, ce, LAB_T, s->labfrom[b], s->labto[b], tree))
        return CVM_E_NOMEM;
    for (x = ce; x != c0;) {
        cvm_index x1 = forward ? s->nxt[x] : s->prv[x];
        cvm_index x2 = forward ? s->nxt[x1] : s->prv[x1];
        cvm_status st;
        if (forward)
            st = label_child(s, x1, LAB_S, s->lfrom[x], s->lto[x], tree);
        else
            st = label_child(s, x1, LAB_S, s->lto[x1], s->lfrom[x1], tree);
        if (!st && forward)
            st = label_child(s, x2, LAB_T, s->lfrom[x1], s->lto[x1], tree);
        else if (!st)
            st = label_child(s, x2, LAB_T, s->lto[x2], s->lfrom[x2], tree);
        if (st)
            return st;
        x = x2;
    }
    s->alive[b] = 0;
    s->label[b] = FREE;
    s->free_ids[s->nfree++] = b;
    x = c0;
    do {
        if (s->label[x] == LAB_S && become_s(s, x))
            return CVM_E_NOMEM;
        if (s->label[x] == FREE && become_free(s, x))
            return CVM_E_NOMEM;
        x = s->nxt[x];
    } while (x != c0);
    return CVM_OK;
}

/* ---- set-up, warm start, main loop ---- */

static void solver_free(solver *s)
{
    int k;
    void **p[] = {(void **)&s->adj_off, (void **)&s->adj, (void **)&s->mate, (void **)&s->top,
                  (void **)&s->next_leaf, (void **)&s->parent, (void **)&s->nxt,
                  (void **)&s->prv, (void **)&s->lfrom, (void **)&s->lto, (void **)&s->base,
                  (void **)&s->base_child, (void **)&s->first, (void **)&s->last,
                  (void **)&s->labfrom, (void **)&s->labto, (void **)&s->tree,
                  (void **)&s->label, (void **)&s->alive, (void **)&s->d0, (void **)&s->dt,
                  (void **)&s->mark, (void **)&s->free_ids, (void **)&s->work,
                  (void **)&s->tl_head, (void **)&s->tl};
    size_t i;
    for (i = 0; i < sizeof p / sizeof p[0]; i++) {
        cvm__free(s->ctx, *p[i]);
        *p[i] = NULL;
    }
    for (k = 0; k < NQ; k++) {
        cvm__free(s->ctx, s->q[k].a);
        s->q[k].a = NULL;
    }
}

static cvm_status solver_alloc(solver *s)
{
    size_t n = (size_t)s->n, n2 = 2 * n + 1, i;
    cvm_index **ix[] = {&s->mate, &s->top, &s->next_leaf, &s->tl_head, &s->free_ids,
                        &s->parent, &s->nxt, &s->prv, &s->lfrom, &s->lto, &s->base,
                        &s->base_child, &s->first, &s->last, &s->labfrom, &s->labto,
                        &s->tree, &s->mark, &s->work};
    for (i = 0; i < sizeof ix / sizeof ix[0]; i++)
        if (!(*ix[i] = cvm__malloc(s->ctx, (i < 5 ? n + 1 : n2) * sizeof(cvm_index))))
            return CVM_E_NOMEM;
    s->adj_off = cvm__calloc(s->ctx, n + 2, sizeof *s->adj_off);
    s->adj = cvm__malloc(s->ctx, (2 * s->m + 1) * sizeof *s->adj);
    s->label = cvm__calloc(s->ctx, n2, 1);
    s->alive = cvm__calloc(s->ctx, n2, 1);
    s->d0 = cvm__calloc(s->ctx, n2, sizeof *s->d0);
    s->dt = cvm__calloc(s->ctx, n2, sizeof *s->dt);
    if (!s->adj_off || !s->adj || !s->label || !s->alive || !s->d0 || !s->dt)
        return CVM_E_NOMEM;
    return CVM_OK;
}

static void build_adjacency(solver *s)
{
    size_t e, i, n = (size_t)s->n;
    for (e = 0; e < s->m; e++) {
        s->adj_off[s->ends[2 * e] + 1]++;
        s->adj_off[s->ends[2 * e + 1] + 1]++;
    }
    for (i = 0; i < n; i++)
        s->adj_off[i + 1] += s->adj_off[i];
    for (e = 0; e < s->m; e++) { /* adj_off[v] runs ahead while filling... */
        s->adj[s->adj_off[s->ends[2 * e]]++] = (cvm_index)e;
        s->adj[s->adj_off[s->ends[2 * e + 1]]++] = (cvm_index)e;
    }
    for (i = n; i > 0; i--) /* ...and is shifted back */
        s->adj_off[i] = s->adj_off[i - 1];
    s->adj_off[0] = 0;
}

/* Feasible even duals y(v) = 4 * (largest weight at v) / 2, the tight edges
 * matched greedily, then each exposed vertex's dual lowered to its least
 * feasible value (not below 0), matching it along an edge that becomes tight
 * to an exposed neighbour (heaviest first). */
static void warm_start(solver *s)
{
    cvm_index v;
    size_t e, k;
    for (v = 0; v < s->n; v++) {
        int64_t y = 0;
        for (k = s->adj_off[v]; k < s->adj_off[v + 1]; k++)
            if (2 * s->w[s->adj[k]] > y)
                y = 2 * s->w[s->adj[k]];
        s->d0[v] = y;
        s->mate[v] = NONE;
    }
    for (e = 0; e < s->m; e++) {
        cvm_index a = s->ends[2 * e], b = s->ends[2 * e + 1];
        if (s->mate[a] == NONE && s->mate[b] == NONE && s->d0[a] + s->d0[b] == 4 * s->w[e]) {
            s->mate[a] = b;
            s->mate[b] = a;
        }
    }
    for (v = 0; v < s->n; v++) {
        int64_t need = 0;
        cvm_index best = NONE;
        if (s->mate[v] != NONE)
            continue;
        for (k = s->adj_off[v]; k < s->adj_off[v + 1]; k++) {
            e = (size_t)s->adj[k];
            if (4 * s->w[e] - s->d0[other_end(s, e, v)] > need)
                need = 4 * s->w[e] - s->d0[other_end(s, e, v)];
        }
        s->d0[v] = need;
        for (k = s->adj_off[v]; k < s->adj_off[v + 1]; k++) {
            cvm_index o;
            e = (size_t)s->adj[k];
            o = other_end(s, e, v);
            if (s->mate[o] == NONE && need + s->d0[o] == 4 * s->w[e] &&
                (best == NONE || s->w[e] > s->w[best]))
                best = (cvm_index)e;
        }
        if (best != NONE) {
            cvm_index o = other_end(s, (size_t)best, v);
            s->mate[v] = o;
            s->mate[o] = v;
        }
    }
}

static cvm_status solver_init(solver *s)
{
    cvm_index v, i;
    build_adjacency(s);
    warm_start(s);
    s->t = 0;
    s->stamp = 0;
    s->tl_free = NONE;
    for (v = 0; v < 2 * s->n; v++) {
        s->parent[v] = NONE;
        s->labfrom[v] = s->labto[v] = s->tree[v] = NONE;
        s->mark[v] = 0;
        if (v < s->n) {
            s->base[v] = s->first[v] = s->last[v] = s->top[v] = v;
            s->next_leaf[v] = NONE;
            s->tl_head[v] = NONE;
        }
    }
    s->nfree = 0;
    for (i = 2 * s->n - 1; i >= s->n; i--)
        s->free_ids[s->nfree++] = i;
    /* every exposed vertex that can still gain roots a tree */
    for (v = 0; v < s->n; v++)
        if (s->mate[v] == NONE && s->d0[v] > s->yfloor) {
            s->label[v] = LAB_S;
            if (tree_add(s, v, v))
                return CVM_E_NOMEM;
        }
    for (v = 0; v < s->n; v++)
        if (s->label[v] == LAB_S && become_s(s, v))
            return CVM_E_NOMEM;
    return CVM_OK;
}

static cvm_status run(solver *s)
{
    for (;;) {
        int64_t best = T_INF, id;
        int k, which = -1;
        cvm_status st = CVM_OK;
        for (k = 0; k < NQ; k++) {
            int64_t key = heap_peek(s, k);
            if (key < best) {
                best = key;
                which = k;
            }
        }
        if (which < 0)
            return CVM_OK;
        if (best < s->t)
            return cvm__error(s->ctx, CVM_E_INTERNAL, CVM_ENT_NONE, -1,
                              "matching: event %d at %lld before the clock %lld", which,
                              (long long)best, (long long)s->t);
        s->t = best;
        id = s->q[which].a[0].id;
        heap_pop(&s->q[which]);
        if (which == Q_ZERO) {
            cvm_index tree = s->tree[s->top[id]];
            augment_to_root(s, (cvm_index)id, NONE);
            st = dissolve(s, tree);
        } else if (which == Q_EXPAND) {
            st = expand(s, (cvm_index)id);
        } else {
            cvm_index a = s->ends[2 * id], b = s->ends[2 * id + 1];
            if (which == Q_GROW) {
                st = s->label[s->top[a]] == LAB_S ? grow(s, a, b) : grow(s, b, a);
            } else if (s->tree[s->top[a]] != s->tree[s->top[b]]) {
                cvm_index ta = s->tree[s->top[a]], tb = s->tree[s->top[b]];
                augment_to_root(s, a, b);
                augment_to_root(s, b, a);
                st = dissolve(s, ta);
                if (!st)
                    st = dissolve(s, tb);
            } else {
                st = make_blossom(s, a, b);
            }
        }
        if (st)
            return st;
    }
}

static cvm_status export_duals(solver *s, cvm__match_duals *d)
{
    cvm_index v, b;
    size_t nb = 0, nv = 0;
    memset(d, 0, sizeof *d);
    for (b = s->n; b < 2 * s->n; b++)
        if (s->alive[b]) {
            cvm_index x;
            nb++;
            for (x = s->first[b];; x = s->next_leaf[x]) {
                nv++;
                if (x == s->last[b])
                    break;
            }
        }
    d->y = cvm__malloc(s->ctx, ((size_t)s->n + 1) * sizeof *d->y);
    d->z = cvm__malloc(s->ctx, (nb + 1) * sizeof *d->z);
    d->off = cvm__malloc(s->ctx, (nb + 1) * sizeof *d->off);
    d->verts = cvm__malloc(s->ctx, (nv + 1) * sizeof *d->verts);
    if (!d->y || !d->z || !d->off || !d->verts) {
        cvm__match_duals_free(s->ctx, d);
        return CVM_E_NOMEM;
    }
    d->shift = -s->yfloor / 2;
    for (v = 0; v < s->n; v++)
        d->y[v] = dual(s, v) - s->yfloor;
    d->off[0] = 0;
    for (b = s->n; b < 2 * s->n; b++)
        if (s->alive[b]) {
            cvm_index x;
            size_t o = d->off[d->nblossom];
            d->z[d->nblossom] = dual(s, b);
            for (x = s->first[b];; x = s->next_leaf[x]) {
                d->verts[o++] = x;
                if (x == s->last[b])
                    break;
            }
            d->off[++d->nblossom] = o;
        }
    return CVM_OK;
}

static cvm_status check_input(cvm__ctx *ctx, size_t n, size_t m, const cvm_index *ends,
                              const int64_t *w)
{
    size_t e;
    if (n > (size_t)INT32_MAX / 2 || m > (size_t)INT32_MAX / 2)
        return cvm__error(ctx, CVM_E_TOO_LARGE, CVM_ENT_NONE, -1,
                          "matching: %zu vertices and %zu edges exceed INT32_MAX / 2", n, m);
    if (m > 0 && (!ends || !w))
        return cvm__error(ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1, "matching: ends or w is NULL");
    for (e = 0; e < m; e++) {
        cvm_index a = ends[2 * e], b = ends[2 * e + 1];
        if (a < 0 || b < 0 || (size_t)a >= n || (size_t)b >= n)
            return cvm__error(ctx, CVM_E_INPUT_INDEX, CVM_ENT_NONE, (int64_t)e,
                              "matching: edge %zu (%ld-%ld) names a vertex outside [0, %zu)", e,
                              (long)a, (long)b, n);
        if (a == b)
            return cvm__error(ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_NONE, (int64_t)e,
                              "matching: edge %zu joins vertex %ld to itself", e, (long)a);
        if (w[e] < 0 || w[e] > CVM__MATCH_WEIGHT_MAX)
            return cvm__error(ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, (int64_t)e,
                              "matching: edge %zu has weight %lld outside [0, 2^40]", e,
                              (long long)w[e]);
    }
    return CVM_OK;
}

/* The matched edge at v: the heaviest edge to its mate (tight among parallels). */
static void export_mates(const solver *s, cvm_index *mate_out)
{
    cvm_index v;
    for (v = 0; v < s->n; v++) {
        size_t k;
        mate_out[v] = NONE;
        if (s->mate[v] == NONE)
            continue;
        for (k = s->adj_off[v]; k < s->adj_off[v + 1]; k++) {
            cvm_index e = s->adj[k];
            if (other_end(s, (size_t)e, v) == s->mate[v] &&
                (mate_out[v] == NONE || s->w[e] > s->w[mate_out[v]]))
                mate_out[v] = e;
        }
    }
}

cvm_status cvm__matching_solve(cvm_index *mate_out, cvm__match_duals *duals_out, cvm__ctx *ctx,
                               size_t n, size_t m, const cvm_index *ends, const int64_t *w,
                               cvm__match_mode mode)
{
    solver s;
    cvm_status st;
    if (!mate_out && n > 0)
        return cvm__error(ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1, "matching: mate_out is NULL");
    if (mode != CVM__MATCH_MAX_WEIGHT && mode != CVM__MATCH_MAX_CARDINALITY)
        return cvm__error(ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, (int64_t)mode,
                          "matching: unknown mode %d", (int)mode);
    st = check_input(ctx, n, m, ends, w);
    if (st)
        return st;
    memset(&s, 0, sizeof s);
    s.ctx = ctx;
    s.n = (cvm_index)n;
    s.m = m;
    s.ends = ends;
    s.w = w;
    if (mode == CVM__MATCH_MAX_CARDINALITY) {
        /* maximum weight for the weights w + C, C above any weight a smaller
         * matching could make up: run as yfloor = -2C (4C/2 in solver units) */
        int64_t maxw = 0, c;
        size_t e;
        for (e = 0; e < m; e++)
            maxw = w[e] > maxw ? w[e] : maxw;
        if (maxw > 0 && (int64_t)(n / 2 + 1) > ((int64_t)1 << 56) / maxw)
            return cvm__error(ctx, CVM_E_TOO_LARGE, CVM_ENT_NONE, -1,
                              "matching: %zu vertices times the largest weight %lld exceed 2^56",
                              n, (long long)maxw);
        c = (int64_t)(n / 2) * maxw + 1;
        s.yfloor = -2 * c;
    }
    st = solver_alloc(&s);
    if (!st)
        st = solver_init(&s);
    if (!st)
        st = run(&s);
    if (!st) {
        export_mates(&s, mate_out);
        if (duals_out)
            st = export_duals(&s, duals_out);
    }
    solver_free(&s);
    return st == CVM_E_NOMEM ? cvm__nomem(ctx) : st;
}

void cvm__match_duals_free(cvm__ctx *ctx, cvm__match_duals *d)
{
    cvm__free(ctx, d->y);
    cvm__free(ctx, d->z);
    cvm__free(ctx, d->off);
    cvm__free(ctx, d->verts);
    memset(d, 0, sizeof *d);
}

int64_t cvm__match_scale(double q)
{
    double r = q * 1048576.0;
    if (!(r > 0))
        return 0;
    if (r > (double)CVM__MATCH_WEIGHT_MAX)
        return CVM__MATCH_WEIGHT_MAX;
    return (int64_t)(r + 0.5);
}

/* Edges by decreasing weight, ties by index. */
static void sort_edges(cvm_index *a, cvm_index *tmp, size_t n, const int64_t *w)
{
    size_t h, i, j, k;
    if (n < 2)
        return;
    h = n / 2;
    sort_edges(a, tmp, h, w);
    sort_edges(a + h, tmp, n - h, w);
    for (i = 0, j = h, k = 0; k < n; k++) {
        if (j >= n || (i < h && (w[a[i]] > w[a[j]] || (w[a[i]] == w[a[j]] && a[i] < a[j]))))
            tmp[k] = a[i++];
        else
            tmp[k] = a[j++];
    }
    memcpy(a, tmp, n * sizeof *a);
}

cvm_status cvm__matching_greedy(cvm_index *mate_out, cvm__ctx *ctx, size_t n, size_t m,
                                const cvm_index *ends, const int64_t *w)
{
    cvm_index *order, *tmp;
    size_t e;
    cvm_status st = check_input(ctx, n, m, ends, w);
    if (st)
        return st;
    if (!mate_out && n > 0)
        return cvm__error(ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1, "matching: mate_out is NULL");
    order = cvm__malloc(ctx, (m + 1) * sizeof *order);
    tmp = cvm__malloc(ctx, (m + 1) * sizeof *tmp);
    if (!order || !tmp) {
        cvm__free(ctx, order);
        cvm__free(ctx, tmp);
        return cvm__nomem(ctx);
    }
    for (e = 0; e < m; e++)
        order[e] = (cvm_index)e;
    sort_edges(order, tmp, m, w);
    for (e = 0; e < n; e++)
        mate_out[e] = NONE;
    for (e = 0; e < m; e++) {
        cvm_index k = order[e], a = ends[2 * k], b = ends[2 * k + 1];
        if (mate_out[a] == NONE && mate_out[b] == NONE)
            mate_out[a] = mate_out[b] = k;
    }
    cvm__free(ctx, order);
    cvm__free(ctx, tmp);
    return CVM_OK;
}
