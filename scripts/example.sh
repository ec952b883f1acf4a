#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Quick start, command 1: install what is missing, build (Release), and run the
# main example. Extra arguments go to `lagrange` (e.g. --format json).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
build/lagrange examples/double_pendulum.lag --timings "$@"
