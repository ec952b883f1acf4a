// SPDX-License-Identifier: GPL-2.0-or-later
/** @file export_octave.cpp
 *  The MATLAB/Octave target of `lagrange export`: one function file per function. */
#include "output/export_program.h"

#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace lagrange::export_detail {

namespace {

/// The arguments an Octave function may be called without: p from NAME_defaults(), u zero.
std::string octave_defaults(const std::string& name, std::size_t inputs)
{
    return "  if nargin < 3 || isempty(p)\n    p = " + name + "_defaults();\n  end\n  if nargin < 4\n    u = zeros(" +
           std::to_string(inputs) + ", 1);\n  end\n";
}

/// A function file that evaluates `program` into `result`, its outputs as `rows` × `columns`
/// (row by row) after `leading`, rows of the result computed otherwise ("x(3:4); ").
std::string octave_function(const std::string& name, const std::string& function, const std::string& doc,
                            const expression_program& program, const naming& names, const exported_system& system,
                            const std::string& result, std::size_t rows, std::size_t columns,
                            const std::string& header, const std::string& leading = "")
{
    std::ostringstream lines;
    std::set<int> used;
    std::vector<std::string> outputs = write_program(program, dialect::octave, names, "  ", lines, used);
    std::ostringstream out;
    out << "function " << result << " = " << name << "_" << function << "(t, x, p, u)\n"
        << "  % " << doc << "\n" << header
        << octave_defaults(name, system.input_names.size());
    for (int k : used) {
        const argument_place at = place_of(k, system);
        if (at.array != 't')
            out << "  " << names.symbols[static_cast<std::size_t>(k)] << " = " << at.array << "(" << at.index + 1
                << ");\n";
    }
    out << lines.str() << "  " << result << " = [" << leading;
    for (std::size_t r = 0; r < rows; ++r) {
        for (std::size_t c = 0; c < columns; ++c)
            out << (c ? ", " : "") << outputs[r * columns + c];
        out << (r + 1 < rows ? "; " : "");
    }
    out << "];\nend\n";
    return out.str();
}

/// A constrained scene's files: the constraints, and the right-hand side and the multipliers
/// from the augmented system [M −Aᵀ; A 0] [q̈; λ] = [F; −c].
std::vector<exported_file> constrained_files(const exported_system& system, const naming& names,
                                             const std::string& name, const std::string& header)
{
    const std::size_t n = system.coordinates, m = system.constraint_names.size();
    const std::string nq = std::to_string(n), nc = std::to_string(m);
    const std::string inputs = octave_defaults(name, system.input_names.size());
    const std::string parts = "  d = " + name + "_constraint_parts(t, x, p, u);\n";
    const std::string augmented = "  M = " + name + "_mass_matrix(t, x, p, u);\n  F = " + name +
                                  "_forcing(t, x, p, u);\n" + parts + "  A = reshape(d(1:" + nc + " * " + nq + "), " +
                                  nq + ", " + nc + ")';\n  c = d(" + nc + " * " + nq + " + 1:" + nc + " * " + nq +
                                  " + " + nc + ");\n  y = [M, -A'; A, zeros(" + nc + ")] \\ [F; -c];\n";
    std::vector<exported_file> files;
    files.push_back({name + "_constraint_parts.m",
                     octave_function(name, "constraint_parts", "A (row by row), c, then the residuals g, as a column.",
                                     *system.constraint_parts, names, system, "d",
                                     system.constraint_parts->output_count(), 1, header)});
    files.push_back({name + "_constraints.m",
                     "function g = " + name + "_constraints(t, x, p, u)\n  % The residuals g (a column), 0 on the "
                     "motion: f(q, t) of a holonomic constraint, A(q) q' + b of a velocity one.\n" + header + inputs +
                     parts + "  g = d(" + nc + " * " + nq + " + " + nc + " + 1:end);\nend\n"});
    files.push_back({name + "_constraint_jacobian.m",
                     "function A = " + name + "_constraint_jacobian(t, x, p, u)\n  % A (NC x NQ) of the velocity "
                     "form A q' + b = 0.\n" + header + inputs + parts + "  A = reshape(d(1:" + nc + " * " + nq +
                     "), " + nq + ", " + nc + ")';\nend\n"});
    files.push_back({name + "_rhs.m",
                     "function dxdt = " + name + "_rhs(t, x, p, u)\n  % dx/dt as a column: q'' from [M -A'; A 0] "
                     "[q''; lambda] = [F; -c], the constraints\n  % differentiated to the accelerations (" + name +
                     "_constraints measures their drift); for ode45: ode45(@(t, x) " + name +
                     "_rhs(t, x, p), tspan, x0).\n" + header + inputs + augmented + "  dxdt = [x(" + nq + " + 1:2 * " +
                     nq + "); y(1:" + nq + ")];\nend\n"});
    files.push_back({name + "_multipliers.m",
                     "function lambda = " + name + "_multipliers(t, x, p, u)\n  % The multipliers lambda of M q'' = "
                     "F + A' lambda (a column).\n" + header + inputs + augmented + "  lambda = y(" + nq +
                     " + 1:end);\nend\n"});
    files.push_back({name + "_constraint_derivatives.m",
                     octave_function(name, "constraint_derivatives",
                                     "dA/dq_k (k slowest), dc/dq, dc/dq', dc/du, as a column.",
                                     *system.constraint_derivatives, names, system, "e",
                                     system.constraint_derivatives->output_count(), 1, header)});
    // d[q''; lambda]/dy = K \ (d[F; -c]/dy - (dK/dy) [q''; lambda]), K = [M -A'; A 0]
    files.push_back({name + "_jacobian.m",
                     "function [dfdx, dfdu] = " + name + "_jacobian(t, x, p, u)\n  % df/dx (NX x NX) and df/du (NX x "
                     "NU): d[q''; lambda]/dy = K \\ (d[F; -c]/dy - (dK/dy) [q''; lambda]),\n  % K = [M -A'; A 0].\n" +
                     header + inputs + "  n = " + nq + ";\n  m = " + nc + ";\n  nu = " +
                     std::to_string(system.input_names.size()) + ";\n  M = " + name +
                     "_mass_matrix(t, x, p, u);\n  F = " + name + "_forcing(t, x, p, u);\n" + parts +
                     "  A = reshape(d(1:m * n), n, m)';\n  c = d(m * n + 1:m * n + m);\n"
                     "  K = [M, -A'; A, zeros(m)];\n  y = K \\ [F; -c];\n  qdd = y(1:n);\n  lambda = y(n + 1:end);\n"
                     "  D = " + name + "_derivatives(t, x, p, u);\n  E = " + name +
                     "_constraint_derivatives(t, x, p, u);\n  b = m * n^2;\n"
                     "  R = [reshape(D(n^3 + 1:n^3 + n^2), n, n)', reshape(D(n^3 + n^2 + 1:n^3 + 2 * n^2), n, n)', "
                     "reshape(D(n^3 + 2 * n^2 + 1:end), nu, n)';\n"
                     "       -reshape(E(b + 1:b + m * n), n, m)', -reshape(E(b + m * n + 1:b + 2 * m * n), n, m)', "
                     "-reshape(E(b + 2 * m * n + 1:end), nu, m)'];\n"
                     "  for k = 1:n\n    dM = reshape(D((k - 1) * n^2 + 1:k * n^2), n, n)';\n"
                     "    dA = reshape(E((k - 1) * m * n + 1:k * m * n), n, m)';\n"
                     "    R(:, k) = R(:, k) - [dM * qdd - dA' * lambda; dA * qdd];\n  end\n"
                     "  Z = K \\ R;\n  dfdx = [zeros(n), eye(n); Z(1:n, 1:2 * n)];\n"
                     "  dfdu = [zeros(n, nu); Z(1:n, 2 * n + 1:end)];\nend\n"});
    return files;
}

} // namespace

std::vector<exported_file> export_octave(const model& scene, const exported_system& system, const std::string& name,
                                         const std::string& version)
{
    const naming names = name_symbols(system, dialect::octave);
    const std::size_t n = system.coordinates, inputs = system.input_names.size();
    const std::string header = provenance(scene, system, names, version, "  % ");
    const std::size_t derivatives = system.derivatives.output_count();
    std::vector<exported_file> files;
    files.push_back({name + "_mass_matrix.m",
                     octave_function(name, "mass_matrix", "The mass matrix M of M q'' = F (NQ x NQ).", system.mass,
                                     names, system, "M", n, n, header)});
    files.push_back({name + "_forcing.m", octave_function(name, "forcing", "The forcing F of M q'' = F (a column).",
                                                          system.forcing, names, system, "F", n, 1, header)});
    files.push_back({name + "_energy.m",
                     octave_function(name, "energy", "The energy function h = sum q' dL/dq' - L.", system.energy,
                                     names, system, "h", 1, 1, header)});
    if (system.conserved) {
        std::string named;
        for (const std::string& n : system.conserved_names)
            named += (named.empty() ? "" : ", ") + n;
        files.push_back({name + "_conserved.m",
                         octave_function(name, "conserved", "What the motion conserves, a column: " + named + ".",
                                         *system.conserved, names, system, "conserved", system.conserved_names.size(), 1,
                                         header)});
    }
    std::ostringstream defaults;
    defaults << "function p = " << name << "_defaults()\n  % The scene's `values` (the first line), NaN where it "
             << "gives none, in the order of the parameters.\n" << header << "  p = ["
             << number_list(system.defaults, "NaN") << "]';\n  if isempty(p)\n    p = zeros(0, 1);\n  end\nend\n";
    files.push_back({name + "_defaults.m", defaults.str()});
    files.push_back({name + "_derivatives.m",
                     octave_function(name, "derivatives", "dM/dq_k (k slowest), dF/dq, dF/dq', dF/du, as a column.",
                                     system.derivatives, names, system, "d", derivatives, 1, header)});
    if (system.constraint_parts) {
        for (exported_file& file : constrained_files(system, names, name, header))
            files.push_back(std::move(file));
    } else if (system.recursion) { // O(n), as the engine from recursive_coordinates on
        files.push_back({name + "_rhs.m",
                         octave_function(name, "rhs",
                                         "dx/dt = f(t, x, u, p) as a column, q'' by the articulated-body recursion "
                                         "(Inf or NaN where M is singular);\n  % for ode45 and ode15s: ode45(@(t, x) " +
                                             name + "_rhs(t, x, p), tspan, x0).",
                                         *system.recursion, names, system, "dxdt", n, 1, header,
                                         "x(" + std::to_string(n + 1) + ":" + std::to_string(2 * n) + "); ")});
    } else {
        std::ostringstream rhs;
        rhs << "function dxdt = " << name << "_rhs(t, x, p, u)\n"
            << "  % dx/dt = f(t, x, u, p) as a column; for ode45 and ode15s: ode45(@(t, x) " << name
            << "_rhs(t, x, p), tspan, x0).\n" << header
            << octave_defaults(name, inputs)
            << "  M = " << name << "_mass_matrix(t, x, p, u);\n  F = " << name << "_forcing(t, x, p, u);\n"
            << "  dxdt = [x(" << n + 1 << ":" << 2 * n << "); M \\ F];\nend\n";
        files.push_back({name + "_rhs.m", rhs.str()});
    }
    if (!system.constraint_parts) {
        std::ostringstream jac;
        jac << "function [dfdx, dfdu] = " << name << "_jacobian(t, x, p, u)\n"
            << "  % df/dx (NX x NX) and df/du (NX x NU): d(q'')/dy = M \\ (dF/dy - (dM/dy) q'').\n" << header
            << octave_defaults(name, inputs)
            << "  n = " << n << ";\n  m = " << inputs << ";\n"
            << "  M = " << name << "_mass_matrix(t, x, p, u);\n  F = " << name << "_forcing(t, x, p, u);\n"
            << "  d = " << name << "_derivatives(t, x, p, u);\n  qdd = M \\ F;\n"
            << "  dq = reshape(d(n^3 + 1:n^3 + n^2), n, n)';\n"
            << "  for k = 1:n\n    dq(:, k) = dq(:, k) - reshape(d((k - 1) * n^2 + 1:k * n^2), n, n)' * qdd;\n  end\n"
            << "  dv = reshape(d(n^3 + n^2 + 1:n^3 + 2 * n^2), n, n)';\n"
            << "  dfdx = [zeros(n), eye(n); M \\ dq, M \\ dv];\n"
            << "  dfdu = [zeros(n, m); M \\ reshape(d(n^3 + 2 * n^2 + 1:end), m, n)'];\nend\n";
        files.push_back({name + "_jacobian.m", jac.str()});
    }
    if (system.linear) {
        files.push_back({name + "_linear_parts.m",
                         octave_function(name, "linear_parts", "The equilibrium's state, then T and V, as a column.",
                                         *system.linear, names, system, "d", system.linear->output_count(), 1,
                                         header)});
        const std::string call = "  if nargin < 1 || isempty(p)\n    p = " + name + "_defaults();\n  end\n  d = " +
                                 name + "_linear_parts(0, zeros(" + std::to_string(2 * n) + ", 1), p);\n";
        files.push_back({name + "_equilibrium.m",
                         "function x = " + name + "_equilibrium(p)\n  % The state the small oscillations are about "
                         "(a column).\n" + header + call + "  x = d(1:" + std::to_string(2 * n) + ");\nend\n"});
        files.push_back({name + "_linear.m",
                         "function [T, V] = " + name + "_linear(p)\n  % T and V of T q'' + V q = 0 at the "
                         "equilibrium.\n" + header + call + "  n = " + std::to_string(n) + ";\n"
                         "  T = reshape(d(2 * n + 1:2 * n + n^2), n, n)';\n"
                         "  V = reshape(d(2 * n + n^2 + 1:2 * n + 2 * n^2), n, n)';\nend\n"});
    }
    return files;
}

} // namespace lagrange::export_detail
