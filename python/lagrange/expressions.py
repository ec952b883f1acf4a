# SPDX-License-Identifier: GPL-2.0-or-later
"""From the engine's expression strings (GiNaC's plain syntax, as in the JSON documents) to
SymPy, and LaTeX names as the engine prints them."""
import keyword
import re

import sympy
from sympy.parsing.sympy_parser import convert_xor, parse_expr, standard_transformations

# The functions and constants GiNaC prints, by the name it prints them with.
_GINAC_NAMES = {
    "sin": sympy.sin, "cos": sympy.cos, "tan": sympy.tan,
    "asin": sympy.asin, "acos": sympy.acos, "atan": sympy.atan, "atan2": sympy.atan2,
    "sinh": sympy.sinh, "cosh": sympy.cosh, "tanh": sympy.tanh,
    "asinh": sympy.asinh, "acosh": sympy.acosh, "atanh": sympy.atanh,
    "exp": sympy.exp, "log": sympy.log, "sqrt": sympy.sqrt, "abs": sympy.Abs,
    "csgn": sympy.sign, "step": sympy.Heaviside, "factorial": sympy.factorial,
    "Pi": sympy.pi, "I": sympy.I, "Euler": sympy.EulerGamma, "Catalan": sympy.Catalan,
}
_IDENTIFIER = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
_TRANSFORMATIONS = standard_transformations + (convert_xor,)
_SYMBOLS = {}


def symbol(name):
    """The SymPy symbol of an engine name (plain, no assumptions: ``sympy.Symbol('theta')``
    is the same symbol)."""
    found = _SYMBOLS.get(name)
    if found is None:
        found = _SYMBOLS[name] = sympy.Symbol(name)
    return found


def to_expr(text, names=()):
    """A SymPy expression from an engine expression string: ``^`` is a power, ``theta_dot``
    and ``theta_ddot`` are symbols, and every other name is a plain Symbol unless it is a
    function or constant GiNaC prints (sin, cos, exp, sqrt, Pi, I, ...). ``names`` (the
    scene's coordinates and parameters) are always symbols, so a parameter called ``I`` or
    ``gamma`` stays one."""
    if not isinstance(text, str):
        return sympy.sympify(text)
    declared = set(names)
    local = {}
    found = set(_IDENTIFIER.findall(text))
    # A scene's name may be a Python keyword (`lambda`, `is`, `None`), which Python's
    # tokenizer under parse_expr cannot take as a name: it is parsed under a stand-in.
    reserved = sorted(name for name in found if keyword.iskeyword(name) or keyword.issoftkeyword(name))
    if reserved:
        text = re.sub(r"\b(" + "|".join(reserved) + r")\b", r"_lagrange_name_\1", text)
    for name in found:
        key = "_lagrange_name_" + name if name in reserved else name
        if name in declared or name not in _GINAC_NAMES:
            local[key] = symbol(name)
        else:
            local[key] = _GINAC_NAMES[name]
    # A global namespace of SymPy's number classes only: every name in the string is in `local`.
    return parse_expr(text, local_dict=local, global_dict={"Integer": sympy.Integer, "Float": sympy.Float,
                                                           "Rational": sympy.Rational, "Symbol": sympy.Symbol},
                      transformations=_TRANSFORMATIONS)


def latex_name(name):
    r"""LaTeX of an engine name, as the engine prints it: ``theta_dot`` -> ``\dot{\theta}``,
    ``phi_ddot`` -> ``\ddot{\phi}``, ``theta1`` -> ``\theta_{1}``, ``p_phi`` -> ``p_{\phi}``."""
    for suffix, accent in (("_ddot", r"\ddot"), ("_dot", r"\dot")):
        if name.endswith(suffix) and len(name) > len(suffix):
            return accent + "{" + sympy.latex(sympy.Symbol(name[: -len(suffix)])) + "}"
    return sympy.latex(sympy.Symbol(name))


def latex(value):
    """LaTeX of a SymPy expression or matrix, with the engine's names (dots over velocities)."""
    if isinstance(value, str):
        from .results import _text
        return r"\text{" + _text(value) + "}"
    if not isinstance(value, sympy.Basic) and not isinstance(value, sympy.MatrixBase):
        value = sympy.sympify(value)
    names = {s: latex_name(s.name) for s in value.free_symbols if isinstance(s, sympy.Symbol)}
    return sympy.latex(value, symbol_names=names)
