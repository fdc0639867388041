/*
 * g3_remesh.c - the whole surface re-meshed with near-equilateral triangles
 * at a size that follows its curvature, before the points are generated
 * (CVM_GEN3_SURFACE_REMESH_ALL).
 *
 * Why: the near field places one point per pair of surface triangles at 1.1
 * times their circumradius; a needle triangle (a wing surface with fine
 * chordwise and coarse spanwise spacing) has a huge circumradius and leaves
 * its boundary tetrahedra badly shaped, whatever the optimiser does later.
 *
 * Method: isotropic remeshing after Botsch and Kobbelt ("A remeshing approach
 * to multiresolution modeling", SGP 2004), with a target size per vertex, in
 * G3R_PASSES passes of:
 * - collapses of edges shorter than 4/5 of the target, first, so that the
 *   short sides of needles go before their long sides are split; a collapse
 *   may not make an edge longer than both 4/3 of the target and the longest
 *   edge already at the removed vertex, nor a triangle turn over or get worse
 *   than both G3R_SHAPE and the worst triangle it replaces;
 * - one split of each edge longer than 4/3 of the target that was there when
 *   the pass began (splitting new edges again in the same pass would cut
 *   needles into fans of needles); a smooth edge's new point is its midpoint
 *   projected onto the input, and the split is skipped when that point falls
 *   on a feature line or a new triangle would turn over or get worse;
 * - Delaunay flips of smooth edges whose triangles are within 45 degrees;
 * - tangential smoothing: half-way to the neighbours' mean in the vertex's
 *   tangent plane, then onto the input triangles of its smooth patch (never
 *   onto a feature line), kept when no triangle turns over or gets worse.
 * The new surface's vertices lie on the input surface (in doubles; on
 * axis-aligned planes exactly), its edges are chords of it.
 *
 * Features: an edge whose two triangles differ in key (facet marker) or meet
 * at more than G3R_SHARP_DEG between their normals is a feature; features
 * are split at their midpoints (which lie on them) and never flipped. A
 * vertex on exactly two feature edges may slide along them only by a
 * collapse into a neighbour on the same nearly straight feature line; a
 * vertex on one or more than two feature edges, or where its feature line
 * bends by more than 5 degrees, never moves. Smooth patches:
 * input triangles joined across non-feature edges; a free vertex belongs to
 * one and is projected onto it only.
 *
 * Target size at an input vertex: the least of the largest size h, the user
 * sizing there, the mean edge of the input triangles around it (a finely
 * triangulated sphere stays as fine), and G3R_TURN / (curvature) over its
 * smooth edges (curvature estimated per edge as the angle between its
 * triangles' normals over the distance of their centroids); at a vertex that
 * never moves, also its feature edges' length. Then it is limited to grow by
 * the grading g per unit of distance along the input's edges (Dijkstra). A
 * new point on a feature takes the mean of its edge's ends, any other point
 * the value where it is projected.
 *
 * The result is checked by the caller (self-intersection, orientation); a
 * surface this file cannot take (an edge not shared by exactly two
 * triangles) is returned unchanged (out->xyz NULL). Memory through the
 * context's allocator; CVM_E_NOMEM leaves nothing allocated. Deterministic:
 * every pass visits edges and vertices in index order.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "generate3/generate3.h"
#include "generate3/g3_remesh.h"

#define G3R_PASSES 20
#define G3R_FOLD_COS 0.5   /* a new triangle's normal within 60 degrees of the old one */

/* ---- local operations ---- */

static cvm_status g3r_ring_of(g3r_state *R, int32_t v, size_t *n)
{
    while (!cvm__g3r_ring(R, v, n)) {
        size_t c = R->cap_ring;
        if (c > 3 * R->nt + 3)
            return cvm__error(R->ctx, CVM_E_INTERNAL, CVM_ENT_NONE, -1,
                              "surface re-meshing: the triangles around a vertex do not close");
        if (cvm__grow(R->ctx, (void **)&R->ring, &c, R->cap_ring * 2 + 16, sizeof *R->ring))
            return cvm__nomem(R->ctx);
        R->cap_ring = c;
    }
    return CVM_OK;
}

static void g3r_tri_unit_normal(const g3r_state *R, int32_t p0, int32_t p1, int32_t p2, double *n,
                            double *area2)
{
    g3r_normal(g3r_x(R, p0), g3r_x(R, p1), g3r_x(R, p2), n);
    *area2 = g3r_unit(n);
}

/* Shape of triangle (p0, p1, p2): twice its area over its longest edge squared (about the
 * sine of its smallest angle; 0 when degenerate). A new triangle must reach G3R_SHAPE or
 * the worst shape it replaces. */
static double g3r_shape_xyz(const double *p0, const double *p1, const double *p2)
{
    double n[3], a2, l0, l1, l2, lmax;
    g3r_normal(p0, p1, p2, n);
    a2 = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    l0 = g3r_dist(p0, p1);
    l1 = g3r_dist(p1, p2);
    l2 = g3r_dist(p2, p0);
    lmax = l0 > l1 ? l0 : l1;
    lmax = lmax > l2 ? lmax : l2;
    return lmax > 0 ? a2 / (lmax * lmax) : 0;
}

static double g3r_shape(const g3r_state *R, int32_t p0, int32_t p1, int32_t p2)
{
    double n[3], a2, l0, l1, l2, lmax;
    g3r_normal(g3r_x(R, p0), g3r_x(R, p1), g3r_x(R, p2), n);
    a2 = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    l0 = g3r_dist(g3r_x(R, p0), g3r_x(R, p1));
    l1 = g3r_dist(g3r_x(R, p1), g3r_x(R, p2));
    l2 = g3r_dist(g3r_x(R, p2), g3r_x(R, p0));
    lmax = l0 > l1 ? l0 : l1;
    lmax = lmax > l2 ? lmax : l2;
    return lmax > 0 ? a2 / (lmax * lmax) : 0;
}

#define G3R_SHAPE 0.05

static double g3r_edge_target(const g3r_state *R, int32_t a, int32_t b)
{
    return 0.5 * (R->L[a] + R->L[b]);
}

static cvm_status g3r_split(g3r_state *R, int32_t h)
{
    int32_t o = R->opp[h], t = G3R_T(h), u = G3R_T(o);
    int32_t a = g3r_org(R, h), b = g3r_dst(R, h), c = g3r_apex(R, h), d = g3r_apex(R, o);
    int32_t hn = R->opp[G3R_NEXT(h)], hp = R->opp[G3R_PREV(h)];
    int32_t on = R->opp[G3R_NEXT(o)], op = R->opp[G3R_PREV(o)];
    unsigned char fe = R->feat[h], fhn = R->feat[hn], fhp = R->feat[hp], fon = R->feat[on],
                  fop = R->feat[op];
    int32_t m, t2, u2, st = R->tsrc[t], su = R->tsrc[u];
    double y[3], Ly = 0;
    cvm_status s;
    if (!fe) {
        /* the new point goes onto the input, where all four new triangles face as the two
         * old ones did and are no worse shaped; else the edge stays */
        const double *pa = g3r_x(R, a), *pb = g3r_x(R, b), *pc = g3r_x(R, c), *pd = g3r_x(R, d);
        double mid[3], n0[3], n1[3], nn[3], worst = G3R_SHAPE, q;
        const double *tri4[4][3];
        int k;
        for (k = 0; k < 3; k++)
            mid[k] = 0.5 * (pa[k] + pb[k]);
        if (!cvm__g3r_project(R, R->ipatch[st], mid, 0.5 * g3r_dist(pa, pb), y, &Ly))
            return CVM_OK;
        g3r_normal(pa, pb, pc, n0);
        g3r_normal(pb, pa, pd, n1);
        if (!(g3r_unit(n0) > 0) || !(g3r_unit(n1) > 0))
            return CVM_OK;
        q = g3r_shape_xyz(pa, pb, pc);
        worst = q < worst ? q : worst;
        q = g3r_shape_xyz(pb, pa, pd);
        worst = q < worst ? q : worst;
        tri4[0][0] = pc, tri4[0][1] = pa, tri4[0][2] = y;
        tri4[1][0] = pc, tri4[1][1] = y, tri4[1][2] = pb;
        tri4[2][0] = pd, tri4[2][1] = pb, tri4[2][2] = y;
        tri4[3][0] = pd, tri4[3][1] = y, tri4[3][2] = pa;
        for (k = 0; k < 4; k++) {
            const double *ref = k < 2 ? n0 : n1;
            g3r_normal(tri4[k][0], tri4[k][1], tri4[k][2], nn);
            if (!(g3r_unit(nn) > 0) || nn[0] * ref[0] + nn[1] * ref[1] + nn[2] * ref[2] < G3R_FOLD_COS ||
                g3r_shape_xyz(tri4[k][0], tri4[k][1], tri4[k][2]) < worst)
                return CVM_OK;
        }
    }
    if ((s = cvm__g3r_room(R, R->nv + 1, R->nt + 2)))
        return s;
    m = (int32_t)R->nv++;
    t2 = (int32_t)R->nt++;
    u2 = (int32_t)R->nt++;
    {
        const double *pa = g3r_x(R, a), *pb = g3r_x(R, b);
        double *pm = R->x + 3 * (size_t)m;
        int k;
        for (k = 0; k < 3; k++)
            pm[k] = 0.5 * (pa[k] + pb[k]);
    }
    R->L[m] = g3r_edge_target(R, a, b);
    R->vflag[m] = fe ? G3R_LINE : G3R_FREE;
    R->vpatch[m] = fe ? -1 : R->ipatch[st];
    /* T1 = (a, m, c) in t, T2 = (m, b, c), T3 = (b, m, d) in u, T4 = (m, a, d) */
    cvm__g3r_set(R, t, c, a, m, st);  /* 0: a->m, 1: m->c, 2: c->a */
    cvm__g3r_set(R, t2, c, m, b, st); /* 0: m->b, 1: b->c, 2: c->m */
    cvm__g3r_set(R, u, d, b, m, su);  /* 0: b->m, 1: m->d, 2: d->b */
    cvm__g3r_set(R, u2, d, m, a, su); /* 0: m->a, 1: a->d, 2: d->m */
    cvm__g3r_link(R, 3 * t, 3 * u2);
    cvm__g3r_link(R, 3 * t + 1, 3 * t2 + 2);
    cvm__g3r_link(R, 3 * t + 2, hp);
    cvm__g3r_link(R, 3 * t2, 3 * u);
    cvm__g3r_link(R, 3 * t2 + 1, hn);
    cvm__g3r_link(R, 3 * u + 1, 3 * u2 + 2);
    cvm__g3r_link(R, 3 * u + 2, op);
    cvm__g3r_link(R, 3 * u2 + 1, on);
    cvm__g3r_setf(R, 3 * t, fe);
    cvm__g3r_setf(R, 3 * t2, fe);
    cvm__g3r_setf(R, 3 * t + 1, 0);
    cvm__g3r_setf(R, 3 * u + 1, 0);
    cvm__g3r_setf(R, 3 * t + 2, fhp);
    cvm__g3r_setf(R, 3 * t2 + 1, fhn);
    cvm__g3r_setf(R, 3 * u + 2, fop);
    cvm__g3r_setf(R, 3 * u2 + 1, fon);
    R->splits++;
    if (!fe) {
        memcpy(R->x + 3 * (size_t)m, y, sizeof y);
        R->L[m] = Ly;
    }
    return CVM_OK;
}

/* Is b in the ring of c (is c-b an edge)? */
static cvm_status g3r_has_edge(g3r_state *R, int32_t c, int32_t b, int *yes)
{
    size_t n, i;
    cvm_status s = g3r_ring_of(R, c, &n);
    *yes = 0;
    for (i = 0; i < n && !s; i++)
        if (g3r_dst(R, R->ring[i]) == b)
            *yes = 1;
    return s;
}

static cvm_status g3r_valence(g3r_state *R, int32_t v, size_t *n)
{
    return g3r_ring_of(R, v, n);
}

/* Remove org(h) = a into dst(h) = b when that is allowed (see the file's comment). */
static cvm_status g3r_collapse(g3r_state *R, int32_t h, int *done)
{
    int32_t o = R->opp[h], t = G3R_T(h), u = G3R_T(o);
    int32_t a = g3r_org(R, h), b = g3r_dst(R, h), c = g3r_apex(R, h), d = g3r_apex(R, o);
    size_t na, nb, i, j, nc, nd;
    int32_t *ra = NULL;
    double worst, longest;
    cvm_status s;
    *done = 0;
    if (R->vflag[a] == G3R_FIXED || (R->vflag[a] == G3R_LINE && !R->feat[h]))
        return CVM_OK;
    if (c == d)
        return CVM_OK;
    if ((s = g3r_valence(R, c, &nc)) || (s = g3r_valence(R, d, &nd)))
        return s;
    if (nc <= 3 || nd <= 3)
        return CVM_OK;
    if ((s = g3r_ring_of(R, a, &na)))
        return s;
    if (R->vflag[a] == G3R_LINE) {
        /* slide along a straight feature line only: the other feature edge at a continues a-b */
        const double *pa = g3r_x(R, a), *pb = g3r_x(R, b);
        for (i = 0; i < na; i++) {
            int32_t e = g3r_dst(R, R->ring[i]);
            if (R->feat[R->ring[i]] && e != b) {
                const double *pe = g3r_x(R, e);
                double u1[3] = {pa[0] - pb[0], pa[1] - pb[1], pa[2] - pb[2]};
                double u2[3] = {pe[0] - pa[0], pe[1] - pa[1], pe[2] - pa[2]};
                double l1 = g3r_unit(u1), l2 = g3r_unit(u2);
                if (!(l1 > 0 && l2 > 0) || u1[0] * u2[0] + u1[1] * u2[1] + u1[2] * u2[2] < 0.996)
                    return CVM_OK;
            }
        }
    }
    ra = cvm__malloc(R->ctx, na * sizeof *ra);
    if (!ra)
        return cvm__nomem(R->ctx);
    memcpy(ra, R->ring, na * sizeof *ra);
    if ((s = g3r_ring_of(R, b, &nb)))
        goto out;
    /* link condition: the common neighbours of a and b are c and d only */
    for (i = 0; i < na; i++) {
        int32_t w = g3r_dst(R, ra[i]);
        if (w == c || w == d || w == b)
            continue;
        for (j = 0; j < nb; j++)
            if (g3r_dst(R, R->ring[j]) == w)
                goto out;
    }
    /* no triangle turns over or gets worse than G3R_SHAPE and the worst before, no edge too long */
    worst = G3R_SHAPE;
    longest = 0;
    for (i = 0; i < na; i++) {
        double l = g3r_dist(g3r_x(R, a), g3r_x(R, g3r_dst(R, ra[i])));
        longest = l > longest ? l : longest;
    }
    for (i = 0; i < na; i++) {
        int32_t tt = G3R_T(ra[i]);
        double q = g3r_shape(R, R->tv[3 * tt], R->tv[3 * tt + 1], R->tv[3 * tt + 2]);
        worst = q < worst ? q : worst;
    }
    for (i = 0; i < na; i++) {
        int32_t g = ra[i], tt = G3R_T(g), p[3], k;
        double n0[3], n1[3], a0, a1;
        if (tt == t || tt == u)
            continue;
        if (g3r_dist(g3r_x(R, b), g3r_x(R, g3r_dst(R, g))) > 4.0 / 3.0 * g3r_edge_target(R, b, g3r_dst(R, g)) &&
            g3r_dist(g3r_x(R, b), g3r_x(R, g3r_dst(R, g))) > longest)
            goto out;
        for (k = 0; k < 3; k++)
            p[k] = R->tv[3 * tt + k];
        g3r_tri_unit_normal(R, p[0], p[1], p[2], n0, &a0);
        for (k = 0; k < 3; k++)
            p[k] = p[k] == a ? b : p[k];
        g3r_tri_unit_normal(R, p[0], p[1], p[2], n1, &a1);
        if (!(a1 > 0) || n0[0] * n1[0] + n0[1] * n1[1] + n0[2] * n1[2] < G3R_FOLD_COS ||
            g3r_shape(R, p[0], p[1], p[2]) < worst)
            goto out;
    }
    {
        int32_t x1 = R->opp[G3R_NEXT(h)], x2 = R->opp[G3R_PREV(h)];
        int32_t y1 = R->opp[G3R_NEXT(o)], y2 = R->opp[G3R_PREV(o)];
        unsigned char fcb = R->feat[x1] > R->feat[x2] ? R->feat[x1] : R->feat[x2];
        unsigned char fdb = R->feat[y1] > R->feat[y2] ? R->feat[y1] : R->feat[y2];
        for (i = 0; i < na; i++) {
            int32_t tt = G3R_T(ra[i]), k;
            if (tt == t || tt == u)
                continue;
            for (k = 0; k < 3; k++)
                if (R->tv[3 * tt + k] == a)
                    R->tv[3 * tt + k] = b;
        }
        cvm__g3r_link(R, x1, x2);
        cvm__g3r_link(R, y1, y2);
        cvm__g3r_setf(R, x1, fcb);
        cvm__g3r_setf(R, y1, fdb);
        R->tv[3 * t] = R->tv[3 * u] = -1;
        R->vhe[b] = x2;
        R->vhe[c] = x1;
        R->vhe[d] = y1;
        R->vhe[a] = -1;
        R->collapses++;
        *done = 1;
    }
out:
    cvm__free(R->ctx, ra);
    return s;
}

static double g3r_corner_angle(const double *p, const double *q, const double *r)
{
    double u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
    double v[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
    double lu = g3r_unit(u), lv = g3r_unit(v), c;
    if (!(lu > 0 && lv > 0))
        return 0;
    c = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    return acos(c > 1 ? 1 : c < -1 ? -1 : c);
}

/* Flip edge h when its two triangles are not locally Delaunay and nearly flat. */
static cvm_status g3r_flip(g3r_state *R, int32_t h, int *done)
{
    int32_t o = R->opp[h], t = G3R_T(h), u = G3R_T(o);
    int32_t a = g3r_org(R, h), b = g3r_dst(R, h), c = g3r_apex(R, h), d = g3r_apex(R, o);
    double nt_[3], nu[3], n1[3], n2[3], at, au, a1, a2;
    size_t va, vb;
    int exists;
    cvm_status s;
    *done = 0;
    if (R->feat[h] || c == d)
        return CVM_OK;
    if (g3r_corner_angle(g3r_x(R, c), g3r_x(R, a), g3r_x(R, b)) +
            g3r_corner_angle(g3r_x(R, d), g3r_x(R, b), g3r_x(R, a)) <= 3.14159265358979323846 + 1e-9)
        return CVM_OK;
    g3r_tri_unit_normal(R, a, b, c, nt_, &at);
    g3r_tri_unit_normal(R, b, a, d, nu, &au);
    if (nt_[0] * nu[0] + nt_[1] * nu[1] + nt_[2] * nu[2] < 0.707) /* 45 degrees */
        return CVM_OK;
    g3r_tri_unit_normal(R, a, d, c, n1, &a1);
    g3r_tri_unit_normal(R, d, b, c, n2, &a2);
    if (!(a1 > 0 && a2 > 0) || n1[0] * nt_[0] + n1[1] * nt_[1] + n1[2] * nt_[2] < G3R_FOLD_COS ||
        n2[0] * nu[0] + n2[1] * nu[1] + n2[2] * nu[2] < G3R_FOLD_COS ||
        n1[0] * n2[0] + n1[1] * n2[1] + n1[2] * n2[2] < 0.707)
        return CVM_OK;
    {
        double w0 = g3r_shape(R, a, b, c), w1 = g3r_shape(R, b, a, d), worst = G3R_SHAPE;
        worst = w0 < worst ? w0 : worst;
        worst = w1 < worst ? w1 : worst;
        if (g3r_shape(R, a, d, c) < worst || g3r_shape(R, d, b, c) < worst)
            return CVM_OK;
    }
    if ((s = g3r_valence(R, a, &va)) || (s = g3r_valence(R, b, &vb)))
        return s;
    if (va <= 3 || vb <= 3)
        return CVM_OK;
    if ((s = g3r_has_edge(R, c, d, &exists)) || exists)
        return s;
    {
        int32_t xbc = R->opp[G3R_NEXT(h)], xca = R->opp[G3R_PREV(h)];
        int32_t xad = R->opp[G3R_NEXT(o)], xdb = R->opp[G3R_PREV(o)];
        unsigned char fbc = R->feat[xbc], fca = R->feat[xca], fad = R->feat[xad], fdb = R->feat[xdb];
        cvm__g3r_set(R, t, a, d, c, R->tsrc[t]); /* 0: d->c, 1: c->a, 2: a->d */
        cvm__g3r_set(R, u, d, b, c, R->tsrc[u]); /* 0: b->c, 1: c->d, 2: d->b */
        cvm__g3r_link(R, 3 * t, 3 * u + 1);
        cvm__g3r_link(R, 3 * t + 1, xca);
        cvm__g3r_link(R, 3 * t + 2, xad);
        cvm__g3r_link(R, 3 * u, xbc);
        cvm__g3r_link(R, 3 * u + 2, xdb);
        cvm__g3r_setf(R, 3 * t, 0);
        cvm__g3r_setf(R, 3 * t + 1, fca);
        cvm__g3r_setf(R, 3 * t + 2, fad);
        cvm__g3r_setf(R, 3 * u, fbc);
        cvm__g3r_setf(R, 3 * u + 2, fdb);
    }
    R->flips++;
    *done = 1;
    return CVM_OK;
}

/* Move free vertex v half-way to its neighbours' mean in its tangent plane,
 * then onto its patch of the input, unless a triangle would turn over. */
static cvm_status g3r_smooth(g3r_state *R, int32_t v)
{
    size_t n, i;
    double c[3] = {0, 0, 0}, nv[3] = {0, 0, 0}, d[3], dn, q[3], y[3], Ly, old[3], len;
    double *pv = R->x + 3 * (size_t)v;
    int k, found = 0;
    cvm_status s = g3r_ring_of(R, v, &n);
    if (s || n == 0)
        return s;
    for (i = 0; i < n; i++) {
        int32_t h = R->ring[i], tt = G3R_T(h);
        double tn[3];
        const double *pw = g3r_x(R, g3r_dst(R, h));
        g3r_normal(g3r_x(R, R->tv[3 * tt]), g3r_x(R, R->tv[3 * tt + 1]), g3r_x(R, R->tv[3 * tt + 2]), tn);
        for (k = 0; k < 3; k++) {
            c[k] += pw[k] / (double)n;
            nv[k] += tn[k];
        }
    }
    if (!(g3r_unit(nv) > 0))
        return CVM_OK;
    for (k = 0; k < 3; k++)
        d[k] = c[k] - pv[k];
    dn = d[0] * nv[0] + d[1] * nv[1] + d[2] * nv[2];
    for (k = 0; k < 3; k++)
        q[k] = pv[k] + 0.5 * (d[k] - dn * nv[k]);
    len = g3r_dist(q, pv);
    if (!(len > 0))
        return CVM_OK;
    for (k = 0; k < 3 && !found; k++)
        found = cvm__g3r_project(R, R->vpatch[v], q, (0.5 + k) * len, y, &Ly);
    if (!found)
        return CVM_OK;
    memcpy(old, pv, sizeof old);
    {
        double n0[64][3];
        size_t m = n < 64 ? n : 64;
        double ar;
        if (n > 64)
            return CVM_OK;
        double worst = G3R_SHAPE;
        for (i = 0; i < m; i++) {
            int32_t tt = G3R_T(R->ring[i]);
            double q = g3r_shape(R, R->tv[3 * tt], R->tv[3 * tt + 1], R->tv[3 * tt + 2]);
            worst = q < worst ? q : worst;
            g3r_tri_unit_normal(R, R->tv[3 * tt], R->tv[3 * tt + 1], R->tv[3 * tt + 2], n0[i], &ar);
        }
        memcpy(pv, y, sizeof y);
        for (i = 0; i < m; i++) {
            int32_t tt = G3R_T(R->ring[i]);
            double n1[3];
            g3r_tri_unit_normal(R, R->tv[3 * tt], R->tv[3 * tt + 1], R->tv[3 * tt + 2], n1, &ar);
            if (!(ar > 0) || n1[0] * n0[i][0] + n1[1] * n0[i][1] + n1[2] * n0[i][2] < G3R_FOLD_COS ||
                g3r_shape(R, R->tv[3 * tt], R->tv[3 * tt + 1], R->tv[3 * tt + 2]) < worst) {
                memcpy(pv, old, sizeof old);
                return CVM_OK;
            }
        }
    }
    R->L[v] = Ly;
    R->moves++;
    return CVM_OK;
}

/* ---- the passes ---- */

#define G3R_MAX_TRIS ((size_t)4000000) /* beyond: CVM_E_TOO_LARGE */

static int g3r_live(const g3r_state *R, int32_t h) { return R->tv[3 * G3R_T(h)] >= 0; }

/* Drop removed triangles and vertices, keeping the order of the others. */
static cvm_status g3r_compact(g3r_state *R)
{
    int32_t *tm = cvm__malloc(R->ctx, (R->nt ? R->nt : 1) * sizeof *tm);
    int32_t *vm = cvm__malloc(R->ctx, (R->nv ? R->nv : 1) * sizeof *vm);
    size_t t, v, n = 0, k;
    if (!tm || !vm) {
        cvm__free(R->ctx, tm);
        cvm__free(R->ctx, vm);
        return cvm__nomem(R->ctx);
    }
    for (t = 0; t < R->nt; t++)
        tm[t] = R->tv[3 * t] >= 0 ? (int32_t)n++ : -1;
    for (v = 0, n = 0; v < R->nv; v++)
        vm[v] = R->vhe[v] >= 0 ? (int32_t)n++ : -1;
    for (t = 0; t < R->nt; t++) {
        int32_t d = tm[t];
        if (d < 0)
            continue;
        for (k = 0; k < 3; k++) {
            int32_t o = R->opp[3 * t + k];
            R->tv[3 * (size_t)d + k] = vm[R->tv[3 * t + k]];
            R->opp[3 * (size_t)d + k] = 3 * tm[o / 3] + o % 3;
            R->feat[3 * (size_t)d + k] = R->feat[3 * t + k];
        }
        R->tsrc[d] = R->tsrc[t];
    }
    for (v = 0; v < R->nv; v++) {
        int32_t d = vm[v], h = R->vhe[v];
        if (d < 0)
            continue;
        memmove(R->x + 3 * (size_t)d, R->x + 3 * v, 3 * sizeof *R->x);
        R->L[d] = R->L[v];
        R->vflag[d] = R->vflag[v];
        R->vpatch[d] = R->vpatch[v];
        R->vhe[d] = 3 * tm[h / 3] + h % 3;
    }
    for (t = 0, n = 0; t < R->nt; t++)
        n += tm[t] >= 0;
    R->nt = n;
    for (v = 0, n = 0; v < R->nv; v++)
        n += vm[v] >= 0;
    R->nv = n;
    cvm__free(R->ctx, tm);
    cvm__free(R->ctx, vm);
    return CVM_OK;
}

static cvm_status g3r_pass(g3r_state *R)
{
    size_t h, v, sweep, nh;
    int done;
    cvm_status s = g3r_compact(R);
    for (h = 0; h < 3 * R->nt && !s; h++) {
        int32_t g = (int32_t)h, a, b;
        if (!g3r_live(R, g))
            continue;
        a = g3r_org(R, g);
        b = g3r_dst(R, g);
        if (g3r_dist(g3r_x(R, a), g3r_x(R, b)) < 0.8 * g3r_edge_target(R, a, b))
            s = g3r_collapse(R, g, &done);
    }
    for (h = 0, nh = 3 * R->nt; h < nh && !s && R->nt < G3R_MAX_TRIS; h++) {
        int32_t g = (int32_t)h, a, b;
        if (!g3r_live(R, g) || R->opp[g] < g)
            continue;
        a = g3r_org(R, g);
        b = g3r_dst(R, g);
        if (g3r_dist(g3r_x(R, a), g3r_x(R, b)) > 4.0 / 3.0 * g3r_edge_target(R, a, b))
            s = g3r_split(R, g);
    }
    for (sweep = 0, done = 1; sweep < 4 && !s; sweep++) {
        size_t before = R->flips;
        for (h = 0; h < 3 * R->nt && !s; h++) {
            int32_t g = (int32_t)h;
            if (g3r_live(R, g) && R->opp[g] > g)
                s = g3r_flip(R, g, &done);
        }
        if (R->flips == before)
            break;
    }
    for (v = 0; v < R->nv && !s; v++)
        if (R->vhe[v] >= 0 && R->vflag[v] == G3R_FREE)
            s = g3r_smooth(R, (int32_t)v);
    return s;
}

cvm_status cvm__g3_remesh_all(cvm__ctx *ctx, const cvm__g3_surface *s, const int32_t *key,
                              const cvm__g3_params *p, cvm__g3_remeshed *out)
{
    g3r_state R;
    int32_t *map = NULL;
    size_t i, k, np = 0, nt = 0;
    cvm_status st;
    memset(out, 0, sizeof *out);
    memset(&R, 0, sizeof R);
    R.ctx = ctx;
    R.in = s;
    out->tris_before = out->tris_after = s->nt;
    if (s->nt == 0)
        return CVM_OK;
    if ((st = cvm__g3r_build(&R, s, key)) || !R.ok)
        goto done;
    if ((st = cvm__g3r_field(&R, p)))
        goto done;
    for (i = 0; i < G3R_PASSES && !st; i++)
        st = g3r_pass(&R);
    if (!st && R.nt >= G3R_MAX_TRIS)
        st = cvm__error(ctx, CVM_E_TOO_LARGE, CVM_ENT_NONE, -1,
                        "re-meshing the surface needs more than %zu triangles at this size: "
                        "give a larger size, or use CVM_OPT_GEN3_SURFACE = 0",
                        (size_t)G3R_MAX_TRIS);
    if (st)
        goto done;
    /* compact into the output */
    map = cvm__malloc(ctx, (R.nv ? R.nv : 1) * sizeof *map);
    if (!map) {
        st = cvm__nomem(ctx);
        goto done;
    }
    for (i = 0; i < R.nv; i++)
        map[i] = R.vhe[i] >= 0 ? (int32_t)np++ : -1;
    for (i = 0; i < R.nt; i++)
        nt += R.tv[3 * i] >= 0;
    out->xyz = cvm__malloc(ctx, 3 * (np ? np : 1) * sizeof *out->xyz);
    out->tri = cvm__malloc(ctx, 3 * (nt ? nt : 1) * sizeof *out->tri);
    out->tsrc = cvm__malloc(ctx, (nt ? nt : 1) * sizeof *out->tsrc);
    if (!out->xyz || !out->tri || !out->tsrc) {
        st = cvm__nomem(ctx);
        goto done;
    }
    for (i = 0; i < R.nv; i++)
        if (map[i] >= 0)
            memcpy(out->xyz + 3 * (size_t)map[i], R.x + 3 * i, 3 * sizeof *out->xyz);
    for (i = 0, k = 0; i < R.nt; i++) {
        if (R.tv[3 * i] < 0)
            continue;
        out->tri[3 * k] = map[R.tv[3 * i]];
        out->tri[3 * k + 1] = map[R.tv[3 * i + 1]];
        out->tri[3 * k + 2] = map[R.tv[3 * i + 2]];
        out->tsrc[k++] = R.tsrc[i];
    }
    out->np = np;
    out->nt = nt;
    out->tris_after = nt;
    out->facets_remeshed = 0;
    for (i = 0; i < s->nt; i++)
        out->facets_remeshed = (size_t)R.ipatch[i] + 1 > out->facets_remeshed
                                   ? (size_t)R.ipatch[i] + 1 : out->facets_remeshed;
    out->rounds = G3R_PASSES;
done:
    cvm__free(ctx, map);
    cvm__g3r_free(&R);
    if (st)
        cvm__g3_remeshed_free(ctx, out);
    return st;
}
