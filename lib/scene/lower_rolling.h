// SPDX-License-Identifier: GPL-2.0-or-later
/** @file lower_rolling.h
 *  The front end's part of `rolls W on ground [radius r] [axis x|y|z]` (our extension): a
 *  wheel W rolling without slipping on the ground, the plane through the origin across
 *  gravity, lowered into ordinary constraints from the wheel's pose. With k the unit vector
 *  up (against gravity), a the wheel's axis in the scene's frame and c its centre:
 *    the contact point    p = c − r (k − (k·a) a) / √(1 − (k·a)²)   (the rim's lowest point),
 *    `W_contact`          k·p = k·c − r √(1 − (k·a)²) = 0           (holonomic; left out when it
 *                                                                    holds identically),
 *    `W_roll_x`, `_y`     e·(ċ + ω × (p − c)) = 0 for two horizontal e (Pfaffian: the
 *                                                                    material contact point is at rest),
 *  with ω the wheel's angular velocity from the rates of its rotation sequence. Internal to
 *  the front end (not installed). */
#pragma once

#include "core/model.h"
#include "scene/ast.h"

#include <ginac/ginac.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace lagrange {

/// A `rolls` statement, kept until the bodies' attachments are composed.
struct rolling_request {
    name_ref body;
    std::optional<GiNaC::ex> radius; ///< `radius r`; else the disk's or ring's own
    std::optional<name_ref> axis;    ///< `axis y`; else the disk's or ring's own
    source_location where;           ///< the statement
};

/// The constraints of `request`, named `W_contact`, `W_roll_x` and `W_roll_y` (the
/// horizontal directions named after the scene axes they come from). Throws scene_error at
/// the body's name for an unknown body, a free body, one without orientation or position,
/// or a body that is not a disk or ring when no radius and axis are given; at the
/// statement when the scene has no gravity.
std::vector<constraint> rolling_constraints(const model& scene, const rolling_request& request);

/// Appends the constraints of `request` to the scene's, and its contact (the vectors the
/// constraints hold the contact point along) to the scene's `contacts`, after checking the statement
/// (`all`: every `rolls` line, for a body that rolls twice; a radius not positive) and the
/// names it makes: a constraint already declared, or a multiplier `lambda_NAME` that
/// `declared` says is taken.
void add_rolling_constraints(model& scene, const rolling_request& request, const std::vector<rolling_request>& all,
                             const std::function<bool(const std::string&)>& declared);

} // namespace lagrange
