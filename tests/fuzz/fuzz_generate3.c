/*
 * fuzz_generate3.c - libFuzzer target: bytes -> a perturbed hexahedron (the
 * unit cube's eight corners moved by up to 0.3, each face split into two
 * triangles along a fuzzed diagonal, written as a temporary .off) and the
 * options of cvm_mesh_generate3(). Required:
 *   - the run returns CVM_OK, or an error status with a message (without
 *     TetGen a surface triangle that stays no Delaunay face is allowed:
 *     CVM_E_UNSUPPORTED; a surface that folds over itself is refused by the
 *     reader's validation);
 *   - on CVM_OK: cvm_mesh_check() accepts the mesh, the 12 surface triangles
 *     are its boundary faces (12 or more with bit 7), its volume equals the surface's signed volume
 *     (to 1e-9), every generated vertex lies strictly inside the bounding box
 *     (with bit 7, every vertex past the corners lies in the closed box: the
 *     re-meshed faces' points are on it),
 *     and a second run on a fresh handle gives identical points and cells.
 *
 * Bytes (missing ones read as 0):
 *   0..23  corner offsets (b - 128) / 128 * 0.3, corner k, axis a at 3 k + a
 *   24     bits 0-5: the diagonal of each face; bit 6 uniform size; bit 7
 *          CVM_OPT_GEN3_SURFACE = CVM_GEN3_SURFACE_REMESH_PLANAR (coplanar
 *          face pairs re-meshed: then 12 or more boundary faces)
 *   25     size 0.15 + 0.6 b / 255
 *   26     grading 0.05 + 2 b / 255
 *   27     bit 0, with bit 7 of byte 24: CVM_GEN3_SURFACE_REMESH_ALL instead (the
 *          whole surface re-meshed: 4 or more boundary faces, the volume kept to
 *          10 %: a face folded by less than 35 degrees is one smooth patch, and
 *          the coarse re-meshed triangles' chords cut across its crease);
 *          bit 1: the octree free space (CVM_GEN3_FREESPACE_OCTREE), bit 2 with
 *          it: CVM_OPT_GEN3_OCTREE_SPLIT_HANGING
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cvmesh.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define FUZZ_NAME "fuzz_generate3"
#include "fuzz_require.h"

static uint8_t byte_at(const uint8_t *data, size_t size, size_t i)
{
    return i < size ? data[i] : 0;
}

/* The cube's faces as corner quadruples, counter-clockwise seen from outside
 * (corner k = (k & 1, (k >> 1) & 1, (k >> 2) & 1)). */
static const int k_quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                  {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};

static cvm_mesh *run(const char *path, int uniform, int remesh, int octree, double h, double g)
{
    cvm_mesh *m;
    cvm_status s;
    FUZZ_REQUIRE(cvm_mesh_create(&m) == CVM_OK, "create");
    s = cvm_mesh_read(m, path);
    if (s != CVM_OK) {
        /* a folded or degenerate hexahedron is refused by the surface's validation */
        FUZZ_REQUIRE(cvm_status_is_error(s) && cvm_mesh_errmsg(m)[0], "read status %d", (int)s);
        cvm_mesh_free(m);
        return NULL;
    }
    FUZZ_REQUIRE(cvm_mesh_set_option(m, CVM_OPT_GEN3_SIZE_FROM_SURFACE, uniform ? 0 : 1) == CVM_OK,
                 "option");
    FUZZ_REQUIRE(cvm_mesh_set_option(m, CVM_OPT_GEN3_GRADING, g) == CVM_OK, "option");
    FUZZ_REQUIRE(cvm_mesh_set_option(m, CVM_OPT_GEN3_SURFACE, remesh) == CVM_OK, "option");
    if (octree) {
        FUZZ_REQUIRE(cvm_mesh_set_option(m, CVM_OPT_GEN3_FREESPACE, CVM_GEN3_FREESPACE_OCTREE) ==
                         CVM_OK, "option");
        FUZZ_REQUIRE(cvm_mesh_set_option(m, CVM_OPT_GEN3_OCTREE_SPLIT_HANGING, octree == 2) ==
                         CVM_OK, "option");
    }
    s = cvm_mesh_generate3(m, h);
    if (s != CVM_OK) {
        FUZZ_REQUIRE(cvm_status_is_error(s) && cvm_mesh_errmsg(m)[0], "status %d without a message",
                     (int)s);
        FUZZ_REQUIRE(s != CVM_E_INTERNAL && s != CVM_E_NOMEM, "status %d: %s", (int)s,
                     cvm_mesh_errmsg(m));
        FUZZ_REQUIRE(s != CVM_E_UNSUPPORTED || !strstr(cvm_build_string(), "TetGen 1.5"),
                     "unsupported with TetGen: %s", cvm_mesh_errmsg(m));
        cvm_mesh_free(m);
        return NULL;
    }
    return m;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    double c[8][3], lo[3], hi[3], vol = 0, v, h, g;
    char dir[] = "/tmp/fuzz_generate3_XXXXXX", path[64];
    int k, a, uniform, remesh, octree;
    uint8_t diag = byte_at(data, size, 24);
    FILE *f;
    cvm_mesh *m1, *m2;
    for (k = 0; k < 8; k++)
        for (a = 0; a < 3; a++)
            c[k][a] = (double)((k >> a) & 1) +
                      ((double)byte_at(data, size, (size_t)(3 * k + a)) - 128) / 128 * 0.3;
    uniform = (diag >> 6) & 1;
    remesh = (diag >> 7) & 1;
    if (remesh && (byte_at(data, size, 27) & 1))
        remesh = 2;
    octree = (byte_at(data, size, 27) >> 1) & 1 ? 1 + ((byte_at(data, size, 27) >> 2) & 1) : 0;
    h = 0.15 + 0.6 * byte_at(data, size, 25) / 255.0;
    g = 0.05 + 2.0 * byte_at(data, size, 26) / 255.0;
    FUZZ_REQUIRE(mkdtemp(dir) != NULL, "mkdtemp");
    snprintf(path, sizeof path, "%s/s.off", dir);
    f = fopen(path, "w");
    FUZZ_REQUIRE(f != NULL, "fopen");
    fprintf(f, "OFF\n8 12 0\n");
    for (k = 0; k < 8; k++)
        fprintf(f, "%.17g %.17g %.17g\n", c[k][0], c[k][1], c[k][2]);
    for (k = 0; k < 6; k++) {
        const int *q = k_quads[k];
        int s0 = (diag >> k) & 1, t[2][3];
        t[0][0] = q[s0];
        t[0][1] = q[s0 + 1];
        t[0][2] = q[(s0 + 2) % 4];
        t[1][0] = q[s0];
        t[1][1] = q[(s0 + 2) % 4];
        t[1][2] = q[(s0 + 3) % 4];
        for (a = 0; a < 2; a++) {
            const double *p = c[t[a][0]], *r = c[t[a][1]], *s = c[t[a][2]];
            fprintf(f, "3 %d %d %d\n", t[a][0], t[a][1], t[a][2]);
            /* signed volume of the surface: the divergence theorem over its triangles */
            vol += (p[0] * (r[1] * s[2] - r[2] * s[1]) - p[1] * (r[0] * s[2] - r[2] * s[0]) +
                    p[2] * (r[0] * s[1] - r[1] * s[0])) / 6;
        }
    }
    fclose(f);
    m1 = run(path, uniform, remesh, octree, h, g);
    m2 = m1 ? run(path, uniform, remesh, octree, h, g) : NULL;
    unlink(path);
    rmdir(dir);
    if (!m1)
        return 0;
    FUZZ_REQUIRE(m2 != NULL, "the second run failed where the first succeeded");
    FUZZ_REQUIRE(cvm_mesh_check(m1) == CVM_OK, "check: %s", cvm_mesh_errmsg(m1));
    FUZZ_REQUIRE(cvm_mesh_get_measure(&v, m1, CVM_MEASURE_VOLUME) == CVM_OK, "volume");
    FUZZ_REQUIRE(fabs(v - vol) <= (remesh == 2 ? 0.1 : 1e-9) * fabs(vol),
                 "volume %.17g, surface %.17g", v, vol);
    {
        size_t nv1, nv2, nt1, nt2, nf, i;
        double *x1, *x2;
        cvm_index *t1, *t2;
        FUZZ_REQUIRE(cvm_mesh_count(&nv1, m1, CVM_ENT_VERTEX) == CVM_OK, "count");
        FUZZ_REQUIRE(cvm_mesh_count(&nv2, m2, CVM_ENT_VERTEX) == CVM_OK, "count");
        FUZZ_REQUIRE(cvm_mesh_count(&nt1, m1, CVM_ENT_TETRAHEDRON) == CVM_OK, "count");
        FUZZ_REQUIRE(cvm_mesh_count(&nt2, m2, CVM_ENT_TETRAHEDRON) == CVM_OK, "count");
        FUZZ_REQUIRE(cvm_mesh_count(&nf, m1, CVM_ENT_TRIANGLE) == CVM_OK &&
                         (remesh == 2 ? nf >= 4 : remesh ? nf >= 12 : nf == 12),
                     "%zu boundary faces", nf);
        FUZZ_REQUIRE(nv1 == nv2 && nt1 == nt2, "second run: %zu/%zu vertices, %zu/%zu tets", nv1,
                     nv2, nt1, nt2);
        x1 = malloc(3 * nv1 * sizeof *x1 + 1);
        x2 = malloc(3 * nv1 * sizeof *x2 + 1);
        t1 = malloc(4 * nt1 * sizeof *t1 + 1);
        t2 = malloc(4 * nt1 * sizeof *t2 + 1);
        FUZZ_REQUIRE(x1 && x2 && t1 && t2, "malloc");
        FUZZ_REQUIRE(cvm_mesh_copy_points_nd(x1, 3 * nv1, 3, m1) == CVM_OK, "points");
        FUZZ_REQUIRE(cvm_mesh_copy_points_nd(x2, 3 * nv1, 3, m2) == CVM_OK, "points");
        FUZZ_REQUIRE(cvm_mesh_copy_cells(t1, 4 * nt1, m1, CVM_ENT_TETRAHEDRON) == CVM_OK, "cells");
        FUZZ_REQUIRE(cvm_mesh_copy_cells(t2, 4 * nt1, m2, CVM_ENT_TETRAHEDRON) == CVM_OK, "cells");
        FUZZ_REQUIRE(memcmp(x1, x2, 3 * nv1 * sizeof *x1) == 0, "second run: other points");
        FUZZ_REQUIRE(memcmp(t1, t2, 4 * nt1 * sizeof *t1) == 0, "second run: other cells");
        for (a = 0; a < 3; a++) {
            lo[a] = hi[a] = c[0][a];
            for (k = 1; k < 8; k++) {
                lo[a] = c[k][a] < lo[a] ? c[k][a] : lo[a];
                hi[a] = c[k][a] > hi[a] ? c[k][a] : hi[a];
            }
        }
        for (i = 8; i < nv1; i++)
            for (a = 0; a < 3; a++)
                FUZZ_REQUIRE(remesh ? x1[3 * i + a] >= lo[a] && x1[3 * i + a] <= hi[a]
                                    : x1[3 * i + a] > lo[a] && x1[3 * i + a] < hi[a],
                             "vertex %zu outside the bounding box", i);
        free(x1);
        free(x2);
        free(t1);
        free(t2);
    }
    cvm_mesh_free(m1);
    cvm_mesh_free(m2);
    return 0;
}
