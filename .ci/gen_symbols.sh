#!/bin/sh
# gen_symbols.sh [HEADER] - print, sorted, the name of every function the
# public header declares with CVM_API: the list .ci/exported_symbols.txt must
# equal. Regenerate the committed list after an intended API change with
#   sh .ci/gen_symbols.sh > .ci/exported_symbols.txt
# A declaration is a line starting with "CVM_API"; the name is the identifier
# right before its first "(" (declarations may continue on later lines).
set -eu
header=${1:-include/cvmesh.h}
[ -r "$header" ] || { echo "gen_symbols: cannot read $header" >&2; exit 2; }
sed -n 's/^CVM_API[^(]*[ *]\([A-Za-z_][A-Za-z0-9_]*\)[ ]*(.*/\1/p' "$header" | LC_ALL=C sort -u
