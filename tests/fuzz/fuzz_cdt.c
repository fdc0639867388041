/*
 * fuzz_cdt.c - libFuzzer target: bytes -> a small PSLG on a 16 x 16 grid (so
 * collinear, cocircular and duplicate points are common) -> triangulate ->
 * no kernel fault; if CVM_OK, cvm_mesh_check() and the independent oracle
 * must accept the mesh, and a second run on a fresh handle must give identical
 * output bytes.
 * Then the remaining points are inserted and both checks run again.
 *
 * Layout (missing bytes read as 0):
 *   byte 0  flags: 1 map x to 1e6 + x/1000 (rounded: near-degenerate),
 *                  2 nudge odd points by one ulp, 4 add a hole seed,
 *                  8 CVM_OPT_SPLIT_INTERSECTIONS = 0, 16 CVM_OPT_KEEP_CONVEX_HULL = 1,
 *                  32 CVM_OPT_REJECT_DUPLICATES = 1, 64 min_dist > 0 on insertion
 *   byte 1  number of points, 3 + b % 62
 *   byte 2  number of segments, b % 48
 *   byte 3  number of points to insert afterwards, b % 16
 *   then one byte per point (x = b & 15, y = b >> 4), two per segment (point ids
 *   mod n; equal ends are skipped), one per inserted point (grid + 1/2), one hole byte.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cvmesh.h"
#include "support/mesh_oracle.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define FUZZ_NAME "fuzz_cdt"
#include "fuzz_require.h"

typedef struct input {
    int flags;
    double xy[2 * 64];
    size_t np;
    cvm_index seg[2 * 48];
    size_t nseg;
    double ins[2 * 16];
    size_t nins;
    double hole[2];
} input;

typedef struct output {
    cvm_status status;
    cvm_status ins_status;
    size_t nv, nt;
    double *xy;
    cvm_index *tri;
    cvm_index ids[16];
} output;

static uint8_t byte_at(const uint8_t *data, size_t size, size_t *pos)
{
    uint8_t b = *pos < size ? data[*pos] : 0;
    (*pos)++;
    return b;
}

static double coord(const input *in, int v, int odd)
{
    double x = (double)v;
    if (in->flags & 1)
        x = 1e6 + x * 0.001;
    if ((in->flags & 2) && odd)
        x = nextafter(x, 1e300);
    return x;
}

static void decode(input *in, const uint8_t *data, size_t size)
{
    size_t pos = 0, i, nseg;
    memset(in, 0, sizeof *in);
    in->flags = byte_at(data, size, &pos);
    in->np = 3 + byte_at(data, size, &pos) % 62;
    nseg = byte_at(data, size, &pos) % 48;
    in->nins = byte_at(data, size, &pos) % 16;
    for (i = 0; i < in->np; i++) {
        uint8_t b = byte_at(data, size, &pos);
        in->xy[2 * i] = coord(in, b & 15, (int)(i & 1));
        in->xy[2 * i + 1] = coord(in, b >> 4, 0);
    }
    for (i = 0; i < nseg; i++) {
        cvm_index a = (cvm_index)(byte_at(data, size, &pos) % in->np);
        cvm_index b = (cvm_index)(byte_at(data, size, &pos) % in->np);
        if (a == b || (in->xy[2 * a] == in->xy[2 * b] && in->xy[2 * a + 1] == in->xy[2 * b + 1]))
            continue;
        in->seg[2 * in->nseg] = a;
        in->seg[2 * in->nseg + 1] = b;
        in->nseg++;
    }
    for (i = 0; i < in->nins; i++) {
        uint8_t b = byte_at(data, size, &pos);
        in->ins[2 * i] = coord(in, b & 15, 0) + ((in->flags & 1) ? 0.0005 : 0.5);
        in->ins[2 * i + 1] = coord(in, b >> 4, 0) + ((in->flags & 1) ? 0.0005 : 0.5);
    }
    {
        uint8_t b = byte_at(data, size, &pos);
        in->hole[0] = coord(in, b & 15, 0) + ((in->flags & 1) ? 0.00025 : 0.25);
        in->hole[1] = coord(in, b >> 4, 0) + ((in->flags & 1) ? 0.00025 : 0.25);
    }
}

static void validate(cvm_mesh *m, const input *in, const char *when)
{
    char msg[512];
    cvmtest_expect e;
    cvm_status c = cvm_mesh_check(m);
    FUZZ_REQUIRE(c == CVM_OK, "%s: cvm_mesh_check: %s", when, cvm_mesh_errmsg(m));
    cvmtest_expect_init(&e);
    /* Segments are walked only where no triangle around them can have been carved away. */
    if ((in->flags & 16) && !(in->flags & 4)) {
        e.segs = in->seg;
        e.nseg = in->nseg;
    }
    FUZZ_REQUIRE(cvmtest_mesh_validate(msg, sizeof msg, m, &e), "%s: oracle: %s", when, msg);
}

static void fetch(cvm_mesh *m, output *o)
{
    FUZZ_REQUIRE(cvm_mesh_count(&o->nv, m, CVM_ENT_VERTEX) == CVM_OK, "count");
    FUZZ_REQUIRE(cvm_mesh_count(&o->nt, m, CVM_ENT_TRIANGLE) == CVM_OK, "count");
    free(o->xy);
    free(o->tri);
    o->xy = (double *)malloc(2 * o->nv * sizeof(double) + 1);
    o->tri = (cvm_index *)malloc(3 * o->nt * sizeof(cvm_index) + 1);
    FUZZ_REQUIRE(o->xy && o->tri, "out of memory");
    FUZZ_REQUIRE(cvm_mesh_copy_points(o->xy, 2 * o->nv, m) == CVM_OK, "copy_points");
    FUZZ_REQUIRE(cvm_mesh_copy_cells(o->tri, 3 * o->nt, m, CVM_ENT_TRIANGLE) == CVM_OK,
                 "copy_cells");
}

/* No inserted point lies closer than min_dist (rounded squared distance) to a
 * vertex of a triangle that was there before it, whatever lies between them. */
static void check_min_dist(const output *o, double min_dist)
{
    unsigned char *used = (unsigned char *)calloc(o->nv + 1, 1);
    size_t i, j, k;
    FUZZ_REQUIRE(used != NULL, "out of memory");
    for (i = 0; i < 3 * o->nt; i++)
        used[o->tri[i]] = 1;
    for (k = 0; k < 16; k++) {
        cvm_index id = o->ids[k];
        if (id == CVM_REJECTED || id <= 0)
            continue;
        for (j = 0; j < (size_t)id; j++) {
            const double *a = o->xy + 2 * j, *b = o->xy + 2 * (size_t)id;
            double d = (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]);
            if (used[j])
                FUZZ_REQUIRE(d >= min_dist * min_dist, "inserted vertex %ld is %g from vertex %zu",
                             (long)id, sqrt(d), j);
        }
    }
    free(used);
}

static void run(const input *in, output *o, int validate_it)
{
    cvm_mesh *m = NULL;
    cvm_status s;
    memset(o, 0, sizeof *o);
    FUZZ_REQUIRE(cvm_mesh_create(&m) == CVM_OK, "create");
    s = cvm_mesh_set_points(m, in->xy, in->np, 2);
    if (s == CVM_OK)
        s = cvm_mesh_set_segments(m, in->seg, in->nseg);
    if (s == CVM_OK && (in->flags & 4))
        s = cvm_mesh_set_holes(m, in->hole, 1);
    if (s == CVM_OK)
        s = cvm_mesh_set_option(m, CVM_OPT_SPLIT_INTERSECTIONS, (in->flags & 8) ? 0 : 1);
    if (s == CVM_OK)
        s = cvm_mesh_set_option(m, CVM_OPT_KEEP_CONVEX_HULL, (in->flags & 16) ? 1 : 0);
    if (s == CVM_OK)
        s = cvm_mesh_set_option(m, CVM_OPT_REJECT_DUPLICATES, (in->flags & 32) ? 1 : 0);
    FUZZ_REQUIRE(s == CVM_OK, "setting input: %s", cvm_mesh_errmsg(m));
    o->status = cvm_mesh_triangulate(m);
    if (o->status != CVM_OK) {
        size_t nt = 1;
        FUZZ_REQUIRE(cvm_status_is_error(o->status), "triangulate returned %d", (int)o->status);
        /* A failed post-condition or any other kernel fault is a finding. The
         * one refusal allowed is documented at cvm_mesh_triangulate(): a
         * crossing that no double near it can split (it names the vertex). */
        FUZZ_REQUIRE(o->status != CVM_E_INTERNAL ||
                         strstr(cvm_mesh_errmsg(m), "cross, rounded too far off them") != NULL,
                     "triangulate: %s", cvm_mesh_errmsg(m));
        FUZZ_REQUIRE(cvm_mesh_errmsg(m)[0] != '\0', "status %d without a message", (int)o->status);
        FUZZ_REQUIRE(cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE) == CVM_OK && nt == 0,
                     "failed triangulation left %zu triangles", nt);
        cvm_mesh_free(m);
        return;
    }
    if (validate_it)
        validate(m, in, "triangulate");
    fetch(m, o);
    if (in->nins) {
        double min_dist = (in->flags & 64) ? ((in->flags & 1) ? 0.0003 : 0.3) : 0.0;
        size_t i;
        o->ins_status = cvm_mesh_insert_points(o->ids, m, in->ins, in->nins, min_dist);
        FUZZ_REQUIRE(o->ins_status == CVM_OK, "insert_points: %s", cvm_mesh_errmsg(m));
        if (validate_it)
            validate(m, in, "insert_points");
        fetch(m, o);
        for (i = 0; i < in->nins; i++)
            FUZZ_REQUIRE(o->ids[i] == CVM_REJECTED || (o->ids[i] >= 0 && (size_t)o->ids[i] < o->nv),
                         "inserted point %zu got id %ld of %zu vertices", i, (long)o->ids[i], o->nv);
        if (validate_it && min_dist > 0)
            check_min_dist(o, min_dist);
    }
    cvm_mesh_free(m);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    input in;
    output a, b;
    decode(&in, data, size);
    run(&in, &a, 1);
    run(&in, &b, 0);
    FUZZ_REQUIRE(a.status == b.status, "second run gave status %d, first %d", (int)b.status,
                 (int)a.status);
    if (a.status == CVM_OK) {
        FUZZ_REQUIRE(a.nv == b.nv && a.nt == b.nt, "second run: %zu/%zu vertices/triangles vs %zu/%zu",
                     b.nv, b.nt, a.nv, a.nt);
        FUZZ_REQUIRE(memcmp(a.xy, b.xy, 2 * a.nv * sizeof(double)) == 0, "points differ");
        FUZZ_REQUIRE(memcmp(a.tri, b.tri, 3 * a.nt * sizeof(cvm_index)) == 0, "triangles differ");
        FUZZ_REQUIRE(memcmp(a.ids, b.ids, sizeof a.ids) == 0, "inserted ids differ");
    }
    free(a.xy);
    free(a.tri);
    free(b.xy);
    free(b.tri);
    return 0;
}
