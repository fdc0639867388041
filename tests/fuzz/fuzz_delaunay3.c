/*
 * fuzz_delaunay3.c - libFuzzer target: bytes -> a small 3D point set on an
 * 8 x 8 x 4 grid or a BCC lattice snippet (so duplicates, coplanar and
 * cospherical points are common), with weights -> the Delaunay
 * tetrahedralisation, then the regular one -> no kernel fault; a refusal is
 * an error status with a message (never CVM_E_INTERNAL) and leaves no
 * tetrahedra; on success cvm_mesh_check() (orientation, adjacency, the
 * Delaunay / regular property by the exact predicates) must accept the mesh,
 * the 3D measures and dual must compute, and a second run on a fresh handle
 * must give identical points and tetrahedra.
 *
 * Layout (missing bytes read as 0):
 *   byte 0  flags: 1 map x to 1e6 + x/1000 (rounded: near-degenerate),
 *                  2 nudge odd points by one ulp, 4 BCC snippet instead of the grid,
 *                  8 weights (set after the Delaunay run: the regular one),
 *                  16 CVM_OPT_REJECT_DUPLICATES = 1, 32 repeat every third point
 *   byte 1  number of points, 1 + b % 80
 *   then one byte per point: grid x = b & 7, y = (b >> 3) & 7, z = b >> 6;
 *   BCC (b >> 1) as x, y, z in 0..3 (2 bits each, z from the top), plus
 *   (1/2, 1/2, 1/2) when b & 1; then one weight byte per vertex, w = (b % 16) / 16.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cvmesh.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define FUZZ_NAME "fuzz_delaunay3"
#include "fuzz_require.h"

#define MAXP 80

typedef struct input {
    int flags;
    double xyz[3 * MAXP];
    size_t np;
    double w[MAXP];
} input;

typedef struct output {
    cvm_status status, wstatus;
    size_t nv, nt, ntw;
    double *xyz;
    cvm_index *tet, *tetw;
} output;

static uint8_t byte_at(const uint8_t *data, size_t size, size_t *pos)
{
    uint8_t b = *pos < size ? data[*pos] : 0;
    (*pos)++;
    return b;
}

static double coord(const input *in, double v, int odd)
{
    double x = v;
    if (in->flags & 1)
        x = 1e6 + x * 0.001;
    if ((in->flags & 2) && odd)
        x = nextafter(x, 1e300);
    return x;
}

static void decode(input *in, const uint8_t *data, size_t size)
{
    size_t pos = 0, i;
    memset(in, 0, sizeof *in);
    in->flags = byte_at(data, size, &pos);
    in->np = 1 + byte_at(data, size, &pos) % MAXP;
    for (i = 0; i < in->np; i++) {
        uint8_t b = byte_at(data, size, &pos);
        double x, y, z;
        if ((in->flags & 32) && i % 3 == 2) { /* an exact duplicate */
            memcpy(in->xyz + 3 * i, in->xyz + 3 * (i - 1), 3 * sizeof(double));
            continue;
        }
        if (in->flags & 4) {
            double h = (b & 1) ? 0.5 : 0.0;
            x = ((b >> 1) & 3) + h;
            y = ((b >> 3) & 3) + h;
            z = ((b >> 5) & 3) + h;
        } else {
            x = b & 7;
            y = (b >> 3) & 7;
            z = b >> 6;
        }
        in->xyz[3 * i] = coord(in, x, (int)(i & 1));
        in->xyz[3 * i + 1] = coord(in, y, 0);
        in->xyz[3 * i + 2] = coord(in, z, 0);
    }
    for (i = 0; i < in->np; i++)
        in->w[i] = (double)(byte_at(data, size, &pos) % 16) / 16.0;
}

static void fetch(cvm_mesh *m, output *o, int weighted)
{
    size_t nt;
    cvm_index **dst = weighted ? &o->tetw : &o->tet;
    FUZZ_REQUIRE(cvm_mesh_count(&o->nv, m, CVM_ENT_VERTEX) == CVM_OK, "count");
    FUZZ_REQUIRE(cvm_mesh_count(&nt, m, CVM_ENT_TETRAHEDRON) == CVM_OK, "count");
    if (!weighted) {
        free(o->xyz);
        o->xyz = (double *)malloc(3 * o->nv * sizeof(double) + 1);
        FUZZ_REQUIRE(o->xyz != NULL, "out of memory");
        FUZZ_REQUIRE(cvm_mesh_copy_points_nd(o->xyz, 3 * o->nv, 3, m) == CVM_OK, "copy_points");
        o->nt = nt;
    } else {
        o->ntw = nt;
    }
    free(*dst);
    *dst = (cvm_index *)malloc(4 * nt * sizeof(cvm_index) + 1);
    FUZZ_REQUIRE(*dst != NULL, "out of memory");
    FUZZ_REQUIRE(cvm_mesh_copy_cells(*dst, 4 * nt, m, CVM_ENT_TETRAHEDRON) == CVM_OK,
                 "copy_cells");
}

/* The measures and the dual compute on any mesh the kernel accepted. */
static void measure(cvm_mesh *m, size_t nv)
{
    static const cvm_measure which[] = {
        CVM_MEASURE_VOLUME, CVM_MEASURE_CIRCUMCENTRE_OUTSIDE_PCT,
        CVM_MEASURE_CIRCUMCENTRE_OUTSIDE_BOUNDARY_PCT, CVM_MEASURE_MIN_DUAL_EDGE_RATIO_3D,
        CVM_MEASURE_TIME_STEP_PROXY_3D, CVM_MEASURE_VALENCE14_PCT, CVM_MEASURE_MEAN_RADIUS_EDGE};
    double v, hist[32], *vol = (double *)malloc(nv * sizeof(double) + 1);
    size_t i, ne, nf;
    for (i = 0; i < sizeof which / sizeof which[0]; i++) {
        FUZZ_REQUIRE(cvm_mesh_get_measure(&v, m, which[i]) == CVM_OK, "measure %d: %s",
                     (int)which[i], cvm_mesh_errmsg(m));
        FUZZ_REQUIRE(!isnan(v), "measure %d is NaN", (int)which[i]);
    }
    FUZZ_REQUIRE(cvm_mesh_copy_histogram(hist, 32, m, CVM_HIST_VALENCE_3D) == CVM_OK, "valence");
    FUZZ_REQUIRE(cvm_mesh_count_dual3(&ne, &nf, m) == CVM_OK, "count_dual3");
    FUZZ_REQUIRE(vol && cvm_mesh_copy_dual3_volumes(vol, nv, m) == CVM_OK, "dual volumes");
    free(vol);
}

static void run(const input *in, output *o, int validate_it)
{
    cvm_mesh *m = NULL;
    cvm_status s;
    size_t nt = 1;
    memset(o, 0, sizeof *o);
    FUZZ_REQUIRE(cvm_mesh_create(&m) == CVM_OK, "create");
    s = cvm_mesh_set_points(m, in->xyz, in->np, 3);
    if (s == CVM_OK)
        s = cvm_mesh_set_option(m, CVM_OPT_REJECT_DUPLICATES, (in->flags & 16) ? 1 : 0);
    FUZZ_REQUIRE(s == CVM_OK, "setting input: %s", cvm_mesh_errmsg(m));
    o->status = cvm_mesh_triangulate(m);
    if (o->status != CVM_OK) {
        FUZZ_REQUIRE(cvm_status_is_error(o->status), "triangulate returned %d", (int)o->status);
        FUZZ_REQUIRE(o->status != CVM_E_INTERNAL && o->status != CVM_E_NOMEM, "triangulate: %s",
                     cvm_mesh_errmsg(m));
        FUZZ_REQUIRE(cvm_mesh_errmsg(m)[0] != '\0', "status %d without a message", (int)o->status);
        FUZZ_REQUIRE(cvm_mesh_count(&nt, m, CVM_ENT_TETRAHEDRON) == CVM_OK && nt == 0,
                     "failed tetrahedralisation left %zu tetrahedra", nt);
        cvm_mesh_free(m);
        return;
    }
    if (validate_it) {
        FUZZ_REQUIRE(cvm_mesh_check(m) == CVM_OK, "check: %s", cvm_mesh_errmsg(m));
        measure(m, in->np);
    }
    fetch(m, o, 0);
    FUZZ_REQUIRE(o->nv <= in->np && o->nt > 0, "%zu vertices of %zu points, %zu tetrahedra", o->nv,
                 in->np, o->nt);
    if (in->flags & 8) {
        o->wstatus = cvm_mesh_set_weights(m, in->w, o->nv);
        FUZZ_REQUIRE(o->wstatus == CVM_OK, "set_weights: %s", cvm_mesh_errmsg(m));
        if (validate_it) {
            FUZZ_REQUIRE(cvm_mesh_check(m) == CVM_OK, "weighted check: %s", cvm_mesh_errmsg(m));
            measure(m, o->nv);
        }
        fetch(m, o, 1);
    }
    cvm_mesh_free(m);
}

static void output_free(output *o)
{
    free(o->xyz);
    free(o->tet);
    free(o->tetw);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    input in;
    output a, b;
    decode(&in, data, size);
    run(&in, &a, 1);
    run(&in, &b, 0);
    FUZZ_REQUIRE(a.status == b.status && a.wstatus == b.wstatus,
                 "second run gave status %d/%d, first %d/%d", (int)b.status, (int)b.wstatus,
                 (int)a.status, (int)a.wstatus);
    if (a.status == CVM_OK) {
        FUZZ_REQUIRE(a.nv == b.nv && a.nt == b.nt && a.ntw == b.ntw,
                     "second run: %zu/%zu/%zu vertices/tetrahedra vs %zu/%zu/%zu", b.nv, b.nt,
                     b.ntw, a.nv, a.nt, a.ntw);
        FUZZ_REQUIRE(memcmp(a.xyz, b.xyz, 3 * a.nv * sizeof(double)) == 0, "points differ");
        FUZZ_REQUIRE(memcmp(a.tet, b.tet, 4 * a.nt * sizeof(cvm_index)) == 0, "tetrahedra differ");
        FUZZ_REQUIRE(!a.tetw || memcmp(a.tetw, b.tetw, 4 * a.ntw * sizeof(cvm_index)) == 0,
                     "weighted tetrahedra differ");
    }
    output_free(&a);
    output_free(&b);
    return 0;
}
