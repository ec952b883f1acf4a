// SPDX-License-Identifier: GPL-2.0-or-later
/** @file oscillations.h
 *  The small-oscillations family in text, LaTeX and JSON: equilibria, the linearization,
 *  the characteristic polynomial, the modes and normal coordinates, the asymptotic limit
 *  and the numeric modes (its report sections are in report.cpp, the gyroscopic ones in oscillations.cpp and the figure in mode_figures.cpp). */
#pragma once

#include "engine/analysis.h"

#include <nlohmann/json.hpp>

#include <ostream>

namespace lagrange {

void write_oscillations_text(std::ostream& out, const analysis& result);
/// With the notes of the analysis after it (as \paragraph{Note.}).
void write_oscillations_latex(std::ostream& out, const analysis& result);
void write_oscillations_json(nlohmann::ordered_json& doc, const analysis& result);

} // namespace lagrange
