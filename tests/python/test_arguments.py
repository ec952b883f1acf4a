# SPDX-License-Identifier: GPL-2.0-or-later
"""The Python module's arguments and conversions: ``initial=`` and ``values=`` on the
methods that run numbers (against the command line's ``--initial``), errors that name the
argument, ``sympy.sympify`` of a result, and the ImportError another interpreter gets."""
import json
import os
import shutil
import subprocess
import sys

import numpy
import pytest
import sympy

import lagrange

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
CLI = os.environ.get("LAGRANGE_CLI", "")

OSCILLATOR = """
coordinates x
parameters m k
T = 1/2*m*x'^2
V = 1/2*k*x^2
values m = 2, k = 8
initial x = 1
simulate until 3
"""


def test_initial_from_a_dict_starts_the_simulation_there(example):
    run = example("double_pendulum.lag").simulate(until=0.5, initial={"theta": 0.1, "phi_dot": 0.2})
    assert run.states["theta"][0] == 0.1
    assert run.states["phi_dot"][0] == 0.2
    assert run.states["phi"][0] == 0.05  # kept from the scene's `initial` line


def test_initial_with_a_prime_equals_the_command_line(example):
    scene = example("double_pendulum.lag")
    doc = json.loads(scene.document("json", want=["simulation"], until=0.5, initial={"theta": 0.05, "phi'": -0.1}))
    cli = subprocess.run([CLI, "simulate", os.path.join(ROOT, "examples", "double_pendulum.lag"), "--until", "0.5",
                          "--initial", "theta=0.05, phi'=-0.1", "--format", "json"],
                         capture_output=True, text=True, check=True)
    assert doc["simulation"] == json.loads(cli.stdout)["simulation"]


def test_initial_moves_the_oscillator_by_its_closed_form():
    scene = lagrange.Scene.from_text(OSCILLATOR)
    run = scene.simulate(initial={"x": 0.5, "x'": 1.0}, values={"m": 1, "k": 4}, tolerance=1e-11)
    t, w = run.t, 2.0  # ω = √(k/m)
    assert numpy.allclose(run.states["x"], 0.5 * numpy.cos(w * t) + numpy.sin(w * t) / w, rtol=0, atol=1e-8)


def test_virial_takes_initial_and_values():
    """For V ∝ x², 2⟨T⟩ = 2⟨V⟩ over whole periods (n = 2): T = 2π/ω with ω = √(k/m) = 2."""
    v = lagrange.Scene.from_text(OSCILLATOR).virial(until=numpy.pi, initial={"x": 0.3}, values={"m": 1, "k": 4})
    assert v.T == pytest.approx(v.V, rel=1e-7)
    assert v.T == pytest.approx(0.25 * 4 * 0.3 ** 2, rel=1e-7)  # ⟨V⟩ = ½ of E = ½·½kA²


def test_a_bad_initial_entry_is_a_scene_error_located_in_the_argument():
    with pytest.raises(lagrange.SceneError) as error:
        lagrange.Scene.from_text(OSCILLATOR).simulate(initial={"y": 1})
    assert error.value.file == "initial="
    assert "`y` is not a coordinate" in str(error.value)


def test_initial_of_another_type_is_a_type_error():
    with pytest.raises(TypeError, match="initial must be a dict"):
        lagrange.Scene.from_text(OSCILLATOR).simulate(initial=[("x", 1)])


@pytest.mark.parametrize("settings, named", [({"until": -1}, "until"), ({"until": float("inf")}, "until"),
                                             ({"tolerance": 2}, "tolerance"), ({"max_seconds": 0}, "max_seconds")])
def test_a_bad_setting_names_the_argument(settings, named):
    with pytest.raises(ValueError) as error:
        lagrange.Scene.from_text(OSCILLATOR).simulate(**settings)
    assert str(error.value).startswith(named + " must")
    assert "--" not in str(error.value)


def test_results_with_one_main_expression_convert_with_sympify(example):
    ch = example("double_pendulum.lag").characteristic()
    assert sympy.sympify(ch) == ch.polynomial
    assert str(ch.polynomial) in repr(ch)
    L = example("double_pendulum.lag").lagrangian()
    assert sympy.sympify(L) == L.lagrangian
    with pytest.raises(sympy.SympifyError):
        sympy.sympify(example("double_pendulum.lag").equilibrium())


def test_another_interpreter_is_told_which_one_the_module_was_built_for(tmp_path):
    """A copy of this interpreter, run without site-packages (-S), stands for a pyenv or
    virtual-environment Python that has no numpy: importing must name the interpreter the
    module was built for and how to build for another."""
    other = tmp_path / "python3"
    shutil.copy(os.path.realpath(sys.executable), other)
    package = os.path.dirname(os.path.dirname(lagrange.__file__))
    result = subprocess.run([str(other), "-S", "-c", f"import sys; sys.path.insert(0, {package!r}); import lagrange"],
                            capture_output=True, text=True)
    assert result.returncode != 0
    assert "ImportError: lagrange was built for " + lagrange._BUILT_FOR in result.stderr
    assert "-DPython3_EXECUTABLE=" + str(other) in result.stderr


def test_a_likely_slip_is_a_scene_warning():
    with pytest.warns(lagrange.SceneWarning) as caught:
        lagrange.Scene.from_text("parameters m k\ncoordinates x\nT = 1/2*m*x^2\nV = 1/2*k*x^2\n", name="slip.lag")
    assert len(caught) == 1
    assert str(caught[0].message).startswith("slip.lag:3:1: warning: `T` has no velocities")


def test_export_writes_the_python_module_and_refuses_a_bad_target(example, tmp_path):
    """The exported module's right-hand side equals the engine's trajectory's first step: here
    its acceleration at rest against M q'' = F solved by hand (numpy) from the same module."""
    import importlib.util
    import numpy
    paths = example("double_pendulum.lag").export("python", tmp_path / "out")
    assert [os.path.basename(p) for p in paths] == ["double_pendulum.py"]
    spec = importlib.util.spec_from_file_location("double_pendulum", paths[0])
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    x = numpy.array([0.1, -0.2, 0.3, 0.0])
    qdd = numpy.linalg.solve(module.mass_matrix(0.0, x), module.forcing(0.0, x))
    assert numpy.allclose(module.rhs(0.0, x), numpy.concatenate([x[2:], qdd]), rtol=1e-14, atol=0)
    assert module.PARAMETERS == ["M", "m", "l", "g"]
    with pytest.raises(ValueError, match="target must be"):
        example("double_pendulum.lag").export("fortran", tmp_path / "bad")
    assert not (tmp_path / "bad").exists()


LADDER_OFF = """
parameters m l g
coordinates x y theta
T = 1/2*m*(x'^2 + y'^2) + 1/2*(m*l^2/12)*theta'^2
V = m*g*y
constraint wall: x = l/2*sin(theta)
constraint floor: y = l/2*cos(theta)
values m = 1, l = 2, g = 9.81
initial theta = 0.3
simulate until 0.2
"""


def test_an_initial_state_off_the_constraints_is_a_scene_error_unless_projected():
    """As the command line: an error at the value, with the projected state suggested;
    ``project_initial=True`` starts from that state and says so, as --project-initial."""
    scene = lagrange.Scene.from_text(LADDER_OFF, name="ladder.lag")
    with pytest.raises(lagrange.SceneError) as error:
        scene.simulate()
    assert (error.value.file, error.value.line, error.value.column) == ("ladder.lag", 9, 17)
    assert "project_initial=True" in str(error.value)
    run = scene.simulate(project_initial=True)
    assert run.projected_initial["y"] == pytest.approx(numpy.cos(0.3), rel=1e-12)
    assert run.states["y"][0] == run.projected_initial["y"]
    assert run.initial_residual == pytest.approx(0.955336, rel=1e-5)
    cli = subprocess.run([CLI, "simulate", "-", "--project-initial", "--format", "json"], input=LADDER_OFF,
                         capture_output=True, text=True, check=True)
    assert json.loads(cli.stdout)["simulation"]["projected_initial"]["y"] == run.projected_initial["y"]
