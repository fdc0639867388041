/*
 * fuzz_insert3.c - libFuzzer target: bytes -> a small 3D point set on an
 * 8 x 8 x 4 grid or a BCC snippet, its Delaunay tetrahedralisation, then
 * points on a half-grid (so they fall on vertices, edges, faces, the hull and
 * outside it) inserted by cvm_mesh_insert_points_nd(), optionally with
 * min_dist, weights, or the hull made constrained (the constrained path of
 * lib/api/mesh3_insert.c) -> no kernel fault; cvm_mesh_check() accepts the
 * result; the ids of the inserted points are consecutive after the old
 * vertices; no inserted point is nearer than min_dist to a vertex before it
 * (one in a tetrahedron: a vertex whose power cell vanished is not seen);
 * and without weights the result is byte for byte the Delaunay
 * tetrahedralisation of the old vertices and the inserted points.
 *
 * Layout (missing bytes read as 0):
 *   byte 0  flags: 1 BCC snippet instead of the grid, 2 weights (b % 16) / 16
 *           on the old vertices, 4 the hull constrained, 8 min_dist from byte 3,
 *           16 one call per point, 32 the last new point NaN (refused whole)
 *   byte 1  old points, 4 + b % 60;  byte 2  new points, 1 + b % 40;
 *   byte 3  min_dist = b / 64
 *   then one byte per old point (as fuzz_delaunay3.c), two per new point:
 *   x = (v & 15) / 2 - 0.5, y = ((v >> 4) & 15) / 2 - 0.5, z = ((v >> 8) & 7) / 2 - 0.5,
 *   plus 1/3 on x when bit 11 is set; then one weight byte per old vertex.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api/mesh3_internal.h"
#include "cvmesh.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define FUZZ_NAME "fuzz_insert3"
#include "fuzz_require.h"

#define MAXP 64
#define MAXQ 40

static uint8_t byte_at(const uint8_t *data, size_t size, size_t *pos)
{
    uint8_t b = *pos < size ? data[*pos] : 0;
    (*pos)++;
    return b;
}

static cvm_mesh *tetrahedralise(const double *p, size_t n)
{
    cvm_mesh *m = NULL;
    FUZZ_REQUIRE(cvm_mesh_create(&m) == CVM_OK, "create");
    FUZZ_REQUIRE(cvm_mesh_set_points(m, p, n, 3) == CVM_OK, "set_points: %s", cvm_mesh_errmsg(m));
    if (cvm_mesh_triangulate(m) != CVM_OK) {
        cvm_mesh_free(m);
        return NULL;
    }
    return m;
}

static void fetch(cvm_mesh *m, double **p, size_t *nv, cvm_index **t, size_t *nt)
{
    FUZZ_REQUIRE(cvm_mesh_count(nv, m, CVM_ENT_VERTEX) == CVM_OK, "count");
    FUZZ_REQUIRE(cvm_mesh_count(nt, m, CVM_ENT_TETRAHEDRON) == CVM_OK, "count");
    *p = (double *)malloc(3 * *nv * sizeof(double) + 1);
    *t = (cvm_index *)malloc(4 * *nt * sizeof(cvm_index) + 1);
    FUZZ_REQUIRE(*p && *t, "out of memory");
    FUZZ_REQUIRE(cvm_mesh_copy_points_nd(*p, 3 * *nv, 3, m) == CVM_OK, "copy_points");
    FUZZ_REQUIRE(cvm_mesh_copy_cells(*t, 4 * *nt, m, CVM_ENT_TETRAHEDRON) == CVM_OK, "copy_cells");
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    size_t pos = 0, n, nq, i, j, nv0, nt0, nv, nt, got = 0;
    int flags;
    double p[3 * MAXP], q[3 * MAXQ], w[MAXP], md, *v0, *v1;
    cvm_index ids[MAXQ], *t0, *t1;
    unsigned char used[MAXP + MAXQ];
    cvm_mesh *m;
    cvm_status s = CVM_OK;
    flags = byte_at(data, size, &pos);
    n = 4 + byte_at(data, size, &pos) % (MAXP - 4);
    nq = 1 + byte_at(data, size, &pos) % MAXQ;
    md = (flags & 8) ? byte_at(data, size, &pos) / 64.0 : (byte_at(data, size, &pos), 0.0);
    for (i = 0; i < n; i++) {
        uint8_t b = byte_at(data, size, &pos);
        if (flags & 1) {
            double h = (b & 1) ? 0.5 : 0.0;
            p[3 * i] = ((b >> 1) & 3) + h, p[3 * i + 1] = ((b >> 3) & 3) + h;
            p[3 * i + 2] = ((b >> 5) & 3) + h;
        } else {
            p[3 * i] = b & 7, p[3 * i + 1] = (b >> 3) & 7, p[3 * i + 2] = b >> 6;
        }
    }
    for (i = 0; i < nq; i++) {
        unsigned v = byte_at(data, size, &pos);
        v |= (unsigned)byte_at(data, size, &pos) << 8;
        q[3 * i] = (v & 15) / 2.0 - 0.5 + ((v >> 11) & 1) / 3.0;
        q[3 * i + 1] = ((v >> 4) & 15) / 2.0 - 0.5;
        q[3 * i + 2] = ((v >> 8) & 7) / 2.0 - 0.5;
    }
    for (i = 0; i < MAXP; i++)
        w[i] = (double)(byte_at(data, size, &pos) % 16) / 16.0;
    if (!(m = tetrahedralise(p, n)))
        return 0; /* degenerate: fuzz_delaunay3 covers the refusal */
    if (flags & 2)
        FUZZ_REQUIRE(cvm_mesh_count(&nv0, m, CVM_ENT_VERTEX) == CVM_OK
                         && cvm_mesh_set_weights(m, w, nv0) == CVM_OK,
                     "set_weights: %s", cvm_mesh_errmsg(m));
    if (flags & 4)
        m->m3->delaunay = 0; /* hull faces become constraints (mesh3_insert.c) */
    fetch(m, &v0, &nv0, &t0, &nt0);
    if (flags & 32) {
        q[3 * (nq - 1) + 1] = NAN;
        FUZZ_REQUIRE(cvm_mesh_insert_points_nd(ids, m, q, nq, 3, md) == CVM_E_INPUT_NONFINITE,
                     "NaN accepted");
        FUZZ_REQUIRE(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX) == CVM_OK && nv == nv0,
                     "a refused call changed the mesh");
        q[3 * (nq - 1) + 1] = 0.25;
    }
    if (flags & 16) {
        for (i = 0; i < nq && s == CVM_OK; i++)
            s = cvm_mesh_insert_points_nd(ids + i, m, q + 3 * i, 1, 3, md);
    } else {
        s = cvm_mesh_insert_points_nd(ids, m, q, nq, 3, md);
    }
    FUZZ_REQUIRE(s == CVM_OK, "insert: %s", cvm_mesh_errmsg(m));
    FUZZ_REQUIRE(cvm_mesh_check(m) == CVM_OK, "check: %s", cvm_mesh_errmsg(m));
    fetch(m, &v1, &nv, &t1, &nt);
    FUZZ_REQUIRE(nv <= MAXP + MAXQ, "%zu vertices", nv);
    memset(used, 0, sizeof used);
    for (i = 0; i < 4 * nt; i++)
        used[t1[i]] = 1;
    for (i = 0; i < nq; i++) {
        if (ids[i] == CVM_REJECTED)
            continue;
        FUZZ_REQUIRE(ids[i] == (cvm_index)(nv0 + got), "point %zu got id %ld", i, (long)ids[i]);
        FUZZ_REQUIRE(memcmp(v1 + 3 * ids[i], q + 3 * i, 3 * sizeof(double)) == 0, "moved");
        for (j = 0; j < (size_t)ids[i]; j++) {
            const double *a = v1 + 3 * j, *b = q + 3 * i;
            double d = (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1])
                       + (a[2] - b[2]) * (a[2] - b[2]);
            if (!used[j])
                continue; /* a vertex whose power cell vanished is in no tetrahedron */
            FUZZ_REQUIRE(d > 0 && d >= md * md, "point %zu inserted %g from vertex %zu", i,
                         sqrt(d), j);
        }
        got++;
    }
    FUZZ_REQUIRE(nv == nv0 + got && memcmp(v0, v1, 3 * nv0 * sizeof(double)) == 0,
                 "old vertices changed");
    if (!(flags & 2)) { /* the Delaunay tetrahedralisation of all, symbolic ties by id */
        cvm_mesh *r = tetrahedralise(v1, nv);
        double *v2;
        cvm_index *t2;
        size_t nv2, nt2;
        FUZZ_REQUIRE(r != NULL, "all points degenerate");
        fetch(r, &v2, &nv2, &t2, &nt2);
        FUZZ_REQUIRE(nv2 == nv && nt2 == nt, "%zu/%zu tetrahedra, triangulating all gives %zu/%zu",
                     nv, nt, nv2, nt2);
        FUZZ_REQUIRE(memcmp(t1, t2, 4 * nt * sizeof(cvm_index)) == 0,
                     "not the Delaunay tetrahedralisation of all points");
        free(v2);
        free(t2);
        cvm_mesh_free(r);
    }
    free(v0);
    free(t0);
    free(v1);
    free(t1);
    cvm_mesh_free(m);
    return 0;
}
