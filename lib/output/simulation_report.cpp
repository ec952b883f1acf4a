// SPDX-License-Identifier: GPL-2.0-or-later
/** @file simulation_report.cpp
 *  The report's section on the motion in time: the simulation's setting and
 *  accuracy, the coordinates against time (the homework's beats, with the beat
 *  period measured in the trajectory against 2π/(ω₊ − ω₋) from the linearized
 *  frequencies), and the work-precision diagram. Everything printed comes from
 *  the `simulation` and `workprecision` stages. Run times differ from run to
 *  run and the report is byte-identical, so the diagram measures work in steps
 *  (`lagrange workprecision` plots against run time). */
#include "output/report_sections.h"

#include "core/number_text.h"

#include "output/latex_blocks.h"
#include "output/print.h"
#include "output/simulation_output.h"
#include "system/gnuplot.h"

#include <cmath>
#include <cstdio>
#include <map>

namespace lagrange {

namespace {

std::string gnuplot_number(double x) { return significant(x, 9); }

void write_simulation(report_writer& w, const simulation_result& s)
{
    const std::size_t n = s.coordinates.size();
    w.latex("\\subsection{Simulation}\n");
    if (!s.values.empty()) {
        w.text("At ");
        std::size_t k = 0;
        std::string at;
        for (const auto& [name, value] : s.values)
            at += (k++ ? ",\\ " : "") + report_writer::name(name) + " = " + report_writer::math(value);
        w.latex("$" + at + "$").text(", the");
    } else {
        w.text("The");
    }
    w.text(" equations of motion are integrated numerically");
    if (!s.run.states.empty() && s.run.states.front().size() >= 2 * n && !s.run.times.empty()) {
        const std::vector<double>& x0 = s.run.states.front();
        std::vector<std::string> entries;
        for (std::size_t i = 0; i < n; ++i)
            entries.push_back(report_writer::name(s.coordinates[i]) + "(0) = " + report_writer::number(x0[i]));
        for (std::size_t i = 0; i < n; ++i)
            entries.push_back("\\dot{" + report_writer::name(s.coordinates[i]) + "}(0) = " + report_writer::number(x0[n + i]));
        std::string initial;
        for (std::size_t i = 0; i < entries.size(); ++i)
            initial += (i ? ",\\ " : "") + entries[i];
        // Wider than a line: one formula per entry, so that the line can break between them,
        // each number to 6 digits.
        if (latex_math_width(initial) > 75) {
            initial.clear();
            for (std::size_t i = 0; i < 2 * n; ++i)
                initial += (i ? "$, $" : "") + std::string(i < n ? "" : "\\dot{") +
                           report_writer::name(s.coordinates[i % n]) + (i < n ? "" : "}") + "(0) = " +
                           report_writer::number(x0[i], 6);
        }
        w.text(" from ").latex("$" + initial + "$");
    }
    if (!s.run.times.empty())
        w.text(" to ").latex("$t = " + report_writer::number(s.run.times.back()) + "$");
    w.text(" by the method " + s.method);
    if (!s.choice.empty())
        w.text(" (" + s.choice + ")");
    w.text(" at the tolerance ").latex("$" + report_writer::number(s.tolerance, 3) + "$");
    w.text(": " + std::to_string(s.run.steps) + " steps");
    if (s.error_estimate)
        w.text(", a relative error of about ")
            .latex("$" + report_writer::number(*s.error_estimate, 2) + "$")
            .text(s.error_basis.empty() ? "" : " (" + s.error_basis + ")");
    for (const auto& [name, drift] : s.run.invariant_drift)
        w.text(", a relative drift of the " + (name == "energy_balance" ? "energy balance" : name) + " of ").latex("$" + report_writer::number(drift, 2) + "$");
    w.text(".\n");
    if (s.missed_error)
        w.text(" A first run's error, about ")
            .latex("$" + report_writer::number(*s.missed_error, 2) + "$")
            .text(", missed the tolerance, and the run was repeated at the setting ")
            .latex("$" + report_writer::number(s.run_tolerance, 3) + "$")
            .text(".\n");
    if (!s.frequencies.empty()) {
        std::string list;
        for (std::size_t k = 0; k < s.frequencies.size(); ++k)
            list += (k ? ",\\ " : "") + report_writer::number(s.frequencies[k], 6);
        w.text(" The linearized frequencies about the equilibrium are ").latex("$\\omega = " + list + "$").text(".\n");
    }
    if (!s.growth_rates.empty()) {
        std::string list;
        for (std::size_t k = 0; k < s.growth_rates.size(); ++k)
            list += (k ? ",\\ " : "") + report_writer::number(s.growth_rates[k], 6);
        w.text(" The equilibrium is unstable: linearized about it, the motion grows as ")
            .latex("$e^{st}$")
            .text(" with growth rate ")
            .latex("$s = " + list + "$")
            .text(".\n");
    }

    // The coordinates against time, one panel each (at most 3000 points drawn).
    if (s.run.states.empty() || s.run.times.size() != s.run.states.size() || n == 0)
        return;
    std::size_t panels = 0;
    const std::string script = trajectory_plot_script(s, 4, "", panels);
    std::string names;
    for (std::size_t i = 0; i < n; ++i)
        names += (i ? (i + 1 == n ? " and " : ", ") : "") + std::string("$") + report_writer::name(s.coordinates[i]) + "(t)$";
    std::string caption = names + " from the simulation (" + latex_text(s.method) + ").";
    if (s.beats && s.beats->measured > 0)
        caption += " The envelope of $" + report_writer::name(s.beats->coordinate) +
                   "$ swells and fades with the beat period: measured $" + report_writer::number(s.beats->measured, 5) +
                   "$, predicted $2\\pi/(\\omega_{+} - \\omega_{-}) = " + report_writer::number(s.beats->predicted, 5) + "$.";
    w.figure(s.beats ? "beats" : "motion", script, 15, 2.2 + 3.4 * static_cast<double>(panels > 0 ? panels : 2),
             caption);
    if (s.beats && s.beats->measured > 0 && s.beats->predicted > 0) {
        const beat_measurement& b = *s.beats;
        const double difference = std::abs(b.measured - b.predicted) / b.predicted;
        w.text("Beats: the energy passes back and forth between the modes, and the swing of ")
            .latex("$" + report_writer::name(b.coordinate) + "$")
            .text(" dies away and returns. Its envelope has " + std::to_string(b.minima) + " minima, spaced by ")
            .latex("$" + report_writer::number(b.measured, 6) + "$")
            .text(" on average; the two linearized frequencies predict the beat period");
        w.display_terms("\\frac{2\\pi}{\\omega_{+} - \\omega_{-}}", {report_writer::number(b.predicted, 6)},
                        ",\\qquad \\text{a relative difference of } " + report_writer::number(difference, 2) + ".");
    } else if (s.beats) {
        w.text("Fewer than two minima of the envelope of ")
            .latex("$" + report_writer::name(s.beats->coordinate) + "$")
            .text(" fall in the time simulated, so the beat period is not measured.\n");
    }
}

void write_workprecision(report_writer& w, const workprecision_result& r)
{
    w.latex("\\subsection{Work and precision}\n");
    w.text("Every method runs over a ladder of tolerances to ")
        .latex("$t = " + report_writer::number(r.until) + "$")
        .text(", its relative trajectory error measured against the " +
              std::string(r.exact ? "exact normal-mode solution" : r.reference) +
              ". The work is counted in steps (run times differ from run to run and this document does not; "
              "`lagrange workprecision` plots against run time).\n");
    std::map<std::string, std::vector<const workprecision_point*>> by_method;
    std::vector<std::string> order;
    std::size_t failed = 0;
    for (const workprecision_point& p : r.points) {
        if (!by_method.count(p.method))
            order.push_back(p.method);
        by_method[p.method];
        if (p.error && *p.error > 0 && p.steps > 0 && p.failure.empty())
            by_method[p.method].push_back(&p);
        else
            ++failed;
    }
    std::string script = "set logscale xy\nset format x '1e%T'\nset format y '1e%T'\nset grid\n"
                         "set xlabel 'steps'\nset ylabel 'relative error'\nset key outside right top\n";
    std::string plots;
    const char* colours[] = {"#1f4e9c", "#c00000", "#2a8a2a", "#8a4bb0", "#d08000", "#008b8b", "#555555", "#b03060"};
    std::size_t k = 0;
    for (const std::string& method : order) {
        const auto& points = by_method[method];
        if (points.empty())
            continue;
        std::string block = "$m" + std::to_string(k) + " << EOD\n";
        for (const workprecision_point* p : points)
            block += std::to_string(p->steps) + " " + gnuplot_number(*p->error) + "\n";
        script += block + "EOD\n";
        plots += std::string(plots.empty() ? "plot " : ", ") + "$m" + std::to_string(k) +
                 " using 1:2 with linespoints lw 1.5 pt 7 ps 0.5 lc rgb '" + colours[k % 8] + "' title " + gnuplot_string(method);
        ++k;
    }
    if (plots.empty()) {
        w.text("No method produced a measured error.\n");
        return;
    }
    script += plots + "\n";
    w.figure("workprecision", script, 15, 9,
             "Work-precision: relative error against steps, one line per method, each point a tolerance (" +
                 latex_text(r.reference) + ").");
    if (failed > 0)
        w.text(std::to_string(failed) + " of the " + std::to_string(r.points.size()) +
               " runs are left out of the diagram (a run that stopped, or one left out after a looser tolerance "
               "failed).\n");
}

} // namespace

void write_motion_sections(report_writer& w)
{
    const analysis& r = w.result();
    w.latex("\\section{Motion in time}\n");
    if (r.simulation)
        write_simulation(w, *r.simulation);
    if (r.workprecision)
        write_workprecision(w, *r.workprecision);
}

} // namespace lagrange
