// SPDX-License-Identifier: GPL-2.0-or-later
/** @file linear_system.h
 *  The linearized input–output system in text, LaTeX and JSON: the state-space matrices A
 *  and B (symbolic and at the `values` points) and the transfer functions H(s). */
#pragma once

#include "engine/analysis.h"
#include "output/print.h"

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>

namespace lagrange {

void write_linear_system_text(std::ostream& out, const analysis& result);
void write_linear_system_latex(std::ostream& out, const analysis& result);
/// Adds `state_space` ({"state", "inputs", "A", "B", "numeric"}) and `transfer`
/// ({"u -> q": "H(s)"}) to `doc` for the wanted products.
void write_linear_system_json(nlohmann::ordered_json& doc, const analysis& result);

/// H(s) as numerator/denominator, each in descending powers of s, in `syntax`.
std::string transfer_text(const transfer_function& h, const GiNaC::symbol& s, syntax how);

} // namespace lagrange
