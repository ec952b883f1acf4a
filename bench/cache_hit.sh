#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# The cost of a hit in the cache of compiled equations (lib/system/cache.h): warm runs of
# one scene (default: `simulate examples/double_pendulum.lag`) by each binary named, each
# with a private cache folder filled by one run first, the binaries taking turns run by
# run; also one binary's cold runs (LAGRANGE_CACHE=0: compiled every time) for scale.
# Prints the medians and minima of the wall time and of the `simulation` stage (--timings),
# which holds the compile or the cache's lookup and load; and the start alone (--version).
#   bench/cache_hit.sh [runs] [binary...]     (default: 20 runs of $LAGRANGE_BUILD/lagrange)
#   LAGRANGE_BENCH_ARGS="simulate examples/triple_pendulum.lag" bench/cache_hit.sh 20 old/lagrange build/lagrange
# Prints a Markdown table (docs/benchmarks.md, "Cache hits").
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-20}
shift || true
build=${LAGRANGE_BUILD:-build}
if [ $# -gt 0 ]; then binaries=("$@"); else binaries=("$build/lagrange"); fi
args=${LAGRANGE_BENCH_ARGS:-simulate examples/double_pendulum.lag}
/usr/bin/python3 - "$runs" "$args" "${binaries[@]}" <<'PY'
import os, re, shutil, statistics, subprocess, sys, tempfile, time
runs, args, binaries = int(sys.argv[1]), sys.argv[2].split(), sys.argv[3:]

def run(binary, cache, cold=False):
    env = dict(os.environ, XDG_CACHE_HOME=cache)
    env.pop("LAGRANGE_CC", None)
    if cold:
        env["LAGRANGE_CACHE"] = "0"
    else:
        env.pop("LAGRANGE_CACHE", None)
    start = time.perf_counter()
    out = subprocess.run([binary] + args + ["--timings"], capture_output=True, text=True, env=env)
    wall = time.perf_counter() - start
    if out.returncode != 0 or "evaluation: interpreted" in out.stdout:
        sys.exit(f"{binary}: exit {out.returncode}, or not native:\n{out.stdout[-400:]}{out.stderr[-400:]}")
    stage = re.search(r"^\s*simulation: ([0-9.e+-]+) s", out.stdout, re.M)
    return wall, float(stage.group(1)) if stage else float("nan")

caches = [tempfile.mkdtemp(prefix="lagrange-cache-bench-") for _ in binaries]
try:
    for binary, cache in zip(binaries, caches):
        run(binary, cache)  # fills the cache
    warm = {b: [] for b in binaries}
    for _ in range(runs):
        for binary, cache in zip(binaries, caches):
            warm[binary].append(run(binary, cache))
    cold = [run(binaries[-1], caches[-1], cold=True) for _ in range(max(3, runs // 5))]
    # The start alone (--version: the re-exec with a fixed address layout, the shared libraries).
    start = {b: [] for b in binaries}
    for _ in range(runs):
        for binary in binaries:
            t = time.perf_counter()
            subprocess.run([binary, "--version"], capture_output=True)
            start[binary].append(time.perf_counter() - t)
finally:
    for cache in caches:
        shutil.rmtree(cache, ignore_errors=True)

def row(name, samples):
    walls, stages = [s[0] for s in samples], [s[1] for s in samples]
    return (f"| {name} | {len(samples)} | {1000 * statistics.median(walls):.1f} | {1000 * min(walls):.1f} | "
            f"{1000 * statistics.median(stages):.2f} | {1000 * min(stages):.2f} |")

print(f"`lagrange {' '.join(args)}`")
print()
print("| binary | runs | wall, median (ms) | wall, fastest (ms) | simulation stage, median (ms) | simulation stage, fastest (ms) |")
print("|---|---:|---:|---:|---:|---:|")
for binary in binaries:
    print(row(f"{binary} (warm: cache hit)", warm[binary]))
print(row(f"{binaries[-1]} (cold: LAGRANGE_CACHE=0)", cold))
print()
print("| binary | `--version`, median (ms) | `--version`, fastest (ms) |")
print("|---|---:|---:|")
for binary in binaries:
    print(f"| {binary} | {1000 * statistics.median(start[binary]):.2f} | {1000 * min(start[binary]):.2f} |")
PY
