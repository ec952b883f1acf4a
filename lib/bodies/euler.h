// SPDX-License-Identifier: GPL-2.0-or-later
/** @file euler.h
 *  Euler's equations of a free rigid body, I ω̇ + ω × I ω = N, and torque-free motion in
 *  closed form: symmetric bodies symbolically, asymmetric ones with Jacobi elliptic
 *  functions at numbers, Poinsot's construction, and the stability of rotation about
 *  each principal axis. */
#pragma once

#include "bodies/inertia.h"
#include "core/model.h"

#include <ginac/ginac.h>

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace lagrange {

/// Euler's equations of a free body and their torque-free solutions.
struct euler_result {
    std::string body;
    std::vector<GiNaC::ex> omega, rates; ///< w1 w2 w3 and w1_dot ...
    std::vector<GiNaC::ex> moments;      ///< principal moments used (I1, I2, I3)
    std::vector<GiNaC::ex> equations;    ///< I ω̇ + ω × I ω − N, each = 0 (general form if not principal)
    std::vector<GiNaC::ex> principal_equations; ///< in principal axes (set only if the tensor is not diagonal)
    GiNaC::ex kinetic_energy;            ///< ½ Σ I_i ω_i²
    GiNaC::ex angular_momentum_squared;  ///< Σ I_i² ω_i²
    bool torque_free = true;

    /// Symmetric body: ω_a constant, the others rotating at Ω.
    struct symmetric_solution {
        std::size_t axis = 2;            ///< index of the symmetry axis
        GiNaC::ex precession;            ///< Ω = (I_a − I_t) ω_a / I_t
        std::vector<GiNaC::ex> omega;    ///< ω(t)
        std::vector<GiNaC::ex> constants; ///< the symbols or numbers ω(0)
        GiNaC::ex time;                  ///< the symbol t in ω(t)
    };
    std::optional<symmetric_solution> symmetric;

    /// Asymmetric body at numbers: the Jacobi elliptic solution.
    struct elliptic_solution {
        std::array<double, 3> moments{};   ///< I1 I2 I3 (body order)
        std::array<double, 3> initial{};   ///< ω(0)
        std::array<std::size_t, 3> roles{}; ///< body axes carrying cn, sn, dn
        std::array<double, 3> amplitudes{}; ///< of cn, sn, dn (signed)
        double rate = 0;                   ///< λ: the argument is λ t + u0
        double phase = 0;                  ///< u0
        double modulus = 0;                ///< k
        double period = 0;                 ///< 4K(k)/λ
        double energy = 0;                 ///< T
        double momentum_squared = 0;       ///< |L|²
        std::array<double, 3> evaluate(double t) const; ///< ω(t)
    };
    std::optional<elliptic_solution> elliptic;

    /// Poinsot's construction at numbers.
    struct poinsot_construction {
        std::array<double, 3> ellipsoid_axes{}; ///< semi-axes of ωᵀ I ω = 2T: √(2T/I_i)
        double plane_distance = 0;              ///< 2T/|L|: the invariable plane's distance from the centre
        std::vector<std::array<double, 3>> polhode; ///< ω(t) over one period
        std::array<double, 3> moments{};        ///< I1 I2 I3 at the values (body order)
        std::array<double, 3> initial{};        ///< ω(0) in the body axes
        double period = 0;                      ///< of the polhode (0: ω is constant)
    };
    std::optional<poinsot_construction> poinsot;

    /// Rotation about each principal axis: "stable", "unstable" (intermediate), "marginal" or "unknown".
    std::vector<std::string> stability;
};

/// Euler's equations of `body` (which must have `omega`), derived from
/// dL/dt|space = dL/dt|body + ω × L = N, and the torque-free solution where one
/// exists. `values`: a parameter point for the numeric elliptic solution (needs the
/// scene's initial ω as well).
euler_result derive_euler(const rigid_body& body, const inertia_result& inertia,
                          const std::optional<initial_state>& initial, const GiNaC::exmap& values);

} // namespace lagrange
