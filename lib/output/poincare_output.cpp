// SPDX-License-Identifier: GPL-2.0-or-later
/** @file poincare_output.cpp
 *  Writers of a Poincaré section (see poincare_output.h). */
#include "output/poincare_output.h"

#include "output/simulation.h"
#include "core/number_text.h"
#include "system/gnuplot.h"

#include <sstream>

namespace lagrange {

void write_poincare_csv(std::ostream& out, const poincare_result& result)
{
    out << "orbit,t";
    for (const std::string& c : result.coordinates)
        out << ',' << c;
    for (const std::string& c : result.coordinates)
        out << ',' << c << "_dot";
    out << '\n';
    const std::size_t width = result.width();
    for (std::size_t k = 0; k < result.orbits.size(); ++k) {
        const std::vector<double>& points = result.orbits[k].points;
        for (std::size_t p = 0; p + width <= points.size(); p += width) {
            out << k;
            for (std::size_t i = 0; i < width; ++i)
                out << ',' << shortest(points[p + i]);
            out << '\n';
        }
    }
}

void plot_poincare(const std::string& path, const poincare_result& result, const std::string& title)
{
    const std::size_t width = result.width(), n = result.coordinates.size();
    const std::size_t across = result.axes.horizontal, up = result.axes.vertical;
    auto label = [&](std::size_t column) {
        return column > n ? result.coordinates[column - 1 - n] + "'" : result.coordinates[column - 1];
    };
    // One block per orbit (blank lines between), coloured by the orbit's index.
    std::ostringstream data;
    for (std::size_t k = 0; k < result.orbits.size(); ++k) {
        const std::vector<double>& points = result.orbits[k].points;
        for (std::size_t p = 0; p + width <= points.size(); p += width)
            data << shortest(points[p + across]) << ' ' << shortest(points[p + up]) << ' ' << k << '\n';
        data << "\n\n";
    }
    const poincare_section& s = result.section;
    const std::string& q = result.coordinates[s.coordinate];
    std::string subtitle = "section " + q + " = " + shortest(s.level) +
                           (s.direction > 0 ? ", " + q + "' > 0" : s.direction < 0 ? ", " + q + "' < 0" : "") +
                           ", energy " + shortest(result.energy);
    std::ostringstream body;
    body << "set title " << gnuplot_string(title + ": " + subtitle) << " noenhanced\n"
         << "set xlabel " << gnuplot_string(label(across)) << " noenhanced\n"
         << "set ylabel " << gnuplot_string(label(up)) << " noenhanced\n"
         << "set tics out\nunset key\nunset colorbox\n"
            "set palette defined (0 '#1f77b4', 1 '#2ca02c', 2 '#d62728', 3 '#9467bd', 4 '#ff7f0e', 5 '#17becf')\n";
    if (result.crossings() == 0)
        body << "set label 1 'no crossings' at graph 0.5, graph 0.5 center\nplot [-1:1] [-1:1] NaN\n";
    else
        body << "plot 'section.dat' using 1:2:3 with points pointtype 7 pointsize 0.25 lc palette\n";
    draw_gnuplot(path, "", 900, 800, "", body.str(), {{"section.dat", data.str()}});
}

std::string poincare_summary_text(const poincare_result& result)
{
    std::ostringstream out;
    if (!result.no_crossings.empty()) {
        out << "poincare: no crossings: " << result.no_crossings << '\n';
        return out.str();
    }
    out << "poincare: " << result.crossings() << " crossings of " << result.orbits.size() << " orbits on "
        << result.threads << (result.threads == 1 ? " thread" : " threads") << " in " << significant(result.seconds, 3)
        << " s; " << result.steps() << " integration steps; evaluation: " << result.evaluation << '\n';
    out << "poincare: energy at the crossings within " << significant(result.worst_energy_error, 3)
        << " of E = " << shortest(result.energy) << " (relative to "
        << (result.has_minimum ? "E minus the minimum " + shortest(result.minimum) : std::string("max(|E|, 1)"))
        << ")\n";
    if (result.overweight_starts > 0)
        out << "poincare: " << result.overweight_starts
            << " draws of the starts found a velocity ellipsoid larger than its sampled bound: the starts are "
               "not quite uniform there\n";
    if (std::size_t failed = result.failures()) {
        for (std::size_t k = 0; k < result.orbits.size(); ++k)
            if (!result.orbits[k].failure.empty()) {
                out << "poincare: " << failed << " orbits stopped early; the first, orbit " << k << ": "
                    << result.orbits[k].failure << '\n';
                break;
            }
    }
    return out.str();
}

} // namespace lagrange
