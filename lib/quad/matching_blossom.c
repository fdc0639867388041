/*
 * matching_blossom.c - the primal steps of the blossom solver (matching.c):
 * growing a tree, shrinking an odd cycle into a blossom, expanding a T
 * blossom whose dual reached zero, and augmenting through nested blossoms.
 */
#include "quad/matching_solver.h"

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
void cvm__mt_augment_to_root(solver *s, cvm_index v, cvm_index u)
{
    for (;;) {
        cvm_index b = top_of(s, v), tb, sv, tv;
        if (b >= s->n)
            augment_blossom(s, b, v);
        s->mate[v] = u;
        if (s->labfrom[b] == NONE)
            return;
        tb = top_of(s, s->labfrom[b]);
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

cvm_status cvm__mt_grow(solver *s, cvm_index v, cvm_index u)
{
    cvm_index tb = top_of(s, u), tree = s->tree[top_of(s, v)], x, sb;
    if (s->mate[s->base[tb]] == NONE) {
        /* a free exposed blossom has y = 0 at its base: augment into it */
        cvm__mt_augment_to_root(s, v, u);
        if (tb >= s->n)
            augment_blossom(s, tb, u);
        s->mate[u] = v;
        return cvm__mt_dissolve(s, tree);
    }
    set_label(s, tb, LAB_T);
    s->labfrom[tb] = v;
    s->labto[tb] = u;
    if (cvm__mt_tree_add(s, tree, tb))
        return CVM_E_NOMEM;
    if (tb >= s->n && cvm__mt_heap_push(s, Q_EXPAND, s->t + dual(s, tb) / 2, tb))
        return CVM_E_NOMEM;
    x = s->mate[s->base[tb]];
    sb = top_of(s, x);
    set_label(s, sb, LAB_S);
    s->labfrom[sb] = s->base[tb];
    s->labto[sb] = x;
    if (cvm__mt_tree_add(s, tree, sb))
        return CVM_E_NOMEM;
    return cvm__mt_become_s(s, sb);
}

/* The S node above S node x in its tree, or NONE at the root. */
static cvm_index s_parent(solver *s, cvm_index x)
{
    if (s->labfrom[x] == NONE)
        return NONE;
    return top_of(s, s->labfrom[top_of(s, s->labfrom[x])]);
}

/* Tight edge v-u between two S nodes of one tree: shrink the odd cycle they
 * close into a new S blossom. */
cvm_status cvm__mt_make_blossom(solver *s, cvm_index v, cvm_index u)
{
    cvm_index a = top_of(s, v), c = top_of(s, u), lca = NONE, b, i, k, pv = 0, *L = s->work;
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
    for (x = top_of(s, v); x != lca; x = s_parent(s, x))
        pv += 2;
    k = pv;
    for (x = top_of(s, v); x != lca; x = s_parent(s, x)) {
        L[k--] = x;
        L[k--] = top_of(s, s->labfrom[x]);
    }
    nc = pv + 1;
    for (x = top_of(s, u); x != lca; x = s_parent(s, x)) {
        L[nc++] = x;
        L[nc++] = top_of(s, s->labfrom[x]);
    }
    if (s->nfree == 0)
        return cvm__error(s->ctx, CVM_E_INTERNAL, CVM_ENT_NONE, -1, "matching: no blossom id left");
    b = s->free_ids[--s->nfree];
    s->gen[b]++; /* ancestor links to an earlier blossom of this id are stale */
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
    if (cvm__mt_tree_add(s, s->tree[lca], b))
        return CVM_E_NOMEM;
    for (i = 0; i < nc; i++) /* the former T children (labels below the top stay put) */
        if (s->label[L[i]] == LAB_T && cvm__mt_become_s(s, L[i]))
            return CVM_E_NOMEM;
    return CVM_OK;
}

static cvm_status label_child(solver *s, cvm_index c, int lab, cvm_index from, cvm_index to,
                              cvm_index tree)
{
    s->label[c] = (unsigned char)lab;
    s->labfrom[c] = from;
    s->labto[c] = to;
    if (cvm__mt_tree_add(s, tree, c))
        return CVM_E_NOMEM;
    if (lab == LAB_T && c >= s->n && cvm__mt_heap_push(s, Q_EXPAND, s->t + dual(s, c) / 2, c))
        return CVM_E_NOMEM;
    return CVM_OK;
}

/* T blossom b reached z = 0: its children become top-level; the even path
 * from the child it was entered by to its base child stays in the tree
 * (T, S, ..., T), the other children become free. */
cvm_status cvm__mt_expand(solver *s, cvm_index b)
{
    cvm_index c0 = s->base_child[b], ce = child_holding(s, b, s->labto[b]), x;
    int forward = (cycle_pos(s, b, ce) & 1) != 0;
    cvm_index tree = s->tree[b];
    flush_leaves(s, b);
    x = c0;
    do {
        s->parent[x] = NONE;
        s->label[x] = FREE;
        if (x >= s->n)
            s->dt[x] = s->t;
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
        if (s->label[x] == LAB_S && cvm__mt_become_s(s, x))
            return CVM_E_NOMEM;
        if (s->label[x] == FREE && cvm__mt_become_free(s, x))
            return CVM_E_NOMEM;
        x = s->nxt[x];
    } while (x != c0);
    return CVM_OK;
}

