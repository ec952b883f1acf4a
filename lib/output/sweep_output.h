// SPDX-License-Identifier: GPL-2.0-or-later
/** @file sweep_output.h
 *  Streams a numeric sweep as it is computed: a text table (one line per point) or
 *  one JSON object whose `sweep.points` array is written element by element. */
#pragma once

#include "numeric/sweep.h"

#include <ostream>

namespace lagrange {

/// Runs the sweep by `path` (engine's numeric_modes_path) and writes it to `out` (format
/// "text" or "json"), point by point: the swept values, ω₁ … ωₙ (a negative entry is the
/// growth rate of an unstable mode), their error bounds, and the stability at the point.
void write_sweep(std::ostream& out, const model& scene, point_modes& path, const std::vector<sweep_axis>& axes,
                 const std::string& format);

} // namespace lagrange
