# SPDX-License-Identifier: GPL-2.0-or-later
"""scene.poincare(): the command line's Poincaré section as numpy arrays, the same numbers
as `lagrange poincare`'s CSV (compared by value), the same for 1 and 2 threads, the energy
kept at every crossing (H written out here), a section of three coordinates, and its errors; scene.animate(): the command
line's player."""
import os
import subprocess

import numpy
import pytest

import lagrange

HERE = os.path.dirname(os.path.abspath(__file__))
HENON_HEILES = os.path.normpath(os.path.join(HERE, "..", "scenes", "henon_heiles.lag"))
CLI = os.environ.get("LAGRANGE_CLI", "")
SECTION = "x = 0, x' > 0"


def energy(q, q_dot):
    """Hénon–Heiles' H = ½(ẋ² + ẏ²) + ½(x² + y²) + x²y − y³/3."""
    x, y = q[:, 0], q[:, 1]
    return 0.5 * (q_dot ** 2).sum(axis=1) + 0.5 * (x ** 2 + y ** 2) + x ** 2 * y - y ** 3 / 3


@pytest.fixture(scope="module")
def henon_heiles():
    return lagrange.Scene.from_file(HENON_HEILES)


@pytest.mark.skipif(not os.access(CLI, os.X_OK), reason="needs the lagrange command (LAGRANGE_CLI, set by ctest)")
def test_poincare_gives_the_command_lines_numbers(henon_heiles, tmp_path):
    section = henon_heiles.poincare(SECTION, 1 / 12, orbits=8, crossings=40, seed=7, threads=2)
    csv = tmp_path / "section.csv"
    subprocess.run([CLI, "poincare", HENON_HEILES, "--section", SECTION, "--energy", repr(1 / 12), "--orbits", "8",
                    "--crossings", "40", "--seed", "7", "-o", str(csv)], check=True, capture_output=True)
    table = numpy.loadtxt(csv, delimiter=",", skiprows=1, ndmin=2)
    assert section.coordinates == ["x", "y"]
    assert len(section) == table.shape[0] == 8 * 40
    assert numpy.array_equal(section.orbit, table[:, 0].astype(int))
    assert numpy.array_equal(section.t, table[:, 1])
    assert numpy.array_equal(section.q, table[:, 2:4])
    assert numpy.array_equal(section.q_dot, table[:, 4:6])


def test_poincare_is_the_same_on_one_and_two_threads_and_keeps_the_energy(henon_heiles):
    one = henon_heiles.poincare(SECTION, 1 / 12, orbits=6, crossings=30, threads=1)
    two = henon_heiles.poincare(SECTION, 1 / 12, orbits=6, crossings=30, threads=2)
    assert numpy.array_equal(one.q, two.q) and numpy.array_equal(one.q_dot, two.q_dot)
    assert numpy.array_equal(one.t, two.t)
    # On the section x = 0 going through it with ẋ > 0, at the energy 1/12 to the tolerance.
    assert numpy.all(numpy.abs(one.q[:, 0]) <= 1e-12)
    assert numpy.all(one.q_dot[:, 0] > 0)
    assert numpy.max(numpy.abs(energy(one.q, one.q_dot) - 1 / 12)) <= 1e-9


def test_poincare_of_three_coordinates_has_every_column_on_its_ellipse():
    # Three uncoupled oscillators (k = 1, 2, 3): each orbit's (y, y') and (z, z') stay on their
    # ellipses (1/2) y'^2 + y^2 = E_y and (1/2) z'^2 + (3/2) z^2 = E_z.
    scene = lagrange.Scene.from_file(os.path.join(HERE, "..", "scenes", "three_oscillators.lag"))
    section = scene.poincare("x = 0, x' > 0", 1, orbits=4, crossings=20, tolerance=1e-10, threads=2)
    assert section.coordinates == ["x", "y", "z"]
    assert section.q.shape == (80, 3) and section.q_dot.shape == (80, 3)
    numpy.testing.assert_allclose(section.q[:, 0], 0, atol=1e-12)
    for k in range(4):
        rows = section.orbit == k
        y, z, v, w = section.q[rows, 1], section.q[rows, 2], section.q_dot[rows, 1], section.q_dot[rows, 2]
        numpy.testing.assert_allclose(0.5 * v ** 2 + y ** 2, 0.5 * v[0] ** 2 + y[0] ** 2, atol=1e-9)
        numpy.testing.assert_allclose(0.5 * w ** 2 + 1.5 * z ** 2, 0.5 * w[0] ** 2 + 1.5 * z[0] ** 2, atol=1e-9)


def test_poincare_errors(henon_heiles):
    with pytest.raises(lagrange.SceneError) as error:
        henon_heiles.poincare("psi = 0", 0.1)
    assert (error.value.file, error.value.line, error.value.column) == ("--section", 1, 1)
    with pytest.raises(ValueError, match="below the minimum of the energy"):
        henon_heiles.poincare(SECTION, -1)
    with pytest.raises(ValueError, match="orbits must be a positive integer"):
        henon_heiles.poincare(SECTION, 0.1, orbits=0)
    none = henon_heiles.poincare("x = 1.2", 1 / 12, orbits=2)
    assert len(none) == 0
    assert "lies outside the energy surface" in none.no_crossings


@pytest.mark.skipif(not os.access(CLI, os.X_OK), reason="needs the lagrange command (LAGRANGE_CLI, set by ctest)")
def test_animate_gives_the_command_lines_player(tmp_path):
    """scene.animate(): the page of `lagrange animate -o FILE.html`, byte for byte, which
    Jupyter shows in a sandboxed frame; a free body's page carries Poinsot's construction."""
    path = os.path.normpath(os.path.join(HERE, "..", "..", "examples", "double_pendulum.lag"))
    animation = lagrange.Scene.from_file(path).animate(until=3, fps=10, trail=1)
    page = tmp_path / "player.html"
    subprocess.run([CLI, "animate", path, "--until", "3", "--fps", "10", "--trail", "1", "-o", str(page)], check=True)
    assert animation.html == page.read_text(encoding="utf-8")
    shown = animation._repr_html_()
    assert shown.startswith("<iframe") and 'sandbox="allow-scripts"' in shown and "lagrangePlayer" in shown
    free = os.path.normpath(os.path.join(HERE, "..", "..", "examples", "free_asymmetric_top.lag"))
    assert '"poinsot":{' in lagrange.Scene.from_file(free).animate(until=2).html
    with pytest.raises(ValueError, match="view must be"):
        lagrange.Scene.from_file(path).animate(view="yz")


def test_a_runs_animate_is_the_scenes_player_of_that_run():
    """run.animate() on a simulation: the player of the same run, as scene.animate() gives it."""
    path = os.path.normpath(os.path.join(HERE, "..", "..", "examples", "double_pendulum.lag"))
    scene = lagrange.Scene.from_file(path)
    run = scene.simulate(until=2, tolerance=1e-8, initial={"theta": 0.4})
    animation = run.animate(fps=10)
    assert type(animation).__name__ == "Animation"
    assert animation.html == scene.animate(until=2, fps=10, tolerance=1e-8, initial={"theta": 0.4}).html
    assert animation.html != scene.animate(until=2, fps=10, tolerance=1e-8).html


def test_animate_keeps_a_constraint_and_projects_only_when_asked():
    # The Cartesian rod pendulum x² + y² = l² (l = 2), started off the circle.
    scene = lagrange.Scene.from_text("scene \"Rod\"\nparameters m g l\ncoordinates x y\npoint P mass m at (x, y)\n"
                           "gravity g along (0, -1)\nconstraint rod: x^2 + y^2 = l^2\nvalues m = 1, g = 9.81, l = 2\n"
                           "initial x = 1.2, y = -1.5\n")
    with pytest.raises(lagrange.SceneError, match="off the constraints"):
        scene.animate(until=1, fps=10)
    page = scene.animate(until=1, fps=10, project_initial=True)
    assert "lagrangePlayer" in page._repr_html_()
