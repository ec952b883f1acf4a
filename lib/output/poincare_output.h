// SPDX-License-Identifier: GPL-2.0-or-later
/** @file poincare_output.h
 *  Writers of a Poincaré section (ensemble/poincare.h): CSV (one row per crossing, orbit
 *  by orbit, every coordinate and velocity), the picture drawn by gnuplot (the two
 *  quantities of result.axes, by default a free coordinate against its velocity, one colour
 *  per orbit), and the summary for the terminal. Numbers in CSV are the shortest
 *  decimals that read back as the same double, so the file is byte-identical for any
 *  number of threads. */
#pragma once

#include "ensemble/poincare.h"

#include <ostream>
#include <string>

namespace lagrange {

/// `orbit,t,q1,…,qn,q1_dot,…,qn_dot`, then one line per crossing (orbit 0 first, in time order).
void write_poincare_csv(std::ostream& out, const poincare_result& result);

/// The section as a picture, SVG, PNG or PDF by the extension (draw_gnuplot). Throws
/// std::invalid_argument for another extension, computation_error without gnuplot.
void plot_poincare(const std::string& path, const poincare_result& result, const std::string& title);

/// `poincare: N crossings of M orbits …`, the energy error, failures; or `no crossings: why`.
std::string poincare_summary_text(const poincare_result& result);

} // namespace lagrange
