/* tet3_store.c - the flat tetrahedral store: slots, free-slot reuse, workspace growth and face pairing around a new point. */
#include <string.h>

#include "delaunay3/delaunay3_internal.h"

void cvm__tet3_init(cvm__tet3 *T, cvm__ctx *ctx)
{
    memset(T, 0, sizeof *T);
    T->ctx = ctx;
    T->threads = 1;
    T->par_min = CVM__T3_PAR_MIN;
    T->last = -1;
    T->dup_first[0] = T->dup_first[1] = -1;
    T->redundant_first = -1;
}

void cvm__tet3_free(cvm__tet3 *T)
{
    cvm__ctx *ctx = T->ctx;
    size_t par_min;
    int threads;
    cvm__free(ctx, T->pt_block);
    cvm__free(ctx, T->w);
    cvm__free(ctx, T->orig);
    cvm__free(ctx, T->merged);
    cvm__free(ctx, T->outid);
    cvm__free(ctx, T->fate);
    cvm__free(ctx, T->tt_block);
    cvm__free(ctx, T->tmark);
    cvm__free(ctx, T->cface);
    cvm__free(ctx, T->sattr);
    cvm__free(ctx, T->freeslot);
    cvm__free(ctx, T->stack);
    cvm__free(ctx, T->dead);
    cvm__free(ctx, T->excl);
    cvm__free(ctx, T->bf);
    cvm__free(ctx, T->hash);
    cvm__free(ctx, T->etab);
    cvm__free(ctx, T->vseen);
    cvm__free(ctx, T->vkeep);
    cvm__free(ctx, T->key);
    cvm__free(ctx, T->vtet);
    threads = T->threads, par_min = T->par_min;
    cvm__tet3_init(T, ctx);
    T->threads = threads, T->par_min = par_min; /* settings, not contents */
}

/* Bytes from p to its next 64-byte boundary. */
static size_t to_line(const void *p)
{
    return (size_t)((64 - (uintptr_t)p % 64) % 64);
}

cvm_status cvm__tet3_alloc_points(cvm__tet3 *T, size_t cap)
{
    size_t bytes;
    unsigned char *p;
    if (!cvm__mul_ok(cap, sizeof *T->pt, &bytes) || bytes > SIZE_MAX - 64)
        return CVM_E_NOMEM;
    p = cvm__calloc(T->ctx, bytes + 64, 1);
    if (!p)
        return CVM_E_NOMEM;
    T->pt_block = p;
    T->pt = (cvm__t3_point *)(void *)(p + to_line(p));
    return CVM_OK;
}

/* Grow the two per-slot arrays together to ncap slots. tt lives at the first
 * 64-byte boundary of its block; when realloc moves the block to another
 * offset from a boundary, the slots are moved along. */
static cvm_status grow_slots(cvm__tet3 *T, size_t ncap)
{
    size_t bytes, off_old = T->tt ? (size_t)((unsigned char *)T->tt - (unsigned char *)T->tt_block) : 0;
    unsigned char *b;
    void *p;
    if (ncap > (size_t)INT32_MAX / 4 || !cvm__mul_ok(ncap, 8 * sizeof(int32_t), &bytes)
        || bytes > SIZE_MAX - 64)
        return CVM_E_NOMEM;
    b = cvm__realloc(T->ctx, T->tt_block, bytes + 64);
    if (!b)
        return CVM_E_NOMEM;
    if (T->tt && to_line(b) != off_old)
        memmove(b + to_line(b), b + off_old, T->cap * 8 * sizeof(int32_t));
    T->tt_block = b;
    T->tt = (int32_t *)(void *)(b + to_line(b));
    p = cvm__realloc(T->ctx, T->tmark, ncap);
    if (!p)
        return CVM_E_NOMEM;
    T->tmark = p;
    if (T->cface) {
        p = cvm__realloc(T->ctx, T->cface, ncap);
        if (!p)
            return CVM_E_NOMEM;
        T->cface = p;
    }
    if (T->sattr) {
        if (!cvm__mul_ok(ncap, sizeof(double), &bytes))
            return CVM_E_NOMEM;
        p = cvm__realloc(T->ctx, T->sattr, bytes);
        if (!p)
            return CVM_E_NOMEM;
        T->sattr = p;
    }
    /* all hold hold at least T->cap slots now; only then publish the new size */
    T->cap = ncap;
    return CVM_OK;
}

cvm_status cvm__tet3_reserve(cvm__tet3 *T, size_t need_new)
{
    size_t have = T->ndead + T->nfree + (T->cap - T->nslot), ncap;
    if (need_new <= have && T->tt)
        return CVM_OK;
    ncap = T->cap < 64 ? 64 : T->cap;
    while (ncap - T->nslot + T->ndead + T->nfree < need_new)
        ncap += ncap / 2;
    return grow_slots(T, ncap);
}

/* A slot for a new tetrahedron: a dead one of this cavity, else a free one,
 * else a fresh one (cvm__tet3_reserve made room). */
int32_t cvm__tet3_take_slot(cvm__tet3 *T)
{
    int32_t t;
    if (T->ndead > 0)
        t = T->dead[--T->ndead];
    else if (T->nfree > 0)
        t = T->freeslot[--T->nfree];
    else
        t = (int32_t)T->nslot++;
    T->tmark[t] = 0;
    return t;
}

/* Free list capacity is reserved ahead (cvm__tet3_reserve_hash), so this
 * never allocates. */
void cvm__tet3_release_slot(cvm__tet3 *T, int32_t t)
{
    T->tt[8 * (size_t)t] = CVM__T3_DEAD;
    T->tmark[t] = 0;
    T->freeslot[T->nfree++] = t;
}

cvm_status cvm__tet3_reserve_hash(cvm__tet3 *T, size_t nfaces)
{
    size_t need = 4 * nfaces, ncap;
    cvm_status s;
    s = cvm__grow(T->ctx, (void **)&T->freeslot, &T->freecap, T->nfree + T->ndead, sizeof(int32_t));
    if (s != CVM_OK)
        return s;
    if (need <= T->hashcap)
        return CVM_OK;
    ncap = T->hashcap < 256 ? 256 : T->hashcap;
    while (ncap < need)
        ncap *= 2;
    cvm__free(T->ctx, T->hash);
    T->hash = cvm__calloc(T->ctx, ncap, sizeof *T->hash);
    T->hashcap = 0;
    if (!T->hash)
        return CVM_E_NOMEM;
    T->hashcap = ncap;
    T->stamp = 0;
    return CVM_OK;
}

static uint64_t edge_key(int32_t a, int32_t b)
{
    uint32_t x = (uint32_t)a, y = (uint32_t)b;
    return x < y ? ((uint64_t)x << 32) | y : ((uint64_t)y << 32) | x;
}

/* The boundary of a tetrahedron (0 1 2 3) is the sum of its faces f with sign
 * (-1)^f: face 0 = (1 2 3), 1 = (2 0 3), 2 = (0 1 3), 3 = (1 0 2). The new
 * tetrahedra around a point are positively oriented (ghosts included), so the
 * cavity boundary is a closed surface on which every edge appears once in each
 * direction. cyc[f] = (q0, q1, q2): the three positions other than f in the
 * order that makes the edges uniform: the edge of side face q0 (opposite q0,
 * through the apex at f) on the boundary face f is q1 -> q2 as directed in
 * face f, that of q1 is q2 -> q0 and that of q2 is q0 -> q1. */
static const int8_t cyc[4][3] = { { 1, 2, 3 }, { 0, 3, 2 }, { 0, 1, 3 }, { 0, 2, 1 } };

/* A new stamp for the local ids of link_small / cvm__tet3_fill_around. */
static uint32_t next_lstamp(cvm__tet3 *T)
{
    if (++T->lstamp >= (UINT32_C(1) << 25)) { /* wrapped: forget every old id */
        size_t v;
        for (v = 0; v < T->np; v++)
            T->pt[v].loc = 0;
        T->lstamp = 1;
    }
    return T->lstamp;
}

/* The first pass of the edge table for one new tetrahedron: local ids of its
 * face vertices (the ghost is 0; *nv is the next free id), then each side
 * face filed under its edge. Returns 0 when the ids ran out (nothing filed). */
static inline int file_sides(cvm__t3_point *pt, int32_t *etab, cvm__t3_bface *b, uint32_t stamp,
                             uint32_t *nv)
{
    const int8_t *q = cyc[b->f];
    int32_t slot = 4 * b->tet;
    uint32_t l[3], n = *nv, st = stamp << 7;
    int j;
    for (j = 0; j < 3; j++) {
        int32_t x = b->v[q[j]];
        uint32_t id = 0;
        if (x >= 0) { /* not the ghost (local id 0) */
            uint32_t mine = pt[x].loc ^ st; /* the id when below 128: stamped this time */
            uint32_t fresh = mine > 127u;
            id = fresh ? n : mine;
            pt[x].loc = st | id;
            n += fresh;
        }
        l[j] = id;
    }
    *nv = n;
    if (n > CVM__T3_ETAB)
        return 0;
    etab[l[1] * CVM__T3_ETAB + l[2]] = slot + q[0];
    etab[l[2] * CVM__T3_ETAB + l[0]] = slot + q[1];
    etab[l[0] * CVM__T3_ETAB + l[1]] = slot + q[2];
    b->lid[0] = (uint8_t)l[0], b->lid[1] = (uint8_t)l[1], b->lid[2] = (uint8_t)l[2];
    return 1;
}

/* The second pass: each side face reads the face filed under its reversed edge. */
static void read_sides(cvm__tet3 *T)
{
    const int32_t *etab = T->etab;
    size_t i;
    for (i = 0; i < T->nbf; i++) {
        const cvm__t3_bface *b = &T->bf[i];
        const int8_t *q = cyc[b->f];
        int32_t *nb = T->tt + 8 * (size_t)b->tet + 4;
        uint32_t l0 = b->lid[0], l1 = b->lid[1], l2 = b->lid[2];
        int32_t n0 = etab[l2 * CVM__T3_ETAB + l1], n1 = etab[l0 * CVM__T3_ETAB + l2];
        int32_t n2 = etab[l1 * CVM__T3_ETAB + l0];
        nb[q[0]] = n0, nb[q[1]] = n1, nb[q[2]] = n2;
    }
}

/* Pairing through a hash table of undirected edges (any cavity size). */
static void link_hash(cvm__tet3 *T);

/* The usual cavity: at most CVM__T3_ETAB - 1 vertices on its boundary. Each
 * gets a local id (the ghost 0), a directed edge indexes a small table
 * directly: the first pass files each side face under its edge, the second
 * reads the face filed under the reversed edge (no branch on which came
 * first). Returns 0 (nothing linked) when the boundary has too many vertices. */
static int link_small(cvm__tet3 *T)
{
    uint32_t stamp = next_lstamp(T), nv = 1;
    size_t i;
    for (i = 0; i < T->nbf; i++)
        if (!file_sides(T->pt, T->etab, &T->bf[i], stamp, &nv))
            return 0;
    read_sides(T);
    return 1;
}

void cvm__tet3_fill_around(cvm__tet3 *T)
{
    /* local copies: the byte stores of the marks would make every field reload */
    size_t i, nb = T->nbf, nd = T->ndead, nreuse = nd < nb ? nd : nb;
    size_t nfree = T->nfree, nslot = T->nslot;
    int32_t *tt = T->tt, *etab = T->etab, last = T->last;
    const int32_t *dead = T->dead, *freeslot = T->freeslot;
    cvm__t3_point *pt = T->pt;
    cvm__t3_bface *bf = T->bf;
    uint8_t *tmark = T->tmark;
    uint32_t stamp = next_lstamp(T), nv = 1;
    int small = etab != NULL;
    for (i = 0; i < nb; i++) {
        cvm__t3_bface *b = &bf[i];
        int32_t nt, *v, out = b->out, f = b->f;
        if (i < nreuse) /* the slots of the cavity first, last dug first */
            nt = dead[nd - 1 - i];
        else if (nfree > 0)
            nt = freeslot[--nfree];
        else
            nt = (int32_t)nslot++;
        v = tt + 8 * (size_t)nt;
        memcpy(v, b->v, sizeof b->v);
        v[4 + f] = out;
        tt[(size_t)out + ((size_t)out & ~(size_t)3) + 4] = 4 * nt + f;
        tmark[nt] = 0;
        if (tmark[out >> 2]) /* a tetrahedron another thread may also border stays unwritten */
            tmark[out >> 2] = 0;
        b->tet = nt;
        last = v[3] != CVM__T3_GHOST ? nt : last;
        if (small)
            small = file_sides(pt, etab, b, stamp, &nv);
    }
    T->last = last;
    T->nfree = nfree, T->nslot = nslot;
    for (i = nreuse; i < nd; i++)
        cvm__tet3_release_slot(T, T->dead[nd - 1 - i]);
    T->ndead = 0;
    if (small)
        read_sides(T);
    else
        link_hash(T);
}

void cvm__tet3_link_around(cvm__tet3 *T)
{
    if (!T->etab || !link_small(T))
        link_hash(T);
}

static void link_hash(cvm__tet3 *T)
{
    size_t i, mask = T->hashcap - 1;
    uint32_t stamp;
    T->n_big_cavities++;
    if (++T->stamp == 0) { /* wrapped: forget every old entry */
        memset(T->hash, 0, T->hashcap * sizeof *T->hash);
        T->stamp = 1;
    }
    stamp = T->stamp;
    for (i = 0; i < T->nbf; i++) {
        const cvm__t3_bface *b = &T->bf[i];
        int k;
        for (k = 0; k < 4; k++) {
            int32_t x = -3, y = -3, slot;
            uint64_t key;
            size_t h;
            int j;
            if (k == b->f)
                continue;
            for (j = 0; j < 4; j++)
                if (j != k && j != b->f) {
                    if (x == -3)
                        x = b->v[j];
                    else
                        y = b->v[j];
                }
            key = edge_key(x, y);
            slot = 4 * b->tet + k;
            h = (size_t)((key * UINT64_C(0x9E3779B97F4A7C15)) >> 40) & mask;
            for (;;) {
                cvm__t3_hent *e = &T->hash[h];
                if (e->stamp != stamp) {
                    e->stamp = stamp, e->key = key, e->slot = slot;
                    break;
                }
                if (e->key == key) {
                    CVM__T3_TN(T, slot) = e->slot;
                    CVM__T3_TN(T, e->slot) = slot;
                    e->key = ~(uint64_t)0; /* paired: no third face has this edge */
                    break;
                }
                h = (h + 1) & mask;
            }
        }
    }
}
