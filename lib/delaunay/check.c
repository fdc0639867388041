/* check.c - exact re-verification of the triangulation: adjacency, orientation, convex hull, constrained Delaunay property. */
#include "delaunay_internal.h"
#include "tri2_store.h"
#include "geom/geom_internal.h"

static cvm_status fail(cvm__tri2 *T, int32_t t, const char *what)
{
    return cvm__error(T->ctx, CVM_E_INTERNAL, CVM_ENT_TRIANGLE, t, "check failed: %s (triangle slot %ld)",
                      what, (long)t);
}

cvm_status cvm__tri2_check(cvm__tri2 *T)
{
    size_t t;
    for (t = 0; t < T->nt; t++) {
        const int32_t *v = T->tv + 3 * t;
        int j, ghosts = 0;
        if (!cvm__tri2_is_live(T, (int32_t)t))
            continue;
        for (j = 0; j < 3; j++) {
            int32_t h = T->tn[3 * t + j], u = h / 3, k = h % 3;
            const int32_t *w = T->tv + 3 * (size_t)u;
            if (v[j] == CVM__GHOST)
                ghosts++;
            else if (v[j] < 0 || (size_t)v[j] >= T->nv)
                return fail(T, (int32_t)t, "vertex index out of range");
            if (h < 0 || (size_t)u >= T->nt || !cvm__tri2_is_live(T, u))
                return fail(T, (int32_t)t, "neighbour is not a live triangle");
            if (T->tn[h] != (int32_t)(3 * t + j))
                return fail(T, (int32_t)t, "adjacency is not symmetric");
            if (w[(k + 1) % 3] != v[(j + 2) % 3] || w[(k + 2) % 3] != v[(j + 1) % 3])
                return fail(T, (int32_t)t, "neighbours disagree on their shared edge");
            if (T->te && T->te[3 * t + j] != T->te[h])
                return fail(T, (int32_t)t, "the two sides of an edge disagree on its segment");
        }
        if (ghosts > 1)
            return fail(T, (int32_t)t, "triangle with two ghost vertices");
        if (ghosts == 1) {
            /* hull convexity: the real neighbour's apex lies inside, i.e. the hull edge is
             * counter-clockwise around the domain */
            int g = v[0] == CVM__GHOST ? 0 : v[1] == CVM__GHOST ? 1 : 2;
            int32_t a = v[(g + 1) % 3], b = v[(g + 2) % 3];
            int32_t h = T->tn[3 * t + g], u = h / 3;
            int32_t c = T->tv[h];
            if (cvm__tri2_is_ghost(T, u) ||
                cvm__orient2d(cvm__tri2_pt(T, b), cvm__tri2_pt(T, a), cvm__tri2_pt(T, c)) <= 0)
                return fail(T, (int32_t)t, "hull edge not convex");
            {
                /* convex turn at a: the ghost across (G, a) is (s0, a, G) */
                int32_t hn = T->tn[3 * t + (g + 2) % 3];
                const int32_t *gv = T->tv + 3 * (size_t)(hn / 3);
                int gg = gv[0] == CVM__GHOST ? 0 : gv[1] == CVM__GHOST ? 1 : gv[2] == CVM__GHOST ? 2 : -1;
                int32_t s0, s1;
                if (gg < 0)
                    return fail(T, (int32_t)t, "ghost ring broken");
                s0 = gv[(gg + 1) % 3];
                s1 = gv[(gg + 2) % 3];
                if (s1 != a)
                    return fail(T, (int32_t)t, "ghost ring broken");
                /* A hull made only of unconstrained edges is exactly convex. A
                 * domain's hull edges are constrained, and segment splits may then
                 * leave reflex turns of a few ulps: no cavity crosses those edges. */
                if (cvm__orient2d(cvm__tri2_pt(T, b), cvm__tri2_pt(T, a), cvm__tri2_pt(T, s0)) < 0 &&
                    (cvm__tri2_edge_seg(T, (int32_t)t, g) < 0 ||
                     cvm__tri2_edge_seg(T, hn / 3, gg) < 0))
                    return fail(T, (int32_t)t, "convex hull not convex at an unconstrained edge");
            }
            continue;
        }
        if (cvm__orient2d(cvm__tri2_pt(T, v[0]), cvm__tri2_pt(T, v[1]), cvm__tri2_pt(T, v[2])) <= 0)
            return fail(T, (int32_t)t, "triangle not counter-clockwise");
        for (j = 0; j < 3; j++) {
            int32_t h = T->tn[3 * t + j], u = h / 3;
            int32_t d = T->tv[h];
            double ic;
            if ((size_t)u < t || d == CVM__GHOST)
                continue;
            if (T->te && T->te[3 * t + j] >= 0)
                continue;
            if (T->w)
                ic = cvm__power2d(cvm__tri2_pt(T, v[0]), cvm__tri2_pt(T, v[1]), cvm__tri2_pt(T, v[2]),
                                  cvm__tri2_pt(T, d), T->w[v[0]], T->w[v[1]], T->w[v[2]], T->w[d]);
            else
                ic = cvm__incircle(cvm__tri2_pt(T, v[0]), cvm__tri2_pt(T, v[1]),
                                   cvm__tri2_pt(T, v[2]), cvm__tri2_pt(T, d));
            if (ic > 0)
                return fail(T, (int32_t)t, "edge not locally Delaunay (exact in-circle)");
        }
    }
    for (t = 0; t < T->nv; t++) {
        int32_t u = T->vtri[t];
        const int32_t *v;
        if (u < 0)
            continue;
        v = T->tv + 3 * (size_t)u;
        if (!cvm__tri2_is_live(T, u) || (v[0] != (int32_t)t && v[1] != (int32_t)t && v[2] != (int32_t)t))
            return cvm__error(T->ctx, CVM_E_INTERNAL, CVM_ENT_VERTEX, (int64_t)t,
                              "check failed: vertex %lu points to a triangle that does not contain it",
                              (unsigned long)t);
    }
    return CVM_OK;
}
