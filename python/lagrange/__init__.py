# SPDX-License-Identifier: GPL-2.0-or-later
"""lagrange in Python: the engine runs in process and returns SymPy expressions and numpy
arrays.

    >>> import lagrange
    >>> scene = lagrange.Scene.from_file("examples/double_pendulum.lag")
    >>> scene.characteristic().polynomial
    M*l**2*omega**4 + g**2*(M + m) - g*l*omega**2*(2*M + 2*m)

See docs/python.md.
"""
import os as _os
import sys as _sys

from ._build import PYTHON as _BUILT_FOR, VERSION as _BUILT_VERSION


def _import_error(error):
    """An ImportError that says which interpreter the module was built for, when another one
    imports it (a pyenv shim or a virtual environment first on PATH lacks Debian's numpy)."""
    if _os.path.realpath(_sys.executable) == _os.path.realpath(_BUILT_FOR):
        return error
    return ImportError(
        f"lagrange was built for {_BUILT_FOR} (Python {_BUILT_VERSION}), but this is {_sys.executable} "
        f"(Python {_sys.version.split()[0]}), which cannot import it: {error}. Run {_BUILT_FOR}, or build the "
        f"module for this interpreter with `cmake -S . -B build -DPython3_EXECUTABLE={_sys.executable}` "
        "(it needs numpy, sympy and pybind11 installed for that interpreter); see docs/python.md.")


try:
    import numpy as _numpy  # noqa: F401  (the first of the package's dependencies)
    import sympy as _sympy  # noqa: F401
    from . import _lagrange
except ImportError as _error:
    raise _import_error(_error) from _error

from .errors import BudgetExceeded, ComputationError, LagrangeError, SceneError, SceneWarning
from .expressions import latex_name, to_expr
from .scene import Scene

__version__ = _lagrange.__version__

products = _lagrange.products

__all__ = ["Scene", "SceneError", "SceneWarning", "ComputationError", "BudgetExceeded", "LagrangeError", "to_expr",
           "latex_name", "products", "__version__"]
