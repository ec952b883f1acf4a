# SPDX-License-Identifier: GPL-2.0-or-later
"""Scene: a loaded scene file, and one method per product of the engine."""
import json
import os
import re
import warnings

import numpy
import sympy

from . import _lagrange
from .errors import ComputationError, SceneWarning
from .results import (Characteristic, Converter, Equations, EquationsOf, ExprDict, ExprList, Modes, Result, ResultList, _text, complex_array)


def _number(value):
    """A value as the scene language reads it: numbers round-trip (repr), expressions in
    SymPy's syntax get ``^`` for powers."""
    if isinstance(value, bool):
        raise TypeError("a value must be a number or an expression, not a bool")
    if isinstance(value, (int, numpy.integer)):
        return str(int(value))
    if isinstance(value, (float, numpy.floating)):
        return repr(float(value))
    return str(value).replace("**", "^")


def _entry(name, value, argument):
    """One `name=value` entry of a dict argument. The name must be one name and the value
    one expression: a separator in either would be read as more entries (``{"m": "1, g=9"}``
    would set g)."""
    if not isinstance(name, str) or not _NAME.fullmatch(name):
        raise ValueError(f"{argument}: {name!r} is not a name")
    text = _number(value)
    if any(c in text for c in ",=;\n\r"):
        raise ValueError(f"{argument}: the value of {name} must be one number or expression, not {text!r}")
    return f"{name}={text}"


_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*'?")


def _values_lines(values):
    """`values` points as the engine reads them ("a=1,b=2"): from a dict, a string, or a
    list of either (several points)."""
    if values is None:
        return []
    if isinstance(values, (str, dict)):
        values = [values]
    lines = []
    for point in values:
        if isinstance(point, str):
            lines.append(point)
        else:
            lines.append(",".join(_entry(name, v, "values") for name, v in point.items()))
    return lines


def _initial_lines(initial, coordinates):
    """Initial values as the engine reads them ("theta=0.1, phi'=0"): from a dict, whose keys
    name a coordinate (its position) or the coordinate with ``'`` or ``_dot`` (its velocity),
    or from a string in the scene's syntax."""
    if initial is None:
        return []
    if isinstance(initial, str):
        return [initial]
    if not isinstance(initial, dict):
        raise TypeError("initial must be a dict {\"theta\": 0.1, \"theta'\": 0} or a string \"theta=0.1, theta'=0\"")
    entries = []
    for name, value in initial.items():
        if isinstance(name, str) and name.endswith("_dot") and name[:-len("_dot")] in coordinates:
            name = name[:-len("_dot")] + "'"
        entries.append(_entry(name, value, "initial"))
    return [", ".join(entries)] if entries else []


def _check_settings(settings):
    """The numeric settings of a run, checked here so that an error names the argument."""
    until = settings.get("until")
    if until is not None and not (isinstance(until, (int, float, numpy.integer, numpy.floating))
                                  and not isinstance(until, bool) and 0 < until < float("inf")):
        raise ValueError(f"until must be a positive, finite end time (got {until!r})")
    tolerance = settings.get("tolerance")
    if tolerance is not None and not (isinstance(tolerance, (int, float, numpy.integer, numpy.floating))
                                      and not isinstance(tolerance, bool) and 1e-14 <= tolerance < 1):
        raise ValueError(f"tolerance must lie in 1e-14 … 1 (got {tolerance!r})")
    for name in ("max_terms", "max_seconds"):
        value = settings.get(name)
        if value is not None and not (isinstance(value, (int, float, numpy.integer, numpy.floating))
                                      and not isinstance(value, bool) and 0 < value < float("inf")):
            raise ValueError(f"{name} must be a positive, finite number (got {value!r})")


class Scene:
    """A scene, parsed and checked. Each product method runs the engine in this process
    (only the stages the product needs) and returns SymPy expressions and numpy arrays;
    results are kept, so asking twice costs nothing.

    Errors: SceneError (bad input, with .file .line .column .message) when loading or for
    bad values; ComputationError when a product cannot be computed."""

    def __init__(self, model):
        self._model = model
        self._documents = {}
        for text in model.warnings:
            warnings.warn(text.rstrip("\n"), SceneWarning, stacklevel=3)

    # ---- loading -------------------------------------------------------------------
    @classmethod
    def from_file(cls, path, max_seconds=30):
        """Loads a scene file; `use "x.rules"` lines are read relative to its folder. The
        file is read as the command line reads it: at most 64 MiB, and a pipe or device
        that gives no data for ``max_seconds`` is refused (OSError)."""
        path = os.fspath(path)
        _check_settings({"max_seconds": max_seconds})
        text = _lagrange.read_scene(path, float(max_seconds))
        return cls(_lagrange.load(path, text))

    @classmethod
    def from_text(cls, text, name="<text>"):
        """Loads a scene from a string; `name` is the file name errors give."""
        return cls(_lagrange.load(name, text))

    # ---- what the scene declares -----------------------------------------------------
    @property
    def title(self):
        return self._model.title

    @property
    def file(self):
        return self._model.file

    @property
    def coordinates(self):
        """Coordinate names, in declared order."""
        return list(self._model.coordinates)

    @property
    def parameters(self):
        """Parameter names, in declared order."""
        return list(self._model.parameters)

    def __repr__(self):
        return f"Scene({self.title or self.file!r}, coordinates={self.coordinates}, parameters={self.parameters})"

    # ---- the engine --------------------------------------------------------------------
    def document(self, format="text", want=(), values=None, initial=None, timings=False, **settings):
        """The whole document as the command line writes it: ``format`` is "text", "latex"
        (a complete LaTeX document) or "json"; ``want`` a list of items (empty: the scene's
        `want` line or everything it supports). ``values``: a dict ``{"m": 1}``, a string
        "m=1,l=2" or a list of them, replacing the scene's `values` lines; ``initial``: a dict
        ``{"theta": 0.1, "theta'": 0}`` (or ``theta_dot``) or a string "theta=0.1, theta'=0",
        replacing the scene's `initial` entries it names. ``settings``: until, method,
        tolerance, estimate_error, native, max_terms, max_seconds, project_initial (as the
        command-line options)."""
        if isinstance(want, str):
            want = [want]
        _check_settings(settings)
        return self._model.document(format, want=list(want), values=_values_lines(values),
                                    initial=_initial_lines(initial, self.coordinates), timings=timings, **settings)

    def analyze(self, *want, values=None, initial=None, **settings):
        """The JSON document of the products `want` (every product the scene supports if
        none), as a dict with its expressions converted: SymPy for strings, numpy for
        numbers. The product methods below pick their parts out of it."""
        return self._convert(self._json(want, values, settings, initial))

    def _json(self, want, values=None, settings=None, initial=None):
        settings = dict(settings or {})
        key = (tuple(want), tuple(_values_lines(values)), tuple(_initial_lines(initial, self.coordinates)),
               tuple(sorted(settings.items())))
        if key not in self._documents:
            text = self.document("json", want=list(want), values=values, initial=initial, **settings)
            self._documents[key] = json.loads(text)
        return self._documents[key]

    def _converter(self, doc):
        names = list(doc.get("coordinates", [])) + list(doc.get("parameters", []))
        return Converter(names)

    def _convert(self, doc):
        c = self._converter(doc)
        return {k: (v if k in ("scene", "coordinates", "parameters", "stages", "notes", "timings")
                    else c.value(v, k)) for k, v in doc.items()}

    def _parts(self, product, keys, values=None, settings=None, optional=(), initial=None):
        doc = self._json((product,), values, settings, initial)
        c = self._converter(doc)
        missing = [k for k in keys if k not in doc and k not in optional]
        if missing:
            notes = "; ".join(doc.get("notes", []))
            raise ComputationError(f"the engine gave no {', '.join(missing)} for `{product}`"
                                   + (f" ({notes})" if notes else ""))
        return doc, c

    # ---- products ----------------------------------------------------------------------
    def equations(self):
        """The Euler–Lagrange equations, one SymPy expression per coordinate, each = 0
        (``theta_ddot``, ``theta_dot`` are the acceleration and velocity symbols)."""
        doc, c = self._parts("equations", ["equations"])
        return ExprList(c.exprs(doc["equations"]), equals_zero=True)

    def lagrangian(self):
        """L = T − V (with ``kinetic_energy`` and ``potential_energy`` when the scene has them)."""
        doc, c = self._parts("equations", ["lagrangian"])
        return Result("lagrangian", {k: c.expr(doc[k]) for k in ("lagrangian", "kinetic_energy", "potential_energy")
                                     if k in doc}, doc, main="lagrangian")

    def equilibrium(self):
        """The equilibrium point ``{coordinate: expr}`` and its ``stability``."""
        doc, c = self._parts("equilibrium", ["equilibrium"])
        parts = {"equilibrium": ExprDict({k: c.expr(v) for k, v in doc["equilibrium"].items()})}
        if "stability" in doc:
            parts["stability"] = doc["stability"]
        return Result("equilibrium", parts, doc)

    def linearization(self):
        """The matrices ``T`` and ``V`` (SymPy) of the small oscillations at the equilibrium;
        ``G`` (gyroscopic) and ``C`` (damping) too when the scene has them."""
        doc, c = self._parts("linearization", ["T", "V"])
        parts = {k: c.matrix(doc[k]) for k in ("T", "V") if k in doc}
        for key, name in (("gyroscopic", "G"), ("damping", "C")):
            if key in doc:
                parts[name] = c.matrix(doc[key])
        return Result("linearization", parts, doc)

    def characteristic(self):
        """The characteristic polynomial det(V − ω²T) made primitive: ``.polynomial`` (SymPy)
        in ``.variable`` (the symbol omega)."""
        doc, c = self._parts("characteristic", ["characteristic"])
        ch = doc["characteristic"]
        return Characteristic("characteristic", {"polynomial": c.expr(ch["polynomial"]),
                                         "variable": c.expr(ch["variable"])}, doc)

    def frequencies(self):
        """ω² of each mode (ω itself where the scene is gyroscopic), SymPy, ascending where
        the order is known."""
        doc, c = self._parts("frequencies", ["frequencies"])
        label = r"\omega_{{{i}}}" if "gyroscopic" in doc else r"\omega_{{{i}}}^{{2}}"
        return ExprList(c.exprs(doc["frequencies"]), label=label)

    def modes(self):
        """The mode vectors, one SymPy column Matrix per mode, in the order of the frequencies."""
        doc, c = self._parts("modes", ["modes"])
        return Modes([sympy.Matrix(c.exprs(m)) for m in doc["modes"]])

    def normal_coordinates(self):
        """ζ of each mode as a combination of the coordinates (SymPy)."""
        doc, c = self._parts("normal_coordinates", ["normal_coordinates"])
        return ExprList(c.exprs(doc["normal_coordinates"]), label=r"\zeta_{{{i}}}")

    def asymptotic(self):
        """Frequencies and modes in each `limit` of the scene: ``{"rho -> 0": Result}``."""
        doc, c = self._parts("asymptotic", ["asymptotic"])
        return ExprDict({limit: Result("asymptotic", c.value(v), v) for limit, v in doc["asymptotic"].items()})

    def numeric(self, values=None, **settings):
        """Frequencies and modes at parameter values: one Result per point with ``values``
        (dict), ``omega`` (ascending, numpy), ``modes`` (numpy; mode i is ``modes[i]``,
        normalized so that Aᵀ T A = I), ``error`` (estimated relative error of each ω) and,
        with damping, ``eigenvalues`` (complex numpy) and ``damping_ratio``; where a mode grows
        (unstable), ``growth_rate`` (the rate γ of each mode, 0 for the others; its ``omega``
        entry is −γ) and ``stability``. ``values``: a
        dict ``{"m": 1, ...}``, a string "m=1,l=2" or a list of them (several points); they
        replace the scene's `values` lines."""
        doc, c = self._parts("numeric", ["numeric"], values, settings)
        points = []
        for p in doc["numeric"]:
            parts = {}
            for k, v in p.items():
                if k == "eigenvalues":
                    parts[k] = complex_array(v)
                elif k == "values":
                    parts[k] = {name: c.value(x) for name, x in v.items()}
                else:
                    parts[k] = c.value(v, k)
            points.append(Result("numeric", parts, p))
        return ResultList(points)

    def simulate(self, until=None, method=None, tolerance=None, values=None, initial=None, estimate_error=True,
                 native=True, project_initial=False, **settings):
        """Integrates the equations of motion from the scene's `initial` state: ``t`` (numpy),
        ``states`` ({name: numpy array}: each coordinate, then each ``q_dot``), ``y`` (all
        states as columns, in that order), ``method``, ``steps``, ``invariants`` and the rest
        of the JSON `simulation` object. ``until``, ``method``, ``tolerance`` override the
        scene's `simulate` line; ``initial`` (``{"theta": 0.1, "theta'": 0}``) the entries of
        its `initial` line that it names; ``values`` its `values` lines. An initial state off
        the constraints raises SceneError (with the projected state suggested) unless
        ``project_initial=True``, which starts from it projected onto them by least change
        (then ``projected_initial`` and ``initial_residual`` say where to and from how far)."""
        settings = dict(settings, until=until, method=method, tolerance=tolerance, estimate_error=estimate_error,
                        native=native, project_initial=project_initial)
        settings = {k: v for k, v in settings.items() if v is not None}
        doc, c = self._parts("simulation", ["simulation"], values, settings, initial=initial)
        s = doc["simulation"]
        parts = {}
        for k, v in s.items():
            if k == "t":
                parts[k] = numpy.array(v, dtype=float)
            elif k == "states":
                parts[k] = {name: numpy.array(col, dtype=float) for name, col in v.items()}
            else:
                parts[k] = c.value(v, k)
        parts["y"] = numpy.column_stack(list(parts["states"].values())) if parts.get("states") else numpy.zeros((0, 0))
        run = Simulation("simulation", parts, s)
        # run.animate(): the player of this run (its scene, values, initial state, span, tolerance)
        run._scene_animate = lambda **player: self.animate(
            until=float(parts["t"][-1]), values=values, initial=initial,
            tolerance=float(s.get("tolerance", 1e-9)), native=native, project_initial=project_initial, **player)
        return run

    def workprecision(self, values=None, initial=None, **settings):
        """Error against run time of every method over a ladder of tolerances (``values``,
        ``initial`` and ``settings`` as for :meth:`simulate`)."""
        doc, c = self._parts("workprecision", ["workprecision"], values, settings, initial=initial)
        return Result("workprecision", c.value(doc["workprecision"]), doc["workprecision"])

    def virial(self, until=None, values=None, initial=None, **settings):
        """The time averages ``T`` and ``V`` over a simulation, and the span ``over`` they were
        taken on (``quadrature_error`` where estimated); arguments as for :meth:`simulate`."""
        settings = dict(settings, until=until)
        settings = {k: v for k, v in settings.items() if v is not None}
        doc, c = self._parts("virial", ["virial"], values, settings, initial=initial)
        return Result("virial", c.value(doc["virial"]), doc["virial"])

    def poincare(self, section, energy, orbits=50, crossings=100, until=1000, tolerance=1e-9, seed=1, threads=0,
                 values=None, native=True, max_terms=None, max_seconds=None):
        """The Poincaré section of ``lagrange poincare`` (docs/pictures.md): ``section`` as
        ``--section`` (``"x = 0, x' > 0"``), at the energy ``energy``, over ``orbits`` orbits of
        at most ``crossings`` crossings and ``until`` time each; the same numbers as the command
        line's CSV for the same arguments, for any ``threads``. Returns a :class:`PoincareSection`
        of numpy arrays: ``orbit``, ``t``, ``q`` and ``q_dot`` (a column per coordinate, in
        ``coordinates``' order), ``no_crossings`` (why there are none, or "") and ``summary``.
        An unknown coordinate in ``section`` raises SceneError; an energy below the minimum of
        the energy, ValueError."""
        _check_settings({"until": until, "tolerance": tolerance, "max_terms": max_terms, "max_seconds": max_seconds})
        if not isinstance(section, str):
            raise TypeError("section must be a string such as \"x = 0, x' > 0\"")
        for name, value in (("orbits", orbits), ("crossings", crossings), ("seed", seed), ("threads", threads)):
            if isinstance(value, bool) or not isinstance(value, (int, numpy.integer)) or value < (name in ("orbits", "crossings")):
                raise ValueError(f"{name} must be a {'positive' if name in ('orbits', 'crossings') else 'non-negative'} "
                                 f"integer (got {value!r})")
        if isinstance(energy, bool) or not isinstance(energy, (int, float, numpy.integer, numpy.floating)) \
                or not numpy.isfinite(energy):
            raise ValueError(f"energy must be a finite number (got {energy!r})")
        settings = _lagrange.PoincareSettings()
        settings.energy = float(energy)
        settings.orbits = int(orbits)
        settings.crossings = int(crossings)
        settings.until = float(until)
        settings.tolerance = float(tolerance)
        settings.seed = int(seed)
        settings.threads = int(threads)
        settings.native = bool(native)
        limits = {name: value for name, value in (("max_terms", max_terms), ("max_seconds", max_seconds))
                  if value is not None}
        out = json.loads(_lagrange.poincare(self._model, section, _values_lines(values), settings, **limits))
        return PoincareSection(out)

    def animate(self, until=None, fps=30, speed=1, trail=0, view="", values=None, initial=None, tolerance=1e-9,
                native=True, project_initial=False):
        """The self-contained HTML player of ``lagrange animate -o FILE.html`` (docs/pictures.md):
        an :class:`Animation`, which Jupyter shows as the player and ``.save(path)`` writes.
        ``until`` (default: the scene's `simulate until`), ``fps`` frames per unit of simulated
        time, ``speed``, ``trail``, ``view`` ("xy", "xz", "3d"; "": by the scene), ``values``,
        ``initial``, ``tolerance`` and ``project_initial`` as for :meth:`simulate`. A free body is
        drawn by Poinsot's construction."""
        _check_settings({"until": until, "tolerance": tolerance})
        for name, value in (("fps", fps), ("speed", speed), ("trail", trail)):
            if isinstance(value, bool) or not isinstance(value, (int, float, numpy.integer, numpy.floating)) \
                    or not numpy.isfinite(value) or value < 0 or (value == 0 and name != "trail"):
                raise ValueError(f"{name} must be a {'non-negative' if name == 'trail' else 'positive'} finite "
                                 f"number (got {value!r})")
        html = _lagrange.animate(self._model, _values_lines(values), _initial_lines(initial, self.coordinates),
                                 None if until is None else float(until), float(fps), float(tolerance), bool(native),
                                 float(speed), float(trail), view, bool(project_initial))
        return Animation(html)

    def inertia(self):
        """Per body: ``tensor`` (SymPy Matrix), ``principal`` moments and ``mass``."""
        doc, c = self._parts("inertia", ["inertia"])
        return ExprDict({body: Result("inertia", c.value(v), v) for body, v in doc["inertia"].items()})

    def euler(self):
        """Per free body: Euler's ``equations`` (each = 0, in w1 w2 w3 and w1_dot ...) and
        their closed-form ``solution`` where one exists."""
        doc, c = self._parts("euler", ["euler"])
        out = {}
        for body, v in doc["euler"].items():
            parts = c.value(v)
            if "equations" in parts:
                parts["equations"] = ExprList(c.exprs(v["equations"]), equals_zero=True)
            out[body] = Result("euler", parts, v)
        return ExprDict(out)

    def conserved(self):
        """The energy function ``energy`` (when ∂L/∂t = 0) and the momentum ``p_q`` of each
        cyclic coordinate: ``{name: expr}``."""
        doc, c = self._parts("conserved", ["conserved"])
        return ExprDict({k: c.value(v) for k, v in doc["conserved"].items()})

    def hamiltonian(self):
        """``H`` in the coordinates and momenta p_q (``momenta``), and Hamilton's
        ``equations`` as SymPy equations (``Eq(theta_dot, p_theta/(l**2*m))``, …)."""
        doc, c = self._parts("hamiltonian", ["hamiltonian"])
        h = doc["hamiltonian"]
        parts = {}
        for k, v in h.items():
            if k == "equations":
                parts[k] = Equations([sympy.Eq(*(c.expr(side) for side in e.split("=", 1))) for e in v])
            else:
                parts[k] = c.value(v, k)
        return Result("hamiltonian", parts, h, main="H")

    def reduced(self):
        """Routh's reduction: ``routhian``, ``effective_potential`` and the ``momenta`` held fixed."""
        doc, c = self._parts("reduced", ["reduced"])
        return Result("reduced", c.value(doc["reduced"]), doc["reduced"], main="routhian")

    def multipliers(self):
        """Each constraint's multiplier ``{lambda_NAME: expr}``; ``constraint_forces`` with them."""
        doc, c = self._parts("multipliers", ["multipliers"], optional=("constraint_forces",))
        parts = {"multipliers": ExprDict({k: c.value(v) for k, v in doc["multipliers"].items()})}
        if "constraint_forces" in doc:
            parts["constraint_forces"] = c.value(doc["constraint_forces"])
        return Result("multipliers", parts, doc)

    def contact(self):
        """The ground's force on each rolling wheel at its contact point (``rolls W on
        ground``): ``.contact_forces`` ``{body: {"point": [...], "force": [...]}}`` in the
        scene's axes, and the ``.multipliers`` it is built from."""
        doc, c = self._parts("contact", ["contact_forces", "multipliers"])
        return Result("contact", {"contact_forces": c.value(doc["contact_forces"]),
                                  "multipliers": ExprDict({k: c.value(v) for k, v in doc["multipliers"].items()})},
                      doc)

    def eliminated(self):
        """The equations of the coordinates kept after eliminating solvable constraints."""
        doc, c = self._parts("eliminated", ["eliminated"])
        return EquationsOf({k: c.expr(v) for k, v in doc["eliminated"].items()})

    def damping(self):
        """The damping matrix ``C`` at the equilibrium (with ``T`` and ``V``)."""
        doc, c = self._parts("damping", ["damping"])
        parts = {"C": c.matrix(doc["damping"])}
        parts.update({k: c.matrix(doc[k]) for k in ("T", "V") if k in doc})
        return Result("damping", parts, doc)

    def gyroscopic(self):
        """The gyroscopic matrix ``G`` at the equilibrium (antisymmetric), with ``T`` and ``V``."""
        doc, c = self._parts("linearization", ["gyroscopic"])
        parts = {"G": c.matrix(doc["gyroscopic"])}
        parts.update({k: c.matrix(doc[k]) for k in ("T", "V") if k in doc})
        return Result("gyroscopic", parts, doc)

    def state_space(self, values=None):
        """ẋ = A x + B u at the equilibrium: ``state``, ``inputs`` (names), ``A``, ``B`` (SymPy)."""
        doc, c = self._parts("state_space", ["state_space"], values)
        s = doc["state_space"]
        parts = {}
        for k, v in s.items():
            if k in ("A", "B"):
                parts[k] = c.matrix(v)
            elif k in ("state", "inputs"):
                parts[k] = list(v)
            else:
                parts[k] = c.value(v, k)
        return Result("state_space", parts, s)

    def transfer(self):
        """The Laplace transfer function of each input to each coordinate: ``{"u -> q": H(s)}``."""
        doc, c = self._parts("transfer", ["transfer"])
        return ExprDict({k: c.expr(v) for k, v in doc["transfer"].items()})

    def floquet(self, values=None, **settings):
        """Per `values` point: ``period``, Floquet ``multipliers`` (complex numpy) and ``stable``."""
        doc, c = self._parts("floquet", ["floquet"], values, settings)
        points = []
        for p in doc["floquet"]:
            parts = {k: (complex_array(v) if k == "multipliers" else c.value(v, k)) for k, v in p.items()}
            points.append(Result("floquet", parts, p))
        return ResultList(points)

    def export(self, target, folder=".", name=None, values=None):
        """Writes the equations of motion as code into ``folder`` (made if missing), as
        ``lagrange export`` does: ``target`` is "c", "python" or "octave"; ``name`` defaults to
        the scene file's stem; ``values`` give the parameters' defaults. Returns the paths
        written. See docs/export.md."""
        if name is None:
            name = _lagrange.default_export_name(self.file)
        folder = os.fspath(folder)
        files = self._model.export_code(target, folder, name, values=_values_lines(values))
        return [os.path.join(folder, f) for f in files.splitlines()]

    def verification(self, *want):
        """How each symbolic result of the products `want` (all the scene supports if none)
        was checked numerically: ``{item: "how"}``."""
        doc = self._json(want)
        return VerificationResult(doc.get("verification", {}))


class Simulation(Result):
    """A simulation: ``t``, ``states``, ``y`` and the JSON `simulation` object's other parts."""

    def animate(self, fps=30, speed=1, trail=0, view=""):
        """The HTML player of this run (an :class:`Animation`, as :meth:`Scene.animate` gives
        it): the same scene, ``values``, ``initial`` state, end time and tolerance."""
        return self._scene_animate(fps=fps, speed=speed, trail=trail, view=view)

    def _repr_latex_(self):
        t = self._parts.get("t")
        span = f"t \\in [{t[0]:g}, {t[-1]:g}]" if t is not None and len(t) else ""
        lines = [r"\text{method} &: \text{" + _text(self._parts.get("method", "")) + "}",
                 r"\text{steps} &= " + str(self._parts.get("steps", "")), r"\text{output} &: " + span
                 + r",\ " + str(len(t) if t is not None else 0) + r"\ \text{times}"]
        for name, drift in (self._parts.get("invariants") or {}).items():
            lines.append(r"\text{" + _text(name) + "} &= " + f"{drift:.3g}")
        return "$$\\begin{aligned}" + " \\\\ ".join(lines) + "\\end{aligned}$$"


class Animation:
    """The HTML player of an animation: ``.html`` (one self-contained page), shown by Jupyter
    in an isolated frame (``_repr_html_``), written by ``.save(path)``."""

    def __init__(self, html):
        self.html = html

    def save(self, path):
        with open(os.fspath(path), "w", encoding="utf-8") as f:
            f.write(self.html)

    def _repr_html_(self):
        import html as _html
        return ('<iframe style="width: 700px; height: 720px; border: none" sandbox="allow-scripts" srcdoc="'
                + _html.escape(self.html, quote=True) + '"></iframe>')

    def __repr__(self):
        return f"Animation({len(self.html)} bytes of HTML)"


class PoincareSection:
    """The crossings of a Poincaré section: ``orbit`` (int), ``t``, ``q`` and ``q_dot``
    (numpy arrays, one row per crossing, orbit by orbit, as the command line's CSV),
    ``coordinates``, ``no_crossings`` (why there are none, or "") and ``summary`` (the
    command line's summary)."""

    def __init__(self, out):
        self.coordinates = list(out["coordinates"])
        self.no_crossings = out["no_crossings"]
        self.summary = out["summary"]
        self.csv = out["csv"]
        n = len(self.coordinates)
        rows = [line.split(",") for line in self.csv.splitlines()[1:] if line]
        table = numpy.array([[float(x) for x in row] for row in rows], dtype=float).reshape(len(rows), 2 + 2 * n)
        self.orbit = table[:, 0].astype(int)
        self.t = table[:, 1]
        self.q = table[:, 2:2 + n]
        self.q_dot = table[:, 2 + n:]

    def __len__(self):
        return len(self.t)

    def __repr__(self):
        return f"PoincareSection({len(self)} crossings of {len(set(self.orbit.tolist()))} orbits, {self.coordinates})"


class VerificationResult(dict):
    """``{item: how it was checked}``, rendered as text."""

    def _repr_latex_(self):
        lines = [r"\text{" + _text(k) + r"} &: \text{" + _text(v) + "}" for k, v in self.items()]
        return "$$\\begin{aligned}" + " \\\\ ".join(lines) + "\\end{aligned}$$"
