#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Installs what is missing (Debian packages, as root), then configures and builds
# lagrange in Release mode in ./build. Used by example.sh and test.sh.
#   LAGRANGE_WITH_LATEX=1  also installs pdflatex (the tests compile LaTeX output)
#   LAGRANGE_WITH_EXPORT_TOOLS=1  also installs SciPy and Octave (the tests run exported code)
#   LAGRANGE_WITH_MEDIA=1  also installs ffmpeg and Chromium (videos; the tests decode them and open the
#     player) and matplotlib (the peer of bench/animate.sh)
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(g++ cmake make pkg-config libginac-dev libcln-dev libeigen3-dev catch2 libcli11-dev nlohmann-json3-dev libboost-dev libsundials-dev libflint-dev)
# SLEEF: vectorized sines and cosines in the natively compiled equations of motion (without it, libm's)
packages+=(libsleef-dev)
# Nettle: SHA-256 names the entries of the cache of compiled equations (lib/system/cache.cpp)
packages+=(nettle-dev)
# zlib: the report typesetting test reads the figures' PDF streams
packages+=(zlib1g-dev)
# The Python module (python/, built by default when these are found) and its tests and notebook:
# pybind11 and Debian's /usr/bin/python3 with numpy, SymPy, pytest, nbclient and ipykernel.
packages+=(python3-dev pybind11-dev python3-pybind11 python3-numpy python3-sympy python3-pytest python3-nbclient python3-ipykernel)
# gnuplot draws the figures of `lagrange report` and `--plot` (without it they are left out)
packages+=(gnuplot-nox)
# cairo draws the frames of `lagrange animate -o FILE.mp4|gif` (optional in CMake)
packages+=(libcairo2-dev)
# The manual page: help2man writes it from `lagrange --help` at build time; groff checks it (ctest man_page)
packages+=(help2man groff-base)
# Open MPI: `mpirun -np R lagrange ensemble ...` across processes and machines (optional in CMake)
packages+=(libopenmpi-dev openmpi-bin)
if [ "${LAGRANGE_WITH_LATEX:-0}" = 1 ]; then
  packages+=(texlive-latex-base)
fi
# The tests of `lagrange export` run the exported code: Python with SciPy's solve_ivp, and
# Octave's ode45 (octave-cli).
if [ "${LAGRANGE_WITH_EXPORT_TOOLS:-0}" = 1 ]; then
  packages+=(python3-scipy octave)
fi
# `lagrange animate -o FILE.mp4|gif` encodes with ffmpeg; the tests decode with ffprobe and open
# the HTML player in headless Chromium.
if [ "${LAGRANGE_WITH_MEDIA:-0}" = 1 ]; then
  packages+=(ffmpeg chromium python3-matplotlib)
fi
# fuzz/run.sh: clang and its libFuzzer/sanitizer runtimes; bench/run.sh: GNU time (peak memory);
# bench/large_systems.sh: MuJoCo, its peer (the benchmark skips it without).
if [ "${LAGRANGE_WITH_FUZZ:-0}" = 1 ]; then
  packages+=(clang libclang-rt-14-dev)
fi
if [ "${LAGRANGE_WITH_TIME:-0}" = 1 ]; then
  packages+=(time)
fi
if [ "${LAGRANGE_WITH_MUJOCO:-0}" = 1 ]; then
  packages+=(libmujoco-dev)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}" >&2
  if [ "$(id -u)" = 0 ]; then sudo=(); else sudo=(sudo); fi
  "${sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi

if [ "${LAGRANGE_SETUP_ONLY:-0}" = 1 ]; then exit 0; fi
# ccache, when installed, keeps repeated clean-clone builds (CI) from compiling all again.
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}"; fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" "$@" >&2
cmake --build build -j "$(nproc)" >&2
