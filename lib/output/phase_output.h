// SPDX-License-Identifier: GPL-2.0-or-later
/** @file phase_output.h
 *  The phase portrait (numeric/phase_portrait.h) as a picture: the level curves of the
 *  energy, contoured by gnuplot, with the separatrices thicker and the equilibria marked;
 *  or its grid as CSV. */
#pragma once

#include "numeric/phase_portrait.h"

#include <ostream>
#include <string>

namespace lagrange {

/// SVG, PNG or PDF by the extension (draw_gnuplot). Throws std::invalid_argument for another
/// extension, computation_error without gnuplot.
void plot_phase_portrait(const std::string& path, const phase_portrait& portrait, const std::string& title);

/// The gnuplot commands that draw it (its data inline), titled `TITLE: phase portrait of q`
/// (untitled for an empty title).
std::string phase_plot_script(const phase_portrait& portrait, const std::string& title);

/// `q,q_dot,energy`, one line per grid point, velocity rows after one another.
void write_phase_csv(std::ostream& out, const phase_portrait& portrait);

/// The energies drawn, the separatrices and the equilibria, for the terminal.
std::string phase_summary_text(const phase_portrait& portrait);

} // namespace lagrange
