#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# `lagrange simulate` against a hand-written DOP853 loop (build/bench/hand_loop simulate,
# bench/hand_dop853.h) in the same run, at equal error: examples/double_pendulum.lag (M = 1,
# m = 0.01, l = 1, g = 9.81 from theta = 0, phi = 0.05 at rest, until t = 60, 1001 output times,
# the energy checked at each). lagrange runs REPEATS times (the fastest of each figure kept); the
# hand loop integrates at the tolerance of the run lagrange reports (`run_tolerance`, per step /12
# on both sides), keeping the same output times, and measures its error as simulate does, against
# itself at tolerance/1000. Prints the integration of the run reported beside the hand loop's (time,
# steps, error, energy drift, end state), then where the rest of the command's time goes: start-up
# (parse, Lagrangian, equations, the equations compiled or loaded, the linearization), all the
# integrations of the simulation stage (the run, its reference run, a tighter rerun and its
# reference), and the whole command's wall time.
#   bench/simulate_limit.sh [REPEATS]
set -euo pipefail
cd "$(dirname "$0")/.."
repeats=${1:-15}
build=${LAGRANGE_BUILD:-build}
[ -x "$build/lagrange" ] || scripts/setup.sh
[ -x "$build/bench/hand_loop" ] || cmake --build "$build" --target hand_loop
lagrange=$PWD/$build/lagrange
hand=$PWD/$build/bench/hand_loop
scene=$PWD/examples/double_pendulum.lag
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for k in $(seq "$repeats"); do
  start=$(date +%s.%N)
  "$lagrange" simulate "$scene" --format json --timings -o "$work/run$k.json"
  end=$(date +%s.%N)
  echo "$start $end" >"$work/wall$k"
  "$lagrange" simulate "$scene" --timings >"$work/run$k.txt"
done
tolerance=$(/usr/bin/python3 -c "import json, sys; print(repr(json.load(open(sys.argv[1]))['simulation']['run_tolerance']))" \
  "$work/run1.json")
"$hand" simulate "$tolerance" 60 1000 "$repeats" 1 0.01 1 9.81 0 0.05 >"$work/hand"
echo "double pendulum (examples/double_pendulum.lag), until t = 60, 1001 output times, $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg)"
echo
/usr/bin/python3 - "$work" "$repeats" <<'EOF'
import json, re, sys
work, repeats = sys.argv[1], int(sys.argv[2])
runs = [json.load(open(f"{work}/run{k}.json")) for k in range(1, repeats + 1)]
texts = [open(f"{work}/run{k}.txt").read() for k in range(1, repeats + 1)]
walls = [float(b) - float(a) for a, b in (open(f"{work}/wall{k}").read().split() for k in range(1, repeats + 1))]
hand = open(f"{work}/hand").read().split()
h_seconds, h_steps, h_error, h_drift = float(hand[0]), int(hand[1]), float(hand[2]), float(hand[3])
h_end = [float(v) for v in hand[4:8]]
s = runs[0]["simulation"]
assert all(r["simulation"]["steps"] == s["steps"] for r in runs), "the runs took other steps"
assert len(s["t"]) == 1001, "not 1001 output times"
seconds = min(r["simulation"]["seconds"] for r in runs)
end = [s["states"][k][-1] for k in ("theta", "phi", "theta_dot", "phi_dot")]
print(f"run reported: tolerance {s['run_tolerance']:.3g} (asked {s['tolerance']:.3g}; the first run's error "
      f"{s.get('missed_error', float('nan')):.3g} missed it), fastest of {repeats}")
print()
print("| integration of one run | s | steps | error | energy drift | time / hand loop |")
print("|---|---:|---:|---:|---:|---:|")
print(f"| lagrange simulate (the run reported) | {seconds:.6f} | {s['steps']} | {s['error_estimate']:.3g} | "
      f"{s['invariants']['energy_drift']:.3g} | {seconds / h_seconds:.2f} |")
print(f"| hand-written DOP853 loop | {h_seconds:.6f} | {h_steps} | {h_error:.3g} | {h_drift:.3g} | 1.00 |")
print()
print("end state, largest difference: %.2g (lagrange %s, hand loop %s)" % (
    max(abs(a - b) for a, b in zip(end, h_end)), ", ".join(f"{v:.12g}" for v in end),
    ", ".join(f"{v:.12g}" for v in h_end)))
def part(text, name):
    found = re.search(r"^    " + name + r" \(.*\): ([0-9.]+) s$", text, re.M)
    return float(found.group(1))
def fastest(values):
    return min(values)
timings = {k: fastest([r["timings"][k] for r in runs]) for k in runs[0]["timings"]}
preparation = fastest([part(t, "preparation") for t in texts])
integration = fastest([part(t, "integration") for t in texts])
runs_count = re.search(r"integration \((\d+) runs", texts[0]).group(1)
print()
print(f"| the whole command (fastest of {repeats} each) | s | / hand loop's run |")
print("|---|---:|---:|")
startup = timings["lagrangian"] + timings["equations"] + preparation
print(f"| start-up: Lagrangian + equations + preparation (compiled code loaded, linearization) | {startup:.6f} | {startup / h_seconds:.1f} |")
print(f"| simulation stage | {timings['simulation']:.6f} | {timings['simulation'] / h_seconds:.1f} |")
print(f"| of it, integration ({runs_count} runs) | {integration:.6f} | {integration / h_seconds:.1f} |")
print(f"| verification stage | {timings['verification']:.6f} | {timings['verification'] / h_seconds:.1f} |")
print(f"| whole command, wall time (process start and output included) | {fastest(walls):.6f} | {fastest(walls) / h_seconds:.1f} |")
EOF
