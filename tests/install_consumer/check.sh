#!/usr/bin/env bash
# Installs the built project into a temporary prefix, checks that every installed
# header finds the headers it includes there (none left out as internal), builds the
# consumer against it with find_package(lagrange), and checks what it prints.
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
cmake -S "$here" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/consumer" >/dev/null
output=$("$work/consumer/consumer")
echo "consumer printed: $output"
[ "$output" = "k*x+m*x_ddot" ]
