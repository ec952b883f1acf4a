#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Executes a notebook with nbclient and fails (exit 1, naming the cell) if any cell fails.
The kernel is this interpreter (sys.executable), so the notebook sees the same `lagrange`
package (PYTHONPATH) and the same numpy and sympy.
    run_notebook.py NOTEBOOK.ipynb"""
import json
import os
import sys
import tempfile


def main(path):
    with tempfile.TemporaryDirectory() as home:
        # A kernel spec of this interpreter, found first on JUPYTER_PATH; runtime files in a
        # private folder (CI machines may have no writable home).
        spec = os.path.join(home, "kernels", "lagrange-python")
        os.makedirs(spec)
        with open(os.path.join(spec, "kernel.json"), "w") as f:
            json.dump({"argv": [sys.executable, "-m", "ipykernel_launcher", "-f", "{connection_file}"],
                       "display_name": "lagrange (this Python)", "language": "python"}, f)
        os.environ["JUPYTER_PATH"] = home
        os.environ["JUPYTER_RUNTIME_DIR"] = os.path.join(home, "runtime")
        os.environ["IPYTHONDIR"] = os.path.join(home, "ipython")
        import nbformat
        from nbclient import NotebookClient
        from nbclient.exceptions import CellExecutionError

        notebook = nbformat.read(path, as_version=4)
        client = NotebookClient(notebook, timeout=600, kernel_name="lagrange-python",
                                resources={"metadata": {"path": os.path.dirname(os.path.abspath(path))}})
        try:
            client.execute()
        except CellExecutionError as error:
            print(f"{path}: a cell failed:\n{error}", file=sys.stderr)
            return 1
    cells = sum(1 for c in notebook.cells if c.cell_type == "code")
    print(f"{path}: all {cells} code cells ran")
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1]))
