// SPDX-License-Identifier: GPL-2.0-or-later
/** @file critical.h
 *  The critical parameters (numeric/critical.h) as text, LaTeX and JSON, and the root
 *  locus (every eigenvalue's real and imaginary part along the range) as a gnuplot plot. */
#pragma once

#include "engine/analysis.h"
#include "numeric/critical.h"

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>

namespace lagrange {

void write_critical_text(std::ostream& out, const analysis& result);
void write_critical_latex(std::ostream& out, const analysis& result);
/// "critical": {"parameter", "range": [from, to], "values": {...}, "crossings": [{"value",
/// "tolerance", "eigenvalue": [re, im], "unstable_before", "unstable_after"}], "table":
/// {"columns": [...], "rows": [[...]]}, "locus": {"columns", "rows"}}.
void write_critical_json(nlohmann::ordered_json& doc, const analysis& result);

/// The gnuplot commands (after the terminal) that draw the root locus: Re s (black dots)
/// and |Im s| (grey rings) of every eigenvalue against the parameter, the crossings marked.
std::string critical_plot_script(const critical_result& critical);

} // namespace lagrange
