#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Long fuzzing run in the background (log in fuzz/long.log): fuzz/start-bg.sh SECONDS
cd "$(dirname "$0")/.."
nohup fuzz/run.sh "${1:-2400}" >> fuzz/long.log 2>&1 &
echo $! > fuzz/long.pid
