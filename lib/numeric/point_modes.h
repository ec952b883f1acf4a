// SPDX-License-Identifier: GPL-2.0-or-later
/** @file point_modes.h
 *  The one path from a linearization to its numeric small oscillations at a parameter
 *  point, for conservative, gyroscopic (G ≠ 0), damped (C ≠ 0) and constrained scenes
 *  alike (a constrained scene's linearization is in its independent coordinates). The
 *  `numeric` stage evaluates it at the `values` points (numeric_normal_modes), `--sweep`
 *  at the points of its grid (numeric/sweep.h): the same numbers at the same values. */
#pragma once

#include "numeric/compiled_modes.h"
#include "program/expression_program.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace lagrange {

/// T, V (and G, C where not zero) compiled once, evaluated at many points.
/// - G = 0: compiled_modes (real modes, ω with an error bound that meets the tolerance);
/// - G ≠ 0, or V not symmetric (circulatory forces): the quadratic eigenproblem
///   (s²T − sG + V)x = 0 (numeric/gyroscopic_modes.h);
/// - C ≠ 0: besides, the damped eigenvalues of (s²T + s(C − G) + V)x = 0
///   (numeric/damped_modes.h), which decide `stability`.
/// Not thread-safe (it keeps its workspace); copy it per thread.
class point_modes {
public:
    /// `damping`: the damping matrix C at the same equilibrium; null (or zero) without one.
    /// Throws computation_error if a matrix holds a symbol that is not a parameter.
    point_modes(const model& scene, const linearization_result& linear, const GiNaC::matrix* damping = nullptr);

    std::size_t size() const { return size_; }               ///< number of coordinates
    bool uses(std::size_t k) const { return used_[k]; }      ///< whether parameter k needs a value
    bool gyroscopic() const { return gyroscopic_; } ///< G ≠ 0 or a circulatory V: complex modes
    bool damped() const { return damped_; }

    /// The modes at `values` (every parameter in model::parameters order; those not used may
    /// be NaN), into `out` (its buffers reused from call to call); `out.values` lists the
    /// parameters used. Throws computation_error naming the cause, ending with `where()`
    /// (" at the values on line 3"), which is called only on that error path: a kinetic matrix
    /// that is singular there, an entry that is not finite (the entry and why: overflow, a
    /// pole, a value outside the domain of sqrt or log), frequencies that are not finite.
    void evaluate(const double* values, numeric_modes& out, const std::function<std::string()>& where);

private:
    /// Throws an error naming an entry of T, V (G, C) that is not a finite real number at
    /// `values` (exact evaluation with GiNaC, only on an error path); returns if all are.
    void diagnose(const double* values, const std::string& where) const;

    const model* scene_;
    const linearization_result* linear_;
    std::size_t size_ = 0;
    bool gyroscopic_ = false, damped_ = false;
    std::vector<bool> used_;
    GiNaC::matrix damping_;
    std::optional<compiled_modes> conservative_; ///< G = 0: ω and real modes
    std::optional<expression_program> matrices_; ///< G ≠ 0 or C ≠ 0: [T, V, G, C], row-major
    std::vector<double> scratch_, entries_;
    Eigen::MatrixXd kinetic_, potential_, gyroscopic_matrix_, damping_matrix_;
};

/// The `numeric` stage: the modes at every `values` point of the scene (point_modes), each
/// echoing every parameter value the point gives. Throws computation_error with the cause
/// (singular kinetic matrix at these values, a parameter without a value, ...) rather than
/// returning NaN or infinity.
std::vector<numeric_modes> numeric_normal_modes(const model& scene, const linearization_result& linear,
                                                const GiNaC::matrix* damping = nullptr);

/// "stable", "marginal" or "unstable" at the point: `modes.stability` where the
/// eigenvalues decided it (G or C ≠ 0); else from ω²: unstable when some ω² < 0 beyond its
/// error, marginal when some ω is 0 within its error.
std::string stability_of(const numeric_modes& modes);

} // namespace lagrange
