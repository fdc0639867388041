#!/bin/sh
# run.sh CLI DOMAINS PYTHON - end-to-end tests of the cvmesh program: every
# example domain (DOMAINS/*.poly) to every output format, help and version, bad
# command lines (exit 2), bad inputs and failed writes (exit 1, one line naming
# file:line, no output file left). The outputs are checked by the project's own
# tests/tools/verify_mesh.py and read back by meshio, both run by PYTHON (the
# venv of make check, with numpy and meshio).
# Prints "N passed, M failed" last; exits 1 if anything failed.
set -e

if [ $# -ne 3 ]; then
    echo "usage: sh tests/cli/run.sh path/to/cvmesh DOMAINS_DIR PYTHON" >&2
    exit 2
fi
CLI=$1
DOMAINS=$2
PY=$3
case $CLI in /*) ;; *) CLI=$(pwd)/$CLI ;; esac
HERE=$(cd "$(dirname "$0")" && pwd)
VERIFY=$HERE/../tools/verify_mesh.py
if ! "$PY" -c 'import numpy, meshio' > /dev/null 2>&1; then
    echo "run.sh: $PY lacks numpy or meshio (make check-cli builds the venv from tests/requirements.txt)" >&2
    exit 2
fi
DATA=$HERE/../data
TMP=$(mktemp -d "${TMPDIR:-/tmp}/cvmesh_cli.XXXXXX")
trap 'rm -rf "$TMP"' EXIT INT TERM

passed=0
failed=0
pass() { passed=$((passed + 1)); }
fail() { failed=$((failed + 1)); echo "FAIL: $*"; }

# expect_exit CODE DESC CMD... : run CMD (stdout/stderr to $TMP/out, $TMP/err), check its exit code.
expect_exit() {
    want=$1; desc=$2; shift 2
    set +e
    "$@" > "$TMP/out" 2> "$TMP/err"
    got=$?
    set -e
    if [ "$got" -eq "$want" ]; then pass; else fail "$desc: exit $got, expected $want: $(head -c 300 "$TMP/err")"; fi
}

# expect_grep DESC FILE PATTERN : FILE contains PATTERN (fixed string).
expect_grep() {
    if grep -F -q -e "$3" "$2"; then pass; else fail "$1: '$3' not in $(basename "$2"): $(head -c 300 "$2")"; fi
}

# expect_one_line DESC : $TMP/err is exactly one line starting "cvmesh: ".
expect_one_line() {
    n=$(wc -l < "$TMP/err")
    if [ "$n" -eq 1 ] && grep -q '^cvmesh: ' "$TMP/err"; then pass; else fail "$1: stderr is not one 'cvmesh: ' line: $(cat "$TMP/err")"; fi
}

# expect_empty_dir DESC DIR : nothing was left in DIR.
expect_empty_dir() {
    if [ -z "$(ls -A "$2")" ]; then pass; else fail "$1: files left: $(ls -A "$2" | tr '\n' ' ')"; fi
}

HAVE_NUMPY=1
HAVE_MESHIO=1

# ---- help and version -------------------------------------------------------
expect_exit 0 "--help" "$CLI" --help
expect_grep "--help" "$TMP/out" "usage: cvmesh"
expect_grep "--help lists triangulate" "$TMP/out" "triangulate"
expect_exit 0 "triangulate --help" "$CLI" triangulate --help
expect_grep "triangulate --help" "$TMP/out" "--quality"
expect_grep "triangulate --help" "$TMP/out" "--seed S"
expect_grep "triangulate --help" "$TMP/out" "--reject-duplicates"
expect_exit 0 "help triangulate" "$CLI" help triangulate
expect_grep "help triangulate" "$TMP/out" "--timings"
expect_exit 0 "--version" "$CLI" --version
expect_grep "--version" "$TMP/out" "cvmesh 0."

# ---- bad command lines: exit 2, no output -----------------------------------
OUT=$TMP/usage
mkdir "$OUT"
expect_exit 2 "no arguments" "$CLI"
expect_exit 2 "unknown command" "$CLI" frobnicate
expect_one_line "unknown command"
expect_exit 2 "no input" "$CLI" triangulate -o "$OUT/x.vtu"
expect_exit 2 "unknown flag" "$CLI" triangulate "$DOMAINS/square.poly" --frobnicate
expect_one_line "unknown flag"
expect_exit 2 "unknown output format" "$CLI" triangulate "$DOMAINS/square.poly" -o "$OUT/x.stl"
expect_exit 2 "--svg without .svg" "$CLI" triangulate "$DOMAINS/square.poly" --svg "$OUT/x.png"
expect_exit 2 "--svg-window with three numbers" "$CLI" triangulate "$DOMAINS/square.poly" --svg "$OUT/x.svg" \
    --svg-window 0,0,1
expect_grep "--svg-window with three numbers" "$TMP/err" "expected four numbers"
expect_exit 2 "--svg-window empty" "$CLI" refine "$DOMAINS/square.poly" --svg "$OUT/x.svg" --svg-window=0,1,1,0
expect_grep "--svg-window empty" "$TMP/err" "YMAX > YMIN"
expect_exit 2 "-o without a name" "$CLI" triangulate "$DOMAINS/square.poly" -o
expect_exit 2 "--seed not a number" "$CLI" triangulate "$DOMAINS/square.poly" --seed abc -o "$OUT/x.vtu"
expect_exit 2 "--seed out of range" "$CLI" triangulate "$DOMAINS/square.poly" --seed -1 -o "$OUT/x.vtu"
expect_grep "--seed out of range quotes the bounds" "$TMP/err" "--seed"
expect_one_line "--seed out of range"
# 2^53 + 1 is not a double: refused, never rounded to 2^53
expect_exit 2 "--seed 2^53+1 refused" "$CLI" triangulate "$DOMAINS/square.poly" --seed 9007199254740993 -o "$OUT/x.vtu"
expect_grep "--seed 2^53+1 refused" "$TMP/err" "--seed 9007199254740993: integers beyond 2^53 = 9007199254740992 cannot be taken exactly"
expect_one_line "--seed 2^53+1 refused"
expect_exit 2 "--seed 1e16 refused" "$CLI" triangulate "$DOMAINS/square.poly" --seed 1e16 -o "$OUT/x.vtu"
expect_exit 0 "--seed 2^53 taken" "$CLI" triangulate "$DOMAINS/square.poly" --seed 9007199254740992 -o "$OUT/x.vtu"
rm -f "$OUT/x.vtu"
expect_exit 2 "--threads too many" "$CLI" triangulate "$DOMAINS/square.poly" --threads=5000 -o "$OUT/x.vtu"
expect_empty_dir "bad command lines" "$OUT"

# ---- every example domain to every format ---------------------------------
for poly in "$DOMAINS"/*.poly; do
    name=$(basename "$poly" .poly)
    OUT=$TMP/$name
    mkdir "$OUT"
    for ext in vtu msh node svg; do
        expect_exit 0 "$name to .$ext" "$CLI" triangulate "$poly" -o "$OUT/$name.$ext"
        if [ -s "$OUT/$name.$ext" ]; then pass; else fail "$name.$ext missing or empty"; fi
    done
    expect_grep "$name.vtu" "$OUT/$name.vtu" '<VTKFile type="UnstructuredGrid"'
    expect_grep "$name.msh" "$OUT/$name.msh" '$MeshFormat'
    expect_grep "$name.svg" "$OUT/$name.svg" '<svg '
    for side in ele edge; do
        if [ -s "$OUT/$name.$side" ]; then pass; else fail "$name.$side missing beside $name.node"; fi
    done
    if ls "$OUT" | grep -q '\.tmp\.'; then fail "$name: temporary files left"; else pass; fi
    if [ "$HAVE_NUMPY" -eq 1 ]; then
        if "$PY" "$VERIFY" "$poly" "$OUT/$name" > "$OUT/verify.json" 2>&1; then
            pass
        else
            fail "$name: verify_mesh.py: $(tail -c 400 "$OUT/verify.json")"
        fi
    fi
    if [ "$HAVE_MESHIO" -eq 1 ]; then
        if "$PY" -c 'import sys, meshio
for f in sys.argv[1:]:
    m = meshio.read(f)
    assert len(m.points) > 0 and any(c.type == "triangle" for c in m.cells), f' \
            "$OUT/$name.vtu" "$OUT/$name.msh" > "$OUT/meshio.log" 2>&1; then
            pass
        else
            fail "$name: meshio cannot read the output: $(tail -c 400 "$OUT/meshio.log")"
        fi
    fi
done

# ---- report, timings, extra picture, determinism ---------------------------
OUT=$TMP/report
mkdir "$OUT"

# A picture framed on the airfoil: the window's aspect, fewer triangles than the whole mesh.
expect_exit 0 "--svg-window" "$CLI" refine "$DOMAINS/naca0012.poly" --size 1 --svg "$OUT/whole.svg"
expect_exit 0 "--svg-window" "$CLI" refine "$DOMAINS/naca0012.poly" --size 1 --svg "$OUT/win.svg" \
    --svg-window=-0.45,-0.6,1.55,0.6
expect_grep "--svg-window" "$OUT/win.svg" 'viewBox="0 0 800.00 522.00"'
expect_grep "--svg-window" "$OUT/win.svg" '<clipPath id="window">'
if [ "$(grep -c '<polygon' "$OUT/win.svg")" -lt "$(grep -c '<polygon' "$OUT/whole.svg")" ]; then pass
else fail "--svg-window: the framed picture draws as many triangles as the whole one"; fi
expect_exit 0 "--quality --timings --svg" "$CLI" triangulate "$DOMAINS/annulus.poly" \
    -o "$OUT/a.vtu" --svg "$OUT/a.svg" --quality=full --timings --seed 3 --threads 1
for want in "vertices" "triangles" "min angle" "max angle" "angles in [55, 65] deg" \
            "obtuse (not well-centred)" "interior degree 6" "min dual edge ratio" \
            "angle histogram" "degree histogram"; do
    expect_grep "--quality" "$TMP/out" "$want"
done
for phase in read triangulate "recover segments" write; do
    if grep -E -q "^$phase: [0-9]+\.[0-9]+$" "$TMP/out"; then pass; else fail "--timings: no '$phase: seconds' line"; fi
done
if [ -s "$OUT/a.vtu" ] && [ -s "$OUT/a.svg" ]; then pass; else fail "-o with --svg: a file is missing"; fi
expect_exit 0 "same run again" "$CLI" triangulate "$DOMAINS/annulus.poly" -o "$OUT/b.vtu" --seed 3
if cmp -s "$OUT/a.vtu" "$OUT/b.vtu"; then pass; else fail "the same input and seed gave different bytes"; fi
expect_exit 0 "write with no -o" "$CLI" triangulate "$DOMAINS/square.poly" --quality

# A right triangle at the largest doubles: angles and dual ratios are exact,
# lengths and the area overflow to inf, and nothing is NaN.
expect_exit 0 "--quality near the largest doubles" "$CLI" triangulate "$DATA/huge_right_triangle.node" --quality=full
for want in "min angle|45 deg" "max angle|90 deg" "area|inf" "max edge|inf" "q2 max|0.8047" \
            "q1 mean min angle|45 deg"; do
    expect_grep "--quality near the largest doubles" "$TMP/out" \
        "$(printf '%-28s %s' "${want%%|*}" "${want#*|}")"
done
expect_grep "--quality near the largest doubles: 45-degree angles" "$TMP/out" "  40-50              2 "
if grep -i -q nan "$TMP/out"; then fail "--quality near the largest doubles prints NaN: $(grep -i nan "$TMP/out" | head -3)"; else pass; fi

# The short report has the measures and no histogram; --quality=full adds them.
expect_exit 0 "--quality short" "$CLI" triangulate "$DOMAINS/square.poly" --quality
expect_grep "--quality short" "$TMP/out" "min angle"
if grep -q "histogram" "$TMP/out"; then fail "--quality (short) prints histograms"; else pass; fi
expect_exit 2 "--quality=bad" "$CLI" triangulate "$DOMAINS/square.poly" --quality=long
expect_one_line "--quality=bad"
# Nothing asked for: a note says so, exit 0.
expect_exit 0 "nothing to do" "$CLI" triangulate "$DOMAINS/square.poly"
expect_grep "nothing to do: a note" "$TMP/err" "nothing to write or print"
# --flag=value beside --flag value, for the commands' own flags and the outputs.
expect_exit 0 "--flag=value" "$CLI" refine "$DOMAINS/square.poly" --size=0.2 --algo=frontal \
    --output="$OUT/eq.vtu" --svg="$OUT/eq.svg" --seed=4
expect_exit 0 "--flag value" "$CLI" refine "$DOMAINS/square.poly" --size 0.2 --algo frontal \
    --output "$OUT/sp.vtu" --svg "$OUT/sp.svg" --seed 4
if cmp -s "$OUT/eq.vtu" "$OUT/sp.vtu"; then pass; else fail "--flag=value and --flag value gave different meshes"; fi
expect_exit 2 "--timings=1" "$CLI" refine "$DOMAINS/square.poly" --timings=1
expect_exit 2 "--size= (empty)" "$CLI" refine "$DOMAINS/square.poly" --size=
# Extensions are case-insensitive.
expect_exit 0 "upper-case extension" "$CLI" triangulate "$DOMAINS/square.poly" -o "$OUT/UP.VTU" --svg "$OUT/UP.SVG"
expect_grep "upper-case extension" "$OUT/UP.VTU" "<VTKFile"
# -o -: the mesh on standard output (reports on standard error), no temporary left.
mkdir "$OUT/tmpdir"
expect_exit 0 "-o -" env TMPDIR="$OUT/tmpdir" "$CLI" refine "$DOMAINS/square.poly" --size 0.2 -o - \
    --quality --timings --seed 4
expect_grep "-o -: the mesh on stdout" "$TMP/out" "<VTKFile"
expect_grep "-o -: reports on stderr" "$TMP/err" "min angle"
expect_grep "-o -: timings on stderr" "$TMP/err" "refine: "
expect_empty_dir "-o -: temporary folder" "$OUT/tmpdir"
expect_exit 0 "-o - --format msh" "$CLI" optimise "$DOMAINS/square.poly" --size 0.3 -o - --format msh
expect_grep "-o - --format msh" "$TMP/out" "\$MeshFormat"
expect_exit 2 "-o - --format node" "$CLI" triangulate "$DOMAINS/square.poly" -o - --format node
expect_exit 2 "--format without -o -" "$CLI" triangulate "$DOMAINS/square.poly" -o "$OUT/f.vtu" --format msh
# --timings on every subcommand.
expect_exit 0 "refine --timings" "$CLI" refine "$DOMAINS/square.poly" --size 0.2 --timings
for phase in read triangulate refine; do
    if grep -E -q "^$phase: [0-9]+\.[0-9]+$" "$TMP/out"; then pass; else fail "refine --timings: no '$phase: seconds' line"; fi
done
expect_exit 0 "optimise --timings" "$CLI" optimise "$DOMAINS/square.poly" --size 0.3 --timings -o "$OUT/t.vtu"
for phase in read triangulate refine optimise write; do
    if grep -E -q "^$phase: [0-9]+\.[0-9]+$" "$TMP/out"; then pass; else fail "optimise --timings: no '$phase: seconds' line"; fi
done
# The progress line: --progress forces it (stderr is not a terminal here), --quiet hides it.
expect_exit 0 "--progress" "$CLI" refine "$DOMAINS/square.poly" --size 0.05 --progress -o "$OUT/p.vtu"
expect_grep "--progress" "$TMP/err" "cvmesh: refining"
expect_exit 0 "--quiet" "$CLI" refine "$DOMAINS/square.poly" --size 0.05 --quiet -o "$OUT/q.vtu"
if [ -s "$TMP/err" ]; then fail "--quiet: stderr not empty: $(head -c 200 "$TMP/err")"; else pass; fi
# Help prints defaults as they are typed.
expect_exit 0 "optimise --help" "$CLI" optimise --help
expect_grep "help: default as typed" "$TMP/out" "[default 0.15, range 0..0.25]"
expect_grep "help: integer default" "$TMP/out" "[default 300, range 30..1000000]"
if grep -q "0.1499999" "$TMP/out"; then fail "help prints 0.1499999..."; else pass; fi

# ---- other inputs -----------------------------------------------------------
OUT=$TMP/inputs
mkdir "$OUT"
expect_exit 0 ".node point set" "$CLI" triangulate "$DATA/cocircular_octagon_and_centre.node" -o "$OUT/p.node"
if [ -s "$OUT/p.ele" ]; then pass; else fail ".node point set: no .ele"; fi
expect_exit 0 ".poly with points in .node" "$CLI" triangulate "$DATA/points_in_node_file.poly" -o "$OUT/q.msh"
expect_exit 0 "0-based poly with comments" "$CLI" triangulate "$DATA/zero_based_with_comments.poly" -o "$OUT/z.vtu" --keep-hull
expect_exit 0 "regions and attributes" "$CLI" triangulate "$DATA/one_based_attributes_regions.poly" -o "$OUT/r.vtu"
expect_grep "regions give cell data" "$OUT/r.vtu" 'Name="attribute"'
# .msh: one physical surface per region, nodes classified on the curves (meshio reads both).
expect_exit 0 "regions to .msh" "$CLI" refine "$DATA/one_based_attributes_regions.poly" --size 0.3 -o "$OUT/r.msh"
if "$PY" -c '
import sys, meshio
m = meshio.read(sys.argv[1])
assert {"region_7", "region_9", "marker_1"} <= set(m.cell_sets), m.cell_sets.keys()
dims = set(int(d) for d in m.point_data["gmsh:dim_tags"][:, 0])
assert dims == {0, 1, 2}, dims
' "$OUT/r.msh" > "$OUT/meshio_regions.log" 2>&1; then pass; else fail "regions .msh with meshio: $(tail -c 300 "$OUT/meshio_regions.log")"; fi
# crossings rounded at the scale of 1e6: success, 13 points plus 16 crossing vertices (a
# rounded crossing within 16 ulps of an end of the piece it crosses is that end)
expect_exit 0 "crossings near a large offset" "$CLI" triangulate "$DATA/crossings_near_large_offset.poly" -o "$OUT/c.node"
expect_grep "crossings near a large offset: 16 crossing vertices" "$OUT/c.node" "29 2 0 1"

# ---- tetrahedralize: 3D points and closed surfaces ----------------------------
OUT=$TMP/tet
mkdir "$OUT"
D3=$DOMAINS/../data3d
expect_exit 0 "tetrahedralize a BCC .node" "$CLI" tetrahedralize "$DATA/bcc_2x2x2.node" -o "$OUT/bcc.vtu" --quality --timings
for want in "tetrahedra                   96" "volume                       8" "read: " "tetrahedralize: " \
            "min dual edge                0.353553" "dihedral angles (10 deg)"; do
    expect_grep "tetrahedralize --quality" "$TMP/out" "$want"
done
expect_exit 0 "tetrahedralize two cubes" "$CLI" tetrahedralize "$D3/two_cubes.poly" -o "$OUT/two.vtu"
expect_exit 0 "tetrahedralize a cube .off to .msh" "$CLI" tetrahedralize "$D3/cube.off" -o "$OUT/cube.msh"
expect_exit 0 "tetrahedralize a binary .stl to .node" "$CLI" tetrahedralize "$D3/cube_binary.stl" -o "$OUT/cube.node"
for f in cube.node cube.ele cube.face; do
    if [ -s "$OUT/$f" ]; then pass; else fail "tetrahedralize .node: $f missing"; fi
done
# meshio reads the tetrahedra; their volumes sum to the domain's
if "$PY" -c '
import sys, meshio, numpy as np
for path, want in ((sys.argv[1], 8.0), (sys.argv[2], 2.0), (sys.argv[3], 1.0)):
    m = meshio.read(path)
    t = np.vstack([c.data for c in m.cells if c.type == "tetra"])
    p = m.points[t]
    v = np.einsum("ij,ij->i", p[:, 0] - p[:, 3], np.cross(p[:, 1] - p[:, 3], p[:, 2] - p[:, 3])) / 6
    assert (v > 0).all(), path
    assert abs(v.sum() - want) < 1e-12 * want, (path, v.sum())
' "$OUT/bcc.vtu" "$OUT/two.vtu" "$OUT/cube.msh" > "$OUT/meshio.log" 2>&1; then pass; else fail "tetrahedralize outputs with meshio: $(tail -c 300 "$OUT/meshio.log")"; fi
expect_exit 1 "tetrahedralize an open surface" "$CLI" tetrahedralize "$DATA/open_tetra.off" -o "$OUT/open.vtu"
expect_one_line "tetrahedralize an open surface"
expect_grep "tetrahedralize an open surface" "$TMP/err" "open"
if [ ! -e "$OUT/open.vtu" ]; then pass; else fail "tetrahedralize an open surface wrote a file"; fi
expect_exit 1 "tetrahedralize a 2D input" "$CLI" tetrahedralize "$DOMAINS/square.poly"
expect_one_line "tetrahedralize a 2D input"
expect_exit 2 "tetrahedralize to .svg" "$CLI" tetrahedralize "$D3/cube.off" -o "$OUT/c.svg"
expect_exit 1 "tetrahedralize a missing file" "$CLI" tetrahedralize "$OUT/none.off"

# ---- mesh3: co-volume generation inside a closed surface --------------------------
OUT=$TMP/mesh3
mkdir "$OUT"
expect_exit 0 "mesh3 --help" "$CLI" mesh3 --help
expect_grep "mesh3 --help" "$TMP/out" "--grading G"
if "$CLI" --version | grep -q "TetGen 1.5"; then
    # the cube's faces are cocircular squares: recovered by TetGen only
    expect_exit 0 "mesh3 a cube" "$CLI" mesh3 "$D3/cube.off" --size 0.25 --uniform -o "$OUT/cube.vtu" \
        --quality --timings
    for want in "matched face pairs           384" "unmatched faces              0" \
                "volume                       1" "boundary faces               768" "generate: "; do
        expect_grep "mesh3 --quality" "$TMP/out" "$want"
    done
    expect_exit 0 "mesh3 a cube to .node" "$CLI" mesh3 "$D3/cube.off" --size 0.25 -o "$OUT/cube.node"
    for f in cube.node cube.ele cube.face; do
        if [ -s "$OUT/$f" ]; then pass; else fail "mesh3 .node: $f missing"; fi
    done
    if [ "$HAVE_NUMPY" -eq 1 ] && "$PY" -c '
import sys, meshio, numpy as np
m = meshio.read(sys.argv[1])
t = np.vstack([c.data for c in m.cells if c.type == "tetra"])
p = m.points[t]
v = np.einsum("ij,ij->i", p[:, 0] - p[:, 3], np.cross(p[:, 1] - p[:, 3], p[:, 2] - p[:, 3])) / 6
assert (v > 0).all()
assert abs(v.sum() - 1.0) < 1e-12, v.sum()
inner = np.ones(len(m.points), bool)
inner[:386] = False
x = m.points[inner]
assert ((x > 0) & (x < 1)).all()
' "$OUT/cube.vtu" > "$OUT/meshio.log" 2>&1; then pass; else
        [ "$HAVE_NUMPY" -eq 1 ] && fail "mesh3 cube with meshio: $(tail -c 300 "$OUT/meshio.log")"
    fi
fi
expect_exit 0 "mesh3 a tetrahedron" "$CLI" mesh3 "$D3/tetra.off" --size 0.5 --uniform -o "$OUT/tetra.vtu"
# the same bytes for any thread count
for n in 1 2; do
    expect_exit 0 "mesh3 with $n threads" env OMP_NUM_THREADS=$n "$CLI" mesh3 "$D3/tetra.off" --size 0.3 \
        -o "$OUT/tetra_$n.node"
done
if cmp -s "$OUT/tetra_1.node" "$OUT/tetra_2.node" && cmp -s "$OUT/tetra_1.ele" "$OUT/tetra_2.ele"; then
    pass
else
    fail "mesh3: other bytes with 2 threads"
fi
# a mesh made elsewhere: the .node + .ele just written, optimised as it is
expect_exit 0 "optimise a .ele" "$CLI" optimise "$OUT/tetra_1.ele" --quality --opt-sweeps 5 \
    -o "$OUT/tetra_opt.vtu"
for want in "non-compliant after merging" "outside before optimising" "optimiser sweeps"; do
    expect_grep "optimise a .ele --quality" "$TMP/out" "$want"
done
if grep -q "matched face pairs" "$TMP/out"; then fail "optimise .ele: generator rows printed"; else pass; fi
printf '1 4 0\n1 1 2 3 999\n' > "$OUT/tetra_1bad.ele"
cp "$OUT/tetra_1.node" "$OUT/tetra_1bad.node"
expect_exit 1 "optimise a bad .ele" "$CLI" optimise "$OUT/tetra_1bad.ele"
expect_grep "optimise a bad .ele" "$TMP/err" "names point 999"
expect_exit 2 "optimise a .ele with --size" "$CLI" optimise "$OUT/tetra_1.ele" --size 0.1
expect_exit 0 "mesh3 --freespace octree" "$CLI" mesh3 "$D3/tetra.off" --size 0.3 --uniform \
    --freespace octree --quality -o "$OUT/octree.vtu"
expect_grep "mesh3 --freespace octree" "$TMP/out" "octree points"
expect_grep "mesh3 --freespace octree" "$TMP/out" "lattice points               0"
if [ -s "$OUT/octree.vtu" ]; then pass; else fail "mesh3 --freespace octree wrote no file"; fi
expect_exit 0 "mesh3 --freespace lattice" "$CLI" mesh3 "$D3/tetra.off" --size 0.3 --uniform --quality
if grep -q "octree" "$TMP/out"; then fail "mesh3 --freespace lattice reports an octree"; else pass; fi
"$CLI" mesh3 --help > "$TMP/out" 2>&1
expect_grep "mesh3 --help lists --remesh-surface" "$TMP/out" "--remesh-surface"
if "$CLI" --version | grep -q "TetGen 1.5"; then
    expect_exit 0 "mesh3 --remesh-surface" "$CLI" mesh3 "$D3/cube.off" --size 0.25 \
        --remesh-surface -o "$OUT/remeshed.vtu" --quality
    expect_grep "mesh3 --remesh-surface" "$TMP/out" "boundary faces"
    if [ -s "$OUT/remeshed.vtu" ]; then pass; else fail "mesh3 --remesh-surface wrote no file"; fi
fi
expect_exit 0 "mesh3 --freespace refine" "$CLI" mesh3 "$D3/tetra.off" --size 0.3 --uniform \
    --freespace refine --quality
expect_grep "mesh3 --freespace refine" "$TMP/out" "refinement points"
expect_exit 0 "mesh3 --freespace refine --max-steiner" "$CLI" mesh3 "$D3/tetra.off" --size 0.3 \
    --uniform --freespace refine --max-steiner 5 --quality
expect_grep "mesh3 --freespace refine --max-steiner" "$TMP/out" "refinement points            5"
expect_grep "mesh3 --freespace refine --max-steiner" "$TMP/err" "CVM_OPT_MAX_STEINER"
expect_exit 0 "mesh3 --optimise" "$CLI" mesh3 "$D3/tetra.off" --size 0.3 --optimise --opt-sweeps 3 \
    -o "$OUT/o.vtu" --quality
expect_grep "mesh3 --optimise" "$TMP/out" "outside before optimising"
expect_grep "mesh3 --optimise" "$TMP/out" "optimiser sweeps"
if [ -s "$OUT/o.vtu" ]; then pass; else fail "mesh3 --optimise wrote no file"; fi
# the same bytes for any thread count, optimised too
for n in 1 2; do
    expect_exit 0 "mesh3 --optimise with $n threads" env OMP_NUM_THREADS=$n "$CLI" mesh3 "$D3/tetra.off" \
        --size 0.3 --optimise --opt-sweeps 2 -o "$OUT/otetra_$n.node" --dual "$OUT/otetra_$n.dual.vtu"
done
if cmp -s "$OUT/otetra_1.node" "$OUT/otetra_2.node" && cmp -s "$OUT/otetra_1.dual.vtu" "$OUT/otetra_2.dual.vtu"; then
    pass
else
    fail "mesh3 --optimise: other bytes with 2 threads"
fi
# merged dual cells: reported with --quality; --merge-tol 0 merges nothing, so the
# non-compliant share is then the outside share
expect_exit 0 "mesh3 --merge-tol" "$CLI" mesh3 "$D3/tetra.off" --size 0.3 --merge-tol 1 --quality
expect_grep "mesh3 --merge-tol" "$TMP/out" "merged (--merge-tol)"
expect_grep "mesh3 --merge-tol" "$TMP/out" "non-compliant after merging"
expect_grep "mesh3 --merge-tol" "$TMP/out" "merge groups dissolved"
expect_exit 0 "mesh3 --merge-tol 0" "$CLI" mesh3 "$D3/tetra.off" --size 0.3 --merge-tol 0 --quality
expect_grep "mesh3 --merge-tol 0" "$TMP/out" "merged (--merge-tol)         0.000 %"
out_pct=$(sed -n 's/^circumcentre outside *//p' "$TMP/out")
nc_pct=$(sed -n 's/^non-compliant after merging *//p' "$TMP/out")
if [ -n "$out_pct" ] && [ "$out_pct" = "$nc_pct" ]; then pass; else
    fail "mesh3 --merge-tol 0: non-compliant '$nc_pct', outside '$out_pct'"
fi
expect_exit 0 "mesh3 --merged-cells" "$CLI" mesh3 "$D3/tetra.off" --size 0.3 --merge-tol 1 --merged-cells \
    -o "$OUT/merged.vtu"
expect_grep "mesh3 --merged-cells" "$OUT/merged.vtu" "faceoffsets"
if [ "$HAVE_NUMPY" -eq 1 ] && "$PY" -c '
import sys, meshio
m = meshio.read(sys.argv[1])
assert all(c.type.startswith("polyhedron") for c in m.cells), [c.type for c in m.cells]
assert any(c.type != "polyhedron4" for c in m.cells)
' "$OUT/merged.vtu" > "$OUT/merged.log" 2>&1; then pass; else
    [ "$HAVE_NUMPY" -eq 1 ] && fail "mesh3 --merged-cells with meshio: $(tail -c 300 "$OUT/merged.log")"
fi
expect_exit 2 "mesh3 --merge-tol 2" "$CLI" mesh3 "$D3/tetra.off" --size 0.3 --merge-tol 2
expect_exit 2 "mesh3 --merge-tol x" "$CLI" mesh3 "$D3/tetra.off" --size 0.3 --merge-tol x
expect_exit 0 "mesh3 --help" "$CLI" mesh3 --help
expect_grep "mesh3 --help" "$TMP/out" "--merge-tol F"
expect_exit 2 "mesh3 --opt-budget 0" "$CLI" mesh3 "$D3/tetra.off" --size 0.5 --optimise --opt-budget 0
expect_exit 1 "mesh3 --layers 2" "$CLI" mesh3 "$D3/tetra.off" --size 0.5 --layers 2
expect_grep "mesh3 --layers 2" "$TMP/err" "unsupported"
expect_exit 2 "mesh3 without --size" "$CLI" mesh3 "$D3/tetra.off"
expect_exit 2 "mesh3 --size 0" "$CLI" mesh3 "$D3/tetra.off" --size 0
expect_exit 2 "mesh3 --freespace bogus" "$CLI" mesh3 "$D3/tetra.off" --size 1 --freespace bogus
expect_exit 1 "mesh3 a 2D input" "$CLI" mesh3 "$DOMAINS/square.poly" --size 1
expect_one_line "mesh3 a 2D input"
expect_exit 1 "mesh3 two regions" "$CLI" mesh3 "$D3/two_cubes.poly" --size 0.5
expect_grep "mesh3 two regions" "$TMP/err" "unsupported"
# --point-source: a finer mesh around the point, more vertices than without it
expect_exit 0 "mesh3 --help" "$CLI" mesh3 --help
expect_grep "mesh3 --help lists --point-source" "$TMP/out" "--point-source X,Y,Z,H[,G]"
expect_exit 0 "mesh3 --point-source" "$CLI" mesh3 "$D3/tetra.off" --size 0.5 --uniform \
    --point-source 0,0,0,0.08,0.3 -o "$OUT/tetra_ps.node"
expect_exit 0 "mesh3 without a source" "$CLI" mesh3 "$D3/tetra.off" --size 0.5 --uniform \
    -o "$OUT/tetra_nops.node"
n_ps=$(head -n 1 "$OUT/tetra_ps.node" | awk '{print $1}')
n_no=$(head -n 1 "$OUT/tetra_nops.node" | awk '{print $1}')
if [ "${n_ps:-0}" -gt "${n_no:-0}" ]; then pass; else
    fail "mesh3 --point-source: $n_ps vertices, not more than $n_no without"
fi
expect_exit 2 "mesh3 --point-source 1,2" "$CLI" mesh3 "$D3/tetra.off" --size 0.5 --point-source 1,2
expect_grep "mesh3 --point-source 1,2" "$TMP/err" "X,Y,Z,H"
expect_exit 2 "mesh3 --point-source H=0" "$CLI" mesh3 "$D3/tetra.off" --size 0.5 \
    --point-source 0,0,0,0
expect_exit 2 "mesh3 --point-source G<0" "$CLI" mesh3 "$D3/tetra.off" --size 0.5 \
    --point-source 0,0,0,0.1,-1
expect_exit 2 "mesh3 --point-source 6 values" "$CLI" mesh3 "$D3/tetra.off" --size 0.5 \
    --point-source 0,0,0,0.1,0.2,3
# ---- quad: metric-aligned quad-dominant meshes ---------------------------------
OUT=$TMP/quad
mkdir "$OUT"
expect_exit 0 "quad --help" "$CLI" quad --help
expect_grep "quad --help" "$TMP/out" "--metric SPEC"
expect_exit 0 "quad the unit lattice" "$CLI" quad --domain-box 0,0,4,4 --metric builtin:identity \
    -o "$OUT/box.vtu" --quality --timings
for want in "quads                        16" "quads by count               100.00 %" \
    "edges, L_M in [0.71,1.41]    100.00 %" "quadmesh: " "write: "; do
    expect_grep "quad --quality" "$TMP/out" "$want"
done
expect_grep "quad .vtu has VTK_QUAD cells" "$OUT/box.vtu" "9 9 9 9"
expect_exit 0 "quad a .poly, binary .vtu" "$CLI" quad "$DOMAINS/square.poly" --metric builtin:stretch:9 \
    --p 4 --recombine greedy -o "$OUT/sq.vtu" --vtu-encoding binary --seed 3
if [ -s "$OUT/sq.vtu" ]; then pass; else fail "quad .poly: no .vtu written"; fi
expect_exit 0 "quad to .msh" "$CLI" quad --domain-box 0,0,4,4 --metric builtin:identity -o "$OUT/box.msh"
if [ "$HAVE_MESHIO" -eq 1 ]; then
    if "$PY" -c '
import sys, meshio, numpy as np
for path, want in ((sys.argv[1], 16.0), (sys.argv[2], 1.0)):
    m = meshio.read(path)
    area = 0.0
    for c in m.cells:
        assert c.type in ("quad", "triangle", "line"), c.type
        if c.type == "line":
            continue
        p = m.points[c.data][:, :, :2]
        q = np.roll(p, -1, axis=1)
        a = 0.5 * (p[:, :, 0] * q[:, :, 1] - p[:, :, 1] * q[:, :, 0]).sum(axis=1)
        assert (a > 0).all(), path
        area += a.sum()
    assert abs(area - want) < 1e-12 * want, (path, area)
' "$OUT/box.vtu" "$OUT/sq.vtu" > "$OUT/meshio.log" 2>&1; then pass; else fail "quad outputs with meshio: $(tail -c 300 "$OUT/meshio.log")"; fi
    if "$PY" -c '
import sys, meshio
m = meshio.read(sys.argv[1])
q = sum(len(c.data) for c in m.cells if c.type == "quad")
assert q == 16, q
' "$OUT/box.msh" > "$OUT/meshio_msh.log" 2>&1; then pass; else fail "quad .msh with meshio: $(tail -c 300 "$OUT/meshio_msh.log")"; fi
fi
expect_exit 1 "quad to .svg (not yet)" "$CLI" quad --domain-box 0,0,2,2 --metric builtin:identity -o "$OUT/q.svg"
expect_one_line "quad to .svg"
expect_exit 1 "quad a non-convex domain" "$CLI" quad "$DOMAINS/annulus.poly" --metric builtin:identity:4
expect_one_line "quad a non-convex domain"
expect_exit 2 "quad without --metric" "$CLI" quad --domain-box 0,0,1,1
expect_exit 2 "quad with an unknown metric" "$CLI" quad --domain-box 0,0,1,1 --metric builtin:nope
expect_exit 2 "quad with a bad box" "$CLI" quad --domain-box 1,0,0,1 --metric builtin:identity
expect_exit 2 "quad with a bad constant" "$CLI" quad --domain-box 0,0,1,1 --metric constant:1,2,1

# ---- optimise: the power dual -------------------------------------------------
OUT=$TMP/optimise
mkdir "$OUT"
for algo in frontal delaunay; do
    expect_exit 0 "optimise $algo" "$CLI" optimise "$DOMAINS/annulus.poly" --algo $algo --size 0.2 \
        -o "$OUT/o_$algo.node" --quality --seed 5
    expect_grep "optimise $algo: compliant" "$TMP/out" "non-compliant (not merged)   0.0000 %"
    for want in "power vertex outside" "merged" "time-step proxy" "sweeps" "min angle"; do
        expect_grep "optimise --quality" "$TMP/out" "$want"
    done
    if [ "$HAVE_NUMPY" -eq 1 ]; then
        if "$PY" "$VERIFY" "$DOMAINS/annulus.poly" "$OUT/o_$algo" --weights \
               --no-delaunay > "$OUT/verify.json" 2>&1 &&
           grep -q '"pct_power_outside": 0.0,' "$OUT/verify.json"; then
            pass
        else
            fail "optimise $algo: verify_mesh.py --weights: $(tail -c 400 "$OUT/verify.json")"
        fi
    fi
done
expect_exit 0 "optimise again, same seed" "$CLI" optimise "$DOMAINS/annulus.poly" --algo frontal \
    --size 0.2 -o "$OUT/again.node" --seed 5
if cmp -s "$OUT/o_frontal.node" "$OUT/again.node"; then pass; else fail "optimise: same input and seed gave different bytes"; fi
expect_exit 0 "optimise a .node point set" "$CLI" optimise "$DATA/cocircular_octagon_and_centre.node" -o "$OUT/p.vtu"
expect_exit 0 "optimise with the cuckoo solver" "$CLI" optimise "$DOMAINS/square.poly" --size 0.2 \
    --solver 2 --quality
expect_grep "optimise --solver 2" "$TMP/out" "non-compliant (not merged)   0.0000 %"
expect_exit 2 "optimise: bad solver" "$CLI" optimise "$DOMAINS/square.poly" --solver 3
expect_exit 2 "optimise: bad --algo" "$CLI" optimise "$DOMAINS/square.poly" --algo aflr
expect_exit 2 "optimise: no input" "$CLI" optimise
expect_exit 0 "optimise --help" "$CLI" optimise --help
expect_grep "optimise --help" "$TMP/out" "--merge-tol"
expect_exit 1 "optimise: missing input" "$CLI" optimise "$OUT/no_such.poly"
expect_one_line "optimise: missing input"

# ---- bad inputs: exit 1, one line naming file:line, no output ---------------
for case in bad_truncated_points.poly:4 bad_nan_coordinate.poly:3 bad_segment_index.poly:7 \
            bad_point_count_too_small.poly:6 bad_binary_garbage.poly:3; do
    file=${case%:*}
    line=${case##*:}
    OUT=$TMP/bad_$file
    mkdir "$OUT"
    expect_exit 1 "$file" "$CLI" triangulate "$DATA/$file" -o "$OUT/x.vtu" --svg "$OUT/x.svg"
    expect_one_line "$file"
    expect_grep "$file names its line" "$TMP/err" "$file:$line:"
    expect_empty_dir "$file" "$OUT"
done

OUT=$TMP/bad_other
mkdir "$OUT"
expect_exit 1 "missing input" "$CLI" triangulate "$OUT/none.poly" -o "$OUT/x.vtu"
expect_grep "missing input" "$TMP/err" "cannot open"
expect_one_line "missing input"
expect_exit 1 "input of unknown type" "$CLI" triangulate "$HERE/run.sh" -o "$OUT/x.vtu"
expect_one_line "input of unknown type"
cat > "$OUT/crossing.poly" <<'EOF'
# a square with both diagonals as segments: they cross at (0.5, 0.5)
4 2 0 0
1 0 0
2 1 0
3 1 1
4 0 1
6 0
1 1 2
2 2 3
3 3 4
4 4 1
5 1 3
6 2 4
0
EOF
expect_exit 1 "crossing segments rejected" "$CLI" triangulate "$OUT/crossing.poly" -o "$OUT/x.vtu" --no-split-intersections
expect_one_line "crossing segments rejected"
expect_grep "crossing segments named" "$TMP/err" "segment"
expect_exit 0 "crossing segments split" "$CLI" triangulate "$OUT/crossing.poly" -o "$OUT/split.vtu"
rm -f "$OUT/split.vtu"
printf '3 2 0 0\n1 0 0\n2 1 0\n3 1 0\n' > "$OUT/dup.node"
expect_exit 1 "duplicates rejected" "$CLI" triangulate "$OUT/dup.node" -o "$OUT/x.vtu" --reject-duplicates
expect_one_line "duplicates rejected"
rm -f "$OUT/crossing.poly" "$OUT/dup.node"

# ---- messages after parsing speak in the file's terms -----------------------
# (1-based numbering, comment lines: file numbers and lines differ from indices)
printf '# four points, numbered from 1\n4 2 0 0\n1 0 0\n2 1 0\n\n3 0 1\n4 0 0\n' > "$OUT/dup1.node"
expect_exit 1 "duplicate in a 1-based .node" "$CLI" triangulate "$OUT/dup1.node" --reject-duplicates
expect_grep "duplicate in a 1-based .node" "$TMP/err" \
    "cvmesh: $OUT/dup1.node:7: point 4 at (0, 0) duplicates point 1 (line 3)"
expect_one_line "duplicate in a 1-based .node"
printf '3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n3 0\n1 1 2\n2 1 1\n3 2 3\n0\n' > "$OUT/zl.poly"
expect_exit 1 "zero-length segment in a 1-based .poly" "$CLI" triangulate "$OUT/zl.poly"
expect_grep "zero-length segment in a 1-based .poly" "$TMP/err" \
    "cvmesh: $OUT/zl.poly:7: segment 2 (points 1-1) has zero length"
printf '4 2 0 0\n1 0 0\n2 4 0\n3 4 4\n4 0 4\n6 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n5 1 3\n6 2 4\n0\n' > "$OUT/cross1.poly"
expect_exit 1 "crossing segments in a 1-based .poly" "$CLI" triangulate "$OUT/cross1.poly" --no-split-intersections
expect_grep "crossing segments in a 1-based .poly" "$TMP/err" \
    "cross1.poly:12: segment 6 (points 2-4) crosses segment 5 (line 11) (points 1-3) in its interior"
printf '3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n3 0\n1 1 2\n2 2 3\n3 3 1\n1\n1 0.25 0.25\n' > "$OUT/hole.poly"
expect_exit 1 "hole inside the only closed boundary" "$CLI" triangulate "$OUT/hole.poly"
expect_grep "hole inside the only closed boundary" "$TMP/err" \
    "hole.poly:10: hole 1 at (0.25, 0.25) removed every remaining triangle: no closed loop of segments separates it from the rest of the domain"
mkdir "$OUT/dir.poly"
expect_exit 1 "a directory as input" "$CLI" triangulate "$OUT/dir.poly"
expect_grep "a directory as input" "$TMP/err" "cannot read $OUT/dir.poly: it is a directory"
rmdir "$OUT/dir.poly"
printf '3 2 0 0\n0 0 0\n1 1 \033]0;owned\007\n2 0 1\n' > "$OUT/esc.node"
expect_exit 1 "control bytes in a field" "$CLI" triangulate "$OUT/esc.node"
expect_grep "control bytes in a field are escaped" "$TMP/err" "found '\\x1b]0;owned\\x07'"
if LC_ALL=C grep -q "$(printf '\033')" "$TMP/err"; then fail "control bytes in a field: ESC printed raw"; else pass; fi
printf '3 2 0 0\n1 0 0\n2 0x1p0 0\n3 0 1\n' > "$OUT/hex.node"
expect_exit 1 "hexadecimal float refused" "$CLI" triangulate "$OUT/hex.node"
expect_grep "hexadecimal float refused" "$TMP/err" \
    "hex.node:3: point 2: expected a decimal number, found '0x1p0' (hexadecimal floats are not read)"
# a maximum area <= 0 means no bound, in a .poly region (Triangle's -1) as with --max-area
printf '4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n1\n1 0.5 0.5 7 -1\n' > "$OUT/reg.poly"
expect_exit 0 "region area -1" "$CLI" refine "$OUT/reg.poly" -o "$OUT/reg_m1.vtu"
sed 's/ -1$//' "$OUT/reg.poly" > "$OUT/reg0.poly"
expect_exit 0 "region without area" "$CLI" refine "$OUT/reg0.poly" -o "$OUT/reg_none.vtu"
if cmp -s "$OUT/reg_m1.vtu" "$OUT/reg_none.vtu"; then pass; else fail "region area -1 is not 'no bound'"; fi
expect_exit 0 "--max-area -1" "$CLI" refine "$OUT/reg0.poly" --max-area -1 -o "$OUT/ma_m1.vtu"
if cmp -s "$OUT/ma_m1.vtu" "$OUT/reg_none.vtu"; then pass; else fail "--max-area -1 is not 'no bound'"; fi
rm -f "$OUT/dup1.node" "$OUT/zl.poly" "$OUT/cross1.poly" "$OUT/hole.poly" "$OUT/esc.node" "$OUT/hex.node" \
    "$OUT/reg.poly" "$OUT/reg0.poly" "$OUT/reg_m1.vtu" "$OUT/reg_none.vtu" "$OUT/ma_m1.vtu"
expect_empty_dir "bad inputs" "$OUT"

# ---- the power dual and .vtu input -------------------------------------------
OUT=$TMP/dual
mkdir "$OUT"
expect_exit 0 "refine --dual --quality" "$CLI" refine "$DOMAINS/annulus.poly" --algo frontal \
    --size 0.2 -o "$OUT/m.vtu" --dual "$OUT/d.vtu" --quality=full
for want in "power vertex outside" "time-step proxy" "q1 mean min angle" "q2 max" "q3 max" \
            "q4 max" "q5 min" "q5 min at the boundary" "q5 histogram"; do
    expect_grep "refine --quality" "$TMP/out" "$want"
done
expect_grep "--dual" "$OUT/d.vtu" 'Name="area"'
expect_grep "--dual" "$OUT/d.vtu" '<DataArray type="UInt8" Name="types" format="ascii">'
expect_exit 0 "triangulate a .vtu mesh" "$CLI" triangulate "$OUT/m.vtu" -o "$OUT/m2.vtu" \
    --dual "$OUT/d2.vtu" --quality
if cmp -s "$OUT/m.vtu" "$OUT/m2.vtu"; then pass; else fail ".vtu read and written again differs"; fi
if cmp -s "$OUT/d.vtu" "$OUT/d2.vtu"; then pass; else fail "the dual of the re-read .vtu differs"; fi
expect_exit 0 "refine a .vtu mesh further" "$CLI" refine "$OUT/m.vtu" --size 0.1 -o "$OUT/m3.msh"
expect_exit 2 "--dual needs .vtu" "$CLI" triangulate "$DOMAINS/square.poly" --dual "$OUT/d.svg"
printf '<VTKFile type="UnstructuredGrid"><Piece NumberOfPoints="3" NumberOfCells="1">\n<Points>\n<DataArray NumberOfComponents="3" format="ascii">0 0 0 1 0 0 0 nan 0</DataArray></Points></Piece></VTKFile>\n' > "$OUT/nan.vtu"
expect_exit 1 "NaN in a .vtu" "$CLI" triangulate "$OUT/nan.vtu" -o "$OUT/x.vtu"
expect_grep "NaN in a .vtu" "$TMP/err" "nan.vtu:3: Points: entry 7 (from 0) is 'nan', not a finite number"
expect_one_line "NaN in a .vtu"
if [ ! -e "$OUT/x.vtu" ]; then pass; else fail "NaN in a .vtu: output written"; fi

# ---- failed writes: exit 1, nothing left ------------------------------------
OUT=$TMP/write
mkdir "$OUT"
expect_exit 1 "output directory missing" "$CLI" triangulate "$DOMAINS/square.poly" -o "$OUT/no/such/x.vtu"
expect_grep "output directory missing" "$TMP/err" "cannot create"
expect_one_line "output directory missing"
if [ -e /dev/full ]; then
    ln -s /dev/full "$OUT/full.msh"
    expect_exit 1 "disk full" "$CLI" triangulate "$DOMAINS/naca0012.poly" -o "$OUT/full.msh"
    expect_grep "disk full" "$TMP/err" "cannot write"
    expect_one_line "disk full"
    rm -f "$OUT/full.msh"
    ln -s /dev/full "$OUT/full.ele"
    expect_exit 1 "disk full on .ele" "$CLI" triangulate "$DOMAINS/naca0012.poly" -o "$OUT/full.node"
    rm -f "$OUT/full.ele"
fi
expect_exit 1 "picture fails after the mesh" "$CLI" triangulate "$DOMAINS/square.poly" -o "$OUT/ok.node" --svg "$OUT/no/such/x.svg"
expect_one_line "picture fails after the mesh"
expect_empty_dir "failed writes" "$OUT"

# ---- refine with the automatic size ---------------------------------------
OUT=$TMP/auto
mkdir -p "$OUT"
expect_exit 0 "refine --auto" "$CLI" refine "$DOMAINS/cylinder.poly" --algo frontal --auto 3 --grading 4 \
    -o "$OUT/cyl.vtu" --quality
expect_grep "refine --auto meets the angle" "$TMP/out" "triangles below the angle: 0"
expect_exit 0 "refine --no-swap --smooth 3" "$CLI" refine "$DOMAINS/square.poly" --algo frontal --size 0.1 \
    --no-swap --smooth 3 -o "$OUT/sq.vtu"
expect_exit 2 "--smooth out of range" "$CLI" refine "$DOMAINS/square.poly" --smooth 1000 -o "$OUT/x.vtu"
# -1 (the default) is each refiner's own sweep count: frontal 3 relaxation + 4 smart
# sweeps, AFLR 5 + 3; -2 is out of range and writes nothing
for a in "frontal 3 4" "aflr 5 3"; do
    set -- $a
    expect_exit 0 "refine --algo $1 (default sweeps)" "$CLI" refine "$DOMAINS/annulus.poly" --algo $1 \
        --size 0.3 -o "$OUT/def_$1.node"
    expect_exit 0 "refine --algo $1 --relax $2 --smooth $3" "$CLI" refine "$DOMAINS/annulus.poly" \
        --algo $1 --size 0.3 --relax $2 --smooth $3 -o "$OUT/exp_$1.node"
    if cmp -s "$OUT/def_$1.node" "$OUT/exp_$1.node" && cmp -s "$OUT/def_$1.ele" "$OUT/exp_$1.ele"; then pass
    else fail "$1: the default sweeps are not --relax $2 --smooth $3"; fi
done
expect_exit 2 "--smooth -2" "$CLI" refine "$DOMAINS/square.poly" --smooth -2 -o "$OUT/neg.vtu"
if [ ! -e "$OUT/neg.vtu" ]; then pass; else fail "--smooth -2 wrote a file"; fi
expect_exit 2 "--auto not positive" "$CLI" refine "$DOMAINS/square.poly" --auto 0 -o "$OUT/x.vtu"
expect_exit 2 "--grading without --auto" "$CLI" refine "$DOMAINS/square.poly" --grading 3 -o "$OUT/x.vtu"
expect_grep "--grading without --auto" "$TMP/err" "--grading needs --auto"
expect_exit 2 "--grading not a number" "$CLI" refine "$DOMAINS/square.poly" --auto 2 --grading x -o "$OUT/x.vtu"

# ---- boundary grading: a fine wall carried inwards --------------------------
OUT=$TMP/bgrad
mkdir -p "$OUT"
expect_exit 0 "refine --boundary-grading" "$CLI" refine "$DOMAINS/cylinder.poly" --algo frontal --size 0.2 \
    --boundary-grading 0.3 -o "$OUT/cyl.node" --quality
expect_grep "refine --boundary-grading meets the angle" "$TMP/out" "triangles below the angle: 0"
# more vertices than at the uniform size alone (12174 then; 12357 graded)
nv_graded=$(head -n 1 "$OUT/cyl.node" | awk '{print $1}')
expect_exit 0 "refine uniform" "$CLI" refine "$DOMAINS/cylinder.poly" --algo frontal --size 0.2 -o "$OUT/u.node"
nv_uniform=$(head -n 1 "$OUT/u.node" | awk '{print $1}')
if [ "$nv_graded" -gt "$nv_uniform" ]; then pass; else
    fail "boundary grading adds vertices ($nv_graded graded, $nv_uniform uniform)"; fi
expect_exit 0 "optimise --boundary-grading" "$CLI" optimise "$DOMAINS/cylinder.poly" --size 0.2 \
    --boundary-grading 0.3 -o "$OUT/opt.vtu" --quality
expect_grep "optimise --boundary-grading is compliant" "$TMP/out" "non-compliant (not merged)   0.0000 %"
grep -v -i "time" "$TMP/out" > "$OUT/graded.txt"
# the default of optimise --size is that grading (the same mesh), 0 turns it off
expect_exit 0 "optimise --size grades by default" "$CLI" optimise "$DOMAINS/cylinder.poly" --size 0.2 \
    --quality
if grep -v -i "time" "$TMP/out" | cmp -s - "$OUT/graded.txt"; then pass; else
    fail "optimise --size: not the graded default"; fi
minang=$(awk '/^min angle/ {print $3}' "$TMP/out")
if awk -v a="$minang" 'BEGIN {exit !(a >= 40)}'; then pass; else
    fail "optimise cylinder --size 0.2: min angle $minang < 40"; fi
expect_exit 0 "optimise --boundary-grading 0" "$CLI" optimise "$DOMAINS/cylinder.poly" --size 0.2 \
    --boundary-grading 0 --quality
if grep -v -i "time" "$TMP/out" | cmp -s - "$OUT/graded.txt"; then
    fail "optimise --boundary-grading 0 changed nothing"; else pass; fi
expect_exit 2 "--boundary-grading not positive" "$CLI" refine "$DOMAINS/square.poly" --size 0.1 \
    --boundary-grading -1 -o "$OUT/x.vtu"
expect_exit 2 "optimise --boundary-grading without --size" "$CLI" optimise "$DOMAINS/square.poly" \
    --boundary-grading 0.3 -o "$OUT/x.vtu"
expect_grep "optimise --boundary-grading without --size" "$TMP/err" "--boundary-grading needs --size"
expect_exit 2 "optimise --boundary-grading negative" "$CLI" optimise "$DOMAINS/square.poly" --size 0.1 \
    --boundary-grading -0.5 -o "$OUT/x.vtu"
expect_exit 2 "--boundary-grading not a number" "$CLI" refine "$DOMAINS/square.poly" --size 0.1 \
    --boundary-grading x -o "$OUT/x.vtu"
expect_exit 2 "optimise --boundary-grading nan" "$CLI" optimise "$DOMAINS/square.poly" --size 0.1 \
    --boundary-grading nan -o "$OUT/x.vtu"
expect_exit 2 "--boundary-grading without a value" "$CLI" refine "$DOMAINS/square.poly" --boundary-grading
if [ -e "$OUT/x.vtu" ]; then fail "failed boundary-grading runs wrote $OUT/x.vtu"; else pass; fi

# ---- --time-limit bounds the whole command ------------------------------------
OUT=$TMP/tlimit
mkdir -p "$OUT"
expect_exit 0 "triangulate --help: time limit" "$CLI" triangulate --help
expect_grep "triangulate --help: time limit" "$TMP/out" "--time-limit bounds the whole command"
if "$PY" "$HERE/../bench/hole_grid.py" 30 "$OUT/grid.poly"; then
    # a stopped triangulation writes nothing and says where it stopped
    expect_exit 1 "triangulate stopped by --time-limit" "$CLI" triangulate "$OUT/grid.poly" \
        --time-limit 0.000001 -o "$OUT/t.vtu"
    expect_one_line "triangulate stopped by --time-limit"
    expect_grep "triangulate stopped by --time-limit" "$TMP/err" "time limit reached"
    if [ ! -e "$OUT/t.vtu" ]; then pass; else fail "a stopped triangulation wrote t.vtu"; fi
    expect_exit 0 "the hole grid in time" "$CLI" triangulate "$OUT/grid.poly" --time-limit 600 \
        -o "$OUT/g.vtu"
    expect_exit 0 "the hole grid's mesh reads back" "$CLI" triangulate "$OUT/g.vtu" -o "$OUT/g2.vtu"
    if cmp -s "$OUT/g.vtu" "$OUT/g2.vtu"; then pass; else fail "the hole grid's .vtu rewrites differently"; fi
else
    fail "hole_grid.py could not write the hole grid"
fi
# a stopped refinement writes its valid mesh and says so
expect_exit 0 "refine stopped by --time-limit" "$CLI" refine "$DOMAINS/square.poly" --size 0.01 \
    --time-limit 0.000001 -o "$OUT/r.vtu"
expect_grep "refine stopped by --time-limit" "$TMP/err" "reached the time limit"
expect_exit 0 "a stopped refinement reads back" "$CLI" triangulate "$OUT/r.vtu" -o "$OUT/r2.vtu"

# ---- optimise a .vtu mesh read back, with its dual ---------------------------
OUT=$TMP/optvtu
mkdir -p "$OUT"
expect_exit 0 "refine to .vtu" "$CLI" refine "$DOMAINS/square.poly" --algo frontal --size 0.1 -o "$OUT/sq.vtu"
expect_exit 0 "optimise a .vtu" "$CLI" optimise "$OUT/sq.vtu" --time-limit 60 -o "$OUT/opt.vtu" \
    --dual "$OUT/dual.vtu" --quality
expect_grep "optimise .vtu: compliant" "$TMP/out" "non-compliant (not merged)   0.0000 %"
expect_grep "optimise .vtu: dual cells written" "$OUT/dual.vtu" "<VTKFile"
expect_exit 0 "optimised .vtu reads back" "$CLI" refine "$OUT/opt.vtu" --quality -o "$OUT/again.vtu"

# ---- refine --algo aflr: layers in the outputs, --fronts ---------------------
OUT=$TMP/aflr
mkdir "$OUT"
expect_exit 0 "refine --help" "$CLI" refine --help
expect_grep "refine --help" "$TMP/out" "--fronts M1,M2,..."
expect_exit 0 "refine --algo aflr" "$CLI" refine "$DOMAINS/naca0012.poly" --algo aflr --size 0.5 \
    --fronts 1,2 -o "$OUT/naca.vtu" --svg "$OUT/naca.svg" --quality
expect_grep "aflr report" "$TMP/out" "triangles below the angle: 0"
expect_grep "aflr .vtu layers" "$OUT/naca.vtu" 'Name="layer_index"'
expect_grep "aflr .svg layers" "$OUT/naca.svg" "advancing-front layer"
expect_exit 0 "refine --algo aflr to .node" "$CLI" refine "$DOMAINS/channel.poly" --algo aflr \
    --size 0.1 -o "$OUT/channel.node"
if [ "$HAVE_NUMPY" -eq 1 ]; then
    if "$PY" "$VERIFY" "$DOMAINS/channel.poly" "$OUT/channel" > "$OUT/verify.json" 2>&1; then
        pass
    else
        fail "aflr channel: verify_mesh.py: $(tail -c 400 "$OUT/verify.json")"
    fi
fi
expect_exit 2 "--fronts not a list" "$CLI" refine "$DOMAINS/square.poly" --algo aflr --fronts 1,x
expect_grep "--fronts not a list" "$TMP/err" "--fronts 1,x"
expect_exit 2 "--fronts without a value" "$CLI" refine "$DOMAINS/square.poly" --algo aflr --fronts

# ---- refine --resample-boundary (CVM_OPT_KEEP_SEGMENT_VERTICES = 0) ------------
OUT=$TMP/resample
mkdir "$OUT"
expect_exit 0 "refine --help lists --resample-boundary" "$CLI" refine --help
expect_grep "refine --help lists --resample-boundary" "$TMP/out" "--resample-boundary"
expect_exit 0 "refine --resample-boundary" "$CLI" refine "$DOMAINS/annulus.poly" --algo frontal \
    --size 0.3 --resample-boundary --quality -o "$OUT/annulus.vtu"
expect_grep "--resample-boundary meets the angle" "$TMP/out" "triangles below the angle: 0"
# 192 input segments (spacing 0.1 and 0.2) become 21 + 84 pieces of about 0.3
expect_grep "--resample-boundary re-discretises the circles" "$TMP/out" "segments                     105"
rm -f "$OUT/plain.vtu"
expect_exit 1 "--resample-boundary without a size is refused" "$CLI" refine \
    "$DOMAINS/annulus.poly" --resample-boundary --quality -o "$OUT/plain.vtu"
expect_grep "--resample-boundary without a size names the option" "$TMP/err" "KEEP_SEGMENT_VERTICES"
expect_one_line "--resample-boundary without a size"
if [ -e "$OUT/plain.vtu" ]; then fail "--resample-boundary without a size wrote a file"; else pass; fi

# ---- refine --smooth-layers (CVM_OPT_AFLR_SMOOTH_LAYERS) ------------------------
OUT=$TMP/smoothlayers
mkdir "$OUT"
expect_exit 0 "refine --help lists --smooth-layers" "$CLI" refine --help
expect_grep "refine --help lists --smooth-layers" "$TMP/out" "--smooth-layers N"
expect_exit 0 "refine --algo aflr --smooth-layers 2" "$CLI" refine "$DOMAINS/naca0012.poly" \
    --algo aflr --size 0.5 --smooth-layers 2 --quality -o "$OUT/naca.node"
expect_grep "--smooth-layers meets the angle" "$TMP/out" "triangles below the angle: 0"
expect_exit 0 "refine --algo aflr without --smooth-layers" "$CLI" refine "$DOMAINS/naca0012.poly" \
    --algo aflr --size 0.5 -o "$OUT/plain.node"
if cmp -s "$OUT/naca.node" "$OUT/plain.node"; then
    fail "--smooth-layers 2 gave the same points as without it"
else
    pass
fi
if [ "$HAVE_NUMPY" -eq 1 ]; then
    if "$PY" "$VERIFY" "$DOMAINS/naca0012.poly" "$OUT/naca" > "$OUT/verify.json" 2>&1; then
        pass
    else
        fail "--smooth-layers: verify_mesh.py: $(tail -c 400 "$OUT/verify.json")"
    fi
fi
rm -f "$OUT/frontal.vtu"
expect_exit 1 "--smooth-layers with frontal is refused" "$CLI" refine "$DOMAINS/square.poly" \
    --algo frontal --size 0.2 --smooth-layers 1 -o "$OUT/frontal.vtu"
expect_grep "--smooth-layers with frontal names the option" "$TMP/err" "AFLR_SMOOTH_LAYERS"
expect_one_line "--smooth-layers with frontal"
if [ -e "$OUT/frontal.vtu" ]; then fail "--smooth-layers with frontal wrote a file"; else pass; fi
expect_exit 2 "--smooth-layers out of range" "$CLI" refine "$DOMAINS/square.poly" --algo aflr \
    --smooth-layers -1 -o "$OUT/x.vtu"

# ---- the outputs of a command are one set: a failure changes no file --------
OUT=$TMP/atomic
mkdir "$OUT"
# expect_same DESC FILE TEXT : FILE holds exactly the line TEXT.
expect_same() {
    if [ -f "$2" ] && [ "$(cat "$2")" = "$3" ]; then pass; else fail "$1: $(basename "$2") was changed or removed"; fi
}
expect_no_tmp() {
    if ls -A "$2" | grep -q '\.tmp\.'; then fail "$1: temporary files left: $(ls -A "$2" | tr '\n' ' ')"; else pass; fi
}
expect_exit 1 "refine: the picture fails after the mesh" "$CLI" refine "$DOMAINS/square.poly" --size 0.3 \
    -o "$OUT/keep.vtu" --svg "$OUT/no/such/p.svg"
expect_one_line "refine: the picture fails after the mesh"
if [ -e "$OUT/keep.vtu" ]; then fail "refine: a failed --svg left the new mesh"; else pass; fi
printf 'old mesh\n' > "$OUT/tkeep.vtu"
expect_exit 1 "triangulate: the picture fails after the mesh" "$CLI" triangulate "$DOMAINS/square.poly" \
    -o "$OUT/tkeep.vtu" --svg "$OUT/no/such/t.svg"
expect_same "triangulate: a failed --svg keeps the old mesh" "$OUT/tkeep.vtu" "old mesh"
if [ -e /dev/full ]; then
    ln -s /dev/full "$OUT/full.svg"
    expect_exit 1 "refine: the picture fills the disk" "$CLI" refine "$DOMAINS/square.poly" --size 0.3 \
        -o "$OUT/tkeep.vtu" --svg "$OUT/full.svg"
    expect_same "refine: a full disk for --svg keeps the old mesh" "$OUT/tkeep.vtu" "old mesh"
    rm -f "$OUT/full.svg"
fi
printf 'old picture\n' > "$OUT/d.svg"
printf 'plain file\n' > "$OUT/plain"
expect_exit 1 "optimise: the dual fails after the mesh" "$CLI" optimise "$DOMAINS/square.poly" \
    -o "$OUT/tkeep.vtu" --dual "$OUT/plain/d.vtu"
expect_same "optimise: a failed --dual keeps the old mesh" "$OUT/tkeep.vtu" "old mesh"
expect_exit 1 "triangulate: the dual fails after mesh and picture" "$CLI" triangulate \
    "$DOMAINS/square.poly" -o "$OUT/tkeep.vtu" --svg "$OUT/d.svg" --dual "$OUT/plain/d.vtu"
expect_grep "the dual fails: says --dual" "$TMP/err" "--dual"
expect_same "a failed --dual keeps the old mesh" "$OUT/tkeep.vtu" "old mesh"
expect_same "a failed --dual keeps the old picture" "$OUT/d.svg" "old picture"
# .node writes three files: one that cannot be replaced (a directory in its
# place, which fails for root too) leaves the other two as they were
printf 'old node\n' > "$OUT/imm.node"
printf 'old edge\n' > "$OUT/imm.edge"
mkdir "$OUT/imm.ele"
expect_exit 1 ".node: .ele cannot be written" "$CLI" triangulate "$DOMAINS/square.poly" -o "$OUT/imm.node"
expect_one_line ".node: .ele cannot be written"
expect_same ".node: a failed .ele keeps the old .node" "$OUT/imm.node" "old node"
expect_same ".node: a failed .ele keeps the old .edge" "$OUT/imm.edge" "old edge"
expect_no_tmp "failed sets" "$OUT"
# a successful set replaces every file
expect_exit 0 "triangulate: mesh, picture and dual" "$CLI" triangulate "$DOMAINS/square.poly" \
    -o "$OUT/tkeep.vtu" --svg "$OUT/d.svg" --dual "$OUT/dual.vtu"
expect_grep "the set replaced the mesh" "$OUT/tkeep.vtu" "<VTKFile"
expect_grep "the set replaced the picture" "$OUT/d.svg" "<svg "
expect_grep "the set wrote the dual" "$OUT/dual.vtu" "<VTKFile"
expect_no_tmp "successful set" "$OUT"

# ---- overwriting keeps a file's permissions; new files follow the umask -----
OUT=$TMP/perm
mkdir "$OUT"
printf 'old\n' > "$OUT/p.vtu"
chmod 600 "$OUT/p.vtu"
printf 'old\n' > "$OUT/q.node"
chmod 640 "$OUT/q.node"
expect_exit 0 "overwrite a 0600 file" "$CLI" triangulate "$DOMAINS/square.poly" -o "$OUT/p.vtu"
expect_exit 0 "overwrite a 0640 .node" "$CLI" triangulate "$DOMAINS/square.poly" -o "$OUT/q.node"
mode_of() { ls -l "$1" | cut -c1-10; }
if [ "$(mode_of "$OUT/p.vtu")" = "-rw-------" ]; then pass; else fail "0600 file became $(mode_of "$OUT/p.vtu")"; fi
if [ "$(mode_of "$OUT/q.node")" = "-rw-r-----" ]; then pass; else fail "0640 .node became $(mode_of "$OUT/q.node")"; fi
(umask 027 && "$CLI" triangulate "$DOMAINS/square.poly" -o "$OUT/new.vtu") > /dev/null 2>&1
if [ "$(mode_of "$OUT/new.vtu")" = "-rw-r-----" ]; then pass; else fail "new file under umask 027 is $(mode_of "$OUT/new.vtu")"; fi
(umask 022 && "$CLI" triangulate "$DOMAINS/square.poly" -o "$OUT/new2.vtu") > /dev/null 2>&1
if [ "$(mode_of "$OUT/new2.vtu")" = "-rw-r--r--" ]; then pass; else fail "new file under umask 022 is $(mode_of "$OUT/new2.vtu")"; fi

# ---- SIGINT / SIGTERM: exit 128 + N, one line, every file as it was ---------
# 300k random points: the write of .node/.ele/.edge (tens of MB) takes long
# enough to be caught in the act. A shell without job control starts background
# commands with SIGINT ignored (and cvmesh keeps it so); env --default-signal
# (coreutils 8.31) undoes that for the SIGINT runs.
OUT=$TMP/signal
mkdir "$OUT"
awk 'BEGIN { n = 300000; srand(7); print n, 2, 0, 0
             for (i = 0; i < n; i++) printf "%d %.9f %.9f\n", i, rand(), rand() }' > "$TMP/big.node"
# signal_run DESC SIG CODE WHEN CMD... : run CMD in the background; send SIG as
# soon as a temporary file exists (WHEN = tmp: during the write) or after WHEN
# seconds (any phase); expect exit CODE, one "interrupted" line, and $OUT as it was.
signal_run() {
    desc=$1; sig=$2; code=$3; when=$4; shift 4
    rm -rf "$OUT" && mkdir "$OUT"
    printf 'old node\n' > "$OUT/s.node"
    set +e
    "$@" > "$TMP/out" 2> "$TMP/err" &
    pid=$!
    if [ "$when" = tmp ]; then
        i=0
        while [ $i -lt 6000 ] && kill -0 $pid 2> /dev/null && ! ls -A "$OUT" | grep -q '\.tmp\.'; do
            sleep 0.01; i=$((i + 1))
        done
    else
        sleep "$when"
    fi
    kill -s "$sig" $pid
    wait $pid
    got=$?
    set -e
    if [ "$got" -eq "$code" ]; then pass; else fail "$desc: exit $got, expected $code: $(head -c 300 "$TMP/err")"; fi
    expect_one_line "$desc"
    expect_grep "$desc" "$TMP/err" "interrupted by SIG$sig while"
    expect_same "$desc: the old file" "$OUT/s.node" "old node"
    if [ "$(ls -A "$OUT")" = "s.node" ]; then pass; else fail "$desc: files left: $(ls -A "$OUT" | tr '\n' ' ')"; fi
}
signal_run "SIGTERM writing .node" TERM 143 tmp "$CLI" triangulate "$TMP/big.node" -o "$OUT/s.node"
expect_grep "SIGTERM during the write names it" "$TMP/err" "while writing $OUT/s.node"
signal_run "SIGTERM triangulating" TERM 143 0.2 "$CLI" triangulate "$TMP/big.node" -o "$OUT/s.node" --svg "$OUT/s.svg"
signal_run "SIGTERM refining" TERM 143 0.5 "$CLI" refine "$DOMAINS/square.poly" --size 0.001 -o "$OUT/s.node"
if env --default-signal=INT true > /dev/null 2>&1; then
    signal_run "SIGINT writing .node" INT 130 tmp env --default-signal=INT "$CLI" triangulate "$TMP/big.node" -o "$OUT/s.node"
    expect_grep "SIGINT during the write names it" "$TMP/err" "while writing $OUT/s.node"
    signal_run "SIGINT triangulating" INT 130 0.2 env --default-signal=INT "$CLI" triangulate "$TMP/big.node" -o "$OUT/s.node"
else
    echo "note: env --default-signal is missing: the SIGINT runs are skipped"
fi
rm -f "$TMP/big.node"

# ---- interoperability with meshio, VTK and Gmsh, both ways (tests/cli/interop.py) --
if "$PY" "$HERE/interop.py" "$CLI" "$TMP/interop" > "$TMP/interop.log" 2>&1; then pass
else fail "interop.py: $(grep -E '^FAIL|Error' "$TMP/interop.log" | head -n 5)"; fi

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
