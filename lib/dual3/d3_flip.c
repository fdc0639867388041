/*
 * d3_flip.c - the mutable connectivity of the 3D power-dual optimiser
 * (dual3.h): a copy of the tetrahedra with their neighbours and constrained
 * faces, the vertex stars found by walking it, exact 2-3, 3-2 and 4-4 flips
 * of faces that are not locally regular, and the undo log that takes a
 * rejected move back. Every flip is decided by exact predicates: the face is not
 * locally regular (perturbed power test), it and every other face the flip
 * removes are unconstrained and between tetrahedra of one region, and the new
 * tetrahedra are positively oriented (orient3d) and fill the old ones' union.
 * A flip never removes a vertex (each old corner is a corner of a new
 * tetrahedron) nor a constrained face, so the surface and every power cell
 * stay; a vertex whose cell would vanish leaves a face no flip can repair,
 * and its move is undone.
 */
#include <string.h>

#include "dual3/d3_internal.h"
#include "geom/geom_internal.h"

void cvm__d3_topo_free(cvm__ctx *ctx, cvm__d3_work *K)
{
    cvm__free(ctx, K->tet);
    cvm__free(ctx, K->nbr);
    cvm__free(ctx, K->cface);
    cvm__free(ctx, K->attr);
    cvm__free(ctx, K->dead);
    cvm__free(ctx, K->mark);
    cvm__free(ctx, K->vt);
    cvm__free(ctx, K->deg);
    cvm__free(ctx, K->star);
    cvm__free(ctx, K->star0);
    cvm__free(ctx, K->queue);
    cvm__free(ctx, K->log);
    cvm__free(ctx, K->remap);
    cvm__free(ctx, K->out);
    cvm__free(ctx, K->bnd);
    K->tet = K->nbr = K->vt = K->deg = K->star = K->star0 = K->queue = K->remap = NULL;
    K->cface = K->dead = K->out = K->bnd = NULL;
    K->attr = NULL;
    K->mark = NULL;
    K->log = NULL;
}

cvm_status cvm__d3_topo_init(cvm__ctx *ctx, cvm__d3_work *K, const cvm__d3_mesh *M)
{
    /* room for growth: flips add a tetrahedron (2-3) or take one away (3-2); a full
       array is compacted, and with no room left a move that needs flips is refused */
    size_t cap = M->ntet + M->ntet / 2 + 4 * CVM__D3_MAX_FLIPS + 64, t, i;
    K->cap = cap;
    K->tet = cvm__malloc(ctx, 4 * cap * sizeof *K->tet);
    K->nbr = cvm__malloc(ctx, 4 * cap * sizeof *K->nbr);
    K->cface = cvm__malloc(ctx, 4 * cap);
    K->attr = M->attr ? cvm__malloc(ctx, cap * sizeof *K->attr) : NULL;
    K->dead = cvm__calloc(ctx, cap, 1);
    K->mark = cvm__calloc(ctx, cap, sizeof *K->mark);
    K->vt = cvm__malloc(ctx, (M->nv + 1) * sizeof *K->vt);
    K->deg = cvm__calloc(ctx, M->nv + 1, sizeof *K->deg);
    K->star = cvm__malloc(ctx, CVM__D3_MAX_STAR * sizeof *K->star);
    K->star0 = cvm__malloc(ctx, CVM__D3_MAX_STAR * sizeof *K->star0);
    K->queue = cvm__malloc(ctx, CVM__D3_QUEUE * sizeof *K->queue);
    K->log = cvm__malloc(ctx, CVM__D3_LOG * sizeof *K->log);
    K->remap = cvm__malloc(ctx, cap * sizeof *K->remap);
    K->out = cvm__calloc(ctx, cap, 1);
    K->bnd = cvm__calloc(ctx, cap, 1);
    if (!K->tet || !K->nbr || !K->cface || (M->attr && !K->attr) || !K->dead || !K->mark ||
        !K->vt || !K->deg || !K->star || !K->star0 || !K->queue || !K->log || !K->remap ||
        !K->out || !K->bnd) {
        cvm__d3_topo_free(ctx, K);
        return cvm__nomem(ctx);
    }
    memcpy(K->tet, M->tet, 4 * M->ntet * sizeof *K->tet);
    memcpy(K->nbr, M->nbr, 4 * M->ntet * sizeof *K->nbr);
    memcpy(K->cface, M->cface, 4 * M->ntet);
    if (M->attr)
        memcpy(K->attr, M->attr, M->ntet * sizeof *K->attr);
    K->ntet = M->ntet;
    for (i = 0; i < M->nv; i++)
        K->vt[i] = -1;
    for (t = 0; t < M->ntet; t++)
        for (i = 0; i < 4; i++) {
            int32_t q = M->tet[4 * t + i];
            if (K->vt[q] < 0)
                K->vt[q] = (int32_t)t;
            K->deg[q]++;
        }
    K->W = *M;
    K->W.tet = K->tet;
    K->W.nbr = K->nbr;
    K->W.cface = K->cface;
    K->W.attr = K->attr;
    K->M = &K->W;
    return CVM_OK;
}

static void d3f_set_log(cvm__d3_work *K, int kind, int32_t *arr, int32_t idx, int32_t val)
{
    if (K->logging && K->nlog < CVM__D3_LOG) {
        K->log[K->nlog].kind = kind;
        K->log[K->nlog].idx = idx;
        K->log[K->nlog].old = arr[idx];
        K->nlog++;
    }
    arr[idx] = val;
}

static void d3f_set_dead(cvm__d3_work *K, int32_t t)
{
    if (K->logging && K->nlog < CVM__D3_LOG) {
        K->log[K->nlog].kind = 1;
        K->log[K->nlog].idx = t;
        K->log[K->nlog].old = K->dead[t];
        K->nlog++;
    }
    K->dead[t] = 1;
}

void cvm__d3_undo_all(cvm__d3_work *K, size_t ntet0)
{
    while (K->nlog) {
        const cvm__d3_undo *u = &K->log[--K->nlog];
        switch (u->kind) {
        case 0: K->nbr[u->idx] = u->old; break;
        case 1: K->dead[u->idx] = (uint8_t)u->old; break;
        case 2: K->vt[u->idx] = u->old; break;
        default: K->deg[u->idx] = u->old; break;
        }
    }
    K->ntet = ntet0;
    K->W.ntet = ntet0;
}

static uint32_t d3f_next_stamp(cvm__d3_work *K)
{
    if (++K->stamp == 0) { /* wrapped: forget every old mark */
        memset(K->mark, 0, K->cap * sizeof *K->mark);
        K->stamp = 1;
    }
    return K->stamp;
}

int cvm__d3_gather_star(cvm__d3_work *K, int32_t v)
{
    uint32_t st;
    size_t head = 0, n = 0, i;
    int32_t t0 = K->vt[v];
    K->nstar = 0;
    if (t0 < 0)
        return -1;
    st = d3f_next_stamp(K);
    K->star[n++] = t0;
    K->mark[t0] = st;
    while (head < n) {
        int32_t t = K->star[head++];
        int f;
        for (f = 0; f < 4; f++) {
            int32_t nb = K->nbr[4 * (size_t)t + (size_t)f];
            /* through the faces at v (those opposite another corner) */
            if (K->tet[4 * (size_t)t + (size_t)f] == v || nb < 0 || K->mark[nb >> 2] == st)
                continue;
            if (n == CVM__D3_MAX_STAR)
                return -1;
            K->mark[nb >> 2] = st;
            K->star[n++] = nb >> 2;
        }
    }
    if ((int32_t)n != K->deg[v]) /* a star in pieces (a pinched surface): not moved */
        return -1;
    for (i = 1; i < n; i++) { /* insertion sort: the visiting order of the fixed version */
        int32_t x = K->star[i];
        size_t j = i;
        while (j > 0 && K->star[j - 1] > x) {
            K->star[j] = K->star[j - 1];
            j--;
        }
        K->star[j] = x;
    }
    K->nstar = n;
    return 0;
}

void cvm__d3_compact(cvm__d3_work *K)
{
    size_t t, k = 0, i;
    for (t = 0; t < K->ntet; t++)
        K->remap[t] = K->dead[t] ? -1 : (int32_t)k++;
    for (t = 0; t < K->ntet; t++) {
        size_t n = (size_t)K->remap[t];
        if (K->dead[t])
            continue;
        for (i = 0; i < 4; i++) {
            int32_t nb = K->nbr[4 * t + i];
            K->tet[4 * n + i] = K->tet[4 * t + i];
            K->nbr[4 * n + i] = nb < 0 ? nb : 4 * K->remap[nb >> 2] + (nb & 3);
            K->cface[4 * n + i] = K->cface[4 * t + i];
        }
        if (K->attr)
            K->attr[n] = K->attr[t];
        K->out[n] = K->out[t];
        K->bnd[n] = K->bnd[t];
        K->dead[n] = 0;
        K->mark[n] = 0;
    }
    for (i = 0; i < K->W.nv; i++)
        if (K->vt[i] >= 0)
            K->vt[i] = K->remap[K->vt[i]];
    for (t = k; t < K->ntet; t++) {
        K->dead[t] = 0;
        K->mark[t] = 0;
    }
    K->ntet = k;
    K->W.ntet = k;
}

/* 1 when room is left for one move's flips (compacting when needed). */
static int d3f_room(cvm__d3_work *K)
{
    if (K->ntet + 4 * CVM__D3_MAX_FLIPS <= K->cap)
        return 1;
    cvm__d3_compact(K);
    return K->ntet + 4 * CVM__D3_MAX_FLIPS <= K->cap;
}

static void d3f_sort3(int32_t *v)
{
    int32_t t;
    if (v[0] > v[1]) t = v[0], v[0] = v[1], v[1] = t;
    if (v[1] > v[2]) t = v[1], v[1] = v[2], v[2] = t;
    if (v[0] > v[1]) t = v[0], v[0] = v[1], v[1] = t;
}

/* The corners of face f of the tetrahedron with corners c, sorted. */
static void d3f_face_key(const int32_t *c, int f, int32_t k[3])
{
    int i, j = 0;
    for (i = 0; i < 4; i++)
        if (i != f)
            k[j++] = c[i];
    d3f_sort3(k);
}

/* Replace the nk tetrahedra kill[] by the nn positively oriented tetrahedra nt[],
 * which fill the same polyhedron: append them, link their faces to each other and to
 * the old ones' outer neighbours (constrained flags inherited), mark the old dead. */
static void d3f_replace(cvm__d3_work *K, const int32_t *kill, int nk, int32_t nt[][4], int nn)
{
    size_t base = K->ntet;
    int j, f, j2, f2, i, q;
    for (j = 0; j < nn; j++) {
        size_t n = base + (size_t)j;
        memcpy(K->tet + 4 * n, nt[j], 4 * sizeof *K->tet);
        for (f = 0; f < 4; f++) {
            K->nbr[4 * n + (size_t)f] = -2;
            K->cface[4 * n + (size_t)f] = 0;
        }
        if (K->attr)
            K->attr[n] = K->attr[kill[0]];
        K->dead[n] = 0;
        K->mark[n] = 0;
        K->out[n] = 0;
        K->bnd[n] = 0;
    }
    K->ntet = base + (size_t)nn;
    K->W.ntet = K->ntet;
    for (j = 0; j < nn; j++)
        for (f = 0; f < 4; f++) {
            size_t slot = 4 * (base + (size_t)j) + (size_t)f;
            int32_t key[3], k2[3];
            int done = 0;
            if (K->nbr[slot] != -2)
                continue;
            d3f_face_key(nt[j], f, key);
            for (j2 = j + 1; j2 < nn && !done; j2++)
                for (f2 = 0; f2 < 4 && !done; f2++) {
                    d3f_face_key(nt[j2], f2, k2);
                    if (memcmp(key, k2, sizeof key) == 0) {
                        size_t s2 = 4 * (base + (size_t)j2) + (size_t)f2;
                        K->nbr[slot] = (int32_t)s2;
                        K->nbr[s2] = (int32_t)slot;
                        done = 1;
                    }
                }
            for (i = 0; i < nk && !done; i++)
                for (f2 = 0; f2 < 4 && !done; f2++) {
                    size_t os = 4 * (size_t)kill[i] + (size_t)f2;
                    int32_t nb = K->nbr[os];
                    d3f_face_key(K->tet + 4 * (size_t)kill[i], f2, k2);
                    if (memcmp(key, k2, sizeof key) != 0)
                        continue;
                    K->nbr[slot] = nb;
                    K->cface[slot] = K->cface[os];
                    if (nb >= 0)
                        d3f_set_log(K, 0, K->nbr, nb, (int32_t)slot);
                    else
                        K->bnd[base + (size_t)j] = 1;
                    done = 1;
                }
        }
    for (i = 0; i < nk; i++) {
        d3f_set_dead(K, kill[i]);
        for (q = 0; q < 4; q++) {
            int32_t c = K->tet[4 * (size_t)kill[i] + (size_t)q];
            d3f_set_log(K, 3, K->deg, c, K->deg[c] - 1);
        }
    }
    for (j = 0; j < nn; j++)
        for (q = 0; q < 4; q++) {
            int32_t c = nt[j][q];
            d3f_set_log(K, 3, K->deg, c, K->deg[c] + 1);
            if (K->vt[c] != (int32_t)base + j)
                d3f_set_log(K, 2, K->vt, c, (int32_t)base + j);
        }
}

static int d3f_same_region(const cvm__d3_work *K, int32_t a, int32_t b)
{
    return !K->attr || K->attr[a] == K->attr[b];
}

static int d3f_corner_of(const int32_t *c, int32_t v)
{
    int i;
    for (i = 0; i < 4; i++)
        if (c[i] == v)
            return i;
    return -1;
}

/* The positively oriented order of corners c (one swap when negative); 0 when flat. */
static int d3f_orient_fix(const double *X, int32_t c[4])
{
    double o = cvm__orient3d(X + 3 * (size_t)c[0], X + 3 * (size_t)c[1], X + 3 * (size_t)c[2],
                             X + 3 * (size_t)c[3]);
    if (o < 0) {
        int32_t tmp = c[0];
        c[0] = c[1], c[1] = tmp;
    }
    return o != 0;
}

/* The 4-4 flip of edge pq, whose tetrahedra are t = (x p q d), u = (x p q e) and, on
 * the other side of the plane p q d e (which holds d, e, p, q exactly), (p q d y) and
 * (p q e y): the segment de crosses pq inside both (the caller's orient3d tests), so
 * the four tetrahedra x d e p, x d e q, y d e p, y d e q fill the same octahedron.
 * The number of new tetrahedra (4) or 0. */
static int d3f_flip44(cvm__d3_work *K, int32_t t, int32_t u, int32_t x, int32_t p, int32_t q,
                  int32_t d, int32_t e)
{
    const double *X = K->W.xyz;
    int32_t s3, s4, y, kill[4], nn[4][4], apex[2];
    int ft = d3f_corner_of(K->tet + 4 * (size_t)t, x), fu = d3f_corner_of(K->tet + 4 * (size_t)u, x), f3,
        i, j;
    s3 = K->nbr[4 * (size_t)t + (size_t)ft]; /* across p q d: (p q d y) */
    s4 = K->nbr[4 * (size_t)u + (size_t)fu]; /* across p q e: (p q e y) */
    if (s3 < 0 || s4 < 0 || K->cface[4 * (size_t)t + (size_t)ft] ||
        K->cface[4 * (size_t)u + (size_t)fu])
        return 0;
    y = K->tet[s3];
    if (K->tet[s4] != y || (f3 = d3f_corner_of(K->tet + 4 * (size_t)(s3 >> 2), d)) < 0)
        return 0;
    /* (p q d y) and (p q e y) must share the face p q y */
    if ((K->nbr[4 * (size_t)(s3 >> 2) + (size_t)f3] >> 2) != (s4 >> 2) ||
        K->cface[4 * (size_t)(s3 >> 2) + (size_t)f3] || !d3f_same_region(K, t, s3 >> 2) ||
        !d3f_same_region(K, t, s4 >> 2))
        return 0;
    apex[0] = x, apex[1] = y;
    for (i = 0; i < 2; i++)
        for (j = 0; j < 2; j++) {
            int32_t *c = nn[2 * i + j];
            c[0] = apex[i], c[1] = d, c[2] = e, c[3] = j ? q : p;
            if (!d3f_orient_fix(X, c))
                return 0;
        }
    kill[0] = t, kill[1] = u, kill[2] = s3 >> 2, kill[3] = s4 >> 2;
    d3f_replace(K, kill, 4, nn, 4);
    return 4;
}

/* Flip the face f of t (not locally regular, checked by the caller) when a 2-3 or
 * a 3-2 flip can remove it; the number of new tetrahedra (the last slots), 0 when
 * not flipped. */
static int d3f_try_flip(cvm__d3_work *K, int32_t t, int f)
{
    const double *X = K->W.xyz;
    int32_t nb = K->nbr[4 * (size_t)t + (size_t)f], u, d, e, abc[3], tmp, nt[3][4];
    double o[3];
    int i, j = 0, neg = -1, nneg = 0, zero = -1, nzero = 0, g;
    if (nb < 0 || K->cface[4 * (size_t)t + (size_t)f] ||
        (K->logging && K->nlog + 64 > CVM__D3_LOG))
        return 0;
    u = nb >> 2;
    g = nb & 3;
    if (!d3f_same_region(K, t, u))
        return 0;
    d = K->tet[4 * (size_t)t + (size_t)f];
    e = K->tet[4 * (size_t)u + (size_t)g];
    for (i = 0; i < 4; i++)
        if (i != f)
            abc[j++] = K->tet[4 * (size_t)t + (size_t)i];
    if ((3 - f) & 1) /* (a, b, c, d) an even permutation of t's corners: positive */
        tmp = abc[0], abc[0] = abc[1], abc[1] = tmp;
    /* new tetrahedron i: t with corner abc[i] replaced by e */
    for (i = 0; i < 3; i++) {
        int32_t c[4];
        c[0] = abc[0], c[1] = abc[1], c[2] = abc[2], c[3] = d;
        c[i] = e;
        memcpy(nt[i], c, sizeof c);
        o[i] = cvm__orient3d(X + 3 * (size_t)c[0], X + 3 * (size_t)c[1], X + 3 * (size_t)c[2],
                             X + 3 * (size_t)c[3]);
        if (o[i] == 0)
            zero = i, nzero++;
        else if (o[i] < 0)
            neg = i, nneg++;
    }
    if (nzero == 1 && nneg == 0) /* de meets the edge pq: 4-4 when pq has 4 tetrahedra */
        return d3f_flip44(K, t, u, abc[zero], abc[(zero + 1) % 3], abc[(zero + 2) % 3], d, e);
    if (nzero)
        return 0;
    if (nneg == 0) { /* segment de crosses the triangle abc: 2-3 */
        int32_t kill[2];
        kill[0] = t, kill[1] = u;
        d3f_replace(K, kill, 2, nt, 3);
        return 3;
    }
    if (nneg == 1) { /* de passes beyond edge pq (the other two): 3-2 when pq has 3 tetrahedra */
        int32_t x = abc[neg], p = abc[(neg + 1) % 3], q = abc[(neg + 2) % 3], kill[3], s3, n2;
        int ft = d3f_corner_of(K->tet + 4 * (size_t)t, x), fu = d3f_corner_of(K->tet + 4 * (size_t)u, x);
        double o1, o2;
        int32_t nn[2][4];
        s3 = K->nbr[4 * (size_t)t + (size_t)ft];
        if (s3 < 0 || fu < 0 || K->cface[4 * (size_t)t + (size_t)ft] ||
            K->tet[s3] != e) /* the tetrahedron across t's face p q d must be p q d e */
            return 0;
        n2 = K->nbr[4 * (size_t)u + (size_t)fu];
        if (n2 < 0 || (n2 >> 2) != (s3 >> 2) || K->cface[4 * (size_t)u + (size_t)fu] ||
            !d3f_same_region(K, t, s3 >> 2))
            return 0;
        o1 = cvm__orient3d(X + 3 * (size_t)x, X + 3 * (size_t)d, X + 3 * (size_t)e,
                           X + 3 * (size_t)p);
        o2 = cvm__orient3d(X + 3 * (size_t)x, X + 3 * (size_t)d, X + 3 * (size_t)e,
                           X + 3 * (size_t)q);
        /* p and q strictly on both sides of x d e: pq crosses that triangle (the three
           tetrahedra around pq are positive), the two new ones fill the same union */
        if (!((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)))
            return 0;
        nn[0][0] = x, nn[0][1] = d, nn[0][2] = e, nn[0][3] = p;
        nn[1][0] = x, nn[1][1] = d, nn[1][2] = e, nn[1][3] = q;
        if (o1 < 0)
            nn[0][0] = d, nn[0][1] = x;
        else
            nn[1][0] = d, nn[1][1] = x;
        kill[0] = t, kill[1] = u, kill[2] = s3 >> 2;
        d3f_replace(K, kill, 3, nn, 2);
        return 2;
    }
    return 0;
}

static int d3f_conflict(const cvm__d3_work *K, int32_t t, int f)
{
    return !cvm__d3_face_regular(K->M, (size_t)t, f);
}

/* Whether face f of live tetrahedron t may stay not regular: both its tetrahedra
 * are older than the move (so it is the same face as before), it failed before
 * (v at x0, w0), and it fails strictly now only if it did before: a face of the
 * input that no flip repairs may fail on a tie (perturbation) but never turns
 * into a vertex strictly inside an orthosphere. */
static int d3f_failed_before(const cvm__d3_work *K, int32_t t, int f, int32_t v, const double *x0,
                         double w0, size_t ntet0)
{
    int32_t nb = K->nbr[4 * (size_t)t + (size_t)f];
    if ((size_t)t >= ntet0 || nb < 0 || (size_t)(nb >> 2) >= ntet0)
        return 0;
    if (!cvm__d3_face_conflict_at(K->M, (size_t)t, f, v, x0, w0, 1))
        return 0;
    return !cvm__d3_face_conflict_at(K->M, (size_t)t, f, -1, NULL, 0, 0) ||
           cvm__d3_face_conflict_at(K->M, (size_t)t, f, v, x0, w0, 0);
}

static int d3f_has(const int32_t *c, int32_t v)
{
    return c[0] == v || c[1] == v || c[2] == v || c[3] == v;
}

/* 1 for the second side of a face between two tetrahedra of v's star (a face at v,
 * the neighbour with the smaller slot has it): each such face once. */
static int d3f_twice(const cvm__d3_work *K, int32_t t, int f, int32_t v)
{
    int32_t nb = K->nbr[4 * (size_t)t + (size_t)f];
    return nb >= 0 && K->tet[4 * (size_t)t + (size_t)f] != v && (nb >> 2) < t &&
           d3f_has(K->tet + 4 * (size_t)t, v);
}

int cvm__d3_restore(cvm__d3_work *K, int32_t v, const double *x0, double w0, size_t ntet0)
{
    size_t qn = 0, head = 0, s, nflip = 0;
    int round;
    K->mflips = 0;
    for (s = 0; s < K->nstar; s++) {
        int f;
        for (f = 0; f < 4; f++)
            if (!d3f_twice(K, K->star[s], f, v))
                K->queue[qn++] = 4 * K->star[s] + f;
    }
    for (round = 0; round < 4; round++) {
        size_t flips_round = 0, t;
        while (head < qn) {
            int32_t slot = K->queue[head++], tt = slot >> 2;
            int f = slot & 3, k, nn;
            if (K->dead[tt] || !d3f_conflict(K, tt, f))
                continue;
            if (nflip == CVM__D3_MAX_FLIPS)
                return 0;
            if (!(nn = d3f_try_flip(K, tt, f)))
                continue;
            nflip++, flips_round++;
            K->mflips = nflip;
            /* the new tetrahedra are the last nn: their faces next */
            for (t = K->ntet - (size_t)nn; t < K->ntet; t++)
                for (k = 0; k < 4; k++) {
                    if (qn == CVM__D3_QUEUE)
                        return 0;
                    K->queue[qn++] = (int32_t)(4 * t + (size_t)k);
                }
        }
        if (!flips_round && round == 0)
            return 0; /* every face of the star was queued: none could be flipped */
        /* what must hold: every face of v's star and of the new tetrahedra */
        if (cvm__d3_gather_star(K, v))
            return 0;
        qn = head = 0;
        for (s = 0; s < K->nstar + (K->ntet - ntet0); s++) {
            int32_t tt = s < K->nstar ? K->star[s] : (int32_t)(ntet0 + (s - K->nstar));
            int f;
            if (K->dead[tt] || (s >= K->nstar && d3f_has(K->tet + 4 * (size_t)tt, v)))
                continue; /* dead, or a new tetrahedron of the star, seen there */
            for (f = 0; f < 4; f++)
                if (!d3f_twice(K, tt, f, v) && d3f_conflict(K, tt, f) &&
                    !d3f_failed_before(K, tt, f, v, x0, w0, ntet0)) {
                    if (qn == CVM__D3_QUEUE)
                        return 0;
                    K->queue[qn++] = 4 * tt + f;
                }
        }
        if (qn == 0)
            return 1;
        if (!flips_round && round > 0)
            return 0;
    }
    return 0;
}

/* 1 when each of the last nn tetrahedra has no dihedral cosine above cmax. */
static int d3f_new_ok(const cvm__d3_work *K, int nn, double cmax)
{
    size_t t;
    for (t = K->ntet - (size_t)nn; t < K->ntet; t++)
        if (cvm__d3_tet_max_cos(K->M, t, -1, NULL) > cmax)
            return 0;
    return 1;
}

size_t cvm__d3_regularise(cvm__d3_work *K, double cfloor)
{
    size_t n = 0, pass, t;
    int f;
    K->logging = 0;
    for (pass = 0; pass < 8; pass++) {
        size_t before = n, end;
        if (!d3f_room(K))
            break;
        end = K->ntet;
        for (t = 0; t < end; t++)
            for (f = 0; f < 4 && !K->dead[t]; f++) {
                size_t ntet0 = K->ntet;
                double cold = -1;
                int nn, k;
                int32_t nb;
                if (!d3f_conflict(K, (int32_t)t, f) || K->ntet + 4 > K->cap)
                    continue;
                /* the old tetrahedra's worst angle: every tetrahedron a flip of this face
                   can remove is t, its neighbour, or a neighbour of one of them */
                cold = cvm__d3_tet_max_cos(K->M, t, -1, NULL);
                nb = K->nbr[4 * t + (size_t)f];
                for (k = 0; k < 4; k++) {
                    int32_t a = K->nbr[4 * t + (size_t)k], b = K->nbr[4 * (size_t)(nb >> 2) + (size_t)k];
                    double c;
                    if (a >= 0 && (c = cvm__d3_tet_max_cos(K->M, (size_t)(a >> 2), -1, NULL)) > cold)
                        cold = c;
                    if (b >= 0 && (c = cvm__d3_tet_max_cos(K->M, (size_t)(b >> 2), -1, NULL)) > cold)
                        cold = c;
                }
                K->logging = 1;
                K->nlog = 0;
                nn = d3f_try_flip(K, (int32_t)t, f);
                if (nn && cfloor < 2 && !d3f_new_ok(K, nn, cold > cfloor ? cold : cfloor)) {
                    cvm__d3_undo_all(K, ntet0);
                    nn = 0;
                }
                K->logging = 0;
                K->nlog = 0;
                n += nn > 0;
            }
        if (n == before)
            break;
    }
    return n;
}
