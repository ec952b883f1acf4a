// SPDX-License-Identifier: GPL-2.0-or-later
/** @file free_body_motion.h
 *  A free rigid body's Euler equations I ω̇ + ω × I ω = N (from bodies/euler)
 *  at one parameter point, solved for ω̇ once (I is a constant matrix of numbers there)
 *  and compiled into straight-line code with their symbolic Jacobian ∂ω̇/∂ω, as a
 *  first-order ode_system with state x = (ω1, ω2, ω3). Torque-free bodies carry their
 *  invariants T = ½ ωᵀIω and |L|² = |Iω|², and the exact solution the engine derives:
 *  the closed form of a symmetric body, the Jacobi elliptic solution of an asymmetric one. */
#pragma once

#include "bodies/euler.h"
#include "program/expression_program.h"
#include "program/native_code.h"
#include "numeric/ode.h"
#include "core/model.h"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace lagrange {

/// True when the scene is a free body to integrate: no coordinates, a body with `omega`.
bool has_free_body(const model& scene);

class free_body_motion {
public:
    /// The first body of the scene with `omega`, at `values` (a value for every parameter
    /// it uses); the initial ω from the scene's `initial` line. Throws computation_error
    /// naming a missing value, or when the scene has no (or more than one) free body.
    free_body_motion(const model& scene, const std::map<std::string, GiNaC::ex>& values);

    const std::string& body() const { return body_; }
    const std::vector<std::string>& names() const { return names_; } ///< w1 w2 w3
    const std::vector<double>& initial() const { return initial_; }
    bool torque_free() const { return torque_free_; }
    /// "the Jacobi elliptic solution" / "the symmetric-body closed form", or empty when none.
    const std::string& exact_kind() const { return exact_kind_; }

    void rhs(double t, const double* w, double* dwdt) const;
    void jacobian(double t, const double* w, double* out) const; ///< row-major 3 × 3
    std::array<double, 3> exact(double t) const;                 ///< only when exact_kind() is set

    /// Compiles the right-hand side and Jacobian to machine code (native_code.h); false,
    /// and the interpreter stays in use, without a C compiler.
    bool compile_native(const native_limits& limits = {}, std::string* why = nullptr);
    bool native() const { return static_cast<bool>(native_); }

    /// The system for the integrators (refers to this object, which must outlive it):
    /// rhs, Jacobian, the invariants "energy" (T) and "angular_momentum_squared" (|L|²)
    /// when torque-free, the exact solution when there is one, and after compile_native()
    /// the native program as `compiled` (ode.h), which DOP853 calls directly.
    ode_system system() const;

private:
    std::string body_;
    std::vector<std::string> names_;
    std::vector<double> initial_;
    double tensor_[9] = {};
    bool torque_free_ = true;
    bool time_dependent_ = false;
    std::string exact_kind_;
    std::optional<euler_result::elliptic_solution> elliptic_;
    expression_program symmetric_program_; ///< ω(t) of the symmetric body's closed form, symbol t
    expression_program rhs_program_;       ///< ω̇ (3), symbols w1 w2 w3 t
    expression_program jacobian_program_;  ///< ∂ω̇_i/∂ω_j (9, row-major)
    native_rhs native_;
    mutable std::vector<double> scratch_;
};

} // namespace lagrange
