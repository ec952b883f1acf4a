// SPDX-License-Identifier: GPL-2.0-or-later
/** @file expression_program.cpp
 *  Compiling GiNaC expressions to a postfix instruction list and running it (its C
 *  source for native compilation: c_source.cpp).
 *  Written by hand: GiNaC's own evaluation (subs + evalf) walks the tree with
 *  arbitrary-precision numbers, and the JIT libraries that compile expressions need a
 *  compiler or LLVM at run time; a program here is a few dozen instructions run in a
 *  switch loop. */
#include "program/expression_program.h"

#include "algebra/canonical_order.h"

#include <cln/cln.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <unordered_map>
#include <sstream>
#include <stdexcept>

namespace lagrange {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

/// Builds the instruction list, one slot per distinct subexpression.
class compiler {
public:
    compiler(const std::vector<GiNaC::ex>& symbols, const std::vector<GiNaC::ex>& invariant,
             std::vector<instruction>& code, bool& algebraic)
        : symbols_(symbols), code_(code), algebraic_(algebraic)
    {
        if (!invariant.empty())
            for (const GiNaC::ex& s : symbols)
                if (std::none_of(invariant.begin(), invariant.end(), [&](const GiNaC::ex& i) { return i.is_equal(s); }))
                    variant_.push_back(s);
    }

    int slot(const GiNaC::ex& e) { return value(e, false); }

    /// Compiles a definition: its symbol reads the slot of its value from now on.
    void define(const program_definition& d)
    {
        if (!GiNaC::is_a<GiNaC::symbol>(d.symbol))
            throw std::invalid_argument("a definition names a symbol");
        const int s = slot(d.value);
        defined_.emplace(d.symbol, s);
        if (!variant_.empty() && !is_invariant(d.value))
            variant_.push_back(d.symbol);
    }

private:
    /// The slot of e, or of −e: the same subexpression, sum or product, with either sign,
    /// is compiled once. Sums add their terms in canonical order, and a sum that is a
    /// factor is taken with its canonical sign (canonical_order.h), so that the program,
    /// and the rounding of its floating-point operations, is the same in every process
    /// whatever order and signs GiNaC chose.
    int value(const GiNaC::ex& e, bool negate)
    {
        std::string key = keys_.key(e, negate);
        auto found = memo_.find(key);
        if (found != memo_.end())
            return found->second;
        int result = GiNaC::is_a<GiNaC::add>(e) ? sum(e, negate) : term(e, negate);
        memo_.emplace(std::move(key), result);
        return result;
    }

    int sum(const GiNaC::ex& e, bool negate)
    {
        std::vector<std::pair<std::string, GiNaC::ex>> terms;
        for (const GiNaC::ex& t : e)
            terms.emplace_back(keys_.term(t).rest, t);
        std::sort(terms.begin(), terms.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        int result = -1;
        for (const auto& [key, t] : terms) {
            int s = value(t, negate);
            result = result < 0 ? s : binary(instruction::code::add, result, s);
        }
        return result;
    }

    int term(const GiNaC::ex& t, bool negate)
    {
        if (GiNaC::is_a<GiNaC::numeric>(t))
            return constant(negate ? -GiNaC::ex_to<GiNaC::numeric>(t) : GiNaC::ex_to<GiNaC::numeric>(t));
        GiNaC::numeric coefficient = 1;
        std::vector<std::pair<std::string, GiNaC::ex>> factors;
        const GiNaC::exvector operands = GiNaC::is_a<GiNaC::mul>(t) ? GiNaC::exvector(t.begin(), t.end())
                                                                     : GiNaC::exvector{t};
        for (const GiNaC::ex& f : operands) {
            if (GiNaC::is_a<GiNaC::numeric>(f)) {
                coefficient *= GiNaC::ex_to<GiNaC::numeric>(f);
                continue;
            }
            canonical_factor c = keys_.factor(f);
            negate = negate != c.negative;
            factors.emplace_back(c.key, f);
        }
        if (negate)
            coefficient = -coefficient;
        std::stable_sort(factors.begin(), factors.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        const bool unit = coefficient == 1 || coefficient == -1;
        std::size_t invariant = 0;
        for (const auto& [key, f] : factors)
            invariant += is_invariant(f) ? 1 : 0;
        // With a coefficient or more than one invariant factor, and some that vary: those first.
        const bool split = invariant > (unit ? 1 : 0) && invariant < factors.size();
        int product = unit || split ? -1 : constant(coefficient);
        if (split) {
            GiNaC::ex part = unit ? GiNaC::ex(1) : GiNaC::ex(coefficient);
            for (const auto& [key, f] : factors)
                if (is_invariant(f))
                    part *= keys_.factor(f).negative ? -f : f;
            product = value(part, false);
        }
        for (const auto& [key, f] : factors) {
            if (split && is_invariant(f))
                continue;
            int s = factor(f);
            product = product < 0 ? s : binary(instruction::code::mul, product, s);
        }
        if (product < 0)
            product = constant(GiNaC::numeric(1));
        return coefficient == -1 ? unary(instruction::code::neg, product) : product;
    }

    /// Whether e reads symbols, and none that varies between evaluations (false when no
    /// symbol was named invariant).
    bool is_invariant(const GiNaC::ex& e) const
    {
        return !variant_.empty() &&
               std::none_of(variant_.begin(), variant_.end(), [&](const GiNaC::ex& s) { return e.has(s); });
    }

    /// The slot of a factor taken with its canonical sign.
    int factor(const GiNaC::ex& f)
    {
        if (GiNaC::is_a<GiNaC::add>(f))
            return value(f, keys_.sum(f).negative);
        std::string key = keys_.key(f);
        auto found = memo_.find(key);
        if (found != memo_.end())
            return found->second;
        int result = build(f);
        memo_.emplace(std::move(key), result);
        return result;
    }

    int emit(instruction i)
    {
        code_.push_back(i);
        return static_cast<int>(code_.size()) - 1;
    }

    int constant(const GiNaC::numeric& n)
    {
        if (!n.is_real())
            throw std::invalid_argument("the complex number " + to_text(n) + " cannot be evaluated as a real");
        cln::cl_RA exact = cln::rational(cln::realpart(n.to_cl_N()));
        instruction i;
        i.op = instruction::code::constant;
        i.value = cln::double_approx(exact);
        cln::cl_RA rest = exact - cln::rational(cln::cl_DF(i.value));
        i.value_low = cln::double_approx(rest);
        i.value_error = std::abs(i.value_low) * (1 + 4 * unit_roundoff);
        return emit(i);
    }

    int unary(instruction::code op, int operand, int second = 0, double value = 0)
    {
        instruction i;
        i.op = op;
        i.first = operand;
        i.second = second;
        i.value = value;
        return emit(i);
    }

    int binary(instruction::code op, int a, int b)
    {
        instruction i;
        i.op = op;
        i.first = a;
        i.second = b;
        return emit(i);
    }

    int build(const GiNaC::ex& e)
    {
        using code = instruction::code;
        if (GiNaC::is_a<GiNaC::numeric>(e))
            return constant(GiNaC::ex_to<GiNaC::numeric>(e));
        if (GiNaC::is_a<GiNaC::constant>(e)) {
            int saved = GiNaC::Digits;
            GiNaC::Digits = 40;
            GiNaC::ex value = e.evalf();
            GiNaC::Digits = saved;
            return constant(GiNaC::ex_to<GiNaC::numeric>(value));
        }
        if (GiNaC::is_a<GiNaC::symbol>(e)) {
            if (auto found = defined_.find(e); found != defined_.end())
                return found->second;
            for (std::size_t k = 0; k < symbols_.size(); ++k)
                if (e.is_equal(symbols_[k])) {
                    instruction i;
                    i.op = code::symbol;
                    i.first = static_cast<int>(k);
                    return emit(i);
                }
            throw std::invalid_argument("the symbol `" + to_text(e) + "` is not a parameter");
        }
        if (GiNaC::is_a<GiNaC::power>(e)) {
            GiNaC::ex exponent = e.op(1);
            // A sum to an integer power is the power of the sum with its canonical sign
            // (factor() has put the sign in the term's coefficient).
            const bool canonical_base = GiNaC::is_a<GiNaC::add>(e.op(0)) && exponent.info(GiNaC::info_flags::integer);
            int base = canonical_base ? factor(e.op(0)) : slot(e.op(0));
            if (GiNaC::is_a<GiNaC::numeric>(exponent)) {
                GiNaC::numeric p = GiNaC::ex_to<GiNaC::numeric>(exponent);
                GiNaC::numeric twice = p * 2;
                if (twice.is_integer()) {
                    long whole = twice.to_long();
                    bool inverse = whole < 0;
                    whole = std::abs(whole);
                    if (whole % 2 == 1)
                        base = unary(code::square_root, base);
                    else
                        whole /= 2;
                    int result = whole == 1 ? base : unary(code::integer_power, base, static_cast<int>(whole));
                    return inverse ? unary(code::recip, result) : result;
                }
                if (p.is_real()) {
                    algebraic_ = false;
                    return unary(code::real_power, base, 0, p.to_double());
                }
            }
            throw std::invalid_argument("the power " + to_text(e) + " has no real numeric exponent");
        }
        if (GiNaC::is_a<GiNaC::function>(e) && e.nops() == 1) {
            // the conjugate of a real is itself; of anything else, not a real function
            if (is_ex_the_function(e, GiNaC::conjugate_function) && e.op(0).info(GiNaC::info_flags::real))
                return slot(e.op(0));
            if (is_ex_the_function(e, GiNaC::abs)) // exact in every arithmetic: stays algebraic
                return unary(code::absolute, slot(e.op(0)));
            int argument = slot(e.op(0));
            algebraic_ = false;
            if (is_ex_the_function(e, GiNaC::sin))
                return unary(code::sine, argument);
            if (is_ex_the_function(e, GiNaC::cos))
                return unary(code::cosine, argument);
            if (is_ex_the_function(e, GiNaC::exp))
                return unary(code::exponential, argument);
            if (is_ex_the_function(e, GiNaC::log))
                return unary(code::logarithm, argument);
            if (is_ex_the_function(e, GiNaC::tan)) // tan u = sin u / cos u
                return binary(code::mul, unary(code::sine, argument),
                              unary(code::recip, unary(code::cosine, argument)));
            if (is_ex_the_function(e, GiNaC::sinh))
                return unary(code::hyperbolic_sine, argument);
            if (is_ex_the_function(e, GiNaC::cosh))
                return unary(code::hyperbolic_cosine, argument);
            if (is_ex_the_function(e, GiNaC::tanh))
                return unary(code::hyperbolic_tangent, argument);
            if (is_ex_the_function(e, GiNaC::asin))
                return unary(code::arcsine, argument);
            if (is_ex_the_function(e, GiNaC::acos))
                return unary(code::arccosine, argument);
            if (is_ex_the_function(e, GiNaC::atan))
                return unary(code::arctangent, argument);
        }
        throw std::invalid_argument("cannot evaluate " + to_text(e) + " numerically");
    }

    static std::string to_text(const GiNaC::ex& e)
    {
        std::ostringstream out;
        out << e;
        return out.str();
    }

    const std::vector<GiNaC::ex>& symbols_;
    std::vector<instruction>& code_;
    bool& algebraic_;
    /// Slots by the canonical key of their value: one slot for a value however GiNaC
    /// wrote it (lookups only, never iterated).
    std::unordered_map<std::string, int> memo_;
    canonical_keys keys_;
    std::vector<GiNaC::ex> variant_; ///< the symbols not named invariant, when some are
    std::map<GiNaC::ex, int, GiNaC::ex_is_less> defined_; ///< the slot of each defined symbol
};

// ---- the three arithmetics, as overloads the interpreter picks from ----

double make_constant(const instruction& i, double*) { return i.value; }
bounded_double make_constant(const instruction& i, bounded_double*) { return {i.value, i.value_error}; }
double_double make_constant(const instruction& i, double_double*) { return {i.value, i.value_low}; }

double add(double a, double b) { return a + b; }
double mul(double a, double b) { return a * b; }
double neg(double a) { return -a; }
double recip(double a) { return 1 / a; }
double square_root(double a) { return std::sqrt(a); }
double real_power(double a, double p) { return std::pow(a, p); }
double sine(double a) { return std::sin(a); }
double cosine(double a) { return std::cos(a); }
double exponential(double a) { return std::exp(a); }
double logarithm(double a) { return std::log(a); }
double hyperbolic_sine(double a) { return std::sinh(a); }
double hyperbolic_cosine(double a) { return std::cosh(a); }
double hyperbolic_tangent(double a) { return std::tanh(a); }
double arcsine(double a) { return std::asin(a); }
double arccosine(double a) { return std::acos(a); }
double arctangent(double a) { return std::atan(a); }
double absolute(double a) { return std::fabs(a); }

bounded_double add(bounded_double a, bounded_double b) { return running::add(a, b); }
bounded_double mul(bounded_double a, bounded_double b) { return running::mul(a, b); }
bounded_double neg(bounded_double a) { return running::neg(a); }
bounded_double recip(bounded_double a) { return running::recip(a); }
bounded_double square_root(bounded_double a) { return running::sqrt(a); }
bounded_double real_power(bounded_double a, double p)
{
    double v = std::pow(a.value, p), m = std::abs(a.value);
    double e = a.error < m ? std::abs(v) * std::abs(p) * a.error / (m - a.error) * 2 : infinity;
    return {v, e + 2 * unit_roundoff * std::abs(v)};
}
bounded_double sine(bounded_double a) { return {std::sin(a.value), a.error + 2 * unit_roundoff}; }
bounded_double cosine(bounded_double a) { return {std::cos(a.value), a.error + 2 * unit_roundoff}; }
bounded_double exponential(bounded_double a)
{
    double v = std::exp(a.value);
    return {v, v * std::expm1(a.error) * 1.01 + 2 * unit_roundoff * v};
}
bounded_double logarithm(bounded_double a)
{
    double v = std::log(a.value), m = std::abs(a.value);
    double e = a.error < m ? -std::log1p(-a.error / m) * 1.01 : infinity;
    return {v, e + 2 * unit_roundoff * std::abs(v) + unit_roundoff};
}
// The error of an argument x̂ ± e carried through f is at most e·max |f′| over the interval
// (mean value theorem), times 1.01 for the roundings of that product; 0 where e is, NaN where
// e is. libm's own rounding: glibc documents at most 2 ulps for sinh, cosh and tanh and 1 for
// asin, acos and atan; twice that is allowed, an ulp being at most 2u·|value|.
constexpr double hyperbolic_rounding = 8 * unit_roundoff, inverse_rounding = 4 * unit_roundoff;
bounded_double hyperbolic_sine(bounded_double a)
{
    // |sinh′| = cosh, largest at the end of the interval farthest from 0
    double v = std::sinh(a.value);
    double e = a.error == 0 ? 0.0 : a.error * std::cosh(std::abs(a.value) + a.error) * 1.01;
    return {v, e + hyperbolic_rounding * std::abs(v)};
}
bounded_double hyperbolic_cosine(bounded_double a)
{
    // |cosh′| = |sinh|, largest at the end of the interval farthest from 0
    double v = std::cosh(a.value);
    double e = a.error == 0 ? 0.0 : a.error * std::sinh(std::abs(a.value) + a.error) * 1.01;
    return {v, e + hyperbolic_rounding * v};
}
/// The smallest |t| in [x̂ − e, x̂ + e]: where |tanh′| and |atan′|, which fall with |t|, are largest.
double nearest_zero(bounded_double a) { return std::max(std::abs(a.value) - a.error, 0.0); }
bounded_double hyperbolic_tangent(bounded_double a)
{
    // |tanh′| = 1/cosh², at most 1; and tanh lies in (−1, 1), so no error exceeds 2
    double v = std::tanh(a.value), c = std::cosh(nearest_zero(a));
    double e = a.error == 0 ? 0.0 : std::min(a.error / (c * c) * 1.01, 2.0);
    return {v, e + hyperbolic_rounding * std::abs(v)};
}
bounded_double arctangent(bounded_double a)
{
    // |atan′| = 1/(1 + t²), at most 1; and atan lies in (−π/2, π/2)
    double v = std::atan(a.value), d = nearest_zero(a);
    double e = a.error == 0 ? 0.0 : std::min(a.error / (1 + d * d) * 1.01, 3.2);
    return {v, e + inverse_rounding * std::abs(v)};
}
/// The error an argument's error makes in asin or acos, whose derivatives ±1/√(1 − t²) grow
/// without bound towards ±1: e/√(1 − D²) with D = |x̂| + e rounded up, at most π (the width of
/// their ranges); infinite where the interval reaches ±1, since the exact argument may lie
/// beyond, where neither is real.
double arcsine_propagated(bounded_double a)
{
    if (a.error == 0)
        return 0.0;
    double far = std::nextafter(std::abs(a.value) + a.error, infinity); // NaN for NaN
    return far < 1 ? std::min(a.error / std::sqrt((1 - far) * (1 + far)) * 1.01, 3.2) : infinity;
}
bounded_double arcsine(bounded_double a)
{
    double v = std::asin(a.value);
    return {v, arcsine_propagated(a) + inverse_rounding * std::abs(v)};
}
bounded_double arccosine(bounded_double a)
{
    double v = std::acos(a.value);
    return {v, arcsine_propagated(a) + inverse_rounding * std::abs(v)};
}
bounded_double absolute(bounded_double a) { return {std::fabs(a.value), a.error}; } // ||x| − |x̂|| ≤ |x − x̂|

double_double add(double_double a, double_double b) { return dd::add(a, b); }
double_double mul(double_double a, double_double b) { return dd::mul(a, b); }
double_double neg(double_double a) { return dd::neg(a); }
double_double recip(double_double a) { return dd::div({1, 0}, a); }
double_double square_root(double_double a) { return dd::sqrt(a); }
// Transcendental steps keep only double accuracy (the program is then not algebraic()).
double_double real_power(double_double a, double p)
{
    double v = std::pow(a.hi, p);
    return dd::two_sum(v, v * p * a.lo / a.hi);
}
double_double sine(double_double a) { return dd::two_sum(std::sin(a.hi), std::cos(a.hi) * a.lo); }
double_double cosine(double_double a) { return dd::two_sum(std::cos(a.hi), -std::sin(a.hi) * a.lo); }
double_double exponential(double_double a)
{
    double v = std::exp(a.hi);
    return dd::two_sum(v, v * a.lo);
}
double_double logarithm(double_double a) { return dd::two_sum(std::log(a.hi), a.lo / a.hi); }
double_double hyperbolic_sine(double_double a) { return dd::two_sum(std::sinh(a.hi), std::cosh(a.hi) * a.lo); }
double_double hyperbolic_cosine(double_double a) { return dd::two_sum(std::cosh(a.hi), std::sinh(a.hi) * a.lo); }
double_double hyperbolic_tangent(double_double a)
{
    double t = std::tanh(a.hi);
    return dd::two_sum(t, (1 - t) * (1 + t) * a.lo);
}
double_double arctangent(double_double a) { return dd::two_sum(std::atan(a.hi), a.lo / (1 + a.hi * a.hi)); }
/// asin and acos in double-double. Below |hi| = 3/4 the first-order term. Beyond, where the
/// derivatives grow without bound and the low part may be as large as a quarter of 1 − |hi|,
/// from w = 1 − |x| (1 − |hi| is exact there, and two_sum takes the low part off exactly):
/// acos |x| = 2 asin √(w/2), within a few u relative, and asin |x| = π/2 − acos |x|. An
/// argument past ±1 by its low part alone (w < 0) is taken as ±1, the value the double run
/// reads; past ±1 by its high part, NaN.
constexpr double_double half_pi{0x1.921fb54442d18p0, 0x1.1a62633145c07p-54};
double acos_of_magnitude(double_double a)
{
    const double_double w = dd::two_sum(1 - std::abs(a.hi), a.hi < 0 ? a.lo : -a.lo);
    return 2 * std::asin(std::sqrt(std::max(w.hi + w.lo, 0.0) / 2));
}
double_double arcsine(double_double a)
{
    if (!(std::abs(a.hi) >= 0.75) || std::abs(a.hi) > 1)
        return dd::two_sum(std::asin(a.hi), a.lo / std::sqrt((1 - a.hi) * (1 + a.hi)));
    const double_double r = dd::add(half_pi, {-acos_of_magnitude(a), 0});
    return a.hi < 0 ? dd::neg(r) : r;
}
double_double arccosine(double_double a)
{
    if (!(std::abs(a.hi) >= 0.75) || std::abs(a.hi) > 1)
        return dd::two_sum(std::acos(a.hi), -a.lo / std::sqrt((1 - a.hi) * (1 + a.hi)));
    const double r = acos_of_magnitude(a);
    return a.hi < 0 ? dd::add(dd::add(half_pi, half_pi), {-r, 0}) : double_double{r, 0};
}
// exact: the double-double of |x|, keeping its ~32 digits
double_double absolute(double_double a) { return {std::fabs(a.hi), a.hi < 0 ? -a.lo : a.lo}; }

template <class number>
number integer_power(number base, int exponent)
{
    number result{};
    bool first = true;
    while (exponent > 0) {
        if (exponent & 1) {
            result = first ? base : mul(result, base);
            first = false;
        }
        exponent >>= 1;
        if (exponent > 0)
            base = mul(base, base);
    }
    return result;
}

// ---- a priori bounds (see a_priori_bound) ----

/// Rounds a bound up past the rounding of its own computation in double.
double up(double relative) { return relative * (1 + 0x1p-30); }

/// (1 + r)·(1 + double_double_step) − 1, the bound after one more rounding.
double one_more_rounding(double r) { return up(r + double_double_step + r * double_double_step); }

a_priori_bound unknown_bound() { return {}; }

a_priori_bound bound_of(const instruction& i, const std::vector<a_priori_bound>& slots)
{
    using op = instruction::code;
    const a_priori_bound a = reads_first_slot(i.op) ? slots.at(static_cast<std::size_t>(i.first)) : a_priori_bound{};
    switch (i.op) {
    case op::constant:
        // value + value_low is within 2^-106 of the exact constant when value_low ≠ 0
        return {true, i.value > 0 ? 1 : (i.value < 0 ? -1 : 0), i.value_error == 0 ? 0.0 : double_double_step};
    case op::symbol: return {true, 1, 0};
    case op::neg: return a.known ? a_priori_bound{true, -a.sign, a.relative} : unknown_bound();
    case op::add: {
        const a_priori_bound& b = slots.at(static_cast<std::size_t>(i.second));
        if (!a.known || !b.known || a.sign * b.sign < 0)
            return unknown_bound(); // terms of opposite sign may cancel
        return {true, a.sign != 0 ? a.sign : b.sign, one_more_rounding(std::max(a.relative, b.relative))};
    }
    case op::mul: {
        const a_priori_bound& b = slots.at(static_cast<std::size_t>(i.second));
        if (!a.known || !b.known)
            return unknown_bound();
        if (a.sign == 0 || b.sign == 0)
            return {true, 0, 0};
        return {true, a.sign * b.sign, one_more_rounding(up(a.relative + b.relative + a.relative * b.relative))};
    }
    case op::recip:
        // 1/(x(1 + θ)) = (1/x)(1 − θ/(1 + θ)), |θ/(1 + θ)| ≤ r/(1 − r)
        if (!a.known || a.sign == 0 || a.relative > 0.5)
            return unknown_bound();
        return {true, a.sign, one_more_rounding(up(a.relative / (1 - a.relative)))};
    case op::square_root:
        // |√(1 + θ) − 1| ≤ r/(2 − r) for |θ| ≤ r ≤ 1
        if (!a.known || a.sign < 0 || a.relative > 0.5)
            return unknown_bound();
        return {true, a.sign, one_more_rounding(up(a.relative / (2 - a.relative)))};
    case op::integer_power: {
        if (!a.known)
            return unknown_bound();
        int n = i.second;
        if (a.sign == 0)
            return {true, 0, 0};
        // x^n (1 + θ)^n, then one rounding per product of integer_power()
        int products = 0;
        for (int e = n, first = 1; e > 0; e >>= 1) {
            if (e & 1) {
                products += first ? 0 : 1;
                first = 0;
            }
            if (e > 1)
                ++products;
        }
        double r = up(std::expm1(n * std::log1p(a.relative)));
        for (int k = 0; k < products; ++k)
            r = one_more_rounding(r);
        return {true, n % 2 == 0 ? 1 : a.sign, r};
    }
    case op::absolute:
        // |x(1 + θ)| = |x|(1 + θ): the same relative error
        return a.known ? a_priori_bound{true, a.sign != 0 ? 1 : 0, a.relative} : unknown_bound();
    case op::real_power:
    case op::sine:
    case op::cosine:
    case op::exponential:
    case op::logarithm:
    case op::hyperbolic_sine:
    case op::hyperbolic_cosine:
    case op::hyperbolic_tangent:
    case op::arcsine:
    case op::arccosine:
    case op::arctangent: return unknown_bound();
    }
    return unknown_bound();
}

/// Where each slot's magnitude lies when every symbol lies in [2^−t, 2^t]:
/// log2 |value| ∈ [low − low_slope·t, high + high_slope·t] (slots of known sign only).
/// From it, the widest such t in which no slot can leave [a_priori_smallest,
/// a_priori_largest]: inside it, checking the symbols is enough.
struct magnitude {
    double low = 0, low_slope = 0, high = 0, high_slope = 0;
};

double widest_safe_exponent(const std::vector<instruction>& code, const std::vector<a_priori_bound>& bounds)
{
    using op = instruction::code;
    constexpr double margin = 0x1p-10; // bits, per step: roundings and the relative errors
    const double floor_bits = std::log2(a_priori_smallest) + 8, ceiling_bits = std::log2(a_priori_largest) - 8;
    std::vector<magnitude> m(code.size());
    double widest = 1000;
    for (std::size_t k = 0; k < code.size(); ++k) {
        const instruction& i = code[k];
        if (!bounds[k].known || bounds[k].sign == 0)
            continue; // never checked (zeros are exact; unknown slots have no bound to keep)
        const magnitude a = reads_first_slot(i.op) ? m.at(static_cast<std::size_t>(i.first)) : magnitude{};
        const magnitude b = reads_second_slot(i.op) ? m.at(static_cast<std::size_t>(i.second)) : magnitude{};
        magnitude& r = m[k];
        switch (i.op) {
        case op::constant: r.low = r.high = std::log2(std::abs(i.value)); break;
        case op::symbol: r.low_slope = r.high_slope = 1; break;
        case op::neg:
        case op::absolute: r = a; break;
        case op::add: {
            // terms of one sign: at least either term, at most twice the larger
            const bool a_zero = bounds.at(static_cast<std::size_t>(i.first)).sign == 0;
            const bool b_zero = bounds.at(static_cast<std::size_t>(i.second)).sign == 0;
            if (a_zero || b_zero) {
                r = a_zero ? b : a;
                break;
            }
            const magnitude& lower = a.low_slope < b.low_slope || (a.low_slope == b.low_slope && a.low > b.low) ? a : b;
            r.low = lower.low;
            r.low_slope = lower.low_slope;
            r.high = std::max(a.high, b.high) + 1;
            r.high_slope = std::max(a.high_slope, b.high_slope);
            break;
        }
        case op::mul: r = {a.low + b.low, a.low_slope + b.low_slope, a.high + b.high, a.high_slope + b.high_slope}; break;
        case op::recip: r = {-a.high, a.high_slope, -a.low, a.low_slope}; break;
        case op::square_root: r = {a.low / 2, a.low_slope / 2, a.high / 2, a.high_slope / 2}; break;
        case op::integer_power: {
            double n = i.second;
            r = {a.low * n, a.low_slope * n, a.high * n, a.high_slope * n};
            break;
        }
        default: return 0; // not of known sign (unreachable)
        }
        r.low -= margin;
        r.high += margin;
        if (r.low < floor_bits || r.high > ceiling_bits)
            return 0; // out of range at t = 0 already: check every point in full
        if (r.low_slope > 0)
            widest = std::min(widest, (r.low - floor_bits) / r.low_slope);
        if (r.high_slope > 0)
            widest = std::min(widest, (ceiling_bits - r.high) / r.high_slope);
    }
    return std::floor(widest);
}

template <class number>
number from_symbol(double v);
template <>
double from_symbol<double>(double v) { return v; }
template <>
bounded_double from_symbol<bounded_double>(double v) { return {v, 0}; }
template <>
double_double from_symbol<double_double>(double v) { return {v, 0}; }

template <class number>
void interpret(const std::vector<instruction>& code, const std::vector<int>& outputs, const double* symbols,
               std::vector<number>& slots, number* out)
{
    using op = instruction::code;
    slots.resize(code.size());
    number* s = slots.data();
    for (std::size_t k = 0; k < code.size(); ++k) {
        const instruction& i = code[k];
        switch (i.op) {
        case op::constant: s[k] = make_constant(i, static_cast<number*>(nullptr)); break;
        case op::symbol: s[k] = from_symbol<number>(symbols[i.first]); break;
        case op::add: s[k] = add(s[i.first], s[i.second]); break;
        case op::mul: s[k] = mul(s[i.first], s[i.second]); break;
        case op::neg: s[k] = neg(s[i.first]); break;
        case op::recip: s[k] = recip(s[i.first]); break;
        case op::square_root: s[k] = square_root(s[i.first]); break;
        case op::integer_power: s[k] = integer_power(s[i.first], i.second); break;
        case op::real_power: s[k] = real_power(s[i.first], i.value); break;
        case op::sine: s[k] = sine(s[i.first]); break;
        case op::cosine: s[k] = cosine(s[i.first]); break;
        case op::exponential: s[k] = exponential(s[i.first]); break;
        case op::logarithm: s[k] = logarithm(s[i.first]); break;
        case op::hyperbolic_sine: s[k] = hyperbolic_sine(s[i.first]); break;
        case op::hyperbolic_cosine: s[k] = hyperbolic_cosine(s[i.first]); break;
        case op::hyperbolic_tangent: s[k] = hyperbolic_tangent(s[i.first]); break;
        case op::arcsine: s[k] = arcsine(s[i.first]); break;
        case op::arccosine: s[k] = arccosine(s[i.first]); break;
        case op::arctangent: s[k] = arctangent(s[i.first]); break;
        case op::absolute: s[k] = absolute(s[i.first]); break;
        }
    }
    for (std::size_t k = 0; k < outputs.size(); ++k)
        out[k] = s[outputs[k]];
}

/// One instruction over a batch of points, structure of arrays: slot k holds
/// [hi × B, lo × B, value × B, error × B] (`bounded`), or [hi × B, lo × B] (double-double
/// only). All B lanes are computed (lanes past the batch's count read symbols of 1, and
/// their results are never read back), so the loops have a fixed trip count and no
/// branches, and vectorize.
template <bool fused, bool bounded>
LAGRANGE_ALWAYS_INLINE inline void step_batch(const instruction& i, std::size_t k, const double* symbols,
                                              std::size_t stride, std::size_t count, double* s)
{
    using op = instruction::code;
    constexpr std::size_t B = expression_program::batch_size;
    constexpr std::size_t width = bounded ? 4 * B : 2 * B;
    constexpr std::size_t run = bounded ? 2 * B : 0; // offset of the bounded run (itself when none)
    double* __restrict th = s + k * width;
    double* __restrict tl = th + B;
    double* __restrict tv = th + run;
    double* __restrict te = th + run + (bounded ? B : 0);
    const double* __restrict ah = s + static_cast<std::size_t>(i.first) * width;
    const double* __restrict al = ah + B;
    const double* __restrict av = ah + run;
    const double* __restrict ae = ah + run + (bounded ? B : 0);
    const double* __restrict bh = s + static_cast<std::size_t>(i.second) * width;
    const double* __restrict bl = bh + B;
    const double* __restrict bv = bh + run;
    const double* __restrict be = bh + run + (bounded ? B : 0);
    auto put = [&](std::size_t j, double_double x, bounded_double y) LAGRANGE_ALWAYS_INLINE {
        th[j] = x.hi;
        tl[j] = x.lo;
        if constexpr (bounded) {
            tv[j] = y.value;
            te[j] = y.error;
        }
    };
    // without the bounded run, its steps are dead code and compiled away
    auto A = [&](std::size_t j) { return double_double{ah[j], al[j]}; };
    auto Ab = [&](std::size_t j) { return bounded ? bounded_double{av[j], ae[j]} : bounded_double{}; };
    auto Bd = [&](std::size_t j) { return double_double{bh[j], bl[j]}; };
    auto Bb = [&](std::size_t j) { return bounded ? bounded_double{bv[j], be[j]} : bounded_double{}; };
    switch (i.op) {
    case op::constant: {
        double_double c = make_constant(i, static_cast<double_double*>(nullptr));
        bounded_double d = make_constant(i, static_cast<bounded_double*>(nullptr));
        for (std::size_t j = 0; j < B; ++j)
            put(j, c, d);
        break;
    }
    case op::symbol:
        for (std::size_t j = 0; j < B; ++j) {
            double v = j < count ? symbols[j * stride + static_cast<std::size_t>(i.first)] : 1.0;
            put(j, {v, 0}, {v, 0});
        }
        break;
    case op::add:
        for (std::size_t j = 0; j < B; ++j)
            put(j, dd::add(A(j), Bd(j)), running::add(Ab(j), Bb(j)));
        break;
    case op::mul:
        for (std::size_t j = 0; j < B; ++j)
            put(j, dd::mul<fused>(A(j), Bd(j)), running::mul(Ab(j), Bb(j)));
        break;
    case op::neg:
        for (std::size_t j = 0; j < B; ++j)
            put(j, dd::neg(A(j)), running::neg(Ab(j)));
        break;
    case op::recip:
        for (std::size_t j = 0; j < B; ++j)
            put(j, dd::div<fused>({1, 0}, A(j)), running::recip(Ab(j)));
        break;
    case op::square_root:
        for (std::size_t j = 0; j < B; ++j)
            put(j, dd::sqrt<fused>(A(j)), running::sqrt(Ab(j)));
        break;
    case op::integer_power: {
        // integer_power()'s products in its order (binary powering), in lockstep over the
        // lanes: the exponent is the same for all, so each product is one vectorized loop.
        // The running power is kept in the target slot, the squared base here.
        alignas(64) double xh[B], xl[B], xv[B], xe[B];
        auto X = [&](std::size_t j) { return double_double{xh[j], xl[j]}; };
        auto Xb = [&](std::size_t j) { return bounded_double{xv[j], xe[j]}; };
        auto T = [&](std::size_t j) { return double_double{th[j], tl[j]}; };
        auto Tb = [&](std::size_t j) { return bounded ? bounded_double{tv[j], te[j]} : bounded_double{}; };
        for (std::size_t j = 0; j < B; ++j) {
            xh[j] = ah[j];
            xl[j] = al[j];
            xv[j] = bounded ? av[j] : 0.0;
            xe[j] = bounded ? ae[j] : 0.0;
        }
        bool first = true;
        for (int e = i.second; e > 0;) {
            if (e & 1) {
                if (first)
                    for (std::size_t j = 0; j < B; ++j)
                        put(j, X(j), Xb(j));
                else
                    for (std::size_t j = 0; j < B; ++j)
                        put(j, dd::mul<fused>(T(j), X(j)), running::mul(Tb(j), Xb(j)));
                first = false;
            }
            e >>= 1;
            if (e > 0)
                for (std::size_t j = 0; j < B; ++j) {
                    double_double x = dd::mul<fused>(X(j), X(j));
                    bounded_double y = running::mul(Xb(j), Xb(j));
                    xh[j] = x.hi;
                    xl[j] = x.lo;
                    if constexpr (bounded) {
                        xv[j] = y.value;
                        xe[j] = y.error;
                    }
                }
        }
        break;
    }
    // not algebraic: double accuracy only, no vectorization needed
    case op::real_power:
        for (std::size_t j = 0; j < B; ++j)
            put(j, real_power(A(j), i.value), real_power(Ab(j), i.value));
        break;
    case op::sine: for (std::size_t j = 0; j < B; ++j) put(j, sine(A(j)), sine(Ab(j))); break;
    case op::cosine: for (std::size_t j = 0; j < B; ++j) put(j, cosine(A(j)), cosine(Ab(j))); break;
    case op::exponential: for (std::size_t j = 0; j < B; ++j) put(j, exponential(A(j)), exponential(Ab(j))); break;
    case op::logarithm: for (std::size_t j = 0; j < B; ++j) put(j, logarithm(A(j)), logarithm(Ab(j))); break;
    case op::hyperbolic_sine:
        for (std::size_t j = 0; j < B; ++j)
            put(j, hyperbolic_sine(A(j)), hyperbolic_sine(Ab(j)));
        break;
    case op::hyperbolic_cosine:
        for (std::size_t j = 0; j < B; ++j)
            put(j, hyperbolic_cosine(A(j)), hyperbolic_cosine(Ab(j)));
        break;
    case op::hyperbolic_tangent:
        for (std::size_t j = 0; j < B; ++j)
            put(j, hyperbolic_tangent(A(j)), hyperbolic_tangent(Ab(j)));
        break;
    case op::arcsine: for (std::size_t j = 0; j < B; ++j) put(j, arcsine(A(j)), arcsine(Ab(j))); break;
    case op::arccosine: for (std::size_t j = 0; j < B; ++j) put(j, arccosine(A(j)), arccosine(Ab(j))); break;
    case op::arctangent: for (std::size_t j = 0; j < B; ++j) put(j, arctangent(A(j)), arctangent(Ab(j))); break;
    // exact, and algebraic: vectorized as the steps above
    case op::absolute: for (std::size_t j = 0; j < B; ++j) put(j, absolute(A(j)), absolute(Ab(j))); break;
    }
}

template <bool fused, bool bounded>
LAGRANGE_ALWAYS_INLINE inline void run_batch_kernel(const std::vector<instruction>& code, const double* symbols,
                                                    std::size_t stride, std::size_t count, double* s)
{
    for (std::size_t k = 0; k < code.size(); ++k)
        step_batch<fused, bounded>(code[k], k, symbols, stride, count, s);
}

template <bool bounded>
void run_batch_portable(const std::vector<instruction>& code, const double* symbols, std::size_t stride,
                        std::size_t count, double* s)
{
    run_batch_kernel<false, bounded>(code, symbols, stride, count, s);
}

#if LAGRANGE_HAVE_FMA_KERNELS
template <bool bounded>
LAGRANGE_FMA_TARGET void run_batch_fma(const std::vector<instruction>& code, const double* symbols,
                                       std::size_t stride, std::size_t count, double* s)
{
    run_batch_kernel<true, bounded>(code, symbols, stride, count, s);
}
#endif

template <bool bounded>
void run_batch_any(const std::vector<instruction>& code, const double* symbols, std::size_t stride,
                   std::size_t count, double* s)
{
#if LAGRANGE_HAVE_FMA_KERNELS
    if (fma_kernels()) {
        run_batch_fma<bounded>(code, symbols, stride, count, s);
        return;
    }
#endif
    run_batch_portable<bounded>(code, symbols, stride, count, s);
}

} // namespace

void expression_program::run_batch(const double* symbols, std::size_t stride, std::size_t count,
                                   std::vector<double>& scratch, double* out) const
{
    constexpr std::size_t B = batch_size;
    count = std::min(count, B);
    scratch.resize(code_.size() * 4 * B);
    double* s = scratch.data();
    run_batch_any<true>(code_, symbols, stride, count, s);
    for (std::size_t k = 0; k < outputs_.size(); ++k) {
        const double* from = s + static_cast<std::size_t>(outputs_[k]) * 4 * B;
        std::copy(from, from + 4 * B, out + k * 4 * B);
    }
}

void expression_program::run_batch_a_priori(const double* symbols, std::size_t stride, std::size_t count,
                                            std::vector<double>& scratch, const double** outputs,
                                            a_priori_status* status) const
{
    constexpr std::size_t B = batch_size;
    count = std::min(count, B);
    scratch.resize(code_.size() * 2 * B);
    double* s = scratch.data();
    run_batch_any<false>(code_, symbols, stride, count, s);
    // symbols in the range where no slot can leave its own (widest_safe_exponent): all hold
    const double low = safe_symbols_.first, high = safe_symbols_.second;
    double unsafe = 0;
    for (std::size_t k : symbol_slots_) {
        const double* __restrict x = s + k * 2 * B;
        for (std::size_t j = 0; j < B; ++j) // lanes past count hold 1 (see step_batch)
            unsafe += ((x[j] >= low) & (x[j] <= high)) ? 0.0 : 1.0;
    }
    if (unsafe == 0)
        std::fill(status, status + count, a_priori_status::holds);
    else
        check_block(s, count, status);
    for (std::size_t k = 0; k < outputs_.size(); ++k)
        outputs[k] = s + static_cast<std::size_t>(outputs_[k]) * 2 * B;
}

void expression_program::check_block(const double* s, std::size_t count, a_priori_status* status) const
{
    constexpr std::size_t B = batch_size;
    // every slot of known sign: symbols positive, values in range (NaN, from a symbol or an
    // overflow inside a double-double step, included); flags per lane, so that it vectorizes
    alignas(64) double not_positive[B], out_of_range[B];
    std::fill(not_positive, not_positive + B, 0.0);
    std::fill(out_of_range, out_of_range + B, 0.0);
    for (std::size_t k : checked_slots_) {
        const double* __restrict hi = s + k * 2 * B;
        const double sign = bounds_[k].sign;
        if (code_[k].op == instruction::code::symbol)
            for (std::size_t j = 0; j < B; ++j)
                not_positive[j] = hi[j] > 0 ? not_positive[j] : 1.0;
        for (std::size_t j = 0; j < B; ++j)
            out_of_range[j] = in_a_priori_range(sign * hi[j]) ? out_of_range[j] : 1.0;
    }
    for (std::size_t j = 0; j < count; ++j)
        status[j] = not_positive[j] != 0   ? a_priori_status::not_positive
                    : out_of_range[j] != 0 ? a_priori_status::out_of_range
                                           : a_priori_status::holds;
}

expression_program::expression_program(const std::vector<program_definition>& definitions,
                                       const std::vector<GiNaC::ex>& outputs, const std::vector<GiNaC::ex>& symbols,
                                       const std::vector<GiNaC::ex>& invariant)
{
    compiler build(symbols, invariant, code_, algebraic_);
    // The same operations in every process: see compiler::value.
    for (const program_definition& d : definitions)
        build.define(d);
    for (const GiNaC::ex& e : outputs)
        outputs_.push_back(build.slot(e));
    for (const instruction& i : code_)
        bounds_.push_back(bound_of(i, bounds_));
    for (int slot : outputs_)
        output_bounds_.push_back(bounds_[static_cast<std::size_t>(slot)]);
    for (std::size_t k = 0; k < code_.size(); ++k) {
        if (code_[k].op == instruction::code::symbol)
            symbol_slots_.push_back(k);
        if (bounds_[k].known && bounds_[k].sign != 0 && code_[k].op != instruction::code::constant)
            checked_slots_.push_back(k);
    }
    double widest = widest_safe_exponent(code_, bounds_);
    safe_symbols_ = {std::exp2(-widest), std::exp2(widest)};
}

expression_program::a_priori_status expression_program::check_a_priori(
    const std::vector<double_double>& scratch) const
{
    a_priori_status status = a_priori_status::holds;
    for (std::size_t k : checked_slots_) {
        if (k >= scratch.size())
            break;
        double v = bounds_[k].sign * scratch[k].hi;
        if (code_[k].op == instruction::code::symbol && !(v > 0))
            return a_priori_status::not_positive;
        if (!in_a_priori_range(v))
            status = a_priori_status::out_of_range;
    }
    return status;
}

void expression_program::run(const double* symbols, std::vector<double>& scratch, double* out) const
{
    interpret(code_, outputs_, symbols, scratch, out);
}

void expression_program::run(const double* symbols, std::vector<bounded_double>& scratch, bounded_double* out) const
{
    interpret(code_, outputs_, symbols, scratch, out);
}

void expression_program::run(const double* symbols, std::vector<double_double>& scratch, double_double* out) const
{
    interpret(code_, outputs_, symbols, scratch, out);
}

} // namespace lagrange
