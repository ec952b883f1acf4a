// SPDX-License-Identifier: GPL-2.0-or-later
/** @file parser.h
 *  Recursive-descent parser of the scene language: one function per grammar rule. */
#pragma once

#include "scene/ast.h"
#include "scene/lexer.h"

#include <vector>

namespace lagrange {

/// Deepest nesting of parentheses, signs, powers and calls an expression may have.
constexpr int max_expression_depth = 200;

/// Parses a whole scene. Throws scene_error at the first syntax error.
scene_ast parse_scene(const std::vector<token>& tokens);

/// Parses one expression that fills a whole line (used for rule files and for
/// expressions given on the command line); `tokens` must end with newline, end.
struct parsed_rule {
    expr_ptr pattern;
    expr_ptr replacement;
    source_location where;
};
std::vector<parsed_rule> parse_rules(const std::vector<token>& tokens);

} // namespace lagrange
