// SPDX-License-Identifier: GPL-2.0-or-later
/** @file bodies_output.h
 *  The rigid-body products of an analysis (`inertia`, `euler`) in text, LaTeX and JSON.
 *  Called by the document printers; they take results and never compute mechanics. */
#pragma once

#include "engine/analysis.h"

#include <nlohmann/json_fwd.hpp>

#include <ostream>

namespace lagrange {

void write_bodies_text(std::ostream& out, const analysis& result);
void write_bodies_latex(std::ostream& out, const analysis& result);
/// Adds the keys `inertia` and `euler` (spec §4, with extensions) to `doc`.
void write_bodies_json(nlohmann::ordered_json& doc, const analysis& result);

} // namespace lagrange
