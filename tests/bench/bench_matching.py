"""bench_matching.py - the matching of the Blossom-Quad recombination (lib/quad/matching.c) beside
networkx.max_weight_matching on the same graphs: the dual graphs of Delaunay triangulations of
uniform random points (2e4 and 2e5 triangles), edges weighted by the quality of the quad the two
triangles form (identity metric; pairs with quality below QMIN dropped, 0 = every convex pair).

cvmesh rows come from the C driver bench_matching.c (internal API; medians of 5 runs, CPU and wall
seconds: the machine may be shared, CPU time is the steadier figure). networkx (pure Python, about
cubic) runs once on the 2e3-triangle graphs, where it must reach the same weight; set
CVM_BENCH_NX_FULL=1 to run it on the 2e4-triangle graph with QMIN 0.5 as well (about 5 minutes).

usage: bench_matching.py BUILD DOMAINS   (make bench calls it through run.sh; DOMAINS unused)
"""
import os
import subprocess
import sys
import tempfile
import time

BUILD = sys.argv[1] if len(sys.argv) > 1 else "build"


def build_driver():
    path = os.path.join(BUILD, "bench", "bench_matching")
    os.makedirs(os.path.dirname(path), exist_ok=True)
    cc = os.environ.get("CC", "cc")
    subprocess.check_call([cc, "-std=c99", "-O2", "-Iinclude", "-Ilib", "-o", path,
                           "tests/bench/bench_matching.c",
                           os.path.join(BUILD, "lib", "libcvmesh.a")]
                          + os.environ.get("BENCH_LIBS", "-llbfgs -lz -lm -fopenmp").split())
    return path


def run_driver(driver, npts, qmin, graph=None):
    args = [driver, str(npts), str(qmin)] + ([graph] if graph else [])
    out = subprocess.run(args, capture_output=True, text=True, check=True).stdout
    return dict(kv.split("=") for kv in out.split())


def networkx_weight(graph):
    try:
        import networkx as nx
    except ImportError:
        return None, None
    with open(graph) as f:
        n, m = map(int, f.readline().split())
        g = nx.Graph()
        g.add_nodes_from(range(n))
        for _ in range(m):
            a, b, w = map(int, f.readline().split())
            g.add_edge(a, b, weight=w)
    t0 = time.process_time()
    mate = nx.max_weight_matching(g)
    t = time.process_time() - t0
    return t, sum(g[a][b]["weight"] for a, b in mate)


def main():
    driver = build_driver()
    print("# bench_matching: maximum-weight matching on triangulation dual graphs "
          "(cvmesh: median of 5, seconds; nx: networkx %s, 1 run, CPU seconds)"
          % _nx_version())
    print("%-10s %5s %8s %8s %10s %10s %10s %10s %8s %10s %8s" % (
        "triangles", "qmin", "edges", "t_cpu", "t_wall", "t_maxcard", "t_greedy", "w/greedy",
        "quads%", "t_nx", "t_ratio"))
    with tempfile.TemporaryDirectory() as tmp:
        full = os.environ.get("CVM_BENCH_NX_FULL") == "1"
        for npts in (1000, 10000, 100000):
            for qmin in (0.5, 0.0):
                nx_here = npts <= 1000 or (full and npts <= 10000 and qmin == 0.5)
                graph = os.path.join(tmp, "g.txt") if nx_here else None
                r = run_driver(driver, npts, qmin, graph)
                t_nx, w_nx = networkx_weight(graph) if graph else (None, None)
                if w_nx is not None and w_nx != int(r["w_maxweight"]):
                    raise SystemExit("bench_matching: networkx weight %d != cvmesh %s"
                                     % (w_nx, r["w_maxweight"]))
                t_cpu = float(r["t_maxweight_cpu"])
                print("%-10s %5.2f %8s %8.4f %10.4f %10s %10s %10.4f %8s %10s %8s" % (
                    r["triangles"], qmin, r["edges"], t_cpu, float(r["t_maxweight_wall"]),
                    r["t_maxcard_cpu"], r["t_greedy_cpu"],
                    int(r["w_maxweight"]) / max(1, int(r["w_greedy"])), r["quads_pct"],
                    "%.3f" % t_nx if t_nx is not None else "-",
                    "%.4f" % (t_cpu / t_nx) if t_nx else "-"))
                sys.stdout.flush()


def _nx_version():
    try:
        import networkx
        return networkx.__version__
    except ImportError:
        return "missing"


if __name__ == "__main__":
    main()
