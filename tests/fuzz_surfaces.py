#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Bounded random input for the surfaces the scene fuzzer (fuzz/) does not reach: the command
line's options of every command (report and ensemble settings included), the cache's reading
of its entries, and the Python module's argument checks. A fixed seed makes each run the same
inputs; every input must end in exit code 0, 1 or 2 (never a signal, an abort, a hang or a
sanitizer report), and bad input must say where it is.

    tests/fuzz_surfaces.py LAGRANGE SOURCE_DIR [CASES]

With PYTHONPATH naming the Python module's folder, the Python checks run too."""
import os
import random
import shutil
import subprocess
import sys
import tempfile

LAGRANGE, SOURCE = sys.argv[1], sys.argv[2]
CASES = int(sys.argv[3]) if len(sys.argv) > 3 else 120
SCENE = os.path.join(SOURCE, "examples", "damped_driven_oscillator.lag")
PENDULUM = os.path.join(SOURCE, "examples", "double_pendulum.lag")
rng = random.Random(20261128)
failures = []
exit_codes = {}

NUMBERS = ["0", "-1", "1e-400", "1e400", "nan", "inf", "-inf", "0x10", "1e3", "2.5", "", " ", "1,2", "=",
           "9" * 40, "-0", "1e-14", "0.5", "4096", "4097", "18446744073709551616"]
WORDS = ["x", "u", "theta", "m=1", "x=0..1:2", "x=1..0:3", "x=0..1:0", "x=0..1:2:log", "k=-1..1:3:log",
         "final", "flip_time", "flip_time:x", "max_lyapunov", "floquet_stable", "nosuch", "x'=0..1:2",
         "\u009b2J", "\x1b[31m", "a\nb", "$(touch /tmp/pwned)", "`id`", "%s%n", "../../etc/passwd"]
OUTPUTS = ["out.csv", "out.json", "out.png", "out.txt", "out.tex", "out.pdf", "-", "", "dir/", "/proc/x.csv",
           "/nonexistent/out.csv"]
COMMON = ["--max-terms", "--max-seconds", "--values", "--initial", "--format", "-o", "--want"]
COMMANDS = {
    "": COMMON + ["--timings", "--sweep"],
    "report": ["--max-terms", "--max-seconds", "--values", "--initial", "-o", "--want"],
    "simulate": COMMON + ["--until", "--method", "--tolerance", "--plot", "--csv", "--every"],
    "response": ["--input", "--output", "--from", "--to", "--points", "--linear", "--format", "--plot",
                 "--max-seconds"],
    "ensemble": ["--grid", "--until", "--measure", "-o", "--threads", "--tolerance", "--random", "--seed",
                 "--resume", "--values", "--initial", "--interpret", "--mpi-timeout", "--max-seconds"],
    "check": [],
}
FLAGS = {"--timings", "--linear", "--resume", "--interpret"}


def value_for(option, folder):
    if option in ("-o", "--plot", "--csv"):
        name = rng.choice(OUTPUTS)
        return name if name.startswith("/") or name in ("-", "") else os.path.join(folder, name)
    return rng.choice(NUMBERS + WORDS)


def run(args, env=None, timeout=60):
    try:
        result = subprocess.run([LAGRANGE] + args, capture_output=True, timeout=timeout, env=env,
                                stdin=subprocess.DEVNULL)
    except subprocess.TimeoutExpired:
        return None
    return result


def judge(args, result):
    if result is None:
        failures.append(f"hang: {args}")
        return
    err = result.stderr.decode("utf-8", "replace")
    exit_codes[result.returncode] = exit_codes.get(result.returncode, 0) + 1
    if result.returncode not in (0, 1, 2):
        failures.append(f"exit {result.returncode}: {args}\n{err[-2000:]}")
    elif any(mark in err for mark in ("terminate called", "Sanitizer", "runtime error:", "Segmentation")):
        failures.append(f"crash report: {args}\n{err[-2000:]}")
    elif result.returncode == 2 and not err.strip():
        failures.append(f"exit 2 without a message: {args}")
    if b"\xc2\x9b" in result.stdout + result.stderr:
        failures.append(f"a C1 control character reached the terminal: {args}")


def options_cases(folder):
    for _ in range(CASES):
        command = rng.choice(list(COMMANDS))
        args = [command] if command else []
        args.append(rng.choice([SCENE, PENDULUM]))
        for option in rng.sample(COMMANDS[command], k=min(len(COMMANDS[command]), rng.randint(0, 4))):
            args.append(option)
            if option not in FLAGS:
                args.append(value_for(option, folder))
        if command in ("simulate", "ensemble") and "--until" not in args:
            args += ["--until", "0.5"]
        if command == "ensemble" and "--grid" not in args:
            args += ["--grid", "x=0..1:2"]
        # The symbolic stages here are small; the bound is a hang detector.
        judge(args, run(args + ([] if "--max-seconds" in args else ["--max-seconds", "20"])))


def cache_cases(folder):
    """Random bytes in place of each cache entry: the run must repair it and print the same."""
    cache = os.path.join(folder, "cache")
    env = dict(os.environ, LAGRANGE_CACHE=cache)
    args = ["simulate", PENDULUM, "--until", "0.5", "--format", "json"]
    first = run(args, env)
    judge(args, first)
    if first is None or first.returncode != 0:
        return
    entries = [os.path.join(root, f) for root, _, files in os.walk(cache) for f in files]
    for case in range(max(4, CASES // 10)):
        for entry in entries:
            size = os.path.getsize(entry) if os.path.exists(entry) else 0
            with open(entry, "r+b" if os.path.exists(entry) else "wb") as f:
                how = case % 4
                if how == 0:
                    f.truncate(rng.randint(0, max(size, 1)))
                elif how == 1:
                    f.seek(rng.randint(0, max(size - 1, 0)))
                    f.write(bytes(rng.randrange(256) for _ in range(rng.randint(1, 64))))
                elif how == 2:
                    f.truncate(0)
                    f.write(os.urandom(rng.randint(0, 4096)))
                else:
                    f.seek(0)
                    f.write(b"\x7fELF" + bytes(60))
        again = run(args, env)
        judge(args + ["(cache entry corrupted)"], again)
        if again is not None and again.returncode == 0 and again.stdout != first.stdout:
            failures.append(f"a corrupted cache entry changed the output (case {case})")
        entries = [os.path.join(root, f) for root, _, files in os.walk(cache) for f in files]


def python_cases():
    try:
        import lagrange
    except ImportError:
        print("python checks: skipped (the module is not on PYTHONPATH)")
        return
    scene = lagrange.Scene.from_file(SCENE)
    allowed = (ValueError, TypeError, lagrange.SceneError, lagrange.ComputationError, OSError)
    pool = [0, -1, 1e-400, 1e400, float("nan"), float("inf"), "1, k=2", "x", "", None, True, [1], {"a": 1},
            "1\nvalues k = 3", 10 ** 30, "sin(", "1e-14", 0.5, b"1"]
    for _ in range(CASES):
        kwargs = {}
        for key in rng.sample(["until", "tolerance", "max_seconds", "max_terms", "values", "initial", "method"],
                              k=rng.randint(1, 3)):
            if key == "values":
                kwargs[key] = {rng.choice(["m", "k", "b", "nosuch", "m, k", ""]): rng.choice(pool)}
            elif key == "initial":
                kwargs[key] = {rng.choice(["x", "x'", "x_dot", "u", "nosuch"]): rng.choice(pool)}
            else:
                kwargs[key] = rng.choice(pool)
        kwargs.setdefault("until", 0.5)
        try:
            scene.simulate(**kwargs)
        except allowed:
            pass
        except Exception as error:  # anything else is a defect: a raw pybind11 or SymPy error
            failures.append(f"python simulate({kwargs!r}) raised {type(error).__name__}: {error}")


def main():
    folder = tempfile.mkdtemp(prefix="lagrange-fuzz-")
    os.makedirs(os.path.join(folder, "dir"), exist_ok=True)
    try:
        options_cases(folder)
        cache_cases(folder)
        python_cases()
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    for failure in failures:
        print("FAIL:", failure)
    print(f"{len(failures)} failures over {CASES} option cases, the cache and the Python arguments; exit codes "
          + ", ".join(f"{code}: {count}" for code, count in sorted(exit_codes.items())))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
