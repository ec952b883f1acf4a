#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Installs the built project into a temporary prefix, checks that every installed
# header finds the headers it includes there (none left out as internal) and that the
# library is shared with a SONAME, builds the consumer against it twice, with
# find_package(lagrange) and with pkg-config (lagrange.pc), and checks what each prints.
#   check.sh BUILD_DIR
set -euo pipefail
build=$1
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
include=$work/prefix/include/lagrange
[ -f "$include/lagrange.h" ]
missing=0
while IFS= read -r header; do
    while IFS= read -r included; do
        if [ ! -f "$include/$included" ]; then
            echo "installed ${header#"$include"/} includes \"$included\", which is not installed"
            missing=1
        fi
    done < <(sed -nE 's/^[[:space:]]*#[[:space:]]*include[[:space:]]+"([^"]+)".*/\1/p' "$header")
done < <(find "$include" -name '*.h' | sort)
[ "$missing" = 0 ]
# The shared library: liblagrange.so.MAJOR.MINOR, with that SONAME.
library=$(find "$work/prefix" -name 'liblagrange.so.*.*.*' | head -n 1)
[ -n "$library" ] || { echo "no liblagrange.so.X.Y.Z installed"; exit 1; }
soname=$(readelf -d "$library" | sed -nE 's/.*\(SONAME\).*\[(.*)\]/\1/p')
echo "installed $(basename "$library"), SONAME $soname"
[[ $soname == liblagrange.so.* ]] && [ -e "$(dirname "$library")/$soname" ]
pc=$(find "$work/prefix" -name lagrange.pc | head -n 1)
[ -n "$pc" ] || { echo "no lagrange.pc installed"; exit 1; }
export PKG_CONFIG_PATH="$(dirname "$pc")${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}"
version=$(pkg-config --modversion lagrange)
expected=$(printf 'k*x+m*x_ddot\n%s' "$version")
check_output() { # NAME BINARY: runs it, compares what it prints, and checks it uses the SONAME
    local output
    output=$("$2")
    echo "consumer ($1) printed: $(tr '\n' ' ' <<<"$output")"
    [ "$output" = "$expected" ]
    readelf -d "$2" | grep -q "NEEDED.*\[$soname\]" || { echo "consumer ($1) does not load $soname"; exit 1; }
}
cmake -S "$here" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/consumer" >/dev/null
check_output cmake "$work/consumer/consumer"
# shellcheck disable=SC2046 # pkg-config's flags are words
c++ -std=c++17 -O1 "$here/main.cpp" -o "$work/consumer_pc" $(pkg-config --cflags --libs lagrange) \
    -Wl,-rpath,"$(pkg-config --variable=libdir lagrange)"
check_output pkg-config "$work/consumer_pc"
