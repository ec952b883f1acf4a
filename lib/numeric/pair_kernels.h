// SPDX-License-Identifier: GPL-2.0-or-later
/** @file pair_kernels.h
 *  The closed form of the modes of one and two coordinates, the kernels behind
 *  compiled_modes' fastest route: W = ω² from a W² − b W + c = 0 (two coordinates) or
 *  W = V/T (one) in double-double, with an error bound beside, on the lanes of a block
 *  as expression_program::run_batch leaves them. Also the step from W and its bound to
 *  ω², ω and ω's error that every route of compiled_modes takes. */
#pragma once

#include "program/double_double.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace lagrange {

/// What the closed form does with one lane of a block.
enum class lane_use : unsigned char {
    skip, ///< nothing (another route computes it)
    use,  ///< checks T, writes the results
};

/// The constants of the a priori route (see compiled_modes::set_a_priori_bounds).
struct a_priori_constants {
    double omega_bound = 0;
    bool zero_root = false;
};

/// Relative error of √m given an absolute error `dw` of m > dw.
inline double root_relative_error(double dw, double m)
{
    double x = dw / m;
    return x / (1 + std::sqrt(std::max(0.0, 1 - x)));
}

/// Fills ω², ω and the error of one mode from ω² = w (rounded to double) with absolute
/// error bound dw; `extra` is added to a relative error (rounding of the root).
inline void set_frequency(double w, double dw, double extra, double& w2, double& omega, double& error)
{
    double m = std::abs(w);
    if (m <= dw || m == 0) {
        w2 = 0;
        omega = 0;
        error = std::sqrt(dw);
        return;
    }
    w2 = w;
    omega = std::copysign(std::sqrt(m), w);
    error = (root_relative_error(dw, m) + extra) * (1 + 1e-6);
}

/// The two-coordinate closed form on `count` lanes of a block of B lanes (B = 1, or
/// expression_program::batch_size): output k's hi at o[k][j], lo at [B + j] and, without
/// a priori `constants` (null), the bounded run's value and error at [2B + j], [3B + j];
/// `scale` takes the running bound from double to double-double. Lane j's ω², ω and error
/// go to [2j], [2j + 1], its modes (may be null; T-normalized columns) to [4j … 4j + 3],
/// where use[j] is not skip (`use` null: every lane). T must have been checked positive
/// definite. The FMA version where fma_kernels(); the same numbers either way.
void pair_block(const double* const* o, std::size_t B, std::size_t count, double scale,
                const a_priori_constants* constants, const lane_use* use, double* w2, double* w, double* error,
                double* modes);

/// The one-coordinate closed form of one lane: W = V/T in double-double, its bound from
/// the bounded values scaled by `scale`; `mode` (may be null) gets 1/√T.
void single_lane(double_double T, double_double V, bounded_double T_bounded, bounded_double V_bounded, double scale,
                 double& w2, double& w, double& error, double* mode);

} // namespace lagrange
