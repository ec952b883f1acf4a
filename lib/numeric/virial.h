// SPDX-License-Identifier: GPL-2.0-or-later
/** @file virial.h
 *  The virial product: the time averages of the kinetic and potential energy over a
 *  simulation, ⟨T⟩ and ⟨V⟩, which the virial theorem relates (2⟨T⟩ = n⟨V⟩ for a
 *  potential homogeneous of degree n, over a period or in the long-time limit). */
#pragma once

#include "core/model.h"
#include "mechanics/lagrangian.h"
#include "numeric/simulation.h"

#include <optional>

namespace lagrange {

/// ⟨T⟩ and ⟨V⟩ over [from, to], the span the simulation covered. Energies in the
/// scene's units (none are assumed), times in its time unit.
struct virial_result {
    double kinetic = 0;   ///< ⟨T⟩ = (1/(t1 − t0)) ∫ T dt [E]
    double potential = 0; ///< ⟨V⟩ [E]
    double from = 0, to = 0; ///< the span averaged over [τ]
    /// The quadrature's error in ⟨T⟩ and ⟨V⟩, estimated (the trapezoid rule on the
    /// simulation's output times, against every other sample: Richardson); none for an
    /// odd number of output intervals.
    std::optional<double> quadrature_error;
};

/// The averages of T and V as the scene built them (points, springs, gravity, `T` and `V`
/// lines), at the simulation's parameter point, along its trajectory. Throws
/// computation_error for a trajectory of fewer than 3 output times or a span of zero.
virial_result time_averages(const model& scene, const lagrangian_result& lagrangian, const simulation_result& motion);

} // namespace lagrange
