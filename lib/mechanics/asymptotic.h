// SPDX-License-Identifier: GPL-2.0-or-later
/** @file asymptotic.h
 *  The leading behaviour of the closed-form frequencies, modes and normal
 *  coordinates as a parameter or the scene's ratio goes to 0 or ∞, and the
 *  beats between modes whose frequencies agree to leading order. */
#pragma once

#include "core/model.h"
#include "mechanics/modes.h"

#include <ginac/ginac.h>

#include <cstddef>
#include <string>
#include <vector>

namespace lagrange {

/// Two modes whose frequencies agree to leading order: they beat.
struct beat {
    std::size_t lower = 0, upper = 0; ///< indices of the two modes (ascending frequency)
    GiNaC::ex difference;             ///< ω_upper − ω_lower to leading order
    GiNaC::ex period;                 ///< 2π/(ω_upper − ω_lower) to leading order
};

struct asymptotic_result {
    std::string label; ///< "rho -> 0" or "rho -> oo"
    std::vector<GiNaC::ex> frequencies;        ///< ω², the leading term times (1 + corrections) until they differ
    std::vector<std::vector<GiNaC::ex>> modes;
    std::vector<GiNaC::ex> normal_coordinates; ///< leading term of each coefficient
    std::vector<beat> beats;                   ///< pairs with the same leading ω²
    /// Each ω² as {leading term, 1, correction, …} (ω² = leading·(1 + correction + …)),
    /// for printing in series order; empty where no series was found.
    std::vector<std::vector<GiNaC::ex>> frequency_series;
};

/// The leading behaviour of the frequencies and modes in the scene's `limit`.
asymptotic_result asymptotic_limit(const model& scene, const modes_result& modes);

} // namespace lagrange
