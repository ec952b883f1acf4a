// SPDX-License-Identifier: GPL-2.0-or-later
/** @file sweep_output.h
 *  Streams a numeric sweep as it is computed: a text table (one line per point) or
 *  one JSON object whose `sweep.points` array is written element by element. */
#pragma once

#include "numeric/sweep.h"

#include <ostream>

namespace lagrange {

/// Runs the sweep and writes it to `out` (format "text" or "json"), point by point.
void write_sweep(std::ostream& out, const model& scene, const linearization_result& linear,
                 const std::vector<sweep_axis>& axes, const std::string& format);

} // namespace lagrange
