#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# The cost of self-verification on the examples: for each scene, the wall time of
# `lagrange EX --format json --timings` and the time of its `verification` stage (from
# the JSON's `timings`), medians of N runs (default 5), and the stage's share of the
# rest of the run (the run with verification switched off). The engine has no switch
# to turn verification off, so the stage's own time stands for the difference.
#   bench/verification_overhead.sh [runs] [examples...]
# Prints a Markdown table (docs/benchmarks.md, "Verification overhead").
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-5}
shift || true
build=${LAGRANGE_BUILD:-build}
[ -x "$build/lagrange" ] || scripts/setup.sh
if [ $# -gt 0 ]; then scenes=("$@"); else scenes=(examples/*.lag); fi
/usr/bin/python3 - "$build/lagrange" "$runs" "${scenes[@]}" <<'PY'
import json, os, statistics, subprocess, sys, time
binary, runs, scenes = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
print("| example | run (ms) | verification (ms) | overhead | fastest run (ms) | fastest verification (ms) | overhead of the fastest | checked |")
print("|---|---:|---:|---:|---:|---:|---:|---|")
over = []
for scene in scenes:
    walls, stages, items = [], [], []
    for _ in range(runs):
        start = time.perf_counter()
        out = subprocess.run([binary, scene, "--format", "json", "--timings"], capture_output=True, text=True)
        walls.append(time.perf_counter() - start)
        doc = json.loads(out.stdout) if out.returncode == 0 else {}
        stages.append(doc.get("timings", {}).get("verification", 0.0))
        items = sorted(doc.get("verification", {}).keys())
    wall, stage = statistics.median(walls), statistics.median(stages)
    share = stage / (wall - stage)
    fastest = min(stages) / (min(walls) - min(stages))
    name = os.path.basename(scene)
    print(f"| {name} | {1000 * wall:.1f} | {1000 * stage:.2f} | {100 * share:.1f}% | {1000 * min(walls):.1f} | "
          f"{1000 * min(stages):.2f} | {100 * fastest:.1f}% | {', '.join(items)} |")
    if share > 0.10:
        over.append(f"{name} ({100 * share:.0f}%)")
print()
print(f"{runs} runs each; overhead = verification / (run - verification), of the medians and of the fastest; "
      f"median above 10%: {', '.join(over) if over else 'none'}")
PY
