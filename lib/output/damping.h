// SPDX-License-Identifier: GPL-2.0-or-later
/** @file damping.h
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

/// The damped eigenvalues of one numeric entry (`n.damped`): a line with the stability,
/// then each real s and each conjugate pair re ± im·i with its error, damping ratio and mode
/// (the lower member of a pair has the conjugate mode), and whether the damping is
/// proportional there.
void write_damped_eigenvalues_text(std::ostream& out, const numeric_modes& n);
void write_damped_eigenvalues_latex(std::ostream& out, const numeric_modes& n);
/// Adds `eigenvalue_error`, `damping_ratio` (null for s = 0), `damped_modes` (one vector of
/// [re, im] per eigenvalue, largest component 1), `damped_mode_backward_error` and
/// `proportional_damping` to a numeric entry's JSON (which already holds `eigenvalues` and
/// `stability`).
void write_damped_eigenvalues_json(nlohmann::ordered_json& entry, const numeric_modes& n);

/// Whether the printed normal modes are those of the undamped system, not the motion:
/// C ≠ 0 (or, when the damping stage did not run, the scene has dissipation or dampers).
bool modes_are_undamped(const analysis& result);

} // namespace lagrange
