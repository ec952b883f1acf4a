// SPDX-License-Identifier: GPL-2.0-or-later
/** @file simulation.h
 *  The `simulation` and `workprecision` sections of the text, LaTeX and JSON
 *  documents, the trajectory as CSV, and plots drawn by gnuplot (SVG, PNG or PDF). */
#pragma once

#include "numeric/simulation.h"

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace lagrange {

/// Run times are printed only when `timings` is set (they differ from run to run).
/// The state an initial state off the constraints was projected to (`--project-initial`),
/// for the top of the text document; nothing when it was not projected.
void write_projected_initial_text(std::ostream& out, const simulation_result& s);
void write_simulation_text(std::ostream& out, const simulation_result& s, bool timings);
void write_workprecision_text(std::ostream& out, const workprecision_result& w);
void write_simulation_latex(std::ostream& out, const simulation_result& s, bool timings);
void write_workprecision_latex(std::ostream& out, const workprecision_result& w);
nlohmann::ordered_json simulation_json(const simulation_result& s, bool timings);
nlohmann::ordered_json workprecision_json(const workprecision_result& w);

/// t, then each coordinate, then each velocity (`q_dot`), one row per output time.
void write_trajectory_csv(std::ostream& out, const simulation_result& s);

/// θ(t), φ(t), … against time, drawn by gnuplot (the format by the extension): one panel per coordinate, stacked
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

/// Error against run time, log–log, one line per method, drawn by gnuplot.
void plot_workprecision(const std::string& path, const workprecision_result& w, const std::string& title);

/// Draws a plot of `width` × `height` pixels into `path`, in the format its extension names
/// (plot_format_of: SVG, PNG or PDF): `preamble` (such as `set encoding utf8`), the
/// terminal for that format with `text_mode` ("enhanced", "noenhanced" or ""), then
/// `body`, run by gnuplot in a private folder that holds `files` (name, bytes). Throws
/// std::invalid_argument for another extension, computation_error if gnuplot
/// is missing or fails, or the SVG cannot be written.
void draw_gnuplot(const std::string& path, const std::string& preamble, int width, int height,
                  const std::string& text_mode, const std::string& body,
                  const std::vector<std::pair<std::string, std::string>>& files);

} // namespace lagrange
