// SPDX-License-Identifier: GPL-2.0-or-later
/** @file compiled_modes.h
 *  Numeric normal modes at each `values` point: ω ascending, the mode matrix with
 *  Aᵀ T A = I, and an error estimate per frequency that bounds the error. T and V are
 *  compiled once (compiled_modes) and evaluated per point by the route that meets the
 *  tolerance. numeric/point_modes.h is the one path from a linearization to the modes at
 *  a point, for the `numeric` stage and sweeps alike. */
#pragma once

#include "mechanics/linearization.h"
#include "program/expression_program.h"
#include "core/model.h"

#include <Eigen/Dense>

#include <complex>
#include <string>
#include <utility>
#include <vector>

namespace lagrange {

struct numeric_modes {
    std::vector<std::pair<std::string, double>> values; ///< the parameter point
    std::vector<double> omega_squared;                  ///< ascending, signed (ω² < 0: unstable mode)
    std::vector<double> omega;                          ///< sign(ω²)·√|ω²|: a negative entry is the growth
                                                        ///< rate of an imaginary frequency
    Eigen::MatrixXd modes;                              ///< columns, Aᵀ T A = I
    std::vector<double> error;                          ///< bound on the relative error of each ω;
                                                        ///< for a zero mode (ω = 0) the absolute error
    std::string method;                                 ///< which numeric path gave these
    /// Per mode, the rate γ > 0 at which it grows (q ∝ e^{γt}; an unstable mode), else 0:
    /// −ω for ω < 0 (ω² < 0, or a real eigenvalue s = γ with G), Re s beyond its error for a
    /// complex s with G. Set by point_modes; printers show a growing mode by it, never as a
    /// negative ω (output/mode_frequency.h).
    std::vector<double> growth_rate;
    /// With a gyroscopic matrix G (numeric/gyroscopic_modes.h): `omega` holds the n
    /// frequencies from the upper half of `eigenvalues`, `modes` is empty and
    /// `complex_modes` holds their vectors; empty otherwise.
    std::vector<std::complex<double>> eigenvalues;      ///< all 2n s with q ∝ x e^{st}, quadratic_modes order
    Eigen::MatrixXcd complex_modes;                     ///< n × n, x* T x = 1 (quadratic_modes.h)
    std::string stability;                              ///< "stable", "marginal" or "unstable" at this point
    /// With a damping matrix C ≠ 0 (numeric/damped_modes.h): `eigenvalues` are the 2n s of
    /// M q̈ + (C − G) q̇ + K q = 0, while `omega` and `modes` stay those of the undamped
    /// system (C = 0).
    bool damped = false;
    std::vector<double> eigenvalue_error; ///< estimated absolute error of each damped eigenvalue
    std::vector<double> damping_ratio;    ///< −Re s/|s| of each damped eigenvalue (NaN for s = 0)
    /// n × 2n: column k is the mode x of eigenvalues[k], (s²M + s(C − G) + K)x = 0, scaled so
    /// that its first component of largest modulus (to a relative 10⁻⁸) is exactly 1.
    Eigen::MatrixXcd damped_modes;
    std::vector<double> damped_mode_backward_error; ///< of each (s, x), quadratic_modes.h
    /// C M⁻¹K = K M⁻¹C at this point (to rounding) and G = 0: the damped modes are the real
    /// undamped mode shapes.
    bool proportional_damping = false;
};

/// The numeric routes from T and V to the modes.
enum class modes_method {
    automatic,           ///< the best exact route, then high precision if its bound exceeds the tolerance
    closed_form,         ///< 1 or 2 coordinates: det(V − ω²T) = 0 solved in double-double (Vieta for
                         ///< the smaller root) from symbolically simplified coefficients
    symbolic_normalized, ///< K = L⁻¹VL⁻ᵀ with T = LLᵀ done symbolically, then Eigen's symmetric solver
    eigen_generalized,   ///< T and V evaluated, then Eigen's GeneralizedSelfAdjointEigenSolver
    high_precision,      ///< T and V at `digits` digits (CLN), Cholesky and cyclic Jacobi in cln::cl_F
};
std::string to_string(modes_method m); ///< "closed form", "symbolic normalization", ...

/// What the closed form does with one lane of a block (numeric/pair_kernels.h).
enum class lane_use : unsigned char;

struct compiled_modes_options {
    modes_method method = modes_method::automatic;
    double tolerance = 1e-13; ///< automatic: relative error bound above which high precision is used
    int digits = 50;          ///< decimal digits of the high-precision route
};

/// T and V compiled once (symbolic simplification and normalization, then straight-line
/// code), evaluated at many parameter points. Not thread-safe: it keeps its workspace;
/// copy it per thread.
class compiled_modes {
public:
    /// `parameters` in the order evaluate() takes their values; `coordinate_names`
    /// (optional) name coordinates in error messages. Throws computation_error if T or
    /// V holds a symbol that is not a parameter.
    compiled_modes(const std::vector<parameter>& parameters, const linearization_result& linear,
                   compiled_modes_options options = {}, std::vector<std::string> coordinate_names = {});

    std::size_t size() const { return size_; } ///< number of coordinates
    /// Whether T or V depends on parameter `k` (those it does not need no value).
    bool uses(std::size_t k) const { return used_[k]; }

    /// Modes at one point, into caller buffers of size() entries (modes: size()², column-major,
    /// may be null). Returns the route that produced them. Throws computation_error when T is
    /// singular or indefinite there.
    modes_method evaluate(const double* parameter_values, double* omega_squared, double* omega, double* error,
                          double* modes);
    numeric_modes evaluate(const double* parameter_values);
    /// Modes at `count` points: point j's values start at parameter_values + j·stride, its
    /// results at omega_squared + j·size(), omega + j·size(), error + j·size() and
    /// modes + j·size()² (may be null); `used` (may be null) gets each point's route.
    /// The same numbers as evaluate() point by point; the automatic route's closed form
    /// runs its compiled program on a block of points at a time.
    void evaluate_batch(std::size_t count, const double* parameter_values, std::size_t stride, double* omega_squared,
                        double* omega, double* error, double* modes, modes_method* used = nullptr);

private:
    void set_a_priori_bounds();
    /// `out_of_range` (may be null): whether a value left the range of a priori bounds (an
    /// under- or overflow inside), so that the running bound is not to be trusted either.
    modes_method closed_form(const double* p, double* w2, double* w, double* error, double* modes,
                             bool* out_of_range = nullptr);
    /// The closed form on `count` lanes of the closed program's outputs: output k's hi at
    /// outputs[k][j], lo at [B + j], and with running bounds (`a_priori` false) the bounded
    /// run's value and error at [2B + j], [3B + j], as expression_program::run_batch or
    /// run_batch_a_priori leave them; results per lane. `use` may be null (every lane: use).
    void closed_form_block(const double* const* outputs, std::size_t B, std::size_t count, bool a_priori,
                           const lane_use* use, double* w2, double* w, double* error, double* modes) const;
    modes_method normalized(const double* p, double* w2, double* w, double* error, double* modes);
    modes_method generalized(const double* p, double* w2, double* w, double* error, double* modes);
    modes_method high_precision(const double* p, double* w2, double* w, double* error, double* modes, int digits);
    /// High precision at growing digits where `route`'s result misses the tolerance, or where
    /// its bound is `distrusted` (then the result stands only if high precision cannot do better).
    modes_method refine(const double* p, modes_method route, bool distrusted, double* w2, double* w, double* error,
                        double* modes);
    /// refine()'s search for a route within the tolerance; refine() then refuses a result whose
    /// bound is too wide to be an answer.
    modes_method refine_route(const double* p, modes_method route, bool distrusted, double* w2, double* w,
                              double* error, double* modes);
    /// evaluate_batch on the `block` points from `start`; `rows`: room for the closed program's outputs.
    void evaluate_block(std::size_t start, std::size_t block, const double* p, std::size_t stride, double* w2,
                        double* w, double* error, double* modes, modes_method* used, const double** rows);
    bool acceptable(const double* error, const double* w) const;
    bool all_acceptable(std::size_t count, const double* w2, const double* error) const;
    /// `digits`: the precision at which high precision found it so (0: a double route).
    [[noreturn]] void not_positive_definite(std::size_t coordinate, int digits = 0) const;

    std::size_t size_ = 0;
    compiled_modes_options options_;
    std::vector<parameter> parameters_;
    std::vector<bool> used_;
    std::vector<std::string> coordinate_names_;
    GiNaC::matrix kinetic_, potential_;
    expression_program closed_;     ///< size ≤ 2: [det T, b, det V, b² − 4 det T det V, T upper, V upper]
    expression_program normalized_; ///< [pivots of T = LLᵀ, K upper, L⁻¹ lower], if found
    expression_program entries_;    ///< [T upper, V upper]
    bool has_closed_ = false, has_normalized_ = false;
    /// The two-coordinate closed form with a priori bounds (see a_priori_bound): its
    /// coefficients a, b, c, b² − 4ac and T's diagonal have known signs, so every root W
    /// has a relative error bound fixed in advance, and ω that of omega_bound_; zero_root_:
    /// det V is identically 0, so a root may be exactly 0.
    bool a_priori_ = false, zero_root_ = false;
    double omega_bound_ = 0;
    std::vector<expression_program::a_priori_status> batch_status_;
    std::vector<lane_use> batch_use_;
    std::size_t singular_coordinate_ = static_cast<std::size_t>(-1); ///< T's pivot there is identically 0
    std::vector<double> scratch_double_;
    std::vector<bounded_double> scratch_bounded_, out_bounded_;
    std::vector<double_double> scratch_dd_, out_dd_;
    std::vector<double> batch_scratch_, batch_out_;
    Eigen::MatrixXd work_, work_abs_;
    Eigen::VectorXd vector_, vector_abs_, residual_;
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> symmetric_solver_;
};

/// Sets values[k] (and given[k]) for every parameter k that `point` gives a value to,
/// in the order of scene.parameters. Throws computation_error when a value is not a
/// real number.
void read_value_point(const model& scene, const value_point& point, std::vector<double>& values,
                      std::vector<bool>& given);

} // namespace lagrange
