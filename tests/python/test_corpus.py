# SPDX-License-Identifier: GPL-2.0-or-later
"""The corpus through Python against the command line, by value: for every example and test
scene, what `Scene.analyze()` gives (the default products, converted to SymPy and numpy) means
what the command line's JSON says. The JSON's expressions are parsed here on their own
(GiNaC's plain syntax read by SymPy's parser, every name a symbol) and both sides evaluated at
one random point; numbers compare as numbers."""
import json
import os
import random
import re

import numpy
import pytest
import sympy
from sympy.parsing.sympy_parser import parse_expr

from conftest import CLI

# GiNaC's names in plain output, as SymPy's; every other name is a symbol.
KNOWN = {"sin": sympy.sin, "cos": sympy.cos, "tan": sympy.tan, "sqrt": sympy.sqrt, "exp": sympy.exp,
         "log": sympy.log, "asin": sympy.asin, "acos": sympy.acos, "atan": sympy.atan, "sinh": sympy.sinh,
         "cosh": sympy.cosh, "tanh": sympy.tanh, "abs": sympy.Abs, "atan2": sympy.atan2, "Pi": sympy.pi,
         "I": sympy.I, "Euler": sympy.EulerGamma, "Catalan": sympy.Catalan}
IDENTIFIER = re.compile(r"(?<![0-9.])[A-Za-z_][A-Za-z_0-9]*")  # not the e of 1e-14


def independent(text, declared):
    """A JSON expression as SymPy, without the package's converter (None: not an expression);
    the scene's `declared` names are symbols even where GiNaC has a meaning for them (I)."""
    names = {}

    def rename(match):
        name = match.group(0)
        if name in KNOWN and name not in declared:
            return name
        names.setdefault(name, f"v{len(names)}_")
        return names[name]
    local = dict(KNOWN)
    renamed = IDENTIFIER.sub(rename, text)
    local.update({safe: sympy.Symbol(name) for name, safe in names.items()})
    try:
        return parse_expr(renamed.replace("^", "**"), local_dict=local, global_dict={"Integer": sympy.Integer,
                          "Float": sympy.Float, "Rational": sympy.Rational, "Symbol": sympy.Symbol})
    except Exception:
        return None


def point_value(name):
    """The random value of a symbol, fixed by its name (so both sides get the same)."""
    return random.Random("corpus:" + name).uniform(0.3, 1.3)


def number(expr):
    return complex(expr.xreplace({s: sympy.Float(point_value(s.name)) for s in expr.free_symbols}).evalf())


def same_value(cli, ours, where, differ, declared):
    """Records in `differ` each place where the command line's JSON value `cli` and the
    package's converted value `ours` mean different things."""
    if isinstance(cli, dict):
        if not isinstance(ours, dict) or set(cli) != set(ours):
            differ.append(f"{where}: keys")
            return
        for key in cli:
            same_value(cli[key], ours[key], f"{where}.{key}", differ, declared)
        return
    if isinstance(ours, sympy.MatrixBase):
        ours = ours.tolist()
    elif isinstance(ours, numpy.ndarray):
        ours = ours.tolist()
    if isinstance(cli, list):
        if isinstance(ours, list) and ours and isinstance(ours[0], sympy.MatrixBase):  # mode vectors
            ours = [list(v) for v in ours]
        if not isinstance(ours, list) or len(cli) != len(ours):
            differ.append(f"{where}: length")
            return
        for k, (a, b) in enumerate(zip(cli, ours)):
            same_value(a, b, f"{where}[{k}]", differ, declared)
        return
    if isinstance(cli, bool) or cli is None:
        if cli != ours:
            differ.append(f"{where}: {cli} and {ours}")
        return
    if isinstance(cli, (int, float)):
        if not isinstance(ours, (int, float)) or not (ours == cli or abs(ours - cli) <= 1e-15 * abs(cli)):
            differ.append(f"{where}: {cli} and {ours}")
        return
    if isinstance(ours, str):  # words, a note
        if ours != cli:
            differ.append(f"{where}: text")
        return
    theirs = independent(cli, declared)
    if theirs is None:
        differ.append(f"{where}: `{cli}` is no expression, but the package read one")
        return
    if isinstance(ours, sympy.Basic) and not isinstance(ours, sympy.Expr):  # a relation or a truth value
        ours = ours.lhs - ours.rhs if isinstance(ours, sympy.Equality) else ours
    try:
        a, b = number(theirs), number(sympy.sympify(ours))
    except (TypeError, ValueError, ZeroDivisionError, AttributeError):
        return  # not a number at the random point (a pole): nothing to compare there
    if not abs(a - b) <= 1e-12 * max(1.0, abs(a)):
        differ.append(f"{where}: {a} and {b}")


@pytest.mark.skipif(not os.access(CLI, os.X_OK), reason="needs the lagrange command (LAGRANGE_CLI, set by ctest)")
def test_analyze_means_what_the_command_lines_json_says(python_documents, cli_documents):
    import lagrange
    differ = []
    compared = 0
    for path, documents in sorted(python_documents.items()):
        if not path.endswith(".lag") or "json" not in cli_documents[path]:
            continue
        assert documents, f"{path}: the command line ran it, the module did not"
        cli = json.loads(cli_documents[path]["json"])
        # Scene.analyze() is this conversion of the module's JSON document (the session's
        # documents are the module's own, made once for this test and test_byte_identical.py)
        ours = lagrange.Scene.from_file(path)._convert(json.loads(documents[0]))
        assert list(ours) == list(cli), path
        same_value(cli, ours, os.path.basename(path), differ,
                   set(cli.get("coordinates", [])) | set(cli.get("parameters", [])))
        compared += 1
    assert compared >= 50
    assert differ == []
