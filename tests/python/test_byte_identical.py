# SPDX-License-Identifier: GPL-2.0-or-later
"""What docs/python.md promises about bytes: with address randomization off (setarch -R),
scene.document() gives the command line's output byte for byte, in every process."""
import os
import shutil
import subprocess
import sys

import pytest

import lagrange

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLES = os.path.join(HERE, "..", "..", "examples")
SCENES = ["double_pendulum.lag", "elastic_pendulum.lag", "compound_double_pendulum.lag", "penning_trap.lag"]
CLI = os.environ.get("LAGRANGE_CLI", "")

# Each scene's JSON document (everything the scene supports) and its text, in one process.
PRINT_DOCUMENTS = r"""
import sys, lagrange
for path in sys.argv[1:]:
    scene = lagrange.Scene.from_file(path)
    sys.stdout.write(scene.document("json") + "\0" + scene.document("text") + "\0")
"""


def fixed_layout_python(*args):
    return subprocess.run(["setarch", "-R", sys.executable, "-c", *args], check=True, capture_output=True,
                          env=dict(os.environ)).stdout


@pytest.mark.skipif(shutil.which("setarch") is None, reason="setarch (util-linux) is missing")
def test_fixed_layout_is_reported():
    out = fixed_layout_python("import lagrange; print(lagrange.address_layout_fixed())")
    assert out.strip() == b"True"
    with open("/proc/sys/kernel/randomize_va_space") as f:
        randomized = f.read().strip() != "0"
    assert lagrange.address_layout_fixed() == (not randomized)


@pytest.mark.skipif(shutil.which("setarch") is None or not os.access(CLI, os.X_OK),
                    reason="needs setarch and the lagrange command (LAGRANGE_CLI, set by ctest)")
def test_documents_are_the_command_lines_bytes():
    paths = [os.path.join(EXAMPLES, s) for s in SCENES]
    first = fixed_layout_python(PRINT_DOCUMENTS, *paths)
    second = fixed_layout_python(PRINT_DOCUMENTS, *paths)
    assert first == second
    expected = b""
    for path in paths:
        for fmt in ("json", "text"):
            expected += subprocess.run([CLI, path, "--format", fmt], check=True, capture_output=True).stdout + b"\0"
    assert first == expected
