"""Mesh a 3 x 1 channel with cvmesh and report its quality.

Usage: python channel.py [OUT.vtu] [--plot PNG]
Builds the channel as a planar straight-line graph (boundary points every h),
triangulates it, refines it (frontal-Delaunay, finer near the inlet), checks
the result with exact predicates, prints quality measures and writes the mesh.
"""

import argparse
import sys

import numpy as np

import cvmesh


def channel(length=3.0, height=1.0, h=0.1):
    """Boundary points (counter-clockwise) and the segments closing them."""
    nx, ny = round(length / h), round(height / h)
    bottom = [(i * length / nx, 0.0) for i in range(nx)]
    right = [(length, j * height / ny) for j in range(ny)]
    top = [(i * length / nx, height) for i in range(nx, 0, -1)]
    left = [(0.0, j * height / ny) for j in range(ny, 0, -1)]
    points = np.array(bottom + right + top + left)
    n = len(points)
    segments = np.column_stack([np.arange(n), (np.arange(n) + 1) % n])
    return points, segments


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out", nargs="?", default="channel.vtu")
    ap.add_argument("--plot", metavar="PNG")
    args = ap.parse_args(argv)

    points, segments = channel()
    mesh = cvmesh.Mesh.from_pslg(points, segments, markers=np.ones(len(points), np.int32))
    mesh.triangulate()
    sizing = cvmesh.Sizing(uniform=0.1)
    sizing.add_line_source(0.0, 0.0, 0.0, 1.0, h=0.03, growth=0.3)   # the inlet
    status = mesh.refine(algorithm="frontal", sizing=sizing, min_angle=28)
    mesh.check()

    q = mesh.quality()
    print("cvmesh %s: %s, %d vertices, %d triangles"
          % (cvmesh.version(), status.name, len(mesh.points), len(mesh.triangles)))
    print("angles %.1f..%.1f deg, %.1f%% obtuse, area %.6f"
          % (q.min_angle_deg, q.max_angle_deg, q.obtuse_pct, q.area))
    mesh.write(args.out)
    print("wrote", args.out)
    if args.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(9, 3.5))
        mesh.plot(ax, color_by="quality")
        fig.savefig(args.plot, dpi=120)
        print("wrote", args.plot)
    return 0


if __name__ == "__main__":
    sys.exit(main())
