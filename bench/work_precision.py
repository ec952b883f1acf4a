#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Work-precision, ours against SciPy, in one run.

Runs the peer ../shared/peers/work_precision_scipy.py (scipy.integrate.solve_ivp:
RK45, DOP853, Radau, LSODA; in a private copy, so the shared folder is left
alone) and build/bench/work_precision (ours: dopri5, rkf78, dop853, bulirsch-stoer, bdf,
implicit-midpoint) on the same four problems with the same error measure, one problem
at a time (ours, then the peer's), then
prints for each accuracy level 1e-3 ... 1e-12 the fastest run of each side whose
trajectory error is within that level, and the ratio.

Also prints the ratio of both sides' fastest repeats (each side's fastest run within the
level by its minimum time), the best case of both.

Usage: bench/work_precision.py [--build DIR] [--peer-json FILE] [--ours-json FILE] [--save-json PREFIX]
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
PEERS = os.path.join(HERE, "..", "..", "shared", "peers")


PROBLEMS = ("rigid", "lindp", "dp_small", "dp_large")


def run_peer(problem):
    """The peer's rows for one problem (its script with --problems PROBLEM)."""
    try:
        import scipy, mpmath, matplotlib  # noqa: F401  (the peer needs them)
    except ImportError:
        sys.exit("work_precision.py: the peer needs Debian's python3-scipy python3-mpmath python3-matplotlib")
    folder = tempfile.mkdtemp(prefix="lagrange-peer-")
    try:
        for name in ("work_precision_scipy.py", "common.py"):
            shutil.copy(os.path.join(PEERS, name), folder)
        subprocess.run([sys.executable, "work_precision_scipy.py", "--problems", problem], cwd=folder,
                       check=True, stdout=sys.stderr)
        with open(os.path.join(folder, "results", "work_precision.json")) as f:
            return json.load(f)
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def run_ours(build, problem):
    out = subprocess.run([os.path.join(build, "bench", "work_precision"), "10", problem], check=True,
                         stdout=subprocess.PIPE, stderr=subprocess.DEVNULL).stdout
    return json.loads(out)


def merge(into, part):
    into.setdefault("problems", {}).update(part.get("problems", {}))
    into.setdefault("rows", []).extend(part.get("rows", []))


def parse_peer_log(path):
    """Rows from the peer's progress lines (for a peer run that was cut short)."""
    import re
    rows = []
    pattern = re.compile(r"^\s+(\w+)\s+(\w+)\s+tol=(\S+) time=(\S+)s .*err_traj=(\S+)")
    for line in open(path):
        m = pattern.match(line)
        if m:
            rows.append({"problem": m.group(1), "method": m.group(2), "tol": float(m.group(3)),
                         "time_s": float(m.group(4)), "err_traj": float(m.group(5))})
    return {"problems": {}, "rows": rows}


def fastest(rows, problem, level, time_key):
    best = None
    for r in rows:
        if r.get("problem") != problem or r.get("err_traj") is None or r.get(time_key) is None:
            continue
        if r["err_traj"] <= level and (best is None or r[time_key] < best[time_key]):
            best = r
    return best


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(HERE, "..", "build"))
    ap.add_argument("--peer-json")
    ap.add_argument("--ours-json")
    ap.add_argument("--peer-log", help="the peer's printed progress, if its run was cut short")
    ap.add_argument("--save-json", metavar="PREFIX",
                    help="also write both sides' rows to PREFIX-ours.json and PREFIX-peer.json")
    a = ap.parse_args()
    # One problem at a time, ours and then the peer's, so that both sides of a problem are
    # timed within a minute or two of each other: the host's load changes over minutes.
    ours = json.load(open(a.ours_json)) if a.ours_json else {}
    if a.peer_log:
        peer = parse_peer_log(a.peer_log)
    else:
        peer = json.load(open(a.peer_json)) if a.peer_json else {}
    for problem in PROBLEMS:
        if not a.ours_json:
            merge(ours, run_ours(a.build, problem))
        if not a.peer_json and not a.peer_log:
            merge(peer, run_peer(problem))
    if a.save_json:
        for side, rows in (("ours", ours), ("peer", peer)):
            with open(f"{a.save_json}-{side}.json", "w") as f:
                json.dump(rows, f, indent=1)
    print("Work precision: fastest run whose max relative trajectory error (1001 samples) is within the level")
    print("(both sides the median of repeated runs: lagrange of those filling 0.1 s, at least 7; "
          "scipy solve_ivp of its script's 7, or 3 for runs of 0.2 s or more; "
          "method and tolerance setting in brackets;")
    print(" min ratio: the same with each side's fastest repeat instead of the median, "
          "the best case of both)")
    for problem in PROBLEMS:
        print(f"\n{problem}: reference ours = {ours['problems'][problem]['reference']}; "
              f"scipy = {peer['problems'].get(problem, {}).get('reference', 'see its docstring')}")
        print(f"  {'level':>6} {'lagrange_s':>11} {'':24} {'scipy_s':>9} {'':18} {'ratio':>7} {'min ratio':>9}")
        for e in range(3, 13):
            level = 10.0 ** -e
            o = fastest(ours["rows"], problem, level, "time_s")
            p = fastest(peer["rows"], problem, level, "time_s")
            om = fastest(ours["rows"], problem, level, "time_min_s")
            pm = fastest(peer["rows"], problem, level, "time_min_s")
            os_ = f"{o['time_s']:.2e}" if o else "-"
            ps = f"{p['time_s']:.2e}" if p else "-"
            on = f"[{o['method']} {o['tol']:.0e}]" if o else ""
            pn = f"[{p['method']} {p['tol']:.0e}]" if p else ""
            ratio = f"{p['time_s'] / o['time_s']:.0f}" if o and p else "-"
            min_ratio = f"{pm['time_min_s'] / om['time_min_s']:.0f}" if om and pm else "-"
            print(f"  {level:6.0e} {os_:>11} {on:24} {ps:>9} {pn:18} {ratio:>7} {min_ratio:>9}")

if __name__ == "__main__":
    main()
