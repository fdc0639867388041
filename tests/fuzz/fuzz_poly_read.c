/*
 * fuzz_poly_read.c - libFuzzer target: any bytes, parsed as a Triangle .poly
 * file (or .node with FUZZ_IS_POLY 0) through an in-memory cvm__reader, give a
 * status and never a crash, a leak or undefined behaviour.
 *
 * The input size also selects fault injection (tests/fuzz/fuzz_input.h):
 *   size % 3 == 0  the reader returns short reads (1 + size % 13 bytes);
 *   size % 7 == 0  the reader fails with -1 after size / 2 bytes (must not give CVM_OK);
 *   size % 5 == 0  allocation 1 + sum(bytes) % 16 fails (CVM_E_NOMEM or CVM_OK).
 * A successfully read PSLG must be consistent (counts, finite coordinates,
 * segment indices in range when it has points) and, when small, is
 * triangulated: CVM_OK must then pass cvm_mesh_check().
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_input.h"

#ifndef FUZZ_IS_POLY
#define FUZZ_IS_POLY 1
#endif

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define FUZZ_NAME "fuzz_poly_read"
#include "fuzz_require.h"

static void check_pslg(const cvm__pslg *p)
{
    size_t i;
    FUZZ_REQUIRE(p->np == 0 || p->xy != NULL, "np %zu without coordinates", p->np);
    for (i = 0; i < 2 * p->np; i++)
        FUZZ_REQUIRE(isfinite(p->xy[i]), "coordinate %zu is not finite", i);
    FUZZ_REQUIRE(p->nseg == 0 || p->seg != NULL, "nseg %zu without segments", p->nseg);
    /* A .poly with 0 points takes them from the .node beside it (cvm__read_file),
     * so its segment indices can be checked only once points are present. */
    for (i = 0; p->np > 0 && i < 2 * p->nseg; i++)
        FUZZ_REQUIRE(p->seg[i] >= 0 && (size_t)p->seg[i] < p->np,
                     "segment %zu names point %ld of %zu", i / 2, (long)p->seg[i], p->np);
    for (i = 0; i < 2 * p->nholes; i++)
        FUZZ_REQUIRE(isfinite(p->holes[i]), "hole coordinate %zu is not finite", i);
    FUZZ_REQUIRE(p->nattr == 0 || p->np == 0 || p->pattr != NULL, "attributes missing");
}

/* Triangulate a small PSLG through the public API; CVM_OK must pass the check. */
static void triangulate(const cvm__pslg *p)
{
    cvm_mesh *m = NULL;
    cvm_status s;
    if (p->np == 0 || p->np > 300 || p->nseg > 300)
        return;
    if (cvm_mesh_create(&m) != CVM_OK)
        abort();
    s = cvm_mesh_set_points(m, p->xy, p->np, 2);
    if (s == CVM_OK)
        s = cvm_mesh_set_segments(m, p->seg, p->nseg);
    if (s == CVM_OK)
        s = cvm_mesh_set_holes(m, p->holes, p->nholes);
    if (s == CVM_OK)
        s = cvm_mesh_triangulate(m);
    if (s == CVM_OK) {
        cvm_status c = cvm_mesh_check(m);
        FUZZ_REQUIRE(c == CVM_OK, "cvm_mesh_check: %s", cvm_mesh_errmsg(m));
    } else {
        FUZZ_REQUIRE(cvm_mesh_errmsg(m)[0] != '\0', "status %d without a message", (int)s);
    }
    cvm_mesh_free(m);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    cvm__ctx ctx;
    cvm__pslg p;
    cvm__reader r;
    fuzz_input src;
    cvmtest_alloc a;
    cvm_status s;
    fuzz_input_setup(data, size, &src, &r, &ctx, &a);

    memset(&p, 0, sizeof p);
    s = cvm__read_triangle_format(&ctx, &r, FUZZ_IS_POLY ? "fuzz.poly" : "fuzz.node",
                                  FUZZ_IS_POLY, &p);
    if (s == CVM_OK) {
        FUZZ_REQUIRE(!src.failed, "read error at byte %zu was ignored", src.fail_at);
        check_pslg(&p);
        if (a.n_failed == 0)
            triangulate(&p);
    } else {
        FUZZ_REQUIRE(cvm_status_is_error(s), "status %d", (int)s);
        FUZZ_REQUIRE(ctx.errmsg[0] != '\0', "status %d (%s) without a message", (int)s,
                     cvm_status_str(s));
        FUZZ_REQUIRE(s != CVM_E_NOMEM || a.n_failed > 0, "NOMEM with no failed allocation");
        FUZZ_REQUIRE(p.np == 0 && p.xy == NULL && p.nseg == 0 && p.seg == NULL,
                     "PSLG not left empty on error");
    }
    cvm__pslg_free(&ctx, &p);
    FUZZ_REQUIRE(a.live_blocks == 0, "%ld blocks leaked (status %d)", a.live_blocks, (int)s);
    return 0;
}
