#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Quick start, command 2: install what is missing (with pdflatex, SciPy and Octave), build (Release),
# and run the whole test suite with ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
LAGRANGE_WITH_LATEX=1 LAGRANGE_WITH_EXPORT_TOOLS=1 LAGRANGE_WITH_MEDIA=1 scripts/setup.sh
cd build
ctest --output-on-failure -j "$(nproc)" "$@"
