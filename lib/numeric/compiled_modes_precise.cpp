// SPDX-License-Identifier: GPL-2.0-or-later
/** @file compiled_modes_precise.cpp
 *  The high-precision route of compiled_modes: T and V evaluated exactly by GiNaC at the
 *  point, equilibrated by powers of two, and solved in CLN (numeric/cln_eigen.h) at
 *  growing digits until the frequencies and, if asked for, the mode vectors are resolved. */
#include "numeric/compiled_modes.h"

#include "core/errors.h"
#include "numeric/cln_eigen.h"
#include "numeric/pair_kernels.h"

#include <cln/cln.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace lagrange {

namespace {

cln::cl_F to_cl(const GiNaC::ex& e, const cln::float_format_t& format)
{
    if (!GiNaC::is_a<GiNaC::numeric>(e) || !GiNaC::ex_to<GiNaC::numeric>(e).is_real())
        throw computation_error("cannot evaluate " + [&] { std::ostringstream o; o << e; return o.str(); }()
                                + " to a real number");
    return cln::cl_float(cln::realpart(GiNaC::ex_to<GiNaC::numeric>(e).to_cl_N()), format);
}

/// ⌊e/2⌋ for either sign of e.
long floor_half(long e) { return e >= 0 ? e / 2 : -((1 - e) / 2); }

/// Whether |x| is at most the largest double (a CLN float has no such limit).
bool within_double_range(const cln::cl_F& x)
{
    return cln::zerop(x) || cln::float_exponent(x) <= std::numeric_limits<double>::max_exponent;
}

/// Whether x rounds to a normal double: neither overflow nor a subnormal's lost digits.
bool within_normal_range(const cln::cl_F& x)
{
    long e = cln::float_exponent(x);
    return e < std::numeric_limits<double>::max_exponent && e > std::numeric_limits<double>::min_exponent;
}

} // namespace

modes_method compiled_modes::high_precision(const double* p, double* w2, double* w, double* error, double* modes,
                                            int digits)
{
    using cln::cl_F;
    const std::size_t n = size_;
    const cln::float_format_t format = cln::float_format(digits);
    GiNaC::exmap point;
    for (std::size_t k = 0; k < parameters_.size(); ++k)
        if (used_[k])
            point[parameters_[k].symbol] = GiNaC::numeric(cln::rational(cln::cl_DF(p[k])));
    int saved = GiNaC::Digits;
    GiNaC::Digits = digits + 10;
    cln_matrix T(n, std::vector<cl_F>(n)), V = T;
    try {
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < n; ++j) {
                T[i][j] = to_cl(kinetic_(i, j).subs(point).evalf(), format);
                V[i][j] = to_cl(potential_(i, j).subs(point).evalf(), format);
            }
    } catch (...) {
        GiNaC::Digits = saved;
        throw;
    }
    GiNaC::Digits = saved;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i; j < n; ++j)
            if (!within_double_range(T[i][j]) || !within_double_range(V[i][j]))
                throw computation_error(std::string("an entry of the ") + (within_double_range(T[i][j]) ? "potential"
                                                                                                        : "kinetic")
                                        + " matrix is beyond the range of double precision at these values");
    // Equilibrate: D T D and D V D with D = diag(2^s), T's diagonal scaled into [1/4, 1).
    // Powers of two scale exactly and leave the eigenvalues as they are (the modes become
    // D⁻¹ a); without it a T whose diagonal spans many decades (m/M = 1e-300) has a
    // Cholesky factor whose conditioning, squared, swamps any precision in the error bound.
    std::vector<long> shift(n, 0);
    for (std::size_t i = 0; i < n; ++i)
        if (cln::plusp(T[i][i]))
            shift[i] = -floor_half(cln::float_exponent(T[i][i]));
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) {
            T[i][j] = cln::scale_float(T[i][j], shift[i] + shift[j]);
            V[i][j] = cln::scale_float(V[i][j], shift[i] + shift[j]);
        }
    const cln_eigen_result eigen = cln_generalized_eigen(T, V, format, modes != nullptr);
    const bool more_digits = digits < 4 * options_.digits;
    if (eigen.failed_pivot < n) {
        // a pivot within rounding: T singular, or so ill-conditioned (M = 1, m = 1e120) that
        // more digits tell
        if (more_digits)
            return high_precision(p, w2, w, error, modes, 2 * digits);
        not_positive_definite(eigen.failed_pivot, digits);
    }
    // An ω² that this precision tells from 0 (above its rounding) but whose bound would print
    // it as 0 (M = 1, m = 1e60: the bound grows with T's conditioning squared): more digits
    // give it a relative bound; at the most digits, the answer is refused rather than ω = 0.
    {
        cl_F largest = cln::cl_float(0, format);
        for (const cl_F& W : eigen.eigenvalues)
            largest = cln::max(largest, cln::abs(W));
        const cl_F rounding = largest * cln::float_epsilon(format) * cln::cl_float(64.0 * n, format);
        for (const cl_F& W : eigen.eigenvalues)
            if (cln::abs(W) > rounding &&
                (!std::isfinite(eigen.error) || cln::abs(W) <= cln::cl_float(eigen.error, format))) {
                if (more_digits)
                    return high_precision(p, w2, w, error, modes, 2 * digits);
                throw computation_error("the numeric modes cannot be computed reliably at these values: a "
                                        "frequency is not zero, but its error bound exceeds it even with "
                                        + std::to_string(digits) + " digits (the kinetic matrix is too "
                                        "ill-conditioned)");
            }
    }
    // A mode vector errs by about the rounding of K over the gap to the next eigenvalue:
    // two frequencies 1e-150 apart (m/M = 1e-300) need about 170 digits to tell their
    // modes apart, while the frequencies themselves are exact at 50.
    if (modes && more_digits) {
        cl_F largest = cln::cl_float(0, format);
        for (const cl_F& W : eigen.eigenvalues)
            largest = cln::max(largest, cln::abs(W));
        const cl_F resolved = largest * cln::float_epsilon(format) * cln::cl_float(0x1p60, format);
        for (std::size_t k = 0; k + 1 < n; ++k)
            if (eigen.eigenvalues[k + 1] - eigen.eigenvalues[k] < resolved)
                return high_precision(p, w2, w, error, modes, 2 * digits);
    }
    for (std::size_t k = 0; k < n; ++k) {
        const cl_F& W = eigen.eigenvalues[k];
        if (!cln::zerop(W) && !within_normal_range(W))
            throw computation_error("a frequency squared is beyond the range of double precision at these values");
        cl_F root = cln::sqrt(cln::abs(W));
        double rounded = cln::double_approx(root);
        double extra = rounded != 0 ? cln::double_approx(cln::abs(root - cln::cl_float(rounded, format))) / rounded : 0;
        set_frequency(cln::double_approx(W), eigen.error, extra, w2[k], w[k], error[k]);
        if (w[k] != 0)
            w[k] = std::copysign(rounded, w[k]);
    }
    if (modes)
        for (std::size_t c = 0; c < n; ++c)
            for (std::size_t i = 0; i < n; ++i) {
                double entry = std::ldexp(eigen.modes[c * n + i], static_cast<int>(shift[i]));
                if (!std::isfinite(entry) || (entry != 0 && std::abs(entry) < std::numeric_limits<double>::min()))
                    throw computation_error("a mode vector is beyond the range of double precision at these values");
                modes[c * n + i] = entry;
            }
    return modes_method::high_precision;
}

} // namespace lagrange
