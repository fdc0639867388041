/*
 * fuzz_surf3_common.h - the body shared by the 3D surface reader fuzz
 * targets (fuzz_off_read.c, fuzz_stl_read.c, fuzz_tetpoly_read.c): any bytes,
 * through the fault-injecting input of fuzz_input.h, give a status and never a
 * crash, a leak or undefined behaviour. A surface read successfully must be
 * consistent (finite coordinates, indices in range, offsets increasing) and,
 * when small, is validated: a status with a message, or triangles whose
 * corners are points of the surface.
 */
#ifndef CVM_FUZZ_SURF3_COMMON_H
#define CVM_FUZZ_SURF3_COMMON_H

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "fuzz_input.h"
#include "fuzz_require.h"
#include "io/surf3_io.h"
#include "surface3/surface3_internal.h"

static void fuzz_check_surf3(const cvm__surf3 *s)
{
    size_t i;
    for (i = 0; i < 3 * s->np; i++)
        FUZZ_REQUIRE(isfinite(s->xyz[i]), "coordinate %zu is not finite", i);
    for (i = 0; i < s->npoly; i++) {
        int32_t k;
        FUZZ_REQUIRE(s->poff[i] <= s->poff[i + 1], "polygon %zu has a negative size", i);
        FUZZ_REQUIRE(s->pfacet[i] >= 0 && (size_t)s->pfacet[i] < s->nfacet, "polygon %zu: facet %ld", i,
                     (long)s->pfacet[i]);
        for (k = s->poff[i]; k < s->poff[i + 1]; k++)
            FUZZ_REQUIRE(s->pidx[k] >= 0 && (size_t)s->pidx[k] < s->np, "polygon %zu names point %ld of %zu",
                         i, (long)s->pidx[k], s->np);
    }
    for (i = 0; i < 3 * s->nholes; i++)
        FUZZ_REQUIRE(isfinite(s->holes[i]), "hole coordinate %zu is not finite", i);
    for (i = 0; i < 5 * s->nregions; i++)
        FUZZ_REQUIRE(isfinite(s->regions[i]), "region value %zu is not finite", i);
}

static void fuzz_validate_surf3(cvm__ctx *ctx, const cvm__surf3 *s)
{
    cvm__surf3_tris t;
    cvm_status st;
    size_t i;
    if (s->npoly > 2000)
        return;
    st = cvm__surf3_validate(ctx, s, s->nregions > 1 ? CVM__SURF3_ALLOW_INTERNAL : 0, &t);
    if (st != CVM_OK) {
        FUZZ_REQUIRE(cvm_status_is_error(st) && ctx->errmsg[0] != '\0', "status %d without a message", (int)st);
        return;
    }
    for (i = 0; i < 3 * t.nt; i++)
        FUZZ_REQUIRE(t.tri[i] >= 0 && (size_t)t.tri[i] < s->np, "triangle corner %zu out of range", i);
    cvm__surf3_tris_free(ctx, &t);
}

/* Read data with read_fn, check, validate, free. */
#define FUZZ_SURF3_BODY(read_call)                                                                   \
    cvm__ctx ctx;                                                                                    \
    cvm__surf3 s;                                                                                    \
    cvm__reader r;                                                                                   \
    fuzz_input src;                                                                                  \
    cvmtest_alloc a;                                                                                 \
    cvm_status st;                                                                                   \
    fuzz_input_setup(data, size, &src, &r, &ctx, &a);                                                \
    st = (read_call);                                                                                \
    if (st == CVM_OK) {                                                                              \
        FUZZ_REQUIRE(!src.failed, "read error at byte %zu was ignored", src.fail_at);               \
        fuzz_check_surf3(&s);                                                                        \
        fuzz_validate_surf3(&ctx, &s);                                                               \
    } else {                                                                                         \
        FUZZ_REQUIRE(cvm_status_is_error(st), "status %d", (int)st);                                 \
        FUZZ_REQUIRE(ctx.errmsg[0] != '\0', "status %d (%s) without a message", (int)st,             \
                     cvm_status_str(st));                                                            \
        FUZZ_REQUIRE(st != CVM_E_NOMEM || a.n_failed > 0, "NOMEM with no failed allocation");       \
        FUZZ_REQUIRE(s.np == 0 && s.xyz == NULL && s.npoly == 0, "surface not left empty on error"); \
    }                                                                                                \
    cvm__surf3_free(&ctx, &s);                                                                       \
    FUZZ_REQUIRE(a.live_blocks == 0, "%ld blocks leaked (status %d)", a.live_blocks, (int)st);

#endif
