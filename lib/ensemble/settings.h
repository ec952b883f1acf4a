// SPDX-License-Identifier: GPL-2.0-or-later
/** @file settings.h
 *  An ensemble's settings from what was asked for and what the scene says: the end time
 *  of every run, the tolerance, the random points, and what the analysis must compute for
 *  the measure. The policy lives here, so that every front end (the CLI, Python) applies
 *  it alike. */
#pragma once

#include "ensemble/ensemble.h"

#include <optional>
#include <set>
#include <stdexcept>

namespace lagrange {

/// What a front end was asked for; unset: the scene's, or the default.
struct ensemble_request {
    std::optional<double> until;     ///< the end time of every run
    std::optional<double> tolerance;
    std::size_t random = 0;          ///< > 0: this many random points instead of the grid
    std::uint64_t seed = 1;
    bool native = true;
};

/// A request that cannot be run as asked (exit 2 in the CLI): no end time, or one that is
/// not a positive number, or a seed without random points.
struct ensemble_request_error : std::invalid_argument {
    using std::invalid_argument::invalid_argument;
};

/// The settings of `request` for `scene` and `measure`. The end time: `until`, else one
/// period of the drive for floquet_stable, else the scene's `simulate until`; the
/// tolerance: `tolerance`, else the scene's, else 1e-9 (as `simulate` reads them). Throws
/// ensemble_request_error when there is no end time, it is not a positive number, or the
/// tolerance is outside 1e-14 … 1.
ensemble_settings ensemble_settings_for(const model& scene, const ensemble_measure& measure,
                                        const ensemble_request& request);

/// The products the analysis must compute for `measure`: the equations, and for
/// floquet_stable also `floquet` (the point that solves the equations at every t).
std::set<product> ensemble_products(const ensemble_measure& measure);

} // namespace lagrange
