/*
 * topology.c - vertex removal for the dual optimiser: the one topological
 * operation it needs in the weighted setting, where the mesh only has to be
 * the regular triangulation of the final weighted points.
 *
 * cvm__dual_remove_vertex(T, v, avoid) removes an interior vertex v: while v
 * has more than three triangles, one of its edges v-x is flipped away (the
 * quad v, a, x, b must be strictly convex by exact orient2d, so the new
 * triangles a-x-b and b-v-a are counter-clockwise); of the flippable edges
 * the one whose new ear a-x-b has the largest smallest angle is taken (ties:
 * first in star order from T->vtri[v]), except that an ear adding an edge at
 * vertex avoid is taken only when no other is flippable (so avoid, a
 * neighbour of v, loses its edge to v and gains none). At three triangles
 * v-a-b, v-b-c, v-c-a become a-b-c (the 3-to-1 flip; a-b-c is
 * counter-clockwise because v lies strictly inside it). The star of v must be
 * free of ghost, outside-the-domain and constrained edges and of a region
 * border; the result is a valid triangulation, not necessarily regular: the
 * caller restores that with Lawson flips. v is left without a triangle
 * (vtri -1) for cvm__tri2_compact.
 *
 * The choice of which vertices to remove is optimise.c's. Everything here is
 * exact orient2d plus a plain-double angle measure choosing among valid
 * flips, and depends only on the mesh (deterministic).
 */
#include "dual_internal.h"
#include "delaunay/tri2_store.h"
#include "geom/geom_internal.h"
#include "geom/measure.h"

/* Index of v in triangle t. */
int cvm__dual_removable(const cvm__tri2 *T, int32_t v, size_t *deg)
{
    int32_t t0 = T->vtri[v], t = t0;
    size_t n = 0;
    if (t0 < 0)
        return 0;
    do {
        int i;
        if (!cvm__tri2_in_domain(T, t) || (T->ta && T->ta[t] != T->ta[t0]))
            return 0;
        i = cvm__tri2_corner(T, t, v);
        if (cvm__tri2_edge_seg(T, t, (i + 1) % 3) >= 0 || cvm__tri2_edge_seg(T, t, (i + 2) % 3) >= 0)
            return 0;
        t = T->tn[3 * (size_t)t + (size_t)(i + 1) % 3] / 3;
        n++;
    } while (t != t0 && n <= T->nt);
    if (deg)
        *deg = n;
    return n >= 3;
}

/* The 3-to-1 flip of v's three triangles. */
static void merge3(cvm__tri2 *T, int32_t v)
{
    int32_t s[3], o[3], e[3], c[3];
    int k;
    s[0] = T->vtri[v];
    for (k = 0; k < 3; k++) {
        int i = cvm__tri2_corner(T, s[k], v);
        size_t h = 3 * (size_t)s[k] + (size_t)i;
        o[k] = T->tn[h];  /* outer half-edge across the edge opposite v */
        e[k] = T->te ? T->te[h] : -1;
        c[k] = T->tv[3 * (size_t)s[k] + (size_t)(i + 1) % 3]; /* s[k] = (v, c[k], c[k+1]) */
        if (k < 2)
            s[k + 1] = T->tn[3 * (size_t)s[k] + (size_t)(i + 1) % 3] / 3;
    }
    /* s[0] becomes (c0, c1, c2): edge 0 (c1 c2) is s[1]'s outer edge, edge 1 (c2 c0)
     * s[2]'s, edge 2 (c0 c1) s[0]'s */
    {
        int32_t t = s[0];
        size_t t3 = 3 * (size_t)t;
        T->tv[t3] = c[0];
        T->tv[t3 + 1] = c[1];
        T->tv[t3 + 2] = c[2];
        for (k = 0; k < 3; k++) {
            int32_t h = o[(k + 1) % 3];
            T->tn[t3 + (size_t)k] = h;
            T->tn[h] = (int32_t)(t3 + (size_t)k);
            if (T->te)
                T->te[t3 + (size_t)k] = e[(k + 1) % 3];
        }
        cvm__tri2_kill(T, s[1]);
        cvm__tri2_kill(T, s[2]);
        for (k = 0; k < 3; k++)
            T->vtri[c[k]] = t;
        T->vtri[v] = -1;
        T->last = t;
    }
}

int cvm__dual_remove_vertex(cvm__tri2 *T, int32_t v, int32_t avoid)
{
    size_t deg;
    if (!cvm__dual_removable(T, v, &deg))
        return 0;
    while (deg > 3) {
        int32_t t0 = T->vtri[v], t = t0, best_t = -1;
        int best_j = -1, best_bad = 1;
        double best_q = -1.0;
        size_t n = 0;
        do {
            int i = cvm__tri2_corner(T, t, v), j = (i + 1) % 3;
            int32_t a = T->tv[3 * (size_t)t + (size_t)j], x = T->tv[3 * (size_t)t + (size_t)(i + 2) % 3];
            int32_t h = T->tn[3 * (size_t)t + (size_t)j], u = h / 3;
            int32_t b = T->tv[3 * (size_t)u + (size_t)(h % 3)];
            const double *pa = T->xy + 2 * (size_t)a, *px = T->xy + 2 * (size_t)x;
            const double *pb = T->xy + 2 * (size_t)b, *pv = T->xy + 2 * (size_t)v;
            /* edge j of t is x-v; its flip makes a-x-b and b-v-a */
            if (cvm__orient2d(pa, px, pb) > 0 && cvm__orient2d(pb, pv, pa) > 0) {
                int bad = a == avoid || b == avoid;
                double q = cvm__min_sin2(pa, px, pb);
                if (best_t < 0 || bad < best_bad || (bad == best_bad && q > best_q)) {
                    best_t = t;
                    best_j = j;
                    best_bad = bad;
                    best_q = q;
                }
            }
            t = T->tn[3 * (size_t)t + (size_t)(i + 1) % 3] / 3;
            n++;
        } while (t != t0 && n <= deg);
        if (best_t < 0)
            return 0; /* not expected (v lies in its link's kernel); the mesh stays valid */
        {
            int32_t u = T->tn[3 * (size_t)best_t + (size_t)best_j] / 3;
            cvm__tri2_flip(T, best_t, best_j); /* best_t = (a, x, b), u = (b, v, a) */
            T->vtri[v] = u;
        }
        deg--;
    }
    merge3(T, v);
    return 1;
}
