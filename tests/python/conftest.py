# SPDX-License-Identifier: GPL-2.0-or-later
"""Shared fixtures of the Python tests: the example scenes, loaded once per test session."""
import glob
import os
import subprocess
import sys

import pytest

EXAMPLES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples")


@pytest.fixture(scope="session")
def example():
    import lagrange
    loaded = {}

    def load(name):
        if name not in loaded:
            loaded[name] = lagrange.Scene.from_file(os.path.join(EXAMPLES, name))
        return loaded[name]
    return load


ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
CLI = os.environ.get("LAGRANGE_CLI", "")
FORMATS = ("json", "text", "latex")


def corpus():
    """The examples, the test scenes and the fuzz seeds, sorted."""
    paths = glob.glob(os.path.join(ROOT, "examples", "*.lag")) + glob.glob(os.path.join(ROOT, "tests", "scenes", "*.lag"))
    paths += glob.glob(os.path.join(ROOT, "fuzz", "seeds", "*"))
    return sorted(os.path.normpath(p) for p in paths if os.path.isfile(p))


# Each scene's documents in one process, in the order given; a scene that does not parse,
# or whose analysis fails, gives an empty record (the command line's exit code is then
# not 0 either, and the tests leave it out).
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


@pytest.fixture(scope="session")
def python_documents():
    """Every corpus scene's documents (json, text, latex) from the module in one process:
    test_byte_identical.py and test_corpus.py both read them, so each scene runs once."""
    return documents_in_one_process(corpus())


@pytest.fixture(scope="session")
def cli_documents():
    """Every corpus scene's documents from the command line: {path: {format: stdout}}, the
    formats whose run exited 0."""
    documents = {}
    for path in corpus():
        documents[path] = {}
        for fmt in FORMATS:
            run = subprocess.run([CLI, path, "--format", fmt], capture_output=True)
            if run.returncode == 0:
                documents[path][fmt] = run.stdout.decode()
    return documents
