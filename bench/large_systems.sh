#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Large systems at the physical limit (issue 39): the planar N-link chain for N = 2, 5, 10,
# 20, 50 (or the sizes given), in one run beside its peers. Per N: deriving and building the
# programs, the first run's C compile (no cache), ns per q̈(q, q̇) through compiled_motion
# (bench/large_systems.cpp) against a hand-written O(N) recursion built in the same run (rod
# tensions along the chain) and, when Debian's libmujoco-dev is installed, MuJoCo's
# mj_forward (bench/mujoco_chain.c; skipped otherwise, and said so); then the whole
# `lagrange simulate` command (until t = 5) without the cache and with it.
#   bench/large_systems.sh [N ...]
set -euo pipefail
cd "$(dirname "$0")/.."
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(2 5 10 20 50)
build=${LAGRANGE_BUILD:-build}
[ -x "$build/bench/large_systems" ] && [ -x "$build/lagrange" ] || scripts/setup.sh
[ -f /usr/include/mujoco/mujoco.h ] || LAGRANGE_WITH_MUJOCO=1 LAGRANGE_SETUP_ONLY=1 scripts/setup.sh || true
lagrange=$PWD/$build/lagrange
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cc=${CC:-cc}
mujoco=""
if [ -f /usr/include/mujoco/mujoco.h ] && "$cc" -O2 -o "$work/mujoco_chain" bench/mujoco_chain.c -lmujoco 2>"$work/mujoco.log"; then
  mujoco="$work/mujoco_chain"
  mujoco_version=$(dpkg-query -W -f '${Version}' libmujoco-dev 2>/dev/null || echo "?")
fi
# seconds of one command, its output discarded
wall() {
  local start end
  start=$(date +%s.%N)
  "$@" >/dev/null 2>&1 || echo "warning: $* failed" >&2
  end=$(date +%s.%N)
  awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f", b - a }'
}
echo "planar N-link chain, $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg) at start"
[ -n "$mujoco" ] && echo "MuJoCo $mujoco_version (mj_forward)" || echo "MuJoCo: skipped (libmujoco-dev is not installed)"
echo
echo "| N | form | derive s | first compile s | lagrange ns | hand O(N) ns | ratio | MuJoCo ns | MuJoCo/lagrange | simulate, no cache s | simulate, cached s | agreement |"
echo "|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for n in "${sizes[@]}"; do
  read -r _ derive compile mode ours hand ratio difference _ form < <("$build/bench/large_systems" "$n")
  [ "$mode" = native ] || compile="$compile ($mode)"
  peer="-" peer_ratio="-"
  if [ -n "$mujoco" ]; then
    read -r _ peer < <("$mujoco" "$n")
    peer_ratio=$(awk -v a="$peer" -v b="$ours" 'BEGIN { printf "%.2f", a / b }')
  fi
  "$build/bench/large_systems" --scene "$n" >"$work/chain$n.lag"
  cold=$(LAGRANGE_CACHE=0 wall "$lagrange" simulate "$work/chain$n.lag")
  mkdir -p "$work/cache"
  XDG_CACHE_HOME=$work/cache "$lagrange" simulate "$work/chain$n.lag" >/dev/null 2>&1 || true
  warm=$(XDG_CACHE_HOME=$work/cache wall "$lagrange" simulate "$work/chain$n.lag")
  echo "| $n | $form | $derive | $compile | $ours | $hand | $ratio | $peer | $peer_ratio | $cold | $warm | $difference |"
done
echo
echo "ratio: lagrange ns / hand ns (1 is the O(N) recursion's speed); agreement: largest relative"
echo "difference of q̈ between lagrange and the hand recursion over 64 random states."
