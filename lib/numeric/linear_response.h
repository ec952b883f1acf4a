// SPDX-License-Identifier: GPL-2.0-or-later
/** @file linear_response.h
 *  The linearized input–output system at numbers: A and B of the state-space form at each
 *  `values` point, and the frequency response H(iω) of one input to one coordinate over a
 *  range of drive frequencies (a Bode diagram's magnitude and phase). */
#pragma once

#include "core/model.h"
#include "mechanics/linearization.h"
#include "mechanics/state_space.h"

#include <Eigen/Dense>

#include <complex>
#include <string>
#include <utility>
#include <vector>

namespace lagrange {

/// A and B at one `values` point.
struct state_space_point {
    std::vector<std::pair<std::string, double>> values; ///< the parameters given on the line
    Eigen::MatrixXd a, b;
    /// The eigenvalues of A (Eigen's real Schur form), ascending by imaginary part, then real part.
    std::vector<std::complex<double>> eigenvalues;
    /// From the eigenvalues, to 1e-9 of the largest: "stable" (every Re s < 0), "marginal"
    /// (the largest Re s is 0: zero or imaginary eigenvalues, no mode grows exponentially) or
    /// "unstable" (some Re s > 0).
    std::string stability;
};

/// A and B at every `values` point that gives a value to each parameter they use (a point
/// that does not is left out). Throws computation_error when an entry is not finite.
std::vector<state_space_point> state_space_at_values(const model& scene, const state_space_result& system);

/// The frequency response of one input to one coordinate at one `values` point.
struct frequency_response {
    std::string input, output;
    std::vector<std::pair<std::string, double>> values;
    std::vector<double> omega;                ///< drive frequencies, ascending
    std::vector<std::complex<double>> gain;   ///< H(iω)
    std::vector<double> magnitude;            ///< |H(iω)|
    std::vector<double> magnitude_db;         ///< 20 log₁₀ |H(iω)|
    std::vector<double> phase_degrees;        ///< arg H(iω), unwrapped along ω, starting in (−180°, 180°]
    /// The largest |H| on the grid, refined by golden-section search between its neighbours
    /// (NaN when it lies at an end of the range).
    double peak_omega = 0, peak_magnitude = 0;
};

struct response_settings {
    double from = 0, to = 0; ///< 0: chosen from the system's eigenvalues (a decade either side)
    std::size_t points = 400;
    bool logarithmic = true;
};

/// H(iω) = e_outputᵀ (K − ω²M + iω(C − G))⁻¹ B_q e_input by complex LU at each ω, at
/// `point`, or when it is null at every `values` line overlaid in order (later ones win). Throws computation_error for an unknown
/// input or coordinate name, a parameter without a value, or a singular system at some ω
/// (an undamped resonance on the grid).
frequency_response frequency_response_of(const model& scene, const linearization_result& linear,
                                         const state_space_result& system, const std::string& input,
                                         const std::string& output, const response_settings& settings,
                                         const value_point* point = nullptr);

} // namespace lagrange
