// SPDX-License-Identifier: GPL-2.0-or-later
/** @file constraints.h
 *  Constraints in text, LaTeX and JSON: each constraint with its kind and integrability
 *  (shown with the equations of motion), the multipliers λ and the forces the constraints
 *  exert on the points. */
#pragma once

#include "engine/analysis.h"

#include <nlohmann/json.hpp>

#include <ostream>

namespace lagrange {

void write_constraints_text(std::ostream& out, const analysis& result);
void write_constraints_latex(std::ostream& out, const analysis& result);
/// Adds `constraints` ({NAME: {"kind", "equation", "integrable"}} and `constraints_integrable`)
/// with the equations, `multipliers` ({NAME: expr}) and `constraint_forces`
/// ({NAME: {POINT: [components]}}) to `doc`.
void write_constraints_json(nlohmann::ordered_json& doc, const analysis& result);

} // namespace lagrange
