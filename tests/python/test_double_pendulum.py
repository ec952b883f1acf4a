# SPDX-License-Identifier: GPL-2.0-or-later
"""The homework's double pendulum through the Python module, against references derived here
independently with SymPy (the Lagrangian from the positions) and numpy (eigh)."""
import numpy
import pytest
import sympy

M, m, l, g, omega = sympy.symbols("M m l g omega")
theta, phi, theta_dot, phi_dot, theta_ddot, phi_ddot = sympy.symbols(
    "theta phi theta_dot phi_dot theta_ddot phi_ddot")
VALUES = {M: 1, m: sympy.Rational(1, 100), l: 1, g: sympy.Rational(981, 100)}


def zero(e):
    return sympy.simplify(sympy.expand_trig(sympy.sympify(e))) == 0


@pytest.fixture(scope="module")
def scene(example):
    return example("double_pendulum.lag")


@pytest.fixture(scope="module")
def reference():
    """L, T, V and the Euler–Lagrange expressions, from the positions of the two bobs."""
    t = sympy.Symbol("t")
    th, ph = sympy.Function("th")(t), sympy.Function("ph")(t)
    x1, y1 = l * sympy.sin(th), -l * sympy.cos(th)
    x2, y2 = x1 + l * sympy.sin(ph), y1 - l * sympy.cos(ph)
    kinetic = (M * (x1.diff(t) ** 2 + y1.diff(t) ** 2) + m * (x2.diff(t) ** 2 + y2.diff(t) ** 2)) / 2
    potential = M * g * y1 + m * g * y2
    lagrangian = kinetic - potential
    plain = {th.diff(t, 2): theta_ddot, ph.diff(t, 2): phi_ddot, th.diff(t): theta_dot, ph.diff(t): phi_dot,
             th: theta, ph: phi}

    def to_plain(e):
        return e.subs({k: plain[k] for k in (th.diff(t, 2), ph.diff(t, 2))}).subs(
            {k: plain[k] for k in (th.diff(t), ph.diff(t))}).subs({th: theta, ph: phi})
    equations = [to_plain(lagrangian.diff(q.diff(t)).diff(t) - lagrangian.diff(q)) for q in (th, ph)]
    T = to_plain(kinetic)
    V = to_plain(potential)
    velocities, coordinates = (theta_dot, phi_dot), (theta, phi)
    at_rest = {theta: 0, phi: 0}
    T2 = sympy.Matrix(2, 2, lambda i, j: T.diff(velocities[i], velocities[j]).subs(at_rest))
    V2 = sympy.Matrix(2, 2, lambda i, j: V.diff(coordinates[i], coordinates[j]).subs(at_rest))
    return {"L": to_plain(lagrangian), "equations": equations, "T": T2, "V": V2}


def test_equations_are_the_euler_lagrange_equations(scene, reference):
    equations = scene.equations()
    assert len(equations) == 2
    for mine, theirs in zip(equations, reference["equations"]):
        assert zero(mine - theirs)


def test_lagrangian(scene, reference):
    assert zero(scene.lagrangian().lagrangian - reference["L"])


def test_equilibrium(scene):
    e = scene.equilibrium()
    assert e.equilibrium == {"theta": 0, "phi": 0}
    assert e.stability == "stable"


def test_linearization_is_the_hessians(scene, reference):
    lin = scene.linearization()
    assert sympy.simplify(lin.T - reference["T"]) == sympy.zeros(2, 2)
    assert sympy.simplify(lin.V - reference["V"]) == sympy.zeros(2, 2)


def test_characteristic_polynomial_is_the_closed_form(scene):
    ch = scene.characteristic()
    assert ch.variable == omega
    closed = M * l**2 * omega**4 - 2 * (M + m) * g * l * omega**2 + (M + m) * g**2
    assert sympy.simplify(ch.polynomial - closed) == 0


def test_frequencies_are_the_roots(scene, reference):
    w2 = scene.frequencies()
    assert len(w2) == 2
    # Vieta: their sum and product are those of det(V − ω²T) = 0 in ω².
    T, V = reference["T"], reference["V"]
    quadratic = sympy.Poly((V - sympy.Symbol("w") * T).det(), sympy.Symbol("w"))
    a, b, c = quadratic.all_coeffs()
    assert sympy.simplify(w2[0] + w2[1] + b / a) == 0
    assert sympy.simplify(w2[0] * w2[1] - c / a) == 0
    # ascending at the scene's values
    assert float(w2[0].subs(VALUES)) < float(w2[1].subs(VALUES))


def test_modes_solve_the_pencil(scene, reference):
    T, V = reference["T"], reference["V"]
    for w2, mode in zip(scene.frequencies(), scene.modes()):
        assert mode.shape == (2, 1)
        residual = (V - w2 * T) * mode
        assert all(sympy.simplify(r) == 0 for r in residual)


def test_normal_coordinates_separate_the_modes(scene):
    modes = scene.modes()
    zeta = scene.normal_coordinates()
    assert len(zeta) == 2
    for i, z in enumerate(zeta):
        row = sympy.Matrix([[z.diff(theta), z.diff(phi)]])
        assert sympy.simplify(z - row[0] * theta - row[1] * phi) == 0  # linear in the coordinates
        other = modes[1 - i]
        # ζ_i does not see mode j ≠ i (the parameters are positive, as the engine declares them)
        positive = {s: sympy.Symbol(s.name, positive=True) for s in (M, m, l, g)}
        assert sympy.simplify((row * other)[0].subs(positive)) == 0


def test_asymptotic_limit_is_the_leading_term(scene):
    rho = sympy.Symbol("rho")
    limit = scene.asymptotic()["rho -> 0"]
    exact = [((1 + rho) * g - s * g * sympy.sqrt(rho * (1 + rho))) / l for s in (1, -1)]
    for approx, full in zip(limit.frequencies, exact):
        # the difference is O(ρ): it vanishes faster than √ρ
        assert sympy.limit((full - approx) / sympy.sqrt(rho), rho, 0, "+") == 0


def generalized_eigen(T, V):
    """ω and T-normalized modes (columns) of V a = ω² T a, by Cholesky and numpy.linalg.eigh."""
    L = numpy.linalg.cholesky(T)
    Linv = numpy.linalg.inv(L)
    w2, y = numpy.linalg.eigh(Linv @ V @ Linv.T)
    return numpy.sqrt(w2), Linv.T @ y


@pytest.mark.parametrize("values", [None, {"M": 2, "m": 1.5, "l": 0.5, "g": 9.81}, "M=1,m=1,l=1,g=1"])
def test_numeric_against_eigh(scene, reference, values):
    points = scene.numeric(values)
    assert len(points) == 1
    p = points[0]
    at = {sympy.Symbol(k): v for k, v in p.values.items()}
    if isinstance(values, dict):
        assert p.values == values
    T = numpy.array(reference["T"].subs(at), dtype=float)
    V = numpy.array(reference["V"].subs(at), dtype=float)
    w, A = generalized_eigen(T, V)
    assert isinstance(p.omega, numpy.ndarray)
    numpy.testing.assert_allclose(p.omega, w, rtol=1e-12)
    modes = numpy.asarray(p.modes).T  # columns
    numpy.testing.assert_allclose(modes.T @ T @ modes, numpy.eye(2), atol=1e-12)
    numpy.testing.assert_allclose(V @ modes, T @ modes @ numpy.diag(p.omega**2), rtol=1e-10, atol=1e-10)
    assert numpy.all(p.error < 1e-10)


def test_simulation_conserves_the_energy(scene, reference):
    run = scene.simulate(until=5)
    assert run.t[0] == 0 and run.t[-1] == pytest.approx(5)
    assert run.y.shape == (len(run.t), 4)
    assert list(run.states) == ["theta", "phi", "theta_dot", "phi_dot"]
    L = reference["L"]
    h = sum(v * L.diff(v) for v in (theta_dot, phi_dot)) - L
    energy = sympy.lambdify((theta, phi, theta_dot, phi_dot), h.subs(VALUES), "numpy")
    E = energy(*(run.states[k] for k in ("theta", "phi", "theta_dot", "phi_dot")))
    assert numpy.max(numpy.abs(E - E[0])) < 1e-7 * abs(E[0])
    assert run.invariants["energy_drift"] < 1e-7
    assert isinstance(run.method, str) and run.steps > 0


def test_verification_names_each_check(scene):
    checks = scene.verification("equations", "characteristic", "modes")
    assert {"equations", "characteristic"} <= set(checks)
    assert all(isinstance(v, str) and v for v in checks.values())


def test_latex_of_each_result(scene):
    for result in (scene.equations(), scene.lagrangian(), scene.equilibrium(), scene.linearization(),
                   scene.characteristic(), scene.frequencies(), scene.modes(), scene.normal_coordinates(),
                   scene.asymptotic(), scene.numeric(), scene.simulate(until=1), scene.verification("equations")):
        text = result._repr_latex_()
        assert text.startswith("$") and text.endswith("$")
        assert text.count("{") == text.count("}")
    assert r"\ddot{\theta}" in scene.equations()._repr_latex_()
    assert r"\omega^{4}" in scene.characteristic()._repr_latex_()
