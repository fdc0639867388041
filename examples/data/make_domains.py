#!/usr/bin/env python3
"""Write the example and test domains of cvmesh as Triangle .poly files.

    python3 examples/data/make_domains.py [OUTDIR]     (default: this folder)

Every coordinate is printed with 17 significant digits, so the files read back
to the exact doubles computed here and the output is the same on every
machine. Only the standard library is used.
"""

import math
import os
import sys


def num(v):
    """17 significant digits; -0 is written as 0."""
    return "%.17g" % (v + 0.0)


def ring(n, r, cx=0.0, cy=0.0):
    """n points on a circle of radius r, counter-clockwise from angle 0."""
    return [(cx + r * math.cos(2 * math.pi * k / n), r * math.sin(2 * math.pi * k / n) + cy)
            for k in range(n)]


def loop(first, n, marker):
    """Segments closing the points first..first+n-1 (0-based) into a loop."""
    return [(first + k, first + (k + 1) % n, marker) for k in range(n)]


def naca4_half_thickness(x, t=0.12):
    """Half thickness of a symmetric NACA 4-digit section of thickness t at chord
    position x (chord 1), with the closed-trailing-edge coefficient -0.1036."""
    return 5 * t * (0.2969 * math.sqrt(x) - 0.1260 * x - 0.3516 * x ** 2
                    + 0.2843 * x ** 3 - 0.1036 * x ** 4)


def square():
    pts = [(0, 0), (1, 0), (1, 1), (0, 1)]
    return ("unit square; thesis test case (Poisson), target edge e.g. 0.02",
            pts, loop(0, 4, 1), [])


def channel():
    pts = [(0, 0), (3, 0), (3, 1), (0, 1)]
    segs = [(0, 1, 1), (1, 2, 3), (2, 3, 1), (3, 0, 2)]
    return ("channel L=3 H=1; markers 1 walls, 2 inlet, 3 outlet", pts, segs, [])


def annulus():
    pts = ring(64, 1.0) + ring(128, 4.0)
    return ("annulus r=1..4; marker 1 inner, 2 outer; graded sizing 0.4 + (r-1)/2.5 as in the thesis",
            pts, loop(0, 64, 1) + loop(64, 128, 2), [(0, 0)])


def cylinder():
    pts = [(-10, -10), (10, -10), (10, 10), (-10, 10)] + ring(96, 0.5)
    return ("circular cylinder r=0.5 in a 20x20 box; marker 1 wall, 2 far field",
            pts, loop(0, 4, 2) + loop(4, 96, 1), [(0, 0)])


def naca0012():
    # Cosine spacing from the trailing edge over the upper surface to the
    # leading edge, then back along the lower surface; 200 points in all.
    n = 100
    upper = []
    for k in range(n, 0, -1):
        x = 0.5 * (1 - math.cos(math.pi * k / n))
        upper.append((x, naca4_half_thickness(x)))
    upper[0] = (1.0, 0.0)          # the closed trailing edge, exactly
    lower = []
    for k in range(n):
        x = 0.5 * (1 - math.cos(math.pi * k / n))
        lower.append((x, -naca4_half_thickness(x)))
    far = ring(64, 15.0, cx=0.5)
    pts = upper + lower + far
    return ("NACA 0012 (closed trailing edge, chord 1) in a circular far field r=15; "
            "marker 1 wall, 2 far field",
            pts, loop(0, 2 * n, 1) + loop(2 * n, 64, 2), [(0.5, 0)])


DOMAINS = {"square": square, "channel": channel, "annulus": annulus,
           "cylinder": cylinder, "naca0012": naca0012}


def poly_text(comment, pts, segs, holes):
    """Triangle .poly, 1-based, one boundary marker per point and segment."""
    out = ["# %s" % comment, "%d 2 0 1" % len(pts)]
    out += ["%d %s %s 1" % (i + 1, num(x), num(y)) for i, (x, y) in enumerate(pts)]
    out.append("%d 1" % len(segs))
    out += ["%d %d %d %d" % (i + 1, a + 1, b + 1, m) for i, (a, b, m) in enumerate(segs)]
    out.append("%d" % len(holes))
    out += ["%d %s %s" % (i + 1, num(x), num(y)) for i, (x, y) in enumerate(holes)]
    return "\n".join(out) + "\n"


def main(argv):
    outdir = argv[1] if len(argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    os.makedirs(outdir, exist_ok=True)
    for name, make in DOMAINS.items():
        path = os.path.join(outdir, name + ".poly")
        tmp = path + ".tmp"
        with open(tmp, "w") as f:
            f.write(poly_text(*make()))
        os.replace(tmp, path)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
