/* refiner.c - the driver of a refinement run: set-up, the algorithm passes, post-processing and the final report. */
#include <math.h>
#include <string.h>

#include "refine_internal.h"
#include "geom/geom_internal.h"
#include "geom/measure.h"

/* Domain triangle t = (c, a, b) (c at corner j) on a hull edge a-b that no
 * segment covers, with c on the chain of a-b (cvm__rf_on_chain): t and the ghost g
 * across a-b become the ghosts across c-a and b-c, so the hull passes through
 * c, reflex by a rounding error, as a segment's chain passes through a
 * rounded crossing. The hull edges a-c and c-b are constrained afterwards
 * (rf_constrain_hull), so no cavity crosses the reflex corner. */
static void rf_hull_through(cvm__tri2 *T, int32_t t, int j)
{
    size_t ht = 3 * (size_t)t;
    int32_t hg = T->tn[ht + (size_t)j], g = hg / 3, c = T->tv[ht + (size_t)j];
    int32_t a = T->tv[ht + (size_t)(j + 1) % 3], b = T->tv[ht + (size_t)(j + 2) % 3];
    int k = hg % 3;
    size_t gg = 3 * (size_t)g;
    int32_t hp = T->tn[gg + (size_t)(k + 1) % 3]; /* the ghost beyond a */
    int32_t hn2 = T->tn[ht + (size_t)(j + 1) % 3]; /* the domain triangle beyond b-c */
    int32_t seg_bc = T->te[ht + (size_t)(j + 1) % 3];
    /* t -> ghost (c, a, -): b's corner becomes the ghost vertex */
    T->tv[ht + (size_t)(j + 2) % 3] = CVM__GHOST;
    /* g -> ghost (-, b, c): a's corner becomes c */
    T->tv[gg + (size_t)(k + 2) % 3] = c;
    /* t's edge a-(-) faces the ghost beyond a */
    T->tn[ht + (size_t)j] = hp;
    T->tn[hp] = (int32_t)(ht + (size_t)j);
    T->te[ht + (size_t)j] = -1;
    /* t's edge (-)-c and g's edge c-(-) face each other */
    T->tn[ht + (size_t)(j + 1) % 3] = (int32_t)(gg + (size_t)(k + 1) % 3);
    T->tn[gg + (size_t)(k + 1) % 3] = (int32_t)(ht + (size_t)(j + 1) % 3);
    T->te[ht + (size_t)(j + 1) % 3] = -1;
    T->te[gg + (size_t)(k + 1) % 3] = -1;
    /* g's edge b-c faces the domain triangle that t's did */
    T->tn[gg + (size_t)k] = hn2;
    T->tn[hn2] = (int32_t)(gg + (size_t)k);
    T->te[gg + (size_t)k] = seg_bc;
    T->tf[t] = T->tf[g];
    T->vtri[a] = t;
    T->vtri[b] = g;
    T->vtri[c] = t;
    T->last = t;
}

/* Route the hull through every vertex on the chain of a hull edge
 * (rf_hull_through), until none is left. Kept, the flat triangle between such
 * an edge and its vertex is a wedge of a vanishing angle: no rounded point
 * splits the edge or the segments at the vertex, so the triangles beside them
 * could never be refined. A hull edge that is a piece of input segment s is
 * routed only when the vertex is also on the chain of s; the two new hull
 * edges then become pieces of s (unless another segment holds them), so the
 * vertex, where another segment typically ends within rounding of s, is where
 * the two meet, and the shells of the small-angle rule are centred there. */
static void rf_hull_through_flat(cvm__refiner *R)
{
    cvm__tri2 *T = R->T;
    size_t t, rounds;
    int j, again = 1;
    for (rounds = 0; again && rounds <= T->nt; rounds++) {
        again = 0;
        for (t = 0; t < T->nt; t++) {
            if (!cvm__tri2_in_domain(T, (int32_t)t))
                continue;
            for (j = 0; j < 3; j++) {
                size_t h = 3 * t + (size_t)j;
                const int32_t *tv = T->tv + 3 * t;
                int32_t seg = T->te[h], hg = T->tn[h], hca;
                const double *pc = T->xy + 2 * (size_t)tv[j];
                if (!cvm__tri2_is_ghost(T, hg / 3) ||
                    !cvm__rf_on_chain(T->xy + 2 * (size_t)tv[(j + 1) % 3],
                                      T->xy + 2 * (size_t)tv[(j + 2) % 3], pc))
                    continue;
                if (seg >= 0 && ((size_t)seg >= R->nseg || R->seg_ends[2 * (size_t)seg] < 0 ||
                                 R->seg_ends[2 * (size_t)seg + 1] < 0 ||
                                 !cvm__rf_on_chain(T->xy + 2 * (size_t)R->seg_ends[2 * (size_t)seg],
                                                   T->xy + 2 * (size_t)R->seg_ends[2 * (size_t)seg + 1],
                                                   pc)))
                    continue;
                rf_hull_through(T, (int32_t)t, j);
                if (seg >= 0) {
                    /* t = (c, a, ghost): its edge c-a; the ghost across a-b
                     * now holds edge b-c at the corner it had */
                    hca = (int32_t)(3 * t + (size_t)(j + 2) % 3);
                    if (T->te[hca] < 0)
                        T->te[hca] = T->te[T->tn[hca]] = seg;
                    if (T->te[hg] < 0)
                        T->te[hg] = T->te[T->tn[hg]] = seg;
                }
                again = 1;
                break;
            }
        }
    }
}

/* Convex hull edges that no segment covers become segments of their own (ids
 * after the input segments): those of the domain first, so refinement never
 * leaves the hull, then those of triangles outside the domain. A split point on
 * a hull segment may round a few ulps outside its line; the hull then turns
 * reflex at the segment's ends, which cvm__tri2_check accepts only between
 * constrained hull edges (no cavity crosses them), so a hull edge of a carved
 * triangle beside such a segment must be constrained too. */
static cvm_status rf_constrain_hull(cvm__refiner *R)
{
    cvm__tri2 *T = R->T;
    size_t t;
    int j, pass;
    for (pass = 0; pass < 2; pass++)
        for (t = 0; t < T->nt; t++) {
            if (pass == 0 ? !cvm__tri2_in_domain(T, (int32_t)t)
                          : !cvm__tri2_is_live(T, (int32_t)t) || cvm__tri2_is_ghost(T, (int32_t)t) ||
                                cvm__tri2_in_domain(T, (int32_t)t))
                continue;
            for (j = 0; j < 3; j++) {
                size_t h = 3 * t + (size_t)j;
                int32_t nb = T->tn[h] / 3;
                size_t cap = 2 * R->nseg;
                if (T->te[h] >= 0 || !cvm__tri2_is_ghost(T, nb))
                    continue;
                if (R->nseg >= (size_t)INT32_MAX ||
                    cvm__grow(R->ctx, (void **)&R->seg_ends, &cap, 2 * R->nseg + 2, sizeof(int32_t)))
                    return cvm__nomem(R->ctx);
                R->seg_ends[2 * R->nseg] = T->tv[h - (size_t)j + (size_t)(j + 1) % 3];
                R->seg_ends[2 * R->nseg + 1] = T->tv[h - (size_t)j + (size_t)(j + 2) % 3];
                T->te[h] = (int32_t)R->nseg;
                T->te[T->tn[h]] = (int32_t)R->nseg;
                R->nseg++;
            }
        }
    return CVM_OK;
}

/* Route every input segment through each vertex on its chain beside it
 * (cvm__rf_route_through), until none is left: the flat triangle between them
 * is a wedge no split can enter, and the vertex (typically where another
 * segment ends, within rounding of this one) is where the two meet, so the
 * shells of the small-angle rule must be centred there. */
static cvm_status rf_route_through_flat(cvm__refiner *R)
{
    cvm__tri2 *T = R->T;
    size_t t, rounds;
    int j, again = 1;
    cvm_status s;
    for (rounds = 0; again && rounds <= T->nv; rounds++) {
        again = 0;
        for (t = 0; t < T->nt; t++) {
            if (!cvm__tri2_in_domain(T, (int32_t)t))
                continue;
            for (j = 0; j < 3; j++) {
                int32_t seg = T->te[3 * t + (size_t)j];
                int done;
                if (seg < 0 || (size_t)seg >= R->p->nseg)
                    continue;
                if ((s = cvm__rf_route_through(R, (int32_t)t, j, seg, 0, &done)))
                    return s;
                if (done) {
                    again = 1;
                    break;
                }
            }
        }
    }
    return CVM_OK;
}

static cvm_status rf_setup(cvm__refiner *R, cvm__tri2 *T, const cvm__refine_params *p)
{
    size_t v, t;
    double th = p->min_angle_deg * CVM__PI / 180.0;
    cvm_status s;
    memset(R, 0, sizeof *R);
    R->T = T;
    R->ctx = T->ctx;
    R->p = p;
    R->queue_star = cvm__rf_queue_star;
    cvm__bq_init(&R->q, R->ctx);
    R->sin2_min = sin(th) * sin(th);
    R->size2 = 1.0;
    R->lens_cos2 = cos(2 * th) * cos(2 * th);
    if ((s = cvm__tri2_enable_constraints(T)))
        return cvm__nomem(R->ctx);
    R->seg_ends = cvm__malloc(R->ctx, (2 * p->nseg + 2) * sizeof *R->seg_ends);
    if (!R->seg_ends)
        return cvm__nomem(R->ctx);
    if (p->nseg)
        memcpy(R->seg_ends, p->seg_ends, 2 * p->nseg * sizeof *R->seg_ends);
    R->nseg = p->nseg;
    rf_hull_through_flat(R);
    if ((s = rf_constrain_hull(R)))
        return s;
    if (cvm__rf_reserve_vertices(R, T->nv + 1))
        return cvm__nomem(R->ctx);
    for (v = 0; v < T->nv; v++)
        R->vseg[v] = -1;
    /* all at once: a batch sizing callback gets them in few calls */
    if ((s = cvm__sizing_at_many(p->sizing, T->xy, T->nv, R->vls, R->ctx)))
        return s;
    for (t = 0; t < T->nt; t++) {
        int j;
        if (!cvm__tri2_in_domain(T, (int32_t)t))
            continue;
        for (j = 0; j < 3; j++)
            if (T->te[3 * t + (size_t)j] >= 0) {
                R->vseg[T->tv[3 * t + (size_t)(j + 1) % 3]] = -2;
                R->vseg[T->tv[3 * t + (size_t)(j + 2) % 3]] = -2;
            }
    }
    return rf_route_through_flat(R);
}

static void rf_teardown(cvm__refiner *R)
{
    cvm__bq_destroy(&R->q);
    cvm__free(R->ctx, R->seg_ends);
    cvm__free(R->ctx, R->vls);
    cvm__free(R->ctx, R->vseg);
    cvm__free(R->ctx, R->segq);
    cvm__free(R->ctx, R->star);
    cvm__free(R->ctx, R->cav);
    cvm__free(R->ctx, R->enc);
    cvm__rf_aflr_free(R);
}

/* Smallest angle of triangle t in degrees, from its coordinates: the angle
 * opposite the shortest edge (one atan2 instead of three). */
static double rf_min_angle_deg(const cvm__tri2 *T, int32_t t)
{
    const int32_t *tv = T->tv + 3 * (size_t)t;
    double l[3];
    int k, m = 0;
    for (k = 0; k < 3; k++) {
        const double *a = T->xy + 2 * (size_t)tv[(k + 1) % 3];
        const double *b = T->xy + 2 * (size_t)tv[(k + 2) % 3];
        l[k] = cvm__dist2(a, b);
        if (l[k] < l[m])
            m = k;
    }
    {
        const double *o = T->xy + 2 * (size_t)tv[m];
        const double *a = T->xy + 2 * (size_t)tv[(m + 1) % 3];
        const double *b = T->xy + 2 * (size_t)tv[(m + 2) % 3];
        return cvm__corner_angle(o, a, b) * 180.0 / CVM__PI;
    }
}

/* Record where triangle t was left unmet (reason bits CVM_UNMET_*). */
static cvm_status rf_unmet(cvm__refiner *R, cvm__refine_report *rep, size_t *cap, int32_t t,
                           int bits)
{
    const cvm__tri2 *T = R->T;
    const int32_t *tv = T->tv + 3 * (size_t)t;
    double *e;
    int k;
    if (cvm__grow(R->ctx, (void **)&rep->unmet, cap, 3 * (rep->n_unmet + 1), sizeof *rep->unmet))
        return cvm__nomem(R->ctx);
    e = rep->unmet + 3 * rep->n_unmet++;
    e[0] = e[1] = 0;
    for (k = 0; k < 3; k++) {
        e[0] += T->xy[2 * (size_t)tv[k]] / 3;
        e[1] += T->xy[2 * (size_t)tv[k] + 1] / 3;
    }
    e[2] = bits;
    return CVM_OK;
}

static cvm_status rf_report(cvm__refiner *R, cvm__refine_report *rep)
{
    const cvm__tri2 *T = R->T;
    size_t t, cap = 0;
    double best_sin2 = HUGE_VAL;
    rep->steiner = R->steiner;
    rep->met_angle_deg = 180.0;
    for (t = 0; t < T->nt; t++) {
        double key;
        int c, bits = 0;
        if (!cvm__tri2_in_domain(T, (int32_t)t))
            continue;
        c = cvm__rf_classify(R, (int32_t)t, &key);
        if (c == 1) {
            rep->unmet_size++;
            bits |= CVM_UNMET_SIZE;
        }
        if (c == 3) {
            rep->small_angle++;
            bits |= CVM_UNMET_SMALL_INPUT_ANGLE;
        }
        if (c != 3) {
            /* the smallest angle (< 90 degrees) grows with its sine: take the
             * three arc tangents only for triangles that may hold the
             * minimum (the slack covers the rounding of the sine) */
            const int32_t *tv = T->tv + 3 * t;
            double s2 = cvm__min_sin2_ccw(T->xy + 2 * (size_t)tv[0], T->xy + 2 * (size_t)tv[1],
                                         T->xy + 2 * (size_t)tv[2]);
            if (s2 <= best_sin2 * (1 + 1e-6)) {
                double a = rf_min_angle_deg(T, (int32_t)t);
                if (a < rep->met_angle_deg)
                    rep->met_angle_deg = a;
                if (s2 < best_sin2)
                    best_sin2 = s2;
            }
        }
        if (c == 2 || c == 3 ||
            (c == 1 && R->sin2_min > 0 && rf_min_angle_deg(T, (int32_t)t) < R->p->min_angle_deg)) {
            rep->unmet_angle++;
            bits |= CVM_UNMET_ANGLE;
        }
        if (bits && rf_unmet(R, rep, &cap, (int32_t)t, bits))
            return CVM_E_NOMEM;
    }
    return CVM_OK;
}

/* Post-processing (swap.c, smooth.c) of the Steiner vertices first..nv-1:
 * degree swapping, smoothing, then the Delaunay-restoring flips; *changed
 * receives the number of swaps, moves and flips. */
static cvm_status rf_post(cvm__refiner *R, size_t first, size_t *changed)
{
    const cvm__refine_params *p = R->p;
    cvm_status s = CVM_OK;
    cvm_status s2;
    size_t n = 0;
    *changed = 0;
    if (R->T->w)
        return CVM_OK; /* a weighted (regular) triangulation: left as refined */
    if (p->swap) {
        s = cvm__rf_swap_degree(R, &n);
        *changed += n;
    }
    if (!s && p->smooth_sweeps > 0 && p->smooth_method != 1) {
        s = cvm__rf_smooth(R, first, NULL, p->relax_sweeps, p->smooth_sweeps, &n);
        *changed += n;
    }
    if (!s && p->smooth_sweeps > 0 && p->smooth_method != 0) {
        s = cvm__rf_smooth_maxmin(R, first, NULL, p->smooth_sweeps, p->smooth_method == 3, &n);
        *changed += n;
    }
    /* restored even after an error above: it finishes without memory if it must */
    if (p->restore_delaunay && (p->swap || p->smooth_sweeps > 0)) {
        n = 0;
        if ((s2 = cvm__rf_restore_delaunay(R->T, &n)) != CVM_OK && !s)
            s = s2;
        *changed += n;
    }
    return s;
}

cvm_status cvm__refine(cvm__tri2 *T, const cvm__refine_params *p, cvm__refine_report *rep)
{
    cvm__refiner R;
    cvm_status s;
    size_t first = T->nv, changed = 0;
    memset(rep, 0, sizeof *rep);
    s = rf_setup(&R, T, p);
    if (!s && p->march && !cvm__sizing_is_empty(p->sizing))
        s = cvm__rf_march_segments(&R);
    if (!s && (s = cvm__rf_queue_encroached_all(&R)) == CVM_OK)
        s = cvm__rf_split_queued(&R);
    if (!s && p->algo == CVM_ALGO_FRONTAL)
        s = cvm__rf_frontal(&R);
    if (!s && p->algo == CVM_ALGO_AFLR)
        s = cvm__rf_aflr(&R);
    /* frontal and AFLR: the clean-ups, swaps and smoothing keep frontal's
     * acceptance bound, so the mesh meets circumradius <= 0.707 x size */
    if (p->algo == CVM_ALGO_FRONTAL || p->algo == CVM_ALGO_AFLR)
        R.size2 = CVM__FRONTAL_ACCEPT2;
    if (!s)
        s = cvm__rf_delaunay(&R);
    if (!s)
        s = rf_post(&R, first, &changed);
    /* swapping keeps the bounds; smoothing may lower an angle below the
     * requested one where its star already had a smaller one (an exempt
     * triangle at a small input angle: CVM_OPT_SMOOTH_SWEEPS), and the
     * Delaunay-restoring flips may make a triangle too big or too thin again:
     * refine those */
    if (!s && changed > 0)
        s = cvm__rf_delaunay(&R);
    /* the report states the documented bound: frontal's 0.707 x size after the
     * frontal and AFLR passes, so a triangle left over it where a segment split
     * was refused (the hull limitation) is listed, as Delaunay refinement lists
     * one over 1.0 x size */
    if (p->algo != CVM_ALGO_FRONTAL && p->algo != CVM_ALGO_AFLR)
        R.size2 = 1.0;
    if (!cvm_status_is_error(s)) {
        cvm_status s2 = rf_report(&R, rep);
        if (s2)
            s = s2;
    }
    rep->steiner = R.steiner;
    if (!cvm_status_is_error(s) && p->algo == CVM_ALGO_AFLR) {
        cvm_status s2 = cvm__rf_aflr_cell_layers(&R, &rep->cell_layer);
        if (s2)
            s = s2;
    }
    rf_teardown(&R);
    return s;
}
