/*
 * fuzz_ele_read.c - libFuzzer target: any bytes, parsed as a TetGen .ele on the
 * 27 points of a 3 x 3 x 3 grid numbered from 1 (as TetGen numbers them),
 * through an in-memory cvm__reader with injected short reads, read errors and
 * allocation failures (fuzz_input.h), then built into a mesh as
 * cvm_mesh_set_tetrahedra() builds it. Required: a status with a message and
 * never a crash or a leak; tetrahedra read name existing points and carry
 * finite attributes; a mesh built has every tetrahedron positively oriented
 * (exact), every point used and its faces' corners in range.
 */
#include <stdint.h>
#include <string.h>

#include "api/mesh3_internal.h"
#include "fuzz_input.h"
#include "fuzz_require.h"
#include "geom/geom_internal.h"
#include "io/surf3_io.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define FUZZ_NAME "fuzz_ele_read"

#define ELE_NP 27

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    cvm__ctx ctx;
    cvm__reader r;
    fuzz_input src;
    cvmtest_alloc a;
    cvm__tetele te;
    cvm__mesh3 b;
    double xyz[3 * ELE_NP];
    uint8_t used[ELE_NP];
    cvm_status st;
    size_t i;
    for (i = 0; i < ELE_NP; i++)
        xyz[3 * i] = (double)(i % 3), xyz[3 * i + 1] = (double)(i / 3 % 3),
        xyz[3 * i + 2] = (double)(i / 9);
    fuzz_input_setup(data, size, &src, &r, &ctx, &a);
    st = cvm__read_tetele(&ctx, &r, "fuzz.ele", 1, ELE_NP, &te);
    if (st != CVM_OK) {
        FUZZ_REQUIRE(cvm_status_is_error(st) && ctx.errmsg[0] != '\0', "status %d without a message",
                     (int)st);
        FUZZ_REQUIRE(st != CVM_E_NOMEM || a.n_failed > 0, "NOMEM with no failed allocation");
        FUZZ_REQUIRE(te.tet == NULL && te.attr == NULL && te.nt == 0, "not left empty on error");
        return 0;
    }
    FUZZ_REQUIRE(!src.failed, "read error at byte %zu was ignored", src.fail_at);
    for (i = 0; i < 4 * te.nt; i++)
        FUZZ_REQUIRE(te.tet[i] >= 0 && te.tet[i] < ELE_NP, "corner %zu names point %ld", i,
                     (long)te.tet[i]);
    for (i = 0; te.attr && i < te.nt; i++)
        FUZZ_REQUIRE(te.attr[i] - te.attr[i] == 0, "attribute %zu is not finite", i);
    st = cvm__mesh3_tets_build(&ctx, xyz, ELE_NP, te.tet, te.attr, te.nt, te.first, 1, &b);
    if (st == CVM_OK) {
        memset(used, 0, sizeof used);
        FUZZ_REQUIRE(b.have && b.nv == ELE_NP && b.ntet == te.nt, "mesh sizes");
        for (i = 0; i < b.ntet; i++) {
            const int32_t *v = b.tet + 4 * i;
            FUZZ_REQUIRE(cvm__orient3d(xyz + 3 * v[0], xyz + 3 * v[1], xyz + 3 * v[2],
                                       xyz + 3 * v[3]) > 0,
                         "tetrahedron %zu is not positively oriented", i);
            used[v[0]] = used[v[1]] = used[v[2]] = used[v[3]] = 1;
        }
        for (i = 0; i < ELE_NP; i++)
            FUZZ_REQUIRE(used[i], "point %zu unused", i);
        for (i = 0; i < 3 * b.nface; i++)
            FUZZ_REQUIRE(b.face[i] >= 0 && b.face[i] < ELE_NP, "face corner %zu out of range", i);
        cvm__mesh3_tets_free(&ctx, &b);
    } else {
        FUZZ_REQUIRE(cvm_status_is_error(st) && ctx.errmsg[0] != '\0', "build: status %d without a "
                     "message", (int)st);
        FUZZ_REQUIRE(st != CVM_E_NOMEM || a.n_failed > 0, "build: NOMEM with no failed allocation");
        FUZZ_REQUIRE(b.tet == NULL && b.face == NULL, "build: not left empty on error");
    }
    cvm__tetele_free(&ctx, &te);
    return 0;
}
