#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Builds the libFuzzer target with clang (ASan + UBSan) in build-fuzz/ and runs it.
#   fuzz/run.sh [SECONDS]   (default 60); extra libFuzzer flags in FUZZ_FLAGS
# The corpus is fuzz/corpus (kept between runs, not in git), seeded on every run from examples/,
# tests/seeds and fuzz/seeds. Crashes go to fuzz/crashes/. Runs under `nice -n 19`.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
LAGRANGE_WITH_FUZZ=1 LAGRANGE_SETUP_ONLY=1 scripts/setup.sh
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}"
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DLAGRANGE_FUZZ=ON -DLAGRANGE_SANITIZE=ON -DLAGRANGE_BUILD_TESTS=OFF -DLAGRANGE_BUILD_BENCH=OFF \
  "${launcher[@]}" >/dev/null
nice -n 19 cmake --build build-fuzz -j "${FUZZ_JOBS:-2}" --target lagrange_fuzz >/dev/null

mkdir -p fuzz/corpus fuzz/crashes
# the seeds join the corpus on every run (new seeds too), never overwriting what is there
for seed in examples/*.lag fuzz/seeds/*.lag; do
  [ -e "fuzz/corpus/$(basename "$seed")" ] || cp "$seed" fuzz/corpus/
done
# Short allocation stacks: GiNaC allocates constantly, and deep stacks slow ASan down 2x.
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=1:malloc_context_size=5}"
export LSAN_OPTIONS="suppressions=$PWD/scripts/sanitizers/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="suppressions=$PWD/scripts/sanitizers/ubsan.supp:print_stacktrace=1:halt_on_error=1"
# -timeout=20: an input that runs longer is a hang. The budgets' cooperative checks run
# between GiNaC calls, and one call (a symbolic solve of a rolling coin's 7 × 7 system with
# its constants changed) can take seconds under ASan on a shared machine; in the program
# the watchdog ends such a call at --max-seconds. -rss_limit_mb: swell is a bug too.
exec nice -n 19 build-fuzz/fuzz/lagrange_fuzz -timeout=20 -rss_limit_mb=2048 -max_len=4096 \
  -max_total_time="$seconds" -print_final_stats=1 -artifact_prefix=fuzz/crashes/ \
  -dict=fuzz/scene.dict ${FUZZ_FLAGS:-} fuzz/corpus
