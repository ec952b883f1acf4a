#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Ensemble throughput against threads and MPI processes: the flip-time map of the equal-mass
# double pendulum (tests/scenes/ensemble_double_pendulum.lag) over a COUNT x COUNT grid until
# t = UNTIL, run with 1…T threads in one process and with 1…R processes of one thread each
# (mpirun --oversubscribe), each REPEATS times (the fastest kept). Prints a Markdown table of
# wall time, points per second, the scaling efficiency (rate / (workers x the one-worker rate)),
# and the CPU seconds of all processes with the work efficiency (CPU seconds of one worker / CPU
# seconds of N: what the parallel run costs beyond the computation itself, which on a machine
# busy with other work is the part of the scaling one can measure), and checks that every run
# wrote the same bytes.
#   bench/ensemble_scaling.sh [COUNT] [UNTIL] [MAX_WORKERS] [REPEATS]
set -euo pipefail
cd "$(dirname "$0")/.."
count=${1:-100}
until=${2:-10}
max_workers=${3:-$(nproc)}
repeats=${4:-3}
build=${LAGRANGE_BUILD:-build}
[ -x "$build/lagrange" ] || scripts/setup.sh
lagrange=$PWD/$build/lagrange
scene=$PWD/tests/scenes/ensemble_double_pendulum.lag
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
args=(ensemble "$scene" --grid "theta=-3.1..3.1:$count, phi=-3.1..3.1:$count" --until "$until" --measure flip_time)
points=$((count * count))
# run KIND WORKERS: the fastest of the repeats, as "wall cpu"
run() {
  local kind=$1 workers=$2 best="" line
  for _ in $(seq "$repeats"); do
    if [ "$kind" = threads ]; then
      /usr/bin/env time -f "%e %U %S" -o "$work/time" "$lagrange" "${args[@]}" --threads "$workers" \
        -o "$work/$kind$workers.csv" 2>/dev/null
    else
      /usr/bin/env time -f "%e %U %S" -o "$work/time" mpirun -np "$workers" --oversubscribe "$lagrange" \
        "${args[@]}" --threads 1 -o "$work/$kind$workers.csv" 2>/dev/null
    fi
    line=$(awk '{ printf "%s %.2f", $1, $2 + $3 }' "$work/time")
    if [ -z "$best" ] || awk -v a="${line%% *}" -v b="${best%% *}" 'BEGIN { exit !(a < b) }'; then best=$line; fi
  done
  cmp -s "$work/threads1.csv" "$work/$kind$workers.csv" || { echo "error: $kind $workers wrote other bytes" >&2; exit 1; }
  echo "$best"
}
echo "flip-time map ${count}x${count} (${points} points), until t = $until, $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg) at start"
echo
echo "| run | workers | wall s | points/s | efficiency | CPU s | points per CPU s | work efficiency |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|"
base=""
base_cpu=""
for kind in threads mpi; do
  command -v mpirun >/dev/null 2>&1 || [ "$kind" = threads ] || { echo "(no mpirun: MPI rows left out)"; break; }
  for workers in $(seq 1 "$max_workers"); do
    result=$(run "$kind" "$workers")
    wall=${result%% *}
    cpu=${result##* }
    [ -n "$base" ] || base=$wall
    [ -n "$base_cpu" ] || base_cpu=$cpu
    label=$([ "$kind" = threads ] && echo "1 process, $workers threads" || echo "mpirun -np $workers, 1 thread each")
    awk -v l="$label" -v w="$workers" -v t="$wall" -v c="$cpu" -v p="$points" -v b="$base" -v bc="$base_cpu" \
      'BEGIN { printf "| %s | %d | %.2f | %.0f | %.0f%% | %.2f | %.0f | %.0f%% |\n", l, w, t, p / t, 100 * b / (t * w),
               c, p / c, 100 * bc / c }'
  done
done
