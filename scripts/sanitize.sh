#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# The test suite under AddressSanitizer + UndefinedBehaviorSanitizer (and LeakSanitizer):
# builds build-asan/ with -DLAGRANGE_SANITIZE=ON (clang++), then runs ctest there.
#   scripts/sanitize.sh [ctest arguments]    e.g. scripts/sanitize.sh -LE 'slow|install'
# Any sanitizer report fails the run (halt_on_error; the CLI's exit code changes).
# Suppressions: scripts/sanitizers/*.supp (CLN's static tables, a shift idiom in CLN's header).
set -euo pipefail
cd "$(dirname "$0")/.."
LAGRANGE_WITH_FUZZ=1 LAGRANGE_SETUP_ONLY=1 scripts/setup.sh
# ccache, when installed: paths relative to the checkout, so that a clone elsewhere (CI) hits too.
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}"
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER="${CXX:-clang++}" \
  -DLAGRANGE_SANITIZE=ON -DLAGRANGE_BUILD_BENCH=OFF "${launcher[@]}" >&2
# The suppressions apply to the build too: it runs lagrange_tests to list its tests.
export LAGRANGE_TEST_TIME_SCALE=10 # the CLI tests' time limits: sanitized code is slower
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:malloc_context_size=10"
export LSAN_OPTIONS="suppressions=$PWD/scripts/sanitizers/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="suppressions=$PWD/scripts/sanitizers/ubsan.supp:print_stacktrace=1:halt_on_error=1"
cmake --build build-asan -j "$(nproc)" --target lagrange_tests lagrange_cli >&2
cd build-asan
ctest --output-on-failure -j "$(nproc)" "$@"
