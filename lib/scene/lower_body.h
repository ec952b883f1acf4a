// SPDX-License-Identifier: GPL-2.0-or-later
/** @file lower_body.h
 *  The front end's part of rigid bodies: their statements, and for those stated as §5
 *  writes them the checks of a given
 *  inertia tensor (symmetric, no negative moment, the triangle inequality, also about
 *  the centre of mass when given `about` a point), and the composition of `attached to`
 *  chains into positions and orientations in the scene's frame. Internal to the front
 *  end (not installed). */
#pragma once

#include "core/model.h"
#include "scene/ast.h"
#include "scene/lower_expression.h"
#include "scene/lower_rolling.h"

#include <ginac/ginac.h>

#include <cstddef>
#include <map>
#include <optional>
#include <string>

namespace lagrange {

/// What makes a body's given inertia impossible, and where it shows: a negative moment
/// (at that diagonal entry), the triangle inequality broken (at the tensor), or either
/// one about the centre of mass only (at `about`).
struct inertia_problem {
    enum class place { entry, tensor, about } at = place::tensor;
    std::size_t entry = 0; ///< for `entry`: the index of the moment (diagonal entry)
};

/// The message of `problem` for body `body`: of the statement itself, or of the values
/// that cause it (`at_values`, then it follows "these values make ").
std::string inertia_message(const inertia_problem& problem, const std::string& body, bool at_values);

/// The inertia tensor of a body given by `inertia`, about the point it was given at
/// (the centre of mass unless `about`): diag(I1, I2, I3) or the nine entries.
GiNaC::matrix given_tensor(const rigid_body& body);

/// Checks the inertia of an `inertia` body with the parameters replaced by `at` (empty:
/// as written, where only numbers can be checked): no moment negative, and the second
/// moments ½ tr(I) 1 − I positive semidefinite (the triangle inequality of the principal
/// moments), about the given point and, with `about`, about the centre of mass.
std::optional<inertia_problem> check_inertia(const rigid_body& body, const GiNaC::exmap& at);

/// Throws scene_error at the first entry (i, j) of a tensor whose mirror (j, i) differs.
void check_tensor_symmetric(const std::vector<GiNaC::ex>& entries, const body_statement& b);

/// The statements `body`, `omega` and `torque`, lowered against the names declared so
/// far (the statement lowering of lower.cpp derives from this).
class body_lowering : public expression_lowering {
protected:
    void lower_body(const statement& s);
    void lower_omega(const statement& s);
    void lower_torque(const statement& s);
    /// `rolls W on ground [radius r] [axis y]`: kept until the end of the scene.
    void lower_rolls(const statement& s);
    /// At the end of the scene: composes the `attached to` chains (resolve_attachments), then
    /// adds the constraints of the `rolls` lines, which need the bodies' poses.
    void resolve_body_attachments();

private:
    /// A constant of a body (dimension, mass): parameters and numbers; a number must be positive.
    GiNaC::ex body_constant(const expr_node& node, const char* what);
    rigid_body* body_named(const name_ref& n);
    void lower_given_inertia(const body_statement& b, rigid_body& body);
    GiNaC::ex lower_density(const expr_node& node, const rigid_body& body);

    std::map<std::size_t, name_ref> attachments_; ///< body index → the name after `attached to`
    std::vector<rolling_request> rolling_;        ///< the `rolls` lines, in order
};

/// Composes each attached body's `at` and orientation with those of the body it is
/// attached to, parents first: r = r_A + R_A at, R = R_A R_own. `attachments` maps a
/// body's index to the name after `attached to`. Throws scene_error at that name for an
/// unknown body, a cycle of attachments, or a free body (one with `omega`) on either side.
void resolve_attachments(model& scene, const std::map<std::size_t, name_ref>& attachments);

} // namespace lagrange
