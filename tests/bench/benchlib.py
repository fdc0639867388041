"""benchlib.py - what the benchmark scripts share: building a C driver against
the library under test, and an own .poly reader (so no benchmark trusts the
library's reader for the peers' input)."""
import os
import subprocess

import numpy as np


def build_driver(build, name):
    """Compile tests/bench/NAME.c against BUILD/lib/libcvmesh.a into
    BUILD/bench/NAME ($CC, default cc); returns the program's path."""
    path = os.path.join(build, "bench", name)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    cc = os.environ.get("CC", "cc")
    subprocess.check_call([cc, "-std=c99", "-O2", "-Iinclude", "-o", path,
                           "tests/bench/%s.c" % name, os.path.join(build, "lib", "libcvmesh.a"),
                           ] + os.environ.get("BENCH_LIBS", "-llbfgs -lz -lm -fopenmp").split())
    return path


def read_poly(path):
    """Points (n, 2), segments (m, 2, 0-based) and holes (k, 2) of a Triangle
    .poly file; a missing holes section means none."""
    rows = []
    for line in open(path):
        line = line.split("#", 1)[0].split()
        if line:
            rows.append(line)
    n, i = int(rows[0][0]), 1
    pts = np.array([[float(r[1]), float(r[2])] for r in rows[i:i + n]])
    base = int(rows[1][0]) if n else 0
    i += n
    ns = int(rows[i][0])
    i += 1
    segs = np.array([[int(r[1]) - base, int(r[2]) - base] for r in rows[i:i + ns]])
    i += ns
    nh = int(rows[i][0]) if i < len(rows) else 0
    i += 1
    holes = np.array([[float(r[1]), float(r[2])] for r in rows[i:i + nh]]).reshape(-1, 2)
    return pts, segs, holes
