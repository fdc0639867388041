#!/usr/bin/env python3
"""Write a .poly: the square [0, n] x [0, n] with an n x n grid of square holes.

Usage: hole_grid.py N [OUT.poly]   (N*N holes; stdout without OUT)

Hole (i, j) is the square [i + 0.25, i + 0.75] x [j + 0.25, j + 0.75] with its
hole point at its centre. Every coordinate is a multiple of 1/4, so the file
is exact in any precision. A benchmark input for carving many holes and for
reading the written mesh back.
"""
import sys


def write(n, f):
    npts = 4 + 4 * n * n
    f.write("%d 2 0 1\n" % npts)
    for k, (x, y) in enumerate([(0, 0), (n, 0), (n, n), (0, n)]):
        f.write("%d %g %g 1\n" % (k, x, y))
    k = 4
    for j in range(n):
        for i in range(n):
            for dx, dy in ((0.25, 0.25), (0.75, 0.25), (0.75, 0.75), (0.25, 0.75)):
                f.write("%d %.2f %.2f 2\n" % (k, i + dx, j + dy))
                k += 1
    f.write("%d 1\n" % (4 + 4 * n * n))
    s = 0
    for a in range(4):
        f.write("%d %d %d 1\n" % (s, a, (a + 1) % 4))
        s += 1
    for h in range(n * n):
        b = 4 + 4 * h
        for a in range(4):
            f.write("%d %d %d 2\n" % (s, b + a, b + (a + 1) % 4))
            s += 1
    f.write("%d\n" % (n * n))
    h = 0
    for j in range(n):
        for i in range(n):
            f.write("%d %.1f %.1f\n" % (h, i + 0.5, j + 0.5))
            h += 1


def main():
    if len(sys.argv) not in (2, 3) or not sys.argv[1].isdigit() or int(sys.argv[1]) < 1:
        sys.stderr.write("usage: hole_grid.py N [OUT.poly]\n")
        return 2
    n = int(sys.argv[1])
    if len(sys.argv) == 3:
        with open(sys.argv[2], "w") as f:
            write(n, f)
    else:
        write(n, sys.stdout)
    return 0


if __name__ == "__main__":
    sys.exit(main())
