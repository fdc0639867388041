/* optimise_score.c - the dual optimiser's view of the mesh: local sizes, boundary flags and
 * layers, the score of a triangle (optimise.c), the stars of vertices and the kind of local
 * problem each vertex gets. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "optimise_run.h"
#include "geom/geom_internal.h"
#include "geom/measure.h"


uint64_t cvm__dopt_stream_key(uint64_t seed, uint64_t sweep, uint64_t v)
{
    return seed * 0x9E3779B97F4A7C15ull ^ (sweep + 1) * 0xC2B2AE3D27D4EB4Full ^ (v + 1) * 0x165667B19E3779F9ull;
}

cvm_status cvm__dopt_sizes(dopt *D)
{
    cvm__tri2 *T = D->T;
    size_t v;
    cvm__dual_mesh_sizes(T, D->vsize);
    if (!D->p->size_fn)
        return CVM_OK;
    for (v = 0; v < T->nv; v++) {
        cvm_status s;
        double h;
        if (T->vtri[v] < 0)
            continue;
        if ((s = D->p->size_fn(D->p->size_payload, T->xy[2 * v], T->xy[2 * v + 1], &h)))
            return s;
        if (isfinite(h) && h > 0)
            D->vsize[v] = h;
    }
    return CVM_OK;
}

void cvm__dopt_boundary_flags(dopt *D)
{
    cvm__tri2 *T = D->T;
    size_t t;
    int j;
    memset(D->vbnd, 0, T->nv);
    for (t = 0; t < T->nt; t++) {
        if (!cvm__tri2_in_domain(T, (int32_t)t))
            continue;
        for (j = 0; j < 3; j++) {
            int32_t u = T->tn[3 * t + (size_t)j] / 3;
            if (!cvm__tri2_in_domain(T, u)) {
                D->vbnd[T->tv[3 * t + (size_t)(j + 1) % 3]] = 1;
                D->vbnd[T->tv[3 * t + (size_t)(j + 2) % 3]] = 1;
            }
        }
    }
}

void cvm__dual_layers(const cvm__tri2 *T, const uint8_t *vbnd, int32_t *layer, int32_t *queue)
{
    size_t t, head = 0, tail = 0;
    int j;
    for (t = 0; t < T->nt; t++) {
        const int32_t *v = T->tv + 3 * t;
        layer[t] = INT32_MAX;
        if (cvm__tri2_in_domain(T, (int32_t)t) && (vbnd[v[0]] || vbnd[v[1]] || vbnd[v[2]])) {
            layer[t] = 0;
            queue[tail++] = (int32_t)t;
        }
    }
    while (head < tail) {
        int32_t x = queue[head++];
        for (j = 0; j < 3; j++) {
            int32_t a = T->tn[3 * (size_t)x + (size_t)j], u = a < 0 ? -1 : a / 3;
            if (u < 0 || layer[u] != INT32_MAX || !cvm__tri2_in_domain(T, u))
                continue;
            layer[u] = layer[x] + 1;
            queue[tail++] = u;
        }
    }
}

static double score(const dopt *D, int32_t t)
{
    const cvm__tri2 *T = D->T;
    const int32_t *v = T->tv + 3 * (size_t)t;
    double cx, cy, prio;
    if (D->st[t] != CVM__DUAL_NONCOMPLIANT)
        return 0.0;
    cx = (T->xy[2 * (size_t)v[0]] + T->xy[2 * (size_t)v[1]] + T->xy[2 * (size_t)v[2]]) / 3.0;
    cy = (T->xy[2 * (size_t)v[0] + 1] + T->xy[2 * (size_t)v[1] + 1] + T->xy[2 * (size_t)v[2] + 1]) / 3.0;
    prio = D->layer[t] == INT32_MAX ? 1.0 : 1.0 + D->p->layer_priority / (1.0 + (double)D->layer[t]);
    return prio * hypot(cx - D->V[2 * (size_t)t], cy - D->V[2 * (size_t)t + 1]);
}

double cvm__dopt_sq(double x)
{
    return x * x;
}

/* Weak (see dopt) for a compliant slot t: a measure in plain doubles. */
static int is_weak(const dopt *D, int32_t t)
{
    const cvm__tri2 *T = D->T;
    const int32_t *v = T->tv + 3 * (size_t)t;
    const double *V = D->V + 2 * (size_t)t;
    double l2[3], c;
    int k;
    if (D->st[t] == CVM__DUAL_MERGED)
        return 1;
    {
        const double *p0 = T->xy + 2 * (size_t)v[0], *p1 = T->xy + 2 * (size_t)v[1];
        const double *p2 = T->xy + 2 * (size_t)v[2];
        c = (p1[0] - p0[0]) * (p2[1] - p0[1]) - (p1[1] - p0[1]) * (p2[0] - p0[0]);
    }
    for (k = 0; k < 3; k++) {
        const double *a = T->xy + 2 * (size_t)v[(k + 1) % 3], *b = T->xy + 2 * (size_t)v[(k + 2) % 3];
        double s;
        l2[k] = cvm__dopt_sq(b[0] - a[0]) + cvm__dopt_sq(b[1] - a[1]);
        s = ((b[0] - a[0]) * (V[1] - a[1]) - (b[1] - a[1]) * (V[0] - a[0])) / sqrt(l2[k]);
        if (s < 0.5 * D->p->margin * sqrt(l2[k]))
            return 1;
    }
    for (k = 0; k < 3; k++)
        if (c * c < D->sin2_target * l2[(k + 1) % 3] * l2[(k + 2) % 3])
            return 1;
    return 0;
}

/* Re-score slot t (a domain triangle), keeping the non-compliant and weak counts. */
void cvm__dopt_rescore(dopt *D, int32_t t)
{
    uint8_t old = D->st[t], oldw = D->weak[t];
    D->st[t] = (uint8_t)cvm__dual_tri_compliance(D->T, D->msize, D->p->merge_tol, D->V, t);
    D->nc += (D->st[t] == CVM__DUAL_NONCOMPLIANT) - (old == CVM__DUAL_NONCOMPLIANT);
    D->weak[t] = (uint8_t)(D->st[t] != CVM__DUAL_NONCOMPLIANT && is_weak(D, t));
    D->nweak += D->weak[t];
    D->nweak -= oldw;
    D->F[t] = score(D, t);
}

void cvm__dopt_score_all(dopt *D)
{
    cvm__tri2 *T = D->T;
    size_t t;
    cvm__dual_mesh_sizes(T, D->msize);
    for (t = 0; t < T->nt; t++)
        if (cvm__tri2_in_domain(T, (int32_t)t))
            cvm__dual_tri_vertex(T, (int32_t)t, D->V + 2 * t);
    D->nc = D->nweak = 0;
    for (t = 0; t < T->nt; t++) {
        D->st[t] = D->weak[t] = 0;
        D->F[t] = 0.0;
        if (cvm__tri2_in_domain(T, (int32_t)t))
            cvm__dopt_rescore(D, (int32_t)t);
    }
}

/* Live triangles around v into star (room for them); their number. */
size_t cvm__dopt_gather_star(const dopt *D, int32_t v, int32_t *star)
{
    return cvm__tri2_star(D->T, v, star, (size_t)-1);
}

/* 1 when a triangle of the star is a domain triangle. */
static int domain_of_star(const dopt *D, const int32_t *star, size_t n)
{
    size_t k;
    for (k = 0; k < n; k++)
        if (cvm__tri2_in_domain(D->T, star[k]))
            return 1;
    return 0;
}

/* Index of the ghost vertex in ghost triangle g. */
static int ghost_corner(const cvm__tri2 *T, int32_t g)
{
    const int32_t *tv = T->tv + 3 * (size_t)g;
    return tv[0] == CVM__GHOST ? 0 : tv[1] == CVM__GHOST ? 1 : 2;
}

/* 1 when the hull edge of ghost triangle g is a constrained edge of a domain
 * triangle. */
static int hull_domain_side(const cvm__tri2 *T, int32_t g)
{
    int k = ghost_corner(T, g);
    return cvm__tri2_edge_seg(T, g, k) >= 0 && cvm__tri2_in_domain(T, T->tn[3 * (size_t)g + (size_t)k] / 3);
}

/* 1 when moving a corner of the hull edge of ghost triangle g cannot break the
 * hull convexity cvm__tri2_check asks of unconstrained hull edges: that edge
 * and the hull edges of the two ghost triangles beside g are constrained.
 * Taken only where all three are sides of the domain: a hull edge of a carved
 * triangle is constrained by the refiner, but a corner beside one stays fixed. */
static int hull_safe(const cvm__tri2 *T, int32_t g)
{
    int k = ghost_corner(T, g), e;
    if (!hull_domain_side(T, g))
        return 0;
    for (e = 1; e <= 2; e++) {
        int32_t h = T->tn[3 * (size_t)g + (size_t)(k + e) % 3] / 3;
        if (!cvm__tri2_is_ghost(T, h) || !hull_domain_side(T, h))
            return 0;
    }
    return 1;
}

/* Degrees of freedom of v (see optimise.h) and, for a vertex on a segment,
 * the segment's direction. 0: v has no domain triangle. */
int cvm__dopt_vertex_mode(const dopt *D, int32_t v, const int32_t *star, size_t n, double *dir)
{
    const cvm__tri2 *T = D->T;
    int32_t nb[2] = {-1, -1}, sg[2] = {-1, -1};
    int ncon = 0, ghost = 0, domain = 0, other = 0;
    size_t k;
    for (k = 0; k < n; k++) {
        int32_t t = star[k];
        const int32_t *tv = T->tv + 3 * (size_t)t;
        int i = tv[0] == v ? 0 : tv[1] == v ? 1 : 2, e;
        if (cvm__tri2_is_ghost(T, t)) {
            ghost = 1;
            if (!hull_safe(T, t))
                return domain_of_star(D, star, n) ? 1 : 0;
            continue;
        }
        domain |= cvm__tri2_in_domain(T, t);
        other |= !cvm__tri2_in_domain(T, t);
        for (e = 1; e <= 2; e++) {
            int32_t x = tv[(i + 3 - e) % 3], s = cvm__tri2_edge_seg(T, t, (i + e) % 3);
            if (s < 0 || x == nb[0] || x == nb[1])
                continue;
            if (ncon < 2) {
                nb[ncon] = x;
                sg[ncon] = s;
            }
            ncon++;
        }
    }
    if (!domain)
        return 0;
    if ((size_t)v < D->p->n_fixed)
        return 1;
    if (ncon == 0 && !ghost && !other)
        return 3;
    /* between two constrained edges of one segment, or of two exactly collinear ones */
    if (ncon == 2 && (sg[0] == sg[1] || cvm__orient2d(T->xy + 2 * (size_t)nb[0], T->xy + 2 * (size_t)v,
                                                        T->xy + 2 * (size_t)nb[1]) == 0)) {
        const double *a = T->xy + 2 * (size_t)nb[0], *b = T->xy + 2 * (size_t)nb[1];
        double len = hypot(b[0] - a[0], b[1] - a[1]);
        dir[0] = (b[0] - a[0]) / len;
        dir[1] = (b[1] - a[1]) / len;
        return 2;
    }
    return 1;
}
