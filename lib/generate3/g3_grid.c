/*
 * g3_grid.c - points in a uniform grid of cubic cells, hashed by cell
 * (open addressing), each cell a linked list of point ids: "is any point
 * within r of x" visits the cells within r. Only a yes/no leaves this file,
 * so the table's order never shows in any output.
 */
#include <math.h>

#include "generate3/generate3.h"

typedef struct cell_ent {
    uint64_t key; /* 0: empty */
    int32_t head;
} cell_ent;

struct cvm__g3_grid {
    cvm__ctx *ctx;
    double cell;
    cell_ent *tab;
    size_t cap, used; /* cap a power of two */
    int32_t *next;    /* per id: next id in its cell, or -1 */
    size_t next_cap;
};

#define OFFSET ((int64_t)1 << 20)

static uint64_t key_of(int64_t i, int64_t j, int64_t k)
{
    /* 21 bits per axis, never 0 */
    return ((uint64_t)((i + OFFSET) & 0x1fffff) << 42 | (uint64_t)((j + OFFSET) & 0x1fffff) << 21 |
            (uint64_t)((k + OFFSET) & 0x1fffff)) + 1;
}

static size_t hash_of(uint64_t key, size_t cap)
{
    key ^= key >> 31;
    key *= UINT64_C(0x9e3779b97f4a7c15);
    key ^= key >> 29;
    return (size_t)key & (cap - 1);
}

static int64_t coord(const cvm__g3_grid *g, double v)
{
    double t = floor(v / g->cell);
    if (t < (double)-OFFSET)
        return -OFFSET;
    if (t > (double)OFFSET)
        return OFFSET;
    return (int64_t)t;
}

cvm_status cvm__g3_grid_create(cvm__g3_grid **out, cvm__ctx *ctx, double cell)
{
    cvm__g3_grid *g = cvm__calloc(ctx, 1, sizeof *g);
    *out = NULL;
    if (!g)
        return cvm__nomem(ctx);
    g->ctx = ctx;
    g->cell = cell > 0 ? cell : 1;
    g->cap = 1024;
    if (!(g->tab = cvm__calloc(ctx, g->cap, sizeof *g->tab))) {
        cvm__free(ctx, g);
        return cvm__nomem(ctx);
    }
    *out = g;
    return CVM_OK;
}

void cvm__g3_grid_free(cvm__g3_grid *g)
{
    if (!g)
        return;
    cvm__free(g->ctx, g->tab);
    cvm__free(g->ctx, g->next);
    cvm__free(g->ctx, g);
}

static cell_ent *find(const cvm__g3_grid *g, uint64_t key)
{
    size_t h = hash_of(key, g->cap);
    while (g->tab[h].key && g->tab[h].key != key)
        h = (h + 1) & (g->cap - 1);
    return &g->tab[h];
}

static cvm_status grow(cvm__g3_grid *g)
{
    cell_ent *old = g->tab;
    size_t i, ocap = g->cap;
    cell_ent *t = cvm__calloc(g->ctx, 2 * ocap, sizeof *t);
    if (!t)
        return cvm__nomem(g->ctx);
    g->tab = t;
    g->cap = 2 * ocap;
    for (i = 0; i < ocap; i++)
        if (old[i].key)
            *find(g, old[i].key) = old[i];
    cvm__free(g->ctx, old);
    return CVM_OK;
}

cvm_status cvm__g3_grid_add(cvm__g3_grid *g, const double *xyz, int32_t id)
{
    const double *x = xyz + 3 * (size_t)id;
    cell_ent *e;
    uint64_t key;
    if ((size_t)id >= g->next_cap) {
        size_t cap = g->next_cap ? 2 * g->next_cap : 1024;
        int32_t *n;
        while (cap <= (size_t)id)
            cap *= 2;
        if (!(n = cvm__realloc(g->ctx, g->next, cap * sizeof *n)))
            return cvm__nomem(g->ctx);
        g->next = n;
        g->next_cap = cap;
    }
    if (2 * (g->used + 1) > g->cap && grow(g))
        return CVM_E_NOMEM;
    key = key_of(coord(g, x[0]), coord(g, x[1]), coord(g, x[2]));
    e = find(g, key);
    if (!e->key) {
        e->key = key;
        e->head = -1;
        g->used++;
    }
    g->next[id] = e->head;
    e->head = id;
    return CVM_OK;
}

int cvm__g3_grid_near(const cvm__g3_grid *g, const double *xyz, const double *x, double r)
{
    int64_t lo[3], hi[3], i, j, k;
    double r2 = r * r;
    int a;
    for (a = 0; a < 3; a++) {
        lo[a] = coord(g, x[a] - r);
        hi[a] = coord(g, x[a] + r);
    }
    for (i = lo[0]; i <= hi[0]; i++)
        for (j = lo[1]; j <= hi[1]; j++)
            for (k = lo[2]; k <= hi[2]; k++) {
                const cell_ent *e = find(g, key_of(i, j, k));
                int32_t id;
                if (!e->key)
                    continue;
                for (id = e->head; id >= 0; id = g->next[id]) {
                    const double *p = xyz + 3 * (size_t)id;
                    double dx = p[0] - x[0], dy = p[1] - x[1], dz = p[2] - x[2];
                    if (dx * dx + dy * dy + dz * dz < r2)
                        return 1;
                }
            }
    return 0;
}
