// SPDX-License-Identifier: GPL-2.0-or-later
/** @file virial.cpp
 *  The time averages of T and V as text, LaTeX and JSON (see virial.h). */
#include "output/virial.h"
#include "output/report_sections.h"

#include "core/number_text.h"

namespace lagrange {

namespace {

std::string number(double x) { return significant(x, 10); }

} // namespace

void write_virial_text(std::ostream& out, const analysis& result)
{
    if (!result.virial)
        return;
    const virial_result& v = *result.virial;
    out << "\nTime averages (virial)\n";
    out << "  over t = " << round_trip(v.from) << " … " << round_trip(v.to) << '\n';
    out << "  ⟨T⟩ = " << text_exponent(number(v.kinetic)) << '\n';
    out << "  ⟨V⟩ = " << text_exponent(number(v.potential)) << '\n';
    out << "  2⟨T⟩/⟨V⟩ = " << text_exponent(number(2 * v.kinetic / v.potential))
        << " (the virial theorem: n for V homogeneous of degree n)\n";
    if (v.quadrature_error)
        out << "  quadrature error: " << text_exponent(significant(*v.quadrature_error, 3)) << '\n';
}

void write_virial_latex(std::ostream& out, const analysis& result)
{
    if (!result.virial)
        return;
    const virial_result& v = *result.virial;
    out << "\\subsection*{Time averages (virial)}\n";
    out << "Over $t = " << latex_number(v.from) << " \\ldots " << latex_number(v.to) << "$:\n";
    out << "\\begin{align*}\n";
    out << "\\langle T\\rangle &= " << latex_number(v.kinetic, 10) << ",\\\\\n";
    out << "\\langle V\\rangle &= " << latex_number(v.potential, 10) << ",\\\\\n";
    out << "2\\langle T\\rangle / \\langle V\\rangle &= " << latex_number(2 * v.kinetic / v.potential, 10) << ".\n";
    out << "\\end{align*}\n";
}

void write_virial_json(nlohmann::ordered_json& doc, const analysis& result)
{
    if (!result.virial)
        return;
    const virial_result& v = *result.virial;
    nlohmann::ordered_json entry;
    entry["T"] = v.kinetic;
    entry["V"] = v.potential;
    entry["over"] = {v.from, v.to};
    if (v.quadrature_error)
        entry["quadrature_error"] = *v.quadrature_error;
    doc["virial"] = entry;
}

void write_virial_section(report_writer& w)
{
    const virial_result& v = *w.result().virial;
    w.latex("\\section{Time averages}\n");
    w.text("The kinetic and potential energy averaged over the simulated motion, from ")
        .latex("$t = " + report_writer::number(v.from) + "$ to $t = " + report_writer::number(v.to) + "$")
        .text(". For a bounded motion in a potential homogeneous of degree ")
        .latex("$n$")
        .text(", the virial theorem gives ")
        .latex("$2\\langle T\\rangle = n\\langle V\\rangle$")
        .text(" over a long time.");
    w.latex("\n\\begin{align*}\n\\langle T\\rangle &= " + report_writer::number(v.kinetic, 10) +
            ",\\\\\n\\langle V\\rangle &= " + report_writer::number(v.potential, 10) +
            ",\\\\\n2\\langle T\\rangle / \\langle V\\rangle &= " +
            report_writer::number(2 * v.kinetic / v.potential, 10) + ".\n\\end{align*}\n");
    if (v.quadrature_error)
        w.text("The averages' quadrature error is estimated at ")
            .latex("$" + report_writer::number(*v.quadrature_error, 3) + "$")
            .text(".\n");
}

} // namespace lagrange
