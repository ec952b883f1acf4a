// SPDX-License-Identifier: GPL-2.0-or-later
/** @file lower_constraint.h
 *  The front end's part of `constraint NAME: lhs = rhs`: the kind of a constraint
 *  (holonomic, Pfaffian, or neither: an error) and the check that no constraint is
 *  redundant or inconsistent with the others. Internal to the front end (not installed). */
#pragma once

#include "core/model.h"
#include "scene/ast.h"

#include <ginac/ginac.h>

#include <string>
#include <vector>

namespace lagrange {

/// The constraint `name` with f = lhs − rhs, classified: holonomic when f has no
/// velocities, Pfaffian when it is linear in them; otherwise a scene_error at `where`
/// (the left-hand side).
constraint classify_constraint(const name_ref& name, const GiNaC::ex& f, const source_location& where,
                               const model& scene);

/// Throws scene_error at the first constraint whose velocity form depends on those before
/// it (at every one of a few random points): redundant when it follows from them,
/// inconsistent when it contradicts them; and at the one that leaves no degree of freedom.
void check_constraints(const model& scene);

/// `independent q2, q4'`: the coordinates named without `'` and the speeds named with it, by
/// index; `line_text` is the statement's line, kept for errors found later.
independent_request lower_independent(const statement& s, const model& scene, const std::string& line_text);

} // namespace lagrange
