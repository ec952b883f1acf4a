#!/usr/bin/env bash
# The example artefacts that docs/ links to and that the build does not make otherwise:
# the Bode diagram of examples/damped_driven_oscillator.lag (docs/products.md) and the
# double pendulum's flip-time map (docs/ensemble.md; LAGRANGE_MAP_COUNT x LAGRANGE_MAP_COUNT
# points, 200 by default, fewer in ctest to keep it quick).
#
#   scripts/docs_artefacts.sh [LAGRANGE] [FOLDER]
#
# LAGRANGE is the program (default build/lagrange), FOLDER where the files go (default
# docs). `cmake --build build --target docs_artefacts` runs it into docs/; ctest runs it
# into the build tree and checks the SVG. Exits 77 (ctest: skipped) without gnuplot,
# which draws the plot.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
lagrange="${1:-$root/build/lagrange}"
folder="${2:-$root/docs}"
if ! command -v gnuplot >/dev/null 2>&1; then
  echo "skipped: gnuplot is not installed, so no Bode diagram can be drawn" >&2
  exit 77
fi
mkdir -p "$folder"
bode="$folder/damped_driven_oscillator_bode.svg"
"$lagrange" response "$root/examples/damped_driven_oscillator.lag" --input u --output x --plot "$bode" >/dev/null
if [ ! -s "$bode" ] || ! grep -q "<svg" "$bode" || ! grep -q "resonance" "$bode"; then
  echo "error: no SVG with the resonance peak drawn into $bode" >&2
  exit 1
fi
echo "wrote $bode"
count="${LAGRANGE_MAP_COUNT:-200}"
map="$folder/ensemble_flip_map.png"
"$lagrange" ensemble "$root/tests/scenes/ensemble_double_pendulum.lag" \
  --grid "theta=-3.1..3.1:$count, phi=-3.1..3.1:$count" --until 10 --measure flip_time -o "$map"
if [ ! -s "$map" ] || [ "$(head -c 4 "$map" | tail -c 3)" != PNG ]; then
  echo "error: no PNG map drawn into $map" >&2
  exit 1
fi
echo "wrote $map"
