// SPDX-License-Identifier: GPL-2.0-or-later
/** @file pictures.h
 *  The stages behind the pictures of motion, for the command line and Python alike: what
 *  `animate` draws for a scene (a free body's Poinsot construction, or else the motion of its
 *  points) and the Poincaré section of `poincare`. */
#pragma once

#include "algebra/budget.h"
#include "engine/analysis.h"
#include "ensemble/poincare.h"
#include "numeric/animation.h"
#include "core/model.h"

namespace lagrange {

/// The frames of `scene`: for a free body (no coordinates, a body with `omega`) the first
/// torque-free body's Poinsot construction from the `euler` stage; otherwise the points'
/// motion from the `equations` stage. Throws computation_error when neither can be drawn.
animation_frames animate_scene(const model& scene, const animation_settings& settings, const budget_limits& limits);

/// The phase portrait that the report draws for a scene of one coordinate (from `result`, its
/// analysis with the equations), where one can be drawn: no constraints or forces, an L that
/// does not depend on t, and numbers for the parameters; otherwise none.
std::optional<phase_portrait> report_phase_portrait(const model& scene, const analysis& result);

/// The section of `scene` at `settings`: the `equations` stage, and the `equilibrium` stage
/// where it succeeds (it gives the energy's minimum and the well the orbits start in; a scene
/// whose equilibria are not found still has a section). Throws as compute_poincare.
poincare_result poincare_scene(const model& scene, const poincare_section& section, const poincare_settings& settings,
                               const budget_limits& limits);

} // namespace lagrange
