// SPDX-License-Identifier: GPL-2.0-or-later
/** @file symmetries.h
 *  The symmetries in text, LaTeX and JSON: the conserved quantities, the Hamiltonian
 *  with Hamilton's equations, Routh's reduction and the steady motion. */
#pragma once

#include "engine/analysis.h"

#include <nlohmann/json.hpp>

#include <ostream>

namespace lagrange {

void write_symmetries_text(std::ostream& out, const analysis& result);
void write_symmetries_latex(std::ostream& out, const analysis& result);
/// Adds `conserved`, `hamiltonian`, `reduced` and `steady_motion` to `doc`, those computed.
void write_symmetries_json(nlohmann::ordered_json& doc, const analysis& result);

} // namespace lagrange
