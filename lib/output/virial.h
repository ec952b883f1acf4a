// SPDX-License-Identifier: GPL-2.0-or-later
/** @file virial.h
 *  The virial product (numeric/virial.h) as text, LaTeX and JSON; its report section is
 *  declared in report_sections.h. */
#pragma once

#include "engine/analysis.h"

#include <nlohmann/json.hpp>

#include <ostream>

namespace lagrange {

void write_virial_text(std::ostream& out, const analysis& result);
void write_virial_latex(std::ostream& out, const analysis& result);
/// "virial": {"T": ⟨T⟩, "V": ⟨V⟩, "over": [t0, t1]} (and "quadrature_error" when estimated).
void write_virial_json(nlohmann::ordered_json& doc, const analysis& result);

} // namespace lagrange
