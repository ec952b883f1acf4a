// SPDX-License-Identifier: GPL-2.0-or-later
/** @file export_python.cpp
 *  The Python target of `lagrange export`: NAME.py, functions on NumPy arrays. */
#include "output/export_program.h"

#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace lagrange::export_detail {

namespace {

std::string python_function(const std::string& function, const std::string& doc, const expression_program& program,
                            const naming& names, const exported_system& system, const std::string& result)
{
    std::ostringstream lines;
    std::set<int> used;
    std::vector<std::string> outputs = write_program(program, dialect::python, names, "    ", lines, used);
    std::ostringstream out;
    out << "def " << function << "(t, x, p=None, u=None):\n    \"\"\"" << doc << "\"\"\"\n"
        << "    t, x, p, u, shape = _arguments(t, x, p, u)\n";
    for (int k : used) {
        const argument_place at = place_of(k, system);
        if (at.array != 't')
            out << "    " << names.symbols[static_cast<std::size_t>(k)] << " = _column(" << at.array << ", " << at.index
                << ")\n";
    }
    out << lines.str() << "    return " << result << "(shape, ";
    for (std::size_t k = 0; k < outputs.size(); ++k)
        out << (k ? ", " : "") << outputs[k];
    out << ")\n\n\n";
    return out.str();
}

/// A constrained scene's functions: the constraints, and the right-hand side and the
/// multipliers from the augmented system [M −Aᵀ; A 0] [q̈; λ] = [F; −c].
std::string constrained_functions(const exported_system& system, const naming& names, const std::string& list)
{
    std::ostringstream py;
    py << "NC = " << system.constraint_names.size() << "\nCONSTRAINTS = " << list << "\n\n\n"
       << python_function("_constraint_parts", "A (flattened), c, then the residuals g.", *system.constraint_parts,
                          names, system, "_vector")
       << "def constraints(t, x, p=None, u=None):\n"
       << "    \"\"\"The residuals g, shape (..., NC), 0 on the motion: f(q, t) of a holonomic constraint,\n"
       << "    A(q) q' + b of a velocity one.\"\"\"\n"
       << "    return _constraint_parts(t, x, p, u)[..., NC * NQ + NC:]\n\n\n"
       << "def constraint_jacobian(t, x, p=None, u=None):\n"
       << "    \"\"\"A of the velocity form A q' + b = 0, shape (..., NC, NQ).\"\"\"\n"
       << "    parts = _constraint_parts(t, x, p, u)\n"
       << "    return parts[..., :NC * NQ].reshape(parts.shape[:-1] + (NC, NQ))\n\n\n"
       << "def _augmented(t, x, p, u):\n"
       << "    t, x, p, u, shape = _arguments(t, x, p, u)\n"
       << "    both = _mass_and_forcing(t, x, p, u)\n"
       << "    parts = _constraint_parts(t, x, p, u)\n"
       << "    a = parts[..., :NC * NQ].reshape(shape + (NC, NQ))\n"
       << "    k = np.zeros(shape + (NQ + NC, NQ + NC))\n"
       << "    k[..., :NQ, :NQ] = both[..., :NQ * NQ].reshape(shape + (NQ, NQ))\n"
       << "    k[..., :NQ, NQ:] = -np.swapaxes(a, -1, -2)\n    k[..., NQ:, :NQ] = a\n"
       << "    b = np.concatenate([both[..., NQ * NQ:], -parts[..., NC * NQ:NC * NQ + NC]], axis=-1)\n"
       << "    return x, shape, np.linalg.solve(k, b[..., None])[..., 0], k\n\n\n"
       << "def rhs(t, x, p=None, u=None):\n"
       << "    \"\"\"dx/dt, shape (..., NX): q'' from [M -A^T; A 0] [q''; lambda] = [F; -c], the constraints\n"
       << "    differentiated to the accelerations (constraints() measures their drift).\"\"\"\n"
       << "    x, shape, y, _ = _augmented(t, x, p, u)\n"
       << "    return np.concatenate([np.broadcast_to(np.asarray(x)[..., NQ:], shape + (NQ,)), y[..., :NQ]], axis=-1)\n\n\n"
       << "def multipliers(t, x, p=None, u=None):\n"
       << "    \"\"\"The multipliers lambda of M q'' = F + A^T lambda, shape (..., NC).\"\"\"\n"
       << "    return _augmented(t, x, p, u)[2][..., NQ:]\n\n\n"
       << python_function("_constraint_derivatives", "dA/dq_k (k slowest), dc/dq, dc/dq', dc/du, flattened.",
                          *system.constraint_derivatives, names, system, "_vector")
       << "def jacobian(t, x, p=None, u=None):\n"
       << "    \"\"\"(df/dx of shape (..., NX, NX), df/du of shape (..., NX, NU)): d[q''; lambda]/dy =\n"
       << "    K^-1 (d[F; -c]/dy - (dK/dy) [q''; lambda]) with K = [M -A^T; A 0].\"\"\"\n"
       << "    _, shape, y, k = _augmented(t, x, p, u)\n"
       << "    d, e = _derivatives(t, x, p, u), _constraint_derivatives(t, x, p, u)\n"
       << "    d, e = np.broadcast_to(d, shape + d.shape[-1:]), np.broadcast_to(e, shape + e.shape[-1:])\n"
       << "    qdd, lam = y[..., :NQ], y[..., NQ:]\n"
       << "    n3, n2, m2 = NQ ** 3, NQ * NQ, NC * NQ * NQ\n"
       << "    dmass = d[..., :n3].reshape(shape + (NQ, NQ, NQ))\n"
       << "    da = e[..., :m2].reshape(shape + (NQ, NC, NQ))\n"
       << "    top = np.concatenate([d[..., n3:n3 + n2].reshape(shape + (NQ, NQ))\n"
       << "                          - np.einsum(\"...kij,...j->...ik\", dmass, qdd)\n"
       << "                          + np.einsum(\"...kri,...r->...ik\", da, lam),\n"
       << "                          d[..., n3 + n2:n3 + 2 * n2].reshape(shape + (NQ, NQ)),\n"
       << "                          d[..., n3 + 2 * n2:].reshape(shape + (NQ, NU))], axis=-1)\n"
       << "    bottom = np.concatenate([-e[..., m2:m2 + NC * NQ].reshape(shape + (NC, NQ))\n"
       << "                             - np.einsum(\"...krj,...j->...rk\", da, qdd),\n"
       << "                             -e[..., m2 + NC * NQ:m2 + 2 * NC * NQ].reshape(shape + (NC, NQ)),\n"
       << "                             -e[..., m2 + 2 * NC * NQ:].reshape(shape + (NC, NU))], axis=-1)\n"
       << "    z = np.linalg.solve(k, np.concatenate([top, bottom], axis=-2))\n"
       << "    dfdx = np.zeros(shape + (NX, NX))\n"
       << "    dfdx[..., :NQ, NQ:] = np.eye(NQ)\n    dfdx[..., NQ:, :] = z[..., :NQ, :NX]\n"
       << "    dfdu = np.zeros(shape + (NX, NU))\n    dfdu[..., NQ:, :] = z[..., :NQ, NX:]\n"
       << "    return dfdx, dfdu\n";
    return py.str();
}

} // namespace

std::vector<exported_file> export_python(const model& scene, const exported_system& system, const std::string& name,
                                         const std::string& version)
{
    const naming names = name_symbols(system, dialect::python);
    const std::size_t n = system.coordinates;
    auto quoted_list = [](const std::vector<std::string>& words) {
        std::string out;
        for (const std::string& w : words)
            out += (out.empty() ? "\"" : ", \"") + w + "\"";
        return "[" + out + "]";
    };
    std::ostringstream py;
    py << "\"\"\"" << name << ": the equations of motion as functions on NumPy arrays.\n\n"
       << provenance(scene, system, names, version, "")
       << "Every function takes (t, x, p=DEFAULTS, u=None) and works on a leading batch axis: x of shape\n"
       << "(..., NX), p of shape (..., NP), u of shape (..., NU). rhs works with scipy.integrate.solve_ivp:\n"
       << "solve_ivp(rhs, (0, 10), x0, args=(DEFAULTS,)).\n\"\"\"\nimport numpy as np\n\n"
       << "NQ = " << n << "\nNX = " << 2 * n << "\nNU = " << system.input_names.size() << "\nNP = "
       << system.parameter_names.size() << "\n"
       << "STATE = " << quoted_list(system.state_names) << "\n"
       << "PARAMETERS = " << quoted_list(system.parameter_names) << "\n"
       << "INPUTS = " << quoted_list(system.input_names) << "\n"
       << (system.conserved ? "CONSERVED = " + quoted_list(system.conserved_names) + "\n" : "")
       << "DEFAULTS = np.array([" << number_list(system.defaults, "np.nan") << "], dtype=float)\n\n\n"
       << "def _arguments(t, x, p, u):\n"
       << "    x = np.asarray(x, dtype=float)\n"
       << "    p = DEFAULTS if p is None else np.asarray(p, dtype=float)\n"
       << "    u = np.zeros(NU) if u is None else np.asarray(u, dtype=float)\n"
       << "    if x.shape[-1:] != (NX,) or p.shape[-1:] != (NP,) or u.shape[-1:] != (NU,):\n"
       << "        raise ValueError(f\"x, p and u end in {NX}, {NP} and {NU} entries, not {x.shape}, {p.shape}, "
          "{u.shape}\")\n"
       << "    t = np.asarray(t, dtype=float)\n"
       << "    shape = np.broadcast_shapes(t.shape, x.shape[:-1], p.shape[:-1], u.shape[:-1])\n"
       << "    if shape == ():  # one state: Python floats, far quicker than NumPy's 0-d arrays\n"
       << "        return float(t), x.tolist(), p.tolist(), u.tolist(), shape\n"
       << "    return t, x, p, u, shape\n\n\n"
       << "def _column(a, k):\n    return a[k] if isinstance(a, list) else a[..., k]\n\n\n"
       << "def _vector(shape, *values):\n"
       << "    if shape == ():\n        return np.array(values, dtype=float)\n"
       << "    return np.stack([np.broadcast_to(np.asarray(v, dtype=float), shape) for v in values], axis=-1)\n\n\n"
       << "def _square(shape, *values):\n    return _vector(shape, *values).reshape(shape + (NQ, NQ))\n\n\n"
       << "def _scalar(shape, value):\n    return np.broadcast_to(np.asarray(value, dtype=float), shape).copy()\n\n\n";
    py << python_function("mass_matrix", "The mass matrix M of M q'' = F, shape (..., NQ, NQ).", system.mass, names,
                          system, "_square");
    py << python_function("forcing", "The forcing F of M q'' = F, shape (..., NQ).", system.forcing, names, system,
                          "_vector");
    py << python_function("_mass_and_forcing", "M (flattened) then F, their common parts computed once.",
                          system.mass_and_forcing, names, system, "_vector");
    py << python_function("energy", "The energy function h = sum q' dL/dq' - L.", system.energy, names, system,
                          "_scalar");
    if (system.conserved)
        py << python_function("conserved",
                              "What the motion conserves, shape (..., len(CONSERVED)), named in CONSERVED: the\n"
                              "    energy function where L does not depend on t, then each cyclic coordinate's momentum.",
                              *system.conserved, names, system, "_vector");
    py << python_function("_derivatives", "dM/dq_k (k slowest), dF/dq, dF/dq', dF/du, flattened.",
                          system.derivatives, names, system, "_vector");
    if (system.recursion)
        py << python_function("_recursion", "q'' by the articulated-body recursion, shape (..., NQ).", *system.recursion,
                              names, system, "_vector");
    if (system.constraint_parts)
        py << constrained_functions(system, names, quoted_list(system.constraint_names));
    else if (system.recursion) // O(n), as the engine from recursive_coordinates on
        py << "def rhs(t, x, p=None, u=None):\n"
           << "    \"\"\"dx/dt = f(t, x, u, p), shape (..., NX), q'' by the articulated-body recursion;\n"
           << "    numpy.linalg.LinAlgError where M is singular (a zero pivot: a q'' not finite).\"\"\"\n"
           << "    t, x, p, u, shape = _arguments(t, x, p, u)\n"
           << "    try:\n        qdd = _recursion(t, x, p, u)\n"
           << "    except ZeroDivisionError:  # one state, on Python floats\n"
           << "        raise np.linalg.LinAlgError(\"singular mass matrix\") from None\n"
           << "    if not np.isfinite(qdd).all():\n"
           << "        raise np.linalg.LinAlgError(\"singular mass matrix\")\n"
           << "    return np.concatenate([np.broadcast_to(np.asarray(x)[..., NQ:], shape + (NQ,)), qdd], axis=-1)\n\n\n";
    else
        py << "def rhs(t, x, p=None, u=None):\n"
           << "    \"\"\"dx/dt = f(t, x, u, p), shape (..., NX); numpy.linalg.LinAlgError where M is singular.\"\"\"\n"
           << "    t, x, p, u, shape = _arguments(t, x, p, u)\n"
           << "    both = _mass_and_forcing(t, x, p, u)\n"
           << "    mass, force = both[..., :NQ * NQ].reshape(shape + (NQ, NQ)), both[..., NQ * NQ:]\n"
           << "    qdd = np.linalg.solve(mass, force[..., None])[..., 0]\n"
           << "    return np.concatenate([np.broadcast_to(np.asarray(x)[..., NQ:], shape + (NQ,)), qdd], axis=-1)\n\n\n";
    if (!system.constraint_parts)
        py << "def jacobian(t, x, p=None, u=None):\n"
           << "    \"\"\"(df/dx of shape (..., NX, NX), df/du of shape (..., NX, NU)).\"\"\"\n"
           << "    t, x, p, u, shape = _arguments(t, x, p, u)\n"
           << "    both = _mass_and_forcing(t, x, p, u)\n"
           << "    mass, force = both[..., :NQ * NQ].reshape(shape + (NQ, NQ)), both[..., NQ * NQ:]\n"
           << "    d = _derivatives(t, x, p, u)\n"
           << "    dmass = d[..., :NQ ** 3].reshape(shape + (NQ, NQ, NQ))\n"
           << "    dfq = d[..., NQ ** 3:NQ ** 3 + NQ * NQ].reshape(shape + (NQ, NQ))\n"
           << "    dfv = d[..., NQ ** 3 + NQ * NQ:NQ ** 3 + 2 * NQ * NQ].reshape(shape + (NQ, NQ))\n"
           << "    dfu = d[..., NQ ** 3 + 2 * NQ * NQ:].reshape(shape + (NQ, NU))\n"
           << "    qdd = np.linalg.solve(mass, force[..., None])[..., 0]\n"
           << "    # d(q'')/dy = M^-1 (dF/dy - (dM/dy) q''): dM/dq_k q'' as column k\n"
           << "    dq = np.linalg.solve(mass, dfq - np.einsum(\"...kij,...j->...ik\", dmass, qdd))\n"
           << "    dv = np.linalg.solve(mass, dfv)\n"
           << "    dfdx = np.zeros(shape + (NX, NX))\n"
           << "    dfdx[..., :NQ, NQ:] = np.eye(NQ)\n    dfdx[..., NQ:, :NQ] = dq\n    dfdx[..., NQ:, NQ:] = dv\n"
           << "    dfdu = np.zeros(shape + (NX, NU))\n"
           << "    if NU:\n        dfdu[..., NQ:, :] = np.linalg.solve(mass, dfu)\n"
           << "    return dfdx, dfdu\n";
    if (system.linear)
        py << "\n\n"
           << python_function("_linear", "The equilibrium's state, then T and V, flattened.", *system.linear, names,
                              system, "_vector")
           << "def equilibrium(p=None):\n"
           << "    \"\"\"The state the small oscillations are about, shape (..., NX).\"\"\"\n"
           << "    return _linear(0.0, np.zeros(NX), p)[..., :NX]\n\n\n"
           << "def linear(p=None):\n"
           << "    \"\"\"(T, V) of T q'' + V q = 0 at the equilibrium, each of shape (..., NQ, NQ).\"\"\"\n"
           << "    both = _linear(0.0, np.zeros(NX), p)\n    shape = both.shape[:-1]\n"
           << "    return (both[..., NX:NX + NQ * NQ].reshape(shape + (NQ, NQ)),\n"
           << "            both[..., NX + NQ * NQ:].reshape(shape + (NQ, NQ)))\n";
    return {{name + ".py", py.str()}};
}

} // namespace lagrange::export_detail
