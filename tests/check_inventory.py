#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The suite guards itself: every Catch2 test case of every test folder is run by exactly
one ctest test, every folder's executable is run by ctest, and no test case's name holds
a character that breaks a Catch2 filter.

    check_inventory.py CTEST BUILD_DIR
"""
import json
import os
import re
import subprocess
import sys

# Characters that Catch2's test-spec parser reads as syntax, or that ctest splits on.
FORBIDDEN = re.compile(r'[;\[\]*~"\\]')


def names(command):
    # Catch2 2 exits with the number of cases listed, so the exit code says nothing; a
    # listing that fails prints nothing (an empty selection is --warn NoTests' business).
    run = subprocess.run(command + ["--list-test-names-only"], capture_output=True, text=True)
    if run.returncode < 0:
        sys.exit(f"check_inventory: {' '.join(command)} was killed: {run.stderr.strip()}")
    return [line for line in run.stdout.splitlines() if line.strip()]


def main():
    ctest, build = sys.argv[1], sys.argv[2]
    shown = subprocess.run([ctest, "--show-only=json-v1"], cwd=build, capture_output=True, text=True, check=True)
    selections = {}  # executable -> {ctest test: names}
    for test in json.loads(shown.stdout)["tests"]:
        command = test.get("command") or []
        if not command or not os.path.basename(command[0]).startswith("tests_"):
            continue
        arguments, k = [], 1
        while k < len(command):
            if command[k] == "--requires":
                k += 2
                continue
            if command[k] == "--warn":
                k += 2
                continue
            arguments.append(command[k])
            k += 1
        selections.setdefault(command[0], {})[test["name"]] = names([command[0]] + arguments)

    failures = []
    folder = os.path.join(build, "tests")
    built = sorted(os.path.join(folder, f) for f in os.listdir(folder)
                   if f.startswith("tests_") and os.access(os.path.join(folder, f), os.X_OK))
    for executable in built:
        if os.path.realpath(executable) not in {os.path.realpath(e) for e in selections}:
            failures.append(f"{os.path.basename(executable)} is built but no ctest test runs it")
    total = 0
    for executable, by_test in sorted(selections.items()):
        everything = names([executable]) + names([executable, "[.]"])
        total += len(everything)
        run_by = {}
        for test, selected in by_test.items():
            for name in selected:
                run_by.setdefault(name, []).append(test)
        for name in everything:
            if name not in run_by:
                failures.append(f"{os.path.basename(executable)}: no ctest test runs “{name}”")
            elif len(run_by[name]) > 1:
                failures.append(f"{os.path.basename(executable)}: “{name}” runs in {', '.join(run_by[name])}")
            if FORBIDDEN.search(name) or name != name.strip():
                failures.append(f"{os.path.basename(executable)}: the name “{name}” breaks a test filter")
    for failure in failures:
        print("check_inventory:", failure)
    if failures:
        return 1
    print(f"check_inventory: {total} test cases in {len(selections)} executables, each run by one ctest test")
    return 0


if __name__ == "__main__":
    sys.exit(main())
