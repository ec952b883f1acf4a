// SPDX-License-Identifier: GPL-2.0-or-later
/** @file compiled_motion.h
 *  The equations of motion M(q) q̈ = f(t, q, q̇) of a Lagrangian at one parameter
 *  point, compiled once into straight-line code (M, f, the energy function, and the
 *  symbolic derivatives that make the Jacobian of the first-order system), and
 *  solved for q̈ at each evaluation — the mass matrix is never inverted symbolically.
 *  State layout: x = (q1 … qn, q̇1 … q̇n), and with generalized forces (dissipation,
 *  dampers, applied forces) and no explicit time in L a last entry W, the work
 *  ∫ Σ Q_i q̇_i dt they have done, so that the energy balance h(x) − W is an invariant. */
#pragma once

#include "mechanics/equations_of_motion.h"
#include "program/expression_program.h"
#include "program/native_code.h"
#include "numeric/ode.h"
#include "core/model.h"

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lagrange {

/// The shape of the right-hand side's program. `expanded`: M and f as derived, each angle
/// difference q_i − q_j with its own sine and cosine. `single_angles`: those written through
/// the sines and cosines of the single angles (program/angle_sums.h), the link directions a
/// recursion along a chain passes on: n sines and cosines instead of n², and products.
/// `recursive`: q̈ by the articulated-body recursion of a tree of point masses
/// (numeric/point_tree.h), O(n), without M (which the Jacobian still takes, in the automatic
/// form); the automatic form where the scene is no such tree.
/// `automatic`: single angles from single_angles_coordinates on, the recursion from
/// recursive_coordinates on.
enum class motion_form { automatic, expanded, single_angles, recursive };
/// Where single angles start to pay (bench/large_systems.sh, docs/benchmarks.md): chains of
/// 2 to 4 links evaluate as fast either way, from 5 on single angles are faster.
constexpr std::size_t single_angles_coordinates = 5;
/// Where the recursion starts to pay (likewise).
constexpr std::size_t recursive_coordinates = 3;

class compiled_motion {
public:
    /// `values`: a value for every parameter that L uses (exact or floating); throws
    /// computation_error naming a parameter without one, or an expression that cannot
    /// be evaluated.
    compiled_motion(const model& scene, const equations_of_motion& equations,
                    const std::map<std::string, GiNaC::ex>& values, motion_form form = motion_form::automatic);

    std::size_t coordinates() const { return n_; }
    std::size_t dimension() const { return 2 * n_ + (accumulates_work_ ? 1 : 0); }
    /// L has no explicit time and there are no generalized forces: energy is conserved.
    bool conservative() const { return conservative_; }
    /// The state ends with the work W of the generalized forces (see above).
    bool accumulates_work() const { return accumulates_work_; }
    std::size_t instructions() const
    {
        return (recursive_ ? recursive_program_ : rhs_program_).instruction_count();
    }
    /// Whether the right-hand side takes single angles (see motion_form).
    bool single_angles() const { return single_angles_; }
    /// Whether the right-hand side is the recursion (see motion_form).
    bool recursive() const { return recursive_; }

    /// dxdt = (q̇, q̈) with M q̈ = f solved by LDLᵀ, or by the recursion; throws
    /// computation_error when M is not positive definite at x (the recursion: when a
    /// q̈ is not finite, M's solve says why).
    void rhs(double t, const double* x, double* dxdt) const;
    /// ∂(q̇, q̈)/∂(q, q̇), row-major 2n × 2n: ∂q̈/∂y = M⁻¹ (∂f/∂y − (∂M/∂y) q̈).
    void jacobian(double t, const double* x, double* out) const;
    /// The energy function h = Σ q̇ ∂L/∂q̇ − L (conserved when L has no explicit t).
    double energy(const double* x) const;
    /// The power of the generalized forces Σ Q_i q̇_i at (t, x).
    double power(double t, const double* x) const;

    /// Compiles M, f and the Jacobian's parts to machine code (see native_code.h);
    /// false, and the interpreter stays in use, when no C compiler is available.
    bool compile_native(const native_limits& limits = {}, std::string* why = nullptr);
    /// M and f only, what explicit methods evaluate (the Jacobian's program is several
    /// times larger, and so is its compile); compile_native_jacobian() adds the rest.
    bool compile_native_rhs(const native_limits& limits = {}, std::string* why = nullptr);
    bool compile_native_jacobian(const native_limits& limits = {}, std::string* why = nullptr);
    bool native() const { return static_cast<bool>(native_); }

    /// The system for the integrators: rhs, Jacobian, and the energy as an invariant
    /// (relative to `energy_scale`, 0 for its initial magnitude) when it is conserved, or the
    /// energy balance h − W when the state carries the work W; after
    /// compile_native() also the native program as `compiled` (ode.h), which DOP853 calls directly.
    ode_system system(double energy_scale = 0) const;

private:
    /// q̈ at x; `keep_factor` leaves the LDLᵀ factor of M in factor_ (for the Jacobian).
    void solve(double t, const double* x, double* acceleration, bool keep_factor = false) const;
    std::size_t n_ = 0;
    bool conservative_ = true;
    bool explicit_time_ = false;          ///< t appears in M or f at the parameter values
    bool accumulates_work_ = false;
    bool single_angles_ = false;
    bool recursive_ = false;
    expression_program rhs_program_;      ///< M (row-major, n²) then f (n)
    /// dxdt = (q̇, q̈) by the recursion, when recursive_ (then native_.rhs is this program's,
    /// and the Jacobian's M and f are interpreted)
    expression_program recursive_program_;
    expression_program power_program_;    ///< Σ Q_i q̇_i, then its derivatives by q and q̇ (2n)
    expression_program jacobian_program_; ///< ∂M/∂q_k (n³), ∂f/∂q (n²), ∂f/∂q̇ (n²)
    expression_program energy_program_;
    /// The momenta p_q = ∂L/∂q̇ of the cyclic coordinates (conserved, reported as invariants
    /// named `p_q` when there are no generalized forces), and their names.
    expression_program momentum_program_;
    std::vector<std::string> momentum_names_;
    native_rhs native_;
    mutable std::vector<double> scratch_, symbols_, outputs_, factor_, jacobian_outputs_;
};

/// The program of (q̇, q̈) by the articulated-body recursion (numeric/point_tree.h) at `values`,
/// reading `symbols` (q, q̇ first, then t and whatever `values` leaves symbols), or nothing
/// when the scene is no such tree; throws std::invalid_argument as expression_program does.
std::optional<expression_program> recursive_rates(const model& scene, const equations_of_motion& equations,
                                                  const std::map<std::string, GiNaC::ex>& values,
                                                  const std::vector<GiNaC::ex>& symbols);

/// Whether `recursion` (writing q̇ then q̈) gives the q̈ of M q̈ = f from `mass_and_force` (M
/// row-major, then f) at three fixed states, to 1e-8 of the largest; both read (q, q̇, t). States
/// where M is singular are skipped.
bool recursion_agrees(const expression_program& recursion, const expression_program& mass_and_force, std::size_t n);

/// The programs' symbols in the state's order: q1 … qn, q̇1 … q̇n, then t.
std::vector<GiNaC::ex> state_symbols(const model& scene);

/// f expanded when that is smaller. The derived forcing keeps terms that cancel apart, as
/// q̇1·(… + c·sin(q1 − q2)·q̇2) − c·sin(q1 − q2)·q̇1·q̇2: expanded, a 20-link chain's forcing
/// compiles to 2.3 times fewer instructions. A product of sums that would multiply out
/// (expanded_terms beyond the nodes written) stays as it is.
GiNaC::ex cancelled(const GiNaC::ex& f);

/// M q̈ = f at the parameter values: M row-major (symmetric, each entry substituted once)
/// and f (expanded where that makes it smaller: its cancelling terms gone).
struct motion_expressions {
    std::vector<GiNaC::ex> mass, force;
};
motion_expressions motion_at_values(const model& scene, const equations_of_motion& equations,
                                    const std::map<std::string, GiNaC::ex>& values);

/// The derivatives that make the first-order system's Jacobian: ∂M/∂q_k for each k (n³),
/// then ∂f/∂q (n²), then ∂f/∂q̇ (n²), row by row.
std::vector<GiNaC::ex> motion_jacobian(const model& scene, const motion_expressions& motion);

/// A value for every parameter from the first `values` line (later lines are other points).
std::map<std::string, GiNaC::ex> first_value_point(const model& scene);

/// The initial state x0 = (q, q̇) of the scene's `initial` line at those values (zeros if none);
/// the work W (when the motion accumulates it) starts at 0 and is not part of it.
std::vector<double> initial_state_vector(const model& scene, const std::map<std::string, GiNaC::ex>& values);

} // namespace lagrange
