/*
 * matching_events.c - the event queue and tree bookkeeping of the weighted
 * matching (matching.c, matching_blossom.c): pushing events on the lazy
 * heaps, listing the nodes of each tree, and the events a node makes relevant
 * when it becomes S or free, or when its tree dissolves.
 */
#include "quad/matching_solver.h"

/* ---- lazy heaps ---- */

cvm_status cvm__mt_heap_push(solver *s, int k, int64_t key, int64_t id)
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

/* ---- tree lists: the top-level nodes labelled in each tree ---- */

cvm_status cvm__mt_tree_add(solver *s, cvm_index tree, cvm_index node)
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
cvm_status cvm__mt_become_s(solver *s, cvm_index x)
{
    cvm_index v;
    for (v = s->first[x];; v = s->next_leaf[v]) {
        size_t k;
        if (cvm__mt_heap_push(s, Q_ZERO, s->t + dual(s, v) - s->yfloor, v))
            return CVM_E_NOMEM;
        for (k = s->adj_off[v]; k < s->adj_off[v + 1]; k++) {
            size_t e = (size_t)s->adj[k];
            cvm_index o = top_of(s, other_end(s, e, v));
            int64_t sl;
            if (o == top_of(s, v) || s->label[o] == LAB_T)
                continue;
            sl = slack(s, e);
            if (s->label[o] == LAB_S) {
                if (sl & 1)
                    return cvm__error(s->ctx, CVM_E_INTERNAL, CVM_ENT_NONE, (int64_t)e,
                                      "matching: odd slack on S-S edge %zu", e);
                if (cvm__mt_heap_push(s, Q_SS, s->t + sl / 2, (int64_t)e))
                    return CVM_E_NOMEM;
            } else if (cvm__mt_heap_push(s, Q_GROW, s->t + sl, (int64_t)e)) {
                return CVM_E_NOMEM;
            }
        }
        if (v == s->last[x])
            break;
    }
    return CVM_OK;
}

/* The vertices of x became free: their edges to S nodes may grow trees. */
cvm_status cvm__mt_become_free(solver *s, cvm_index x)
{
    cvm_index v;
    for (v = s->first[x];; v = s->next_leaf[v]) {
        size_t k;
        for (k = s->adj_off[v]; k < s->adj_off[v + 1]; k++) {
            size_t e = (size_t)s->adj[k];
            if (s->label[top_of(s, other_end(s, e, v))] == LAB_S &&
                cvm__mt_heap_push(s, Q_GROW, s->t + slack(s, e), (int64_t)e))
                return CVM_E_NOMEM;
        }
        if (v == s->last[x])
            break;
    }
    return CVM_OK;
}

/* Unlabel every node of tree (after an augmentation or a flip through it). */
cvm_status cvm__mt_dissolve(solver *s, cvm_index tree)
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
            cvm__mt_become_free(s, s->tl[i].node))
            return CVM_E_NOMEM;
    if (last != NONE) {
        s->tl[last].next = s->tl_free;
        s->tl_free = s->tl_head[tree];
    }
    s->tl_head[tree] = NONE;
    return CVM_OK;
}
