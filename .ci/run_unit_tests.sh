#!/bin/sh
# run_unit_tests.sh BIN LOG [JOBS] - run each suite of the unit-test program BIN
# in its own process, JOBS (default 2) at a time, slowest first; LOG gets every
# suite's output in BIN --list order, then a total line in Check's format
# ("100%: Checks: N, Failures: 0, Errors: 0"), which is also printed. Exit
# status 0 only if every suite passed. Tests that CVMTEST_SKIP (tests/unit/support/skip.h)
# are counted and listed: a skip is loud, never silent. The environment (CK_*, ASAN_OPTIONS,
# CVM_* data folders) passes through to every suite.
set -u
bin=$1
log=$2
jobs=${3:-2}
dir=$(mktemp -d "${TMPDIR:-/tmp}/cvm_unit.XXXXXX") || exit 1
trap 'rm -rf "$dir"' EXIT
trap 'exit 130' INT
trap 'exit 143' TERM
suites=$("$bin" --list) || { echo "run_unit_tests: $bin --list failed"; exit 1; }
# The slowest suites (measured) start first so that none of them ends last alone;
# the others follow in list order.
slow="generate3 quad delaunay3 api io geom refine"
order=
for s in $slow; do
    case " $(echo $suites) " in *" $s "*) order="$order $s";; esac
done
for s in $suites; do
    case " $slow " in *" $s "*) ;; *) order="$order $s";; esac
done
start=$(date +%s)
printf '%s\n' $order | xargs -P "$jobs" -I{} sh -c \
    '"$1" "$3" > "$2/$3.out" 2>&1; echo $? > "$2/$3.rc"' sh "$bin" "$dir" {}
: > "$log"
checks=0 failures=0 errors=0 skipped=0 bad=
for s in $suites; do
    cat "$dir/$s.out" >> "$log"
    rc=$(cat "$dir/$s.rc" 2>/dev/null || echo 1)
    line=$(grep -E '^[0-9]+%: Checks: ' "$dir/$s.out" | tail -n 1)
    if [ -n "$line" ]; then
        set -- $(echo "$line" | sed 's/^[0-9]*%: Checks: \([0-9]*\), Failures: \([0-9]*\), Errors: \([0-9]*\).*/\1 \2 \3/')
        checks=$((checks + $1)) failures=$((failures + $2)) errors=$((errors + $3))
    fi
    n_skip=$(grep -c '^SKIP: ' "$dir/$s.out" || true)
    skipped=$((skipped + n_skip))
    if [ "$rc" != 0 ] || [ -z "$line" ]; then
        bad="$bad $s"
        cat "$dir/$s.out"
    fi
    echo "unit: $s: ${line:-no summary (exit $rc)}$( [ "$n_skip" = 0 ] || echo ", $n_skip skipped")"
done
pct=100
if [ "$checks" -gt 0 ]; then pct=$(( (checks - failures - errors) * 100 / checks )); fi
total="$pct%: Checks: $checks, Failures: $failures, Errors: $errors"
echo "$total" >> "$log"
if [ "$skipped" != 0 ]; then
    echo "unit: $skipped tests skipped (each passed as a check):"
    grep -h '^SKIP: ' "$dir"/*.out | sed 's/^/    /'
fi
echo "unit: $(echo $suites | wc -w) suites, $jobs at a time, $skipped skipped, $(( $(date +%s) - start )) s"
echo "$total"
if [ -n "$bad" ]; then
    echo "unit: failed:$bad"
    exit 1
fi
