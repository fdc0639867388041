#!/usr/bin/env python3
"""Crop a `cvmesh ... --svg` picture of ../shared/data/naca0012.poly to the
airfoil: crop_svg.py IN.svg OUT.svg [x0 x1 y0 y1] (world coordinates, default
-0.45 1.55 -0.6 0.6). The picture maps world (x, y) to
(10 + (x - minx) s, 10 + (maxy - y) s) with s = 780 / span of the mesh's
bounding box; for the NACA 0012 far field (r = 15 around (0.5, 0)) minx = -14.5,
maxy = 15, span = 30. Line widths are scaled down with the zoom.

Regenerate the README pictures (needs rsvg-convert, Debian librsvg2-bin):
  for a in delaunay frontal aflr; do
    cvmesh refine ../shared/data/naca0012.poly --algo $a --auto 4 --grading 3 --svg /tmp/$a.svg
    python3 examples/pictures/crop_svg.py /tmp/$a.svg /tmp/c.svg
    rsvg-convert /tmp/c.svg -o examples/pictures/naca0012_$a.png
  done
"""
import re
import sys


def main():
    src, dst = sys.argv[1], sys.argv[2]
    x0, x1, y0, y1 = (float(v) for v in (sys.argv[3:7] if len(sys.argv) >= 7
                                         else (-0.45, 1.55, -0.6, 0.6)))
    s = open(src).read()
    m = re.search(r'viewBox="0 0 ([\d.]+) ([\d.]+)" width="[\d.]+" height="[\d.]+"', s)
    if not m:
        raise SystemExit("crop_svg: %s is not a cvmesh picture" % src)
    width = float(m.group(1))
    minx, maxy, scale = -14.5, 15.0, 780 / 30.0
    vx, vy = 10 + (x0 - minx) * scale, 10 + (maxy - y1) * scale
    vw, vh = (x1 - x0) * scale, (y1 - y0) * scale
    zoom = width / vw
    s = s.replace(m.group(0), 'viewBox="%.3f %.3f %.3f %.3f" width="800" height="%.0f"'
                  % (vx, vy, vw, vh, 800 * vh / vw), 1)
    s = re.sub(r'stroke-width="([\d.]+)"',
               lambda k: 'stroke-width="%.4f"' % (float(k.group(1)) / zoom * 2.5), s)
    open(dst, "w").write(s)


if __name__ == "__main__":
    main()
