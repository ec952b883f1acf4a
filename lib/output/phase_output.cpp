// SPDX-License-Identifier: GPL-2.0-or-later
/** @file phase_output.cpp
 *  The phase portrait's picture and CSV (see phase_output.h). */
#include "output/phase_output.h"
#include "output/report_sections.h"

#include "output/simulation.h"
#include "core/number_text.h"
#include "system/gnuplot.h"

#include <sstream>

namespace lagrange {

namespace {

std::string level_list(const std::vector<double>& levels)
{
    std::string text;
    for (double level : levels)
        text += (text.empty() ? "" : ", ") + shortest(level);
    return text;
}

} // namespace

std::string phase_plot_script(const phase_portrait& portrait, const std::string& title)
{
    // The grid as gnuplot's scans (one velocity row per block), contoured into tables.
    std::ostringstream grid;
    for (std::size_t r = 0; r < portrait.grid; ++r) {
        for (std::size_t i = 0; i < portrait.grid; ++i)
            grid << shortest(portrait.q(i)) << ' ' << shortest(portrait.v(r)) << ' '
                 << shortest(portrait.energy[r * portrait.grid + i]) << '\n';
        grid << '\n';
    }
    std::ostringstream points;
    for (double q : portrait.stable)
        points << shortest(q) << " 0 0\n";
    for (double q : portrait.unstable)
        points << shortest(q) << " 0 1\n";
    if (portrait.stable.empty() && portrait.unstable.empty())
        points << "NaN NaN 0\n";
    std::ostringstream body;
    body << "$grid << EOD\n" << grid.str() << "EOD\n$points << EOD\n" << points.str() << "EOD\n"
         << "set contour base\nunset surface\nset view map\n"
         << "set cntrparam levels discrete " << level_list(portrait.levels) << "\n"
         << "set table $levels\nsplot $grid using 1:2:3 with lines\nunset table\n";
    if (!portrait.separatrices.empty())
        body << "set cntrparam levels discrete " << level_list(portrait.separatrices) << "\n"
             << "set table $separatrices\nsplot $grid using 1:2:3 with lines\nunset table\n";
    body << "unset contour\n";
    if (!title.empty())
        body << "set title " << gnuplot_string(title + ": phase portrait of " + portrait.coordinate) << " noenhanced\n";
    body << "set xlabel " << gnuplot_string(portrait.coordinate) << " noenhanced\nset ylabel "
         << gnuplot_string(portrait.coordinate + "'") << " noenhanced\n"
         << "set xrange [" << shortest(portrait.q_low) << ":" << shortest(portrait.q_high) << "]\n"
         << "set yrange [" << shortest(portrait.v_low) << ":" << shortest(portrait.v_high) << "]\n"
         << "set tics out\nset key outside bottom center horizontal\n"
         << "plot $levels with lines lc rgb '#1f77b4' title 'orbits (levels of the energy)'";
    if (!portrait.separatrices.empty())
        body << ", $separatrices with lines lw 2.5 lc rgb '#d62728' title 'separatrices'";
    body << ", $points using 1:($3 == 0 ? $2 : NaN) with points pt 7 ps 1.2 lc rgb 'black' title 'stable'"
         << ", $points using 1:($3 == 1 ? $2 : NaN) with points pt 6 ps 1.5 lw 2 lc rgb '#d62728' title "
            "'unstable'\n";
    return body.str();
}

void plot_phase_portrait(const std::string& path, const phase_portrait& portrait, const std::string& title)
{
    draw_gnuplot(path, "", 900, 760, "", phase_plot_script(portrait, title), {});
}

void write_phase_csv(std::ostream& out, const phase_portrait& portrait)
{
    out << portrait.coordinate << ',' << portrait.coordinate << "_dot,energy\n";
    for (std::size_t r = 0; r < portrait.grid; ++r)
        for (std::size_t i = 0; i < portrait.grid; ++i)
            out << shortest(portrait.q(i)) << ',' << shortest(portrait.v(r)) << ','
                << shortest(portrait.energy[r * portrait.grid + i]) << '\n';
}

std::string phase_summary_text(const phase_portrait& portrait)
{
    std::ostringstream out;
    out << "phase: " << portrait.coordinate << " from " << shortest(portrait.q_low) << " to "
        << shortest(portrait.q_high) << "; energies " << level_list(portrait.levels) << '\n';
    if (!portrait.separatrices.empty())
        out << "phase: separatrices at energies " << level_list(portrait.separatrices) << " (through the unstable "
            << "equilibria at " << portrait.coordinate << " = " << level_list(portrait.unstable) << ")\n";
    else
        out << "phase: no separatrix (no unstable equilibrium in the picture)\n";
    return out.str();
}

void write_phase_section(report_writer& w)
{
    const phase_portrait& p = *w.result().phase;
    const std::string q = report_writer::name(p.coordinate);
    w.latex("\\section{Phase portrait}\n");
    w.text("With one coordinate the energy ").latex("$h(" + q + ", \\dot{" + q + "})$")
        .text(" is conserved, so every orbit runs along one of its level curves. The curves below are the "
              "levels at the values of the parameters");
    if (!p.separatrices.empty())
        w.text("; the thick ones, through the unstable equilibria, are the separatrices between the orbits that "
               "stay in a well and those that leave it");
    w.text(".\n");
    w.figure("phase", phase_plot_script(p, ""), 14, 11,
             "Phase portrait of $" + q + "$: the level curves of the energy from its minimum " +
                 report_writer::number(p.minimum, 4) + (p.separatrices.empty() ? "" : ", the separatrices thick") +
                 "; stable equilibria filled, unstable ones open.");
}

} // namespace lagrange
