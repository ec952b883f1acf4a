#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# A frozen MPI process ends the run: three processes share a long ensemble, rank 2 is stopped
# (SIGSTOP, as a frozen node), and within --mpi-timeout and a few seconds the run must end
# with a message naming rank 2, where it waited for ever before. Exits 77 (ctest: skipped)
# without mpirun or when lagrange was built without MPI.
#   tests/ensemble_mpi_frozen.sh LAGRANGE SCENE
set -euo pipefail
lagrange=$1
scene=$2
if ! command -v mpirun >/dev/null 2>&1; then
  echo "skipped: mpirun is not installed (Debian: openmpi-bin libopenmpi-dev)"
  exit 77
fi
work=$(mktemp -d)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpirun -np 3 --oversubscribe "$lagrange" ensemble "$scene" --grid "theta=-3.1..3.1:400, phi=-3.1..3.1:400" \
  --until 30 --measure flip_time --threads 1 --mpi-timeout 3 -o "$work/out.csv" 2>"$work/err" &
runner=$!
trap 'kill -9 $runner 2>/dev/null || true; pkill -9 -P $runner 2>/dev/null || true; rm -rf "$work"' EXIT
# Find rank 2 by its environment, once the processes are up.
frozen=""
for _ in $(seq 100); do
  for pid in $(pgrep -f -- "--mpi-timeout 3" || true); do
    if tr '\0' '\n' <"/proc/$pid/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=2"; then
      frozen=$pid
    fi
  done
  [ -n "$frozen" ] && break
  sleep 0.1
done
if [ -z "$frozen" ]; then
  if grep -q "built without MPI" "$work/err"; then
    echo "skipped: this lagrange was built without MPI"
    exit 77
  fi
  echo "error: rank 2 never started" >&2
  cat "$work/err" >&2
  exit 1
fi
sleep 1
kill -STOP "$frozen"
start=$(date +%s)
status=0
wait "$runner" || status=$?
elapsed=$(($(date +%s) - start))
kill -CONT "$frozen" 2>/dev/null || true
cat "$work/err"
if [ "$status" = 0 ]; then
  echo "error: the run ended well with a process stopped" >&2
  exit 1
fi
if ! grep -q "MPI rank 2 has sent nothing for more than 3 s" "$work/err"; then
  echo "error: the message does not name rank 2" >&2
  exit 1
fi
if [ "$elapsed" -gt 20 ]; then
  echo "error: the run ended $elapsed s after the stop (timeout 3 s)" >&2
  exit 1
fi
echo "ok: stopped rank 2 ended the run after $elapsed s, named"
