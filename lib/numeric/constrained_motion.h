// SPDX-License-Identifier: GPL-2.0-or-later
/** @file constrained_motion.h
 *  The simulation of a scene with constraints: the index-1 form [M −Aᵀ; A 0] [q̈; λ] =
 *  [f; −c] compiled at the parameter point and integrated by an explicit method from one
 *  output time to the next, the state projected back onto the constraints (positions onto
 *  the holonomic ones by Newton's method, then velocities onto A q̇ + b = 0) after each
 *  piece. The largest residual before projection is reported beside the energy drift, and
 *  the times where a multiplier changes sign (a ladder leaving its wall) are found by bisection. */
#pragma once

#include "mechanics/equations_of_motion.h"
#include "program/expression_program.h"
#include "numeric/ode.h"
#include "numeric/simulation.h"
#include "core/errors.h"
#include "core/model.h"

#include <map>
#include <string>
#include <vector>

namespace lagrange {

class constrained_motion {
public:
    /// Throws computation_error naming a parameter without a value.
    constrained_motion(const model& scene, const equations_of_motion& equations,
                       const std::map<std::string, GiNaC::ex>& values);

    std::size_t coordinates() const { return n_; }
    std::size_t constraints() const { return m_; }
    /// No explicit time in L or the constraints and no generalized forces: energy is conserved.
    bool conservative() const { return conservative_; }

    /// q̈ and λ at (t, x = (q, q̇)); throws computation_error where the system is singular.
    void solve(double t, const double* x, double* acceleration, double* multipliers) const;
    /// The largest |f| of a holonomic constraint and |Σ a q̇ + b| of every constraint at (t, x).
    double residual(double t, const double* x) const;
    /// Each holonomic f (0 for a Pfaffian row), then each A q̇ + b, at (t, x).
    std::vector<double> residuals(double t, const double* x) const;
    /// Moves x onto the constraints: q by minimum-norm Newton steps on the holonomic ones,
    /// then q̇ by the least change that satisfies A q̇ + b = 0.
    void project(double t, double* x) const;
    double energy(const double* x) const;
    ode_system system() const;

private:
    void evaluate(const expression_program& program, double t, const double* x, double* out) const;
    std::size_t n_ = 0, m_ = 0;
    bool conservative_ = true;
    std::vector<bool> holonomic_;
    expression_program dynamics_;  ///< M (n²), f (n), A (m n), c (m)
    expression_program residuals_; ///< the holonomic f (m, 0 for Pfaffian rows), A q̇ + b (m)
    expression_program energy_;
    mutable std::vector<double> scratch_, symbols_, outputs_;
};

/// The bad input of an initial state `given` off the constraints: located at the written
/// value that the projection (`projected`, null when it did not converge) moves most, naming
/// each constraint missed and suggesting the projected state (simulate and animate throw it).
scene_error off_constraints(const model& scene, const constrained_motion& motion, const std::vector<double>& given,
                            const std::vector<double>* projected, double tolerance);

/// Simulates a scene with constraints (see above). An initial state off the constraints
/// (by more than the tolerance) is a scene_error at the value the least-change projection
/// moves most, naming the residuals and suggesting the projected state; with
/// settings.project_initial the run starts from the projected state instead.
simulation_result simulate_constrained(const model& scene, const equations_of_motion& equations,
                                       const simulation_settings& settings = {});

} // namespace lagrange
