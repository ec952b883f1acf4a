/** @file expression_program.h
 *  Straight-line numeric code compiled once from GiNaC expressions in a fixed list
 *  of symbols: a postfix instruction list with common subexpressions shared, run
 *  many times in double, in double with a running error bound, or in double-double. */
#pragma once

#include <ginac/ginac.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace lagrange {

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

    /// The program as a C function `static void NAME(const double* symbols, double* out)`
    /// (straight-line code, constants exact as hexadecimal floats), for native compilation.
    std::string c_source(const std::string& name) const;

    /// Runs the program on the symbol values; `scratch` is resized as needed.
    void run(const double* symbols, std::vector<double>& scratch, double* out) const;
    void run(const double* symbols, std::vector<bounded_double>& scratch, bounded_double* out) const;
    void run(const double* symbols, std::vector<double_double>& scratch, double_double* out) const;

    /// Runs the program on `count` points at once (at most batch_size), in double-double
    /// and with running error bounds together: point j's symbols start at
    /// symbols + j·stride; output k of point j goes to dd_out[k·batch_size + j] and
    /// bounded_out[k·batch_size + j]. One dispatch per instruction for the whole
    /// batch instead of one per point (the loops over points vectorize).
    static constexpr std::size_t batch_size = 32;
    void run_batch(const double* symbols, std::size_t stride, std::size_t count, std::vector<double_double>& dd_scratch,
                   std::vector<bounded_double>& bounded_scratch, double_double* dd_out,
                   bounded_double* bounded_out) const;

private:
    std::vector<instruction> code_;
    std::vector<int> outputs_; ///< slot of each output
    bool algebraic_ = true;
};

// ---- double-double arithmetic (Dekker, Knuth; Hida–Li–Bailey's QD formulas) ----

namespace dd {

inline double_double two_sum(double a, double b)
{
    double s = a + b;
    double bb = s - a;
    return {s, (a - (s - bb)) + (b - bb)};
}

inline double_double quick_two_sum(double a, double b)
{
    double s = a + b;
    return {s, b - (s - a)};
}

inline double_double two_prod(double a, double b)
{
    constexpr double splitter = 134217729.0; // 2^27 + 1
    double p = a * b;
    double ta = splitter * a, tb = splitter * b;
    double ahi = ta - (ta - a), alo = a - ahi;
    double bhi = tb - (tb - b), blo = b - bhi;
    return {p, ((ahi * bhi - p) + ahi * blo + alo * bhi) + alo * blo};
}

inline double_double add(double_double a, double_double b)
{
    double_double s = two_sum(a.hi, b.hi);
    double_double t = two_sum(a.lo, b.lo);
    s.lo += t.hi;
    s = quick_two_sum(s.hi, s.lo);
    s.lo += t.lo;
    return quick_two_sum(s.hi, s.lo);
}

inline double_double neg(double_double a) { return {-a.hi, -a.lo}; }
inline double_double sub(double_double a, double_double b) { return add(a, neg(b)); }

inline double_double mul(double_double a, double_double b)
{
    double_double p = two_prod(a.hi, b.hi);
    p.lo += a.hi * b.lo + a.lo * b.hi;
    return quick_two_sum(p.hi, p.lo);
}

inline double_double div(double_double a, double_double b)
{
    double q1 = a.hi / b.hi;
    double_double r = sub(a, mul(b, {q1, 0}));
    double q2 = r.hi / b.hi;
    r = sub(r, mul(b, {q2, 0}));
    double q3 = r.hi / b.hi;
    return add(quick_two_sum(q1, q2), {q3, 0});
}

inline double_double sqrt(double_double a)
{
    if (a.hi <= 0)
        return {a.hi == 0 ? 0.0 : std::sqrt(a.hi), 0};
    double s = std::sqrt(a.hi);
    double_double r = sub(a, two_prod(s, s));
    return quick_two_sum(s, r.hi / (2 * s));
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
    if (a.value < 0 && -a.value > a.error)
        return {std::sqrt(a.value), HUGE_VAL};
    double v = std::sqrt(a.value > 0 ? a.value : 0.0);
    double low = std::sqrt(a.value - a.error > 0 ? a.value - a.error : 0.0);
    double e = v + low > 0 ? a.error / (v + low) : std::sqrt(a.error);
    return {v, e + unit_roundoff * v};
}

} // namespace running

} // namespace lagrange
