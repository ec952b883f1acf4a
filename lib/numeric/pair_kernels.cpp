// SPDX-License-Identifier: GPL-2.0-or-later
/** @file pair_kernels.cpp
 *  The closed-form kernels of compiled_modes: one coordinate lane by lane, two on a
 *  block of lanes with selects instead of branches (the loops vectorize), compiled
 *  twice, portable and for CPUs with FMA; both give the same bits. */
#include "numeric/pair_kernels.h"

#include "program/expression_program.h"

#include <cmath>
#include <cstddef>
#include <type_traits>

namespace lagrange {

namespace {

/// set_frequency without branches (selects), for the vectorized closed form; the same
/// numbers. ω is the double-double √|w| rounded, `extra` its rounding.
LAGRANGE_ALWAYS_INLINE inline void set_frequency_select(double w, double dw, double extra, double omega_hi,
                                                        double& w2, double& omega, double& error)
{
    double m = std::abs(w);
    bool zero = m <= (dw > 0 ? dw : 0.0); // m <= dw || m == 0, in a form that vectorizes
    w2 = zero ? 0.0 : w;
    omega = zero ? 0.0 : std::copysign(omega_hi, w);
    error = zero ? std::sqrt(dw) : (root_relative_error(dw, m) + extra) * (1 + 1e-6);
}

/// a where c holds, else b, without a branch (the loops over lanes vectorize).
LAGRANGE_ALWAYS_INLINE inline double_double select(bool c, double_double a, double_double b)
{
    return {c ? a.hi : b.hi, c ? a.lo : b.lo};
}
LAGRANGE_ALWAYS_INLINE inline bounded_double select(bool c, bounded_double a, bounded_double b)
{
    return {c ? a.value : b.value, c ? a.error : b.error};
}

/// ω = √|W| in double-double; `extra` the relative error of ω rounded to double (plus the
/// square root's own, within 2^-100).
template <bool fused>
LAGRANGE_ALWAYS_INLINE inline double_double root_of(double_double W, double& extra)
{
    double_double omega = dd::sqrt<fused>(select(W.hi < 0, dd::neg(W), W));
    extra = omega.hi != 0 ? std::abs(omega.lo) / omega.hi + 0x1p-100 : 0;
    return omega;
}

/// One root W (with bound) to ω², ω and the error bound of lane j's mode k.
template <bool fused>
LAGRANGE_ALWAYS_INLINE inline void pair_root(double_double W, bounded_double Wb, double scale, double& w2, double& w,
                                             double& error)
{
    double extra;
    double_double omega = root_of<fused>(W, extra);
    set_frequency_select(W.hi, Wb.error * scale, extra, omega.hi, w2, w, error);
}

/// The same with an a priori bound: ω's relative error is within `omega_bound` (plus its
/// rounding to double); W = 0 only where it may be exactly, and then so is its error. (That
/// W stayed in range is checked after the loop, which then vectorizes.)
template <bool fused>
LAGRANGE_ALWAYS_INLINE inline void pair_root_a_priori(double_double W, double omega_bound, double& w2, double& w,
                                                      double& error)
{
    double extra;
    double_double omega = root_of<fused>(W, extra);
    bool zero = W.hi == 0;
    w2 = zero ? 0.0 : W.hi;
    w = zero ? 0.0 : std::copysign(omega.hi, W.hi);
    error = zero ? 0.0 : (omega_bound + extra) * (1 + 1e-6);
}

/// The two-coordinate closed form on the lanes of a block laid out as expression_program::
/// run_batch leaves it (output k, lane j: hi at o[4kB + j], lo at +B, the bounded run's
/// value at +2B and its error bound at +3B). Outputs: [k·2 + i] for lane k. All B lanes are
/// computed (fixed trip count, no branches: the loop vectorizes).
/// a W² − b W + c = 0 (outputs a, b, c, b² − 4ac): the root of larger magnitude without
/// cancellation, the other by Vieta, in double-double; the error bound runs beside.
template <bool fused, std::size_t B, bool a_priori>
LAGRANGE_ALWAYS_INLINE inline void pair_frequencies(const double* const* at, double scale,
                                                    a_priori_constants constants, double* __restrict w2,
                                                    double* __restrict w, double* __restrict error,
                                                    double* __restrict root_hi, double* __restrict root_lo)
{
    const double* o[4] = {at[0], at[1], at[2], at[3]};
    for (std::size_t j = 0; j < B; ++j) {
        auto X = [&](std::size_t k) { return double_double{o[k][j], o[k][B + j]}; };
        auto Y = [&](std::size_t k) { return bounded_double{o[k][2 * B + j], o[k][3 * B + j]}; };
        double_double x0 = X(0), x1 = X(1), x2 = X(2), x3 = X(3);
        bool negative_b = x1.hi < 0;
        double_double root = dd::sqrt<fused>(select(x3.hi > 0, x3, double_double{}));
        double_double q = dd::add(x1, select(negative_b, dd::neg(root), root));
        double_double big = dd::div<fused>(q, {2 * x0.hi, 2 * x0.lo}); // 2a, 2c: exact
        bool has_q = q.hi != 0;
        double_double small = select(has_q, dd::div<fused>({2 * x2.hi, 2 * x2.lo}, q), double_double{});
        bool swap = big.hi < small.hi;
        double_double first = select(swap, big, small), second = select(swap, small, big);
        if constexpr (a_priori) {
            pair_root_a_priori<fused>(first, constants.omega_bound, w2[2 * j], w[2 * j], error[2 * j]);
            pair_root_a_priori<fused>(second, constants.omega_bound, w2[2 * j + 1], w[2 * j + 1], error[2 * j + 1]);
        } else {
            bounded_double b0 = Y(0), b1 = Y(1), b2 = Y(2), b3 = Y(3);
            bounded_double root_b = running::sqrt(select(b3.value > 0, b3, bounded_double{0, b3.error}));
            bounded_double q_b = running::add(b1, select(negative_b, running::neg(root_b), root_b));
            bounded_double big_b = running::mul(q_b, running::recip(running::add(b0, b0)));
            bounded_double small_b = select(has_q, running::mul(running::add(b2, b2), running::recip(q_b)),
                                            bounded_double{0, big_b.error});
            bounded_double first_b = select(swap, big_b, small_b), second_b = select(swap, small_b, big_b);
            pair_root<fused>(first, first_b, scale, w2[2 * j], w[2 * j], error[2 * j]);
            pair_root<fused>(second, second_b, scale, w2[2 * j + 1], w[2 * j + 1], error[2 * j + 1]);
        }
        root_hi[2 * j] = first.hi;
        root_lo[2 * j] = first.lo;
        root_hi[2 * j + 1] = second.hi;
        root_lo[2 * j + 1] = second.lo;
    }
}

/// Mode k of each lane is orthogonal to the larger row of V − W T, then scaled so that
/// aᵀ T a = 1 (T = [[x4, x5], [x5, x6]], V = [[x7, x8], [x8, x9]]). Selects, no
/// branches: the loop over lanes vectorizes. Modes of lane j at modes[4j…4j+3].
template <bool fused, std::size_t B>
LAGRANGE_ALWAYS_INLINE inline void pair_modes(const double* const* at, const double* __restrict root_hi,
                                              const double* __restrict root_lo, const double* __restrict w2,
                                              double* __restrict modes)
{
    const double* o[10] = {at[0], at[1], at[2], at[3], at[4], at[5], at[6], at[7], at[8], at[9]};
    for (std::size_t j = 0; j < B; ++j) {
        auto X = [&](std::size_t k) { return double_double{o[k][j], o[k][B + j]}; };
        bool equal = w2[2 * j] == w2[2 * j + 1];
        auto mode = [&](auto constant) LAGRANGE_ALWAYS_INLINE { // k = 0, 1 unrolled: the lane loop vectorizes
            constexpr int k = decltype(constant)::value;
            double_double W{root_hi[2 * j + k], root_lo[2 * j + k]};
            auto entry = [&](std::size_t v, std::size_t t) { return dd::sub(X(v), dd::mul<fused>(W, X(t))); };
            double_double r11 = entry(7, 4), r12 = entry(8, 5), r22 = entry(9, 6);
            double n1 = std::max(std::abs(r11.hi), std::abs(r12.hi)), n2 = std::max(std::abs(r12.hi), std::abs(r22.hi));
            // V = W T (both rows zero, or a double root): any T-orthonormal pair
            bool degenerate = std::max(n1, n2) == 0;
            if constexpr (k == 1)
                degenerate = degenerate | equal;
            bool first_row = n1 >= n2;
            double_double a0 = select(first_row, dd::neg(r12), dd::neg(r22));
            double_double a1 = select(first_row, r11, r12);
            if constexpr (k == 0) {
                a0 = select(degenerate, dd::from(1), a0);
                a1 = select(degenerate, dd::from(0), a1);
            } else {
                a0 = select(degenerate, dd::neg(dd::div<fused>(X(5), X(4))), a0);
                a1 = select(degenerate, dd::from(1), a1);
            }
            double_double norm = dd::add(dd::add(dd::mul<fused>(dd::mul<fused>(a0, a0), X(4)),
                                                 dd::mul<fused>(dd::mul<fused>(a1, a1), X(6))),
                                         dd::mul<fused>(dd::mul<fused>(dd::add(a0, a0), a1), X(5)));
            double_double scale_by = dd::div<fused>(dd::from(1), dd::sqrt<fused>(norm));
            modes[4 * j + 2 * k] = dd::mul<fused>(a0, scale_by).hi;
            modes[4 * j + 2 * k + 1] = dd::mul<fused>(a1, scale_by).hi;
        };
        mode(std::integral_constant<int, 0>{});
        mode(std::integral_constant<int, 1>{});
    }
}

/// Lane j's results go out where use[j] is not skip (use null: every lane).
template <bool fused, std::size_t B, bool a_priori>
LAGRANGE_ALWAYS_INLINE inline void pair_block_kernel(const double* const* o, std::size_t count, double scale,
                                                     a_priori_constants constants, const lane_use* use,
                                                     double* w2, double* w, double* error, double* modes)
{
    alignas(32) double lane_w2[2 * B], lane_w[2 * B], lane_error[2 * B], root_hi[2 * B], root_lo[2 * B];
    alignas(32) double lane_modes[4 * B];
    pair_frequencies<fused, B, a_priori>(o, scale, constants, lane_w2, lane_w, lane_error, root_hi, root_lo);
    if constexpr (a_priori)
        for (std::size_t i = 0; i < 2 * count; ++i) { // a root out of range (NaN included): no bound
            double m = std::abs(root_hi[i]);
            if (!in_a_priori_range(m) && !(m == 0 && constants.zero_root))
                lane_error[i] = HUGE_VAL;
        }
    if (modes)
        pair_modes<fused, B>(o, root_hi, root_lo, lane_w2, lane_modes);
    for (std::size_t j = 0; j < count; ++j) {
        if (use && use[j] == lane_use::skip)
            continue;
        for (std::size_t i = 0; i < 2; ++i) {
            w2[2 * j + i] = lane_w2[2 * j + i];
            w[2 * j + i] = lane_w[2 * j + i];
            error[2 * j + i] = lane_error[2 * j + i];
        }
        if (modes)
            for (std::size_t i = 0; i < 4; ++i)
                modes[4 * j + i] = lane_modes[4 * j + i];
    }
}

template <bool fused, bool a_priori>
LAGRANGE_ALWAYS_INLINE inline void pair_block_any(const double* const* o, std::size_t B, std::size_t count, double scale,
                                                  a_priori_constants constants, const lane_use* use, double* w2,
                                                  double* w, double* error, double* modes)
{
    // one point, or a whole batch: the same arithmetic per lane
    if (B == 1)
        pair_block_kernel<fused, 1, a_priori>(o, count, scale, constants, use, w2, w, error, modes);
    else
        pair_block_kernel<fused, expression_program::batch_size, a_priori>(o, count, scale, constants, use, w2, w,
                                                                            error, modes);
}

void pair_block_portable(const double* const* o, std::size_t B, std::size_t count, double scale,
                         const a_priori_constants* constants, const lane_use* use, double* w2, double* w,
                         double* error, double* modes)
{
    if (constants)
        pair_block_any<false, true>(o, B, count, scale, *constants, use, w2, w, error, modes);
    else
        pair_block_any<false, false>(o, B, count, scale, {}, use, w2, w, error, modes);
}

#if LAGRANGE_HAVE_FMA_KERNELS
LAGRANGE_FMA_TARGET void pair_block_fma(const double* const* o, std::size_t B, std::size_t count, double scale,
                                        const a_priori_constants* constants, const lane_use* use, double* w2,
                                        double* w, double* error, double* modes)
{
    if (constants)
        pair_block_any<true, true>(o, B, count, scale, *constants, use, w2, w, error, modes);
    else
        pair_block_any<true, false>(o, B, count, scale, {}, use, w2, w, error, modes);
}
#endif

} // namespace

void pair_block(const double* const* o, std::size_t B, std::size_t count, double scale,
                const a_priori_constants* constants, const lane_use* use, double* w2, double* w, double* error,
                double* modes)
{
#if LAGRANGE_HAVE_FMA_KERNELS
    if (fma_kernels()) {
        pair_block_fma(o, B, count, scale, constants, use, w2, w, error, modes);
        return;
    }
#endif
    pair_block_portable(o, B, count, scale, constants, use, w2, w, error, modes);
}

void single_lane(double_double T, double_double V, bounded_double T_bounded, bounded_double V_bounded, double scale,
                 double& w2, double& w, double& error, double* mode)
{
    double_double W = dd::div(V, T);
    bounded_double Wb = running::mul(V_bounded, running::recip(T_bounded));
    double dw = Wb.error * scale;
    double extra;
    double_double omega = root_of<false>(W, extra);
    set_frequency(W.hi, dw, extra, w2, w, error);
    if (w != 0)
        w = std::copysign(omega.hi, W.hi);
    if (mode)
        *mode = 1 / dd::sqrt(T).hi;
}

} // namespace lagrange
