#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# The frames of an animation against the video's length and a matplotlib peer, in one run:
# the double pendulum (examples/double_pendulum.lag) over UNTIL time units at FPS frames per
# second, by `lagrange animate` drawing its frames (cairo) into a pipe whose reader discards
# them (a stand-in ffmpeg on PATH: the drawing alone), then encoding a real MP4 (ffmpeg), and
# by bench/animate_matplotlib.py drawing the same frames with matplotlib (Agg). The fastest of
# REPEATS runs each. Needs ffmpeg and python3-matplotlib (Debian).
#   bench/animate.sh [UNTIL] [FPS] [REPEATS]
set -euo pipefail
cd "$(dirname "$0")/.."
until=${1:-60}
fps=${2:-30}
repeats=${3:-3}
build=${LAGRANGE_BUILD:-build}
[ -x "$build/lagrange" ] || scripts/setup.sh
lagrange=$PWD/$build/lagrange
scene=$PWD/examples/double_pendulum.lag
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir "$work/discard"
cat >"$work/discard/ffmpeg" <<'SHIM'
#!/bin/sh
for a; do last=$a; done
cat >/dev/null
: >"$last"
SHIM
chmod +x "$work/discard/ffmpeg"
# fastest PATH_PREFIX OUTPUT: the fastest wall time of the repeats of `lagrange animate`
fastest() {
  local best="" wall
  for _ in $(seq "$repeats"); do
    PATH="$1$PATH" /usr/bin/env time -f "%e" -o "$work/time" "$lagrange" animate "$scene" --until "$until" \
      --fps "$fps" -o "$2"
    wall=$(tail -1 "$work/time")
    if [ -z "$best" ] || awk -v a="$wall" -v b="$best" 'BEGIN { exit !(a < b) }'; then best=$wall; fi
  done
  echo "$best"
}
drawn=$(fastest "$work/discard:" "$work/discarded.mp4")
encoded=$(fastest "" "$work/video.mp4")
frames=$(ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 "$work/video.mp4")
length=$(ffprobe -v error -show_entries format=duration -of csv=p=0 "$work/video.mp4")
"$lagrange" animate "$scene" --until "$until" --fps "$fps" -o "$work/player.html"
peer=""
for _ in $(seq "$repeats"); do
  line=$(/usr/bin/python3 bench/animate_matplotlib.py "$work/player.html")
  if [ -z "$peer" ] || awk -v a="${line%% *}" -v b="${peer%% *}" 'BEGIN { exit !(a < b) }'; then peer=$line; fi
done
echo "double pendulum, $until time units at $fps fps: $frames frames, a $length s video; $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg)"
echo
echo "| run | wall s | / video length | / lagrange's frames |"
echo "|---|---:|---:|---:|"
row() { awk -v l="$1" -v t="$2" -v v="$length" -v b="$drawn" 'BEGIN { printf "| %s | %.2f | %.3f | %.2f |\n", l, t, t / v, t / b }'; }
row "lagrange animate, frames drawn (cairo, piped and discarded)" "$drawn"
row "lagrange animate -o FILE.mp4 (drawn and encoded by ffmpeg)" "$encoded"
row "matplotlib (Agg), the same frames drawn" "${peer%% *}"
