#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# The flip-time map of the equal-mass double pendulum over a COUNT x COUNT grid, computed as
# one process with 1 and with 2 threads and by `mpirun -np 2 --oversubscribe`: the three CSV
# files must be byte-identical, and no point may flip where 3 cos(theta) + cos(phi) > 2
# (from rest the energy is too low). Exits 77 (ctest: skipped) without mpirun or when
# lagrange was built without MPI.
#   tests/ensemble_mpi.sh LAGRANGE SCENE [COUNT] [UNTIL]
set -euo pipefail
lagrange=$1
scene=$2
count=${3:-16}
until=${4:-5}
if ! command -v mpirun >/dev/null 2>&1; then
  echo "skipped: mpirun is not installed (Debian: openmpi-bin libopenmpi-dev)"
  exit 77
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
args=(ensemble "$scene" --grid "theta=-3.1..3.1:$count, phi=-3.1..3.1:$count" --until "$until" --measure flip_time)
"$lagrange" "${args[@]}" --threads 1 -o "$work/one.csv"
"$lagrange" "${args[@]}" --threads 2 -o "$work/two.csv"
# CI runs as root, which Open MPI refuses unless told otherwise.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
if ! mpirun -np 2 --oversubscribe "$lagrange" "${args[@]}" --threads 1 -o "$work/mpi.csv" 2>"$work/mpi.err"; then
  if grep -q "built without MPI" "$work/mpi.err"; then
    echo "skipped: this lagrange was built without MPI"
    exit 77
  fi
  cat "$work/mpi.err" >&2
  exit 1
fi
cat "$work/mpi.err"
cmp "$work/one.csv" "$work/two.csv"
cmp "$work/one.csv" "$work/mpi.csv"
rows=$(($(wc -l <"$work/one.csv") - 1))
if [ "$rows" != $((count * count)) ]; then
  echo "error: $rows rows, not $((count * count))" >&2
  exit 1
fi
awk -F, 'NR > 1 { if (3 * cos($1) + cos($2) > 2) { low++; if ($3 != "inf") bad++ } if ($3 != "inf") flips++ }
  END { printf "%d points with 3cos(theta)+cos(phi) > 2, %d of them flipped; %d flips in all\n", low, bad, flips
        exit (bad > 0 || low == 0 || flips == 0) }' "$work/one.csv"
echo "ok: one thread, two threads and two MPI processes wrote the same $rows rows"
