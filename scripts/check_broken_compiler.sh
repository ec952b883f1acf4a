#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# The tests that need the C compiler cannot pass without one. Every test case tagged [cc]
# is run alone with a compiler that fails (LAGRANGE_CC=false): each must fail. Then the
# ctest tests labelled cc run with no compiler at all (LAGRANGE_CC=/nonexistent/cc): each
# must be reported as skipped.
#   scripts/check_broken_compiler.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=$(cd "${1:-build}" && pwd)
cases=0
passed=()
for exe in "$build"/tests/tests_*; do
    [ -x "$exe" ] || continue
    while IFS= read -r name; do
        [ -n "$name" ] || continue
        cases=$((cases + 1))
        # A name is one filter: its commas escaped (check_inventory.py forbids [ ] * ~ " \ ;).
        if LAGRANGE_CC=false "$exe" "${name//,/\\,}" >/dev/null 2>&1; then
            passed+=("$(basename "$exe"): $name")
        fi
    done < <("$exe" --list-test-names-only "[cc]" || true)
done
if [ "$cases" = 0 ]; then
    echo "check_broken_compiler: no test case is tagged [cc]" >&2
    exit 1
fi
if [ ${#passed[@]} -gt 0 ]; then
    printf 'check_broken_compiler: passed with LAGRANGE_CC=false: %s\n' "${passed[@]}" >&2
    exit 1
fi
log=$(cd "$build" && LAGRANGE_CC=/nonexistent/cc ctest -L '^cc$' 2>&1) || { echo "$log" >&2; exit 1; }
run=$(grep -cE 'Test +#' <<<"$log" || true)
skipped=$(grep -cE 'Test +#.*Skipped' <<<"$log" || true)
if [ "$run" = 0 ] || [ "$run" != "$skipped" ]; then
    echo "$log" >&2
    echo "check_broken_compiler: without a compiler, $skipped of $run cc tests were skipped" >&2
    exit 1
fi
echo "check_broken_compiler: $cases [cc] test cases each fail with a failing compiler; $run cc tests skipped without one"
