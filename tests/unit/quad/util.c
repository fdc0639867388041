/* util.c - helpers of the quad tests: random and triangulation graphs, the optimality certificate. */
#include <stdlib.h>
#include <string.h>

#include "quad/quad_tests.h"

static uint64_t splitmix(uint64_t *s)
{
    uint64_t z = (*s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

void qtest_graph_free(qtest_graph *g)
{
    free(g->ends);
    free(g->w);
    memset(g, 0, sizeof *g);
}

void qtest_random_graph(qtest_graph *g, uint64_t k)
{
    static const int64_t wmax_of[4] = {1, 10, 1000, 1000000};
    uint64_t s = k * 1000003u + 7u;
    size_t n, i, j, cap;
    uint64_t pct;
    int64_t wmax;
    n = 2 + (size_t)(splitmix(&s) % 39);
    pct = 2 + splitmix(&s) % 50;
    wmax = wmax_of[splitmix(&s) % 4];
    cap = n * (n - 1) / 2 + 1;
    g->n = n;
    g->m = 0;
    g->ends = malloc(2 * cap * sizeof *g->ends);
    g->w = malloc(cap * sizeof *g->w);
    ck_assert(g->ends && g->w);
    for (i = 0; i < n; i++)
        for (j = i + 1; j < n; j++)
            if (splitmix(&s) % 100 < pct) {
                g->ends[2 * g->m] = (cvm_index)i;
                g->ends[2 * g->m + 1] = (cvm_index)j;
                g->w[g->m++] = (int64_t)(splitmix(&s) % (uint64_t)(wmax + 1));
            }
}

void qtest_delaunay_dual(qtest_graph *g, size_t npts, uint64_t seed, int64_t wmax)
{
    double *xy = malloc(2 * npts * sizeof *xy);
    cvm_mesh *m = NULL;
    cvm_index *nb;
    size_t nt, i;
    uint64_t s = seed;
    ck_assert_ptr_nonnull(xy);
    for (i = 0; i < 2 * npts; i++)
        xy[i] = (double)(splitmix(&s) >> 11) * (1.0 / 9007199254740992.0);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, npts, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    nb = malloc(3 * nt * sizeof *nb);
    g->ends = malloc(3 * nt * sizeof *g->ends);
    g->w = malloc(3 * nt * sizeof *g->w);
    ck_assert(nb && g->ends && g->w);
    ck_assert_int_eq(cvm_mesh_copy_neighbors(nb, 3 * nt, m), CVM_OK);
    g->n = nt;
    g->m = 0;
    for (i = 0; i < 3 * nt; i++)
        if (nb[i] > (cvm_index)(i / 3)) {
            g->ends[2 * g->m] = (cvm_index)(i / 3);
            g->ends[2 * g->m + 1] = nb[i];
            g->w[g->m++] = (int64_t)(splitmix(&s) % (uint64_t)(wmax + 1));
        }
    free(nb);
    free(xy);
    cvm_mesh_free(m);
}

void qtest_assert_matching(const qtest_graph *g, const cvm_index *mate, int64_t *weight,
                           size_t *card)
{
    size_t v;
    *weight = 0;
    *card = 0;
    for (v = 0; v < g->n; v++) {
        cvm_index e = mate[v], o;
        if (e < 0)
            continue;
        ck_assert_uint_lt((size_t)e, g->m);
        ck_assert(g->ends[2 * e] == (cvm_index)v || g->ends[2 * e + 1] == (cvm_index)v);
        o = g->ends[2 * e] == (cvm_index)v ? g->ends[2 * e + 1] : g->ends[2 * e];
        ck_assert_int_eq(mate[o], e);
        if ((cvm_index)v < o) {
            *weight += g->w[e];
            (*card)++;
        }
    }
}

static const cvm__match_duals *sort_duals;

static int by_size(const void *a, const void *b)
{
    size_t x = *(const size_t *)a, y = *(const size_t *)b;
    size_t sx = sort_duals->off[x + 1] - sort_duals->off[x];
    size_t sy = sort_duals->off[y + 1] - sort_duals->off[y];
    return sx != sy ? (sx < sy ? -1 : 1) : (x < y ? -1 : x > y);
}

/* The blossoms, smallest first, must each be a union of whole earlier
 * (maximal) blossoms and loose vertices; returns the nesting depth. */
static int assert_laminar(size_t n, const cvm__match_duals *d, size_t *owner, size_t *depth_of)
{
    size_t *order = malloc((d->nblossom + 1) * sizeof *order), *seen, i, k, v;
    int deepest = 0;
    seen = calloc(d->nblossom + 1, sizeof *seen);
    ck_assert(order && seen);
    for (i = 0; i < d->nblossom; i++)
        order[i] = i;
    sort_duals = d;
    qsort(order, d->nblossom, sizeof *order, by_size);
    for (v = 0; v < n; v++)
        owner[v] = (size_t)-1;
    for (i = 0; i < d->nblossom; i++) {
        size_t b = order[i], total = 0;
        depth_of[b] = 1;
        for (k = d->off[b]; k < d->off[b + 1]; k++) {
            size_t p = owner[d->verts[k]];
            if (p == (size_t)-1) {
                total++;
            } else if (seen[p] != i + 1) {
                seen[p] = i + 1;
                total += d->off[p + 1] - d->off[p];
                if (depth_of[p] + 1 > depth_of[b])
                    depth_of[b] = depth_of[p] + 1;
            }
        }
        ck_assert_uint_eq(total, d->off[b + 1] - d->off[b]);
        for (k = d->off[b]; k < d->off[b + 1]; k++)
            owner[d->verts[k]] = b;
        if ((int)depth_of[b] > deepest)
            deepest = (int)depth_of[b];
    }
    free(order);
    free(seen);
    return deepest;
}

int qtest_assert_certificate(const qtest_graph *g, const cvm_index *mate,
                             const cvm__match_duals *d)
{
    int64_t *slack = malloc((g->m + 1) * sizeof *slack);
    size_t *owner = malloc((g->n + 1) * sizeof *owner), *depth_of = NULL;
    unsigned char *in = calloc(g->n + 1, 1);
    size_t e, b, k, v, *start, *adj, *pos;
    int deepest = 0;
    ck_assert(slack && owner && in);
    /* vertex -> edges */
    start = calloc(g->n + 2, sizeof *start);
    adj = malloc((2 * g->m + 1) * sizeof *adj);
    pos = malloc((g->n + 1) * sizeof *pos);
    depth_of = calloc(d->nblossom + 1, sizeof *depth_of);
    ck_assert(start && adj && pos && depth_of);
    for (e = 0; e < g->m; e++) {
        start[g->ends[2 * e] + 1]++;
        start[g->ends[2 * e + 1] + 1]++;
    }
    for (v = 0; v < g->n; v++)
        start[v + 1] += start[v];
    memcpy(pos, start, g->n * sizeof *pos);
    for (e = 0; e < g->m; e++) {
        adj[pos[g->ends[2 * e]]++] = e;
        adj[pos[g->ends[2 * e + 1]]++] = e;
    }
    for (e = 0; e < g->m; e++)
        slack[e] = d->y[g->ends[2 * e]] + d->y[g->ends[2 * e + 1]] - 4 * (g->w[e] + d->shift);
    for (b = 0; b < d->nblossom; b++) {
        size_t size = d->off[b + 1] - d->off[b], inside = 0;
        ck_assert_int_ge(d->z[b], 0);
        ck_assert_uint_eq(size % 2, 1);
        ck_assert_uint_ge(size, 3);
        for (k = d->off[b]; k < d->off[b + 1]; k++)
            in[d->verts[k]] = 1;
        for (k = d->off[b]; k < d->off[b + 1]; k++) {
            size_t j, u = (size_t)d->verts[k];
            for (j = start[u]; j < start[u + 1]; j++) {
                size_t f = adj[j];
                cvm_index o = g->ends[2 * f] == (cvm_index)u ? g->ends[2 * f + 1] : g->ends[2 * f];
                if (in[o] && (cvm_index)u < o) {
                    slack[f] += d->z[b];
                    inside += mate[u] == (cvm_index)f;
                }
            }
        }
        if (d->z[b] > 0)
            ck_assert_uint_eq(2 * inside + 1, size);
        for (k = d->off[b]; k < d->off[b + 1]; k++)
            in[d->verts[k]] = 0;
    }
    deepest = assert_laminar(g->n, d, owner, depth_of);
    for (e = 0; e < g->m; e++) {
        ck_assert_msg(slack[e] >= 0, "edge %zu has slack %lld", e, (long long)slack[e]);
        if (mate[g->ends[2 * e]] == (cvm_index)e)
            ck_assert_msg(slack[e] == 0, "matched edge %zu has slack %lld", e,
                          (long long)slack[e]);
    }
    for (v = 0; v < g->n; v++) {
        ck_assert_int_ge(d->y[v], 0);
        if (mate[v] < 0)
            ck_assert_msg(d->y[v] == 0, "exposed vertex %zu has y %lld", v, (long long)d->y[v]);
    }
    free(slack);
    free(owner);
    free(in);
    free(start);
    free(adj);
    free(pos);
    free(depth_of);
    return deepest;
}

void qtest_ctx(cvm__ctx *ctx, cvmtest_alloc *a)
{
    cvm__ctx_init_default(ctx);
    ctx->alloc_fn = cvmtest_malloc;
    ctx->realloc_fn = cvmtest_realloc;
    ctx->free_fn = cvmtest_free;
    ctx->payload = a;
}

void qtest_metric(cvm_sizing **s, cvm__metric *mt, cvm__ctx *ctx, const cvm__metric_builtin *b,
                  const double *corners, size_t nc)
{
    cvm__ctx_init_default(ctx);
    ck_assert_int_eq(cvm_sizing_create(s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_metric_fn(*s, cvm__metric_builtin_fn, 1, (void *)b), CVM_OK);
    mt->s = *s;
    mt->bnd = corners;
    mt->nbnd = nc;
}
