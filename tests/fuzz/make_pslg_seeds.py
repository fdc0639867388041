#!/usr/bin/env python3
"""Write the seed corpora of fuzz_refine and fuzz_optimise (tests/fuzz/corpus/
refine, optimise): the five shared domains reduced to the PSLG encoding of
fuzz_pslg.h (square, channel, annulus, cylinder, NACA 0012 as a thin hole in a
disc), plus small-angle, crossing, two-hole and scaled variants. Run from the
repository root; the files are committed, this script documents them."""
import os

J0 = 8 << 4  # no angular jitter


def loop(radii, jit=None):
    jit = jit or [8] * len(radii)
    return [(r & 15) | (j << 4) for r, j in zip(radii, jit)]


def pslg(outer, stretch=0, holes=(), scale=0, inner=()):
    """outer: per-vertex bytes; holes: (n_vertex_bytes, elong, cb);
    inner: pairs of end bytes."""
    b0 = (len(outer) - 3) | (stretch << 4) | (len(holes) << 6)
    b1 = scale | (len(inner) << 2)
    out = [b0, b1] + outer
    for verts, elong, cb in holes:
        out += [(len(verts) - 3) | (elong << 3), cb] + verts
    for e0, e1 in inner:
        out += [e0, e1]
    return out


SQUARE = pslg(loop([15] * 4))
CHANNEL = pslg(loop([15] * 4), stretch=2)
ANNULUS = pslg(loop([15] * 16), holes=[(loop([15] * 10), 0, 0x88)])
CYLINDER = pslg(loop([15] * 4), stretch=2, holes=[(loop([5] * 10), 0, 0x84)])
# a thin, blunt-nosed hole: radii larger towards one end
NACA = pslg(loop([15] * 16), holes=[(loop([2, 3, 5, 7, 8, 10, 10, 8, 3, 1]), 3, 0x88)])
TRIANGLE = pslg(loop([15, 15, 15]))
SPIKE = pslg(loop([15, 0, 15, 15, 0], [8, 15, 0, 8, 8]))  # sharp corners
CROSSING = pslg(loop([15] * 6), inner=[(0x22, 0xdd), (0x2d, 0xd2), (0x28, 0xd9)])
FAN = pslg(loop([15] * 8), inner=[(0x77, 0xf0), (0x77, 0xf3), (0x77, 0xe0)])  # small angles at a point
TWO_HOLES = pslg(loop([15] * 12), stretch=2, holes=[(loop([6] * 6), 0, 0x84), (loop([6] * 8), 1, 0x8c)])

SHAPES = {
    "square": SQUARE, "channel": CHANNEL, "annulus": ANNULUS, "cylinder": CYLINDER,
    "naca": NACA, "triangle": TRIANGLE, "spike": SPIKE, "crossing": CROSSING, "fan": FAN,
    "two_holes": TWO_HOLES,
}


def scaled(shape, scale):
    return [shape[0], (shape[1] & ~3) | scale] + shape[2:]


def write(target, name, data):
    path = os.path.join("tests/fuzz/corpus", target, name)
    with open(path, "wb") as f:
        f.write(bytes(data))


# fuzz_refine: o0 algo|lens<<2|march<<3|keepseg<<4|hull<<5|size<<6|area<<7,
# angle, size, area, smoothing, swap|layers<<1|budget<<3, seed
DEL, FRONT, AFLR = 0, 2, 3
refine = {
    "square_delaunay_33": ([DEL | 64, 255, 8, 0, 0, 0, 1], SQUARE),
    "channel_frontal_30": ([FRONT | 64 | 8, 196, 6, 0, 0xff & (4 | 2 << 3 | 3 << 5), 1, 2], CHANNEL),
    "annulus_aflr_28": ([AFLR | 64, 157, 4, 0, 0, 1 | 1 << 1, 3], ANNULUS),
    "cylinder_frontal_keepseg": ([FRONT | 64 | 16, 157, 6, 0, 0, 1, 4], CYLINDER),
    "naca_delaunay_lens": ([DEL | 4 | 128, 196, 0, 8, 0, 0, 5], NACA),
    "naca_aflr_area": ([AFLR | 128 | 64, 157, 10, 16, 5 | 1 << 3, 1, 6], NACA),
    "triangle_angle_only": ([DEL, 255, 0, 0, 0, 0, 7], TRIANGLE),
    "spike_small_angles": ([DEL | 64, 196, 4, 0, 0, 0, 8], SPIKE),
    "crossing_frontal": ([FRONT | 64, 157, 6, 0, 3 | 3 << 3, 1, 9], CROSSING),
    "fan_aflr_small_angles": ([AFLR | 64, 255, 6, 0, 0, 1 | 2 << 1, 10], FAN),
    "two_holes_delaunay_budget20": ([DEL | 64, 196, 2, 0, 0, 4 << 3, 11], TWO_HOLES),
    "annulus_frontal_budget100": ([FRONT | 64, 157, 2, 0, 0, 5 << 3, 12], ANNULUS),
    "square_hull_frontal": ([FRONT | 64 | 32, 157, 8, 0, 0, 1, 13], SQUARE),
    "channel_tiny_scale": ([DEL | 64 | 8, 196, 6, 0, 0, 0, 14], scaled(CHANNEL, 1)),
    "annulus_huge_scale_aflr": ([AFLR | 64, 157, 6, 0, 0, 1, 15], scaled(ANNULUS, 2)),
    "cylinder_offset_delaunay": ([DEL | 64 | 4, 196, 6, 0, 0, 0, 16], scaled(CYLINDER, 3)),
}
for name, (opts, shape) in refine.items():
    write("refine", name, opts + shape)

# fuzz_optimise: o0 algo|cuckoo<<2|keepin<<3|topo<<4|prepass<<6|weights<<7,
# angle, size|mergetol<<4|margin<<6, sweeps|rounds<<4|trials<<6,
# dualmin|target<<4, pattern|cuckoo<<5, seed, layer|sizing<<7
optimise = {
    "square_pattern": ([DEL | 1 << 4, 196, 8 | 1 << 4, 8 | 3 << 4, 10 | 10 << 4, 15 | 1 << 5, 1, 2], SQUARE),
    "channel_cuckoo": ([FRONT | 4 | 1 << 4, 196, 10 | 1 << 4, 4 | 1 << 4, 10 | 10 << 4, 15, 2, 2 | 128], CHANNEL),
    "annulus_pattern_weights": ([DEL | 1 << 4 | 128, 157, 8 | 1 << 4, 8 | 2 << 4, 10 | 10 << 4, 20, 3, 2], ANNULUS),
    "cylinder_keep_input": ([FRONT | 8, 196, 10 | 2 << 4 | 1 << 6, 6 | 1 << 4, 8 | 8 << 4, 10, 4, 0], CYLINDER),
    "naca_topology2": ([AFLR | 2 << 4, 157, 6 | 1 << 4, 6 | 3 << 4 | 1 << 6, 10 | 10 << 4, 10, 5, 2], NACA),
    "naca_cuckoo_prepass": ([DEL | 4 | 1 << 4 | 64, 157, 12 | 1 << 4, 3 | 1 << 4, 10 | 10 << 4, 0, 6, 2], NACA),
    "spike_no_merge": ([DEL | 1 << 4, 196, 8, 8 | 2 << 4, 10 | 10 << 4, 10, 7, 2], SPIKE),
    "fan_topology0": ([FRONT, 196, 8 | 1 << 4 | 3 << 6, 8 | 1 << 4, 10 | 10 << 4, 10, 8, 4], FAN),
    "crossing_trials": ([FRONT | 1 << 4, 157, 8 | 1 << 4, 6 | 2 << 4 | 2 << 6, 10 | 10 << 4, 10, 9, 2], CROSSING),
    "two_holes_margin0": ([DEL | 1 << 4, 196, 6 | 1 << 4 | 1 << 6, 6 | 1 << 4, 10 | 10 << 4, 10, 10, 2], TWO_HOLES),
    "triangle_zero_sweeps": ([DEL | 1 << 4 | 128, 255, 4 | 1 << 4, 0 | 1 << 4, 0, 10, 11, 2], TRIANGLE),
    "square_tiny_scale_weights": ([FRONT | 1 << 4 | 128, 196, 8 | 1 << 4, 8 | 1 << 4, 10 | 10 << 4, 10, 12, 2],
                                  scaled(SQUARE, 1)),
    "annulus_offset": ([AFLR | 1 << 4, 157, 8 | 1 << 4, 6 | 1 << 4, 10 | 10 << 4, 10, 13, 2 | 128],
                       scaled(ANNULUS, 3)),
    "cylinder_huge_scale_cuckoo": ([DEL | 4 | 2 << 4, 157, 10 | 1 << 4, 3 | 1 << 4, 10 | 10 << 4, 5, 14, 2],
                                   scaled(CYLINDER, 2)),
}
for name, (opts, shape) in optimise.items():
    write("optimise", name, opts + shape)
