# SPDX-License-Identifier: GPL-2.0-or-later
"""lagrange in Python: the engine runs in process and returns SymPy expressions and numpy
arrays.

    >>> import lagrange
    >>> scene = lagrange.Scene.from_file("examples/double_pendulum.lag")
    >>> scene.characteristic().polynomial
    M*l**2*omega**4 + g**2*(M + m) - g*l*omega**2*(2*M + 2*m)

See docs/python.md.
"""
from . import _lagrange
from .errors import BudgetExceeded, ComputationError, LagrangeError, SceneError
from .expressions import latex_name, to_expr
from .scene import Scene

__version__ = _lagrange.__version__

products = _lagrange.products

__all__ = ["Scene", "SceneError", "ComputationError", "BudgetExceeded", "LagrangeError", "to_expr",
           "latex_name", "products", "__version__"]
