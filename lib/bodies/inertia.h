// SPDX-License-Identifier: GPL-2.0-or-later
/** @file inertia.h
 *  The inertia of rigid bodies: tensors derived by integrating the density over the
 *  body (I_ij = ∫ρ (r² δ_ij − x_i x_j) dV about the centre of mass), principal moments
 *  and axes, L = I ω and T = ½ ωᵀ I ω, parallel axes and rotated frames, and the
 *  angular velocity from z-x-z Euler angles. */
#pragma once

#include "core/model.h"

#include <ginac/ginac.h>

#include <optional>
#include <string>
#include <vector>

namespace lagrange {

/// One variable of integration with its limits (which may depend on outer variables).
struct integration_limit {
    GiNaC::realsymbol variable;
    GiNaC::ex lower;
    GiNaC::ex upper;
};

/// One integral over a body, kept so that a report can show where a result comes
/// from (the homework's eqs. 16–35): ∫ρ·weight dV written in the body coordinates,
/// and the same integral in the coordinates of the region, deltas carried out.
struct body_integral {
    std::string quantity;              ///< "measure", "mass", "x", "y", "z" (first moments), "xx", "xy", ...
    GiNaC::ex density;                 ///< ρ in the body coordinates x, y, z (without the deltas)
    std::vector<GiNaC::ex> deltas;     ///< thin bodies: ρ carries δ(e) for each e here (e.g. x, y; r − R)
    GiNaC::ex weight;                  ///< 1, x_i, or r² δ_ij − x_i x_j, in x, y, z
    GiNaC::ex integrand;               ///< ρ·weight·Jacobian in the region's coordinates
    std::vector<integration_limit> limits; ///< innermost first
    GiNaC::ex value;
};

/// The inertia of one body about its centre of mass, in body axes.
struct inertia_result {
    std::string body;
    std::string coordinates;           ///< "cartesian", "cylindrical", "spherical", "ellipsoidal", "given"
    GiNaC::ex mass;
    GiNaC::ex density;                 ///< ρ in x, y, z (uniform bodies: M / measure), 0 if given by moments
    std::vector<GiNaC::ex> centre_of_mass; ///< in the frame the region was integrated in (0 if centred)
    GiNaC::matrix tensor{3, 3};        ///< about the centre of mass
    bool diagonal = true;              ///< body axes are principal axes
    std::vector<GiNaC::ex> principal;  ///< principal moments (body order if diagonal)
    std::optional<GiNaC::matrix> principal_axes; ///< columns; when known
    std::vector<body_integral> integrals;
    std::optional<GiNaC::matrix> about_origin; ///< parallel-axis shift to the origin, for a constant `at`
    std::vector<GiNaC::ex> omega;      ///< the ω components used below (the `omega` names, else ω1 ω2 ω3)
    std::vector<GiNaC::ex> angular_momentum; ///< L = I ω, body frame
    GiNaC::ex kinetic_energy;          ///< ½ ωᵀ I ω
};

/// Derives the inertia of `body` by integration (or takes the given moments or tensor,
/// moved to the centre of mass by parallel axes when given `about` a body point).
/// Throws computation_error when the density cannot be integrated exactly.
inertia_result derive_inertia(const rigid_body& body);

/// The tensor diag(I1, I2, I3) of three principal moments, in principal axes.
GiNaC::matrix diagonal_tensor(const std::vector<GiNaC::ex>& moments);

/// ∫_lower^upper f d(variable), exactly: polynomials in the variable, and products of
/// sin^a cos^b over a full period [0, 2π] or over [0, π] (closed-form moments via the
/// Beta function). Throws computation_error otherwise.
GiNaC::ex integrate_exactly(const GiNaC::ex& f, const GiNaC::realsymbol& variable, const GiNaC::ex& lower,
                            const GiNaC::ex& upper);

/// The inertia tensor about a point at `offset` from the centre of mass (parallel axes):
/// I + M (|a|² 1 − a aᵀ).
GiNaC::matrix shifted_tensor(const GiNaC::matrix& tensor, const GiNaC::ex& mass, const std::vector<GiNaC::ex>& offset);

/// R I Rᵀ: the tensor in a frame where the body axes are the columns of R.
GiNaC::matrix rotated_tensor(const GiNaC::matrix& tensor, const GiNaC::matrix& rotation);

/// R = Rz(φ) Rx(θ) Rz(ψ) (z-x-z Euler angles): body components to space components.
GiNaC::matrix euler_rotation(const GiNaC::ex& phi, const GiNaC::ex& theta, const GiNaC::ex& psi);

/// ω in the body frame from the entries of Rᵀ Ṙ (its skew part), derived with the total
/// time derivative of the scene; entries returned unsimplified.
std::vector<GiNaC::ex> body_angular_velocity(const GiNaC::matrix& rotation, const model& scene);

} // namespace lagrange
