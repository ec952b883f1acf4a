/** @file damping_output.h
 *  The damped small oscillations in text, LaTeX and JSON: the damping matrix C, the
 *  characteristic polynomial det(K + sC + s²M), its roots with their regimes, and
 *  proportional damping with the modal damping ratios. */
#pragma once

#include "engine/analysis.h"

#include <nlohmann/json.hpp>

#include <ostream>

namespace lagrange {

void write_damping_text(std::ostream& out, const model& scene, const damping_result& damping);
void write_damping_latex(std::ostream& out, const model& scene, const damping_result& damping);
/// Adds `damping` (the matrix C, rows of strings), `damped_characteristic` and
/// `proportional_damping` to `doc`.
void write_damping_json(nlohmann::ordered_json& doc, const model& scene, const damping_result& damping);

} // namespace lagrange
