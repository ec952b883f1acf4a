// SPDX-License-Identifier: GPL-2.0-or-later
/** @file tops.cpp
 *  The heavy top's family (shown with `equations` and `inertia`): Routh's effective potential
 *  with the cyclic momenta at their sleeping values, the sleeping-top condition, the steady
 *  precessions and the nutation about them, in text, LaTeX, JSON and the report. */
#include "output/body_family.h"

#include "core/number_text.h"
#include "output/latex_blocks.h"
#include "output/print.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace lagrange {

void write_tops_text(std::ostream& out, const analysis& result)
{
    if (!result.tops)
        return;
    for (const top_result& top : *result.tops) {
        const term_order order{{{top.spin}}};
        out << "\nTop " << top.body << " (Routh, p_φ = p_ψ = I3·" << print(top.spin, syntax::text) << ")\n";
        out << "  I1 about the pivot = " << print(top.pivot_moment, syntax::text)
            << ", I3 = " << print(top.spin_moment, syntax::text) << '\n';
        out << "  V_eff = " << print(top.effective_potential, syntax::text, order) << '\n';
        out << "  V_eff ≈ const + (" << print(top.curvature, syntax::text, order) << ")·"
            << print(top.nutation, syntax::text) << "²\n";
        out << "  the sleeping top is stable when " << print(top.condition, syntax::text, order) << " > 0\n";
        if (!top.precession_quadratic.empty()) {
            const term_order by_rate{{{top.precession}, {top.spin}}};
            const GiNaC::ex& w = top.precession;
            const std::vector<GiNaC::ex>& a = top.precession_quadratic;
            out << "  steady precession at " << print(top.nutation, syntax::text) << ": "
                << print(a[2] * w * w + a[1] * w + a[0], syntax::text, by_rate) << " = 0\n"
                << "    slow Ω = " << print(top.slow_precession, syntax::text, order) << '\n'
                << "    fast Ω = " << print(top.fast_precession, syntax::text, order) << '\n';
            if (!top.nutation_frequency_squared.is_zero())
                out << "  nutation about it: ω² = " << print(top.nutation_frequency_squared, syntax::text, by_rate)
                    << '\n';
        }
    }
}

void write_tops_latex(std::ostream& out, const analysis& result)
{
    if (!result.tops)
        return;
    for (const top_result& top : *result.tops) {
        const term_order order{{{top.spin}}};
        out << "\\subsection*{Top $" << print_name(top.body, syntax::latex) << "$}\n"
            << "With the cyclic momenta at their sleeping values $p_\\phi = p_\\psi = I_3 "
            << print(top.spin, syntax::latex) << "$, $I_1 = " << print(top.pivot_moment, syntax::latex)
            << "$ about the pivot and $I_3 = " << print(top.spin_moment, syntax::latex) << "$:\n"
            << latex_equation("V_{\\mathrm{eff}}", print_terms(top.effective_potential, syntax::latex, order), "")
            << "about $" << print(top.nutation, syntax::latex) << " = 0$ its curvature gives the sleeping-top condition\n"
            << latex_equation("", print_terms(top.condition, syntax::latex, order), " > 0.");
        if (!top.precession_quadratic.empty()) {
            const term_order by_rate{{{top.precession}, {top.spin}}};
            const GiNaC::ex& w = top.precession;
            const std::vector<GiNaC::ex>& a = top.precession_quadratic;
            out << "Steady precession at $" << print(top.nutation, syntax::latex) << "$:\n"
                << latex_equation("", print_terms(a[2] * w * w + a[1] * w + a[0], syntax::latex, by_rate), " = 0,")
                << latex_equations({{"\\Omega_{\\mathrm{slow}}", print_terms(top.slow_precession, syntax::latex, order), ","},
                                    {"\\Omega_{\\mathrm{fast}}", print_terms(top.fast_precession, syntax::latex, order)}});
            if (!top.nutation_frequency_squared.is_zero())
                out << "Nutation about it:\n"
                    << latex_equation("\\omega^2", print_terms(top.nutation_frequency_squared, syntax::latex, by_rate), "");
        }
    }
}

void write_tops_json(nlohmann::ordered_json& doc, const analysis& result)
{
    if (result.tops && !result.tops->empty()) {
        nlohmann::ordered_json all = nlohmann::ordered_json::object();
        for (const top_result& top : *result.tops) {
            const term_order order{{{top.spin}}};
            all[top.body] = {{"pivot_moment", print(top.pivot_moment, syntax::plain)},
                             {"spin_moment", print(top.spin_moment, syntax::plain)},
                             {"effective_potential", print(top.effective_potential, syntax::plain, order)},
                             {"curvature", print(top.curvature, syntax::plain, order)},
                             {"sleeping_condition", print(top.condition, syntax::plain, order) + " > 0"}};
            if (!top.precession_quadratic.empty()) {
                const term_order by_rate{{{top.precession}, {top.spin}}};
                const GiNaC::ex& w = top.precession;
                const std::vector<GiNaC::ex>& a = top.precession_quadratic;
                all[top.body]["precession_condition"] =
                    print(a[2] * w * w + a[1] * w + a[0], syntax::plain, by_rate) + " = 0";
                all[top.body]["slow_precession"] = print(top.slow_precession, syntax::plain, order);
                all[top.body]["fast_precession"] = print(top.fast_precession, syntax::plain, order);
                if (!top.nutation_frequency_squared.is_zero())
                    all[top.body]["nutation_frequency_squared"] =
                        print(top.nutation_frequency_squared, syntax::plain, by_rate);
            }
        }
        doc["top"] = all;
    }
}

void write_tops_section(report_writer& w)
{
    w.latex("\\section{The heavy top}\n");
    for (const top_result& top : *w.result().tops) {
        const term_order order{{{top.spin}}};
        const std::string theta = report_writer::math(top.nutation);
        if (w.result().tops->size() > 1)
            w.latex("\\subsection{Body " + body_title(top.body) + "}\n");
        w.text("The body ").latex(body_title(top.body)).text(" has the moment ")
            .latex("$I_{1} = " + report_writer::math(top.pivot_moment) + "$")
            .text(" about the pivot (perpendicular to its axis) and ")
            .latex("$I_{3} = " + report_writer::math(top.spin_moment) + "$")
            .text(" about its axis. Two Euler angles are cyclic, so their momenta are conserved; the top sleeps "
                  "(spins upright, ")
            .latex("$" + theta + " = 0$")
            .text(") with both equal to ")
            .latex("$I_{3}" + report_writer::math(top.spin) + "$")
            .text(", where ")
            .latex("$" + report_writer::math(top.spin) + "$")
            .text(" is the conserved spin. Routh's procedure with these momenta leaves the motion in ")
            .latex("$" + theta + "$")
            .text(" alone, in the effective potential");
        w.display("V_{\\mathrm{eff}}(" + theta + ")", top.effective_potential);
        w.text("Near the upright position,");
        w.display_terms("V_{\\mathrm{eff}}", {"\\text{const} + \\left(" +
                                                  join(print_terms(top.curvature, syntax::latex, order), " ") +
                                                  "\\right)" + theta + "^{2} + O(" + theta + "^{4})"});
        w.text("so the sleeping top is stable when the curvature is positive, that is when");
        w.display_rows({{"", print_terms(top.condition, syntax::latex, order), " > 0."}});
        if (!top.precession_quadratic.empty()) {
            const term_order by_rate{{{top.precession}, {top.spin}}};
            const GiNaC::ex& rate = top.precession;
            const std::vector<GiNaC::ex>& a = top.precession_quadratic;
            w.text("The top precesses steadily at the angle ")
                .latex("$" + theta + "$")
                .text(" (with ")
                .latex("$\\dot{" + theta + "} = 0$")
                .text(") at a rate ")
                .latex("$\\Omega = \\dot{\\phi}$")
                .text(" that makes the nutation equation vanish, a quadratic in the rate:");
            w.display_rows({{"", print_terms(a[2] * rate * rate + a[1] * rate + a[0], syntax::latex, by_rate), " = 0."}});
            w.text("Its two roots are the slow and the fast precession (for a positive spin):");
            w.display("\\Omega_{\\mathrm{slow}}", top.slow_precession);
            w.display("\\Omega_{\\mathrm{fast}}", top.fast_precession);
            if (!top.nutation_frequency_squared.is_zero()) {
                w.text("About a steady precession, with both cyclic momenta at their values there, the "
                       "curvature of the effective potential over the moment about the pivot gives the "
                       "frequency of small nutation:");
                w.display("\\omega_{\\mathrm{nut}}^{2}", top.nutation_frequency_squared);
            }
        }
    }
}

} // namespace lagrange
