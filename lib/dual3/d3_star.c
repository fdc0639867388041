/*
 * d3_star.c - one vertex's star in the 3D power-dual optimiser: the smooth
 * penalty of its tetrahedra (floating point) and the exact checks that keep
 * the mesh a valid regular tetrahedralisation (dual3.h).
 */
#include <math.h>
#include <string.h>

#include "dual3/d3_internal.h"
#include "geom/geom_internal.h"
#include "geom/measure3.h"

/* The corners and weights of tetrahedron t with vertex v (if a corner) at x, wv. */
static void corners(const cvm__d3_mesh *M, size_t t, int32_t v, const double *x, double wv,
                    const double *P[4], double W[4])
{
    int k;
    for (k = 0; k < 4; k++) {
        int32_t q = M->tet[4 * t + (size_t)k];
        P[k] = q == v ? x : M->xyz + 3 * (size_t)q;
        W[k] = q == v ? wv : M->w[q];
    }
}

static void sub3(const double *a, const double *b, double *o)
{
    o[0] = a[0] - b[0], o[1] = a[1] - b[1], o[2] = a[2] - b[2];
}

static double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross3(const double *a, const double *b, double *o)
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

double cvm__d3_tet_penalty(const double *const P[4], const double W[4], double margin,
                           double *dist_out)
{
    static const int F[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
    double o[3], c[3], l = 0, pen = 0, e[3], u[3], n[3], q[3];
    int i, j;
    if (cvm__tet_volume(P[0], P[1], P[2], P[3]) <= 0 || cvm__tet_power_centre(P[0], P[1], P[2], P[3], W, o))
        return HUGE_VAL;
    for (i = 0; i < 4; i++)
        for (j = i + 1; j < 4; j++)
            l += sqrt(cvm__dist2_3(P[i], P[j]));
    l /= 6;
    for (i = 0; i < 4; i++) {
        const double *a = P[F[i][0]];
        double len, d, gap;
        sub3(P[F[i][1]], a, e);
        sub3(P[F[i][2]], a, u);
        cross3(e, u, n);
        len = sqrt(dot3(n, n));
        if (!(len > 0))
            return HUGE_VAL;
        sub3(P[i], a, q);
        if (dot3(q, n) < 0)
            len = -len;
        sub3(o, a, q);
        d = dot3(q, n) / len; /* > 0 on corner i's side */
        gap = margin * l - d;
        if (gap > 0)
            pen += gap * gap;
    }
    for (i = 0; i < 3; i++)
        c[i] = 0.25 * (P[0][i] + P[1][i] + P[2][i] + P[3][i]) - o[i];
    if (dist_out)
        *dist_out = sqrt(dot3(c, c));
    return (pen + 1e-3 * dot3(c, c)) / (l * l);
}

double cvm__d3_star_penalty(const cvm__d3_work *K, int32_t v, const double *x, double wv,
                            double stop)
{
    const cvm__d3_mesh *M = K->M;
    int32_t s;
    double sum = 0;
    for (s = K->voff[v]; s < K->voff[v + 1]; s++) {
        size_t t = (size_t)K->vtet[s];
        const double *P[4];
        double W[4], f;
        corners(M, t, v, x, wv, P, W);
        f = cvm__d3_tet_penalty(P, W, K->p->margin, NULL);
        if (f == HUGE_VAL)
            return HUGE_VAL;
        sum += K->bnd[t] ? 2 * f : f; /* L_k */
        if (sum >= stop) /* every term is >= 0: it cannot win any more */
            return sum;
    }
    return sum;
}

double cvm__d3_star_dihedral(const cvm__d3_work *K, int32_t v, const double *x)
{
    const cvm__d3_mesh *M = K->M;
    int32_t s;
    double dmin = 180;
    for (s = K->voff[v]; s < K->voff[v + 1]; s++) {
        size_t t = (size_t)K->vtet[s];
        const double *P[4];
        double W[4], lo, hi;
        corners(M, t, v, x, 0, P, W);
        cvm__tet_dihedral_range_deg(P[0], P[1], P[2], P[3], &lo, &hi);
        dmin = lo < dmin ? lo : dmin;
    }
    return dmin;
}

/* The exact power test of face f of tetrahedron t against the vertex across
 * it, v at (x, wv): 1 when that vertex is in conflict (the face is not
 * locally regular), else 0; 0 for a constrained face. */
static int face_conflict(const cvm__d3_mesh *M, size_t t, int f, int32_t v, const double *x,
                         double wv)
{
    int32_t nb = M->nbr[4 * t + (size_t)f], e;
    const double *P[4], *E;
    double W[4], we;
    if (nb < 0 || M->cface[4 * t + (size_t)f])
        return 0;
    /* nb = 4 u + g names the slot; the vertex across is corner g of u */
    e = M->tet[4 * ((size_t)nb >> 2) + ((size_t)nb & 3)];
    if (e == v)
        return 0;
    corners(M, t, v, x, wv, P, W);
    E = M->xyz + 3 * (size_t)e;
    we = M->w[e];
    /* perturbed as cvm_mesh_check() and lib/delaunay3 decide ties (by vertex index) */
    return cvm__power3d_sos(P[0], P[1], P[2], P[3], E, W[0], W[1], W[2], W[3], we,
                            M->tet[4 * t], M->tet[4 * t + 1], M->tet[4 * t + 2],
                            M->tet[4 * t + 3], e) > 0;
}

int cvm__d3_star_valid(const cvm__d3_work *K, int32_t v, const double *x, double wv)
{
    const cvm__d3_mesh *M = K->M;
    const double *x0 = M->xyz + 3 * (size_t)v;
    double w0 = M->w[v];
    int32_t s;
    size_t nout = 0, nout0 = 0, bout = 0, bout0 = 0;
    for (s = K->voff[v]; s < K->voff[v + 1]; s++) {
        size_t t = (size_t)K->vtet[s];
        const double *P[4];
        double W[4];
        corners(M, t, v, x, wv, P, W);
        if (!(cvm__orient3d(P[0], P[1], P[2], P[3]) > 0))
            return 0;
    }
    for (s = K->voff[v]; s < K->voff[v + 1]; s++) {
        size_t t = (size_t)K->vtet[s];
        int f;
        for (f = 0; f < 4; f++) {
            int32_t nb = M->nbr[4 * t + (size_t)f];
            /* a face inside the star is seen from both sides: test it once */
            if (nb >= 0 && M->tet[4 * t + (size_t)f] != v && (size_t)(nb >> 2) < t)
                continue;
            if (face_conflict(M, t, f, v, x, wv) && !face_conflict(M, t, f, v, x0, w0))
                return 0;
        }
    }
    for (s = K->voff[v]; s < K->voff[v + 1]; s++) {
        size_t t = (size_t)K->vtet[s];
        const double *P[4];
        double W[4];
        corners(M, t, v, x, wv, P, W);
        if (cvm__tet_centre_inside(P[0], P[1], P[2], P[3], W) < 0) {
            nout++;
            bout += K->bnd[t];
        }
        nout0 += K->out[t];
        bout0 += K->out[t] & K->bnd[t];
    }
    return nout <= nout0 && bout <= bout0;
}

int cvm__d3_outside(const cvm__d3_mesh *M, size_t t)
{
    const double *P[4];
    double W[4];
    corners(M, t, -1, NULL, 0, P, W);
    return cvm__tet_centre_inside(P[0], P[1], P[2], P[3], W) < 0;
}

int cvm__d3_face_regular(const cvm__d3_mesh *M, size_t t, int f)
{
    return !face_conflict(M, t, f, -1, NULL, 0);
}
