// SPDX-License-Identifier: GPL-2.0-or-later
/** @file damping_report.cpp
 *  The report's sections on non-conservative small oscillations: the damping matrix,
 *  det(K + sC + s²M) with its roots and regimes, proportional damping, the damped
 *  eigenvalues at the `values` points; and the linearized input–output system (the
 *  state-space matrices and the transfer functions). */
#include "output/report_sections.h"
#include "output/format.h"

#include "output/linear_system_output.h"
#include "output/print.h"

#include <cmath>
#include <complex>
#include <string>

namespace lagrange {

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
        w.latex("$\\det(K + " + s + "C + " + s + "^{2}M)$:\n");
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

void write_linear_system_section(report_writer& w)
{
    const analysis& result = w.result();
    const model& scene = w.scene();
    w.latex("\\section{Inputs: state space and transfer functions}\n");
    if (result.state_space && result.wanted.count(product::state_space)) {
        const state_space_result& ss = *result.state_space;
        std::string state, inputs;
        for (const GiNaC::ex& x : ss.state)
            state += (state.empty() ? "" : ",\\ ") + report_writer::math(x);
        for (const input_signal& u : scene.inputs)
            inputs += (inputs.empty() ? "" : ",\\ ") + report_writer::name(u.name);
        w.text("Linearized at the equilibrium, with the state ")
            .latex("$x = (" + state + ")$")
            .text(" and the inputs ")
            .latex("$u = (" + inputs + ")$")
            .text(", the equations of motion ")
            .latex("$M\\ddot q + (C - G)\\dot q + K q = B_q u$")
            .text(" become ")
            .latex("$\\dot x = A x + B u$")
            .text(" with ")
            .latex("$A = \\begin{pmatrix} 0 & I \\\\ -M^{-1}K & M^{-1}(G - C)\\end{pmatrix}$")
            .text(" and ")
            .latex("$B = \\begin{pmatrix} 0 \\\\ M^{-1}B_q\\end{pmatrix}$")
            .text(", where ")
            .latex("$B_q = \\partial Q/\\partial u$")
            .text(":");
        w.latex("\n");
        w.display_matrix("A", ss.a);
        w.display_matrix("B", ss.b);
    }
    if (result.transfer && result.wanted.count(product::transfer)) {
        const transfer_result& tr = *result.transfer;
        const std::string s = report_writer::name(tr.s.get_name());
        w.text("The Laplace transform of the linearized equations from rest gives ")
            .latex("$(" + s + "^{2}M + " + s + "(C - G) + K)\\,X(" + s + ") = B_q U(" + s + ")$")
            .text("; solved by Cramer's rule, each input drives each coordinate through the transfer function ")
            .latex("$H(" + s + ") = X(" + s + ")/U(" + s + ")$")
            .text(". Its poles are the roots of the damped characteristic polynomial that the input reaches; a pole "
                  "with a positive real part is an instability.");
        w.latex("\n");
        write_transfer_rows(w, scene, tr, s);
    }
}

void write_transfer_rows(report_writer& w, const model& scene, const transfer_result& transfer, const std::string& s)
{
    std::vector<report_writer::row> rows;
    for (const transfer_function& h : transfer.entries)
        rows.push_back({"H_{" + report_writer::name(scene.inputs[h.input].name) + " \\to " +
                            report_writer::name(scene.coordinates[h.coordinate].name) + "}(" + s + ")",
                        {transfer_text(h, transfer.s, syntax::latex)},
                        ""});
    w.display_rows(rows);
}

} // namespace lagrange
