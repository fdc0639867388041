/* parallel3.c - insertion of a BRIO round by several threads at once, each inserting the points of its Hilbert-key partition into tetrahedra it alone owns. */
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "delaunay3/conflict3.h"
#include "delaunay3/delaunay3_internal.h"

#define PAR3_MAX_THREADS 64
#define PAR3_DEAD_CAP 2048      /* a larger cavity waits for the serial tail */
#define PAR3_BF_CAP 4096
#define PAR3_HASH_CAP 16384     /* >= 4 PAR3_BF_CAP, a power of two */
#define PAR3_FREE_EXTRA 4096    /* room for slots freed by shrinking cavities */
#define PAR3_PASSES 6
#define PAR3_START_TRIES 64
#define PAR3_HMASK ((UINT64_C(1) << CVM__T3_HBITS) - 1)

/* One thread's share of a pass: a copy of the store struct (same arrays, own
 * workspace, free list and run of fresh slots). */
typedef struct cvm__t3_worker {
    cvm__tet3 v;
    size_t fresh_end; /* v.nslot .. fresh_end: fresh slots not yet used */
    size_t free_lim;  /* the most free slots it may hold (what the store took room for) */
    size_t todo;      /* points of its partition in this pass */
    size_t done;      /* of which inserted */
    int32_t start;    /* an owned finite tetrahedron to walk from, or -1 */
} cvm__t3_worker;

/* What a parallel build keeps between rounds. */
typedef struct cvm__t3_par {
    int nt;
    uint8_t *part;   /* per internal id: the partition of its key in this pass */
    int32_t *pend;   /* the pending points of the round, in key order */
    cvm__t3_worker *wk;
    uint64_t cut[PAR3_MAX_THREADS]; /* ascending: partition j holds keys in [cut[j], cut[j+1]) */
} cvm__t3_par;

int cvm__tet3_build_threads(const cvm__tet3 *T)
{
    int n = T->threads;
#ifdef _OPENMP
    if (n == 0)
        n = omp_get_max_threads();
#endif
    return n < 1 ? 1 : n > PAR3_MAX_THREADS ? PAR3_MAX_THREADS : n;
}

/* ---- duplicates, before any insertion ---- */

static uint64_t par3_coord_bits(double c)
{
    uint64_t u;
    c += 0.0; /* -0 and +0 are the same coordinate */
    memcpy(&u, &c, sizeof u);
    return u;
}

/* splitmix64's finaliser: every input bit reaches every output bit, which
 * coordinates need (small integers and short binary fractions have their
 * low mantissa bits all zero). */
static uint64_t par3_mix(uint64_t z)
{
    z ^= z >> 30;
    z *= UINT64_C(0xBF58476D1CE4E5B9);
    z ^= z >> 27;
    z *= UINT64_C(0x94D049BB133111EB);
    return z ^ (z >> 31);
}

static size_t par3_coord_hash(const double *x, size_t mask)
{
    uint64_t h = par3_mix(par3_coord_bits(x[2]));
    h = par3_mix(h ^ par3_coord_bits(x[1]));
    h = par3_mix(h ^ par3_coord_bits(x[0]));
    return (size_t)h & mask;
}

cvm_status cvm__tet3_merge_duplicates(cvm__tet3 *T)
{
    size_t cap = 1024, mask, i;
    int32_t *tab;
    while (cap < 2 * T->np)
        cap *= 2;
    mask = cap - 1;
    tab = cvm__malloc(T->ctx, cap * sizeof *tab);
    if (!tab)
        return CVM_E_NOMEM;
    memset(tab, 0xff, cap * sizeof *tab);
    for (i = 0; i < T->np; i++) {
        const double *x = T->pt[i].x;
        size_t at;
        if (i + 16 < T->np) /* the table is far larger than the caches */
            CVM__T3_PREFETCH(tab + par3_coord_hash(T->pt[i + 16].x, mask));
        for (at = par3_coord_hash(x, mask);; at = (at + 1) & mask) {
            const double *y;
            if (tab[at] < 0) {
                tab[at] = (int32_t)i;
                break;
            }
            y = T->pt[tab[at]].x;
            /* weighted: the same point with another weight is no duplicate (the
             * power test decides between them); it takes the next free slot */
            if (y[0] == x[0] && y[1] == x[1] && y[2] == x[2]
                && (!T->w || T->w[tab[at]] == T->w[i])) {
                T->fate[i] = CVM__T3_DUPLICATE;
                T->merged[i] = tab[at];
                break;
            }
        }
    }
    cvm__free(T->ctx, tab);
    return CVM_OK;
}

/* ---- one thread's insertions ---- */

static inline int par3_owned(const int32_t *v, const uint8_t *part, uint8_t t)
{
    return part[v[0]] == t && part[v[1]] == t && part[v[2]] == t
           && (v[3] == CVM__T3_GHOST || part[v[3]] == t);
}

/* The walk of insert3.c's locate(), which gives up (-1) on leaving the owned tetrahedra. */
static int32_t par3_locate(cvm__tet3 *V, int32_t p, const uint8_t *part, uint8_t me)
{
    const double *pp = V->pt[p].x;
    int32_t t = V->last, came = -1;
    uint64_t r = V->walk;
    for (;;) {
        const int32_t *v = V->tt + 8 * (size_t)t;
        const double *q[4];
        int i, f0;
        if (v[3] == CVM__T3_GHOST)
            break;
        q[0] = V->pt[v[0]].x, q[1] = V->pt[v[1]].x, q[2] = V->pt[v[2]].x, q[3] = V->pt[v[3]].x;
        r ^= r << 13, r ^= r >> 7, r ^= r << 17;
        f0 = (int)(r >> 62);
        for (i = 0; i < 4; i++) {
            int f = (f0 + i) & 3;
            int32_t slot = 4 * t + f;
            const double *keep;
            double o;
            if (slot == came)
                continue;
            keep = q[f], q[f] = pp;
            o = cvm__t3_orient(V, q[0], q[1], q[2], q[3]);
            q[f] = keep;
            if (o < 0.0) {
                came = CVM__T3_TN(V, slot);
                t = came >> 2;
                if (!cvm__t3_owned_across(V->tt, came, part, me)) {
                    V->walk = r;
                    return -1;
                }
                goto next;
            }
        }
        break;
    next:;
    }
    V->walk = r;
    return t;
}

/* Insert p if everything it touches is owned and fits the thread's slots: 1, else 0. */
static int par3_insert(cvm__t3_worker *W, int32_t p, const uint8_t *part, uint8_t me)
{
    cvm__tet3 *V = &W->v;
    int32_t t = par3_locate(V, p, part, me);
    const int32_t *v;
    size_t nd, nb, grow, shrink;
    if (t < 0)
        return 0;
    v = V->tt + 8 * (size_t)t;
    if (v[3] != CVM__T3_GHOST) {
        const double *pp = V->pt[p].x;
        int k;
        for (k = 0; k < 4; k++) { /* (duplicates were merged before: only a guard) */
            const double *q = V->pt[v[k]].x;
            if (q[0] == pp[0] && q[1] == pp[1] && q[2] == pp[2]
                && (!V->w || V->w[v[k]] == V->w[p])) {
                V->merged[p] = v[k];
                V->fate[p] = CVM__T3_DUPLICATE;
                return 1;
            }
        }
        /* weighted: no conflict with the owned tetrahedron holding p means an
         * empty power cell now, so in the end too (cells only shrink) */
        if (V->w && !cvm__t3_finite_conflict(V, v, p)) {
            V->fate[p] = CVM__T3_REDUNDANT;
            return 1;
        }
    }
    /* (the serial search grows its arrays; this one gives up) */
    if (!(V->w || V->small_int ? cvm__t3_dig(V, t, p, 0, part, me)
                               : cvm__t3_dig(V, t, p, 1, part, me)))
        return 0;
    nd = V->ndead, nb = V->nbf;
    grow = nb > nd ? nb - nd : 0;
    shrink = nd > nb ? nd - nb : 0;
    if (grow > V->nfree + (W->fresh_end - V->nslot) || V->nfree + shrink > W->free_lim
        || 4 * nb > V->hashcap) {
        cvm__t3_unmark_cavity(V, nd, nb);
        V->ndead = V->nbf = 0;
        return 0;
    }
    /* a vertex losing its cell has every tetrahedron around it in the (owned)
     * cavity, so it is of this partition: its fate and stamps are this thread's */
    if (V->w)
        cvm__tet3_mark_vanished(V, p);
    cvm__tet3_fill_around(V);
    V->fate[p] = CVM__T3_VERTEX;
    V->vtet[p] = V->last;
    return 1;
}

static void par3_run_worker(cvm__t3_par *P, int t, size_t m)
{
    cvm__t3_worker *W = &P->wk[t];
    uint8_t me = (uint8_t)t;
    size_t i;
    if (W->start < 0)
        return;
    W->v.last = W->start;
    for (i = 0; i < m; i++) {
        int32_t p = P->pend[i];
        if (P->part[p] == me)
            W->done += (size_t)par3_insert(W, p, P->part, me);
    }
}

/* ---- the passes of a round ---- */

static uint8_t par3_part_of(const cvm__t3_par *P, uint64_t key)
{
    uint64_t h = key & PAR3_HMASK;
    int j = P->nt - 1;
    while (j > 0 && h < P->cut[j])
        j--;
    return (uint8_t)(h < P->cut[0] ? P->nt - 1 : j);
}

/* Is slot s live with x among its vertices (a vertex's recorded tetrahedron
 * may have been dug out and its slot reused since)? */
static int par3_holds(const cvm__tet3 *T, int32_t s, int32_t x)
{
    const int32_t *v;
    if (s < 0 || (size_t)s >= T->nslot)
        return 0;
    v = T->tt + 8 * (size_t)s;
    return v[0] != CVM__T3_DEAD && (v[0] == x || v[1] == x || v[2] == x || v[3] == x);
}

/* An owned finite tetrahedron near point p (of partition me): one made with
 * a vertex of the previous round [plo, lo) close to p along the curve, else
 * the first in slot order. -1 when the partition owns none. Runs before the
 * threads start (it reads slots any of them may write). */
static int32_t par3_find_start(const cvm__tet3 *T, const cvm__t3_par *P, size_t plo, size_t lo,
                               int32_t p, uint8_t me)
{
    uint64_t h = T->key[p] & PAR3_HMASK;
    size_t a = plo, b = lo, d, s;
    while (a < b) {
        size_t mid = a + (b - a) / 2;
        if ((T->key[mid] & PAR3_HMASK) < h)
            a = mid + 1;
        else
            b = mid;
    }
    for (d = 0; d < 2 * PAR3_START_TRIES; d++) {
        size_t j = d & 1 ? a + d / 2 : a - 1 - d / 2;
        int32_t x, c;
        if ((d & 1) ? j >= lo : a < plo + 1 + d / 2)
            continue;
        x = (int32_t)j;
        c = T->vtet[x];
        if (T->fate[x] == CVM__T3_VERTEX && P->part[x] == me && par3_holds(T, c, x)
            && T->tt[8 * (size_t)c + 3] != CVM__T3_GHOST
            && par3_owned(T->tt + 8 * (size_t)c, P->part, me))
            return c;
    }
    for (s = 0; s < T->nslot; s++) {
        const int32_t *v = T->tt + 8 * s;
        if (v[0] != CVM__T3_DEAD && v[3] != CVM__T3_GHOST && par3_owned(v, P->part, me))
            return (int32_t)s;
    }
    return -1;
}

/* Cut the m pending points into nt runs, offset by a fraction of a run that
 * differs from pass to pass (the points left are those near the last cuts),
 * and give every vertex so far the partition of its key. */
static void par3_cut(const cvm__tet3 *T, cvm__t3_par *P, size_t m, size_t hi, int pass)
{
    static const uint8_t eighths[PAR3_PASSES] = { 0, 4, 2, 6, 1, 5 };
    size_t off = m * eighths[pass] / (8 * (size_t)P->nt);
    long v;
    int j, k;
    for (j = 0; j < P->nt; j++)
        P->cut[j] = T->key[P->pend[(off + (size_t)j * m / (size_t)P->nt) % m]] & PAR3_HMASK;
    for (j = 1; j < P->nt; j++) /* ascending (the offset may wrap one around) */
        for (k = j; k > 0 && P->cut[k - 1] > P->cut[k]; k--) {
            uint64_t x = P->cut[k];
            P->cut[k] = P->cut[k - 1], P->cut[k - 1] = x;
        }
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(P->nt) if (hi > 65536)
#endif
    for (v = 0; v < (long)hi; v++)
        P->part[v] = par3_part_of(P, T->key[v]);
}

/* Allocate the workers' fixed workspace once. */
static cvm_status par3_workers_alloc(cvm__tet3 *T, cvm__t3_par *P)
{
    int t;
    P->wk = cvm__calloc(T->ctx, (size_t)P->nt, sizeof *P->wk);
    if (!P->wk)
        return CVM_E_NOMEM;
    for (t = 0; t < P->nt; t++) {
        cvm__tet3 *V = &P->wk[t].v;
        V->dead = cvm__malloc(T->ctx, PAR3_DEAD_CAP * sizeof *V->dead);
        V->bf = cvm__malloc(T->ctx, PAR3_BF_CAP * sizeof *V->bf);
        V->hash = cvm__calloc(T->ctx, PAR3_HASH_CAP, sizeof *V->hash);
        V->etab = cvm__calloc(T->ctx, CVM__T3_ETAB * CVM__T3_ETAB, sizeof *V->etab);
        if (!V->dead || !V->bf || !V->hash || !V->etab)
            return CVM_E_NOMEM;
        V->deadcap = PAR3_DEAD_CAP, V->bfcap = PAR3_BF_CAP, V->hashcap = PAR3_HASH_CAP;
    }
    return CVM_OK;
}

static void par3_workers_free(cvm__tet3 *T, cvm__t3_par *P)
{
    int t;
    if (!P->wk)
        return;
    for (t = 0; t < P->nt; t++) {
        cvm__tet3 *V = &P->wk[t].v;
        cvm__free(T->ctx, V->dead);
        cvm__free(T->ctx, V->bf);
        cvm__free(T->ctx, V->hash);
        cvm__free(T->ctx, V->etab);
        cvm__free(T->ctx, V->freeslot);
    }
    cvm__free(T->ctx, P->wk);
}

/* Hand out slots and workspace for a pass: each worker a copy of the store
 * with its own free slots (an even share of the free list) and a run of fresh
 * slots (about 7 tetrahedra per point, the same margin as the serial reserve). */
static cvm_status par3_pass_setup(cvm__tet3 *T, cvm__t3_par *P, size_t m, int pass)
{
    size_t total = 0, at, fat = 0, i;
    int t;
    cvm_status s;
    for (t = 0; t < P->nt; t++)
        P->wk[t].todo = 0;
    for (i = 0; i < m; i++)
        P->wk[P->part[P->pend[i]]].todo++;
    for (t = 0; t < P->nt; t++)
        total += 7 * P->wk[t].todo + 1024;
    if ((s = cvm__tet3_reserve(T, T->nfree + total)) != CVM_OK
        || (s = cvm__grow(T->ctx, (void **)&T->freeslot, &T->freecap,
                          T->nfree + total + (size_t)P->nt * PAR3_FREE_EXTRA, sizeof(int32_t)))
               != CVM_OK)
        return s;
    /* a thread may run through one stamp per point; the ids of earlier stamps
     * must stay told apart, so wrap here rather than inside a thread */
    if (T->lstamp + m + 2 >= (UINT32_C(1) << 25)) {
        for (i = 0; i < T->np; i++)
            T->pt[i].loc = 0;
        T->lstamp = 0;
    }
    /* weighted: the same for the stamps of vanished vertices; every worker
     * starts from T->vstamp (each stamps only vertices of its own partition,
     * and the next pass starts above them all) */
    if (T->w && (uint64_t)T->vstamp + m + 2 > UINT32_MAX) {
        memset(T->vseen, 0, T->np * sizeof *T->vseen);
        memset(T->vkeep, 0, T->np * sizeof *T->vkeep);
        T->vstamp = 0;
    }
    at = T->nslot;
    for (t = 0; t < P->nt; t++) {
        cvm__t3_worker *W = &P->wk[t];
        cvm__tet3 keep = W->v;
        size_t share = T->nfree / (size_t)P->nt + (t == P->nt - 1 ? T->nfree % (size_t)P->nt : 0);
        if ((s = cvm__grow(T->ctx, (void **)&keep.freeslot, &keep.freecap, share + PAR3_FREE_EXTRA,
                           sizeof(int32_t)))
            != CVM_OK) {
            W->v.freeslot = keep.freeslot, W->v.freecap = keep.freecap;
            return s;
        }
        W->v = *T;
        W->v.dead = keep.dead, W->v.deadcap = keep.deadcap, W->v.ndead = 0;
        W->v.bf = keep.bf, W->v.bfcap = keep.bfcap, W->v.nbf = 0;
        W->v.hash = keep.hash, W->v.hashcap = keep.hashcap, W->v.stamp = keep.stamp;
        W->v.etab = keep.etab;
        W->v.freeslot = keep.freeslot, W->v.freecap = keep.freecap;
        W->v.stack = NULL, W->v.stackcap = 0, W->v.excl = NULL, W->v.exclcap = 0;
        W->v.n_big_cavities = 0;
        memcpy(W->v.freeslot, T->freeslot + fat, share * sizeof *T->freeslot);
        W->v.nfree = share;
        W->free_lim = share + PAR3_FREE_EXTRA;
        fat += share;
        W->v.nslot = at;
        at += 7 * W->todo + 1024;
        W->fresh_end = at;
        W->v.walk = (T->walk ^ (UINT64_C(0x9E3779B97F4A7C15) * (uint64_t)(1 + t + P->nt * pass)))
                    | 1u;
        W->done = 0;
    }
    return CVM_OK;
}

/* After a pass: the unused fresh slots and every free list back to the store. */
static size_t par3_pass_gather(cvm__tet3 *T, cvm__t3_par *P)
{
    size_t done = 0, end = T->nslot, s;
    int t;
    T->nfree = 0;
    for (t = 0; t < P->nt; t++) {
        cvm__t3_worker *W = &P->wk[t];
        memcpy(T->freeslot + T->nfree, W->v.freeslot, W->v.nfree * sizeof *T->freeslot);
        T->nfree += W->v.nfree;
        for (s = W->v.nslot; s < W->fresh_end; s++) {
            T->tt[8 * s] = CVM__T3_DEAD;
            T->tmark[s] = 0;
            T->freeslot[T->nfree++] = (int32_t)s;
        }
        end = W->fresh_end;
        T->n_big_cavities += W->v.n_big_cavities;
        T->lstamp = W->v.lstamp > T->lstamp ? W->v.lstamp : T->lstamp;
        T->vstamp = W->v.vstamp > T->vstamp ? W->v.vstamp : T->vstamp;
        if (W->start >= 0 && done == 0)
            T->last = W->v.last; /* finite and live: only this worker could change it */
        done += W->done;
    }
    T->nslot = end;
    return done;
}

/* The round [lo, hi) (previous round from plo): parallel passes while they
 * insert enough, then the rest in order. */
static cvm_status par3_round(cvm__tet3 *T, cvm__t3_par *P, size_t plo, size_t lo, size_t hi)
{
    int pass, t;
    size_t i;
    cvm_status s;
    for (pass = 0; pass < PAR3_PASSES; pass++) {
        size_t m = 0, done;
        for (i = lo; i < hi; i++)
            if (T->fate[i] == CVM__T3_PENDING)
                P->pend[m++] = (int32_t)i;
        /* a pass costs a sweep over the vertices so far: worth it for enough points */
        if (m < 64 || (pass > 0 && (m < T->par_min / 16 || m < hi / 256)))
            break;
        par3_cut(T, P, m, hi, pass);
        if ((s = par3_pass_setup(T, P, m, pass)) != CVM_OK)
            return s;
        for (t = 0; t < P->nt; t++) {
            int32_t first = -1;
            for (i = 0; i < m && first < 0; i++)
                if (P->part[P->pend[i]] == (uint8_t)t)
                    first = P->pend[i];
            P->wk[t].start = first < 0 ? -1 : par3_find_start(T, P, plo, lo, first, (uint8_t)t);
        }
#ifdef _OPENMP
#pragma omp parallel for schedule(static, 1) num_threads(P->nt)
#endif
        for (t = 0; t < P->nt; t++)
            par3_run_worker(P, t, m);
        done = par3_pass_gather(T, P);
        T->n_par_done += done;
        if (done < m / 8)
            break;
    }
    for (i = lo, s = CVM_OK; i < hi && s == CVM_OK; i++)
        if (T->fate[i] == CVM__T3_PENDING)
            s = cvm__tet3_insert(T, (int32_t)i);
    return s;
}

cvm_status cvm__tet3_insert_rounds(cvm__tet3 *T)
{
    cvm__t3_par P;
    size_t lo = 0, plo = 0, hi;
    cvm_status s = CVM_OK;
    memset(&P, 0, sizeof P);
    P.nt = cvm__tet3_build_threads(T);
    P.part = cvm__malloc(T->ctx, T->np);
    P.pend = cvm__malloc(T->ctx, T->np * sizeof *P.pend);
    if (!P.part || !P.pend || par3_workers_alloc(T, &P) != CVM_OK)
        s = CVM_E_NOMEM;
    for (; lo < T->np && s == CVM_OK; plo = lo, lo = hi) {
        size_t i;
        uint64_t round = T->key[lo] >> CVM__T3_HBITS;
        for (hi = lo + 1; hi < T->np && (T->key[hi] >> CVM__T3_HBITS) == round; hi++)
            ;
        if (hi - lo >= T->par_min && P.nt > 1)
            s = par3_round(T, &P, plo, lo, hi);
        else
            for (i = lo; i < hi && s == CVM_OK; i++)
                if (T->fate[i] == CVM__T3_PENDING)
                    s = cvm__tet3_insert(T, (int32_t)i);
    }
    par3_workers_free(T, &P);
    cvm__free(T->ctx, P.part);
    cvm__free(T->ctx, P.pend);
    return s;
}
