/*
 * test_mesh3_insert.c - cvm_mesh_insert_points_nd() on 3D meshes: insertion
 * into random and BCC Delaunay tetrahedralisations gives the Delaunay
 * tetrahedralisation of all the points (same bytes as triangulating them),
 * every interior face passes the exact in-sphere test, Euler characteristic
 * and volume stay; rejections (outside, duplicate, min_dist, on a constrained
 * face), NaN, stops, weights, recovered surfaces keep every boundary triangle
 * and their regions, and OOM at every allocation.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api/api_tests.h"
#include "api/mesh3_internal.h"
#include "geom/geom_internal.h"
#include "support/failing_alloc.h"
#include "support/skip.h"

static uint64_t next_u64(uint64_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 7;
    *s ^= *s << 17;
    return *s;
}

/* xorshift points in lo + [0, 1)^3 * span, the same for every run. */
static double *rand_pts(size_t n, uint64_t seed, double lo, double span)
{
    double *p = malloc(3 * n * sizeof *p);
    size_t i;
    ck_assert_ptr_nonnull(p);
    for (i = 0; i < 3 * n; i++)
        p[i] = lo + span * ((double)(next_u64(&seed) >> 11) / 9007199254740992.0);
    return p;
}

static double *bcc_pts(int k, size_t *n)
{
    double *p = malloc(3 * (size_t)((k + 1) * (k + 1) * (k + 1) + k * k * k) * sizeof *p);
    int x, y, z;
    *n = 0;
    for (x = 0; x <= k; x++)
        for (y = 0; y <= k; y++)
            for (z = 0; z <= k; z++) {
                p[3 * *n] = x, p[3 * *n + 1] = y, p[3 * *n + 2] = z;
                ++*n;
                if (x < k && y < k && z < k) {
                    p[3 * *n] = x + 0.5, p[3 * *n + 1] = y + 0.5, p[3 * *n + 2] = z + 0.5;
                    ++*n;
                }
            }
    return p;
}

static int cmp_i64_tests(const void *a, const void *b)
{
    int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;
    return (x > y) - (x < y);
}

typedef struct snap {
    int ties_allowed; /* verify(): the plain exact in-sphere test, no perturbation */
    size_t nv, nt, nf;
    double *p, *attr;
    cvm_index *tet, *face;
} snap;

static void take(snap *s, cvm_mesh *m)
{
    s->ties_allowed = 0;
    ck_assert_int_eq(cvm_mesh_count(&s->nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&s->nt, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&s->nf, m, CVM_ENT_TRIANGLE), CVM_OK);
    s->p = malloc((3 * s->nv + 1) * sizeof *s->p);
    s->tet = malloc((4 * s->nt + 1) * sizeof *s->tet);
    s->face = malloc((3 * s->nf + 1) * sizeof *s->face);
    s->attr = malloc((s->nt + 1) * sizeof *s->attr);
    ck_assert_int_eq(cvm_mesh_copy_points_nd(s->p, 3 * s->nv, 3, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(s->tet, 4 * s->nt, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(s->face, 3 * s->nf, m, CVM_ENT_TRIANGLE), CVM_OK);
    /* no public 3D accessor of the region attributes yet: read the handle */
    if (m->m3->tattr)
        memcpy(s->attr, m->m3->tattr, s->nt * sizeof *s->attr);
    else
        memset(s->attr, 0, (s->nt + 1) * sizeof *s->attr);
}

static void drop(snap *s)
{
    free(s->p);
    free(s->tet);
    free(s->face);
    free(s->attr);
}

static double vol6(const double *p, const cvm_index *t)
{
    const double *a = p + 3 * t[0], *b = p + 3 * t[1], *c = p + 3 * t[2], *d = p + 3 * t[3];
    double u[3], v[3], w[3];
    int k;
    for (k = 0; k < 3; k++)
        u[k] = a[k] - d[k], v[k] = b[k] - d[k], w[k] = c[k] - d[k];
    return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
           + u[2] * (v[0] * w[1] - v[1] * w[0]);
}

/* Volume of the tetrahedra with attribute a (all with a = NAN). */
static double volume(const snap *s, double a)
{
    double v = 0;
    size_t i;
    for (i = 0; i < s->nt; i++)
        if (isnan(a) || s->attr[i] == a)
            v += vol6(s->p, s->tet + 4 * i) / 6.0;
    return v;
}

/* A face of a tetrahedron: its sorted corners, the tetrahedron and the opposite corner. */
typedef struct tface {
    int64_t key;
    size_t tet;
    cvm_index apex;
} tface;

static int cmp_tface(const void *a, const void *b)
{
    const tface *x = a, *y = b;
    if (x->key != y->key)
        return x->key < y->key ? -1 : 1;
    return x->tet < y->tet ? -1 : x->tet > y->tet;
}

static int64_t face_key(cvm_index a, cvm_index b, cvm_index c, size_t nv)
{
    cvm_index t;
    if (a > b)
        t = a, a = b, b = t;
    if (b > c)
        t = b, b = c, c = t;
    if (a > b)
        t = a, a = b, b = t;
    return ((int64_t)a * (int64_t)nv + b) * (int64_t)nv + c;
}

/* Every tetrahedron positive; every face in one or two tetrahedra; faces in
 * one are exactly the listed boundary faces when boundary_is_listed; every
 * interior face not listed passes the exact in-sphere test (power test with
 * w) both ways. Returns V - E + F - T. */
static int has_vertex_from(const cvm_index *t, size_t from)
{
    return (size_t)t[0] >= from || (size_t)t[1] >= from || (size_t)t[2] >= from
           || (size_t)t[3] >= from;
}

static long verify_from(const snap *s, const double *w, int boundary_is_listed, size_t from)
{
    char *used = calloc(s->nv + 1, 1);
    size_t nused = 0;
    tface *f = malloc(4 * s->nt * sizeof *f);
    int64_t *e = malloc(6 * s->nt * sizeof *e), *listed = malloc((s->nf + 1) * sizeof *listed);
    size_t i, k, nf = 0, ne = 0, nb = 0;
    static const int ep[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
    for (i = 0; i < s->nt; i++) {
        const cvm_index *t = s->tet + 4 * i;
        ck_assert_msg(cvm__orient3d(s->p + 3 * t[0], s->p + 3 * t[1], s->p + 3 * t[2],
                                    s->p + 3 * t[3]) > 0, "tet %lu not positive", (unsigned long)i);
        for (k = 0; k < 4; k++) {
            f[4 * i + k].key = face_key(t[(k + 1) % 4], t[(k + 2) % 4], t[(k + 3) % 4], s->nv);
            f[4 * i + k].tet = i;
            f[4 * i + k].apex = t[k];
        }
        for (k = 0; k < 6; k++) {
            int64_t a = t[ep[k][0]], b = t[ep[k][1]];
            e[6 * i + k] = a < b ? a * (int64_t)s->nv + b : b * (int64_t)s->nv + a;
        }
    }
    for (i = 0; i < s->nf; i++)
        listed[i] = face_key(s->face[3 * i], s->face[3 * i + 1], s->face[3 * i + 2], s->nv);
    qsort(f, 4 * s->nt, sizeof *f, cmp_tface);
    qsort(e, 6 * s->nt, sizeof *e, cmp_i64_tests);
    qsort(listed, s->nf, sizeof *listed, cmp_i64_tests);
    for (i = 0; i < 6 * s->nt; i++)
        ne += i == 0 || e[i] != e[i - 1];
    for (i = 0; i < 4 * s->nt; i = k) {
        for (k = i + 1; k < 4 * s->nt && f[k].key == f[i].key; k++)
            ;
        ck_assert_msg(k - i <= 2, "a face in %lu tetrahedra", (unsigned long)(k - i));
        nf++;
        if (k - i == 1) {
            nb++;
            if (boundary_is_listed)
                ck_assert_msg(bsearch(&f[i].key, listed, s->nf, sizeof *listed, cmp_i64_tests),
                              "boundary face not listed");
        } else if (!bsearch(&f[i].key, listed, s->nf, sizeof *listed, cmp_i64_tests)
                   && (has_vertex_from(s->tet + 4 * f[i].tet, from)
                       || has_vertex_from(s->tet + 4 * f[i + 1].tet, from))) {
            int side;
            for (side = 0; side < 2; side++) {
                const cvm_index *a = s->tet + 4 * f[i + side].tet;
                cvm_index q = f[i + 1 - side].apex;
                const double *P = s->p;
                int in = s->ties_allowed
                             ? cvm__insphere(P + 3 * a[0], P + 3 * a[1], P + 3 * a[2], P + 3 * a[3],
                                             P + 3 * q) > 0
                         : w ? cvm__power3d_sos(P + 3 * a[0], P + 3 * a[1], P + 3 * a[2], P + 3 * a[3],
                                              P + 3 * q, w[a[0]], w[a[1]], w[a[2]], w[a[3]], w[q],
                                              a[0], a[1], a[2], a[3], q)
                           : cvm__insphere_sos(P + 3 * a[0], P + 3 * a[1], P + 3 * a[2],
                                               P + 3 * a[3], P + 3 * q, a[0], a[1], a[2], a[3], q);
                ck_assert_msg(in <= 0, "vertex %ld inside the sphere of tetrahedron %lu", (long)q,
                              (unsigned long)f[i + side].tet);
            }
        }
    }
    if (boundary_is_listed)
        ck_assert_uint_eq(nb, s->nf);
    for (i = 0; i < 4 * s->nt; i++)
        used[s->tet[i]] = 1;
    for (i = 0; i < s->nv; i++)
        nused += used[i];
    free(used);
    free(f);
    free(e);
    free(listed);
    return (long)nused - (long)ne + (long)nf - (long)s->nt;
}

static long verify(const snap *s, const double *w, int boundary_is_listed)
{
    return verify_from(s, w, boundary_is_listed, 0);
}

static cvm_mesh *mesh_of(const double *p, size_t n)
{
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, p, n, 3), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    return m;
}

/* Insert q into the tetrahedralisation of p; the result must be the
 * tetrahedralisation of p then q, byte for byte, and pass verify(). */
static void insert_equals_triangulate(const double *p, size_t n, const double *q, size_t nq,
                                      double want_volume, int constrained)
{
    cvm_mesh *m = mesh_of(p, n), *r;
    if (constrained) /* the hull faces become constraints: the constrained path (mesh3_insert.c) */
        m->m3->delaunay = 0;
    cvm_index *ids = malloc(nq * sizeof *ids);
    double *all = malloc(3 * (n + nq) * sizeof *all);
    snap a, b;
    size_t i;
    /* one point, then the rest: the store is loaded twice */
    ck_assert_msg(cvm_mesh_insert_points_nd(ids, m, q, 1, 3, 0.0) == CVM_OK, "%s",
                  cvm_mesh_errmsg(m));
    ck_assert_msg(cvm_mesh_insert_points_nd(ids + 1, m, q + 3, nq - 1, 3, 0.0) == CVM_OK, "%s",
                  cvm_mesh_errmsg(m));
    for (i = 0; i < nq; i++)
        ck_assert_int_eq(ids[i], (cvm_index)(n + i));
    ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    take(&a, m);
    ck_assert_int_eq(verify(&a, NULL, 1), 1);
    ck_assert_msg(fabs(volume(&a, NAN) - want_volume) <= 1e-12 * want_volume, "volume %.17g",
                  volume(&a, NAN));
    memcpy(all, p, 3 * n * sizeof *all);
    memcpy(all + 3 * n, q, 3 * nq * sizeof *all);
    r = mesh_of(all, n + nq);
    take(&b, r);
    ck_assert_uint_eq(a.nv, b.nv);
    ck_assert_uint_eq(a.nt, b.nt);
    ck_assert_uint_eq(a.nf, b.nf);
    ck_assert(memcmp(a.p, b.p, 3 * a.nv * sizeof *a.p) == 0);
    ck_assert(memcmp(a.tet, b.tet, 4 * a.nt * sizeof *a.tet) == 0);
    if (!constrained) /* else the same faces, in the order of the first mesh */
        ck_assert(memcmp(a.face, b.face, 3 * a.nf * sizeof *a.face) == 0);
    drop(&a);
    drop(&b);
    cvm_mesh_free(m);
    cvm_mesh_free(r);
    free(ids);
    free(all);
}

START_TEST(insertion_gives_the_delaunay_tetrahedralisation_of_all_points)
{
    static const double corners[24] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0,
                                       0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1};
    size_t n = 3000, nq = 1500;
    double *p = rand_pts(n, 42, 0, 1), *q = rand_pts(nq, 43, 0, 1);
    memcpy(p, corners, sizeof corners);
    /* a few on the hull: they split hull faces, the hull stays the cube */
    q[0] = 0.5, q[1] = 0.25, q[2] = 0.0;
    q[3] = 1.0, q[4] = 0.5, q[5] = 0.5;
    q[6] = 0.0, q[7] = 0.0, q[8] = 0.5; /* on a hull edge */
    insert_equals_triangulate(p, n, q, nq, 1.0, 0);
    insert_equals_triangulate(p, n, q + 9, nq - 3, 1.0, 1); /* the hull constrained */
    free(p);
    free(q);
}
END_TEST

/* The BCC lattice and the face centres of its cubes: everything cospherical,
 * symbolic perturbation decides the same way as for triangulating it all. */
START_TEST(insertion_into_a_bcc_lattice_is_exact)
{
    size_t n, nq = 0;
    int k = 5, x, y, z;
    double *p = bcc_pts(k, &n), *q = malloc(3 * (size_t)(k * k * k) * sizeof *q);
    for (x = 0; x < k; x++)
        for (y = 0; y < k; y++)
            for (z = 0; z < k; z++) {
                q[3 * nq] = x + 0.5, q[3 * nq + 1] = y + 0.5, q[3 * nq + 2] = z;
                nq++;
            }
    insert_equals_triangulate(p, n, q, nq, (double)(k * k * k), 0);
    /* the same with the hull constrained (no point on it): the constrained
     * cavity of a constrained Delaunay mesh gives the same tetrahedra */
    for (x = 0; x < (int)nq; x++)
        if (q[3 * x + 2] == 0)
            q[3 * x + 2] = 0.25;
    insert_equals_triangulate(p, n, q, nq, (double)(k * k * k), 1);
    free(p);
    free(q);
}
END_TEST

START_TEST(points_outside_on_vertices_near_or_not_finite_are_rejected)
{
    static const double corners[24] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0,
                                       0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1};
    size_t n = 400, nv, i;
    double *p = rand_pts(n, 7, 0, 1), q[12], md = 0.05;
    cvm_index ids[4];
    cvm_mesh *m = mesh_of(p, n);
    snap s;
    /* outside the hull, an existing vertex, one just beside a vertex, an inner point */
    q[0] = 2, q[1] = 0.5, q[2] = 0.5;
    memcpy(q + 3, p + 3 * 17, 3 * sizeof *q);
    q[6] = p[3 * 20] + 1e-9, q[7] = p[3 * 20 + 1], q[8] = p[3 * 20 + 2];
    q[9] = 0.5, q[10] = 0.5, q[11] = 0.5;
    ck_assert_int_eq(cvm_mesh_insert_points_nd(ids, m, q, 4, 3, 0.0), CVM_OK);
    ck_assert_int_eq(ids[0], CVM_REJECTED);
    ck_assert_int_eq(ids[1], CVM_REJECTED);
    ck_assert_int_eq(ids[2], (cvm_index)n);
    ck_assert_int_eq(ids[3], (cvm_index)n + 1);
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    /* a point repeated in one call: the first copy is inserted */
    {
        double rep[9] = {0.3, 0.3, 0.3, 0.4, 0.35, 0.3, 0.3, 0.3, 0.3};
        cvm_index rid[3];
        ck_assert_int_eq(cvm_mesh_insert_points_nd(rid, m, rep, 3, 3, 0.0), CVM_OK);
        ck_assert_int_eq(rid[0], (cvm_index)n + 2);
        ck_assert_int_eq(rid[1], (cvm_index)n + 3);
        ck_assert_int_eq(rid[2], CVM_REJECTED);
        n += 2;
    }
    /* NaN: the call names the point and inserts nothing */
    q[7] = NAN;
    ck_assert_int_eq(cvm_mesh_insert_points_nd(ids, m, q, 4, 3, 0.0), CVM_E_INPUT_NONFINITE);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "point 2"));
    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_uint_eq(nv, n + 2);
    n -= 2;
    ck_assert_int_eq(cvm_mesh_insert_points_nd(ids, m, q, 1, 3, -1.0), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_mesh_insert_points_nd(ids, m, q, 1, 3, INFINITY), CVM_E_INPUT_NONFINITE);
    ck_assert_int_eq(cvm_mesh_insert_points_nd(ids, m, NULL, 1, 3, 0.0), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_insert_points_nd(ids, m, q, 0, 3, 0.0), CVM_OK);
    /* min_dist: one point at a time, rejected exactly when the nearest vertex
     * (by brute force, the same rounded squared distance) is nearer than md */
    cvm_mesh_free(m);
    memcpy(p, corners, sizeof corners); /* the hull is the unit cube */
    m = mesh_of(p, n);
    free(p);
    p = rand_pts(300, 8, 0.05, 0.9);
    for (i = 0; i < 300; i++) {
        const double *x = p + 3 * i;
        double best = INFINITY;
        size_t j;
        cvm_index id;
        take(&s, m);
        for (j = 0; j < s.nv; j++) {
            const double *y = s.p + 3 * j;
            double d = (y[0] - x[0]) * (y[0] - x[0]) + (y[1] - x[1]) * (y[1] - x[1])
                       + (y[2] - x[2]) * (y[2] - x[2]);
            best = d < best ? d : best;
        }
        ck_assert_int_eq(cvm_mesh_insert_points_nd(&id, m, x, 1, 3, md), CVM_OK);
        if (best < md * md)
            ck_assert_int_eq(id, CVM_REJECTED);
        else
            ck_assert_int_eq(id, (cvm_index)s.nv);
        drop(&s);
    }
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    take(&s, m);
    ck_assert_int_eq(verify(&s, NULL, 1), 1);
    drop(&s);
    cvm_mesh_free(m);
    free(p);
}
END_TEST

/* Weighted: new points get weight 0; the mesh stays regular. */
START_TEST(insertion_into_a_regular_tetrahedralisation)
{
    size_t n = 1000, nv, i, nin = 0;
    double *p = rand_pts(n, 99, 0, 1), *w, *q = rand_pts(500, 100, 0.01, 0.98), *w2;
    cvm_index ids[500];
    cvm_mesh *m = mesh_of(p, n);
    snap s;
    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    w = calloc(nv, sizeof *w);
    for (i = 0; i < nv; i++)
        w[i] = 1e-3 * (double)(i % 5);
    ck_assert_int_eq(cvm_mesh_set_weights(m, w, nv), CVM_OK);
    ck_assert_int_eq(cvm_mesh_insert_points_nd(ids, m, q, 500, 3, 0.0), CVM_OK);
    ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    for (i = 0; i < 500; i++)
        if (ids[i] != CVM_REJECTED)
            ck_assert_int_eq(ids[i], (cvm_index)(nv + nin++));
    ck_assert_uint_gt(nin, 100);
    take(&s, m);
    ck_assert_uint_eq(s.nv, nv + nin);
    w2 = calloc(s.nv, sizeof *w2);
    memcpy(w2, w, nv * sizeof *w);
    ck_assert_int_eq(verify(&s, w2, 1), 1);
    /* every vertex is still in a tetrahedron */
    {
        char *used = calloc(s.nv, 1);
        for (i = 0; i < 4 * s.nt; i++)
            used[s.tet[i]] = 1;
        for (i = nv; i < s.nv; i++)
            ck_assert(used[i]);
        free(used);
    }
    drop(&s);
    free(w);
    free(w2);
    free(p);
    free(q);
    cvm_mesh_free(m);
}
END_TEST

static void data3d_path(char *buf, size_t len, const char *name)
{
    const char *d = getenv("CVM_DATA3D_DIR");
    snprintf(buf, len, "%s/%s", d && *d ? d : "examples/data3d", name);
}

static cvm_mesh *read_and_mesh(const char *name)
{
    char path[4096];
    cvm_mesh *m;
    cvm_status s;
    data3d_path(path, sizeof path, name);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_msg(cvm_mesh_read(m, path) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    s = cvm_mesh_triangulate(m);
    if (s != CVM_OK) { /* without TetGen, a surface whose triangles are not Delaunay faces */
        ck_assert_int_eq(s, CVM_E_UNSUPPORTED);
        cvm_mesh_free(m);
        return NULL;
    }
    return m;
}

/* The recovered cube (768 surface triangles): points inside are inserted,
 * every surface triangle stays a face, the volume stays 1, and the mesh stays
 * constrained Delaunay; points outside, on the surface or on a surface edge
 * are rejected. */
START_TEST(insertion_into_a_recovered_cube_keeps_its_surface)
{
    cvm_mesh *m = read_and_mesh("cube.off");
    size_t nq = 800, i, nin = 0;
    double *q, bad[12] = {1.5, 0.5, 0.5, 0.3, 0.7, 1.0, 0.0, 0.3, 0.0, 0.5, 0.5, 0.0};
    cvm_index *ids, bid[4];
    snap a, b;
    long chi;
    if (!m)
        CVMTEST_SKIP("needs TetGen (a TETGEN=1 build)");
    take(&a, m);
    q = rand_pts(nq, 5, 0.001, 0.998);
    ids = malloc(nq * sizeof *ids);
    ck_assert_msg(cvm_mesh_insert_points_nd(ids, m, q, nq, 3, 0.0) == CVM_OK, "%s",
                  cvm_mesh_errmsg(m));
    for (i = 0; i < nq; i++)
        if (ids[i] != CVM_REJECTED)
            ck_assert_int_eq(ids[i], (cvm_index)(a.nv + nin++));
    ck_assert_uint_eq(nin, nq);
    ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    /* outside; on a face; on a surface edge (y = x on the face z = 0? no: a cube
     * edge); at a surface vertex */
    ck_assert_int_eq(cvm_mesh_insert_points_nd(bid, m, bad, 4, 3, 0.0), CVM_OK);
    for (i = 0; i < 4; i++)
        ck_assert_msg(bid[i] == CVM_REJECTED, "point %lu inserted", (unsigned long)i);
    take(&b, m);
    ck_assert_uint_eq(b.nf, a.nf);
    ck_assert(memcmp(a.face, b.face, 3 * a.nf * sizeof *a.face) == 0);
    ck_assert(memcmp(a.p, b.p, 3 * a.nv * sizeof *a.p) == 0);
    b.ties_allowed = 1;
    chi = verify_from(&b, NULL, 1, 0);
    ck_assert_int_eq(chi, 1);
    ck_assert(fabs(volume(&b, NAN) - 1.0) < 1e-12);
    drop(&a);
    drop(&b);
    free(q);
    free(ids);
    cvm_mesh_free(m);
}
END_TEST

/* Two cubes with an internal facet and two regions: cavities stay on one
 * side, each region keeps its volume, the internal facet stays. */
START_TEST(insertion_keeps_regions_and_internal_facets)
{
    cvm_mesh *m = read_and_mesh("two_cubes.poly");
    size_t nq = 400, i;
    double *q;
    cvm_index *ids;
    snap a, b;
    if (!m)
        CVMTEST_SKIP("needs TetGen (a TETGEN=1 build)");
    take(&a, m);
    q = rand_pts(nq, 11, 0.001, 1.998);
    for (i = 0; i < nq; i++) /* y, z in the unit square */
        q[3 * i + 1] *= 0.5, q[3 * i + 2] *= 0.5;
    q[0] = 1.0, q[1] = 0.4, q[2] = 0.3; /* on the internal facet: rejected */
    ids = malloc(nq * sizeof *ids);
    ck_assert_msg(cvm_mesh_insert_points_nd(ids, m, q, nq, 3, 0.0) == CVM_OK, "%s",
                  cvm_mesh_errmsg(m));
    ck_assert_int_eq(ids[0], CVM_REJECTED);
    for (i = 1; i < nq; i++)
        ck_assert_int_ne(ids[i], CVM_REJECTED);
    ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    take(&b, m);
    ck_assert(memcmp(a.face, b.face, 3 * a.nf * sizeof *a.face) == 0);
    b.ties_allowed = 1;
    ck_assert_int_eq(verify_from(&b, NULL, 0, a.nv), 1);
    ck_assert(fabs(volume(&b, NAN) - 2.0) < 1e-12);
    ck_assert(fabs(volume(&b, a.attr[0]) - volume(&a, a.attr[0])) < 1e-12);
    ck_assert(fabs(volume(&b, 1.0) - 1.0) < 1e-12 || fabs(volume(&b, 1.0)) < 1e-12);
    for (i = 0; i < b.nt; i++) { /* a tetrahedron's attribute is its cube's */
        const cvm_index *t = b.tet + 4 * i;
        double cx = (b.p[3 * t[0]] + b.p[3 * t[1]] + b.p[3 * t[2]] + b.p[3 * t[3]]) / 4;
        size_t j;
        for (j = 0; j < a.nt; j++) {
            const cvm_index *u = a.tet + 4 * j;
            double ax = (a.p[3 * u[0]] + a.p[3 * u[1]] + a.p[3 * u[2]] + a.p[3 * u[3]]) / 4;
            if ((ax < 1) == (cx < 1)) {
                ck_assert(b.attr[i] == a.attr[j]);
                break;
            }
        }
    }
    drop(&a);
    drop(&b);
    free(q);
    free(ids);
    cvm_mesh_free(m);
}
END_TEST

static int cancel_after(void *payload, cvm_stage stage, double fraction)
{
    int *left = payload;
    (void)stage, (void)fraction;
    return --*left <= 0;
}

/* A cancelled call keeps the points before the stop; the rest are rejected. */
START_TEST(a_cancelled_insertion_keeps_the_points_before_it)
{
    size_t n = 500, i, nv, got;
    double *p = rand_pts(n, 3, 0, 1), *q = rand_pts(100, 4, 0.1, 0.8);
    cvm_index ids[100];
    cvm_mesh *m = mesh_of(p, n);
    int left = 10;
    ck_assert_int_eq(cvm_mesh_set_progress(m, cancel_after, 1, &left), CVM_OK);
    ck_assert_int_eq(cvm_mesh_insert_points_nd(ids, m, q, 100, 3, 0.0), CVM_INCOMPLETE_CANCELLED);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "cancelled"));
    /* min_dist 0 on a Delaunay mesh: the points go in space-filling-curve
     * order; the 10 taken before the stop are numbered in input order */
    for (i = 0, got = 0; i < 100; i++)
        if (ids[i] != CVM_REJECTED)
            ck_assert_int_eq(ids[i], (cvm_index)(n + got++));
    ck_assert_uint_eq(got, 10);
    /* min_dist > 0: input order, the first 10 */
    cvm_mesh_free(m);
    m = mesh_of(p, n);
    left = 10;
    ck_assert_int_eq(cvm_mesh_set_progress(m, cancel_after, 1, &left), CVM_OK);
    ck_assert_int_eq(cvm_mesh_insert_points_nd(ids, m, q, 100, 3, 1e-9), CVM_INCOMPLETE_CANCELLED);
    for (i = 0; i < 100; i++)
        ck_assert_int_eq(ids[i], i < 10 ? (cvm_index)(n + i) : CVM_REJECTED);
    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_uint_eq(nv, n + 10);
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    free(p);
    free(q);
    cvm_mesh_free(m);
}
END_TEST

/* Allocation k fails, for every k: CVM_E_NOMEM, the ids written match the
 * vertices kept, the mesh checks, nothing leaks; the last run inserts all. */
START_TEST(every_failed_allocation_in_insertion_gives_nomem)
{
    size_t n = 150, nq = 60, nv, i;
    double *p = rand_pts(n, 21, 0, 1), *q = rand_pts(nq, 22, 0.1, 0.8);
    cvm_index ids[60];
    cvmtest_alloc a;
    cvm_mesh *m;
    long k;
    int mode;
    cvmtest_alloc_init(&a, 0, 0);
    ck_assert_int_eq(cvmtest_mesh_create(&m, &a), CVM_OK);
    /* mode 0: curve order (min_dist 0); 1: input order (min_dist); 2: the hull constrained;
     * 3: weighted and constrained (the walk near each point of min_dist) */
    for (mode = 0; mode < 4; mode++)
    for (k = 1;; k++) {
        cvm_status s;
        size_t got = 0;
        ck_assert_int_eq(cvm_mesh_set_points(m, p, n, 3), CVM_OK);
        ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
        if (mode == 3) {
            double w[150];
            for (i = 0; i < n; i++)
                w[i] = 1e-3 * (double)(i % 5);
            ck_assert_int_eq(cvm_mesh_set_weights(m, w, n), CVM_OK);
        }
        if (mode >= 2)
            m->m3->delaunay = 0;
        cvmtest_alloc_arm(&a, k, 0);
        s = cvm_mesh_insert_points_nd(ids, m, q, nq, 3, mode ? 1e-3 : 0.0);
        cvmtest_alloc_arm(&a, 0, 0);
        ck_assert_msg(s == CVM_OK || s == CVM_E_NOMEM, "k=%ld: %s", k, cvm_mesh_errmsg(m));
        ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "k=%ld: %s", k, cvm_mesh_errmsg(m));
        for (i = 0; i < nq; i++)
            if (ids[i] != CVM_REJECTED)
                ck_assert_int_eq(ids[i], (cvm_index)(n + got++));
        ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
        ck_assert_uint_eq(nv, n + got);
        if (s == CVM_OK) {
            ck_assert_uint_eq(got, nq);
            break;
        }
        ck_assert(k < 2000);
    }
    cvm_mesh_free(m);
    ck_assert_int_eq((int)a.live_blocks, 0);
    free(p);
    free(q);
}
END_TEST

TCase *api_mesh3_insert_tcase(void)
{
    TCase *tc = tcase_create("mesh3_insert");
    tcase_set_timeout(tc, 300);
    tcase_add_test(tc, insertion_gives_the_delaunay_tetrahedralisation_of_all_points);
    tcase_add_test(tc, insertion_into_a_bcc_lattice_is_exact);
    tcase_add_test(tc, points_outside_on_vertices_near_or_not_finite_are_rejected);
    tcase_add_test(tc, insertion_into_a_regular_tetrahedralisation);
    tcase_add_test(tc, insertion_into_a_recovered_cube_keeps_its_surface);
    tcase_add_test(tc, insertion_keeps_regions_and_internal_facets);
    tcase_add_test(tc, a_cancelled_insertion_keeps_the_points_before_it);
    tcase_add_test(tc, every_failed_allocation_in_insertion_gives_nomem);
    return tc;
}
