# SPDX-License-Identifier: GPL-2.0-or-later
"""What docs/python.md promises about bytes: with address-space randomization on, as
Python runs, scene.document() gives the command line's output byte for byte, in every
process, whatever scenes the process analysed before (the engine orders terms, signs
and roots canonically, never by addresses or symbol serials)."""
import glob
import os
import subprocess
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
CLI = os.environ.get("LAGRANGE_CLI", "")
FORMATS = ("json", "text", "latex")


def corpus():
    """The examples, the test scenes and the fuzz seeds, sorted."""
    paths = glob.glob(os.path.join(ROOT, "examples", "*.lag")) + glob.glob(os.path.join(ROOT, "tests", "scenes", "*.lag"))
    paths += glob.glob(os.path.join(ROOT, "fuzz", "seeds", "*"))
    return sorted(os.path.normpath(p) for p in paths if os.path.isfile(p))


# Each scene's documents in one process, in the order given; a scene that does not parse,
# or whose analysis fails, gives an empty record (the command line's exit code is then
# not 0 either, and the test leaves it out).
PRINT_DOCUMENTS = r"""
import sys, lagrange
for path in sys.argv[1:]:
    try:
        scene = lagrange.Scene.from_file(path)
        documents = [scene.document(fmt) for fmt in ("json", "text", "latex")]
    except Exception:
        documents = []
    sys.stdout.write(path + "\0" + "\0".join(documents) + "\1")
"""


def documents_in_one_process(paths):
    out = subprocess.run([sys.executable, "-c", PRINT_DOCUMENTS, *paths], check=True, capture_output=True,
                         env=dict(os.environ)).stdout.decode()
    records = {}
    for record in out.split("\1")[:-1]:
        path, *documents = record.split("\0")
        records[path] = documents if documents != [""] else []
    return records


def randomized():
    try:
        with open("/proc/sys/kernel/randomize_va_space") as f:
            return f.read().strip() != "0"
    except OSError:
        return False


@pytest.fixture(scope="module")
def two_processes():
    """Every scene's documents from two processes, the second in reverse order (so with
    other symbol serials and, under randomization, another address layout)."""
    paths = corpus()
    return documents_in_one_process(paths), documents_in_one_process(list(reversed(paths)))


def test_the_corpus_is_there():
    assert len(corpus()) >= 60


def test_documents_are_the_same_in_every_process(two_processes):
    first, second = two_processes
    differ = [path for path in first if first[path] != second.get(path)]
    assert differ == [], f"documents differ between processes (randomization {'on' if randomized() else 'off'})"


@pytest.mark.skipif(not os.access(CLI, os.X_OK), reason="needs the lagrange command (LAGRANGE_CLI, set by ctest)")
def test_documents_are_the_command_lines_bytes(two_processes):
    first, _ = two_processes
    differ = []
    compared = 0
    for path, documents in first.items():
        if not documents:
            continue
        for fmt, document in zip(FORMATS, documents):
            run = subprocess.run([CLI, path, "--format", fmt], capture_output=True)
            if run.returncode != 0:
                continue
            compared += 1
            if run.stdout.decode() != document:
                differ.append(f"{os.path.relpath(path, ROOT)} --format {fmt}")
    assert compared >= 100
    assert differ == []
