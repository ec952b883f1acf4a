// SPDX-License-Identifier: GPL-2.0-or-later
/** @file phase_output.cpp
 *  The phase portrait's picture and CSV (see phase_output.h). */
#include "output/phase_output.h"

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

void plot_phase_portrait(const std::string& path, const phase_portrait& portrait, const std::string& title)
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
    body << "set contour base\nunset surface\nset view map\n"
         << "set cntrparam levels discrete " << level_list(portrait.levels) << "\n"
         << "set table 'levels.dat'\nsplot 'grid.dat' using 1:2:3 with lines\nunset table\n";
    if (!portrait.separatrices.empty())
        body << "set cntrparam levels discrete " << level_list(portrait.separatrices) << "\n"
             << "set table 'separatrices.dat'\nsplot 'grid.dat' using 1:2:3 with lines\nunset table\n";
    body << "unset contour\nset title " << gnuplot_string(title + ": phase portrait of " + portrait.coordinate)
         << " noenhanced\nset xlabel " << gnuplot_string(portrait.coordinate) << " noenhanced\nset ylabel "
         << gnuplot_string(portrait.coordinate + "'") << " noenhanced\n"
         << "set xrange [" << shortest(portrait.q_low) << ":" << shortest(portrait.q_high) << "]\n"
         << "set yrange [" << shortest(portrait.v_low) << ":" << shortest(portrait.v_high) << "]\n"
         << "set tics out\nset key outside bottom center horizontal\n"
         << "plot 'levels.dat' with lines lc rgb '#1f77b4' title 'orbits (levels of the energy)'";
    if (!portrait.separatrices.empty())
        body << ", 'separatrices.dat' with lines lw 2.5 lc rgb '#d62728' title 'separatrices'";
    body << ", 'points.dat' using 1:($3 == 0 ? $2 : NaN) with points pt 7 ps 1.2 lc rgb 'black' title 'stable'"
         << ", 'points.dat' using 1:($3 == 1 ? $2 : NaN) with points pt 6 ps 1.5 lw 2 lc rgb '#d62728' title "
            "'unstable'\n";
    draw_gnuplot(path, "", 900, 760, "", body.str(), {{"grid.dat", grid.str()}, {"points.dat", points.str()}});
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

} // namespace lagrange
