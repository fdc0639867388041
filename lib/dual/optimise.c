/*
 * optimise.c - the sweep driver of the dual optimiser: scores every triangle,
 * visits the vertices of the non-compliant ones worst first, solves each
 * vertex's local problem, and restores the regular triangulation after each
 * sweep.
 *
 * Score of domain triangle k: F_k = W_k L_k |C_k - V_k| (centroid C, power
 * vertex V); W_k = 1 when V lies outside k (exact cvm__power_side2d) and k
 * cannot be merged (merge.c), else 0; L_k = 1 + c / (1 + layer_k) with c the
 * layer priority and layer_k the breadth-first layer of k from the boundary
 * (cvm__dual_layers; boundary cells first). Within a sweep the topology is
 * fixed and only coordinates and weights change; the triangles with F > 0 are
 * sorted by F (worst first, ties by slot), cut into min(20, N/25) bins of equal
 * count and shuffled within each bin by a stream keyed by (seed, sweep); each
 * vertex is solved at most once per sweep, and the triangles it touches (and
 * their neighbours, whose merge state depends on it) are re-scored at once.
 * After the sweep, Lawson flips under the exact power test restore the
 * regular triangulation; a vertex whose power cell vanished (the blocking
 * corner of an unflippable illegal edge) is removed when it is a removable
 * Steiner vertex and p->topology is set (topology.c; then compact() renumbers
 * the vertices and carries vsize, vbnd and p->vmap along); any other gets its
 * weight raised (by 0.1,
 * 0.2, 0.4 ... times its squared local size) until none vanishes; after 8
 * rounds every weight is reset to 0, which always leaves a valid
 * (constrained Delaunay) mesh. With p->topology 2, repair_degrees() removes
 * vertices after the first sweeps (experimental). The run stops when
 * nothing is non-compliant or weak, a sweep moves nothing, or at the sweep
 * limit, the time limit or cancellation; once all is compliant, PATIENCE
 * sweeps without progress (smallest angle up by PROGRESS_DEG, or the weak
 * count 1% below its last low) raise the target angle by PUSH_DEG (PUSHES
 * times), then end the run. keep_best() remembers the best state (fewest
 * non-compliant, then largest smallest angle) and end_at_best() returns to it
 * at a normal end: a later sweep can lower the smallest angle, since moves
 * trade angles against the penalty of others.
 *
 * When the run ends compliant, maxmin_phase() raises the smallest angle with
 * every triangle kept compliant: rounds of per-vertex max-min solves under
 * constraints that keep the star regular (so no flip follows and the
 * per-triangle state is kept up to date by the moves), then removal trials on
 * a snapshot of the whole triangulation when CVM_OPT_DUAL_MAXMIN_TRIALS asks
 * (see CVM_OPT_DUAL_MAXMIN_ROUNDS and _TRIALS in
 * cvmesh.h for the rules, docs/design/dual_optimisation.md for the effect).
 *
 * Parallel and deterministic: the order above is cut into batches of vertices
 * no two of which are equal or share a triangle's vertex (so their local
 * problems read no vertex that moves); a batch's problems are solved on
 * OpenMP threads, then applied and re-scored in batch order. Batches depend
 * only on the mesh and the order, so the result is identical for any
 * CVM_OPT_THREADS.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "optimise.h"
#include "geom/geom_internal.h"
#include "geom/measure.h"

#define FIX_ROUNDS 8
#define BATCH 256
#define DEG_HIGH_DEG 47.0 /* average corner angle that calls for degree repair */
#define DEG_SWEEPS 10     /* degree repair after the first DEG_SWEEPS sweeps only */
#define PATIENCE 4        /* sweeps without progress before the run stops */
#define PUSHES 1          /* target raises before the run ends */
#define PUSH_PATIENCE 2   /* PATIENCE after a raise: 4 gave nearly the same results
                             for more time (docs/design/dual_optimisation.md) */
#define PROGRESS_DEG 0.05 /* smallest-angle gain over PATIENCE sweeps that keeps the run going */
#define PUSH_DEG 5.0      /* each raise of the target angle, degrees */
#define BEST_EPS_DEG 1e-3 /* smallest angle gain that makes a state the new best, degrees */
#define MM_BAND_DEG 2.0   /* max-min phase: visit triangles below the smallest angle + this */
#define MM_PATIENCE 3     /* max-min phase: rounds without MM_PROGRESS_DEG gain before it ends */
#define MM_PROGRESS_DEG 0.01
#define MM_SLACK_F (1.0 / 3.0) /* max-min phase: containment slack kept, x the margin */
#define MM_DUAL_F 1.1     /* max-min phase: dual/primal edge ratio kept, x the margin */
#define MM_PATTERN_BUDGET 20 /* max-min phase: compass evaluations after the active-set ascent */
#define RM_BAND_DEG 0.5   /* removal trials: corners of triangles below the smallest angle + this */
#define RM_TRIES 8        /* removal trials: at most this many per call */
#define RM_SWEEPS 8       /* removal trials: penalty sweeps to regain compliance */
#define RM_ROUNDS 15      /* removal trials: max-min rounds before a trial is judged */
#define RM_FAILED 64      /* removal trials: failed positions remembered (not tried again) */
#define RM_HUB_DEG 8      /* removal trials: triangles around a vertex that make it a hub */
#define RM_RINGS 4        /* removal trials: rings around the removed vertex its rounds visit */
#define RM_MAXNB 96       /* removal trials: neighbour slots (a star's corners, repeats included) */

typedef struct dopt {
    cvm__tri2 *T;
    const cvm__dual_opt_params *p;
    double *vsize;   /* nv */
    uint8_t *vbnd;   /* nv: on the domain boundary */
    uint8_t *mark;   /* nv: scratch (visited / vanished) */
    double *V;       /* 2 per slot */
    double *F;       /* per slot */
    uint8_t *st;     /* per slot: cvm__dual_tri_compliance */
    int32_t *layer;  /* per slot: cvm__dual_layers */
    uint8_t *weak;   /* per slot: compliant but an angle below the target, merged, or the
                        power vertex within half the margin of an edge */
    int32_t *list;   /* slots to visit */
    int32_t *star;   /* scratch: sort buffer, then the stars of a batch (disjoint) */
    struct job *jobs; /* BATCH entries */
    uint32_t *stamp; /* nv: batch stamp of the vertices a batch holds or touches */
    uint8_t *gone;   /* nv: removed, not yet compacted */
    uint8_t *region; /* nv: removal trials: the vertices whose triangles its rounds visit */
    int region_on;   /* 1: max-min rounds visit only triangles with a vertex in region */
    int32_t *dup, *map2; /* nv: scratch of compact() */
    size_t nv0;      /* vertex count at the call (vmap's length) */
    int topo;        /* vertex removal on (p->topology with p->vmap) */
    uint32_t cur_stamp;
    int nthreads;
    double *save;    /* 3 per vertex: x, y, w at the start of a sweep */
    double *best;    /* 3 per vertex: x, y, w of the best state (keep_best) */
    size_t best_nv, best_removed;
    size_t nc, nc0;  /* current and initial non-compliant counts */
    size_t nweak;
    double sin2_min, sin2_target;
    int mm;          /* 1 during the max-min-angle phase (maxmin_phase) */
    double mm_min;   /* smallest angle when its round's order was made, degrees */
    int nc_only;     /* 1: a sweep visits the non-compliant triangles only */
    struct snap *snap; /* removal trials: the state to go back to */
    double failed[2 * RM_FAILED]; /* removal trials: positions of vertices whose trial failed */
    size_t nfailed;
    cvm__dual_opt_report *rep;
} dopt;

static uint64_t stream_key(uint64_t seed, uint64_t sweep, uint64_t v)
{
    return seed * 0x9E3779B97F4A7C15ull ^ (sweep + 1) * 0xC2B2AE3D27D4EB4Full ^ (v + 1) * 0x165667B19E3779F9ull;
}

static cvm_status sizes(dopt *D)
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

static void boundary_flags(dopt *D)
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

static double sq(double x)
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
        l2[k] = sq(b[0] - a[0]) + sq(b[1] - a[1]);
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
static void rescore(dopt *D, int32_t t)
{
    uint8_t old = D->st[t], oldw = D->weak[t];
    D->st[t] = (uint8_t)cvm__dual_tri_compliance(D->T, D->vsize, D->p->merge_tol, D->V, t);
    D->nc += (D->st[t] == CVM__DUAL_NONCOMPLIANT) - (old == CVM__DUAL_NONCOMPLIANT);
    D->weak[t] = (uint8_t)(D->st[t] != CVM__DUAL_NONCOMPLIANT && is_weak(D, t));
    D->nweak += D->weak[t];
    D->nweak -= oldw;
    D->F[t] = score(D, t);
}

static void score_all(dopt *D)
{
    cvm__tri2 *T = D->T;
    size_t t;
    for (t = 0; t < T->nt; t++)
        if (cvm__tri2_in_domain(T, (int32_t)t))
            cvm__dual_tri_vertex(T, (int32_t)t, D->V + 2 * t);
    D->nc = D->nweak = 0;
    for (t = 0; t < T->nt; t++) {
        D->st[t] = D->weak[t] = 0;
        D->F[t] = 0.0;
        if (cvm__tri2_in_domain(T, (int32_t)t))
            rescore(D, (int32_t)t);
    }
}

/* Live triangles around v into star (room for them); their number. */
static size_t gather_star(const dopt *D, int32_t v, int32_t *star)
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
static int vertex_mode(const dopt *D, int32_t v, const int32_t *star, size_t n, double *dir)
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

/* One vertex of a batch: its star (in the batch's pool) and the outcome of its
 * local problem. */
typedef struct job {
    int32_t v;
    size_t star0, nstar;
    int moved;
    double p[2], w;
} job;

/* Solve the local problem of job J (reads the mesh, writes only J): the
 * parallel part of a batch. */
static void solve_job(const dopt *D, job *J, uint64_t sweep)
{
    const cvm__tri2 *T = D->T;
    const int32_t *star = D->star + J->star0;
    cvm__dopt_local L;
    double u[CVM__DOPT_MAXDOF] = {0}, f0, f;
    int32_t v = J->v;
    J->moved = 0;
    memset(&L, 0, sizeof L);
    if (!J->nstar || !(D->vsize[v] > 0))
        return;
    L.ndof = vertex_mode(D, v, star, J->nstar, L.dir);
    if (!L.ndof)
        return;
    L.T = T;
    L.v = v;
    L.p0[0] = T->xy[2 * (size_t)v];
    L.p0[1] = T->xy[2 * (size_t)v + 1];
    L.w0 = T->w[v];
    L.h = D->vsize[v];
    L.star = star;
    L.nstar = J->nstar;
    L.vbnd = D->vbnd;
    L.margin = D->p->margin;
    L.sin2_target = D->sin2_target;
    L.sin2_bound = cvm__dopt_star_min_sin2(&L);
    if (L.sin2_bound > D->sin2_min)
        L.sin2_bound = D->sin2_min;
    if (D->mm) {
        double m0[2];
        cvm__dopt_maxmin_cache(&L);
        if (cvm__dopt_eval_maxmin(&L, u, m0) == HUGE_VAL)
            return; /* not regular or too large a star: leave it */
        L.slack_bound = m0[0] < MM_SLACK_F * D->p->margin ? m0[0] : MM_SLACK_F * D->p->margin;
        L.dual_bound = m0[1] < MM_DUAL_F * D->p->margin ? m0[1] : MM_DUAL_F * D->p->margin;
        L.maxmin = 1;
        L.mm_m0 = cvm__dopt_star_min_sin2(&L);
    }
    f0 = cvm__dopt_eval(&L, u);
    if (D->mm) {
        /* the active-set ascent of the position, then the compass search over
         * every degree of freedom from where it ended */
        double ua[CVM__DOPT_MAXDOF], fa;
        cvm__dopt_maxmin_active(&L, f0, ua, &fa);
        if (fa < f0) {
            double w;
            cvm__dopt_point(&L, ua, L.p0, &w);
            L.w0 = w;
        }
        cvm__dopt_pattern(&L, D->p->pattern_budget < MM_PATTERN_BUDGET ? D->p->pattern_budget : MM_PATTERN_BUDGET,
                          fa, u, &f);
        if (!(f < f0))
            return;
        cvm__dopt_point(&L, u, J->p, &J->w);
        J->moved = 1;
        return;
    }
    if (D->p->solver == CVM__DUAL_SOLVER_CUCKOO) {
        cvm__rng r;
        cvm__rng_seed(&r, stream_key(D->p->seed, sweep, (uint64_t)v));
        cvm__dopt_cuckoo(&L, D->p->cuckoo_budget, &r, f0, u, &f);
    } else {
        cvm__dopt_pattern(&L, D->p->pattern_budget, f0, u, &f);
    }
    if (!(f < f0))
        return;
    cvm__dopt_point(&L, u, J->p, &J->w);
    J->moved = 1;
}

static void rescore_star(dopt *D, const int32_t *star, size_t nstar);

/* Apply a solved job: move the vertex, re-score its star and the triangles
 * across its outer edges; in the max-min phase, undo a move that made a
 * triangle non-compliant (then J->moved is 0). Serial, in batch order. */
static void apply_job(dopt *D, job *J)
{
    cvm__tri2 *T = D->T;
    const int32_t *star = D->star + J->star0;
    size_t nc0 = D->nc;
    double old[3];
    if (!J->moved)
        return;
    old[0] = T->xy[2 * (size_t)J->v];
    old[1] = T->xy[2 * (size_t)J->v + 1];
    old[2] = T->w[J->v];
    T->xy[2 * (size_t)J->v] = J->p[0];
    T->xy[2 * (size_t)J->v + 1] = J->p[1];
    T->w[J->v] = J->w;
    rescore_star(D, star, J->nstar);
    if (D->mm && D->nc > nc0) {
        /* the max-min phase keeps every triangle compliant (exact test) */
        T->xy[2 * (size_t)J->v] = old[0];
        T->xy[2 * (size_t)J->v + 1] = old[1];
        T->w[J->v] = old[2];
        rescore_star(D, star, J->nstar);
        J->moved = 0;
    }
}

/* Power vertices and scores of the triangles of a star and of those across its outer edges. */
static void rescore_star(dopt *D, const int32_t *star, size_t nstar)
{
    cvm__tri2 *T = D->T;
    size_t k;
    int j;
    for (k = 0; k < nstar; k++)
        if (cvm__tri2_in_domain(T, star[k]))
            cvm__dual_tri_vertex(T, star[k], D->V + 2 * (size_t)star[k]);
    for (k = 0; k < nstar; k++) {
        int32_t t = star[k];
        if (!cvm__tri2_in_domain(T, t))
            continue;
        rescore(D, t);
        for (j = 0; j < 3; j++) {
            int32_t u2 = T->tn[3 * (size_t)t + (size_t)j] / 3;
            if (cvm__tri2_in_domain(T, u2))
                rescore(D, u2);
        }
    }
}

/* Drop the removed vertices (gone) from T's vertex arrays, renumbering the
 * rest in order; carry vsize, vbnd and the caller's map along. */
static void compact(dopt *D)
{
    cvm__tri2 *T = D->T;
    size_t v, nv = T->nv;
    for (v = 0; v < nv; v++)
        D->dup[v] = D->gone[v] ? 0 : -1; /* vertex 0 is an input point: never gone */
    cvm__tri2_compact(T, D->dup, D->map2);
    for (v = 0; v < nv; v++) {
        int32_t n = D->map2[v];
        if (D->gone[v]) {
            D->map2[v] = -1;
            continue;
        }
        D->vsize[n] = D->vsize[v]; /* n <= v: in place */
        D->vbnd[n] = D->vbnd[v];
    }
    memset(D->gone, 0, nv);
    for (v = 0; v < D->nv0; v++)
        if (D->p->vmap[v] >= 0)
            D->p->vmap[v] = D->map2[D->p->vmap[v]];
}

/* Average angle, in degrees, of vertex v over its domain triangles (each
 * corner's angle, plain doubles) into *avg; their number is returned. */
static size_t corner_angles(const dopt *D, int32_t v, double *avg)
{
    const cvm__tri2 *T = D->T;
    int32_t t0 = T->vtri[v], t = t0;
    size_t n = 0, k = 0;
    double sum = 0;
    if (t0 < 0)
        return 0;
    do {
        const int32_t *tv = T->tv + 3 * (size_t)t;
        int i = tv[0] == v ? 0 : tv[1] == v ? 1 : 2;
        if (cvm__tri2_in_domain(T, t)) {
            const double *p = T->xy + 2 * (size_t)v, *a = T->xy + 2 * (size_t)tv[(i + 1) % 3];
            const double *b = T->xy + 2 * (size_t)tv[(i + 2) % 3];
            sum += cvm__corner_angle(p, a, b);
            n++;
        }
        t = T->tn[3 * (size_t)t + (size_t)(i + 1) % 3] / 3;
    } while (t != t0 && ++k < T->nt);
    *avg = n ? sum / (double)n * (180.0 / CVM__PI) : 0.0;
    return n;
}

/* 1 when a domain triangle around v has an angle below the target. */
static int star_weak(const dopt *D, int32_t v)
{
    const cvm__tri2 *T = D->T;
    int32_t t0 = T->vtri[v], t = t0;
    size_t k = 0;
    if (t0 < 0)
        return 0;
    do {
        if (cvm__tri2_in_domain(T, t) && D->weak[t])
            return 1;
        t = cvm__tri2_around(T, t, v);
    } while (t != t0 && ++k < T->nt);
    return 0;
}

/* Degree repair (see the file comment): a vertex whose corners average less
 * than DEG_HIGH_DEG degrees (degree 8 and more inside) and that touches a weak
 * triangle loses its removable Steiner neighbour of least degree; an interior
 * removable Steiner vertex of degree 4 or less is removed. One operation per
 * neighbourhood and pass (stamps); vertices in index order. The number
 * removed; T is then valid but maybe not regular (restore() follows). */
static size_t repair_degrees(dopt *D)
{
    cvm__tri2 *T = D->T;
    size_t v, nrem = 0;
    D->cur_stamp++;
    for (v = 0; v < T->nv; v++) {
        int32_t t0 = T->vtri[v], t, best = -1;
        size_t deg, bdeg = 0, k = 0;
        double avg;
        if (t0 < 0 || D->gone[v] || D->stamp[v] == D->cur_stamp)
            continue;
        if (v >= D->p->n_input && cvm__dual_removable(T, (int32_t)v, &deg) && deg <= 4) {
            best = (int32_t)v;
        } else if (corner_angles(D, (int32_t)v, &avg) && avg < DEG_HIGH_DEG && star_weak(D, (int32_t)v)) {
            t = t0;
            do {
                const int32_t *tv = T->tv + 3 * (size_t)t;
                int i = tv[0] == (int32_t)v ? 0 : tv[1] == (int32_t)v ? 1 : 2;
                int32_t x = tv[(i + 2) % 3];
                size_t dx;
                if (x >= 0 && (size_t)x >= D->p->n_input && D->stamp[x] != D->cur_stamp &&
                    cvm__dual_removable(T, x, &dx) && (best < 0 || dx < bdeg)) {
                    best = x;
                    bdeg = dx;
                }
                t = T->tn[3 * (size_t)t + (size_t)(i + 1) % 3] / 3;
            } while (t != t0 && ++k < T->nt);
        }
        if (best < 0)
            continue;
        {
            /* stamp the neighbourhood of best before it goes */
            int32_t s0 = T->vtri[best], s = s0;
            k = 0;
            do {
                int i = cvm__tri2_corner(T, s, best);
                D->stamp[T->tv[3 * (size_t)s + (size_t)(i + 1) % 3]] = D->cur_stamp;
                s = T->tn[3 * (size_t)s + (size_t)(i + 1) % 3] / 3;
            } while (s != s0 && ++k < T->nt);
            D->stamp[v] = D->cur_stamp;
            if (cvm__dual_remove_vertex(T, best, best == (int32_t)v ? -1 : (int32_t)v)) {
                D->gone[best] = 1;
                nrem++;
            }
        }
    }
    return nrem;
}

/* Make T regular again with no vanished vertex (see the file comment). */
static cvm_status restore(dopt *D)
{
    cvm__tri2 *T = D->T;
    size_t nfl, v;
    int round;
    cvm_status s;
    if ((s = cvm__tri2_make_regular(T, &nfl)))
        return s;
    D->rep->flips += nfl;
    for (round = 0; D->topo && round < FIX_ROUNDS; round++) {
        size_t nrem = 0;
        if (!cvm__tri2_count_unregular(T, D->mark))
            return CVM_OK;
        for (v = D->p->n_input; v < T->nv; v++)
            if (D->mark[v] && cvm__dual_remove_vertex(T, (int32_t)v, -1)) {
                D->gone[v] = 1;
                nrem++;
            }
        if (!nrem)
            break;
        D->rep->removed_vanished += nrem;
        compact(D);
        if ((s = cvm__tri2_make_regular(T, &nfl)))
            return s;
        D->rep->flips += nfl;
    }
    for (round = 0; round < FIX_ROUNDS; round++) {
        if (!cvm__tri2_count_unregular(T, D->mark))
            return CVM_OK;
        for (v = 0; v < T->nv; v++)
            if (D->mark[v]) {
                double h = D->vsize[v] > 0 ? D->vsize[v] : 1.0;
                T->w[v] += 0.1 * h * h * (double)(1 << round);
                D->rep->weight_fixes++;
            }
        if ((s = cvm__tri2_make_regular(T, &nfl)))
            return s;
        D->rep->flips += nfl;
    }
    if (!cvm__tri2_count_unregular(T, D->mark))
        return CVM_OK;
    memset(T->w, 0, T->nv * sizeof *T->w);
    D->rep->weight_fixes += T->nv;
    if ((s = cvm__tri2_make_regular(T, &nfl)))
        return s;
    D->rep->flips += nfl;
    return CVM_OK;
}

static int by_score(const void *a, const void *b, const double *F, const uint8_t *st)
{
    int32_t x = *(const int32_t *)a, y = *(const int32_t *)b;
    if ((st[x] == CVM__DUAL_NONCOMPLIANT) != (st[y] == CVM__DUAL_NONCOMPLIANT))
        return st[x] == CVM__DUAL_NONCOMPLIANT ? -1 : 1;
    if (F[x] != F[y])
        return F[x] > F[y] ? -1 : 1;
    return x < y ? -1 : x > y;
}

/* Sort list[0..n) by (F descending, slot ascending): insertion into runs
 * merged bottom-up would be faster; a plain merge sort keeps it total. */
static void sort_list(int32_t *a, int32_t *tmp, size_t n, const double *F, const uint8_t *st)
{
    size_t width, i;
    for (width = 1; width < n; width *= 2) {
        for (i = 0; i < n; i += 2 * width) {
            size_t lo = i, mid = i + width < n ? i + width : n, hi = i + 2 * width < n ? i + 2 * width : n;
            size_t x = lo, y = mid, k = lo;
            while (x < mid && y < hi)
                tmp[k++] = by_score(&a[x], &a[y], F, st) <= 0 ? a[x++] : a[y++];
            while (x < mid)
                tmp[k++] = a[x++];
            while (y < hi)
                tmp[k++] = a[y++];
        }
        memcpy(a, tmp, n * sizeof *a);
    }
}

/* Order of one sweep into D->list; returns its length. */
static size_t sweep_order(dopt *D, uint64_t sweep)
{
    cvm__tri2 *T = D->T;
    size_t t, n = 0, nb, b;
    cvm__rng r;
    for (t = 0; t < T->nt; t++)
        if (D->st[t] == CVM__DUAL_NONCOMPLIANT || (D->weak[t] && !D->nc_only))
            D->list[n++] = (int32_t)t;
    sort_list(D->list, D->star, n, D->F, D->st);
    nb = n / 25 < 20 ? n / 25 : 20;
    if (nb < 1)
        nb = 1;
    cvm__rng_seed(&r, stream_key(D->p->seed, sweep, UINT64_MAX - 1));
    for (b = 0; b < nb; b++) {
        size_t lo = b * n / nb, hi = (b + 1) * n / nb, i;
        for (i = hi; i > lo + 1; i--) {
            size_t k = lo + (size_t)cvm__rng_below(&r, i - lo);
            int32_t x = D->list[i - 1];
            D->list[i - 1] = D->list[k];
            D->list[k] = x;
        }
    }
    return n;
}

/* Smallest sin^2 of an angle of triangle t (plain doubles), at most 1. */
static double tri_min_sin2(const cvm__tri2 *T, int32_t t)
{
    const int32_t *v = T->tv + 3 * (size_t)t;
    double m = cvm__min_sin2_corners(T->xy + 2 * (size_t)v[0], T->xy + 2 * (size_t)v[1],
                                     T->xy + 2 * (size_t)v[2]);
    return m < 1.0 ? m : 1.0;
}

/* Order of a max-min round into D->list: the domain triangles whose smallest
 * angle is below the smallest over the mesh + MM_BAND_DEG (that smallest, in
 * degrees, into D->mm_min), smallest first (ties by slot; the key is kept in
 * D->F, which the phase does not otherwise read). Returns the length. */
static size_t mm_order(dopt *D)
{
    cvm__tri2 *T = D->T;
    size_t t, n = 0;
    double m = 1.0, g;
    for (t = 0; t < T->nt; t++) {
        if (!cvm__tri2_in_domain(T, (int32_t)t))
            continue;
        D->F[t] = tri_min_sin2(T, (int32_t)t);
        m = D->F[t] < m ? D->F[t] : m;
    }
    D->mm_min = asin(sqrt(m)) * (180.0 / CVM__PI);
    g = D->mm_min + MM_BAND_DEG < 90.0 ? sin((D->mm_min + MM_BAND_DEG) * CVM__PI / 180.0) : 1.0;
    g *= g;
    for (t = 0; t < T->nt; t++) {
        const int32_t *tv = T->tv + 3 * t;
        if (!cvm__tri2_in_domain(T, (int32_t)t) || !(D->F[t] < g) ||
            (D->region_on && !D->region[tv[0]] && !D->region[tv[1]] && !D->region[tv[2]]))
            continue;
        D->F[t] = -D->F[t];
        D->list[n++] = (int32_t)t;
    }
    sort_list(D->list, D->star, n, D->F, D->st);
    return n;
}

static void save_state(dopt *D)
{
    cvm__tri2 *T = D->T;
    size_t v;
    for (v = 0; v < T->nv; v++) {
        D->save[3 * v] = T->xy[2 * v];
        D->save[3 * v + 1] = T->xy[2 * v + 1];
        D->save[3 * v + 2] = T->w[v];
    }
}

static void load_state(dopt *D)
{
    cvm__tri2 *T = D->T;
    size_t v;
    for (v = 0; v < T->nv; v++) {
        T->xy[2 * v] = D->save[3 * v];
        T->xy[2 * v + 1] = D->save[3 * v + 1];
        T->w[v] = D->save[3 * v + 2];
    }
}

static double progress(const dopt *D)
{
    return D->nc0 ? 1.0 - (double)D->nc / (double)D->nc0 : 1.0;
}

/* The report's non-compliant %, as CVM_MEASURE_DUAL_NONCOMPLIANT_PCT measures
 * it: with the mesh's own sizes, where the sweeps may score with the sizing.
 * D->V must be current; D->save (free at both calls) holds the sizes. */
static double pct(dopt *D)
{
    size_t t, n = 0, nc = 0;
    cvm__dual_mesh_sizes(D->T, D->save);
    for (t = 0; t < D->T->nt; t++)
        if (cvm__tri2_in_domain(D->T, (int32_t)t)) {
            n++;
            nc += cvm__dual_tri_compliance(D->T, D->save, D->p->merge_tol, D->V, (int32_t)t) ==
                  CVM__DUAL_NONCOMPLIANT;
        }
    return n ? 100.0 * (double)nc / (double)n : 0.0;
}

/* Add v to the batch being formed when no vertex of the batch is v or one of
 * its neighbours (so the batch's local problems share no vertex that moves):
 * gather its star into the pool and stamp its star's vertices. 0: blocked. */
static int batch_add(dopt *D, int32_t v, size_t *nb, size_t *used)
{
    const cvm__tri2 *T = D->T;
    job *J = D->jobs + *nb;
    size_t k;
    if (D->stamp[v] == D->cur_stamp)
        return 0;
    J->v = v;
    J->star0 = *used;
    J->nstar = gather_star(D, v, D->star + *used);
    for (k = 0; k < J->nstar; k++) {
        const int32_t *tv = T->tv + 3 * (size_t)D->star[*used + k];
        int c;
        for (c = 0; c < 3; c++)
            if (tv[c] != CVM__GHOST && D->stamp[tv[c]] == D->cur_stamp) {
                J->nstar = 0; /* a neighbour is in the batch: v waits */
                return 0;
            }
    }
    for (k = 0; k < J->nstar; k++) {
        const int32_t *tv = T->tv + 3 * (size_t)D->star[*used + k];
        int c;
        for (c = 0; c < 3; c++)
            if (tv[c] != CVM__GHOST)
                D->stamp[tv[c]] = D->cur_stamp;
    }
    D->stamp[v] = D->cur_stamp;
    *used += J->nstar;
    ++*nb;
    return 1;
}

/* One sweep; *moved_out receives the number of accepted moves. The visiting
 * order is cut into batches of at most BATCH vertices, no two of them equal or
 * adjacent, taken in order from the sorted list (a vertex that would join a
 * batch holding one of its neighbours closes the batch). The local problems of
 * a batch are independent, so they are solved in parallel; the moves are
 * then applied and re-scored in batch order. Batches depend only on the mesh
 * and the order, never on the thread count, so the result does not either. */
static cvm_status sweep(dopt *D, uint64_t k, size_t *moved_out)
{
    cvm__tri2 *T = D->T;
    size_t n = D->mm ? mm_order(D) : sweep_order(D, k), i = 0, moved = 0;
    cvm_status s = CVM_OK;
    memset(D->mark, 0, T->nv);
    while (i < n && !s) {
        size_t nb = 0, used = 0, b;
        int closed = 0;
        D->cur_stamp++;
        while (i < n && nb < BATCH && !closed) {
            int32_t t = D->list[i];
            int j;
            if ((!D->mm && D->st[t] != CVM__DUAL_NONCOMPLIANT && !D->weak[t]) ||
                !cvm__tri2_in_domain(T, t)) {
                i++;
                continue;
            }
            for (j = 0; j < 3 && !closed; j++) {
                int32_t v = T->tv[3 * (size_t)t + (size_t)j];
                if (D->mark[v])
                    continue;
                if (nb == BATCH || !batch_add(D, v, &nb, &used))
                    closed = 1;
                else
                    D->mark[v] = 1;
            }
            if (!closed)
                i++;
        }
        {
            long kk, nbl = (long)nb;
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 8) num_threads(D->nthreads) if (nb > 16)
#endif
            for (kk = 0; kk < nbl; kk++)
                solve_job(D, D->jobs + kk, k);
        }
        for (b = 0; b < nb && !s; b++) {
            apply_job(D, D->jobs + b);
            moved += (size_t)D->jobs[b].moved;
            s = cvm__tick(T->ctx, 1, CVM_STAGE_OPTIMISE_DUAL, progress(D));
        }
    }
    *moved_out = moved;
    return s;
}

static double min_angle(const dopt *D);

/* Go back to the best state kept by keep_best when it beats the current one
 * and has the same vertices: its positions and weights, made regular again
 * (the regular triangulation of a weighted point set is unique, so this is
 * the triangulation it had). The flips since then may have made triangles that
 * the old positions turn over (around clusters of nearly coincident points);
 * flips cannot untangle that, so the run then keeps its current state. */
static cvm_status end_at_best(dopt *D, size_t best_nc, double best_min)
{
    size_t v;
    if (D->best_nv != D->T->nv || D->best_removed != D->rep->removed_vanished + D->rep->removed_degree + D->rep->removed_maxmin)
        return CVM_OK;
    if (!(best_nc < D->nc || (best_nc == D->nc && best_min > min_angle(D) + BEST_EPS_DEG)))
        return CVM_OK;
    save_state(D);
    for (v = 0; v < D->T->nv; v++) {
        D->T->xy[2 * v] = D->best[3 * v];
        D->T->xy[2 * v + 1] = D->best[3 * v + 1];
        D->T->w[v] = D->best[3 * v + 2];
    }
    if (!cvm__tri2_all_ccw(D->T)) {
        load_state(D);
        return CVM_OK;
    }
    return restore(D);
}

/* Smallest angle over the domain triangles, degrees (a measure). */
static double min_angle(const dopt *D)
{
    const cvm__tri2 *T = D->T;
    size_t t;
    double best = 180.0;
    for (t = 0; t < T->nt; t++) {
        const int32_t *v = T->tv + 3 * t;
        double a;
        if (!cvm__tri2_in_domain(T, (int32_t)t))
            continue;
        a = cvm__tri_min_angle_deg(T->xy + 2 * (size_t)v[0], T->xy + 2 * (size_t)v[1],
                                   T->xy + 2 * (size_t)v[2]);
        if (a < best)
            best = a;
    }
    return best;
}

/* The best state so far (see run): fewest non-compliant, then largest
 * smallest angle. 1 when the current state is better (and is now the best). */
static int keep_best(dopt *D, size_t *best_nc, double *best_min)
{
    double mn = min_angle(D);
    size_t v;
    if (!(D->nc < *best_nc || (D->nc == *best_nc && mn > *best_min + BEST_EPS_DEG)))
        return 0;
    *best_nc = D->nc;
    *best_min = mn;
    for (v = 0; v < D->T->nv; v++) {
        D->best[3 * v] = D->T->xy[2 * v];
        D->best[3 * v + 1] = D->T->xy[2 * v + 1];
        D->best[3 * v + 2] = D->T->w[v];
    }
    D->best_nv = D->T->nv;
    D->best_removed = D->rep->removed_vanished + D->rep->removed_degree + D->rep->removed_maxmin;
    return 1;
}

/* The max-min-angle phase, once every triangle is compliant: rounds over the
 * vertices of the triangles whose smallest angle is below the current
 * smallest + MM_BAND_DEG, smallest first, each solving max over its degrees
 * of freedom of its star's smallest angle with every star triangle kept
 * compliant with a slack and dual edges kept long
 * (cvm__dopt_eval_maxmin), the star regular (so no flip follows a move;
 * restore() still runs as a safety net) and a move that made a triangle
 * non-compliant (exact test) undone. The smallest angle never drops; the
 * phase ends after p->maxmin_rounds rounds, a round that moves nothing, or
 * MM_PATIENCE rounds without MM_PROGRESS_DEG gain. */
/* The whole triangulation (and the caller's vertex map) before a removal
 * trial: vertices are only removed and triangles only killed or flipped
 * during a trial, so the arrays keep their capacity and copying back
 * restores it exactly. */
typedef struct snap {
    double *xy, *w, *ta;
    int32_t *vtri, *tv, *tn, *te, *vmap;
    uint8_t *tf;
    size_t nv, nt, n_dead, cap_nv, cap_nt;
    int32_t free_head, last;
    cvm__dual_opt_report rep;
} snap;

static void snap_free(cvm__ctx *ctx, snap *S)
{
    if (!S)
        return;
    cvm__free(ctx, S->xy);
    cvm__free(ctx, S->w);
    cvm__free(ctx, S->ta);
    cvm__free(ctx, S->vtri);
    cvm__free(ctx, S->tv);
    cvm__free(ctx, S->tn);
    cvm__free(ctx, S->te);
    cvm__free(ctx, S->vmap);
    cvm__free(ctx, S->tf);
    cvm__free(ctx, S);
}

/* Copy the arrays of the triangulation (and the vertex map) into the
 * snapshot, or back from it (back = 1), for the snapshot's counts. */
static void snap_copy(dopt *D, int back)
{
    cvm__tri2 *T = D->T;
    snap *S = D->snap;
    size_t nt = S->nt, nv = S->nv;
#define SNAP_COPY(t, s, bytes) ((back) ? memcpy((t), (s), (bytes)) : memcpy((s), (t), (bytes)))
    SNAP_COPY(T->xy, S->xy, 2 * nv * sizeof *S->xy);
    SNAP_COPY(T->w, S->w, nv * sizeof *S->w);
    SNAP_COPY(T->vtri, S->vtri, nv * sizeof *S->vtri);
    SNAP_COPY(T->tv, S->tv, 3 * nt * sizeof *S->tv);
    SNAP_COPY(T->tn, S->tn, 3 * nt * sizeof *S->tn);
    SNAP_COPY(T->tf, S->tf, nt);
    if (T->te)
        SNAP_COPY(T->te, S->te, 3 * nt * sizeof *S->te);
    if (T->ta)
        SNAP_COPY(T->ta, S->ta, nt * sizeof *S->ta);
    if (D->topo)
        SNAP_COPY(D->p->vmap, S->vmap, D->nv0 * sizeof *S->vmap);
#undef SNAP_COPY
}

static cvm_status snap_take(dopt *D)
{
    cvm__tri2 *T = D->T;
    cvm__ctx *ctx = T->ctx;
    snap *S = D->snap;
    size_t nv = T->nv, nt = T->nt;
    if (S && (S->cap_nv < nv || S->cap_nt < nt)) {
        snap_free(ctx, S);
        D->snap = S = NULL;
    }
    if (!S) {
        S = cvm__calloc(ctx, 1, sizeof *S);
        if (!S)
            return CVM_E_NOMEM;
        D->snap = S; /* S->nv 0: nothing to go back to yet */
        S->cap_nv = nv;
        S->cap_nt = nt;
        S->xy = cvm__malloc(ctx, (2 * nv + 1) * sizeof *S->xy);
        S->w = cvm__malloc(ctx, (nv + 1) * sizeof *S->w);
        S->vtri = cvm__malloc(ctx, (nv + 1) * sizeof *S->vtri);
        S->tv = cvm__malloc(ctx, (3 * nt + 1) * sizeof *S->tv);
        S->tn = cvm__malloc(ctx, (3 * nt + 1) * sizeof *S->tn);
        S->tf = cvm__malloc(ctx, nt + 1);
        S->te = T->te ? cvm__malloc(ctx, (3 * nt + 1) * sizeof *S->te) : NULL;
        S->ta = T->ta ? cvm__malloc(ctx, (nt + 1) * sizeof *S->ta) : NULL;
        S->vmap = D->topo ? cvm__malloc(ctx, (D->nv0 + 1) * sizeof *S->vmap) : NULL;
        if (!S->xy || !S->w || !S->vtri || !S->tv || !S->tn || !S->tf || (T->te && !S->te) ||
            (T->ta && !S->ta) || (D->topo && !S->vmap))
            return CVM_E_NOMEM; /* D->snap is freed by the caller */
    }
    S->nv = nv;
    S->nt = nt;
    S->n_dead = T->n_dead;
    S->free_head = T->free_head;
    S->last = T->last;
    S->rep = *D->rep;
    snap_copy(D, 0);
    return CVM_OK;
}

static void snap_back(dopt *D)
{
    cvm__tri2 *T = D->T;
    const snap *S = D->snap;
    double seconds = D->rep->seconds;
    T->nv = S->nv;
    T->nt = S->nt;
    T->n_dead = S->n_dead;
    T->free_head = S->free_head;
    T->last = S->last;
    *D->rep = S->rep;
    D->rep->seconds = seconds;
    snap_copy(D, 1);
}

static cvm_status mm_rounds(dopt *D, uint64_t k0, int rounds, size_t *best_nc, double *best_min,
                                int *stalled);

/* Mark in D->region the n vertices seed[] and RM_RINGS rings of neighbours
 * around them (breadth first; D->list is the queue, D->star scratch). */
static void mark_region(dopt *D, const int32_t *seed, size_t n)
{
    cvm__tri2 *T = D->T;
    size_t head = 0, tail = 0, ring_end, i;
    int ring;
    memset(D->region, 0, T->nv);
    for (i = 0; i < n; i++)
        if (seed[i] >= 0 && !D->region[seed[i]]) {
            D->region[seed[i]] = 1;
            D->list[tail++] = seed[i];
        }
    for (ring = 0; ring < RM_RINGS; ring++) {
        ring_end = tail;
        while (head < ring_end) {
            int32_t v = D->list[head++];
            size_t ns = gather_star(D, v, D->star), k;
            for (k = 0; k < ns; k++) {
                const int32_t *tv = T->tv + 3 * (size_t)D->star[k];
                int c;
                for (c = 0; c < 3; c++)
                    if (tv[c] != CVM__GHOST && !D->region[tv[c]]) {
                        D->region[tv[c]] = 1;
                        D->list[tail++] = tv[c];
                    }
            }
        }
    }
}

/* Number of domain triangles with an angle below deg degrees (plain doubles). */
static size_t count_below(const dopt *D, double deg)
{
    const cvm__tri2 *T = D->T;
    double g = sin(deg * CVM__PI / 180.0);
    size_t t, n = 0;
    g *= g;
    for (t = 0; t < T->nt; t++)
        n += cvm__tri2_in_domain(T, (int32_t)t) && tri_min_sin2(T, (int32_t)t) < g;
    return n;
}

/* Removal trials of the max-min phase (with p->topology and its vertex map):
 * for the triangles within RM_BAND_DEG of the smallest angle, up to RM_TRIES
 * removable Steiner vertices (cvm__dual_removable) - first the least-degree
 * neighbour of each hub (see below), then the triangles' corners, highest
 * degree first, lower index on ties; none at a position whose trial failed
 * before (D->failed) - are removed one at a time; up to RM_SWEEPS sweeps over
 * the non-compliant triangles make every triangle compliant again and up to
 * RM_ROUNDS max-min rounds over RM_RINGS rings around the vertex follow. The
 * result is kept when every triangle is compliant and the smallest angle
 * rose by MM_PROGRESS_DEG, or did not drop and fewer triangles lie within
 * MM_PROGRESS_DEG of it; else the triangulation goes back to its snapshot.
 * Stops at the first kept trial (*kept_out 1). Deterministic: the order and
 * the sweeps depend only on the mesh. */
static cvm_status removal_trials(dopt *D, uint64_t k0, size_t *best_nc, double *best_min, int *kept_out)
{
    cvm__tri2 *T = D->T;
    int32_t cand[RM_TRIES], nb[RM_MAXNB];
    size_t n, i, nc = 0, t, cdeg[RM_TRIES], nnb = 0, nlow0;
    double g, gmin = min_angle(D), target = D->sin2_target;
    cvm_status s = CVM_OK;
    *kept_out = 0;
    if (!D->topo)
        return CVM_OK;
    g = sin((gmin + RM_BAND_DEG) * CVM__PI / 180.0);
    g *= g;
    /* candidates: the removable Steiner neighbour of least degree of each hub
     * (an interior vertex of RM_HUB_DEG or more triangles at the smallest
     * angle of a worst triangle: it caps that angle at 360 / its degree),
     * mark 2; the removable Steiner corners of the worst triangles, mark 1 */
    memset(D->mark, 0, T->nv);
    for (t = 0; t < T->nt; t++) {
        const int32_t *tv = T->tv + 3 * t;
        double l2[3];
        int j, c = 0;
        size_t ns;
        if (!cvm__tri2_in_domain(T, (int32_t)t) || !(tri_min_sin2(T, (int32_t)t) < g))
            continue;
        for (j = 0; j < 3; j++) {
            const double *p = T->xy + 2 * (size_t)tv[(j + 1) % 3], *q = T->xy + 2 * (size_t)tv[(j + 2) % 3];
            l2[j] = sq(p[0] - q[0]) + sq(p[1] - q[1]);
            c = l2[j] < l2[c] ? j : c; /* the smallest angle is opposite the shortest edge */
            if (D->mark[tv[j]] < 1)
                D->mark[tv[j]] = 1;
        }
        if (D->vbnd[tv[c]] || (ns = gather_star(D, tv[c], D->star)) < RM_HUB_DEG)
            continue;
        {
            int32_t best = -1;
            size_t bdeg = 0, q;
            for (q = 0; q < ns; q++) {
                const int32_t *sv = T->tv + 3 * (size_t)D->star[q];
                int e;
                for (e = 0; e < 3; e++) {
                    int32_t x = sv[e];
                    size_t dx;
                    if (x == CVM__GHOST || x == tv[c] || (size_t)x < D->p->n_input ||
                        !cvm__dual_removable(T, x, &dx))
                        continue;
                    if (best < 0 || dx < bdeg || (dx == bdeg && x < best)) {
                        best = x;
                        bdeg = dx;
                    }
                }
            }
            if (best >= 0)
                D->mark[best] = 2;
        }
    }
    for (i = D->p->n_input; i < T->nv; i++) {
        size_t deg, q, f;
        if (!D->mark[i] || !cvm__dual_removable(T, (int32_t)i, &deg))
            continue;
        for (f = 0; f < D->nfailed; f++)
            if (D->failed[2 * f] == T->xy[2 * i] && D->failed[2 * f + 1] == T->xy[2 * i + 1])
                break;
        if (f < D->nfailed)
            continue; /* tried at this very position before, and failed */
        /* keep the RM_TRIES best: mark 2 before 1, then the higher degree, then
         * the lower index (earlier in this loop) */
        for (q = nc; q > 0 && (D->mark[cand[q - 1]] < D->mark[i] ||
                               (D->mark[cand[q - 1]] == D->mark[i] && cdeg[q - 1] < deg)); q--)
            if (q < RM_TRIES) {
                cand[q] = cand[q - 1];
                cdeg[q] = cdeg[q - 1];
            }
        if (q < RM_TRIES) {
            cand[q] = (int32_t)i;
            cdeg[q] = deg;
            nc += nc < RM_TRIES;
        }
    }
    nlow0 = count_below(D, gmin + MM_PROGRESS_DEG);
    /* trials aim at the target the caller set, not at a raised one */
    D->sin2_target = sin(D->p->target_angle_deg * CVM__PI / 180.0);
    D->sin2_target *= D->sin2_target;
    for (n = 0; n < nc && !s; n++) {
        size_t k, moved;
        int stalled;
        double mn;
        if ((s = snap_take(D)))
            break;
        {
            /* its neighbours, to seed the region of the trial's rounds */
            size_t ns = gather_star(D, cand[n], D->star), q;
            nnb = 0;
            for (q = 0; q < ns && nnb < RM_MAXNB; q++) {
                const int32_t *tv = T->tv + 3 * (size_t)D->star[q];
                int c;
                for (c = 0; c < 3; c++)
                    if (tv[c] != CVM__GHOST && tv[c] != cand[n] && nnb < RM_MAXNB)
                        nb[nnb++] = tv[c];
            }
        }
        if (!cvm__dual_remove_vertex(T, cand[n], -1))
            continue;
        D->gone[cand[n]] = 1;
        D->rep->removed_maxmin++;
        compact(D);
        for (i = 0; i < nnb; i++)
            nb[i] = D->map2[nb[i]];
        if ((s = restore(D)))
            break;
        for (k = 0; k < RM_SWEEPS && !s; k++) {
            if ((s = sizes(D)))
                break;
            boundary_flags(D);
            cvm__dual_layers(T, D->vbnd, D->layer, D->list);
            score_all(D);
            if (!D->nc)
                break;
            D->nc_only = 1;
            s = sweep(D, k0 + 1000 * (n + 1) + k, &moved);
            D->nc_only = 0;
            if (s || (s = restore(D)))
                break;
        }
        if (s)
            break;
        score_all(D);
        if (!D->nc) {
            mark_region(D, nb, nnb);
            D->region_on = 1;
            s = mm_rounds(D, k0 + 1000 * (n + 1) + 100, RM_ROUNDS, NULL, NULL, &stalled);
            D->region_on = 0;
            if (s)
                break;
            score_all(D);
        }
        mn = D->nc ? -1.0 : min_angle(D);
        if (mn > gmin + MM_PROGRESS_DEG || (mn >= gmin && count_below(D, gmin + MM_PROGRESS_DEG) < nlow0)) {
            *best_nc = (size_t)-1; /* the old best had other vertices */
            keep_best(D, best_nc, best_min);
            *kept_out = 1;
            break;
        }
        snap_back(D);
        if (D->nfailed < RM_FAILED) {
            D->failed[2 * D->nfailed] = T->xy[2 * (size_t)cand[n]];
            D->failed[2 * D->nfailed + 1] = T->xy[2 * (size_t)cand[n] + 1];
            D->nfailed++;
        }
        if ((s = sizes(D)))
            break;
        boundary_flags(D);
        score_all(D);
    }
    if (s && n < nc && D->snap && D->snap->nv) {
        /* out of memory or stopped inside a trial: back to its regular start */
        snap_back(D);
        score_all(D);
    }
    D->sin2_target = target;
    return s;
}

/* Up to rounds max-min rounds (see maxmin_phase); with best_nc, keep_best
 * follows the last. Moves keep every triangle compliant and the
 * triangulation regular, and no star's smallest angle drops, so the
 * per-triangle state is kept up to date by the moves alone and one restore()
 * at the end is only a safety net. *stalled: 1 when the rounds ended because
 * a round moved nothing or MM_PATIENCE rounds gained less than
 * MM_PROGRESS_DEG. Needs sizes, boundary flags and scores up to date. */
static cvm_status mm_rounds(dopt *D, uint64_t k0, int rounds, size_t *best_nc, double *best_min,
                                int *stalled)
{
    cvm_status s = CVM_OK;
    int r, stall = 0;
    double last = -1.0;
    *stalled = 0;
    for (r = 0; r < rounds && !D->nc; r++) {
        size_t moved = 0;
        D->mm = 1;
        s = sweep(D, k0 + (uint64_t)r, &moved); /* its order (mm_order) sets D->mm_min */
        D->mm = 0;
        D->rep->moves += moved;
        D->rep->maxmin_rounds++;
        if (s)
            break;
        if (D->mm_min > last + MM_PROGRESS_DEG) {
            last = D->mm_min;
            stall = 0;
        } else if (++stall >= MM_PATIENCE) {
            *stalled = 1;
            break;
        }
        if (!moved) {
            *stalled = 1;
            break;
        }
    }
    D->mm = 0;
    if (!s && !(s = restore(D))) {
        score_all(D);
        if (best_nc)
            keep_best(D, best_nc, best_min);
    }
    return s;
}

static cvm_status maxmin_phase(dopt *D, uint64_t k0, size_t *best_nc, double *best_min)
{
    cvm_status s;
    int calls, stalled = 0, kept = 1;
    if ((s = sizes(D)))
        return s;
    boundary_flags(D);
    score_all(D);
    if (D->nc)
        return CVM_OK;
    if ((s = mm_rounds(D, k0, D->p->maxmin_rounds, best_nc, best_min, &stalled)) || D->p->maxmin_trials <= 0)
        return s;
    /* the trials follow the rounds when asked for, stalled or not (at the
     * default 10 rounds the shared meshes end by the count); a kept trial's
     * rounds ran to a stall around it, so the next trials follow at once */
    for (calls = 0; calls < D->p->maxmin_trials && kept && !s; calls++)
        s = removal_trials(D, k0 + (uint64_t)D->p->maxmin_rounds + 100000 * (uint64_t)calls, best_nc,
                           best_min, &kept);
    return s;
}

static cvm_status run(dopt *D)
{
    const cvm__dual_opt_params *p = D->p;
    cvm_status s, s2;
    uint64_t k;
    size_t best_nc = (size_t)-1, stall = 0;
    double best_min = -1.0;
    int phase = 0;
    double prog_min;
    size_t weak_low = (size_t)-1; /* fewest weak triangles at a progress mark */
    if ((s = sizes(D)))
        return s;
    boundary_flags(D);
    if ((s = restore(D)))
        return s;
    cvm__dual_layers(D->T, D->vbnd, D->layer, D->list);
    score_all(D);
    D->nc0 = D->nc;
    D->rep->nc_before_pct = pct(D);
    keep_best(D, &best_nc, &best_min);
    prog_min = best_min;
    for (k = 0; k < (uint64_t)p->max_sweeps && (D->nc || D->nweak); k++) {
        size_t moved = 0, nc_prev, flips0, rem0;
        int better;
        if ((s = sizes(D)))
            return s;
        boundary_flags(D);
        cvm__dual_layers(D->T, D->vbnd, D->layer, D->list);
        score_all(D);
        if (!D->nc && !D->nweak)
            break;
        nc_prev = D->nc;
        save_state(D);
        s = sweep(D, k, &moved);
        D->rep->moves += moved;
        D->rep->sweeps++;
        flips0 = D->rep->flips;
        rem0 = D->rep->removed_vanished;
        if ((s2 = restore(D))) {
            /* out of memory: without a flip, go back to the regular state of the
             * sweep's start; after flips the topology follows the new positions,
             * which stay (conforming, counter-clockwise, maybe not regular) */
            if (D->rep->flips == flips0 && D->rep->removed_vanished == rem0)
                load_state(D);
            return s2;
        }
        if (s)
            return s;
        score_all(D);
        if (D->topo && D->p->topology >= 2 && k < DEG_SWEEPS) {
            size_t nrem = repair_degrees(D);
            if (nrem) {
                D->rep->removed_degree += nrem;
                compact(D);
                if ((s = restore(D)))
                    return s;
                score_all(D);
                best_nc = (size_t)-1; /* the old best had other vertices */
                keep_best(D, &best_nc, &best_min);
                continue; /* the topology changed: sweep again */
            }
        }
        keep_best(D, &best_nc, &best_min);
        better = best_min > prog_min + PROGRESS_DEG;
        if (better)
            prog_min = best_min;
        /* stop when nothing moved, or when everything is compliant and for
         * PATIENCE sweeps neither the smallest angle improved by PROGRESS_DEG
         * nor the weak triangles dropped 1% below their last low; then the
         * target angle is raised (PUSHES times) before the run ends */
        if (!moved)
            break;
        if (!D->nc && !nc_prev) {
            if (better || 100 * D->nweak < 99 * weak_low) {
                stall = 0;
                weak_low = D->nweak < weak_low ? D->nweak : weak_low;
            } else if (++stall >= (phase ? PUSH_PATIENCE : PATIENCE)) {
                double push = p->target_angle_deg + PUSH_DEG * (phase + 1);
                if (phase >= PUSHES || !(p->target_angle_deg > 0) || push > 60.0)
                    break;
                /* next phase: a higher target angle; keep_best keeps the best end */
                phase++;
                stall = 0;
                D->sin2_target = sin(push * CVM__PI / 180.0);
                D->sin2_target *= D->sin2_target;
            }
        }
    }
    if ((s = end_at_best(D, best_nc, best_min)))
        return s;
    if (p->maxmin_rounds > 0 && p->max_sweeps > 0 && !D->nc) {
        score_all(D);
        if (!D->nc && (s = maxmin_phase(D, k, &best_nc, &best_min)))
            return s;
        return end_at_best(D, best_nc, best_min);
    }
    return CVM_OK;
}

cvm_status cvm__dual_optimise(cvm__tri2 *T, const cvm__dual_opt_params *p, cvm__dual_opt_report *rep)
{
    cvm__ctx *ctx = T->ctx;
    dopt D;
    size_t nv = T->nv, nt = T->nt;
    double t0 = cvm__now();
    cvm_status s;
    memset(rep, 0, sizeof *rep);
    memset(&D, 0, sizeof D);
    D.T = T;
    D.p = p;
    D.rep = rep;
    D.sin2_min = sin(p->min_angle_deg * CVM__PI / 180.0);
    D.sin2_min *= D.sin2_min;
    D.nthreads = p->threads;
#ifdef _OPENMP
    if (D.nthreads <= 0)
        D.nthreads = omp_get_max_threads();
#endif
    if (D.nthreads <= 0)
        D.nthreads = 1;
    D.sin2_target = sin(p->target_angle_deg * CVM__PI / 180.0);
    D.sin2_target *= D.sin2_target;
    if (!T->w) {
        T->w = cvm__calloc(ctx, T->cap_v ? T->cap_v : 1, sizeof *T->w);
        if (!T->w)
            return CVM_E_NOMEM;
    }
    if (p->topology && p->vmap) {
        size_t v;
        for (v = 0; v < nv; v++)
            p->vmap[v] = (int32_t)v;
    }
    D.nv0 = nv;
    if (p->prepass && p->topology && p->vmap) {
        /* before the per-vertex and per-triangle arrays: counts may change */
        if ((s = cvm__dual_prepass(T, p, nv, &rep->prepass_removed, &rep->prepass_added))) {
            rep->seconds = cvm__now() - t0;
            return s;
        }
        nv = T->nv;
        nt = T->nt;
    }
    D.vsize = cvm__malloc(ctx, (nv + 1) * sizeof *D.vsize);
    D.vbnd = cvm__malloc(ctx, nv + 1);
    D.mark = cvm__malloc(ctx, nv + 1);
    D.V = cvm__malloc(ctx, (2 * nt + 1) * sizeof *D.V);
    D.F = cvm__malloc(ctx, (nt + 1) * sizeof *D.F);
    D.st = cvm__calloc(ctx, nt + 1, 1);
    D.weak = cvm__calloc(ctx, nt + 1, 1);
    D.layer = cvm__calloc(ctx, nt + 1, sizeof *D.layer);
    D.list = cvm__malloc(ctx, (nt + 1) * sizeof *D.list);
    D.star = cvm__malloc(ctx, (nt + 1) * sizeof *D.star);
    D.save = cvm__malloc(ctx, (3 * nv + 1) * sizeof *D.save);
    D.best = cvm__malloc(ctx, (3 * nv + 1) * sizeof *D.best);
    D.jobs = cvm__malloc(ctx, BATCH * sizeof *D.jobs);
    D.stamp = cvm__calloc(ctx, nv + 1, sizeof *D.stamp);
    D.region = cvm__calloc(ctx, nv + 1, 1);
    D.topo = p->topology && p->vmap;
    if (D.topo) {
        D.gone = cvm__calloc(ctx, nv + 1, 1);
        D.dup = cvm__malloc(ctx, (nv + 1) * sizeof *D.dup);
        D.map2 = cvm__malloc(ctx, (nv + 1) * sizeof *D.map2);
    }
    if (!D.vsize || !D.vbnd || !D.mark || !D.V || !D.F || !D.st || !D.weak || !D.layer || !D.list || !D.star || !D.save || !D.best || !D.jobs ||
        !D.stamp || !D.region || (D.topo && (!D.gone || !D.dup || !D.map2)))
        s = CVM_E_NOMEM;
    else
        s = run(&D);
    if (D.V && D.st && D.weak && D.layer && D.F && D.vsize && D.vbnd && D.save) {
        score_all(&D);
        rep->nc_after_pct = pct(&D);
        if (!rep->sweeps && !D.nc0)
            rep->nc_before_pct = rep->nc_after_pct;
    }
    cvm__free(ctx, D.vsize);
    cvm__free(ctx, D.vbnd);
    cvm__free(ctx, D.mark);
    cvm__free(ctx, D.V);
    cvm__free(ctx, D.F);
    cvm__free(ctx, D.st);
    cvm__free(ctx, D.weak);
    cvm__free(ctx, D.layer);
    cvm__free(ctx, D.list);
    cvm__free(ctx, D.star);
    cvm__free(ctx, D.save);
    cvm__free(ctx, D.best);
    cvm__free(ctx, D.jobs);
    cvm__free(ctx, D.stamp);
    cvm__free(ctx, D.region);
    cvm__free(ctx, D.gone);
    cvm__free(ctx, D.dup);
    cvm__free(ctx, D.map2);
    snap_free(ctx, D.snap);
    rep->seconds = cvm__now() - t0;
    return s;
}
