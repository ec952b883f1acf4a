// SPDX-License-Identifier: GPL-2.0-or-later
/** @file lagrangian.h
 *  The Lagrangian L = T − V from energies, points, gravity and springs, split by degree
 *  in the velocities into L2 + L1 + L0. */
#pragma once

#include "algebra/calculus.h"
#include "algebra/simplify.h"
#include "core/model.h"

#include <ginac/ginac.h>

#include <memory>
#include <vector>

namespace lagrange {

struct harmonic_lagrangian;

struct lagrangian_result {
    GiNaC::ex kinetic_built;   ///< T as built from points and `T` lines, before simplification
    GiNaC::ex potential_built; ///< V as built from gravity, springs and `V` lines
    /// T as built, but with each body's ½ ωᵀ I ω replaced by ½ tr(Ṙ J Ṙᵀ) (J = ½ tr(I) 1 − I),
    /// which does not go through ω: the reference of the numeric checks.
    GiNaC::ex kinetic_reference;
    GiNaC::ex kinetic;         ///< L2, the part of L quadratic in the velocities, simplified
    /// The effective potential U = −L0, minus the part of L free of velocities: V, less the
    /// velocity-free part of T where positions move with t or `T` lines have one (a rotating
    /// frame's centrifugal term). Equilibria and the stiffness matrix come from it.
    GiNaC::ex potential;
    /// L1 = Σ aᵢ(q) q̇ᵢ, the part of L linear in the velocities (magnetic terms, Coriolis terms
    /// of a moving frame); 0 when T is a quadratic form and V free of velocities.
    GiNaC::ex gyroscopic;
    GiNaC::ex lagrangian;      ///< L simplified
    GiNaC::ex lagrangian_canonical; ///< L in canonical trig form (expanded): what the equations use
    bool split = true;         ///< false if L is not a polynomial of degree ≤ 2 in the velocities
    /// L as a harmonic polynomial when it is one (spares derive_equations a conversion).
    std::shared_ptr<const harmonic_lagrangian> harmonic;
};

/// −m g·r: the potential of a mass m at `position` (3 components) in the scene's gravity
/// (0 without gravity).
GiNaC::ex gravity_potential(const model& scene, const GiNaC::ex& mass, const std::vector<GiNaC::ex>& position);

/// Builds T, V and L. Throws scene_error-free computation_error if a spring's
/// length has no value (coincident fixed ends).
lagrangian_result derive_lagrangian(const model& scene, const simplifier& simplify);

} // namespace lagrange
