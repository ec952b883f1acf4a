// SPDX-License-Identifier: GPL-2.0-or-later
/** @file sweep.h
 *  Numeric modes over a grid of parameter values (`--sweep m=1e-6..1e6:1000000:log`),
 *  streamed: each point is handed to a callback and forgotten, so a sweep of any
 *  length runs in constant memory. */
#pragma once

#include "core/model.h"
#include "numeric/point_modes.h"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace lagrange {

/// One swept parameter: `count` values from `from` to `to`, evenly spaced, or
/// geometrically (`:log`; then both ends must be positive).
/// The point a fraction t ∈ [0, 1] of the way from `from` to `to`: evenly spaced, or
/// logarithmic in base 10 (so that a grid's powers of ten come out exact, 1e-3 and not
/// 0.0010000000000000002).
double between(double from, double to, double t, bool logarithmic);

/// The k-th of `count` values from `from` to `to` (k = 0 and k = count − 1 are the ends
/// exactly): the grid of --sweep and of an ensemble's --grid.
double grid_value(double from, double to, std::size_t count, bool logarithmic, std::size_t k);

struct sweep_axis {
    std::string name;
    std::size_t parameter = 0; ///< index into model::parameters
    double from = 0, to = 0;
    std::size_t count = 1;
    bool logarithmic = false;
    double at(std::size_t k) const; ///< the k-th value (exact ends)
};

/// Parses `NAME=FROM..TO:COUNT` or `NAME=FROM..TO:COUNT:log`; throws scene_error
/// located in the pseudo-file `--sweep` on bad input or an unknown parameter.
sweep_axis parse_sweep_axis(const std::string& text, const model& scene);

/// One point of a sweep, valid only during the callback.
struct sweep_row {
    std::size_t index = 0;                 ///< 0-based, the last axis varies fastest
    const double* parameter_values = nullptr; ///< every parameter, in model::parameters order
    /// The modes there, as the `numeric` stage gives them at the same values (point_modes):
    /// `omega` ascending, a negative entry the growth rate of an unstable mode
    /// (sign(ω²)·√|ω²|), `error` the bound on each, `eigenvalues` with G or C ≠ 0.
    const numeric_modes* modes = nullptr;
    std::string stability;                 ///< "stable", "marginal" or "unstable" (stability_of)
};

/// The modes at every point of the grid `axes` (Cartesian product, the last axis
/// fastest), by `path`, the one that the `numeric` stage takes (engine's
/// numeric_modes_path): gyroscopic, damped and constrained scenes alike. Parameters not
/// swept take their values from the scene's `values` points (and --values), later points
/// overriding earlier ones. Throws computation_error naming the point where the modes
/// cannot be computed, or a parameter that has no value.
void sweep_numeric_modes(const model& scene, point_modes& path, const std::vector<sweep_axis>& axes,
                         const std::function<void(const sweep_row&)>& each);

/// The number of points of the grid (throws computation_error above 1e10).
std::size_t sweep_size(const std::vector<sweep_axis>& axes);

} // namespace lagrange
