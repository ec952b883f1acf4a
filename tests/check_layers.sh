#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Fails on an include that points up the layers (docs/architecture.md):
#   core ← algebra, system ← program, scene (front end) | bodies ← mechanics ← numeric ← verify, ensemble
#   ← engine ← output ← cli
# A folder may include its own headers and those of the folders listed for it below;
# the umbrella header lib/lagrange.h, those of every installed folder.
set -euo pipefail
cd "$(dirname "$0")/.."
# The folders each folder may include besides its own.
declare -A below=(
    [core]=""
    [algebra]="core"
    [system]="core"
    [program]="core algebra system"
    [scene]="core algebra system"
    [bodies]="core algebra"
    [mechanics]="core algebra bodies"
    [numeric]="core algebra bodies mechanics system program"
    [verify]="core algebra bodies mechanics numeric system program"
    [ensemble]="core algebra bodies mechanics numeric system program"
    [engine]="core algebra bodies mechanics numeric verify ensemble system scene program"
    [output]="core algebra bodies mechanics numeric verify ensemble system scene engine program"
    [cli]="core algebra bodies mechanics numeric verify ensemble system scene engine output program"
    [lagrange.h]="core algebra bodies mechanics numeric verify ensemble scene engine output program"
)
bad=0
while IFS= read -r file; do
    if [[ $file == cli/* ]]; then from=cli; else from=$(cut -d/ -f2 <<<"$file"); fi
    if [[ -z ${below[$from]+x} ]]; then
        echo "$file: folder '$from' has no layer in tests/check_layers.sh"; bad=1; continue
    fi
    while IFS= read -r line; do
        to=${line#*\"}; to=${to%%/*}
        [[ $to == "$from" ]] && continue
        if [[ " ${below[$from]} " != *" $to "* ]]; then
            echo "$file: includes ${line}\" from layer '$to', which '$from' may not include"; bad=1
        fi
    done < <(grep -E '^\s*#\s*include\s+"[a-z_]+/' "$file" | sed -E 's/^[^"]*"([^"]*)".*/"\1/')
done < <(find lib cli -name '*.h' -o -name '*.cpp' | sort)
if (( bad )); then exit 1; fi
echo "check_layers: every include points down"
