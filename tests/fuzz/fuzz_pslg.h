/*
 * fuzz_pslg.h - the input of the refinement and dual fuzz targets: bytes -> a
 * small planar straight-line graph that usually meshes (a closed outer polygon,
 * up to two polygonal holes with their seeds, a few free inner segments), plus
 * the byte reader the targets decode their options with.
 *
 * The outer polygon and the holes are star-shaped around their centres: vertex k
 * of n lies at angle 2 pi (k + 1/2 + jitter) / n, jitter (b >> 4) / 16 - 1/2, so the
 * vertices are in strict angular order and the polygon is simple before rounding. Every
 * coordinate is rounded to 1/8 on a 16 x 16 box (x stretched by 1, 1.5 or 2),
 * so collinear and cocircular vertices are common; rounding may still make an
 * edge cross another, and inner segments may cross anything (the kernel splits
 * crossings). Then x -> scale * x + offset with the scale 1, 1e-3 or 1e3, or an
 * offset of 1e3 (rounded, near-degenerate input).
 *
 * Layout, after the bytes a target reads first (missing bytes read as 0):
 *   byte 0  bits 0-3: outer vertices 3 + b (at most 16); bits 4-5: x stretch
 *           1, 1.5, 2, 1; bits 6-7: holes b % 3
 *   byte 1  bits 0-1: scale 1, 1e-3, 1e3, 1 with offset 1e3; bits 2-4: inner
 *           segments (at most 6)
 *   per outer vertex one byte: radius 2 + 0.4 (b & 15), jitter (b >> 4)
 *   per hole: byte n = 3 + (b & 7), elongation 1 + ((b >> 3) & 3); byte centre
 *           offset ((b & 15) - 8) / 2, ((b >> 4) - 8) / 2; per vertex one byte:
 *           radius 0.5 + 0.1 (b & 15), jitter (b >> 4)
 *   per inner segment two bytes, each an end (b & 15, b >> 4) + 1/2
 */
#ifndef CVM_FUZZ_PSLG_H
#define CVM_FUZZ_PSLG_H

#include <stddef.h>
#include <stdint.h>

#include "cvmesh.h"

#define FUZZ_PSLG_MAXP 64
#define FUZZ_PSLG_MAXS 64

typedef struct fuzz_bytes {
    const uint8_t *data;
    size_t size, pos;
} fuzz_bytes;

/* The next byte, 0 past the end. */
uint8_t fuzz_byte(fuzz_bytes *b);

typedef struct fuzz_pslg {
    double xy[2 * FUZZ_PSLG_MAXP];
    size_t np;
    cvm_index seg[2 * FUZZ_PSLG_MAXS];
    size_t nseg;
    size_t ninner; /* the last ninner segments are the free inner ones */
    double hole[2 * 2];
    size_t nhole;
    double scale;  /* x -> scale * x + offset */
    double offset;
    double stretch; /* x stretch of the 16 x 16 box */
} fuzz_pslg;

/* Decode a PSLG from the bytes at b's position (layout above). Segments whose
 * ends have equal coordinates are left out. */
void fuzz_pslg_decode(fuzz_pslg *g, fuzz_bytes *b);

/* Give g to m: points, segments, holes. Returns the first failing status. */
cvm_status fuzz_pslg_set(cvm_mesh *m, const fuzz_pslg *g);

#endif
