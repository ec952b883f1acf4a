// SPDX-License-Identifier: GPL-2.0-or-later
/** @file response_output.h
 *  The frequency response (`lagrange response`) as text, CSV and JSON, and its Bode
 *  diagram (magnitude and phase against drive frequency) drawn by gnuplot. */
#pragma once

#include "numeric/linear_response.h"

#include <ostream>
#include <string>

namespace lagrange {

/// A summary (input, output, values, the peak) and the table.
void write_response_text(std::ostream& out, const frequency_response& r);
/// One row per frequency: omega,magnitude,magnitude_db,phase_degrees,real,imag.
void write_response_csv(std::ostream& out, const frequency_response& r);
void write_response_json(std::ostream& out, const frequency_response& r);
/// |H| (log–log) above, the phase in degrees below, as SVG. Throws computation_error if
/// gnuplot is missing or fails.
void plot_response(const std::string& path, const frequency_response& r, const std::string& title);

} // namespace lagrange
