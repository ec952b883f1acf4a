// SPDX-License-Identifier: GPL-2.0-or-later
/** @file check_bodies.h
 *  Self-verification of the rigid bodies' results by routes that share nothing with
 *  their symbolic derivation: each body's mass, centre of mass and inertia tensor by
 *  tensor-product Gauss–Legendre cubature over the region as described here (its own
 *  parametrization of each shape, the density evaluated numerically), or, for a body
 *  given by its tensor, by the parallel-axis shift of the numbers given; Euler's
 *  equations against I ω̇ + ω × I ω − N formed from that tensor, and the torque-free
 *  solutions against a numeric integration of Euler's equations (Boost.Odeint). */
#pragma once

#include "bodies/euler.h"
#include "bodies/inertia.h"
#include "core/model.h"
#include "verify/verify.h"

#include <Eigen/Core>

#include <array>
#include <optional>
#include <vector>

namespace lagrange {

/// The inertia of a body at numbers, computed numerically.
struct numeric_body {
    double mass = 0;
    double measure = 0;                    ///< length, area or volume of the region (0: given by its tensor)
    std::array<double, 3> first_moments{}; ///< ∫ρ x_k dV about the region's centre, body axes
    std::array<double, 3> centre_of_mass{}; ///< from the region's centre, body axes
    double extent = 0;                     ///< the largest |x| of the region (the length scale of the body)
    Eigen::Matrix3d tensor = Eigen::Matrix3d::Zero(); ///< ∫ρ (r² δ_ij − x_i x_j) dV about the centre of mass
};

/// The inertia of `body` with the parameters at `at`: for a shape or region, by
/// tensor-product Gauss–Legendre cubature (Boost's tables; a trapezoidal rule over full
/// turns) of the density over the region in the coordinates that suit it, thin bodies
/// over their curve or surface; for a body given by its moments or tensor, the numbers
/// given moved to the centre of mass by I − M (|a|² 1 − a aᵀ). Nothing when a
/// dimension is not a positive number there, or the mass or density is not real.
std::optional<numeric_body> numeric_inertia(const rigid_body& body, const GiNaC::exmap& at);

/// The entries of `list` at `at` as doubles; nothing when one is not a real number.
std::optional<std::vector<double>> numbers_at(const std::vector<GiNaC::ex>& list, const GiNaC::exmap& at);

/// M (|a|² 1 − a aᵀ): the parallel-axis term of a mass M at offset a.
Eigen::Matrix3d parallel_axis(double mass, const Eigen::Vector3d& a);

/// Checks every inertia result and every Euler result given (null: not computed) at
/// seeded parameter points (each `values` line's, then random ones in [1/2, 2]): the
/// entries `inertia` and `euler`. Throws computation_error "verification failed: the
/// inertia: …" or "verification failed: Euler's equations: …" naming the entry, the
/// body and the point when a result disagrees with its numeric reference.
std::vector<verification_entry> verify_bodies(const model& scene, const std::vector<inertia_result>* inertia,
                                              const std::vector<euler_result>* euler);

} // namespace lagrange
