#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The peer of bench/animate.sh: the frames of a `lagrange animate` page (its embedded
positions, rods and markers) drawn with matplotlib (Agg, 640 × 480) as a user would draw an
animation, each frame's pixels taken from the canvas, as matplotlib's FFMpegWriter does;
the pixels are handed to nothing, so that only the drawing is timed.

    animate_matplotlib.py PLAYER.html

Prints one line: `seconds frames`."""
import json
import re
import sys
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    page = open(sys.argv[1], encoding="utf-8").read()
    data = json.loads(re.search(r'<script id="lagrange-data" type="application/json">(.*?)</script>', page, re.S).group(1))
    markers, positions = data["markers"], data["positions"]
    m, frames = len(markers), len(data["times"])
    xs = [positions[k * 3] for k in range(m * frames)]
    ys = [positions[k * 3 + 1] for k in range(m * frames)]
    began = time.perf_counter()
    figure = plt.figure(figsize=(6.4, 4.8), dpi=100)
    axes = figure.add_axes([0, 0, 1, 1])
    axes.set_xlim(min(xs) - 0.2, max(xs) + 0.2)
    axes.set_ylim(min(ys) - 0.2, max(ys) + 0.2)
    axes.set_aspect("equal")
    axes.axis("off")
    rods = [axes.plot([], [], color="#444444", lw=3)[0] for _ in data["rods"]]
    points = [k for k in range(m) if markers[k]["point"]]
    discs = axes.scatter([0] * len(points), [0] * len(points), s=300, color="#d62728", zorder=3)
    clock = axes.text(0.02, 0.03, "", transform=axes.transAxes)
    for f in range(frames):
        at = lambda k: (positions[(f * m + k) * 3], positions[(f * m + k) * 3 + 1])  # noqa: E731
        for line, (a, b) in zip(rods, data["rods"]):
            line.set_data([at(a)[0], at(b)[0]], [at(a)[1], at(b)[1]])
        discs.set_offsets([at(k) for k in points])
        clock.set_text(f"t = {data['times'][f]:.2f}")
        figure.canvas.draw()
        figure.canvas.buffer_rgba()
    seconds = time.perf_counter() - began
    print(f"{seconds:.3f} {frames}")


if __name__ == "__main__":
    main()
