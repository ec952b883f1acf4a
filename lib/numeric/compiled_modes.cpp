// SPDX-License-Identifier: GPL-2.0-or-later
/** @file compiled_modes.cpp
 *  Numeric normal modes: T and V simplified and compiled once, then per point the
 *  closed form (one or two coordinates, numeric/pair_kernels.h), the symbolically
 *  mass-normalized symmetric problem, or Eigen's generalized solver, each with a
 *  running error bound, and a CLN route at high precision (compiled_modes_precise.cpp)
 *  when that bound is above the tolerance. */
#include "numeric/compiled_modes.h"

#include "core/number_text.h"

#include "algebra/factor.h"
#include "core/errors.h"
#include "numeric/pair_kernels.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace lagrange {

namespace {

/// Bound scale from a double running bound to the same formulas in double-double:
/// each double-double step errs by at most ~8·2⁻¹⁰⁶ where double errs by 2⁻⁵³.
constexpr double double_double_scale = 0x1p-46;

/// Node count of an expression tree, to give up on symbolic routes that blow up.
std::size_t tree_size(const GiNaC::ex& e)
{
    std::size_t n = 1;
    for (std::size_t k = 0; k < e.nops(); ++k)
        n += tree_size(e.op(k));
    return n;
}

/// Normal form with numerator and denominator factored where GiNaC can.
GiNaC::ex tidy(const GiNaC::ex& e)
{
    GiNaC::ex n = GiNaC::normal(e);
    try {
        GiNaC::ex nd = n.numer_denom();
        return factor_if_quick(nd.op(0)) / factor_if_quick(nd.op(1));
    } catch (const std::exception&) {
        return n;
    }
}

/// Whether one mode's error bound `e` is within the tolerance: relative on ω, or for ω² = 0
/// absolute on ω against the largest |ω²|; never for a bound that is not finite. Without
/// branches, so that the block check vectorizes.
inline bool mode_within(double e, double w2, double largest, double tolerance)
{
    bool finite = std::abs(e) <= std::numeric_limits<double>::max();
    bool within = w2 == 0 ? e * e <= tolerance * largest : e <= tolerance;
    return finite & within;
}

/// The widest relative error bound (for ω = 0: absolute, against the largest ω, as
/// mode_within measures it) with which the automatic route still gives its numbers as an
/// answer; past it, it refuses.
constexpr double answer_limit = 1e-6;

std::string number_text(double x) { return significant(x, 3); }

/// Index of T's upper triangle entry (i ≤ j) in row-major order.
std::size_t upper_index(std::size_t i, std::size_t j, std::size_t n) { return i * n - i * (i + 1) / 2 + j; }

} // namespace

std::string to_string(modes_method m)
{
    switch (m) {
    case modes_method::automatic: return "automatic";
    case modes_method::closed_form: return "closed form (double-double)";
    case modes_method::symbolic_normalized: return "symbolic normalization";
    case modes_method::eigen_generalized: return "Eigen generalized solver";
    case modes_method::high_precision: return "high precision (CLN)";
    }
    return "?";
}

compiled_modes::compiled_modes(const std::vector<parameter>& parameters, const linearization_result& linear,
                               compiled_modes_options options, std::vector<std::string> coordinate_names)
    : size_(linear.kinetic.rows()), options_(options), parameters_(parameters),
      coordinate_names_(std::move(coordinate_names)), kinetic_(linear.kinetic), potential_(linear.potential)
{
    const std::size_t n = size_;
    if (linear.kinetic.cols() != n || linear.potential.rows() != n || linear.potential.cols() != n)
        throw computation_error("the kinetic and potential matrices are not square of the same size");
    std::vector<GiNaC::ex> symbols;
    for (const parameter& p : parameters_) {
        symbols.push_back(p.symbol);
        used_.push_back(kinetic_.has(p.symbol) || potential_.has(p.symbol));
    }
    auto T = [&](std::size_t i, std::size_t j) { return GiNaC::normal(kinetic_(i, j)); };
    auto V = [&](std::size_t i, std::size_t j) { return GiNaC::normal(potential_(i, j)); };
    try {
        std::vector<GiNaC::ex> entries;
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i; j < n; ++j)
                entries.push_back(T(i, j));
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i; j < n; ++j)
                entries.push_back(V(i, j));
        entries_ = expression_program(entries, symbols);

        if (n == 1) {
            closed_ = expression_program({T(0, 0), V(0, 0)}, symbols);
            has_closed_ = true;
        } else if (n == 2) {
            GiNaC::ex a = tidy(T(0, 0) * T(1, 1) - T(0, 1) * T(0, 1));
            GiNaC::ex b = tidy(T(0, 0) * V(1, 1) + T(1, 1) * V(0, 0) - 2 * T(0, 1) * V(0, 1));
            GiNaC::ex c = tidy(V(0, 0) * V(1, 1) - V(0, 1) * V(0, 1));
            GiNaC::ex disc = tidy(GiNaC::expand(b * b - 4 * a * c));
            closed_ = expression_program({a, b, c, disc, T(0, 0), T(0, 1), T(1, 1), V(0, 0), V(0, 1), V(1, 1)},
                                         symbols);
            has_closed_ = true;
            set_a_priori_bounds();
        }

        // T = L Lᵀ symbolically, where that stays small (diagonal T, or few coordinates).
        bool diagonal = true;
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < n; ++j)
                if (i != j && !kinetic_(i, j).is_zero())
                    diagonal = false;
        if (diagonal || n <= 3) try {
            std::vector<std::vector<GiNaC::ex>> L(n, std::vector<GiNaC::ex>(n, 0)), inverse = L;
            std::vector<GiNaC::ex> pivots(n);
            std::size_t total = 0;
            for (std::size_t i = 0; i < n; ++i) {
                GiNaC::ex d = T(i, i);
                for (std::size_t k = 0; k < i; ++k)
                    d -= L[i][k] * L[i][k];
                pivots[i] = tidy(d);
                if (pivots[i].is_zero()) {
                    singular_coordinate_ = i;
                    break;
                }
                L[i][i] = GiNaC::sqrt(pivots[i]);
                for (std::size_t j = i + 1; j < n; ++j) {
                    GiNaC::ex s = T(j, i);
                    for (std::size_t k = 0; k < i; ++k)
                        s -= L[j][k] * L[i][k];
                    L[j][i] = GiNaC::normal(s / L[i][i]);
                }
            }
            for (std::size_t j = 0; j < n; ++j) {
                inverse[j][j] = 1 / L[j][j];
                for (std::size_t i = j + 1; i < n; ++i) {
                    GiNaC::ex s = 0;
                    for (std::size_t k = j; k < i; ++k)
                        s += L[i][k] * inverse[k][j];
                    inverse[i][j] = GiNaC::normal(-s / L[i][i]);
                }
            }
            if (singular_coordinate_ < n)
                return;
            std::vector<GiNaC::ex> outputs = pivots;
            for (std::size_t i = 0; i < n; ++i)
                for (std::size_t j = i; j < n; ++j) {
                    GiNaC::ex s = 0;
                    for (std::size_t k = 0; k <= i; ++k)
                        for (std::size_t l = 0; l <= j; ++l)
                            if (!inverse[i][k].is_zero() && !inverse[j][l].is_zero())
                                s += inverse[i][k] * potential_(k, l) * inverse[j][l];
                    outputs.push_back(GiNaC::normal(s));
                    total += tree_size(outputs.back());
                }
            for (std::size_t i = 0; i < n; ++i)
                for (std::size_t j = 0; j <= i; ++j)
                    outputs.push_back(inverse[i][j]);
            if (total < 20000) {
                normalized_ = expression_program(outputs, symbols);
                has_normalized_ = true;
            }
        } catch (const GiNaC::pole_error&) {
            has_normalized_ = false;
        }
    } catch (const std::invalid_argument& e) {
        throw computation_error(std::string("numeric modes: ") + e.what());
    }
}

void compiled_modes::set_a_priori_bounds()
{
    auto bound = [&](std::size_t k) { return closed_.output_bound(k); };
    if (!closed_.algebraic())
        return;
    for (std::size_t k : {0, 1, 2, 3, 4, 6})
        if (!bound(k).known)
            return;
    if (bound(3).sign < 0)
        return;
    // the closed form's steps (pair_frequencies), each with one more double-double rounding
    auto rounded = [](double r) {
        return (r + double_double_step + r * double_double_step) * (1 + 0x1p-30);
    };
    double a = bound(0).relative, b = bound(1).relative, c = bound(2).relative, d = bound(3).relative;
    double root = rounded(d / (2 - d));                // √(b² − 4ac)
    double q = rounded(std::max(b, root));             // b ± √…, both terms of one sign
    if (q >= 0.5 || a >= 0.5)
        return;
    double big = rounded((q + a) / (1 - a));           // q / 2a  ((1 + q)/(1 − a) − 1)
    double small = rounded((c + q) / (1 - q));         // 2c / q
    double w = std::max(big, small);
    if (w >= 0.5)
        return;
    omega_bound_ = w / (1 + std::sqrt(1 - w)) * (1 + 0x1p-30); // |√(1 + θ) − 1| for |θ| ≤ w
    zero_root_ = bound(2).sign == 0;
    a_priori_ = true;
}

void compiled_modes::not_positive_definite(std::size_t coordinate, int digits) const
{
    if (coordinate < size_) {
        std::string name = coordinate < coordinate_names_.size() ? coordinate_names_[coordinate]
                                                                 : "#" + std::to_string(coordinate + 1);
        throw computation_error("the kinetic matrix is not positive definite at these values: coordinate `" + name
                                + "` has no kinetic energy independent of the coordinates before it"
                                + (digits > 0 ? " (to " + std::to_string(digits) + " digits)" : ""));
    }
    throw computation_error("the kinetic matrix is singular or indefinite at these values");
}

bool compiled_modes::acceptable(const double* error, const double* w2) const
{
    double largest = 0;
    for (std::size_t k = 0; k < size_; ++k)
        largest = std::max(largest, std::abs(w2[k]));
    for (std::size_t k = 0; k < size_; ++k)
        if (!mode_within(error[k], w2[k], largest, options_.tolerance))
            return false;
    return true;
}

bool compiled_modes::all_acceptable(std::size_t count, const double* w2, const double* error) const
{
    // acceptable() on every point of two coordinates, as one loop that vectorizes
    const double tolerance = options_.tolerance;
    double misses = 0;
    for (std::size_t j = 0; j < count; ++j) {
        double largest = std::max(std::abs(w2[2 * j]), std::abs(w2[2 * j + 1]));
        for (std::size_t i = 0; i < 2; ++i)
            misses += mode_within(error[2 * j + i], w2[2 * j + i], largest, tolerance) ? 0.0 : 1.0;
    }
    return misses == 0;
}

modes_method compiled_modes::evaluate(const double* p, double* w2, double* w, double* error, double* modes)
{
    switch (options_.method) {
    case modes_method::closed_form:
        if (!has_closed_)
            throw std::invalid_argument("the closed form needs one or two coordinates");
        return closed_form(p, w2, w, error, modes);
    case modes_method::symbolic_normalized:
        if (singular_coordinate_ < size_)
            not_positive_definite(singular_coordinate_);
        if (!has_normalized_)
            throw std::invalid_argument("no symbolic normalization of this kinetic matrix");
        return normalized(p, w2, w, error, modes);
    case modes_method::eigen_generalized: return generalized(p, w2, w, error, modes);
    case modes_method::high_precision: return high_precision(p, w2, w, error, modes, options_.digits);
    case modes_method::automatic: break;
    }
    modes_method used;
    bool distrusted = false;
    try {
        if (has_closed_ && closed_.algebraic()) {
            used = closed_form(p, w2, w, error, modes, &distrusted);
        } else if (has_normalized_) {
            used = normalized(p, w2, w, error, modes);
        } else {
            used = generalized(p, w2, w, error, modes);
        }
    } catch (const computation_error&) {
        // The double routes test T in double: where its entries, or their products, leave
        // the range of double (M = m = 1e-300, l = g = 1e150), a positive definite T can
        // fail that test. High precision, with T equilibrated first, decides (and its
        // message stands when it fails too).
        used = high_precision(p, w2, w, error, modes, options_.digits);
    }
    return refine(p, used, distrusted, w2, w, error, modes);
}

modes_method compiled_modes::refine(const double* p, modes_method route, bool distrusted, double* w2, double* w,
                                    double* error, double* modes)
{
    modes_method used = refine_route(p, route, distrusted, w2, w, error, modes);
    // The best bound there is may still be too wide to call the numbers an answer (at
    // 1e45 the printed ω said nothing at all): refuse rather than print them.
    double largest = 0;
    for (std::size_t k = 0; k < size_; ++k)
        largest = std::max(largest, std::abs(w2[k]));
    for (std::size_t k = 0; k < size_; ++k)
        if (!mode_within(error[k], w2[k], largest, answer_limit))
            throw computation_error("the numeric modes cannot be computed reliably at these values: the error "
                                    "bound of a frequency stays at " + number_text(error[k]) + " even with "
                                    + std::to_string(4 * options_.digits) + " digits");
    return used;
}

modes_method compiled_modes::refine_route(const double* p, modes_method route, bool distrusted, double* w2,
                                          double* w, double* error, double* modes)
{
    // a mode vector that over- or underflowed inside the closed form (M = 1, m = 1e60)
    if (modes && !std::all_of(modes, modes + size_ * size_, [](double x) { return std::isfinite(x); }))
        distrusted = true;
    if (!distrusted && acceptable(error, w2))
        return route;
    if (!distrusted) {
        for (int digits = options_.digits; !acceptable(error, w2) && digits <= 4 * options_.digits; digits *= 2)
            route = high_precision(p, w2, w, error, modes, digits);
        return route;
    }
    const std::size_t n = size_;
    std::vector<double> kept(w2, w2 + n);
    kept.insert(kept.end(), w, w + n);
    kept.insert(kept.end(), error, error + n);
    if (modes)
        kept.insert(kept.end(), modes, modes + n * n);
    modes_method high = route;
    for (int digits = options_.digits; digits <= 4 * options_.digits; digits *= 2) {
        high = high_precision(p, w2, w, error, modes, digits);
        if (acceptable(error, w2))
            return high;
    }
    // high precision does not reach the tolerance either: the smaller of the two errors
    auto worst = [&](const double* e) {
        double largest = 0;
        for (std::size_t k = 0; k < n; ++k)
            largest = std::isfinite(e[k]) ? std::max(largest, e[k]) : HUGE_VAL;
        return largest;
    };
    if (!(worst(kept.data() + 2 * n) < worst(error)))
        return high;
    std::copy(kept.begin(), kept.begin() + n, w2);
    std::copy(kept.begin() + n, kept.begin() + 2 * n, w);
    std::copy(kept.begin() + 2 * n, kept.begin() + 3 * n, error);
    if (modes)
        std::copy(kept.begin() + 3 * n, kept.end(), modes);
    return route;
}

numeric_modes compiled_modes::evaluate(const double* p)
{
    numeric_modes result;
    std::size_t n = size_;
    result.omega_squared.resize(n);
    result.omega.resize(n);
    result.error.resize(n);
    result.modes.resize(n, n);
    modes_method used = evaluate(p, result.omega_squared.data(), result.omega.data(), result.error.data(),
                                 result.modes.data());
    result.method = to_string(used);
    for (std::size_t k = 0; k < parameters_.size(); ++k)
        if (used_[k])
            result.values.emplace_back(parameters_[k].name, p[k]);
    return result;
}

modes_method compiled_modes::closed_form(const double* p, double* w2, double* w, double* error, double* modes,
                                         bool* out_of_range)
{
    using status = expression_program::a_priori_status;
    std::size_t outputs = closed_.output_count();
    out_bounded_.resize(outputs);
    out_dd_.resize(outputs);
    closed_.run(p, scratch_dd_, out_dd_.data());
    status checked = a_priori_ ? closed_.check_a_priori(scratch_dd_) : status::not_positive;
    bool a_priori = checked == status::holds;
    if (!a_priori) // a priori bounds need no bounded run
        closed_.run(p, scratch_bounded_, out_bounded_.data());
    if (out_of_range)
        *out_of_range = checked == status::out_of_range;
    // the batch layout with one lane, so that one point and a batch run the same code
    double packed[4 * 16] = {};
    for (std::size_t k = 0; k < outputs; ++k) {
        packed[4 * k] = out_dd_[k].hi;
        packed[4 * k + 1] = out_dd_[k].lo;
        if (!a_priori) {
            packed[4 * k + 2] = out_bounded_[k].value;
            packed[4 * k + 3] = out_bounded_[k].error;
        }
    }
    const double* rows[16];
    for (std::size_t k = 0; k < outputs; ++k)
        rows[k] = packed + 4 * k;
    closed_form_block(rows, 1, 1, a_priori, nullptr, w2, w, error, modes);
    return modes_method::closed_form;
}

void compiled_modes::evaluate_batch(std::size_t count, const double* p, std::size_t stride, double* w2, double* w,
                                    double* error, double* modes, modes_method* used)
{
    const std::size_t n = size_;
    if (options_.method != modes_method::automatic || !has_closed_ || !closed_.algebraic()) {
        for (std::size_t j = 0; j < count; ++j) {
            modes_method route = evaluate(p + j * stride, w2 + j * n, w + j * n, error + j * n, modes ? modes + j * n * n : nullptr);
            if (used)
                used[j] = route;
        }
        return;
    }
    constexpr std::size_t B = expression_program::batch_size;
    batch_out_.resize(closed_.output_count() * 4 * B);
    batch_status_.resize(B);
    batch_use_.resize(B);
    const double* rows[16]; // of the closed program's outputs
    for (std::size_t start = 0; start < count; start += B) {
        std::size_t block = std::min(B, count - start);
        try {
            evaluate_block(start, block, p, stride, w2, w, error, modes, used, rows);
        } catch (const computation_error&) {
            // a lane whose T failed the double test: point by point, as evaluate() decides
            for (std::size_t point = start; point < start + block; ++point) {
                modes_method route = evaluate(p + point * stride, w2 + point * n, w + point * n,
                                              error + point * n, modes ? modes + point * n * n : nullptr);
                if (used)
                    used[point] = route;
            }
        }
    }
}

void compiled_modes::evaluate_block(std::size_t start, std::size_t block, const double* p, std::size_t stride,
                                    double* w2, double* w, double* error, double* modes, modes_method* used,
                                    const double** rows)
{
    constexpr std::size_t B = expression_program::batch_size;
    const std::size_t n = size_;
    const double* p_block = p + start * stride;
    double* modes_block = modes ? modes + start * n * n : nullptr;
    bool running_bounds = !a_priori_;
    if (a_priori_) {
        // a priori bounds where every parameter is positive (nearly always), the running
        // bound on the other lanes, as closed_form() decides for one point
        using status = expression_program::a_priori_status;
        closed_.run_batch_a_priori(p_block, stride, block, batch_scratch_, rows, batch_status_.data());
        for (std::size_t j = 0; j < block; ++j) {
            batch_use_[j] = batch_status_[j] == status::holds ? lane_use::use : lane_use::skip;
            running_bounds = running_bounds || batch_status_[j] != status::holds;
        }
        closed_form_block(rows, B, block, true, batch_use_.data(), w2 + start * n,
                          w + start * n, error + start * n, modes_block);
        for (std::size_t j = 0; j < block; ++j)
            batch_use_[j] = batch_status_[j] == status::holds ? lane_use::skip : lane_use::use;
    }
    if (running_bounds) {
        closed_.run_batch(p_block, stride, block, batch_scratch_, batch_out_.data());
        for (std::size_t k = 0; k < closed_.output_count(); ++k)
            rows[k] = batch_out_.data() + 4 * k * B;
        closed_form_block(rows, B, block, false, a_priori_ ? batch_use_.data() : nullptr,
                          w2 + start * n, w + start * n, error + start * n, modes_block);
    }
    if (!running_bounds && n == 2 && all_acceptable(block, w2 + start * n, error + start * n) &&
        (!modes_block || std::all_of(modes_block, modes_block + block * n * n,
                                     [](double x) { return std::isfinite(x); }))) {
        if (used)
            std::fill(used + start, used + start + block, modes_method::closed_form);
        return;
    }
    for (std::size_t j = 0; j < block; ++j) {
        std::size_t point = start + j;
        double *w2_j = w2 + point * n, *w_j = w + point * n, *error_j = error + point * n;
        double* modes_j = modes ? modes + point * n * n : nullptr;
        bool distrusted = a_priori_ && batch_status_[j] == expression_program::a_priori_status::out_of_range;
        modes_method route = refine(p + point * stride, modes_method::closed_form, distrusted, w2_j, w_j,
                                    error_j, modes_j);
        if (used)
            used[point] = route;
    }
}

void compiled_modes::closed_form_block(const double* const* o, std::size_t B, std::size_t count, bool a_priori,
                                       const lane_use* use, double* w2, double* w, double* error,
                                       double* modes) const
{
    const std::size_t n = size_;
    // the running bound is of the double run: double-double's is that scaled down
    // (exactly: a priori bounds are of the double-double values themselves)
    const double scale = a_priori ? 1.0 : closed_.algebraic() ? double_double_scale : 1.0;
    auto X = [&](std::size_t k, std::size_t j) { return double_double{o[k][j], o[k][B + j]}; };
    auto Y = [&](std::size_t k, std::size_t j) { return bounded_double{o[k][2 * B + j], o[k][3 * B + j]}; };
    // a priori: the relative bounds of the signs checked here are below 1, so the computed
    // sign is the exact one (and there are no bounded rows)
    auto positive = [&](std::size_t k, std::size_t j) {
        return a_priori ? X(k, j).hi > 0 : X(k, j).hi > Y(k, j).error * scale;
    };
    auto checked = [&](std::size_t j) { return !use || use[j] == lane_use::use; };

    if (n == 1) {
        for (std::size_t j = 0; j < count; ++j) {
            if (!checked(j))
                continue;
            if (!positive(0, j))
                not_positive_definite(0);
            single_lane(X(0, j), X(1, j), Y(0, j), Y(1, j), scale, w2[j], w[j], error[j],
                        modes ? &modes[j] : nullptr);
        }
        return;
    }

    // det T = x0 > 0 iff positive definite (with x4 = T11 > 0)
    for (std::size_t j = 0; j < count; ++j) {
        if (!checked(j))
            continue;
        if (!positive(4, j))
            not_positive_definite(0);
        if (!positive(6, j))
            not_positive_definite(1);
        if (!positive(0, j))
            not_positive_definite(1);
    }
    a_priori_constants constants{omega_bound_, zero_root_};
    pair_block(o, B, count, scale, a_priori ? &constants : nullptr, use, w2, w, error, modes);
}

modes_method compiled_modes::normalized(const double* p, double* w2, double* w, double* error, double* modes)
{
    const std::size_t n = size_, triangle = n * (n + 1) / 2;
    out_bounded_.resize(normalized_.output_count());
    normalized_.run(p, scratch_bounded_, out_bounded_.data());
    const bounded_double* pivots = out_bounded_.data();
    const bounded_double* K = pivots + n;
    const bounded_double* inverse = K + triangle;
    for (std::size_t i = 0; i < n; ++i)
        if (!(pivots[i].value > pivots[i].error))
            not_positive_definite(i);
    work_.resize(n, n);
    double perturbation = 0, norm = 0;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i; j < n; ++j) {
            const bounded_double& k = K[upper_index(i, j, n)];
            work_(i, j) = work_(j, i) = k.value;
            double weight = i == j ? 1 : 2;
            perturbation += weight * k.error * k.error;
            norm += weight * k.value * k.value;
        }
    symmetric_solver_.compute(work_, Eigen::ComputeEigenvectors);
    if (symmetric_solver_.info() != Eigen::Success)
        throw computation_error("the symmetric eigenvalue iteration did not converge");
    // Per mode: |W − λ| ≤ ‖K y − W y‖ for unit y (K symmetric), plus the rounding in that
    // residual and the error of K's entries (Weyl).
    // (into preallocated vectors: no allocation per point)
    const Eigen::MatrixXd& vectors = symmetric_solver_.eigenvectors();
    work_abs_ = work_.cwiseAbs();
    for (std::size_t k = 0; k < n; ++k) {
        double W = symmetric_solver_.eigenvalues()[k];
        const Eigen::VectorXd& y = (vector_ = vectors.col(static_cast<Eigen::Index>(k)));
        residual_.noalias() = work_ * y;
        residual_ -= W * y;
        double residual = residual_.norm() / y.norm();
        vector_abs_ = y.cwiseAbs();
        residual_.noalias() = work_abs_ * vector_abs_;
        double rounding = (n + 3) * unit_roundoff * (residual_.norm() + std::abs(W) * y.norm()) / y.norm();
        double orthogonality = std::abs(y.squaredNorm() - 1);
        double dw = std::sqrt(perturbation) + residual + rounding + orthogonality * std::sqrt(norm);
        set_frequency(W, dw * (1 + 1e-3), unit_roundoff, w2[k], w[k], error[k]);
    }
    if (modes) {
        // A = L⁻ᵀ Y, L⁻¹ stored by rows (lower triangle).
        const Eigen::MatrixXd& Y = symmetric_solver_.eigenvectors();
        for (std::size_t c = 0; c < n; ++c)
            for (std::size_t i = 0; i < n; ++i) {
                double s = 0;
                for (std::size_t k = i; k < n; ++k)
                    s += inverse[k * (k + 1) / 2 + i].value * Y(k, c);
                modes[c * n + i] = s;
            }
    }
    return modes_method::symbolic_normalized;
}

modes_method compiled_modes::generalized(const double* p, double* w2, double* w, double* error, double* modes)
{
    const std::size_t n = size_, triangle = n * (n + 1) / 2;
    out_bounded_.resize(entries_.output_count());
    entries_.run(p, scratch_bounded_, out_bounded_.data());
    Eigen::MatrixXd T(n, n), V(n, n);
    double dT = 0, dV = 0;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i; j < n; ++j) {
            const bounded_double& t = out_bounded_[upper_index(i, j, n)];
            const bounded_double& v = out_bounded_[triangle + upper_index(i, j, n)];
            T(i, j) = T(j, i) = t.value;
            V(i, j) = V(j, i) = v.value;
            double weight = i == j ? 1 : 2;
            dT += weight * t.error * t.error;
            dV += weight * v.error * v.error;
        }
    dT = std::sqrt(dT) + 8.0 * n * unit_roundoff * T.norm();
    dV = std::sqrt(dV) + 8.0 * n * unit_roundoff * V.norm();
    for (std::size_t i = 0; i < n; ++i)
        if (!(T(i, i) > 0))
            not_positive_definite(i);
    double smallest = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(T, Eigen::EigenvaluesOnly).eigenvalues()[0];
    if (!(smallest > dT))
        not_positive_definite(n);
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(
        V, T, modes ? Eigen::ComputeEigenvectors | Eigen::Ax_lBx : Eigen::EigenvaluesOnly | Eigen::Ax_lBx);
    if (solver.info() != Eigen::Success)
        not_positive_definite(n);
    for (std::size_t k = 0; k < n; ++k) {
        double W = solver.eigenvalues()[k];
        double dw = (dV + std::abs(W) * dT) / (smallest - dT);
        set_frequency(W, dw, unit_roundoff, w2[k], w[k], error[k]);
    }
    if (modes)
        Eigen::Map<Eigen::MatrixXd>(modes, n, n) = solver.eigenvectors();
    return modes_method::eigen_generalized;
}

void read_value_point(const model& scene, const value_point& point, std::vector<double>& values,
                      std::vector<bool>& given)
{
    for (const auto& [name, value] : point.values)
        for (std::size_t k = 0; k < scene.parameters.size(); ++k)
            if (scene.parameters[k].name == name) {
                GiNaC::ex number = value.evalf();
                if (!GiNaC::is_a<GiNaC::numeric>(number) || !GiNaC::ex_to<GiNaC::numeric>(number).is_real())
                    throw computation_error("the value of parameter `" + name + "` is not a real number");
                values[k] = GiNaC::ex_to<GiNaC::numeric>(number).to_double();
                given[k] = true;
            }
}

} // namespace lagrange
