// SPDX-License-Identifier: GPL-2.0-or-later
/** @file simulation.cpp
*  Simulation sections, CSV, and gnuplot plots. gnuplot runs through
 *  run_program (system/external.h: an argument vector, no shell) on a script file in
 *  a private temporary folder that is always removed.
 *
*  The report's section on the motion in time: the simulation's setting and
 *  accuracy, the coordinates against time (the homework's beats, with the beat
 *  period measured in the trajectory against 2π/(ω₊ − ω₋) from the linearized
 *  frequencies), and the work-precision diagram. Everything printed comes from
 *  the `simulation` and `workprecision` stages. Run times differ from run to
 *  run and the report is byte-identical, so the diagram measures work in steps
 *  (`lagrange workprecision` plots against run time). */
#include "output/simulation.h"

#include "core/errors.h"
#include "core/number_text.h"
#include "output/latex_blocks.h"
#include "output/print.h"
#include "output/report_sections.h"
#include "system/files.h"
#include "system/gnuplot.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace lagrange {

namespace {

std::string number(double x, int digits = 6) { return significant(x, digits); }

/// x in LaTeX: 1.5\times10^{-9}.
std::string short_latex(double x, int digits = 3)
{
    const std::string text = latex_exponent(significant(x, digits));
    return text.rfind("1\\times", 0) == 0 ? text.substr(7) : text; // 10^{-9}, not 1\times10^{-9}
}

std::string drift_of(const trajectory& run, const std::string& name)
{
    for (const auto& [n, drift] : run.invariant_drift)
        if (n == name)
            return number(drift, 3);
    return "";
}

} // namespace

void draw_gnuplot(const std::string& path, const std::string& preamble, int width, int height,
                  const std::string& text_mode, const std::string& body,
                  const std::vector<std::pair<std::string, std::string>>& files)
{
    const plot_format format = plot_format_of(path);
    if (!gnuplot_available())
        throw computation_error("gnuplot is not installed (Debian package gnuplot-nox): no plot drawn");
    const std::string name = format == plot_format::svg ? "plot.svg" : format == plot_format::png ? "plot.png" : "plot.pdf";
    gnuplot_run run = run_gnuplot(preamble + gnuplot_terminal(format, width, height, text_mode, name) + body, name, files);
    if (run.timed_out)
        throw computation_error("gnuplot did not finish in time: no plot drawn");
    if (!run.drawn)
        throw computation_error("gnuplot failed to draw the plot");
    write_output(path, format == plot_format::pdf ? strip_pdf_dates(run.plot) : run.plot);
}

void write_projected_initial_text(std::ostream& out, const simulation_result& s)
{
    if (!s.projected_initial || !s.initial_residual)
        return;
    const std::size_t n = s.coordinates.size();
    out << "\ninitial state projected onto the constraints (--project-initial; it missed them by "
        << number(*s.initial_residual, 3) << "):";
    for (std::size_t i = 0; i < 2 * n && i < s.projected_initial->size(); ++i)
        if (i < n || (*s.projected_initial)[i] != 0)
            out << (i ? ", " : " ") << print_name(s.coordinates[i % n] + (i < n ? "" : "_dot"), syntax::text) << " = "
                << number((*s.projected_initial)[i]);
    out << '\n';
}

void write_simulation_text(std::ostream& out, const simulation_result& s, bool timings)
{
    const trajectory& run = s.run;
    std::size_t n = s.coordinates.size();
    out << "\nSimulation\n";
    out << "  method: " << s.method << " (" << s.choice << ")\n";
    out << "  from t = 0 to " << number(run.times.empty() ? 0 : run.times.back()) << ", tolerance "
        << number(s.tolerance, 3) << " relative, " << number(s.absolute_tolerance, 3) << " absolute, "
        << run.times.size() << " output times\n";
    if (s.missed_error)
        out << "  run again at tolerance " << number(s.run_tolerance, 3) << ": the first run's error, "
            << number(*s.missed_error, 3) << ", missed the tolerance\n";
    if (!s.frequencies.empty()) {
        out << "  linearized frequencies: ω =";
        for (std::size_t k = 0; k < s.frequencies.size(); ++k)
            out << (k ? ", " : " ") << number(s.frequencies[k]);
        out << '\n';
    }
    if (!s.growth_rates.empty()) {
        out << "  linearized growth rates (unstable, q ∝ e^{st}): s =";
        for (std::size_t k = 0; k < s.growth_rates.size(); ++k)
            out << (k ? ", " : " ") << "+" << number(s.growth_rates[k]);
        out << '\n';
    }
    out << "  steps: " << run.steps << " (" << run.evaluations << " evaluations, " << run.jacobians
        << " Jacobians)\n";
    if (s.error_estimate)
        out << "  error estimate: " << number(*s.error_estimate, 3) << " relative (" << s.error_basis << ")\n";
    else
        out << "  error estimate: " << s.error_basis << '\n';
    for (const auto& [name, drift] : run.invariant_drift) {
        if (name == "energy_balance")
            out << "  energy balance: " << number(drift, 3)
                << " relative (largest |h(t) − h(0) − ∫ Σ Q q̇ dt|: energy change, dissipated and input work)\n";
        else
            out << "  " << name << " drift: " << number(drift, 3) << " relative\n";
    }
    if (s.constraint_residual)
        out << "  constraint residual: " << number(*s.constraint_residual, 3)
            << " (largest |f| and |A q' + b| before each projection onto the constraints)\n";
    for (const constraint_event& e : s.constraint_events) {
        out << "  λ_" << e.constraint << " changes sign at t = " << number(e.time) << ":";
        for (std::size_t i = 0; i < n && i < e.state.size(); ++i)
            out << (i ? ", " : " ") << print_name(s.coordinates[i], syntax::text) << " = " << number(e.state[i]);
        out << '\n';
    }
    if (!s.evaluation.empty())
        out << "  evaluation: " << s.evaluation << '\n';
    if (timings)
        out << "  run time: " << number(run.seconds, 3) << " s\n";
    if (s.beats) {
        const beat_measurement& b = *s.beats;
        out << "  beats (" << print_name(b.coordinate, syntax::text) << "): period measured " << number(b.measured, 5)
            << ", predicted 2π/(ω₂ − ω₁) = " << number(b.predicted, 5) << " (difference "
            << number(100 * std::abs(b.measured - b.predicted) / b.predicted, 2) << " %, " << b.minima
            << " envelope minima)\n";
    }
    if (!run.final_state.empty()) {
        out << "  final state:";
        for (std::size_t i = 0; i < n; ++i)
            out << (i ? ", " : " ") << print_name(s.coordinates[i], syntax::text) << " = "
                << number(run.final_state[i]);
        for (std::size_t i = 0; i < n && !s.first_order; ++i)
            out << ", " << print_name(s.coordinates[i] + "_dot", syntax::text) << " = "
                << number(run.final_state[n + i]);
        out << '\n';
    }
}

void write_workprecision_text(std::ostream& out, const workprecision_result& w)
{
    out << "\nWork precision (t from 0 to " << number(w.until) << "; error " << w.reference << ")\n";
    if (!w.evaluation.empty())
        out << "  evaluation: " << w.evaluation << '\n';
    // Columns as printf's "%-18s %9s %11s %11s %10s %11s".
    auto left = [](const std::string& text, std::size_t width) {
        return text.size() < width ? text + std::string(width - text.size(), ' ') : text;
    };
    auto right = [](const std::string& text, std::size_t width) {
        return text.size() < width ? std::string(width - text.size(), ' ') + text : text;
    };
    out << "  " << left("method", 18) << ' ' << right("tolerance", 9) << ' ' << right("error", 11) << ' '
        << right("seconds", 11) << ' ' << right("steps", 10) << ' ' << right("energy", 11) << '\n';
    for (const workprecision_point& p : w.points) {
        out << "  " << left(p.method, 18) << ' ' << right(scientific(p.tolerance, 0), 9);
        if (!p.failure.empty()) {
            out << "  " << p.failure << '\n';
            continue;
        }
        out << ' ' << right(scientific(p.error ? *p.error : NAN, 3), 11) << ' ' << right(scientific(p.seconds, 3), 11)
            << ' ' << right(std::to_string(p.steps), 10) << ' '
            << right(p.energy_drift ? number(*p.energy_drift, 3) : "-", 11) << '\n';
    }
}

void write_simulation_latex(std::ostream& out, const simulation_result& s, bool timings)
{
    const trajectory& run = s.run;
    out << "\\subsection*{Simulation}\n";
    out << "Method " << latex_text(s.method) << " (" << latex_text(s.choice) << "), from $t = 0$ to $"
        << short_latex(run.times.empty() ? 0 : run.times.back(), 6) << "$, tolerance $" << short_latex(s.tolerance)
        << "$ relative and $" << short_latex(s.absolute_tolerance) << "$ absolute.";
    if (s.missed_error)
        out << " Run again at tolerance $" << short_latex(s.run_tolerance) << "$: the first run's error, $"
            << short_latex(*s.missed_error) << "$, missed the tolerance.";
    out << "\\\\\n";
    out << "\\begin{tabular}{ll}\n";
    out << "steps & " << run.steps << " (" << run.evaluations << " evaluations, " << run.jacobians
        << " Jacobians)\\\\\n";
    if (s.error_estimate)
        out << "error estimate & $" << short_latex(*s.error_estimate) << "$ relative\\\\\n";
    if (!s.growth_rates.empty()) {
        out << "linearized growth rates (unstable, $q \\propto e^{st}$) & $s =";
        for (std::size_t k = 0; k < s.growth_rates.size(); ++k)
            out << (k ? ",\\ " : " ") << "+" << short_latex(s.growth_rates[k], 6);
        out << "$\\\\\n";
    }
    for (const auto& [name, drift] : run.invariant_drift) {
        if (name == "energy_balance")
            out << "energy balance $h(t)-h(0)-\\int Q\\cdot\\dot q\\,dt$ & $" << short_latex(drift)
                << "$ relative\\\\\n";
        else
            out << latex_text(name) << " drift & $" << short_latex(drift) << "$ relative\\\\\n";
    }
    if (s.constraint_residual)
        out << "constraint residual & $" << short_latex(*s.constraint_residual) << "$\\\\\n";
    if (s.initial_residual)
        out << "initial state & off the constraints by $" << short_latex(*s.initial_residual)
            << "$, projected onto them (as asked)\\\\\n";
    for (const constraint_event& e : s.constraint_events)
        out << "$\\lambda_{" << latex_text(e.constraint) << "}$ changes sign & $t = " << short_latex(e.time)
            << "$\\\\\n";
    if (timings)
        out << "run time & " << number(run.seconds, 3) << " s\\\\\n";
    if (s.beats)
        out << "beat period & measured $" << short_latex(s.beats->measured, 5)
            << "$, predicted $2\\pi/(\\omega_2-\\omega_1) = " << short_latex(s.beats->predicted, 5) << "$\\\\\n";
    out << "\\end{tabular}\n\n";
    if (s.error_estimate)
        out << "The error estimate is " << latex_text(s.error_basis) << ".\n";
}

void write_workprecision_latex(std::ostream& out, const workprecision_result& w)
{
    out << "\\subsection*{Work precision}\n";
    out << "Error " << latex_text(w.reference) << ".\\\\\n";
    out << "\\begin{tabular}{lrrrr}\nmethod & tolerance & error & seconds & steps\\\\\n\\hline\n";
    for (const workprecision_point& p : w.points) {
        if (!p.failure.empty() || !p.error)
            continue;
        out << latex_text(p.method) << " & $" << short_latex(p.tolerance) << "$ & $" << short_latex(*p.error)
            << "$ & $" << short_latex(p.seconds) << "$ & " << p.steps << "\\\\\n";
    }
    out << "\\end{tabular}\n";
}

nlohmann::ordered_json simulation_json(const simulation_result& s, bool timings)
{
    const trajectory& run = s.run;
    std::size_t n = s.coordinates.size();
    nlohmann::ordered_json doc;
    doc["method"] = s.method;
    doc["steps"] = run.steps;
    doc["t"] = run.times;
    nlohmann::ordered_json states = nlohmann::ordered_json::object();
    for (std::size_t i = 0; i < (s.first_order ? n : 2 * n); ++i) {
        std::vector<double> column;
        for (const auto& state : run.states)
            column.push_back(state[i]);
        states[i < n ? s.coordinates[i] : s.coordinates[i - n] + "_dot"] = column;
    }
    doc["states"] = states;
    nlohmann::ordered_json invariants = nlohmann::ordered_json::object();
    for (const auto& [name, drift] : run.invariant_drift)
        invariants[name == "energy_balance" ? name : name + "_drift"] = drift;
    if (s.constraint_residual)
        invariants["constraint_residual"] = *s.constraint_residual;
    doc["invariants"] = invariants;
    if (!s.constraint_events.empty()) {
        nlohmann::ordered_json events = nlohmann::ordered_json::array();
        for (const constraint_event& e : s.constraint_events) {
            nlohmann::ordered_json state = nlohmann::ordered_json::object();
            for (std::size_t i = 0; i < n && i < e.state.size(); ++i)
                state[s.coordinates[i]] = e.state[i];
            for (std::size_t i = 0; i < n && n + i < e.state.size(); ++i)
                state[s.coordinates[i] + "_dot"] = e.state[n + i];
            events.push_back({{"multiplier_changes_sign", e.constraint}, {"t", e.time}, {"state", state}});
        }
        doc["events"] = events;
    }
    if (s.initial_residual)
        doc["initial_residual"] = *s.initial_residual;
    if (s.projected_initial) {
        nlohmann::ordered_json state = nlohmann::ordered_json::object();
        for (std::size_t i = 0; i < 2 * n && i < s.projected_initial->size(); ++i)
            state[i < n ? s.coordinates[i] : s.coordinates[i - n] + "_dot"] = (*s.projected_initial)[i];
        doc["projected_initial"] = state;
    }
    doc["choice"] = s.choice;
    doc["tolerance"] = s.tolerance;
    doc["absolute_tolerance"] = s.absolute_tolerance;
    doc["run_tolerance"] = s.run_tolerance;
    if (s.missed_error)
        doc["missed_error"] = *s.missed_error;
    doc["evaluations"] = run.evaluations;
    doc["jacobians"] = run.jacobians;
    if (s.error_estimate)
        doc["error_estimate"] = *s.error_estimate;
    doc["error_basis"] = s.error_basis;
    doc["frequencies"] = s.frequencies;
    if (!s.growth_rates.empty())
        doc["growth_rates"] = s.growth_rates;
    if (s.beats)
        doc["beats"] = {{"coordinate", s.beats->coordinate},
                        {"measured", s.beats->measured},
                        {"predicted", s.beats->predicted},
                        {"minima", s.beats->minima}};
    if (timings)
        doc["seconds"] = run.seconds;
    return doc;
}

nlohmann::ordered_json workprecision_json(const workprecision_result& w)
{
    nlohmann::ordered_json doc;
    doc["reference"] = w.reference;
    doc["exact"] = w.exact;
    doc["until"] = w.until;
    nlohmann::ordered_json runs = nlohmann::ordered_json::array();
    for (const workprecision_point& p : w.points) {
        nlohmann::ordered_json r;
        r["method"] = p.method;
        r["tolerance"] = p.tolerance;
        if (p.failure.empty()) {
            r["error"] = p.error ? nlohmann::ordered_json(*p.error) : nlohmann::ordered_json();
            r["seconds"] = p.seconds;
            r["steps"] = p.steps;
            if (p.energy_drift)
                r["energy_drift"] = *p.energy_drift;
        } else {
            r["failure"] = p.failure;
        }
        runs.push_back(r);
    }
    doc["runs"] = runs;
    return doc;
}

void write_trajectory_csv(std::ostream& out, const simulation_result& s)
{
    std::size_t n = s.coordinates.size();
    out << "t";
    for (const std::string& name : s.coordinates)
        out << ',' << name;
    for (const std::string& name : s.coordinates)
        if (!s.first_order)
            out << ',' << name << "_dot";
    out << '\n';
    for (std::size_t k = 0; k < s.run.states.size(); ++k) {
        out << shortest(s.run.times[k]);
        for (std::size_t i = 0; i < (s.first_order ? n : 2 * n); ++i)
            out << ',' << shortest(s.run.states[k][i]);
        out << '\n';
    }
}

std::string trajectory_plot_script(const simulation_result& s, std::size_t max_panels, const std::string& title,
                                   std::size_t& panels)
{
    // Numbers to 9 digits; labels keep every printable character (gnuplot_string).
    auto plot_number = [](double x) { return significant(x, 9); };
    const std::size_t n = s.coordinates.size();
    const std::size_t stride = (s.run.times.size() + 2999) / 3000;
    std::string data = "$motion << EOD\n";
    for (std::size_t r = 0; r < s.run.times.size() && r < s.run.states.size(); r += stride) {
        data += plot_number(s.run.times[r]);
        for (std::size_t i = 0; i < n; ++i)
            data += " " + plot_number(s.run.states[r][i]);
        data += "\n";
    }
    data += "EOD\n";
    std::string script = data + "set grid\nset key off\nset xrange [" +
                         (s.run.times.empty() ? std::string("*:*")
                                              : plot_number(s.run.times.front()) + ":" + plot_number(s.run.times.back())) +
                         "]\n";
    const char* colours[] = {"#1f4e9c", "#c00000", "#2a8a2a", "#8a4bb0"};
    const std::string title_clause = title.empty() ? "" : " title " + gnuplot_string(title) + " noenhanced";
    panels = n <= max_panels ? n : 0;
    if (panels > 0) {
        script += "set multiplot layout " + std::to_string(panels) + ",1" + title_clause + "\nset lmargin 10\n";
        for (std::size_t i = 0; i < n; ++i) {
            script += "set ylabel " + gnuplot_string(print_name(s.coordinates[i], syntax::text)) + "\n";
            script += i + 1 == n ? "set xlabel 't'\n" : "unset xlabel\n";
            script += "plot $motion using 1:" + std::to_string(i + 2) + " with lines lw 1.2 lc rgb '" + colours[i % 4] +
                      "'\n";
        }
        script += "unset multiplot\n";
    } else {
        if (!title.empty())
            script += "set title " + gnuplot_string(title) + " noenhanced\n";
        script += "set key outside right\nset xlabel 't'\nplot ";
        for (std::size_t i = 0; i < n; ++i)
            script += std::string(i ? ", " : "") + "$motion using 1:" + std::to_string(i + 2) + " with lines title " +
                      gnuplot_string(print_name(s.coordinates[i], syntax::text));
        script += "\n";
    }
    return script;
}

void plot_trajectory(const std::string& path, const simulation_result& s, const std::string& title)
{
    if (s.run.states.empty() || s.coordinates.empty())
        throw computation_error("the simulation has no trajectory to plot");
    std::size_t panels = 0;
    const std::string body = trajectory_plot_script(s, 6, title + " (" + s.method + ")", panels);
    const std::size_t height = 90 + 170 * (panels > 0 ? panels : 2);
    draw_gnuplot(path, "set encoding utf8\n", 900, static_cast<int>(height), "noenhanced", body, {});
}

void plot_workprecision(const std::string& path, const workprecision_result& w, const std::string& title)
{
    std::vector<std::string> methods;
    for (const workprecision_point& p : w.points)
        if (p.failure.empty() && p.error && *p.error > 0 && (methods.empty() || methods.back() != p.method))
            methods.push_back(p.method);
    if (methods.empty())
        throw computation_error("no run of the work-precision table succeeded: nothing to plot");
    std::ostringstream data;
    for (const std::string& m : methods) {
        data << "# " << m << '\n';
        for (const workprecision_point& p : w.points)
            if (p.method == m && p.failure.empty() && p.error && *p.error > 0)
                data << number(p.seconds, 8) << ' ' << number(*p.error, 8) << ' ' << number(p.tolerance, 3) << '\n';
        data << "\n\n";
    }
    std::ostringstream script;
    script << "set logscale xy\nset format x '1e%T'\nset format y '1e%T'\n"
              "set xlabel 'run time (s)'\nset ylabel 'relative error'\nset grid\nset key outside right top\n"
           << "set title " << gnuplot_string(title + " — " + w.reference) << " noenhanced\nplot ";
    for (std::size_t k = 0; k < methods.size(); ++k)
        script << (k ? ", " : "") << "'data.txt' index " << k << " using 1:2 with linespoints lw 1.5 pt 7 ps 0.6 title "
               << gnuplot_string(methods[k]) << " noenhanced";
    script << '\n';
    draw_gnuplot(path, "", 900, 560, "enhanced", script.str(), {{"data.txt", data.str()}});
}

// ---- the report's section ----

namespace {

std::string gnuplot_number(double x) { return significant(x, 9); }

void write_simulation(report_writer& w, const simulation_result& s)
{
    const std::size_t n = s.coordinates.size();
    w.latex("\\subsection{Simulation}\n");
    // The coordinates against time, one panel each (at most 3000 points drawn).
    // Drawn before the prose, so that the float can take the top of this page rather than
    // a page of its own at the end (which left half a page blank).
    if (!s.run.states.empty() && s.run.times.size() == s.run.states.size() && n > 0) {
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
        w.figure(s.beats ? "beats" : "motion", script, 15, 2.2 + 4.4 * static_cast<double>(panels > 0 ? panels : 2),
                 caption);
    }
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
        if (s.initial_residual) // --project-initial: not the state written
            w.text(" (the initial state as written missed the constraints by ")
                .latex("$" + report_writer::number(*s.initial_residual, 3) + "$")
                .text(" and was projected onto them, as asked)");
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
