# SPDX-License-Identifier: GPL-2.0-or-later
"""The Python module under a careless or hostile caller (issue 34, items 4-8): bounded
reads, budgets that hold, Ctrl-C that stops a run at once, fork while the engine works,
names that are Python keywords, and settings and values checked as the command line
checks them."""
import os
import signal
import subprocess
import sys
import textwrap
import threading
import time

import pytest
import sympy

import lagrange


def chain_scene(links):
    """A planar chain of point masses on rods (as tests/helpers/chain_scene.h): its symbolic
    characteristic polynomial takes far longer than a second from about 9 links on."""
    parameters, coordinates, points, x, y = "parameters g", "coordinates", "", "", ""
    for k in range(1, links + 1):
        parameters += f" m{k} l{k}"
        coordinates += f" q{k}"
        x += (" + " if k > 1 else "") + f"l{k}*sin(q{k})"
        y += f" - l{k}*cos(q{k})"
        points += f"point P{k} mass m{k} at ({x},{y})\n"
    return parameters + "\n" + coordinates + "\n" + points + "gravity g along (0, -1)\n"


def test_from_file_refuses_an_endless_file_at_once():
    start = time.monotonic()
    with pytest.raises(OSError, match="larger than"):
        lagrange.Scene.from_file("/dev/zero")
    assert time.monotonic() - start < 5


def test_from_file_refuses_a_pipe_that_gives_nothing(tmp_path):
    fifo = tmp_path / "scene.fifo"
    os.mkfifo(fifo)
    keep = os.open(fifo, os.O_RDWR | os.O_NONBLOCK)  # a writer that never writes
    try:
        start = time.monotonic()
        with pytest.raises(OSError):
            lagrange.Scene.from_file(fifo, max_seconds=0.5)
        assert time.monotonic() - start < 5
    finally:
        os.close(keep)


def test_from_text_refuses_more_than_the_command_line_reads():
    with pytest.raises(lagrange.SceneError, match="larger than 64 MiB"):
        lagrange.Scene.from_text("#" * ((64 << 20) + 1))


def test_max_seconds_holds_inside_a_step_that_cannot_be_interrupted():
    scene = lagrange.Scene.from_text(chain_scene(10))
    start = time.monotonic()
    with pytest.raises(lagrange.BudgetExceeded) as caught:
        scene.document("json", want=["characteristic"], max_terms=10 ** 9, max_seconds=1)
    assert time.monotonic() - start < 8  # the stages before it, and 8 % over the budget (the run alone: minutes)
    assert caught.value.stage == "characteristic"
    assert "max_seconds" in str(caught.value) and "--max-seconds" not in str(caught.value)


def test_ctrl_c_stops_a_run_within_a_fraction_of_a_second(tmp_path):
    script = textwrap.dedent(f"""
        import sys, time
        sys.path.insert(0, {os.path.dirname(os.path.dirname(lagrange.__file__))!r})
        import lagrange
        scene = lagrange.Scene.from_text({chain_scene(10)!r})
        print("running", flush=True)
        try:
            scene.document("json", want=["characteristic"], max_terms=10 ** 9, max_seconds=120)
        except KeyboardInterrupt:
            print("interrupted", flush=True)
    """)
    child = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True)
    assert child.stdout.readline().strip() == "running"
    time.sleep(1.0)
    sent = time.monotonic()
    child.send_signal(signal.SIGINT)
    out, _ = child.communicate(timeout=30)
    assert time.monotonic() - sent < 3  # the run alone would take minutes
    assert out.strip() == "interrupted"
    assert child.returncode == 0


def test_a_fork_while_another_thread_loads_leaves_the_child_usable():
    """A child forked while another thread is inside the engine (a multiprocessing pool)
    must not inherit the engine's lock held: each child loads a scene and analyses it."""
    text = chain_scene(6)
    stop = threading.Event()

    def keep_loading():
        while not stop.is_set():
            lagrange.Scene.from_text(text)

    worker = threading.Thread(target=keep_loading)
    worker.start()
    try:
        for _ in range(10):
            pid = os.fork()
            if pid == 0:
                signal.alarm(20)  # a deadlock ends the child with SIGALRM
                try:
                    scene = lagrange.Scene.from_text("parameters m k\ncoordinates x\nT = 1/2*m*x'^2\nV = 1/2*k*x^2\n")
                    ok = scene.characteristic().polynomial is not None
                finally:
                    os._exit(0 if ok else 1)
            _, status = os.waitpid(pid, 0)
            assert os.WIFEXITED(status) and os.WEXITSTATUS(status) == 0
    finally:
        stop.set()
        worker.join()


# Every Python keyword the scene language lets a parameter take (`and` is its own word), and
# names SymPy gives a meaning (E, S, N, O, Q).
KEYWORDS = ["lambda", "is", "in", "None", "True", "False", "not", "or", "if", "else", "for", "while",
            "def", "class", "return", "import", "from", "as", "with", "pass", "yield", "global", "del", "try",
            "match", "case", "print", "E", "S", "N", "O", "Q", "beta", "gamma", "zeta"]


@pytest.mark.parametrize("name", KEYWORDS)
def test_a_parameter_named_as_a_python_keyword_is_a_symbol(name):
    scene = lagrange.Scene.from_text(f"parameters m k {name}\ncoordinates x\nT = 1/2*m*x'^2\n"
                                     f"V = 1/2*k*x^2 + {name}*x^4\n")
    equation = scene.equations()[0]
    x, m, k, a = sympy.symbols(f"x m k {name}")
    assert sympy.expand(equation - (m * sympy.Symbol("x_ddot") + k * x + 4 * a * x ** 3)) == 0
    converted = scene.analyze("equations")["equations"]
    assert all(isinstance(e, sympy.Basic) for e in converted)  # not raw strings


@pytest.mark.parametrize("settings", [{"max_seconds": float("nan")}, {"max_seconds": 0}, {"max_seconds": -1},
                                      {"max_seconds": float("inf")}, {"max_terms": 0}])
def test_a_budget_cannot_be_switched_off(settings):
    with pytest.raises(ValueError, match="must be a positive, finite number"):
        lagrange.Scene.from_text("parameters m k\ncoordinates x\nT = 1/2*m*x'^2\nV = 1/2*k*x^2\n").document(
            "json", **settings)


@pytest.mark.parametrize("values", [{"m": "0.01, g=1000"}, {"m": "1\nvalues g = 3"}, {"m, g": 1},
                                    {"m": "1; g = 2"}])
def test_a_value_cannot_smuggle_in_another_entry(example, values):
    with pytest.raises(ValueError, match="values"):
        example("double_pendulum.lag").numeric(values)
