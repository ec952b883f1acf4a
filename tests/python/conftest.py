# SPDX-License-Identifier: GPL-2.0-or-later
"""Shared fixtures of the Python tests: the example scenes, loaded once per test session."""
import os

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
