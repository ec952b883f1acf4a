// SPDX-License-Identifier: GPL-2.0-or-later
/** @file double_double.h
 *  The arithmetic beneath the compiled programs and the modes kernels: double-double
 *  numbers (an unevaluated sum hi + lo, about 32 digits) and doubles with a running
 *  error bound, each step inline and branch free so that loops over points vectorize;
 *  and the run-time choice between the portable kernels and those compiled for FMA. */
#pragma once

#include <cmath>

namespace lagrange {

#if defined(__GNUC__)
#define LAGRANGE_ALWAYS_INLINE __attribute__((always_inline))
#else
#define LAGRANGE_ALWAYS_INLINE
#endif

#if defined(__GNUC__) && defined(__x86_64__)
#define LAGRANGE_HAVE_FMA_KERNELS 1
/// Kernels compiled for FMA (and so AVX) beside the portable ones, picked at run time,
/// with 128-bit vectors, which suit the loops over the batch better than 256-bit ones.
#if defined(__clang__) // Clang ignores a target attribute with prefer-vector-width in it
#define LAGRANGE_FMA_TARGET __attribute__((target("fma")))
#else
#define LAGRANGE_FMA_TARGET __attribute__((target("fma,prefer-vector-width=128")))
#endif
#else
#define LAGRANGE_HAVE_FMA_KERNELS 0
#define LAGRANGE_FMA_TARGET
#endif

/// Whether the batch kernels run their FMA versions (x86-64 CPUs with FMA, checked once
/// at run time; the binary itself does not need FMA). Both versions give the
/// same numbers bit for bit: their double-double products are exact either way.
bool fma_kernels();
/// Tests and benchmarks: force the portable kernels (false) or, where the CPU has them,
/// the FMA ones (true). Process-wide.
void use_fma_kernels(bool on);

/// Unit roundoff of double (round to nearest).
constexpr double unit_roundoff = 0x1p-53;

/// A double with a bound on its absolute error (running error analysis, to first
/// order plus the second-order product term): the true value lies in
/// [value − error, value + error] as long as nothing overflows or underflows.
struct bounded_double {
    double value = 0;
    double error = 0;
};

/// An unevaluated sum hi + lo with |lo| ≤ ½ ulp(hi): about 32 significant digits.
struct double_double {
    double hi = 0;
    double lo = 0;
};

// ---- double-double arithmetic (Dekker, Knuth; Hida–Li–Bailey's QD formulas) ----

namespace dd {

LAGRANGE_ALWAYS_INLINE inline double_double two_sum(double a, double b)
{
    double s = a + b;
    double bb = s - a;
    return {s, (a - (s - bb)) + (b - bb)};
}

LAGRANGE_ALWAYS_INLINE inline double_double quick_two_sum(double a, double b)
{
    double s = a + b;
    return {s, b - (s - a)};
}

/// a·b = p + e exactly (barring overflow and underflow). `fused`: e from one FMA, for code
/// compiled for FMA (see fma_kernels()); otherwise Dekker's splitting. Both give the same
/// exact e, so the two kernels agree bit for bit.
template <bool fused = false>
LAGRANGE_ALWAYS_INLINE inline double_double two_prod(double a, double b)
{
    double p = a * b;
    if constexpr (fused) {
        return {p, __builtin_fma(a, b, -p)};
    } else {
        constexpr double splitter = 134217729.0; // 2^27 + 1
        double ta = splitter * a, tb = splitter * b;
        double ahi = ta - (ta - a), alo = a - ahi;
        double bhi = tb - (tb - b), blo = b - bhi;
        return {p, ((ahi * bhi - p) + ahi * blo + alo * bhi) + alo * blo};
    }
}

LAGRANGE_ALWAYS_INLINE inline double_double add(double_double a, double_double b)
{
    double_double s = two_sum(a.hi, b.hi);
    double_double t = two_sum(a.lo, b.lo);
    s.lo += t.hi;
    s = quick_two_sum(s.hi, s.lo);
    s.lo += t.lo;
    return quick_two_sum(s.hi, s.lo);
}

LAGRANGE_ALWAYS_INLINE inline double_double neg(double_double a) { return {-a.hi, -a.lo}; }
LAGRANGE_ALWAYS_INLINE inline double_double sub(double_double a, double_double b) { return add(a, neg(b)); }

template <bool fused = false>
LAGRANGE_ALWAYS_INLINE inline double_double mul(double_double a, double_double b)
{
    double_double p = two_prod<fused>(a.hi, b.hi);
    p.lo += a.hi * b.lo + a.lo * b.hi;
    return quick_two_sum(p.hi, p.lo);
}

/// a/b: DWDivDW2 of Joldes, Muller and Popescu (ACM TOMS 44(2), 2017, Algorithm 17),
/// relative error within 15u² + 56u³, with their DWTimesFP1 for b·q (the same bits with
/// and without FMA: its only product error term is exact either way). Two divisions and a
/// dozen additions, against three divisions and three accurate sums of QD's formula.
template <bool fused = false>
LAGRANGE_ALWAYS_INLINE inline double_double div(double_double a, double_double b)
{
    double th = a.hi / b.hi;
    double_double c = two_prod<fused>(b.hi, th); // (rh, rl) = b·th, DWTimesFP1
    double_double t = quick_two_sum(c.hi, b.lo * th);
    double_double r = quick_two_sum(t.hi, t.lo + c.lo);
    double delta = (a.hi - r.hi) + (a.lo - r.lo);
    return quick_two_sum(th, delta / b.hi);
}

/// √a: SQRTDWtoDW (Lefèvre, Louvet, Muller, Picot, Rideau, IEEE TC 2023), relative error
/// within 25/8 u²: a.hi − s² is exactly representable (s the rounded √a.hi), so both
/// subtractions below are exact, with FMA or without. For a ≤ 0 the double √a.hi (+0 for
/// ±0). Branch free, so that loops over points vectorize.
template <bool fused = false>
LAGRANGE_ALWAYS_INLINE inline double_double sqrt(double_double a)
{
    double s = std::sqrt(a.hi);
    double_double p = two_prod<fused>(s, s);
    double r = ((a.hi - p.hi) - p.lo) + a.lo;
    double_double result = quick_two_sum(s, r / (2 * s));
    bool positive = a.hi > 0;
    return {positive ? result.hi : (a.hi == 0 ? 0.0 : s), positive ? result.lo : 0.0};
}

inline double_double from(double a) { return {a, 0}; }

} // namespace dd

// ---- running error bounds: the interpreter's steps, also for hand-written formulas ----

namespace running {

inline bounded_double add(bounded_double a, bounded_double b)
{
    double v = a.value + b.value;
    return {v, a.error + b.error + unit_roundoff * std::abs(v)};
}

inline bounded_double neg(bounded_double a) { return {-a.value, a.error}; }

inline bounded_double mul(bounded_double a, bounded_double b)
{
    double v = a.value * b.value;
    return {v, std::abs(a.value) * b.error + std::abs(b.value) * a.error + a.error * b.error
                   + unit_roundoff * std::abs(v)};
}

inline bounded_double recip(bounded_double a)
{
    double v = 1 / a.value, m = std::abs(a.value);
    double e = a.error < m ? a.error / (m * (m - a.error)) : HUGE_VAL;
    return {v, e + unit_roundoff * std::abs(v)};
}

inline bounded_double sqrt(bounded_double a)
{
    // branch free (selects), so that loops over points vectorize
    bool negative = a.value < 0 && -a.value > a.error;
    double v = std::sqrt(a.value > 0 ? a.value : 0.0);
    double low = std::sqrt(a.value - a.error > 0 ? a.value - a.error : 0.0);
    double e = v + low > 0 ? a.error / (v + low) : std::sqrt(a.error);
    return {negative ? std::sqrt(a.value) : v, negative ? HUGE_VAL : e + unit_roundoff * v};
}

} // namespace running

} // namespace lagrange
