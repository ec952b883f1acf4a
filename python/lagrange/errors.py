# SPDX-License-Identifier: GPL-2.0-or-later
"""The exceptions of the lagrange package: the library's errors, raised in Python."""


class LagrangeError(Exception):
    """Base class of the errors the engine reports."""


class SceneError(LagrangeError):
    """Bad input in a scene, at a position: ``file``, ``line`` and ``column`` (1-based,
    the column counts code points) and the ``message``. ``str()`` of it is the command
    line's report: ``FILE:LINE:COL: error: MESSAGE``, the line and a caret."""

    def __init__(self, file, line, column, message, formatted=None):
        self.file = file
        self.line = line
        self.column = column
        self.message = message
        self.formatted = formatted or f"{file}:{line}:{column}: error: {message}\n"
        super().__init__(self.formatted.rstrip("\n"))


class SceneWarning(UserWarning):
    """A likely slip in a valid scene (a kinetic energy without velocities), issued with
    ``warnings.warn`` when the scene is loaded; its text is the command line's
    ``FILE:LINE:COL: warning: MESSAGE``, the line and a caret."""


class ComputationError(LagrangeError):
    """The computation cannot be done (no equilibrium, singular kinetic matrix, ...):
    exit code 1 at the command line. ``message`` says why."""

    def __init__(self, message):
        self.message = message
        super().__init__(message)


class BudgetExceeded(ComputationError):
    """A symbolic stage ran out of its size or time budget (``max_terms``,
    ``max_seconds``); ``stage`` names it."""

    def __init__(self, message, stage=""):
        super().__init__(message)
        self.stage = stage
