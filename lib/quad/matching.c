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
#include "quad/matching_solver.h"

/* ---- lazy heaps ---- */

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
static int64_t current_key(solver *s, int k, int64_t id)
{
    if (k == Q_ZERO) {
        cvm_index v = (cvm_index)id;
        return s->label[top_of(s, v)] == LAB_S ? s->t + dual(s, v) - s->yfloor : -1;
    }
    if (k == Q_EXPAND) {
        cvm_index b = (cvm_index)id;
        if (!s->alive[b] || s->parent[b] != NONE || s->label[b] != LAB_T)
            return -1;
        return s->t + dual(s, b) / 2;
    } else {
        size_t e = (size_t)id;
        cvm_index a = top_of(s, s->ends[2 * e]), b = top_of(s, s->ends[2 * e + 1]);
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

/* ---- set-up, warm start, main loop ---- */

static void solver_free(solver *s)
{
    int k;
    void **p[] = {(void **)&s->adj_off, (void **)&s->adj, (void **)&s->mate, (void **)&s->anc,
                  (void **)&s->ancg, (void **)&s->gen,
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
    cvm_index **ix[] = {&s->mate, &s->next_leaf, &s->tl_head, &s->free_ids,
                        &s->parent, &s->nxt, &s->prv, &s->lfrom, &s->lto, &s->base,
                        &s->base_child, &s->first, &s->last, &s->labfrom, &s->labto,
                        &s->tree, &s->mark, &s->work, &s->anc};
    for (i = 0; i < sizeof ix / sizeof ix[0]; i++)
        if (!(*ix[i] = cvm__malloc(s->ctx, (i < 4 ? n + 1 : n2) * sizeof(cvm_index))))
            return CVM_E_NOMEM;
    s->adj_off = cvm__calloc(s->ctx, n + 2, sizeof *s->adj_off);
    s->adj = cvm__malloc(s->ctx, (2 * s->m + 1) * sizeof *s->adj);
    s->label = cvm__calloc(s->ctx, n2, 1);
    s->alive = cvm__calloc(s->ctx, n2, 1);
    s->d0 = cvm__calloc(s->ctx, n2, sizeof *s->d0);
    s->dt = cvm__calloc(s->ctx, n2, sizeof *s->dt);
    s->ancg = cvm__calloc(s->ctx, n2, sizeof *s->ancg);
    s->gen = cvm__calloc(s->ctx, n2, sizeof *s->gen);
    if (!s->adj_off || !s->adj || !s->label || !s->alive || !s->d0 || !s->dt || !s->ancg ||
        !s->gen)
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
        s->anc[v] = NONE;
        s->labfrom[v] = s->labto[v] = s->tree[v] = NONE;
        s->mark[v] = 0;
        if (v < s->n) {
            s->base[v] = s->first[v] = s->last[v] = v;
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
            if (cvm__mt_tree_add(s, v, v))
                return CVM_E_NOMEM;
        }
    for (v = 0; v < s->n; v++)
        if (s->label[v] == LAB_S && cvm__mt_become_s(s, v))
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
            cvm_index tree = s->tree[top_of(s, id)];
            cvm__mt_augment_to_root(s, (cvm_index)id, NONE);
            st = cvm__mt_dissolve(s, tree);
        } else if (which == Q_EXPAND) {
            st = cvm__mt_expand(s, (cvm_index)id);
        } else {
            cvm_index a = s->ends[2 * id], b = s->ends[2 * id + 1];
            if (which == Q_GROW) {
                st = s->label[top_of(s, a)] == LAB_S ? cvm__mt_grow(s, a, b) : cvm__mt_grow(s, b, a);
            } else if (s->tree[top_of(s, a)] != s->tree[top_of(s, b)]) {
                cvm_index ta = s->tree[top_of(s, a)], tb = s->tree[top_of(s, b)];
                cvm__mt_augment_to_root(s, a, b);
                cvm__mt_augment_to_root(s, b, a);
                st = cvm__mt_dissolve(s, ta);
                if (!st)
                    st = cvm__mt_dissolve(s, tb);
            } else {
                st = cvm__mt_make_blossom(s, a, b);
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
