// SPDX-License-Identifier: GPL-2.0-or-later
/** @file poinsot.h
 *  Poinsot's construction of a torque-free body's motion, in space: the inertia ellipsoid
 *  ρᵀ I ρ = 1 (body axes) turned by the body's orientation R(t), rolling without slipping on
 *  the invariable plane, which is normal to L at the distance √(2T)/|L| from the centre.
 *  The point of contact is ρ = R ω/√(2T), on the instantaneous axis; the polhode is its
 *  path on the ellipsoid (body axes), the herpolhode its path on the plane (space).
 *
 *  The space axes are chosen with z opposite to L, so that the plane is z = −√(2T)/|L| and
 *  the ellipsoid rests on it; at t = 0 they are the body axes turned by the smallest
 *  rotation that takes L to −z. Euler's equations and the orientation's quaternion
 *  (q̇ = ½ q ⊗ ω) are integrated together by DOP853 and read from its dense output. */
#pragma once

#include "bodies/euler.h"

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace lagrange {

struct poinsot_settings {
    double until = 0;        ///< length of the run (0: three periods of the polhode, or 10 if it has none)
    double step = 0;         ///< time between frames (0: a 600th of the run)
    double tolerance = 1e-11; ///< DOP853's relative tolerance per step
};

struct poinsot_motion {
    std::string body;
    std::array<double, 3> moments{};   ///< I1 I2 I3 (principal, body order)
    std::array<double, 3> semi_axes{}; ///< of the inertia ellipsoid ρᵀIρ = 1: 1/√I_k
    double energy = 0;                 ///< T = ½ ωᵀIω
    double momentum = 0;               ///< |L| = |Iω|
    double plane_distance = 0;         ///< √(2T)/|L|: the invariable plane is z = −plane_distance
    double period = 0;                 ///< of the polhode (0: ω is constant)
    std::vector<double> times;
    std::vector<std::array<double, 3>> omega;    ///< ω in body axes, at each time
    std::vector<std::array<double, 9>> rotation; ///< body → space (row-major), at each time
    std::vector<std::array<double, 3>> contact;  ///< R ω/√(2T) in space: the herpolhode
    std::vector<std::array<double, 3>> polhode;  ///< ω/√(2T) in body axes over one period, closed
    std::string method;
    std::size_t steps = 0;
};

/// The construction for `body` (an `euler` result that carries `poinsot`: torque-free, at
/// numbers, with ω(0) ≠ 0). Throws computation_error otherwise, and for more than 10 million
/// frames; integration errors pass through.
poinsot_motion compute_poinsot(const euler_result& body, const poinsot_settings& settings);

} // namespace lagrange
