// SPDX-License-Identifier: GPL-2.0-or-later
/** @file lower_expression.h
 *  What lowering statements (lower.cpp) and rules files share: the model under
 *  construction, the table of declared names, and expressions lowered against it.
 *  Internal to the front end (not installed); lower.h is its API. */
#pragma once

#include "core/model.h"
#include "scene/ast.h"
#include "scene/source.h"

#include <ginac/ginac.h>

#include <cstddef>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace lagrange {

/// Names no declaration may take: the statement keywords and the words of
/// statements, `t`, `Pi`, `pi`, `oo`, `dot`, `T`, `V`, `L`.
const std::set<std::string>& reserved_names();

/// What a name in an expression stands for.
struct name_entry {
    enum class kind { parameter, coordinate, shorthand, ratio, angular, input } name_kind;
    GiNaC::ex value;        ///< the symbol, or a shorthand's expression
    std::size_t index = 0;  ///< coordinate index
    source_location declared;
};

/// Where an expression stands decides what it may contain.
struct expr_context {
    const char* what;              ///< "a position", "a value", ... for messages
    bool coordinates = true;       ///< q
    bool velocities = false;       ///< q'
    bool parameters = true;
    bool time = true;              ///< t
    bool wildcards = false;        ///< $0 (rules)
    bool angular = false;          ///< w1 of `omega B (w1, w2, w3)` (torques)
    bool inputs = false;           ///< u of `input u` (forces)
};

/// Lowers expressions against a table of names: those declared so far (statements),
/// or those of a scene (rules files and `--values`).
class expression_lowering {
public:
    /// Lowering of expressions for rule files and `--values`: names of `scene` resolve.
    void adopt_names(const model& scene);

    /// `node` as an expression; throws scene_error where it breaks `context` or a limit.
    GiNaC::ex lower(const expr_node& node, const expr_context& context);

    /// A vector's components, padded with zeros to three.
    std::vector<GiNaC::ex> lower_vector(const vector_expr& v, const expr_context& context);

protected:
    /// Checks that `n` may name a new `what` (not reserved, not declared before).
    void declare_name(const name_ref& n, const char* what);

    model scene_;
    std::map<std::string, name_entry> names_;
    std::vector<coordinate> coordinates_;

private:
    GiNaC::ex lower_name(const expr_node& node, const expr_context& context);
    bool has_position(const GiNaC::ex& e) const;
    bool has_velocity(const GiNaC::ex& e) const;
    GiNaC::ex lower_velocity(const expr_node& node, const std::string& name, const expr_context& context);
    GiNaC::ex lower_power(const expr_node& node, const expr_context& context);
    GiNaC::ex lower_call(const expr_node& node, const expr_context& context);
};

/// Runs `body`, attaching the offending line of `source` to any scene_error.
template <typename F>
auto with_source(const source_text& source, F body) -> decltype(body())
{
    try {
        return body();
    } catch (scene_error& error) {
        attach_line(error, source);
        throw;
    }
}

} // namespace lagrange
