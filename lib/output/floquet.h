// SPDX-License-Identifier: GPL-2.0-or-later
/** @file floquet.h
 *  The `floquet` product (spec §5) in text, LaTeX and JSON: per point that solves the
 *  equations at every t and per `values` point, the period, the multipliers and whether
 *  they all lie on or inside the unit circle. Printers only; nothing is computed here. */
#pragma once

#include "engine/analysis.h"

#include <nlohmann/json_fwd.hpp>

#include <ostream>

namespace lagrange {

void write_floquet_text(std::ostream& out, const analysis& result);
void write_floquet_latex(std::ostream& out, const analysis& result);
/// Adds the key `floquet` to `doc` when the analysis has it.
void write_floquet_json(nlohmann::ordered_json& doc, const analysis& result);

} // namespace lagrange
