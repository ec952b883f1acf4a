// SPDX-License-Identifier: GPL-2.0-or-later
/** @file body_family.h
 *  The rigid-body family, one file per concept, each with its text, LaTeX, JSON and report
 *  writers: inertia.cpp (`inertia`), euler.cpp (`euler`) and tops.cpp (the heavy top, shown
 *  with `equations` and `inertia`). bodies.cpp calls them in the documents' order
 *  (bodies_output.h, write_body_sections) and holds what they share. Internal to output/. */
#pragma once

#include "output/format.h"
#include "output/print.h"
#include "output/report_sections.h"

#include <nlohmann/json_fwd.hpp>

#include <ostream>
#include <string>
#include <vector>

namespace lagrange {

void write_inertia_text(std::ostream& out, const analysis& result);
void write_inertia_latex(std::ostream& out, const analysis& result);
/// The key `inertia` (spec §4, with extensions).
void write_inertia_json(nlohmann::ordered_json& doc, const analysis& result);
void write_inertia_section(report_writer& w);

void write_euler_text(std::ostream& out, const analysis& result);
void write_euler_latex(std::ostream& out, const analysis& result);
/// The key `euler` (spec §4, with extensions).
void write_euler_json(nlohmann::ordered_json& doc, const analysis& result);
void write_euler_section(report_writer& w);

void write_tops_text(std::ostream& out, const analysis& result);
void write_tops_latex(std::ostream& out, const analysis& result);
/// The key `top`.
void write_tops_json(nlohmann::ordered_json& doc, const analysis& result);
void write_tops_section(report_writer& w);

/// Each expression printed in syntax `s`.
std::vector<std::string> printed(const std::vector<GiNaC::ex>& v, syntax s, const term_order& order = {});
/// Each expression as a JSON string (plain syntax).
nlohmann::ordered_json json_strings(const std::vector<GiNaC::ex>& v, const term_order& order = {});
/// A body's name as LaTeX math, for the report's prose.
std::string body_title(const std::string& name);
/// A displayed line of math; one wider than the page is scaled down to the page width.
std::string latex_line(const std::string& math);

} // namespace lagrange
