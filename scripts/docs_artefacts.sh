#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# The generated documentation: the report PDFs of three examples and the figures that
# docs/ describes (docs/reports.md lists them), among them the double pendulum's flip-time
# map (docs/ensemble.md; LAGRANGE_MAP_COUNT x LAGRANGE_MAP_COUNT points, 200 by default,
# fewer in ctest to keep it quick), the one figure also committed, as ensemble.md shows it.
#
#   scripts/docs_artefacts.sh [LAGRANGE] [FOLDER]
#
# LAGRANGE is the program (default build/lagrange), FOLDER where the files go (default
# build/docs). `cmake --build build --target docs` runs it into build/docs; the ctest test
# `docs_artefacts` runs it into the build tree of the tests and checks every file. Needs
# gnuplot (figures) and pdflatex (reports): without them it exits 77 (ctest: skipped).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
lagrange="${1:-$root/build/lagrange}"
folder="${2:-$root/build/docs}"
for tool in gnuplot pdflatex; do
  if ! command -v "$tool" >/dev/null 2>&1; then
    echo "skipped: $tool is not installed (LAGRANGE_WITH_LATEX=1 scripts/setup.sh installs both)" >&2
    exit 77
  fi
done
mkdir -p "$folder"
examples="$root/examples"

# The reports: the homework's double pendulum, its four bodies, and a free asymmetric top.
"$lagrange" report "$examples/double_pendulum.lag" -o "$folder/double_pendulum_report.pdf"
"$lagrange" report "$examples/homework_bodies.lag" -o "$folder/bodies_report.pdf"
"$lagrange" report "$examples/free_asymmetric_top.lag" -o "$folder/free_asymmetric_top_report.pdf"
# The figures: beats (one panel per coordinate), work against precision (run times of this
# machine), and the damped driven oscillator's Bode diagram.
"$lagrange" simulate "$examples/beats.lag" --plot "$folder/beats.svg" >/dev/null
"$lagrange" workprecision "$examples/linear_double_pendulum.lag" --plot "$folder/workprecision.svg" >/dev/null
"$lagrange" response "$examples/damped_driven_oscillator.lag" --input u --output x \
  --plot "$folder/damped_driven_oscillator_bode.svg" >/dev/null
# The ensemble's flip-time map of the double pendulum.
count="${LAGRANGE_MAP_COUNT:-200}"
"$lagrange" ensemble "$root/tests/scenes/ensemble_double_pendulum.lag" \
  --grid "theta=-3.1..3.1:$count, phi=-3.1..3.1:$count" --until 10 --measure flip_time \
  -o "$folder/ensemble_flip_map.png"
# The pictures of motion (docs/pictures.md): Hénon–Heiles' sections at E = 1/12 and 1/8, the
# double pendulum's sections, its θ phase portrait and its player, the triple pendulum's
# section, and the heavy top's video.
hh="$root/tests/scenes/henon_heiles.lag"
dp="$root/tests/scenes/ensemble_double_pendulum.lag"
"$lagrange" poincare "$hh" --section "x = 0, x' > 0" --energy 0.0833333333333333 --orbits 60 --crossings 300 \
  -o "$folder/henon_heiles_section_12.png" 2>/dev/null
"$lagrange" poincare "$hh" --section "x = 0, x' > 0" --energy 0.125 --orbits 60 --crossings 300 \
  -o "$folder/henon_heiles_section_8.png" 2>/dev/null
# The double pendulum at rising energies (its minimum is -29.43), and a section of three
# coordinates, drawn in the two of its four dimensions that --axes names.
"$lagrange" poincare "$dp" --section "phi = 0, phi' > 0" --energy -25 --orbits 30 --crossings 150 \
  -o "$folder/double_pendulum_section_25.png" 2>/dev/null
"$lagrange" poincare "$dp" --section "phi = 0, phi' > 0" --energy -15 --orbits 40 --crossings 200 \
  -o "$folder/double_pendulum_section.png" 2>/dev/null
"$lagrange" poincare "$dp" --section "phi = 0, phi' > 0" --energy -5 --orbits 30 --crossings 150 \
  -o "$folder/double_pendulum_section_5.png" 2>/dev/null
"$lagrange" poincare "$root/tests/scenes/triple_pendulum.lag" --values m1=1,m2=1,m3=1,l1=1,l2=1,l3=1,g=9.81 \
  --section "theta1 = 0, theta1' > 0" --energy -50 --orbits 40 --crossings 200 --axes "theta3, theta3'" \
  -o "$folder/triple_pendulum_section.png" 2>/dev/null
"$lagrange" phase "$dp" --coordinate theta -o "$folder/double_pendulum_phase.svg" 2>/dev/null
"$lagrange" animate "$examples/double_pendulum.lag" --trail 2 -o "$folder/double_pendulum.html"
# Videos need ffmpeg (LAGRANGE_WITH_MEDIA=1 scripts/setup.sh): without it they are left out.
if command -v ffmpeg >/dev/null; then
  "$lagrange" animate "$examples/free_asymmetric_top.lag" --until 12 --fps 15 -o "$folder/free_asymmetric_top_poinsot.gif"
  "$lagrange" animate "$examples/double_pendulum.lag" --until 10 --trail 2 --fps 15 -o "$folder/double_pendulum.gif"
  "$lagrange" animate "$examples/heavy_top.lag" --until 4 --fps 15 -o "$folder/heavy_top.gif"
fi

fail() { echo "error: $1" >&2; exit 1; }
for pdf in double_pendulum_report bodies_report free_asymmetric_top_report; do
  head -c 5 "$folder/$pdf.pdf" | grep -q '%PDF-' || fail "$folder/$pdf.pdf is not a PDF"
done
for svg in beats workprecision damped_driven_oscillator_bode double_pendulum_phase; do
  grep -q '<svg' "$folder/$svg.svg" || fail "no SVG drawn into $folder/$svg.svg"
done
grep -q 'resonance' "$folder/damped_driven_oscillator_bode.svg" || fail "the Bode diagram lacks its resonance peak"
# beats.lag has two coordinates: two panels, each with its own axis label.
grep -q 'θ' "$folder/beats.svg" && grep -q 'φ' "$folder/beats.svg" || fail "beats.svg lacks a panel per coordinate"
for png in ensemble_flip_map henon_heiles_section_12 henon_heiles_section_8 double_pendulum_section \
    double_pendulum_section_25 double_pendulum_section_5 triple_pendulum_section; do
  [ "$(head -c 4 "$folder/$png.png" | tail -c 3)" = PNG ] || fail "no PNG drawn into $folder/$png.png"
done
grep -q 'lagrangePlayer' "$folder/double_pendulum.html" || fail "no player written into $folder/double_pendulum.html"
if command -v ffmpeg >/dev/null; then
  for gif in free_asymmetric_top_poinsot double_pendulum heavy_top; do
    head -c 6 "$folder/$gif.gif" | grep -q 'GIF89a' || fail "no GIF encoded into $folder/$gif.gif"
  done
fi
echo "wrote into $folder:"
(cd "$folder" && ls -1 -- *.pdf *.svg *.png *.html; ls -1 -- *.gif 2>/dev/null || true)
