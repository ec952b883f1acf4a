/** @file expression_program.h
 *  Straight-line numeric code compiled once from GiNaC expressions in a fixed list
 *  of symbols: a postfix instruction list with common subexpressions shared, run
 *  many times in double, in double with a running error bound, or in double-double. */
#pragma once

#include <ginac/ginac.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace lagrange {

#if defined(__GNUC__)
#define LAGRANGE_ALWAYS_INLINE __attribute__((always_inline))
#else
#define LAGRANGE_ALWAYS_INLINE
#endif

#if defined(__GNUC__) && defined(__x86_64__)
#define LAGRANGE_HAVE_FMA_KERNELS 1
/// Kernels compiled for FMA (and so AVX) beside the portable ones, picked at run time.
/// 128-bit vectors: on the development machine the 256-bit loops over the batch ran at
/// half the speed of 128-bit ones (measured with bench/numeric_modes).
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

/// One step of a program; operands are earlier slots.
struct instruction {
    enum class code { constant, symbol, add, mul, neg, recip, square_root, integer_power, real_power,
                      sine, cosine, exponential, logarithm };
    code op = code::constant;
    int first = 0;          ///< operand slot (or symbol index)
    int second = 0;         ///< second operand slot, or the exponent of integer_power
    double value = 0;       ///< constant (rounded) or real exponent
    double value_low = 0;   ///< constant: the next 53 bits (value + value_low is the double-double)
    double value_error = 0; ///< constant: |exact − value|
};

/// What is known of a slot before it runs, where every symbol it reads is positive: its
/// sign, and a bound on the relative error of its double-double value. Both are known for
/// slots built from symbols and constants by +, ×, ÷, √ and integer powers without adding
/// terms of opposite sign (subtraction-free: no cancellation, so every step only adds its
/// own rounding). Each double-double step is taken to round within 2^-99 relative, eight
/// times the published bounds of these algorithms (at most 16u², Joldes–Muller–Popescu,
/// ACM TOMS 44(2), 2017), and as long as no value under- or overflows (run_batch_a_priori
/// checks that on every point).
struct a_priori_bound {
    bool known = false;
    int sign = 0;         ///< −1, 0 or +1, where known
    double relative = 0;  ///< |computed − exact| ≤ relative·|exact|, where known
};

/// One rounding of a double-double step in a priori bounds (see a_priori_bound).
constexpr double double_double_step = 0x1p-99;
/// Below this a double-double's low part loses bits to underflow; above it Dekker's
/// splitting or a product overflows. A priori bounds need every value in between.
constexpr double a_priori_smallest = 0x1p-968;
constexpr double a_priori_largest = 0x1p995;
/// Whether a magnitude lies in that range (false for NaN). Without branches, for vectorized loops.
LAGRANGE_ALWAYS_INLINE inline bool in_a_priori_range(double magnitude)
{
    return (magnitude >= a_priori_smallest) & (magnitude <= a_priori_largest);
}

/// Compiled from `outputs`, a list of expressions in `symbols`; throws
/// std::invalid_argument naming any other symbol or unsupported function.
class expression_program {
public:
    expression_program() = default;
    expression_program(const std::vector<GiNaC::ex>& outputs, const std::vector<GiNaC::ex>& symbols);

    std::size_t output_count() const { return outputs_.size(); }
    std::size_t instruction_count() const { return code_.size(); }
    /// Only + − × ÷, integer powers and square roots: double-double evaluation keeps
    /// its ~32 digits and the bound scales with the unit roundoff.
    bool algebraic() const { return algebraic_; }

    /// Whether the program takes any sine or cosine.
    bool trigonometric() const;

    /// The program as a C function `static void NAME(const double* symbols, double* out)`
    /// (straight-line code, constants exact as hexadecimal floats), for native compilation.
    /// `sleef_sincos`: its sines and cosines four arguments at a time by SLEEF's AVX2
    /// sincos (its 3.5-ulp one; the source then needs sleef_declarations, AVX2 and
    /// -lsleef): arguments that need no sine or cosine are evaluated first, so each batch
    /// holds all the arguments of its nesting depth. Without it, libm's sin and cos.
    std::string c_source(const std::string& name, bool sleef_sincos = false) const;
    /// The C declarations that code from c_source(…, true) needs: SLEEF's function with its
    /// types spelled as GCC vectors (the same ABI as <sleef.h>'s __m256d, without
    /// <immintrin.h>, whose parsing alone took 0.5 s of each compilation).
    static const char* sleef_declarations();

    /// Runs the program on the symbol values; `scratch` is resized as needed.
    void run(const double* symbols, std::vector<double>& scratch, double* out) const;
    void run(const double* symbols, std::vector<bounded_double>& scratch, bounded_double* out) const;
    void run(const double* symbols, std::vector<double_double>& scratch, double_double* out) const;

    /// Runs the program on `count` points at once (at most batch_size), in double-double
    /// and with running error bounds together, structure of arrays: point j's symbols start
    /// at symbols + j·stride; output k of point j goes to out[k·4·batch_size + j] (hi),
    /// [.. + batch_size + j] (lo), [.. + 2·batch_size + j] (value of the bounded run) and
    /// [.. + 3·batch_size + j] (its error bound). One dispatch per instruction for the
    /// whole batch instead of one per point; the loops over points vectorize (with FMA
    /// products where the CPU has them, see fma_kernels()).
    static constexpr std::size_t batch_size = 32;
    void run_batch(const double* symbols, std::size_t stride, std::size_t count, std::vector<double>& scratch,
                   double* out) const;

    /// A priori bound of output k (see a_priori_bound).
    const a_priori_bound& output_bound(std::size_t k) const { return output_bounds_[k]; }
    /// What a point's run says of the a priori bounds.
    enum class a_priori_status : unsigned char {
        holds,        ///< every symbol positive, every slot of known sign in range
        not_positive, ///< a symbol the program reads is not positive (or not a number): no a priori bounds
        out_of_range, ///< a slot of known sign left [2^-968, 2^995]: under- or overflow, no bounds at all
    };
    /// As run_batch, in double-double only: no running bound is computed (the a priori
    /// bound of output k is output_bound(k).relative·|value|). outputs[k] is set to output
    /// k's lanes in `scratch`: hi at outputs[k][j], lo at outputs[k][batch_size + j].
    /// status[j] says whether point j's bounds hold.
    void run_batch_a_priori(const double* symbols, std::size_t stride, std::size_t count,
                            std::vector<double>& scratch, const double** outputs, a_priori_status* status) const;
    /// The status of a point from the slots a double-double run() left in `scratch`.
    a_priori_status check_a_priori(const std::vector<double_double>& scratch) const;

private:
    std::vector<instruction> code_;
    std::vector<int> outputs_; ///< slot of each output
    bool algebraic_ = true;
    std::vector<a_priori_bound> bounds_;        ///< of each slot
    std::vector<a_priori_bound> output_bounds_; ///< of each output
    std::vector<std::size_t> symbol_slots_;     ///< the slots that read a symbol
    /// The slots the range check covers: of known, nonzero sign and not constant.
    std::vector<std::size_t> checked_slots_;
    /// Symbols all in this range: no slot of known sign can leave its range (a fast check).
    std::pair<double, double> safe_symbols_{HUGE_VAL, 0};
    /// status of each point from every slot of known sign (the full check)
    void check_block(const double* slots, std::size_t count, a_priori_status* status) const;
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
