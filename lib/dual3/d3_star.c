/*
 * d3_star.c - one vertex's star in the 3D power-dual optimiser: the smooth
 * penalty of its tetrahedra (floating point) and the exact checks that keep
 * the mesh a valid regular tetrahedralisation (dual3.h).
 */
#include <math.h>
#include <string.h>

#include "dual3/d3_internal.h"
#include "geom/geom_internal.h"

void cvm__d3_corners(const cvm__d3_mesh *M, size_t t, int32_t v, const double *x, double wv,
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

/* The geometry of P that the penalty and the angle check share: e_k = P_k - P_0,
 * inward face normals n[i] (length twice the face's area; face i opposite corner i),
 * their lengths, and 6 x the volume. 0, or -1 when the volume is not positive. */
typedef struct d3_geo {
    double e[3][3], n[4][3], len[4], det;
} d3_geo;

static int tet_geo(const double *const P[4], d3_geo *G)
{
    int k;
    for (k = 0; k < 3; k++)
        sub3(P[k + 1], P[0], G->e[k]);
    /* e_0 . n_1 = e_1 . n_2 = e_2 . n_3 = det, > 0 for a positively oriented tetrahedron
       (orient3d > 0): each n_k points towards P_k */
    cross3(G->e[2], G->e[1], G->n[1]);
    cross3(G->e[0], G->e[2], G->n[2]);
    cross3(G->e[1], G->e[0], G->n[3]);
    G->det = dot3(G->e[0], G->n[1]);
    if (!(G->det > 0))
        return -1;
    for (k = 0; k < 3; k++) /* the area vectors of a closed surface sum to zero */
        G->n[0][k] = -(G->n[1][k] + G->n[2][k] + G->n[3][k]);
    for (k = 0; k < 4; k++) {
        G->len[k] = sqrt(dot3(G->n[k], G->n[k]));
        if (!(G->len[k] > 0))
            return -1;
    }
    return 0;
}

double cvm__d3_tet_penalty(const double *const P[4], const double W[4], double margin,
                           double *dist_out)
{
    d3_geo G;
    double y[3], c[3], r[3], l2, l, pen = 0, d, gap;
    int i, k;
    if (tet_geo(P, &G))
        return HUGE_VAL;
    /* power vertex y (relative to P0): 2 e_k . y = |e_k|^2 - (w_k - w_0) */
    for (k = 0; k < 3; k++)
        r[k] = dot3(G.e[k], G.e[k]) - (W[k + 1] - W[0]);
    for (k = 0; k < 3; k++)
        y[k] = (r[0] * G.n[1][k] + r[1] * G.n[2][k] + r[2] * G.n[3][k]) / (2 * G.det);
    /* the mean squared edge sets the scale */
    sub3(G.e[1], G.e[0], c);
    l2 = r[0] + r[1] + r[2] + (W[1] - W[0]) + (W[2] - W[0]) + (W[3] - W[0]) + dot3(c, c);
    sub3(G.e[2], G.e[0], c);
    l2 += dot3(c, c);
    sub3(G.e[2], G.e[1], c);
    l2 = (l2 + dot3(c, c)) / 6;
    l = sqrt(l2);
    for (i = 0; i < 4; i++) {
        /* signed distance from face i's plane, > 0 on corner i's side */
        if (i == 0) {
            sub3(y, G.e[0], c);
            d = dot3(c, G.n[0]) / G.len[0];
        } else {
            d = dot3(y, G.n[i]) / G.len[i];
        }
        gap = margin * l - d;
        if (gap > 0)
            pen += gap * gap;
    }
    for (k = 0; k < 3; k++)
        c[k] = 0.25 * (G.e[0][k] + G.e[1][k] + G.e[2][k]) - y[k];
    if (dist_out)
        *dist_out = sqrt(dot3(c, c));
    return (pen + 1e-3 * dot3(c, c)) / l2;
}

/* The largest cosine of a dihedral angle of (P) (the smallest angle's), or 2 when flat. */
static double tet_max_cos(const double *const P[4])
{
    d3_geo G;
    double cmax = -1;
    int i, j;
    if (tet_geo(P, &G))
        return 2;
    for (i = 0; i < 4; i++)
        for (j = i + 1; j < 4; j++) {
            /* inward normals: the angle at the edge shared by faces i, j */
            double c = -dot3(G.n[i], G.n[j]) / (G.len[i] * G.len[j]);
            cmax = c > cmax ? c : cmax;
        }
    return cmax;
}

double cvm__d3_star_penalty(const cvm__d3_work *K, int32_t v, const double *x, double wv,
                            double stop)
{
    const cvm__d3_mesh *M = K->M;
    size_t s;
    double sum = 0;
    for (s = 0; s < K->nstar; s++) {
        size_t t = (size_t)K->star[s];
        const double *P[4];
        double W[4], f;
        cvm__d3_corners(M, t, v, x, wv, P, W);
        f = cvm__d3_tet_penalty(P, W, K->p->margin, NULL);
        if (f == HUGE_VAL)
            return HUGE_VAL;
        sum += K->bnd[t] ? 2 * f : f; /* L_k */
        if (sum >= stop) /* every term is >= 0: it cannot win any more */
            return sum;
    }
    return sum;
}

double cvm__d3_tet_max_cos(const cvm__d3_mesh *M, size_t t, int32_t v, const double *x)
{
    const double *P[4];
    double W[4];
    cvm__d3_corners(M, t, v, x, 0, P, W);
    return tet_max_cos(P);
}

double cvm__d3_star_max_cos(const cvm__d3_work *K, int32_t v, const double *x)
{
    size_t s;
    double cmax = -1;
    for (s = 0; s < K->nstar; s++) {
        double c = cvm__d3_tet_max_cos(K->M, (size_t)K->star[s], v, x);
        cmax = c > cmax ? c : cmax;
    }
    return cmax;
}

/* The exact power test of face f of tetrahedron t against the vertex across
 * it, v at (x, wv): 1 when that vertex is in conflict (the face is not
 * locally regular), else 0; 0 for a constrained face. sos: ties decided by the
 * symbolic perturbation (by vertex index) that cvm_mesh_check() and
 * lib/delaunay3 use; else a tie is no conflict (strictly inside only). */
static int d3s_face_test(const cvm__d3_mesh *M, size_t t, int f, int32_t v, const double *x,
                     double wv, int sos)
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
    cvm__d3_corners(M, t, v, x, wv, P, W);
    E = M->xyz + 3 * (size_t)e;
    we = M->w[e];
    if (!sos)
        return cvm__power3d(P[0], P[1], P[2], P[3], E, W[0], W[1], W[2], W[3], we) > 0;
    return cvm__power3d_sos(P[0], P[1], P[2], P[3], E, W[0], W[1], W[2], W[3], we,
                            M->tet[4 * t], M->tet[4 * t + 1], M->tet[4 * t + 2],
                            M->tet[4 * t + 3], e) > 0;
}

static int face_conflict(const cvm__d3_mesh *M, size_t t, int f, int32_t v, const double *x,
                         double wv)
{
    return d3s_face_test(M, t, f, v, x, wv, 1);
}

int cvm__d3_star_check(const cvm__d3_work *K, int32_t v, const double *x, double wv, int counts)
{
    const cvm__d3_mesh *M = K->M;
    const double *x0 = M->xyz + 3 * (size_t)v;
    double w0 = M->w[v];
    size_t s, nout = 0, nout0 = 0, bout = 0, bout0 = 0;
    for (s = 0; s < K->nstar; s++) {
        size_t t = (size_t)K->star[s];
        const double *P[4];
        double W[4];
        cvm__d3_corners(M, t, v, x, wv, P, W);
        if (!(cvm__orient3d(P[0], P[1], P[2], P[3]) > 0))
            return -1;
    }
    for (s = 0; s < K->nstar; s++) {
        size_t t = (size_t)K->star[s];
        int f;
        for (f = 0; f < 4; f++) {
            int32_t nb = M->nbr[4 * t + (size_t)f];
            /* a face inside the star is seen from both sides: test it once */
            if (nb >= 0 && M->tet[4 * t + (size_t)f] != v && (size_t)(nb >> 2) < t)
                continue;
            if (face_conflict(M, t, f, v, x, wv) &&
                (!face_conflict(M, t, f, v, x0, w0) ||
                 /* with flips, a face failing on a tie only may not fail strictly */
                 (K->p->flips && d3s_face_test(M, t, f, v, x, wv, 0) &&
                  !d3s_face_test(M, t, f, v, x0, w0, 0))))
                return 1;
        }
    }
    if (!counts)
        return 0;
    for (s = 0; s < K->nstar; s++) {
        size_t t = (size_t)K->star[s];
        const double *P[4];
        double W[4];
        cvm__d3_corners(M, t, v, x, wv, P, W);
        if (cvm__tet_centre_inside(P[0], P[1], P[2], P[3], W) < 0) {
            nout++;
            bout += K->bnd[t];
        }
        nout0 += K->out[t];
        bout0 += K->out[t] & K->bnd[t];
    }
    return nout <= nout0 && bout <= bout0 ? 0 : 2;
}

int cvm__d3_outside(const cvm__d3_mesh *M, size_t t)
{
    const double *P[4];
    double W[4];
    cvm__d3_corners(M, t, -1, NULL, 0, P, W);
    return cvm__tet_centre_inside(P[0], P[1], P[2], P[3], W) < 0;
}

int cvm__d3_face_regular(const cvm__d3_mesh *M, size_t t, int f)
{
    return !face_conflict(M, t, f, -1, NULL, 0);
}

int cvm__d3_face_conflict_at(const cvm__d3_mesh *M, size_t t, int f, int32_t v, const double *x,
                             double wv, int sos)
{
    int32_t nb = M->nbr[4 * t + (size_t)f];
    /* the test from t's side sees v only as a corner: with v across, ask from there */
    if (nb >= 0 && M->tet[4 * ((size_t)nb >> 2) + ((size_t)nb & 3)] == v)
        return d3s_face_test(M, (size_t)nb >> 2, nb & 3, v, x, wv, sos);
    return d3s_face_test(M, t, f, v, x, wv, sos);
}
