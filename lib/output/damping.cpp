// SPDX-License-Identifier: GPL-2.0-or-later
/** @file damping.cpp
*  Printers of the damped small oscillations.
 *
*  The report's sections on non-conservative small oscillations: the damping matrix,
 *  det(K + sC + s²M) with its roots and regimes, proportional damping, the damped
 *  eigenvalues at the `values` points; and the linearized input–output system (the
 *  state-space matrices and the transfer functions). */
#include "output/damping.h"

#include "algebra/sign.h"
#include "output/format.h"
#include "output/latex_blocks.h"
#include "output/linear_system.h"
#include "output/print.h"
#include "output/report_sections.h"

#include <charconv>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

namespace lagrange {

namespace {

term_order s_order(const damping_result& damping) { return term_order{{{damping.s}}}; }

/// The roots of one factor: "−γ ± i√(ω₀² − γ²)" and its regime, in `syntax`.
std::string roots_text(const damped_factor& f, syntax s, const damping_result& damping)
{
    const bool latex = s == syntax::latex;
    const std::string variable = print_name(damping.s.get_name(), s);
    if (f.roots.size() == 1)
        return variable + " = " + print(f.roots[0], s);
    const std::string minus_gamma = print(-f.decay, s);
    const std::string pm = latex ? " \\pm " : " ± ";
    auto root = [&](const GiNaC::ex& radicand) {
        return latex ? "\\sqrt{" + print(radicand, s) + "}" : "√(" + print(radicand, s) + ")";
    };
    if (f.regime == "critical")
        return variable + " = " + minus_gamma + (latex ? "\\ \\text{(double root)}" : " (double root)");
    if (f.regime == "underdamped" || f.regime.empty())
        return variable + " = " + minus_gamma + pm + (latex ? "i\\," : "i·") + root(f.discriminant);
    return variable + " = " + minus_gamma + pm + root(-f.discriminant);
}

std::string regime_text(const damped_factor& f, syntax s)
{
    if (f.roots.size() != 2)
        return "";
    if (!f.regime.empty())
        return f.regime;
    const bool latex = s == syntax::latex;
    const std::string d = print(f.discriminant, s);
    return latex ? "\\text{underdamped if } " + d + " > 0 \\text{, critical if } = 0 \\text{, overdamped if } < 0"
                 : "underdamped if " + d + " > 0, critical if = 0, overdamped if < 0";
}

/// "C" or, with a gyroscopic matrix, "(C − G)": the velocity term of det(K + s·… + s²M).
std::string velocity_matrix(const damping_result& damping, syntax s)
{
    return damping.gyroscopic ? (s == syntax::latex ? "(C - G)" : "(C − G)") : "C";
}

} // namespace

void write_damping_text(std::ostream& out, const model& scene, const damping_result& damping)
{
    (void)scene;
    const syntax s = syntax::text;
    out << "\nDamping\n  C =";
    for (unsigned i = 0; i < damping.damping.rows(); ++i) {
        out << (i ? "      " : " ") << "[";
        for (unsigned j = 0; j < damping.damping.cols(); ++j)
            out << (j ? ", " : "") << print(damping.damping(i, j), s);
        out << "]\n";
    }
    out << "  det(K + " << print_name(damping.s.get_name(), s) << velocity_matrix(damping, s) << " + "
        << print_name(damping.s.get_name(), s)
        << "²M) = " << print(damping.polynomial, s, s_order(damping)) << " = 0\n";
    if (!damping.closed_form)
        out << "  roots: no closed form (a factor of degree above 2)\n";
    for (const damped_factor& f : damping.factors) {
        out << "  " << roots_text(f, s, damping);
        std::string regime = regime_text(f, s);
        if (!regime.empty())
            out << "  (" << regime << ")";
        out << '\n';
    }
    if (damping.proportional) {
        out << "  proportional damping: C M⁻¹K = K M⁻¹C, the undamped mode shapes stay";
        if (!damping.modal_damping_ratios.empty()) {
            out << "; modal damping ratios ζ =";
            for (std::size_t k = 0; k < damping.modal_damping_ratios.size(); ++k)
                out << (k ? ", " : " ") << print(damping.modal_damping_ratios[k], s);
        }
        out << '\n';
    } else if (damping.gyroscopic) {
        out << "  with the gyroscopic matrix G the damped modes are complex\n";
    } else {
        out << "  damping not proportional: the damped modes are complex\n";
    }
}

void write_damping_latex(std::ostream& out, const model& scene, const damping_result& damping)
{
    (void)scene;
    const syntax s = syntax::latex;
    const std::string variable = print_name(damping.s.get_name(), s);
    out << "\\subsection*{Damping}\n\\begin{align*}\nC &= " << latex_matrix(damping.damping) << "\n\\end{align*}\n";
    out << "Characteristic polynomial $\\det(K + " << variable << velocity_matrix(damping, s) << " + " << variable
        << "^{2}M)$:\n"
        << latex_equation("", print_terms(damping.polynomial, s, s_order(damping)), " = 0");
    if (!damping.closed_form)
        out << "No closed form of the roots (a factor of degree above 2).\n";
    for (const damped_factor& f : damping.factors) {
        std::string regime = regime_text(f, s);
        out << "\\[" << roots_text(f, s, damping);
        if (!regime.empty())
            out << (f.regime.empty() ? "\\quad " : "\\quad\\text{(") + regime + (f.regime.empty() ? "" : ")}");
        out << "\\]\n";
    }
    if (damping.proportional) {
        out << "Proportional damping: $C M^{-1} K = K M^{-1} C$, the undamped mode shapes stay";
        if (!damping.modal_damping_ratios.empty()) {
            out << "; modal damping ratios $";
            for (std::size_t k = 0; k < damping.modal_damping_ratios.size(); ++k)
                out << (k ? ",\\ " : "") << "\\zeta_{" << k + 1 << "} = " << print(damping.modal_damping_ratios[k], s);
            out << "$";
        }
        out << ".\n\n";
    } else if (damping.gyroscopic) {
        out << "With the gyroscopic matrix $G$ the damped modes are complex.\n\n";
    } else {
        out << "The damping is not proportional: the damped modes are complex.\n\n";
    }
}

void write_damping_json(nlohmann::ordered_json& doc, const model& scene, const damping_result& damping)
{
    (void)scene;
    const syntax s = syntax::plain;
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (unsigned i = 0; i < damping.damping.rows(); ++i) {
        nlohmann::ordered_json row = nlohmann::ordered_json::array();
        for (unsigned j = 0; j < damping.damping.cols(); ++j)
            row.push_back(print(damping.damping(i, j), s));
        rows.push_back(row);
    }
    doc["damping"] = rows;
    nlohmann::ordered_json characteristic;
    characteristic["variable"] = damping.s.get_name();
    characteristic["polynomial"] = print(damping.polynomial, s, s_order(damping));
    characteristic["gyroscopic"] = damping.gyroscopic; // det(K + s(C − G) + s²M) when true
    if (damping.closed_form) {
        nlohmann::ordered_json factors = nlohmann::ordered_json::array();
        for (const damped_factor& f : damping.factors) {
            nlohmann::ordered_json entry;
            entry["factor"] = print(f.factor, s, s_order(damping));
            nlohmann::ordered_json roots = nlohmann::ordered_json::array();
            if (f.roots.size() == 2) {
                entry["decay"] = print(f.decay, s);
                entry["natural_squared"] = print(f.natural_squared, s);
                entry["discriminant"] = print(f.discriminant, s);
                entry["regime"] = f.regime.empty() ? "depends on the parameters" : f.regime;
                const std::string minus_gamma = print(-f.decay, s);
                if (f.regime == "critical") {
                    roots = {minus_gamma, minus_gamma};
                } else if (f.regime == "underdamped" || f.regime.empty()) {
                    const std::string imaginary = "I*sqrt(" + print(f.discriminant, s) + ")";
                    roots = {minus_gamma + "-" + imaginary, minus_gamma + "+" + imaginary};
                } else {
                    const std::string real = "sqrt(" + print(-f.discriminant, s) + ")";
                    roots = {minus_gamma + "-" + real, minus_gamma + "+" + real};
                }
            } else {
                roots.push_back(print(f.roots[0], s));
            }
            entry["roots"] = roots;
            factors.push_back(entry);
        }
        characteristic["factors"] = factors;
    }
    doc["damped_characteristic"] = characteristic;
    nlohmann::ordered_json proportional;
    proportional["proportional"] = damping.proportional;
    if (!damping.modal_damping_ratios.empty()) {
        nlohmann::ordered_json ratios = nlohmann::ordered_json::array();
        for (const GiNaC::ex& z : damping.modal_damping_ratios)
            ratios.push_back(print(z, s));
        proportional["modal_damping_ratios"] = ratios;
    }
    doc["proportional_damping"] = proportional;
}

namespace {

/// The eigenvalues to print: every real one and the upper member of each conjugate pair
/// (the lower one is its exact conjugate), in quadratic_modes order.
std::vector<std::size_t> printed_eigenvalues(const numeric_modes& n)
{
    std::vector<std::size_t> chosen;
    for (std::size_t k = 0; k < n.eigenvalues.size(); ++k)
        if (n.eigenvalues[k].imag() >= 0)
            chosen.push_back(k);
    return chosen;
}

std::string ratio_text(double ratio) { return std::isnan(ratio) ? "none (s = 0)" : round_trip(ratio); }

/// One mode component as a + bi (b omitted when 0), in `s`.
std::string component_text(std::complex<double> z, syntax s)
{
    const bool latex = s == syntax::latex;
    return complex_number(
        z, [&](double v) { return latex ? print(GiNaC::numeric(v), s) : round_trip(v); }, latex ? "\\,i" : "i");
}

/// Column k of the damped modes as (x₁, x₂, …), in text.
std::string damped_mode_text(const numeric_modes& n, std::size_t k)
{
    std::string text = "(";
    for (Eigen::Index i = 0; i < n.damped_modes.rows(); ++i)
        text += (i ? ", " : "") + component_text(n.damped_modes(i, static_cast<Eigen::Index>(k)), syntax::text);
    return text + ")";
}

bool has_damped_modes(const numeric_modes& n)
{
    return n.damped_modes.cols() == static_cast<Eigen::Index>(n.eigenvalues.size()) && n.damped_modes.cols() > 0;
}

} // namespace

void write_damped_eigenvalues_text(std::ostream& out, const numeric_modes& n)
{
    out << "    damped eigenvalues s (q ∝ e^{st}, first-order system): " << n.stability << '\n';
    for (std::size_t k : printed_eigenvalues(n)) {
        const std::complex<double> z = n.eigenvalues[k];
        out << "    s = " << conjugate_pair(z, round_trip, " ± ", "i") << "  (error ≤ " << round_trip(n.eigenvalue_error[k]) << ")  ζ = " << ratio_text(n.damping_ratio[k])
            << '\n';
        if (has_damped_modes(n))
            out << "      mode " << damped_mode_text(n, k) << '\n';
    }
    if (!has_damped_modes(n))
        return;
    out << "    modes x: (s²M + " << (n.complex_modes.size() ? "s(C − G)" : "sC")
        << " + K)x = 0, largest component 1; s̄ has the conjugate mode\n";
    if (n.proportional_damping)
        out << "    proportional damping: the damped modes are the undamped (real) mode shapes\n";
}

void write_damped_eigenvalues_latex(std::ostream& out, const numeric_modes& n)
{
    const syntax s = syntax::latex;
    out << "Damped eigenvalues $s$ ($q \\propto e^{st}$), " << n.stability << ":\n\\begin{align*}\n";
    const std::vector<std::size_t> chosen = printed_eigenvalues(n);
    for (std::size_t j = 0; j < chosen.size(); ++j) {
        const std::complex<double> z = n.eigenvalues[chosen[j]];
        out << "s &= " << conjugate_pair(z, [s](double v) { return print(GiNaC::numeric(v), s); }, " \\pm ", "\\,i");
        // The error and ζ on a line of their own: 17-digit parts leave no room beside s.
        out << "\\\\\n&\\qquad \\text{(error } \\le " << print(GiNaC::numeric(n.eigenvalue_error[chosen[j]]), s)
            << "\\text{)},\\quad \\zeta = ";
        const double ratio = n.damping_ratio[chosen[j]];
        out << (std::isnan(ratio) ? std::string("\\text{none}") : print(GiNaC::numeric(ratio == 0 ? 0.0 : ratio), s));
        out << (j + 1 < chosen.size() ? "\\\\\n" : "\n");
    }
    out << "\\end{align*}\n";
    if (!has_damped_modes(n))
        return;
    // The modes as columns, one per line, so that the width does not grow with n.
    out << "Their modes $x$, in the same order, with $(s^{2}M + " << (n.complex_modes.size() ? "s(C - G)" : "sC")
        << " + K)x = 0$ and the largest component 1 ($\\bar s$ has the conjugate mode)";
    if (n.proportional_damping)
        out << "; the damping is proportional, so they are the undamped (real) mode shapes";
    out << ":\n\\begin{align*}\n";
    for (std::size_t j = 0; j < chosen.size(); ++j) {
        out << "x &= \\begin{pmatrix}";
        for (Eigen::Index i = 0; i < n.damped_modes.rows(); ++i)
            out << (i ? " \\\\ " : "")
                << component_text(n.damped_modes(i, static_cast<Eigen::Index>(chosen[j])), s);
        out << "\\end{pmatrix}" << (j + 1 < chosen.size() ? "\\\\\n" : "\n");
    }
    out << "\\end{align*}\n";
}

void write_damped_eigenvalues_json(nlohmann::ordered_json& entry, const numeric_modes& n)
{
    entry["eigenvalue_error"] = n.eigenvalue_error;
    nlohmann::ordered_json ratios = nlohmann::ordered_json::array();
    for (double r : n.damping_ratio)
        ratios.push_back(std::isnan(r) ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(r));
    entry["damping_ratio"] = ratios;
    if (!has_damped_modes(n))
        return;
    nlohmann::ordered_json modes = nlohmann::ordered_json::array();
    for (Eigen::Index k = 0; k < n.damped_modes.cols(); ++k) {
        nlohmann::ordered_json column = nlohmann::ordered_json::array();
        for (Eigen::Index i = 0; i < n.damped_modes.rows(); ++i) {
            const std::complex<double> z = n.damped_modes(i, k);
            column.push_back({z.real() == 0 ? 0.0 : z.real(), z.imag() == 0 ? 0.0 : z.imag()});
        }
        modes.push_back(column);
    }
    entry["damped_modes"] = modes;
    entry["damped_mode_backward_error"] = n.damped_mode_backward_error;
    entry["proportional_damping"] = n.proportional_damping;
}

bool modes_are_undamped(const analysis& result)
{
    if (result.damping)
        return !is_zero_matrix(result.damping->damping);
    if (result.numeric)
        for (const numeric_modes& n : *result.numeric)
            if (n.damped)
                return true;
    const model& scene = *result.scene;
    return !scene.dampers.empty() || !scene.dissipation.is_zero();
}

// ---- the report's section ----

namespace {

std::string complex_latex(std::complex<double> z, int digits = 10)
{
    return complex_number(z, [digits](double v) { return report_writer::number(v, digits); }, "\\,i");
}

} // namespace

void write_damping_section(report_writer& w)
{
    const analysis& result = w.result();
    w.latex("\\section{Damping}\n");
    if (result.damping) {
        const damping_result& d = *result.damping;
        const std::string s = report_writer::name(d.s.get_name());
        w.text("The generalized forces Q that depend on the velocities (the Rayleigh function's ")
            .latex("$-\\partial F/\\partial\\dot q$")
            .text(", dampers, velocity-dependent forces) give, linearized at the equilibrium, the damping matrix ")
            .latex("$C_{ij} = -\\partial Q_i/\\partial\\dot q_j$")
            .text(", so that the small oscillations obey ")
            .latex("$M\\ddot q + C\\dot q + K q = 0$")
            .text(" with M = T and K = V of the linearization:");
        w.latex("\n");
        w.display_matrix("C", d.damping);
        w.text("With ").latex("$q \\propto e^{" + s + "t}$").text(" the characteristic polynomial is ");
        w.latex("$\\det(K + " + s + velocity_matrix(d, syntax::latex) + " + " + s + "^{2}M)$:\n");
        w.display_terms("", print_terms(d.polynomial, syntax::latex, term_order{{{d.s}}}), " = 0");
        if (!d.closed_form) {
            w.text("It has a factor of degree above 2, so its roots are given numerically below.");
            w.latex("\n");
        }
        for (const damped_factor& f : d.factors) {
            if (f.roots.size() == 1) {
                w.display(s, f.roots[0]);
                continue;
            }
            w.text("The factor ").latex("$" + report_writer::math(f.factor) + "$").text(" has the decay rate ");
            w.latex("$\\gamma = " + report_writer::math(f.decay) + "$").text(" and ");
            w.latex("$\\omega_0^{2} = " + report_writer::math(f.natural_squared) + "$").text("; its roots are ");
            w.latex("$" + s + " = -\\gamma \\pm \\sqrt{\\gamma^{2} - \\omega_0^{2}}$, with ");
            w.latex("$\\omega_0^{2} - \\gamma^{2} = " + report_writer::math(f.discriminant) + "$");
            if (f.regime == "underdamped")
                w.text(" > 0: underdamped, an oscillation that decays.");
            else if (f.regime == "critical")
                w.text(" = 0: critically damped, a double root.");
            else if (f.regime == "overdamped")
                w.text(" < 0: overdamped, two real decay rates.");
            else
                w.text(": underdamped where it is positive, critical where it vanishes, overdamped where it is "
                       "negative.");
            w.latex("\n");
        }
        if (d.proportional) {
            w.text("The damping is proportional: ")
                .latex("$C M^{-1} K = K M^{-1} C$")
                .text(", so the mode shapes of the undamped system diagonalize C as well");
            if (!d.modal_damping_ratios.empty()) {
                w.text(", with the modal damping ratios ");
                std::string ratios;
                for (std::size_t k = 0; k < d.modal_damping_ratios.size(); ++k)
                    ratios += (k ? ",\\ " : "") + std::string("\\zeta_{") + std::to_string(k + 1) +
                              "} = " + report_writer::math(d.modal_damping_ratios[k]);
                w.latex("$" + ratios + "$");
            }
            w.text(".");
        } else if (d.gyroscopic) {
            w.text("With the gyroscopic matrix G the damped modes are complex.");
        } else {
            w.text("The damping is not proportional (")
                .latex("$C M^{-1} K \\ne K M^{-1} C$")
                .text("): the damped modes are complex and do not share the undamped mode shapes.");
        }
        w.latex("\n");
    }
    if (!result.numeric)
        return;
    bool any = false;
    for (const numeric_modes& nm : *result.numeric)
        any = any || nm.damped;
    if (!any)
        return;
    w.text("At each parameter point the engine solves the quadratic eigenproblem ")
        .latex("$(s^{2}M + sC + K)x = 0$")
        .text(" through the real eigenproblem of the first-order system (Eigen), with an estimated error of each "
              "eigenvalue; the damping ratio of an eigenvalue is ")
        .latex("$\\zeta = -\\operatorname{Re} s/|s|$")
        .text(".");
    w.latex("\n");
    for (const numeric_modes& nm : *result.numeric) {
        if (!nm.damped)
            continue;
        w.latex("\\subsection*{Damped eigenvalues at $" + values_latex(nm) + "$: " + nm.stability + "}\n");
        const bool modes = nm.damped_modes.cols() == static_cast<Eigen::Index>(nm.eigenvalues.size());
        w.latex(std::string("\\begin{center}\n\\renewcommand{\\arraystretch}{1.3}\n\\begin{tabular}{") +
                (modes ? "rllll" : "rlll") + "}\n\\hline\n$k$ & $s_{k}$ & error & $\\zeta_{k}$" +
                (modes ? " & mode $x_{k}$" : "") + "\\\\\n\\hline\n");
        for (std::size_t k = 0; k < nm.eigenvalues.size(); ++k) {
            const double ratio = nm.damping_ratio[k];
            std::string mode;
            if (modes) {
                for (Eigen::Index i = 0; i < nm.damped_modes.rows(); ++i)
                    mode += (i ? ",\\ " : "") + complex_latex(nm.damped_modes(i, static_cast<Eigen::Index>(k)), 6);
                mode = " & $(" + mode + ")$";
            }
            w.latex(std::to_string(k + 1) + " & $" + complex_latex(nm.eigenvalues[k]) + "$ & $\\le " +
                    report_writer::number(nm.eigenvalue_error[k], 2) + "$ & " +
                    (std::isnan(ratio) ? std::string("---") : "$" + report_writer::number(ratio, 10) + "$") + mode +
                    "\\\\\n");
        }
        w.latex("\\hline\n\\end{tabular}\n\\end{center}\n");
        if (modes) {
            w.text("Each mode ")
                .latex("$x_{k}$")
                .text(" solves ")
                .latex(nm.complex_modes.size() ? "$(s_{k}^{2}M + s_{k}(C - G) + K)x_{k} = 0$"
                                                : "$(s_{k}^{2}M + s_{k}C + K)x_{k} = 0$")
                .text(" and is scaled so that its largest component is 1 (shown to 6 digits).");
            if (nm.proportional_damping)
                w.text(" The damping is proportional here: the modes are the real undamped mode shapes.");
            else
                w.text(" The damping is not proportional here: a mode is in general complex, its coordinates "
                       "oscillating with different phases.");
            w.latex("\n");
        }
    }
}

} // namespace lagrange
