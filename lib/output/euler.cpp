// SPDX-License-Identifier: GPL-2.0-or-later
/** @file euler.cpp
 *  The `euler` family: Euler's equations of each free body, in principal axes, their
 *  torque-free solution (symmetric or Jacobi elliptic), the conserved quantities, Poinsot's
 *  construction and the stability of rotations, in text, LaTeX, JSON and the report (with
 *  the polhode, ω(t) and the seed's Figure 8). */
#include "output/body_family.h"

#include "core/number_text.h"
#include "output/latex_blocks.h"
#include "output/print.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace lagrange {

namespace {

/// A number in LaTeX math: the shortest round trip, its exponent as \times10^{k}.
std::string latex_round_trip(double x) { return latex_exponent(round_trip(x)); }

term_order euler_order(const euler_result& e)
{
    return {{e.rates, e.omega}};
}

std::string omega_name(const GiNaC::ex& w, syntax s) { return print(w, s); }

std::string gnuplot_number(double x) { return significant(std::abs(x) < 1e-14 ? 0.0 : x, 9); }

/// A name of ω_k for gnuplot's labels (plain text, Unicode).
std::string plain_name(const GiNaC::ex& e) { return print(e, syntax::text); }

/// The polhode on the inertia ellipsoid of semi-axes `axes`, drawn in 3D: ω's (ωᵀIω = 2T)
/// or, `scaled`, ρ = ω/√(2T)'s (ρᵀIρ = 1), as the report states the construction.
void polhode_figure(report_writer& w, const euler_result& e, const std::array<double, 3>& axes,
                    const std::vector<std::array<double, 3>>& polhode, bool scaled, const std::string& tag)
{
    if (polhode.empty())
        return;
    std::string script = "set parametric\nset view equal xyz\nset view 64, 28, 1.2\nset ticslevel 0\nset hidden3d\n"
                         "set urange [0:2*pi]\nset vrange [-pi/2:pi/2]\nset isosamples 25, 13\n"
                         "set key at screen 0.98, 0.97 right top\nset xtics 0.5 offset 0, -0.5\nset ytics 0.5\nset ztics 0.5\n";
    const std::string per = scaled ? "/√(2T)" : "";
    script += "set xlabel '" + plain_name(e.omega[0]) + per + "'\nset ylabel '" + plain_name(e.omega[1]) + per +
              "'\nset zlabel '" + plain_name(e.omega[2]) + per + "'\n";
    script += "$polhode << EOD\n";
    for (const auto& point : polhode)
        script += gnuplot_number(point[0]) + " " + gnuplot_number(point[1]) + " " + gnuplot_number(point[2]) + "\n";
    const auto& first = polhode.front();
    script += gnuplot_number(first[0]) + " " + gnuplot_number(first[1]) + " " + gnuplot_number(first[2]) + "\nEOD\n";
    script += "splot " + gnuplot_number(axes[0]) + "*cos(u)*cos(v), " + gnuplot_number(axes[1]) +
              "*sin(u)*cos(v), " + gnuplot_number(axes[2]) +
              "*sin(v) with lines lc rgb '#c8c8c8' title 'inertia ellipsoid', "
              "$polhode using 1:2:3 with lines lw 2.5 lc rgb '#c00000' title 'polhode'\n";
    w.figure(tag + "polhode", script, 12, 10,
             "The polhode of body " + body_title(e.body) +
                 (scaled ? ": the tip of $\\boldsymbol{\\rho} = \\boldsymbol{\\omega}/\\sqrt{2T}$ over one period, on the "
                           "inertia ellipsoid $\\boldsymbol{\\rho}^{T}\\mathbf{I}\\boldsymbol{\\rho} = 1$."
                         : ": the tip of $\\boldsymbol{\\omega}$ over one period, on the inertia ellipsoid "
                           "$\\boldsymbol{\\omega}^{T}\\mathbf{I}\\boldsymbol{\\omega} = 2T$."));
}

/// The seed's Figure 8: Poinsot's construction in space at t = 0 — the inertia ellipsoid
/// ρᵀIρ = 1 turned to its orientation then, resting on the invariable plane, the polhode on it,
/// ω through the point of contact, and the herpolhode the contact traces on the plane.
void poinsot_figure(report_writer& w, const poinsot_motion& m, const std::string& tag)
{
    if (m.rotation.empty() || m.polhode.empty())
        return;
    const auto& R = m.rotation.front();
    const auto& a = m.semi_axes;
    auto triple = [](const std::array<double, 3>& r) {
        return gnuplot_number(r[0]) + " " + gnuplot_number(r[1]) + " " + gnuplot_number(r[2]) + "\n";
    };
    double half = std::max({a[0], a[1], a[2]});
    for (const auto& c : m.contact)
        half = std::max({half, std::abs(c[0]), std::abs(c[1])});
    half *= 1.15;
    const std::string z = gnuplot_number(-m.plane_distance), h = gnuplot_number(half);
    std::string script = "set parametric\nset view equal xyz\nset view 68, 32, 1.25\nset ticslevel 0\n"
                         "set urange [0:2*pi]\nset vrange [-pi/2:pi/2]\nset isosamples 19, 11\nunset xtics\nunset ytics\n"
                         "unset ztics\nunset border\nset key at screen 0.99, 0.98 right top\n";
    script += "$plane << EOD\n";
    for (int k = -4; k <= 4; ++k) {
        const std::string s = gnuplot_number(k * half / 4);
        script += "-" + h + " " + s + " " + z + "\n" + h + " " + s + " " + z + "\n\n\n" + s + " -" + h + " " + z + "\n" +
                  s + " " + h + " " + z + "\n\n\n";
    }
    script += "EOD\n$polhode << EOD\n";
    for (const auto& b : m.polhode)
        script += triple({R[0] * b[0] + R[1] * b[1] + R[2] * b[2], R[3] * b[0] + R[4] * b[1] + R[5] * b[2],
                          R[6] * b[0] + R[7] * b[1] + R[8] * b[2]});
    script += "EOD\n$herpolhode << EOD\n";
    for (const auto& c : m.contact)
        script += triple(c);
    script += "EOD\n$omega << EOD\n0 0 0\n" + triple(m.contact.front()) + "EOD\n";
    // The ellipsoid's surface: body point (a cos u cos v, b sin u cos v, c sin v) turned by R(0).
    std::string surface;
    for (int i = 0; i < 3; ++i)
        surface += std::string(i ? ", " : "") + gnuplot_number(R[3 * i] * a[0]) + "*cos(u)*cos(v) + " +
                   gnuplot_number(R[3 * i + 1] * a[1]) + "*sin(u)*cos(v) + " + gnuplot_number(R[3 * i + 2] * a[2]) +
                   "*sin(v)";
    script += "splot " + surface + " with lines lc rgb '#c8c8c8' title 'inertia ellipsoid', "
              "$plane using 1:2:3 with lines lc rgb '#9ab0d0' title 'invariable plane', "
              "$herpolhode using 1:2:3 with lines lw 2 lc rgb '#1f4e9c' title 'herpolhode', "
              "$polhode using 1:2:3 with lines lw 2.5 lc rgb '#c00000' title 'polhode', "
              "$omega using 1:2:3 with lines lw 2.5 lc rgb '#e07000' title 'ω'\n";
    w.figure(tag + "poinsot", script, 13, 11,
             "Poinsot's construction for body " + body_title(m.body) +
                 ": the inertia ellipsoid $\\boldsymbol{\\rho}^{T}\\mathbf{I}\\boldsymbol{\\rho} = 1$ at $t = 0$, "
                 "touching the invariable plane (normal to $\\mathbf{L}$, at $\\sqrt{2T}/|\\mathbf{L}| = " +
                 report_writer::number(m.plane_distance, 6) +
                 "$ from the centre) at the tip of $\\boldsymbol{\\rho}$; the polhode on the "
                 "ellipsoid and the herpolhode it rolls out on the plane over $t \\le " +
                 report_writer::number(m.times.back(), 4) + "$.");
}

/// ω(t) of the elliptic solution over one period.
void omega_figure(report_writer& w, const euler_result& e, const std::string& tag)
{
    const auto& s = *e.elliptic;
    constexpr int samples = 240;
    std::string script = "set key outside right\nset xlabel 't'\nset ylabel 'body components of ω'\nset grid\n$omega << EOD\n";
    for (int n = 0; n <= samples; ++n) {
        double t = s.period * n / samples;
        std::array<double, 3> v = s.evaluate(t);
        script += gnuplot_number(t) + " " + gnuplot_number(v[0]) + " " + gnuplot_number(v[1]) + " " +
                  gnuplot_number(v[2]) + "\n";
    }
    script += "EOD\nset xrange [0:" + gnuplot_number(s.period) + "]\nplot ";
    const char* colours[] = {"#1f4e9c", "#c00000", "#2a8a2a"};
    for (int k = 0; k < 3; ++k)
        script += std::string(k ? ", " : "") + "$omega using 1:" + std::to_string(k + 2) + " with lines lw 2 lc rgb '" +
                  colours[k] + "' title '" + plain_name(e.omega[static_cast<std::size_t>(k)]) + "'";
    script += "\n";
    w.figure(tag + "omega", script, 14, 6,
             "The body components of $\\boldsymbol{\\omega}(t)$ of body " + body_title(e.body) +
                 " over one period, from the Jacobi elliptic solution.");
}

void write_body_euler(report_writer& w, const euler_result& e)
{
    const term_order order{{e.rates, e.omega}};
    w.latex("\\subsection{Body " + body_title(e.body) + "}\n");
    w.text("The rate of change of ").latex("$\\mathbf{L}$").text(" in space is its rate in the body frame plus ")
        .latex("$\\boldsymbol{\\omega}\\times\\mathbf{L}$")
        .text(", so ")
        .latex("$\\mathbf{I}\\dot{\\boldsymbol{\\omega}} + \\boldsymbol{\\omega}\\times\\mathbf{I}\\boldsymbol{\\omega} = \\mathbf{N}$")
        .text(e.torque_free ? ", and with no torque, in the body axes," : ", in the body axes,");
    std::vector<report_writer::row> rows;
    for (const GiNaC::ex& equation : e.equations)
        rows.push_back({"", print_terms(equation, syntax::latex, order), " = 0"});
    w.display_rows(rows);
    if (!e.principal_equations.empty()) {
        w.text("In principal axes:");
        rows.clear();
        for (const GiNaC::ex& equation : e.principal_equations)
            rows.push_back({"", print_terms(equation, syntax::latex, order), " = 0"});
        w.display_rows(rows);
    }
    if (e.torque_free && e.moments.size() == 3) {
        std::string moments;
        std::string energy = "\\tfrac{1}{2}\\left(", momentum;
        for (std::size_t k = 0; k < 3; ++k) {
            const std::string I = "I_{" + std::to_string(k + 1) + "}", wk = report_writer::math(e.omega[k]);
            moments += (k ? ",\\quad " : "") + I + " = " + report_writer::math(e.moments[k]);
            energy += (k ? " + " : "") + I + wk + "^{2}";
            momentum += (k ? " + " : "") + I + "^{2}" + wk + "^{2}";
        }
        energy += "\\right)";
        w.text("With the principal moments ").latex("$" + moments + "$").text(
            ", multiplying each equation by its component of ");
        w.latex("$\\boldsymbol{\\omega}$").text(" (or of ").latex("$\\mathbf{L}$").text(") and adding shows that the "
                                                                                          "kinetic energy and the "
                                                                                          "magnitude of the angular "
                                                                                          "momentum are conserved:");
        auto equal = [](std::vector<std::string> terms) {
            if (!terms.empty())
                terms.front() = "= " + terms.front();
            return terms;
        };
        w.display_rows({{"T", {energy}},
                        {"", equal(print_terms(e.kinetic_energy, syntax::latex, order))},
                        {"|\\mathbf{L}|^{2}", {momentum}},
                        {"", equal(print_terms(e.angular_momentum_squared, syntax::latex, order))}});
    }
    if (e.symmetric) {
        const auto& s = *e.symmetric;
        w.text("The body is symmetric about its axis " + std::to_string(s.axis + 1) + ": ")
            .latex("$" + report_writer::math(e.omega[s.axis]) + "$")
            .text(" is constant and the other two components turn at the rate");
        w.display("\\Omega", s.precession);
        w.text("The torque-free solution, from ")
            .latex("$\\boldsymbol{\\omega}(0) = \\left(");
        for (std::size_t k = 0; k < s.constants.size(); ++k)
            w.latex((k ? ",\\ " : "") + report_writer::math(s.constants[k]));
        w.latex("\\right)$").text(", is");
        rows.clear();
        for (std::size_t k = 0; k < 3; ++k)
            rows.push_back({report_writer::math(e.omega[k]) + "(t)", print_terms(s.omega[k], syntax::latex)});
        w.display_rows(rows);
    }
    const std::string tag = "body-" + e.body + "-";
    if (e.elliptic) {
        const auto& s = *e.elliptic;
        const char* functions[] = {"cn", "sn", "dn"};
        w.text("The body is asymmetric. At the values of the scene and from its initial ")
            .latex("$\\boldsymbol{\\omega}(0)$")
            .text(", Euler's equations are solved by Jacobi's elliptic functions (Landau and Lifshitz, ")
            .latex("\\S")
            .text("37)");
        w.text(", with the modulus ").latex("$k = " + report_writer::number(s.modulus, 10) + "$").text(":");
        rows.clear();
        for (std::size_t k = 0; k < 3; ++k) {
            std::size_t role = 0;
            while (s.roles[role] != k)
                ++role;
            rows.push_back({report_writer::math(e.omega[k]) + "(t)",
                            {report_writer::number(s.amplitudes[role], 10) + "\\,\\mathrm{" + functions[role] + "}\\!\\left(" +
                             report_writer::number(s.rate, 10) + "\\,t " + (s.phase < 0 ? "- " : "+ ") +
                             report_writer::number(std::abs(s.phase), 10) + ",\\ k\\right)"}});
        }
        w.display_rows(rows);
        w.text("Its period is ").latex("$4K(k)/\\lambda = " + report_writer::number(s.period, 10) + "$")
            .text(" (").latex("$\\lambda$").text(" the rate of the argument above), and along it ")
            .latex("$T = " + report_writer::number(s.energy, 10) + "$")
            .text(" and ")
            .latex("$|\\mathbf{L}|^{2} = " + report_writer::number(s.momentum_squared, 10) + "$")
            .text(".\n");
        omega_figure(w, e, tag);
    }
    if (e.poinsot) {
        // One normalization, stated once: ρ = ω/√(2T) when the construction was drawn (its
        // figure and the player use it), else ω on ωᵀIω = 2T.
        const poinsot_motion* motion = nullptr;
        if (w.result().poinsot)
            for (const poinsot_motion& m : *w.result().poinsot)
                if (m.body == e.body && !m.polhode.empty())
                    motion = &m;
        const auto& p = *e.poinsot;
        if (motion) {
            const poinsot_motion& m = *motion;
            w.text("Poinsot's construction, in the normalization ")
                .latex("$\\boldsymbol{\\rho} = \\boldsymbol{\\omega}/\\sqrt{2T}$")
                .text(" (used from here on): ").latex("$\\boldsymbol{\\rho}$").text(" lies on the inertia ellipsoid ")
                .latex("$\\boldsymbol{\\rho}^{T}\\mathbf{I}\\boldsymbol{\\rho} = 1$")
                .text(", fixed in the body, with the semi-axes ")
                // Three pieces of mathematics, so that the line may break between them.
                .latex("$1/\\sqrt{I_{k}} = " + report_writer::number(m.semi_axes[0], 8) + "$")
                .text(", ")
                .latex("$" + report_writer::number(m.semi_axes[1], 8) + "$")
                .text(", ")
                .latex("$" + report_writer::number(m.semi_axes[2], 8) + "$")
                .text("; it rolls without slipping on the invariable plane normal to ").latex("$\\mathbf{L}$")
                .text(" at the distance ")
                .latex("$\\sqrt{2T}/|\\mathbf{L}| = " + report_writer::number(m.plane_distance, 8) + "$")
                .text(" from the centre: the point of contact lies on the instantaneous axis, so it is at rest. The curve ")
                .latex("$\\boldsymbol{\\rho}(t)$").text(" traces on the ellipsoid is the polhode.\n");
            polhode_figure(w, e, m.semi_axes, m.polhode, true, tag);
            w.text("Euler's equations and the orientation integrated together (" + m.method + ", " +
                   std::to_string(m.steps) + " steps) draw the construction in space.\n");
            poinsot_figure(w, m, tag);
        } else {
            w.text("Poinsot's construction: ").latex("$\\boldsymbol{\\omega}$").text(" lies on the inertia ellipsoid ")
                .latex("$\\boldsymbol{\\omega}^{T}\\mathbf{I}\\boldsymbol{\\omega} = 2T$")
                .text(" with the semi-axes ")
                .latex("$\\sqrt{2T/I_{k}} = " + report_writer::number(p.ellipsoid_axes[0], 8) + ",\\ " +
                       report_writer::number(p.ellipsoid_axes[1], 8) + ",\\ " +
                       report_writer::number(p.ellipsoid_axes[2], 8) + "$")
                .text(", which rolls without slipping on the invariable plane normal to ")
                .latex("$\\mathbf{L}$")
                .text(" at the distance ")
                .latex("$2T/|\\mathbf{L}| = " + report_writer::number(p.plane_distance, 8) + "$")
                .text(" from the centre. The curve ").latex("$\\boldsymbol{\\omega}(t)$")
                .text(" traces on the ellipsoid is the polhode.\n");
            polhode_figure(w, e, p.ellipsoid_axes, p.polhode, false, tag);
        }
    }
    if (e.stability.size() == 3) {
        w.text("Steady rotation about each principal axis, perturbed slightly:");
        w.latex("\n\\begin{center}\n\\begin{tabular}{cll}\n\\hline\naxis & moment & rotation\\\\\n\\hline\n");
        for (std::size_t k = 0; k < 3; ++k)
            w.latex(std::to_string(k + 1) + " & $" + (k < e.moments.size() ? report_writer::math(e.moments[k]) : "") +
                    "$ & " + latex_text(e.stability[k]) + "\\\\\n");
        w.latex("\\hline\n\\end{tabular}\n\\end{center}\n");
        w.text("Rotation about the axes of the largest and the smallest moment is stable, about the intermediate one "
               "unstable; equal moments make the rotation about those axes marginal.\n\n");
    }
}

} // namespace

void write_euler_text(std::ostream& out, const analysis& result)
{
    if (result.euler) {
        out << "\nEuler's equations\n";
        for (const euler_result& e : *result.euler) {
            const term_order order = euler_order(e);
            out << "  body " << e.body << (e.principal_equations.empty() ? "" : " (general form, body axes)") << ":\n";
            for (const GiNaC::ex& eq : e.equations)
                out << "    " << print(eq, syntax::text, order) << " = 0\n";
            if (!e.principal_equations.empty()) {
                out << "  in principal axes (moments " << join(printed(e.moments, syntax::text), ", ") << "):\n";
                for (const GiNaC::ex& eq : e.principal_equations)
                    out << "    " << print(eq, syntax::text, order) << " = 0\n";
            }
            if (e.torque_free && !e.moments.empty()) {
                out << "    conserved: T = " << print(e.kinetic_energy, syntax::text, order)
                    << ",  |L|² = " << print(e.angular_momentum_squared, syntax::text, order) << '\n';
            }
            if (e.symmetric) {
                const auto& s = *e.symmetric;
                out << "  symmetric body (axis " << s.axis + 1 << "): Ω = " << print(s.precession, syntax::text) << '\n';
                for (unsigned k = 0; k < 3; ++k)
                    out << "    " << omega_name(e.omega[k], syntax::text) << "(t) = " << print(s.omega[k], syntax::text)
                        << '\n';
            }
            if (e.elliptic) {
                const auto& s = *e.elliptic;
                const char* functions[] = {"cn", "sn", "dn"};
                out << "  Jacobi elliptic solution, modulus k = " << round_trip(s.modulus) << ", period "
                    << round_trip(s.period) << ":\n";
                for (unsigned k = 0; k < 3; ++k) {
                    unsigned role = 0;
                    while (s.roles[role] != k)
                        ++role;
                    out << "    " << omega_name(e.omega[k], syntax::text) << "(t) = " << round_trip(s.amplitudes[role]) << "·"
                        << functions[role] << "(" << round_trip(s.rate) << "·t " << (s.phase < 0 ? "- " : "+ ")
                        << round_trip(std::abs(s.phase)) << ", k)\n";
                }
                out << "    T = " << round_trip(s.energy) << ", |L|² = " << round_trip(s.momentum_squared) << '\n';
            }
            if (e.poinsot) {
                const auto& p = *e.poinsot;
                out << "  Poinsot: inertia ellipsoid ωᵀIω = 2T with semi-axes " << round_trip(p.ellipsoid_axes[0]) << ", "
                    << round_trip(p.ellipsoid_axes[1]) << ", " << round_trip(p.ellipsoid_axes[2])
                    << "; invariable plane at distance 2T/|L| = " << round_trip(p.plane_distance) << "; polhode: "
                    << p.polhode.size() << " points (JSON)\n";
            }
            if (!e.stability.empty()) {
                out << "  rotation about axis 1, 2, 3: " << join(e.stability, ", ") << '\n';
            }
        }
    }
}

void write_euler_latex(std::ostream& out, const analysis& result)
{
    if (result.euler) {
        out << "\\subsection*{Euler's equations}\n";
        for (const euler_result& e : *result.euler) {
            const term_order order = euler_order(e);
            out << "Body $" << print_name(e.body, syntax::latex) << "$:\n";
            auto rows = [&](const std::vector<GiNaC::ex>& equations) {
                std::vector<latex_row> r;
                for (const GiNaC::ex& equation : equations)
                    r.push_back({"", print_terms(equation, syntax::latex, order), " = 0"});
                return latex_equations(r);
            };
            out << rows(e.equations);
            if (!e.principal_equations.empty())
                out << "In principal axes:\n" << rows(e.principal_equations);
            if (e.torque_free && !e.moments.empty())
                out << latex_line("T = " + print(e.kinetic_energy, syntax::latex, order) +
                        ",\\quad |L|^{2} = " + print(e.angular_momentum_squared, syntax::latex, order));
            if (e.symmetric) {
                const auto& s = *e.symmetric;
                std::vector<std::string> rows;
                for (unsigned k = 0; k < 3; ++k)
                    rows.push_back(print(e.omega[k], syntax::latex) + "(t) &= " + print(s.omega[k], syntax::latex));
                out << "Symmetric body, $\\Omega = " << print(s.precession, syntax::latex) << "$:\n\\begin{align*}\n"
                    << join(rows, " \\\\\n") << "\n\\end{align*}\n";
            }
            if (e.elliptic) {
                const auto& s = *e.elliptic;
                const char* functions[] = {"cn", "sn", "dn"};
                std::vector<std::string> rows;
                for (unsigned k = 0; k < 3; ++k) {
                    unsigned role = 0;
                    while (s.roles[role] != k)
                        ++role;
                    rows.push_back(print(e.omega[k], syntax::latex) + "(t) &= " + latex_round_trip(s.amplitudes[role]) +
                                   "\\,\\mathrm{" + functions[role] + "}(" + latex_round_trip(s.rate) + "\\,t " +
                                   (s.phase < 0 ? "- " : "+ ") + latex_round_trip(std::abs(s.phase)) + ", k)");
                }
                out << "Jacobi elliptic solution, $k = " << latex_round_trip(s.modulus) << "$, period $" << latex_round_trip(s.period)
                    << "$:\n\\begin{align*}\n" << join(rows, " \\\\\n") << "\n\\end{align*}\n";
            }
            if (e.poinsot)
                out << "Poinsot: the ellipsoid $\\omega^{T} I \\omega = 2T$ has the semi-axes\n\\[" << latex_round_trip(e.poinsot->ellipsoid_axes[0])
                    << ",\\quad " << latex_round_trip(e.poinsot->ellipsoid_axes[1]) << ",\\quad "
                    << latex_round_trip(e.poinsot->ellipsoid_axes[2]) << "\\]\nand the invariable plane is at the distance\n\\[2T/|L| = "
                    << latex_round_trip(e.poinsot->plane_distance) << "\\]\nfrom the centre.\n\n";
            if (!e.stability.empty())
                out << "Rotation about axes 1, 2, 3: " << join(e.stability, ", ") << ".\n\n";
        }
    }
}

void write_euler_json(nlohmann::ordered_json& doc, const analysis& result)
{
    if (result.euler) {
        nlohmann::ordered_json all = nlohmann::ordered_json::object();
        for (const euler_result& e : *result.euler) {
            const term_order order = euler_order(e);
            nlohmann::ordered_json body;
            body["equations"] = json_strings(e.equations, order);
            if (!e.principal_equations.empty())
                body["principal_equations"] = json_strings(e.principal_equations, order);
            if (e.torque_free && !e.moments.empty())
                body["conserved"] = {{"kinetic_energy", print(e.kinetic_energy, syntax::plain, order)},
                                     {"angular_momentum_squared", print(e.angular_momentum_squared, syntax::plain, order)}};
            if (e.symmetric) {
                const auto& s = *e.symmetric;
                body["solution"] = {{"kind", "symmetric"},
                                    {"axis", s.axis + 1},
                                    {"precession", print(s.precession, syntax::plain)},
                                    {"omega", json_strings(s.omega)}};
            } else if (e.elliptic) {
                const auto& s = *e.elliptic;
                const char* functions[] = {"cn", "sn", "dn"};
                nlohmann::ordered_json omega = nlohmann::ordered_json::array();
                for (unsigned k = 0; k < 3; ++k) {
                    unsigned role = 0;
                    while (s.roles[role] != k)
                        ++role;
                    omega.push_back(round_trip(s.amplitudes[role]) + "*" + functions[role] + "(" + round_trip(s.rate) +
                                    "*t" + (s.phase < 0 ? "-" : "+") + round_trip(std::abs(s.phase)) + ", k)");
                }
                body["solution"] = {{"kind", "elliptic"},     {"omega", omega},
                                    {"modulus", s.modulus},   {"rate", s.rate},
                                    {"phase", s.phase},       {"period", s.period},
                                    {"energy", s.energy},     {"angular_momentum_squared", s.momentum_squared}};
            }
            if (e.poinsot) {
                nlohmann::ordered_json polhode = nlohmann::ordered_json::array();
                for (const auto& p : e.poinsot->polhode)
                    polhode.push_back({p[0], p[1], p[2]});
                body["poinsot"] = {{"ellipsoid_axes", e.poinsot->ellipsoid_axes},
                                   {"plane_distance", e.poinsot->plane_distance},
                                   {"polhode", polhode}};
            }
            if (!e.stability.empty())
                body["stability"] = e.stability;
            all[e.body] = body;
        }
        doc["euler"] = all;
    }
}

void write_euler_section(report_writer& w)
{
    w.latex("\\section{Euler's equations}\n");
    for (const euler_result& e : *w.result().euler)
        write_body_euler(w, e);
}

} // namespace lagrange
