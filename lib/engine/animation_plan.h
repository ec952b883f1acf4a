// SPDX-License-Identifier: GPL-2.0-or-later
/** @file animation_plan.h
 *  What `lagrange animate` draws for a scene: a free body's Poinsot construction, or else
 *  the motion of its points (numeric/animation.h), with the stages each needs. */
#pragma once

#include "algebra/budget.h"
#include "numeric/animation.h"
#include "core/model.h"

namespace lagrange {

/// The frames of `scene`: for a free body (no coordinates, a body with `omega`) the first
/// torque-free body's Poinsot construction from the `euler` stage; otherwise the points'
/// motion from the `equations` stage. Throws computation_error when neither can be drawn.
animation_frames animate_scene(const model& scene, const animation_settings& settings, const budget_limits& limits);

} // namespace lagrange
