# SPDX-License-Identifier: GPL-2.0-or-later
"""The other products through the Python module, each against a reference derived here
independently (SymPy from the scene's positions or Lagrangian, numpy integration), and the
errors as Python exceptions."""
import numpy
import pytest
import sympy

import lagrange

S = sympy.Symbol


def same(a, b):
    return sympy.simplify(sympy.sympify(a) - sympy.sympify(b)) == 0


# ---- conserved, hamiltonian, reduced: the spherical pendulum -------------------------------
m, l, g = S("m"), S("l"), S("g")
theta, phi, theta_dot, phi_dot = S("theta"), S("phi"), S("theta_dot"), S("phi_dot")
p_theta, p_phi = S("p_theta"), S("p_phi")


@pytest.fixture(scope="module")
def spherical_L():
    """L of the spherical pendulum from its bob's position."""
    t = S("t")
    th, ph = sympy.Function("th")(t), sympy.Function("ph")(t)
    r = sympy.Matrix([l * sympy.sin(th) * sympy.cos(ph), l * sympy.sin(th) * sympy.sin(ph), -l * sympy.cos(th)])
    v = r.diff(t)
    L = m * v.dot(v) / 2 - m * g * r[2]
    L = L.subs({th.diff(t): theta_dot, ph.diff(t): phi_dot}).subs({th: theta, ph: phi})
    return sympy.simplify(L)


def test_conserved_energy_and_cyclic_momentum(example, spherical_L):
    c = example("spherical_pendulum.lag").conserved()
    L = spherical_L
    assert same(c["energy"], theta_dot * L.diff(theta_dot) + phi_dot * L.diff(phi_dot) - L)
    assert same(c["p_phi"], L.diff(phi_dot))
    assert "p_theta" not in c  # θ is not cyclic
    assert "h &=" in c._repr_latex_()


def test_hamiltonian_is_the_legendre_transform(example, spherical_L):
    h = example("spherical_pendulum.lag").hamiltonian()
    L = spherical_L
    velocities = sympy.solve([sympy.Eq(p_theta, L.diff(theta_dot)), sympy.Eq(p_phi, L.diff(phi_dot))],
                             [theta_dot, phi_dot], dict=True)[0]
    H = (p_theta * theta_dot + p_phi * phi_dot - L).subs(velocities)
    assert same(h.H, H)
    assert h.momenta == ["p_theta", "p_phi"]
    expected = {theta_dot: H.diff(p_theta), phi_dot: H.diff(p_phi),
                S("p_theta_dot"): -H.diff(theta), S("p_phi_dot"): -H.diff(phi)}
    assert len(h.equations) == 4
    for eq in h.equations:
        assert isinstance(eq, sympy.Eq)
        assert same(eq.rhs, expected[eq.lhs])


def test_routhian_and_effective_potential(example, spherical_L):
    r = example("spherical_pendulum.lag").reduced()
    L = spherical_L
    rate = sympy.solve(sympy.Eq(p_phi, L.diff(phi_dot)), phi_dot)[0]
    routhian = (L - p_phi * phi_dot).subs(phi_dot, rate)
    assert same(r.routhian, routhian)
    assert same(r.effective_potential, -routhian.subs(theta_dot, 0))
    assert r.momenta == ["p_phi"]


# ---- multipliers: Atwood's machine ---------------------------------------------------------
def test_multiplier_is_the_tension(example):
    m1, m2, lam, a1, a2 = sympy.symbols("m1 m2 lam a1 a2")
    # m1 ÿ1 = −m1 g + λ, m2 ÿ2 = −m2 g + λ, ÿ1 + ÿ2 = 0 (M q̈ = f + Aᵀλ with A = (1, 1))
    solution = sympy.solve([m1 * a1 + m1 * g - lam, m2 * a2 + m2 * g - lam, a1 + a2], [a1, a2, lam], dict=True)[0]
    result = example("atwood_tension.lag").multipliers()
    assert same(result.multipliers["string"], solution[lam])
    forces = result.constraint_forces["string"]
    assert same(forces["P1"][1], solution[lam]) and same(forces["P1"][0], 0)


# ---- contact: SymPy's rolling disc of test_aux_dep, its height a coordinate ------------------
def test_contact_force_of_the_rolling_disc():
    scene = lagrange.Scene.from_text(
        "parameters m g r I J\ncoordinates q1 q2 q3 x y z\n"
        "body D inertia (I, J, I) mass m at (x, y, z) orientation rotations(z q1, x q2, y q3)\n"
        "gravity g along (0, 0, 1)\nrolls D on ground radius r axis y\n", "disc.lag")
    force = scene.contact().contact_forces["D"]["force"]
    # Upright, rolling straight at spin rate w along heading q1: the ground carries the weight
    # (z is down), as Newton's law for the centre, which does not accelerate, says.
    upright = {S("q2"): 0, S("q1_dot"): 0, S("q2_dot"): 0, S("q3_dot"): S("w"), S("z"): -S("r")}
    assert [sympy.simplify(f.subs(upright)) for f in force] == [0, 0, -S("m") * S("g")]


# ---- damping, state space, transfer: the damped driven oscillator -----------------------
k, b, s = sympy.symbols("k b s")


def test_damping_matrix(example):
    d = example("damped_driven_oscillator.lag").damping()
    # the damper's Rayleigh function F = ½ b ẋ² gives C = ∂²F/∂ẋ²
    x_dot = S("x_dot")
    assert same(d.C[0, 0], sympy.diff(b * x_dot**2 / 2, x_dot, 2))
    assert same(d.T[0, 0], m) and same(d.V[0, 0], k)


def test_state_space_and_transfer(example):
    scene = example("damped_driven_oscillator.lag")
    ss = scene.state_space()
    # m ẍ + b ẋ + k x = u, with state (x, ẋ)
    A = sympy.Matrix([[0, 1], [-k / m, -b / m]])
    B = sympy.Matrix([[0], [1 / m]])
    assert ss.state == ["x", "x_dot"] and ss.inputs == ["u"]
    assert sympy.simplify(ss.A - A) == sympy.zeros(2, 2)
    assert sympy.simplify(ss.B - B) == sympy.zeros(2, 1)
    H = (sympy.Matrix([[1, 0]]) * (s * sympy.eye(2) - A).inv() * B)[0]
    assert same(scene.transfer()["u -> x"], H)


def test_numeric_damped_eigenvalues(example):
    point = example("damped_driven_oscillator.lag").numeric()[0]
    mass, stiffness, damping = (point.values[n] for n in ("m", "k", "b"))
    expected = numpy.roots([mass, damping, stiffness])
    got = numpy.sort_complex(point.eigenvalues)
    numpy.testing.assert_allclose(got, numpy.sort_complex(expected), rtol=1e-12)
    numpy.testing.assert_allclose(point.damping_ratio, -got.real / abs(got), rtol=1e-12)


# ---- floquet: the Kapitza pendulum ---------------------------------------------------------
def monodromy(f, period, steps=4000):
    """The monodromy matrix of y' = f(t) y over one period, by classical Runge–Kutta."""
    h = period / steps
    Y = numpy.eye(2)
    t = 0.0
    for _ in range(steps):
        k1 = f(t) @ Y
        k2 = f(t + h / 2) @ (Y + h / 2 * k1)
        k3 = f(t + h / 2) @ (Y + h / 2 * k2)
        k4 = f(t + h) @ (Y + h * k3)
        Y = Y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        t += h
    return Y


def test_floquet_multipliers_against_integration(example):
    points = example("kapitza_pendulum.lag").floquet()
    assert len(points) == 2
    a, gamma, t = sympy.symbols("a gamma t")
    # The bob at (l sin φ, a cos γt − l cos φ): l φ̈ = −(g + ÿ_pivot) sin φ, linearized at φ = π + ψ.
    pivot_acceleration = sympy.diff(a * sympy.cos(gamma * t), t, 2)
    stiffness = (g + pivot_acceleration) / l  # ψ̈ = stiffness ψ about the inverted position
    for p in points:
        values = {S(n): v for n, v in p.values.items()}
        c = sympy.lambdify(t, stiffness.subs(values), "numpy")
        mono = monodromy(lambda time: numpy.array([[0.0, 1.0], [c(time), 0.0]]), p.period)
        expected = numpy.sort_complex(numpy.linalg.eigvals(mono))
        numpy.testing.assert_allclose(numpy.sort_complex(p.multipliers), expected, rtol=1e-7, atol=1e-7)
        assert p.stable == bool(numpy.all(abs(expected) <= 1 + 1e-6))
        assert p.period == pytest.approx(2 * numpy.pi / values[gamma])
    assert [p.stable for p in points] == [True, False]


# ---- gyroscopic: the Penning trap -------------------------------------------------------
def test_gyroscopic_matrix_and_frequencies(example):
    scene = example("penning_trap.lag")
    lag = scene.lagrangian().lagrangian
    q = [S("x"), S("y"), S("z")]
    v = [S("x_dot"), S("y_dot"), S("z_dot")]
    # the velocity-linear part of L, q̇ᵀ a(q): G_ij = ∂a_j/∂q_i − ∂a_i/∂q_j (up to a sign convention)
    a = [sympy.diff(lag, vi).subs({vj: 0 for vj in v}) for vi in v]
    G = sympy.Matrix(3, 3, lambda i, j: sympy.diff(a[j], q[i]) - sympy.diff(a[i], q[j]))
    result = scene.gyroscopic()
    assert sympy.simplify(result.G + result.G.T) == sympy.zeros(3, 3)
    assert (sympy.simplify(result.G - G) == sympy.zeros(3, 3)) or (sympy.simplify(result.G + G) == sympy.zeros(3, 3))
    omega = S("omega")
    det = (result.V - omega**2 * result.T + sympy.I * omega * result.G).det()
    polynomial = scene.characteristic().polynomial
    assert sympy.simplify(polynomial / sympy.expand(det)).free_symbols.isdisjoint({omega})
    for w in scene.frequencies():  # ω itself here, each a root
        assert sympy.simplify(polynomial.subs(omega, w)) == 0


# ---- inertia and Euler's equations: the homework's bodies and the free top ------------------
def test_inertia_tensors_of_the_homework(example):
    M, R, length = sympy.symbols("M R l")
    result = example("homework_bodies.lag").inertia()
    expected = {
        "S": [M * length**2 / 12, 0, M * length**2 / 12],  # a thin stick along y
        "D": [M * R**2 / 4, M * R**2 / 4, M * R**2 / 2],     # a thin disk in the xy plane
        "B": [2 * M * R**2 / 5] * 3,                           # a solid ball
        "H": [2 * M * R**2 / 3] * 3,                           # a thin hollow sphere
    }
    for body, diagonal in expected.items():
        tensor = result[body].tensor
        assert sympy.simplify(tensor - sympy.diag(*diagonal)) == sympy.zeros(3, 3), body
        assert same(result[body].mass, M)
    assert r"\text{S:}" in result._repr_latex_()


def test_euler_equations_of_the_free_top(example):
    M, a, b_, c = sympy.symbols("M a b c")
    w = sympy.symbols("w1 w2 w3")
    wd = sympy.symbols("w1_dot w2_dot w3_dot")
    I = [M * (b_**2 + c**2) / 12, M * (a**2 + c**2) / 12, M * (a**2 + b_**2) / 12]  # a box
    reference = [I[i] * wd[i] - (I[(i + 1) % 3] - I[(i + 2) % 3]) * w[(i + 1) % 3] * w[(i + 2) % 3] for i in range(3)]
    equations = example("free_asymmetric_top.lag").euler()["X"].equations
    assert len(equations) == 3
    for mine, theirs in zip(equations, reference):
        assert same(mine, theirs)


# ---- simulation against a closed form ------------------------------------------------------
def test_simulation_of_an_oscillator_against_the_cosine():
    scene = lagrange.Scene.from_text("parameters m k\ncoordinates x\nT = 1/2*m*x'^2\nV = 1/2*k*x^2\n"
                                     "values m = 2, k = 8\ninitial x = 1, x' = 0\nsimulate until 10\n")
    run = scene.simulate(tolerance=1e-10)
    numpy.testing.assert_allclose(run.states["x"], numpy.cos(2 * run.t), atol=1e-7)
    numpy.testing.assert_allclose(run.states["x_dot"], -2 * numpy.sin(2 * run.t), atol=1e-7)
    shorter = scene.simulate(until=3)
    assert shorter.t[-1] == pytest.approx(3)


# ---- errors --------------------------------------------------------------------------------
def test_scene_error_carries_the_position():
    line = "V = 1/2*k*y^2"
    with pytest.raises(lagrange.SceneError) as caught:
        lagrange.Scene.from_text("parameters m k\ncoordinates x\nT = 1/2*m*x'^2\n" + line + "\n", "oscillator.lag")
    error = caught.value
    assert (error.file, error.line, error.column) == ("oscillator.lag", 4, line.index("y") + 1)
    assert "y" in error.message
    assert str(error).startswith(f"oscillator.lag:4:{line.index('y') + 1}: error: ")
    assert line in str(error) and "^" in str(error)


def test_bad_values_are_scene_errors(example):
    with pytest.raises(lagrange.SceneError):
        example("double_pendulum.lag").numeric({"M": 1, "nosuch": 2})


def test_values_that_contradict_positive_parameters_are_scene_errors(example):
    # parameters are assumed positive (sqrt(l^2) = l): l = -1 would be a different system
    with pytest.raises(lagrange.SceneError, match="assumed real and positive") as caught:
        example("double_pendulum.lag").numeric({"M": 1, "m": 0.01, "l": -1, "g": 9.81})
    assert caught.value.file == "values="  # the argument it came from


def test_computation_error():
    scene = lagrange.Scene.from_text("parameters m k\ncoordinates x\nT = 1/2*m*x'^2\nV = k*x\n")
    with pytest.raises(lagrange.ComputationError, match="no equilibrium"):
        scene.linearization()


def test_budget_exceeded_is_a_computation_error(example):
    with pytest.raises(lagrange.BudgetExceeded) as caught:
        example("double_pendulum.lag").document("json", want=["characteristic"], max_terms=3)
    assert isinstance(caught.value, lagrange.ComputationError) and caught.value.stage


def test_from_file_reads_use_relative_to_the_scene(tmp_path):
    (tmp_path / "extra.rules").write_text("sin($0)^2 -> 1 - cos($0)^2\n")
    path = tmp_path / "p.lag"
    path.write_text('use "extra.rules"\nparameters m l g\ncoordinates q\nT = 1/2*m*l^2*q\'^2\nV = -m*g*l*cos(q)\n')
    scene = lagrange.Scene.from_file(path)
    assert scene.coordinates == ["q"] and scene.parameters == ["m", "l", "g"]
    assert same(scene.equations()[0], m * l**2 * S("q_ddot") + m * g * l * sympy.sin(S("q")))


def test_documents_as_the_command_line_writes_them(example):
    scene = example("double_pendulum.lag")
    assert scene.document("latex", want=["characteristic"]).lstrip().startswith("\\documentclass")
    assert "Characteristic polynomial" in scene.document("text", want=["characteristic"])
    analysis = scene.analyze("characteristic")
    assert same(analysis["characteristic"]["polynomial"], scene.characteristic().polynomial)


@pytest.mark.parametrize("scene_file, method", [
    ("spherical_pendulum.lag", "conserved"), ("spherical_pendulum.lag", "hamiltonian"),
    ("spherical_pendulum.lag", "reduced"), ("atwood_tension.lag", "multipliers"),
    ("damped_driven_oscillator.lag", "damping"), ("damped_driven_oscillator.lag", "state_space"),
    ("damped_driven_oscillator.lag", "transfer"), ("kapitza_pendulum.lag", "floquet"),
    ("penning_trap.lag", "gyroscopic"), ("homework_bodies.lag", "inertia"),
    ("free_asymmetric_top.lag", "euler"), ("ladder.lag", "eliminated"),
    ("spherical_pendulum.lag", "verification")])
def test_latex_of_each_product(example, scene_file, method):
    text = getattr(example(scene_file), method)()._repr_latex_()
    assert text.startswith("$") and text.endswith("$")
    body = text.strip("$")
    assert body.count("{") == body.count("}") and body.count(r"\left") == body.count(r"\right")
    assert "\t" not in text and "_dot" not in text  # velocities print as \dot{q}
