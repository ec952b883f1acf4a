# SPDX-License-Identifier: GPL-2.0-or-later
"""What docs/python.md promises about bytes: with address-space randomization on, as
Python runs, scene.document() gives the command line's output byte for byte, in every
process, whatever scenes the process analysed before (the engine orders terms, signs
and roots canonically, never by addresses or symbol serials)."""
import os

import pytest

from conftest import CLI, FORMATS, ROOT, corpus, documents_in_one_process


def randomized():
    try:
        with open("/proc/sys/kernel/randomize_va_space") as f:
            return f.read().strip() != "0"
    except OSError:
        return False


@pytest.fixture(scope="module")
def two_processes(python_documents):
    """Every scene's documents from two processes, the second in reverse order (so with
    other symbol serials and, under randomization, another address layout)."""
    return python_documents, documents_in_one_process(list(reversed(corpus())))


def test_the_corpus_is_there():
    assert len(corpus()) >= 60


def test_documents_are_the_same_in_every_process(two_processes):
    first, second = two_processes
    differ = [path for path in first if first[path] != second.get(path)]
    assert differ == [], f"documents differ between processes (randomization {'on' if randomized() else 'off'})"


@pytest.mark.skipif(not os.access(CLI, os.X_OK), reason="needs the lagrange command (LAGRANGE_CLI, set by ctest)")
def test_documents_are_the_command_lines_bytes(two_processes, cli_documents):
    first, _ = two_processes
    differ = []
    compared = 0
    for path, documents in first.items():
        if not documents:
            continue
        for fmt, document in zip(FORMATS, documents):
            if fmt not in cli_documents[path]:
                continue
            compared += 1
            if cli_documents[path][fmt] != document:
                differ.append(f"{os.path.relpath(path, ROOT)} --format {fmt}")
    assert compared >= 100
    assert differ == []
