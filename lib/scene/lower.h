// SPDX-License-Identifier: GPL-2.0-or-later
/** @file lower.h
 *  Semantic checks and lowering: from the syntax tree to the model. Names are
 *  resolved here, in the order they are declared. */
#pragma once

#include "algebra/simplify.h"
#include "core/model.h"
#include "scene/source.h"

#include <functional>
#include <set>
#include <string>

namespace lagrange {

/// Reads a file named by `use "..."` (relative to the scene's folder). The default
/// reads from disk; tests may substitute their own.
using file_reader = std::function<std::string(const std::string& path, const source_location& where)>;

/// Tokenizes, parses, checks and lowers a scene. Throws scene_error (with the
/// offending line attached) on bad input.
model load_model(const source_text& source, const file_reader& read_file = {});

/// Adds a `values` point given on the command line as `a=1,b=2.5`. An error is located in
/// the pseudo-file `origin`: the option or argument the text came from.
void add_values(model& scene, const std::string& text, const std::string& origin = "--values");

/// Sets initial values from the command line's `--initial` ("theta=0.1, phi'=0"), as an
/// `initial` line would: the entries given replace the scene's for those coordinates, and
/// the others keep the scene's (0 where it names none). An error is located in
/// the pseudo-file `origin`.
void add_initial(model& scene, const std::string& text, const std::string& origin = "--initial");

/// Parses a `want` list given on the command line as `equations,modes`.
std::set<product> parse_want_list(const std::string& text);

/// Parses a rules file; names in it resolve against `scene` (if given).
std::vector<rewrite_rule> load_rules(const source_text& source, const model* scene);

/// The rules embedded at build time (rules/*.rules), parsed once.
const std::vector<rewrite_rule>& embedded_rules();


/// The simplifier for a scene: canonical trig form in its coordinates, the
/// embedded rules and the scene's own (`use`), grouping by accelerations and velocities.
simplifier make_simplifier(const model& scene);

} // namespace lagrange
