// SPDX-License-Identifier: GPL-2.0-or-later
/** @file simulation_output.h
 *  The `simulation` and `workprecision` sections of the text, LaTeX and JSON
 *  documents, the trajectory as CSV, and plots drawn by gnuplot (SVG). */
#pragma once

#include "numeric/simulation.h"

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace lagrange {

/// Run times are printed only when `timings` is set (they differ from run to run).
void write_simulation_text(std::ostream& out, const simulation_result& s, bool timings);
void write_workprecision_text(std::ostream& out, const workprecision_result& w);
void write_simulation_latex(std::ostream& out, const simulation_result& s, bool timings);
void write_workprecision_latex(std::ostream& out, const workprecision_result& w);
nlohmann::ordered_json simulation_json(const simulation_result& s, bool timings);
nlohmann::ordered_json workprecision_json(const workprecision_result& w);

/// t, then each coordinate, then each velocity (`q_dot`), one row per output time.
void write_trajectory_csv(std::ostream& out, const simulation_result& s);

/// θ(t), φ(t), … against time, as SVG drawn by gnuplot: one panel per coordinate, stacked
/// over one time axis (up to 6; more share one panel). Throws computation_error if gnuplot
/// is missing or fails.
void plot_trajectory(const std::string& path, const simulation_result& s, const std::string& title);

/// The gnuplot commands that draw the coordinates against time (at most 3000 points), for
/// `plot_trajectory` and the report's figure: one panel per coordinate, stacked, when there
/// are at most `max_panels` coordinates (`panels` is then their number), else all in one
/// panel with a key (`panels` is 0). A `title` (may be empty) goes above. No terminal, no
/// output file: the caller sets them.
std::string trajectory_plot_script(const simulation_result& s, std::size_t max_panels, const std::string& title,
                                   std::size_t& panels);

/// Error against run time, log–log, one line per method, as SVG drawn by gnuplot.
void plot_workprecision(const std::string& path, const workprecision_result& w, const std::string& title);

/// Runs the gnuplot `script` (which must write 'plot.svg') in a private folder that holds
/// `files` (name, bytes) and copies the SVG to `path`. Throws computation_error if gnuplot
/// is missing or fails, or the SVG cannot be written.
void draw_gnuplot_svg(const std::string& path, const std::string& script,
                      const std::vector<std::pair<std::string, std::string>>& files);

} // namespace lagrange
