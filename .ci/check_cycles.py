#!/usr/bin/env python3
"""check_cycles.py OBJDIR - no dependency circle between the library's files.

A file depends on another when its object file uses a symbol the other
defines (nm: undefined vs defined global symbols of OBJDIR/*/*.o). A
strongly connected component of more than one file is a circle: neither
file can be read, tested or moved without the other. Run from the
repository root (objects of sources that no longer exist are skipped).
Exits 1 and names each circle with the symbols that close it.
"""
import collections
import glob
import os
import subprocess
import sys


def symbols(obj):
    out = subprocess.run(["nm", obj], capture_output=True, text=True, check=True).stdout
    defined, used = set(), set()
    for line in out.splitlines():
        parts = line.split()
        if len(parts) == 3 and parts[1] in "TDBRC":
            defined.add(parts[2])
        elif len(parts) == 2 and parts[0] == "U":
            used.add(parts[1])
    return defined, used


def components(nodes, edges):
    """Tarjan's strongly connected components, iteratively."""
    index, low, on, stack, out, counter = {}, {}, set(), [], [], [0]
    for root in nodes:
        if root in index:
            continue
        work = [(root, iter(sorted(edges[root])))]
        index[root] = low[root] = counter[0]
        counter[0] += 1
        stack.append(root)
        on.add(root)
        while work:
            v, it = work[-1]
            w = next(it, None)
            if w is not None:
                if w not in index:
                    index[w] = low[w] = counter[0]
                    counter[0] += 1
                    stack.append(w)
                    on.add(w)
                    work.append((w, iter(sorted(edges[w]))))
                elif w in on:
                    low[v] = min(low[v], index[w])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[v])
            if low[v] == index[v]:
                comp = []
                while True:
                    w = stack.pop()
                    on.discard(w)
                    comp.append(w)
                    if w == v:
                        break
                out.append(sorted(comp))
    return out


def main():
    objdir = sys.argv[1]
    # only objects of sources that still exist (a build directory keeps the
    # objects of files moved or deleted since)
    objs = sorted(o for o in glob.glob(os.path.join(objdir, "*", "*.o"))
                  if os.path.exists(os.path.join("lib", os.path.relpath(o, objdir)[:-2] + ".c")))
    if not objs:
        print("check-cycles: no object files under %s (build first)" % objdir)
        return 1
    owner, uses = {}, {}
    for o in objs:
        d, u = symbols(o)
        for s in d:
            owner[s] = o
        uses[o] = u
    edges = collections.defaultdict(set)
    why = collections.defaultdict(list)
    for o in objs:
        for s in sorted(uses[o]):
            t = owner.get(s)
            if t and t != o:
                edges[o].add(t)
                why[(o, t)].append(s)
    name = lambda o: os.path.relpath(o, objdir)[:-2] + ".c"
    bad = [c for c in components(objs, edges) if len(c) > 1]
    for comp in bad:
        print("check-cycles: these files depend on each other in a circle:")
        for a in comp:
            for b in sorted(edges[a]):
                if b in comp:
                    print("    lib/%s -> lib/%s (%s)" % (name(a), name(b), ", ".join(why[(a, b)][:3])))
    if bad:
        return 1
    print("check-cycles: no dependency circle among %d library files" % len(objs))
    return 0


if __name__ == "__main__":
    sys.exit(main())
