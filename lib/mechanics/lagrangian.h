/** @file lagrangian.h
 *  The Lagrangian L = T − V from energies, points, gravity and springs, and the
 *  total time derivative with q, q̇, q̈ as plain symbols. */
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
    GiNaC::ex kinetic;         ///< T simplified (the part of L quadratic in the velocities)
    GiNaC::ex potential;       ///< V simplified (minus the part of L free of velocities)
    GiNaC::ex gyroscopic;      ///< the part of L linear in the velocities (0 unless `L` says otherwise)
    GiNaC::ex lagrangian;      ///< L simplified
    GiNaC::ex lagrangian_canonical; ///< L in canonical trig form (expanded): what the equations use
    bool split = true;         ///< false if L is not a polynomial of degree ≤ 2 in the velocities
    /// L as a harmonic polynomial when it is one (spares derive_equations a conversion).
    std::shared_ptr<const harmonic_lagrangian> harmonic;
};

/// Builds T, V and L. Throws scene_error-free computation_error if a spring's
/// length has no value (coincident fixed ends).
lagrangian_result derive_lagrangian(const model& scene, const simplifier& simplify);

} // namespace lagrange
