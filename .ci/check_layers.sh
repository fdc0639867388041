#!/bin/sh
# check_layers.sh - the library's folders keep their layering, and its files
# stay small enough to read:
#  1. a file under lib/ includes only its own folder and the layers below it:
#       common <- geom <- delaunay <- sizing <- {boundary, refine, dual};  geom <- delaunay3;
#       common <- geom <- surface3 (3D surface checks);  quad, delaunay3 <- generate3;  common <- geom <- dual3;  common <- geom <- tetgen (TetGen shim, C++);
#       io <- common;
#       api sees every engine (not cli);  cli sees only include/ (and itself).
#     The public headers (include/cvmesh*.h) are open to every layer.
#  2. no .c or .h file under lib/ passes MAX_LINES lines, unless
#     .ci/layers_allow.txt names it with its own bound (and a reason).
#  3. lib/api reaches the simplex store only through lib/api/store.h: no
#     other file of lib/api includes the kernel's store header, names the
#     handle's store (m->tri), its fields (T->nv, ...) or calls cvm__tri2_*.
# Usage: sh .ci/check_layers.sh   (from anywhere; exits 1 on the first report)
set -eu
cd "$(dirname "$0")/.."
MAX_LINES=800
allow=.ci/layers_allow.txt
fail=0

# The folders a layer may include from (its own is always allowed).
allowed() {
    case $1 in
    common) echo "" ;;
    geom) echo "common" ;;
    delaunay) echo "common geom" ;;
    delaunay3) echo "common geom" ;;
    sizing) echo "common geom delaunay" ;;
    boundary | refine | dual) echo "common geom delaunay sizing" ;;
    io) echo "common" ;;
    surface3) echo "common geom" ;;
    tetgen) echo "common geom" ;;
    quad) echo "common geom delaunay sizing refine" ;;
    generate3) echo "common geom delaunay delaunay3 sizing refine quad" ;;
    dual3) echo "common geom" ;;
    api) echo "common geom delaunay delaunay3 sizing boundary surface3 tetgen refine dual quad io generate3 dual3" ;;
    cli) echo "" ;;
    *) echo "?" ;;
    esac
}

for f in lib/*/*.c lib/*/*.cxx lib/*/*.h; do
    [ -f "$f" ] || continue
    layer=$(echo "$f" | cut -d/ -f2)
    ok=$(allowed "$layer")
    if [ "$ok" = "?" ]; then
        echo "check-layers: $f: folder lib/$layer has no layer in .ci/check_layers.sh"
        fail=1
        continue
    fi
    # quoted includes only: <...> are system headers
    for inc in $(sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"\([^"]*\)".*/\1/p' "$f"); do
        case $inc in
        cvmesh.h | cvmesh_experimental.h) continue ;; # include/: public
        *..*)
            echo "check-layers: $f: #include \"$inc\": name lib/ headers as folder/file.h, without .."
            fail=1
            continue ;;
        */*) to=$(echo "$inc" | cut -d/ -f1) ;;
        *)
            if [ -f "$(dirname "$f")/$inc" ]; then to=$layer; else
                echo "check-layers: $f: #include \"$inc\" names no file of lib/$layer or include/"
                fail=1
                continue
            fi ;;
        esac
        [ "$to" = "$layer" ] && continue
        case " $ok " in
        *" $to "*) ;;
        *)
            below=""
            [ -n "$ok" ] && below=$(echo " $ok" | sed 's| \([a-z]*\)|, lib/\1|g')
            echo "check-layers: $f includes \"$inc\": lib/$layer may include only" \
                "lib/$layer$below and include/"
            fail=1 ;;
        esac
    done
done

# Allow-list lines: PATH BOUND # reason. A listed file may not pass its bound;
# an entry whose file is gone or back under MAX_LINES must be removed.
bound_of() {
    sed -e 's/#.*//' "$allow" | awk -v f="$1" '$1 == f { print $2 }'
}
for f in lib/*/*.c lib/*/*.cxx lib/*/*.h; do
    [ -f "$f" ] || continue
    n=$(wc -l < "$f")
    b=$(bound_of "$f")
    if [ -n "$b" ]; then
        if [ "$n" -gt "$b" ]; then
            echo "check-layers: $f has $n lines, more than its allowance of $b in $allow: split it"
            fail=1
        fi
    elif [ "$n" -gt "$MAX_LINES" ]; then
        echo "check-layers: $f has $n lines (> $MAX_LINES): split it, or justify an entry in $allow"
        fail=1
    fi
done
for f in $(sed -e 's/#.*//' "$allow" | awk 'NF { print $1 }'); do
    if [ ! -f "$f" ] || [ "$(wc -l < "$f")" -le "$MAX_LINES" ]; then
        echo "check-layers: $allow: $f is gone or within $MAX_LINES lines: remove its entry"
        fail=1
    fi
done

# The store accessor (store.h, store2.c) is the only file of lib/api that
# touches the store.
store_re='#[[:space:]]*include[[:space:]]*"delaunay/tri2_store\.h"|\bm->tri\b|\bT->[a-z_]+|\bcvm__tri2_[a-z0-9_]+[[:space:]]*\('
for f in lib/api/*.c lib/api/*.h; do
    case $f in lib/api/store.h | lib/api/store2.c) continue ;; esac
    hits=$(grep -nE "$store_re" "$f" | head -3 || true)
    if [ -n "$hits" ]; then
        echo "check-layers: $f reaches into the simplex store; use lib/api/store.h:"
        echo "$hits" | sed 's/^/    /'
        fail=1
    fi
done

[ $fail = 0 ] && echo "check-layers: lib/ keeps its layers; every file within $MAX_LINES lines or allowed; lib/api uses the store through store.h"
exit $fail
