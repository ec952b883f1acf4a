#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Builds the libFuzzer target with clang (ASan + UBSan) in build-fuzz/ and runs it.
#   fuzz/run.sh [SECONDS]   (default 60); extra libFuzzer flags in FUZZ_FLAGS
# The corpus is fuzz/corpus (kept between runs, not in git), seeded on every run from examples/,
# tests/seeds and fuzz/seeds. Crashes go to fuzz/crashes/. Runs under `nice -n 19`.
# An input over libFuzzer's -timeout is a hang only if the program's watchdog does not end it:
# each one is run again with the watchdog on (see the last step).
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
# -fork=1: the fuzzing runs in a child process, so that an input over -timeout=20 ends that
# child, not the run. One GiNaC call (a symbolic solve of a rolling coin's 7 × 7 system with
# an odd constant in it) can take minutes and no cooperative budget check interrupts it; the
# program's watchdog ends it at --max-seconds (start_budget_watchdog), which this target, being
# a library call, starts only when asked (below). -rss_limit_mb: swell is a bug too.
marker="$(mktemp)" log="$(mktemp)"
trap 'rm -f "$marker" "$log"' EXIT
status=0
nice -n 19 build-fuzz/fuzz/lagrange_fuzz -fork=1 -ignore_timeouts=1 -ignore_ooms=0 -ignore_crashes=0 \
  -timeout=20 -rss_limit_mb=2048 -max_len=4096 -max_total_time="$seconds" -print_final_stats=1 \
  -artifact_prefix=fuzz/crashes/ -dict=fuzz/scene.dict ${FUZZ_FLAGS:-} fuzz/corpus || status=$?
found="$(find fuzz/crashes -maxdepth 1 -type f -newer "$marker" | sort)"
# In fork mode libFuzzer ends with the last child's code: 0, or 70 when that child ran over
# -timeout. Any artefact other than a timeout is a failure; each input over -timeout, run
# alone with the watchdog on (LAGRANGE_FUZZ_WATCHDOG), must end within 60 s: normally (0) or
# by the watchdog (3), with no sanitizer report.
if { [ "$status" -ne 0 ] && [ "$status" -ne 70 ]; } || grep -qv -e '/timeout-' -e '^$' <<<"$found"; then
  echo "fuzz: failed (exit $status); inputs in fuzz/crashes/" >&2
  exit $((status == 0 ? 1 : status))
fi
[ -z "$found" ] && exit 0
while read -r input; do
  code=0
  LAGRANGE_FUZZ_WATCHDOG=1 timeout 60 build-fuzz/fuzz/lagrange_fuzz "$input" >"$log" 2>&1 || code=$?
  if [ "$code" -ne 0 ] && [ "$code" -ne 3 ]; then
    echo "fuzz: $input ran over -timeout, and not in a step the watchdog ends (exit $code):" >&2
    tail -n 20 "$log" >&2
    exit 1
  fi
  echo "fuzz: $input ran over -timeout; with the watchdog it ends (exit $code): $(grep -m1 '^fuzz: ' "$log" || echo 'within the time')"
done <<<"$found"
