#!/usr/bin/env python3
"""Write tests/data/matching_networkx.txt: the optimum of networkx.max_weight_matching
(maximum weight, and maximum cardinality then weight) on 200 random graphs. The graphs
are not stored: random_graph(k) below and random_graph() in test_matching.c build the
same graph k from the same splitmix64 stream, so the file holds only the answers.

Usage: python3 tests/unit/quad/gen_matching_oracle.py > tests/data/matching_networkx.txt
"""
import sys

import networkx as nx

MASK = (1 << 64) - 1
NGRAPH = 200
WMAX = (1, 10, 1000, 1000000)


class SplitMix64:
    def __init__(self, seed):
        self.s = seed & MASK

    def next(self):
        self.s = (self.s + 0x9E3779B97F4A7C15) & MASK
        z = self.s
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK
        return z ^ (z >> 31)


def random_graph(k):
    r = SplitMix64(k * 1000003 + 7)
    n = 2 + r.next() % 39
    pct = 2 + r.next() % 50
    wmax = WMAX[r.next() % 4]
    edges = []
    for i in range(n):
        for j in range(i + 1, n):
            if r.next() % 100 < pct:
                edges.append((i, j, r.next() % (wmax + 1)))
    return n, edges


def optimum(n, edges, maxcard):
    g = nx.Graph()
    g.add_nodes_from(range(n))
    for i, j, w in edges:
        g.add_edge(i, j, weight=w)
    mate = nx.max_weight_matching(g, maxcardinality=maxcard)
    return len(mate), sum(g[i][j]["weight"] for i, j in mate)


def main():
    out = sys.stdout
    out.write("# matching_networkx.txt - written by tests/unit/quad/gen_matching_oracle.py with "
              "networkx %s\n" % nx.__version__)
    out.write("# graph n m weight_maxweight card_maxcard weight_maxcard\n")
    for k in range(NGRAPH):
        n, edges = random_graph(k)
        _, w0 = optimum(n, edges, False)
        c1, w1 = optimum(n, edges, True)
        out.write("%d %d %d %d %d %d\n" % (k, n, len(edges), w0, c1, w1))


if __name__ == "__main__":
    main()
