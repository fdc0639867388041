#!/bin/sh
# check_symbols.sh SHARED_LIB LIST [HEADER] - the exported-symbol (ABI) check.
#  1. every dynamic symbol the shared library defines starts with cvm_;
#  2. the library's sorted symbol list equals LIST (.ci/exported_symbols.txt):
#     a symbol in LIST but not exported was removed or renamed (an ABI break),
#     an exported symbol not in LIST must be added to LIST;
#  3. LIST equals the CVM_API declarations of the public header (gen_symbols.sh),
#     so header, library and list agree both ways.
set -eu
lib=${1:?usage: check_symbols.sh SHARED_LIB LIST [HEADER]}
list=${2:?usage: check_symbols.sh SHARED_LIB LIST [HEADER]}
header=${3:-include/cvmesh.h}
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0

[ -r "$lib" ] || { echo "check_symbols: cannot read $lib" >&2; exit 2; }
[ -r "$list" ] || { echo "check_symbols: cannot read $list" >&2; exit 2; }

nm -D --defined-only "$lib" | awk 'NF >= 3 { print $3 }' | sed 's/@.*//' | LC_ALL=C sort -u > "$tmp/lib"
LC_ALL=C sort -u "$list" | sed '/^$/d' > "$tmp/list"
sh "$here/gen_symbols.sh" "$header" > "$tmp/header"

bad=$(grep -v '^cvm_' "$tmp/lib" || true)
if [ -n "$bad" ]; then
    echo "check_symbols: $lib exports symbols without the cvm_ prefix (give them static or hidden linkage):"
    echo "$bad" | sed 's/^/  /'
    fail=1
fi

removed=$(LC_ALL=C comm -23 "$tmp/list" "$tmp/lib")
if [ -n "$removed" ]; then
    echo "check_symbols: symbols in $list are not exported by $lib (removed or renamed: an ABI break):"
    echo "$removed" | sed 's/^/  /'
    fail=1
fi
added=$(LC_ALL=C comm -13 "$tmp/list" "$tmp/lib" | grep '^cvm_' || true)
if [ -n "$added" ]; then
    echo "check_symbols: $lib exports new symbols; if intended, add them to $list:"
    echo "$added" | sed 's/^/  /'
    fail=1
fi

hdr_only=$(LC_ALL=C comm -23 "$tmp/header" "$tmp/list")
if [ -n "$hdr_only" ]; then
    echo "check_symbols: $header declares functions missing from $list; add them to $list"
    echo "  (sh .ci/gen_symbols.sh > $list):"
    echo "$hdr_only" | sed 's/^/  /'
    fail=1
fi
list_only=$(LC_ALL=C comm -13 "$tmp/header" "$tmp/list")
if [ -n "$list_only" ]; then
    echo "check_symbols: $list names functions $header no longer declares (removed or renamed: an ABI break):"
    echo "$list_only" | sed 's/^/  /'
    fail=1
fi

if [ "$fail" = 0 ]; then
    echo "check_symbols: $(wc -l < "$tmp/lib" | tr -d ' ') exported symbols match $list"
fi
exit "$fail"
