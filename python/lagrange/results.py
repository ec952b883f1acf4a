# SPDX-License-Identifier: GPL-2.0-or-later
"""The results the engine returns to Python: SymPy expressions and matrices for symbolic
products, numpy arrays for numbers, each with ``_repr_latex_`` so that Jupyter renders it."""
import re

import numpy
import sympy

from .expressions import latex, latex_name, to_expr


def _display(lines):
    """A Jupyter LaTeX block: the lines aligned on their first ``&``."""
    if not lines:
        return r"$\text{(none)}$"
    return "$$\\begin{aligned}" + " \\\\ ".join(lines) + "\\end{aligned}$$"


def _text(words):
    """Text for \\text{...}: LaTeX's special characters escaped."""
    out = []
    for ch in str(words):
        if ch in "&%$#_{}":
            out.append("\\" + ch)
        elif ch == "\\":
            out.append(r"\textbackslash{}")
        elif ch in "^~":
            out.append(r"\text" + ("asciicircum" if ch == "^" else "asciitilde") + "{}")
        else:
            out.append(ch)
    return "".join(out)


_GREEK = {"alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta", "theta", "iota", "kappa", "lambda", "mu",
          "nu", "xi", "pi", "rho", "sigma", "tau", "upsilon", "phi", "chi", "psi", "omega", "Gamma", "Delta",
          "Theta", "Lambda", "Xi", "Pi", "Sigma", "Upsilon", "Phi", "Psi", "Omega"}
_SHORT_NAME = re.compile(r"[A-Za-z]{1,2}[0-9]*")


def _is_name(key):
    """True for what reads as a symbol (theta, p_phi, w1_dot, x, F0), not a word (mass, period)."""
    head = key.split("_", 1)[0]
    return head in _GREEK or bool(_SHORT_NAME.fullmatch(head))


def _label(key):
    known = {"T": "T", "V": "V", "G": "G", "C": "C", "A": "A", "B": "B", "H": "H",
             "routhian": "R", "effective_potential": r"V_{\mathrm{eff}}", "energy": "h",
             "lagrangian": "L", "kinetic_energy": "T", "potential_energy": "V"}
    if key in known:
        return known[key]
    if "->" in key:
        left, right = (part.strip() for part in key.split("->", 1))
        if _is_name(left) and _is_name(right):
            return "H_{" + latex_name(right) + latex_name(left) + "}(s)"
        return r"\text{" + _text(key) + "}"
    if _is_name(key):
        return latex_name(key)
    return r"\text{" + _text(key.replace("_", " ")) + "}"


class ExprList(list):
    """A list of SymPy expressions, rendered as ``label_i = expr`` (or ``expr = 0``)."""

    def __init__(self, items, label=None, equals_zero=False):
        super().__init__(items)
        self.label = label
        self.equals_zero = equals_zero

    def _repr_latex_(self):
        lines = []
        for i, e in enumerate(self, 1):
            if self.equals_zero:
                lines.append(latex(e) + " &= 0")
            else:
                lines.append(self.label.format(i=i) + " &= " + latex(e))
        return _display(lines)


class Equations(list):
    """SymPy equations (``sympy.Eq``), rendered one per line, aligned on ``=``."""

    def _repr_latex_(self):
        return _display([latex(e.lhs) + " &= " + latex(e.rhs) for e in self])


class ExprDict(dict):
    """Named SymPy expressions (``{name: expr}``), rendered as ``name = expr``; or named
    results (``{body: Result}``), rendered in turn."""

    def _repr_latex_(self):
        lines = []
        for k, v in self.items():
            if isinstance(v, Result):
                lines.append(r"\text{" + _text(k) + r":} &")
            lines.extend(_latex_lines(k, v))
        return _display(lines)


class Modes(list):
    """Mode vectors: one SymPy column Matrix per mode, in the order of the frequencies."""

    def _repr_latex_(self):
        return _display([f"A_{{{i}}} &= " + latex(v) for i, v in enumerate(self, 1)])


class Result:
    """A product with several parts: each part is an attribute and an item (``r.T`` and
    ``r["T"]``); ``keys()`` lists them in the engine's order and ``json`` keeps the JSON.
    A result with one main expression (``main``: the name of that part) converts to it
    with ``sympy.sympify(result)`` and shows it first in its ``repr``."""

    def __init__(self, item, parts, json=None, main=None):
        self.item = item
        self._parts = dict(parts)
        self.json = json
        self._main = main if main in self._parts else None

    def __getattr__(self, name):
        parts = self.__dict__.get("_parts", {})
        if name in parts:
            return parts[name]
        raise AttributeError(f"{self.item} has no part '{name}' (it has {', '.join(parts) or 'none'})")

    def __getitem__(self, key):
        return self._parts[key]

    def __contains__(self, key):
        return key in self._parts

    def __iter__(self):
        return iter(self._parts)

    def __len__(self):
        return len(self._parts)

    def keys(self):
        return self._parts.keys()

    def items(self):
        return self._parts.items()

    def get(self, key, default=None):
        return self._parts.get(key, default)

    def _sympy_(self):
        if self._main is None:
            raise sympy.SympifyError(f"{self.item} has no one main expression (it has {', '.join(self._parts)})")
        return self._parts[self._main]

    def __repr__(self):
        others = ", ".join(f"{k}={v!r}" for k, v in self._parts.items() if k != self._main)
        if self._main is None:
            return f"{type(self).__name__}({self.item}: {others})"
        return f"{type(self).__name__}({self._parts[self._main]}" + (f"; {others})" if others else ")")

    def _repr_latex_(self):
        lines = []
        for key, value in self._parts.items():
            lines.extend(_latex_lines(key, value))
        return _display(lines)


def _latex_lines(key, value):
    """LaTeX lines for one part of a result, whatever its type."""
    if isinstance(value, (sympy.Basic, sympy.MatrixBase)):
        return [_label(key) + " &= " + latex(value)]
    if isinstance(value, numpy.ndarray):
        return [_label(key) + " &= " + latex(sympy.Matrix(value) if value.ndim else sympy.Float(value.item()))]
    if isinstance(value, bool):
        return [r"\text{" + _text(key) + r"} &: \text{" + ("yes" if value else "no") + "}"]
    if isinstance(value, (int, float)):
        return [_label(key) + " &= " + latex(sympy.Float(value) if isinstance(value, float) else value)]
    if isinstance(value, str):
        return [r"\text{" + _text(key) + r"} &: " + latex(value)]
    if hasattr(value, "_repr_latex_"):
        inner = value._repr_latex_()
        if inner.startswith("$$\\begin{aligned}"):
            return [inner[len("$$\\begin{aligned}"):-len("\\end{aligned}$$")]]
        return [r"\text{" + _text(key) + r"} &: " + inner.strip("$")]
    if isinstance(value, dict):
        lines = []
        for k, v in value.items():
            lines.extend(_latex_lines(k, v))
        return lines
    if isinstance(value, (list, tuple)):
        if value and all(isinstance(v, str) for v in value):
            return [r"\text{" + _text(key) + r"} &: " + ", ".join(latex_name(v) for v in value)]
        if value and all(isinstance(v, (sympy.Basic, sympy.MatrixBase)) for v in value):
            return [_label(key) + "_{" + str(i) + "} &= " + latex(v) for i, v in enumerate(value, 1)]
        lines = []
        for v in value:
            lines.extend(_latex_lines(key, v))
        return lines
    return [r"\text{" + _text(key) + r"} &: " + latex(str(value))]


class ResultList(list):
    """A list of results (one per `values` point, one per body): renders each in turn."""

    def _repr_latex_(self):
        lines = []
        for r in self:
            inner = r._repr_latex_()
            lines.append(inner[len("$$\\begin{aligned}"):-len("\\end{aligned}$$")]
                         if inner.startswith("$$\\begin{aligned}") else inner.strip("$"))
        return _display(lines)


# ---- conversion of the JSON values -------------------------------------------------------

class Converter:
    """Turns JSON values of one document into SymPy and numpy, with the scene's names."""

    def __init__(self, names):
        self.names = tuple(names)

    def expr(self, text):
        return to_expr(text, self.names)

    def exprs(self, texts):
        return [self.expr(t) for t in texts]

    def matrix(self, rows):
        return sympy.Matrix([[self.expr(x) for x in row] for row in rows]) if rows else sympy.zeros(0, 0)

    def value(self, value, key=None):
        """Any JSON value: strings as expressions (or kept as text when they are not one, or
        under a key that holds words), numbers and lists of numbers as numpy, dicts and lists
        recursively."""
        if isinstance(value, str):
            if key in TEXT_KEYS:
                return value
            try:
                return self.expr(value)
            except Exception:  # a sentence (a note, how something was checked): kept as text
                return value
        if isinstance(value, bool) or value is None:
            return value
        if isinstance(value, (int, float)):
            return value
        if isinstance(value, list):
            if value and all(_is_number(x) for x in value):
                return numpy.array(value, dtype=float)
            if value and all(isinstance(x, list) and x and all(_is_number(y) for y in x) for x in value):
                if len({len(x) for x in value}) == 1:
                    return numpy.array(value, dtype=float)
            if key not in TEXT_KEYS and value and all(isinstance(x, list) and x and all(isinstance(y, str) for y in x)
                                                      for x in value):
                if key == "modes":  # mode vectors: one column each
                    return Modes([sympy.Matrix(self.exprs(m)) for m in value])
                if len({len(x) for x in value}) == 1:
                    return self.matrix(value)
            return [self.value(x, key) for x in value]
        if isinstance(value, dict):
            return {k: self.value(v, k) for k, v in value.items()}
        return value


def _is_number(x):
    return isinstance(x, (int, float)) and not isinstance(x, bool)


# JSON keys whose strings are words or names, never expressions.
TEXT_KEYS = {"kind", "regime", "coordinates", "method", "choice", "error_basis", "evaluation", "stability",
             "quantity", "note", "notes", "scene", "stages", "state", "inputs", "momenta", "parameters",
             "multiplier_changes_sign", "name", "proportional", "reason", "how", "coordinate", "constraint"}


def complex_array(pairs):
    """[[re, im], ...] as a complex numpy array."""
    return numpy.array([complex(re, im) for re, im in pairs], dtype=complex)


class Characteristic(Result):
    """The characteristic polynomial: ``polynomial`` (SymPy) in ``variable``, rendered ``p = 0``;
    ``sympy.sympify`` gives the polynomial."""

    def __init__(self, item, parts, json=None):
        super().__init__(item, parts, json, main="polynomial")

    def _repr_latex_(self):
        return "$$" + latex(self._parts["polynomial"]) + " = 0$$"


class EquationsOf(dict):
    """Equations by coordinate (``{coordinate: expr}``, each expr = 0), rendered ``expr = 0``."""

    def _repr_latex_(self):
        return _display([latex(v) + r" &= 0 && (" + latex_name(k) + ")" for k, v in self.items()])
