// SPDX-License-Identifier: GPL-2.0-or-later
/** @file floquet.h
 *  Floquet multipliers of the equations linearized about a point that solves them at
 *  every t, for an L periodic in t: the monodromy matrix Φ(T) of the first-order system
 *  over one period, integrated numerically, and its eigenvalues. */
#pragma once

#include "core/model.h"
#include "mechanics/equations_of_motion.h"
#include "mechanics/time_dependence.h"

#include <complex>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace lagrange {

/// The Floquet analysis about one point at one `values` point.
struct floquet_point {
    std::vector<GiNaC::ex> point;                       ///< the point (one value per coordinate)
    std::vector<std::pair<std::string, double>> values; ///< the parameter point, as written
    double period = 0;                                  ///< T, the smallest common period of the drive
    /// The eigenvalues of Φ(T), by modulus descending, then by imaginary part descending.
    std::vector<std::complex<double>> multipliers;
    bool stable = false; ///< every multiplier has |μ| ≤ 1 + floquet_tolerance
};

/// A multiplier with |μ| ≤ 1 + this counts as on or inside the unit circle. Φ(T) is
/// integrated to a relative tolerance of 1e-12 per step, far below this.
constexpr double floquet_tolerance = 1e-6;

/// The period of the t-dependence of `frequencies` (the ω of sin(ω t), cos(ω t)) at
/// `values`: 2π/ω₀ where every ω is an integer multiple of ω₀. Throws computation_error
/// if the frequencies are incommensurate there (then the system is not periodic).
double common_period(const std::vector<GiNaC::ex>& frequencies, const GiNaC::exmap& values);

/// The angular frequencies of the drive in a linearization about a point (each once, up to
/// sign), or those of L when the linearization does not depend on t.
std::vector<GiNaC::ex> drive_frequencies(const model& scene, const equations_of_motion& equations,
                                         const periodic_linearization& linear);

/// The denominator q of a ratio of two drive frequencies as a fraction p/q (exact, or within
/// 1e-9 for a floating value with q ≤ 64); nothing if it is not one (incommensurate).
std::optional<long> frequency_ratio_denominator(const GiNaC::ex& ratio);

/// The monodromy matrix of x' = A(t) x over [0, period], with A(t) given by `rate`
/// (dimension × dimension, row-major), by DOP853 at relative tolerance 1e-12.
std::vector<double> monodromy(std::size_t dimension, const std::function<void(double t, double* a)>& rate,
                              double period);

/// For each point of `time` and each `values` point of the scene: the multipliers of the
/// equations linearized about the point (time_dependence.h). Throws computation_error
/// when L is not periodic in t, a parameter has no value, or the mass matrix is singular.
std::vector<floquet_point> floquet_multipliers(const model& scene, const equations_of_motion& equations,
                                               const time_dependence_result& time);

} // namespace lagrange
