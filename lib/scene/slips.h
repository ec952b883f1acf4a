// SPDX-License-Identifier: GPL-2.0-or-later
/** @file slips.h
 *  Likely slips in a valid scene, found after lowering: each a warning, never an error.
 *  Internal to the front end (not installed). */
#pragma once

#include "core/model.h"

#include <optional>

namespace lagrange {

/// `T = 1/2*m*x^2` (the prime forgotten) is a valid scene with no kinetic energy for x: a
/// warning at `kinetic_line` (the first `T` line) when the `T` lines have no velocity at all,
/// or, with no points or bodies to add kinetic energy, none of some coordinate.
std::optional<scene_warning> kinetic_energy_slip(const model& scene, const source_location& kinetic_line);

} // namespace lagrange
