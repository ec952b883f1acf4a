/** @file simplify.cpp
 *  The canonical form of trigonometric polynomials in the coordinates (products of
 *  sines and cosines of linear combinations of the angles linearized into sums of
 *  harmonics), a compact grouping by velocities and accelerations, and the
 *  simplifier that chains them with the rewrite rules. */
#include "algebra/simplify.h"
#include "algebra/expression.h"
#include "algebra/factor.h"
#include "algebra/budget.h"

#include "algebra/harmonic.h"

#include <cln/integer.h>

#include <algorithm>
#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <set>
#include <unordered_map>
#include <utility>

namespace lagrange {

namespace {

using GiNaC::ex;
using GiNaC::exmap;
using GiNaC::exvector;
using GiNaC::numeric;

/// Coefficients of the angles in the argument of a harmonic cos(n·q), sin(n·q).
using frequency = std::vector<numeric>;

struct frequency_less {
    bool operator()(const frequency& a, const frequency& b) const
    {
        for (size_t i = 0; i < a.size(); ++i) {
            const int order = a[i].compare(b[i]);
            if (order != 0)
                return order < 0;
        }
        return false;
    }
};

struct frequency_hash {
    size_t operator()(const frequency& n) const
    {
        size_t h = n.size();
        for (const numeric& x : n)
            h = h * 1000003u ^ x.gethash();
        return h;
    }
};

struct frequency_equal {
    bool operator()(const frequency& a, const frequency& b) const
    {
        if (a.size() != b.size())
            return false;
        for (size_t i = 0; i < a.size(); ++i)
            if (!a[i].is_equal(b[i]))
                return false;
        return true;
    }
};

/// Sign of the first nonzero entry of a frequency (0 for the zero frequency).
int leading_sign(const frequency& n)
{
    for (const numeric& x : n)
        if (!x.is_zero())
            return x.is_negative() ? -1 : 1;
    return 0;
}

/// The cos and sin coefficients of one harmonic.
struct harmonic {
    ex cos_part = 0;
    ex sin_part = 0;
};

/// A trigonometric polynomial with small coefficients: harmonics by frequency, every
/// frequency zero or with a positive first nonzero entry.
using fourier_series = std::map<frequency, harmonic, frequency_less>;

/// a ± b, with a shortcut for numbers.
ex plus(const ex& a, const ex& b, int sign)
{
    if (ex_kind_of(a) == ex_kind::number && ex_kind_of(b) == ex_kind::number) {
        const numeric& x = GiNaC::ex_to<numeric>(a);
        const numeric& y = GiNaC::ex_to<numeric>(b);
        return sign > 0 ? x.add(y) : x.sub(y);
    }
    return sign > 0 ? a + b : a - b;
}

/// Adds c·cos(n·q) + s·sin(n·q) to `series`, flipping n to its normalized sign.
void add_harmonic(fourier_series& series, frequency n, const ex& c, const ex& s)
{
    const int sign = leading_sign(n);
    if (sign < 0) {
        for (numeric& x : n)
            x = -x;
        harmonic& flipped = series[n];
        flipped.cos_part = plus(flipped.cos_part, c, +1);
        flipped.sin_part = plus(flipped.sin_part, s, -1);
        return;
    }
    harmonic& h = series[n];
    h.cos_part = plus(h.cos_part, c, +1);
    if (sign > 0)
        h.sin_part = plus(h.sin_part, s, +1);
}

frequency combine(const frequency& a, const frequency& b, int sign)
{
    frequency sum(a.size());
    for (size_t i = 0; i < a.size(); ++i)
        sum[i] = sign > 0 ? a[i] + b[i] : a[i] - b[i];
    return sum;
}

/// a·b, with a shortcut for numbers (most harmonic coefficients are rationals).
ex times(const ex& a, const ex& b)
{
    if (ex_kind_of(a) == ex_kind::number && ex_kind_of(b) == ex_kind::number)
        return GiNaC::ex_to<numeric>(a).mul(GiNaC::ex_to<numeric>(b));
    return a * b;
}

/// (a ± b)/2, with a shortcut for numbers.
ex half_sum(const ex& a, const ex& b, int sign)
{
    static const numeric half(1, 2);
    if (ex_kind_of(a) == ex_kind::number && ex_kind_of(b) == ex_kind::number) {
        const numeric& x = GiNaC::ex_to<numeric>(a);
        const numeric& y = GiNaC::ex_to<numeric>(b);
        return half.mul(sign > 0 ? x.add(y) : x.sub(y));
    }
    return half * (sign > 0 ? a + b : a - b);
}

/// Product of two trigonometric polynomials by the product-to-sum formulas.
fourier_series multiply(const fourier_series& a, const fourier_series& b)
{
    fourier_series product;
    budget_check_count(a.size() * b.size(), "a product of trigonometric sums");
    for (const auto& [p, hp] : a) {
        budget_check();
        const bool p_constant = leading_sign(p) == 0;
        for (const auto& [q, hq] : b) {
            if (p_constant) {
                add_harmonic(product, q, times(hp.cos_part, hq.cos_part), times(hp.cos_part, hq.sin_part));
                continue;
            }
            if (leading_sign(q) == 0) {
                add_harmonic(product, p, times(hp.cos_part, hq.cos_part), times(hp.sin_part, hq.cos_part));
                continue;
            }
            const ex cc = times(hp.cos_part, hq.cos_part);
            const ex ss = times(hp.sin_part, hq.sin_part);
            const ex sc = times(hp.sin_part, hq.cos_part);
            const ex cs = times(hp.cos_part, hq.sin_part);
            // cos p cos q = (cos(p-q) + cos(p+q))/2, sin p sin q = (cos(p-q) - cos(p+q))/2,
            // sin p cos q = (sin(p+q) + sin(p-q))/2, cos p sin q = (sin(p+q) - sin(p-q))/2.
            add_harmonic(product, combine(p, q, -1), half_sum(cc, ss, +1), half_sum(sc, cs, -1));
            add_harmonic(product, combine(p, q, +1), half_sum(cc, ss, -1), half_sum(sc, cs, +1));
        }
    }
    for (auto it = product.begin(); it != product.end();) {
        harmonic& h = it->second;
        if (ex_kind_of(h.cos_part) != ex_kind::number)
            h.cos_part = h.cos_part.expand();
        if (ex_kind_of(h.sin_part) != ex_kind::number)
            h.sin_part = h.sin_part.expand();
        if (h.cos_part.is_zero() && h.sin_part.is_zero())
            it = product.erase(it);
        else
            ++it;
    }
    return product;
}

bool is_positive_integer(const ex& e)
{
    return e.info(GiNaC::info_flags::posint);
}

bool is_negative_integer(const ex& e)
{
    return e.info(GiNaC::info_flags::negint);
}

bool is_sin_or_cos(const ex& e)
{
    return GiNaC::is_the_function<GiNaC::sin_SERIAL>(e) || GiNaC::is_the_function<GiNaC::cos_SERIAL>(e);
}

/// The canonical form for one list of angles.
class canonicalizer {
public:
    explicit canonicalizer(const GiNaC::lst& angles)
    {
        for (const ex& q : angles) {
            if (index_.count(q) == 0) {
                index_.emplace(q, angles_.size());
                angles_.push_back(q);
            }
        }
    }

    ex canonical(const ex& e) const
    {
        if (GiNaC::is_a<GiNaC::lst>(e) || GiNaC::is_a<GiNaC::matrix>(e)) {
            canonical_mapper mapper(*this);
            return e.map(mapper);
        }
        const ex prepared = prepare(e);
        if (!has_angle_denominator(prepared))
            return polynomial_form(prepared);
        return rational_form(prepared);
    }

private:
    bool is_angle(const ex& e) const { return (ex_kind_of(e) == ex_kind::symbol) && index_.count(e) != 0; }

    bool has_angle(const ex& e) const
    {
        if (ex_kind_of(e) == ex_kind::symbol)
            return index_.count(e) != 0;
        for (size_t i = 0; i < e.nops(); ++i)
            if (has_angle(e.op(i)))
                return true;
        return false;
    }

    /// True if the polynomial structure of `e` (sums, products, integer powers) has a
    /// negative power of something that depends on the angles.
    bool has_angle_denominator(const ex& e) const
    {
        if (ex_kind_of(e) == ex_kind::sum || ex_kind_of(e) == ex_kind::product) {
            for (size_t i = 0; i < e.nops(); ++i)
                if (has_angle_denominator(e.op(i)))
                    return true;
            return false;
        }
        if (ex_kind_of(e) == ex_kind::power) {
            if (is_negative_integer(e.op(1)))
                return has_angle(e.op(0));
            if (is_positive_integer(e.op(1)))
                return has_angle_denominator(e.op(0));
        }
        return false;
    }

    /// Splits an expanded argument into frequency·angles + offset. False if the
    /// argument is not linear in the angles with rational coefficients.
    bool linear_argument(const ex& argument, frequency& n, ex& offset) const
    {
        n.assign(angles_.size(), numeric(0));
        exvector constant_terms;
        for (const ex& term : terms_of(argument)) {
            if (is_angle(term)) {
                n[index_.at(term)] += 1;
                continue;
            }
            if (ex_kind_of(term) == ex_kind::product && term.nops() == 2) {
                const ex& factor = term.op(0);
                const ex& coefficient = term.op(1);
                if (is_angle(factor) && coefficient.info(GiNaC::info_flags::rational)) {
                    n[index_.at(factor)] += GiNaC::ex_to<numeric>(coefficient);
                    continue;
                }
            }
            if (has_angle(term))
                return false;
            constant_terms.push_back(term);
        }
        offset = sum_of(constant_terms);
        return true;
    }

    /// If `e` is sin or cos of a linear combination of the angles (not constant),
    /// its one-harmonic series; otherwise false.
    bool as_harmonic(const ex& e, fourier_series& series) const
    {
        if (!is_sin_or_cos(e))
            return false;
        frequency n;
        ex offset;
        const ex& argument = e.op(0);
        if (!linear_argument(is_angle(argument) ? argument : argument.expand(), n, offset) ||
            leading_sign(n) == 0)
            return false;
        series.clear();
        const bool is_cos = GiNaC::is_the_function<GiNaC::cos_SERIAL>(e);
        if (offset.is_zero()) {
            add_harmonic(series, n, is_cos ? 1 : 0, is_cos ? 0 : 1);
            return true;
        }
        // cos(n·q + c) = cos(c) cos(n·q) - sin(c) sin(n·q),
        // sin(n·q + c) = sin(c) cos(n·q) + cos(c) sin(n·q).
        const ex cos_offset = GiNaC::cos(offset);
        const ex sin_offset = GiNaC::sin(offset);
        if (is_cos)
            add_harmonic(series, n, cos_offset, -sin_offset);
        else
            add_harmonic(series, n, sin_offset, cos_offset);
        return true;
    }

    /// Canonicalizes what the polynomial structure treats as atoms: arguments of
    /// functions other than harmonics, bases and exponents of non-integer powers.
    ex prepare(const ex& e) const
    {
        if (ex_kind_of(e) == ex_kind::sum || ex_kind_of(e) == ex_kind::product) {
            exvector operands;
            operands.reserve(e.nops());
            bool changed = false;
            for (size_t i = 0; i < e.nops(); ++i) {
                operands.push_back(prepare(e.op(i)));
                changed = changed || !operands.back().is_equal(e.op(i));
            }
            if (!changed)
                return e;
            return (ex_kind_of(e) == ex_kind::sum) ? sum_of(operands) : product_of(operands);
        }
        if (ex_kind_of(e) == ex_kind::power) {
            if (e.op(1).info(GiNaC::info_flags::integer))
                return GiNaC::pow(prepare(e.op(0)), e.op(1));
            return GiNaC::pow(canonical(e.op(0)), canonical(e.op(1)));
        }
        if (ex_kind_of(e) == ex_kind::function) {
            fourier_series unused;
            if (as_harmonic(e, unused))
                return e;
            canonical_mapper mapper(*this);
            return e.map(mapper);
        }
        return e;
    }

    /// The product of the harmonics among the factors of `term`; the other factors go
    /// to `coefficient`. False if the term has no harmonic factor.
    bool split_term(const ex& term, exvector& coefficient, fourier_series& product) const
    {
        bool trigonometric = false;
        for (const ex& factor : factors_of(term)) {
            const fourier_series* series = harmonic_of(factor);
            int exponent = 1;
            if (series == nullptr && ex_kind_of(factor) == ex_kind::power && is_positive_integer(factor.op(1))) {
                series = harmonic_of(factor.op(0));
                exponent = GiNaC::ex_to<numeric>(factor.op(1)).to_int();
            }
            if (series == nullptr) {
                coefficient.push_back(factor);
                continue;
            }
            for (int k = 0; k < exponent; ++k) {
                product = trigonometric ? multiply(product, *series) : *series;
                trigonometric = true;
            }
        }
        return trigonometric;
    }

    /// The linearized, expanded form of a sum of products of harmonics and atoms.
    ex polynomial_form(const ex& e) const
    {
        const ex expanded = e.expand();
        if (has_compound_denominator(expanded))
            return grouped_polynomial_form(expanded);
        // Every term goes straight into one sum, whose constructor adds like terms.
        exvector result;
        for (const ex& term : terms_of(expanded)) {
            exvector coefficient;
            fourier_series product;
            if (!split_term(term, coefficient, product)) {
                result.push_back(term);
                continue;
            }
            for (const auto& [n, h] : product) {
                const harmonic& functions = functions_of(n);
                append_term(result, coefficient, h.cos_part, functions.cos_part);
                append_term(result, coefficient, h.sin_part, functions.sin_part);
            }
        }
        return sum_of(result);
    }

    /// Appends coefficient·part·function, expanded, to `result`.
    static void append_term(exvector& result, exvector coefficient, const ex& part, const ex& function)
    {
        if (part.is_zero())
            return;
        if (ex_kind_of(part) == ex_kind::number) {
            coefficient.push_back(part);
            coefficient.push_back(function);
            result.push_back(product_of(coefficient));
            return;
        }
        for (const ex& term : terms_of((product_of(coefficient) * part).expand()))
            result.push_back(term * function);
    }

    /// Like polynomial_form, but the coefficient of each harmonic is collected and put
    /// over a common denominator (for coefficients such as m/(M+m)).
    ex grouped_polynomial_form(const ex& expanded) const
    {
        struct coefficient_terms {
            exvector cos_terms;
            exvector sin_terms;
        };
        std::map<frequency, coefficient_terms, frequency_less> collected;
        const frequency zero(angles_.size(), numeric(0));
        for (const ex& term : terms_of(expanded)) {
            exvector coefficient;
            fourier_series product;
            if (!split_term(term, coefficient, product)) {
                collected[zero].cos_terms.push_back(term);
                continue;
            }
            const ex coefficient_product = product_of(coefficient);
            for (const auto& [n, h] : product) {
                coefficient_terms& target = collected[n];
                if (!h.cos_part.is_zero())
                    target.cos_terms.push_back(scaled(coefficient_product, h.cos_part));
                if (!h.sin_part.is_zero())
                    target.sin_terms.push_back(scaled(coefficient_product, h.sin_part));
            }
        }
        exvector result;
        for (const auto& [n, terms] : collected) {
            const harmonic& functions = functions_of(n);
            emit(result, terms.cos_terms, functions.cos_part);
            emit(result, terms.sin_terms, functions.sin_part);
        }
        return sum_of(result);
    }

    /// cos(n·q) and sin(n·q) (1 and 0 for n = 0), built once per frequency.
    const harmonic& functions_of(const frequency& n) const
    {
        auto found = functions_.find(n);
        if (found != functions_.end())
            return found->second;
        harmonic functions{1, 0};
        if (leading_sign(n) != 0) {
            const ex argument = angle_combination(n);
            functions = harmonic{GiNaC::cos(argument), GiNaC::sin(argument)};
        }
        return functions_.emplace(n, functions).first->second;
    }

    /// The one-harmonic series of `e` if it is sin or cos of a linear combination of
    /// the angles, else nullptr. Remembered per expression.
    const fourier_series* harmonic_of(const ex& e) const
    {
        if (ex_kind_of(e) != ex_kind::function || !is_sin_or_cos(e))
            return nullptr;
        auto& bucket = harmonics_[e.gethash()];
        for (const auto& [known, series] : bucket)
            if (known.is_equal(e))
                return series.empty() ? nullptr : &series;
        fourier_series series;
        if (!as_harmonic(e, series))
            series.clear();
        bucket.emplace_back(e, std::move(series));
        return bucket.back().second.empty() ? nullptr : &bucket.back().second;
    }

    /// A term's coefficient times a harmonic's coefficient, expanded.
    static ex scaled(const ex& coefficient, const ex& harmonic_coefficient)
    {
        if (ex_kind_of(harmonic_coefficient) == ex_kind::number)
            return coefficient * harmonic_coefficient;
        return (coefficient * harmonic_coefficient).expand();
    }

    /// Appends (sum of terms)·function, expanded, to `result`.
    static void emit(exvector& result, const exvector& terms, const ex& function)
    {
        ex coefficient = sum_of(terms);
        if (coefficient.is_zero())
            return;
        if (has_compound_denominator(coefficient)) {
            coefficient = coefficient.normal();
            for (const ex& term : terms_of((coefficient * function).expand()))
                result.push_back(term);
            return;
        }
        for (const ex& term : terms_of(coefficient))
            result.push_back(term * function);
    }

    ex angle_combination(const frequency& n) const
    {
        exvector terms;
        for (size_t i = 0; i < n.size(); ++i)
            if (!n[i].is_zero())
                terms.push_back(n[i] * angles_[i]);
        return sum_of(terms);
    }

    /// Numerator over denominator, each in canonical form, when the denominator
    /// depends on the angles. Repeats until normal() and the canonical form agree.
    ex rational_form(const ex& e) const
    {
        ex fraction = e;
        ex numerator;
        ex denominator;
        for (int round = 0; round < 4; ++round) {
            const ex parts = fraction.numer_denom();
            const ex next_numerator = polynomial_form(parts.op(0));
            const ex next_denominator = polynomial_form(parts.op(1));
            const bool stable = round > 0 && next_numerator.is_equal(numerator) &&
                                next_denominator.is_equal(denominator);
            numerator = next_numerator;
            denominator = next_denominator;
            if (stable)
                break;
            fraction = numerator / denominator;
        }
        return numerator / denominator;
    }

    /// Applies the canonical form to each operand.
    struct canonical_mapper : GiNaC::map_function {
        explicit canonical_mapper(const canonicalizer& owner) : owner_(owner) {}
        ex operator()(const ex& e) override { return owner_.canonical(e); }
        const canonicalizer& owner_;
    };

    std::map<ex, size_t, GiNaC::ex_is_less> index_;
    exvector angles_;
    mutable std::unordered_map<frequency, harmonic, frequency_hash, frequency_equal> functions_;
    mutable std::unordered_map<unsigned, std::deque<std::pair<ex, fourier_series>>> harmonics_;
};

/// The canonical form computed with harmonic polynomials, if `e` is one (sums,
/// products and integer powers of symbols and of sin/cos of integer combinations of
/// the angles): the same expression as the general path builds, much faster.
std::optional<ex> harmonic_canonical(const ex& e, const GiNaC::lst& angles)
{
    for (const ex& q : angles)
        if (ex_kind_of(q) != ex_kind::symbol)
            return std::nullopt;
    harmonic_space space(angles);
    if (!space.add_symbols_of(e))
        return std::nullopt;
    std::optional<harmonic_polynomial> p = to_harmonic(e, space);
    if (!p)
        return std::nullopt;
    return to_ex(*p);
}

/// Largest number of terms for which a coefficient is handed to GiNaC's factor().
constexpr size_t factor_term_limit = 12;

/// A monomial as base -> exponent (numeric coefficient dropped).
using monomial_exponents = std::map<ex, numeric, GiNaC::ex_is_less>;

monomial_exponents exponents_of(const ex& term)
{
    monomial_exponents exponents;
    for (const ex& factor : factors_of(term)) {
        if (ex_kind_of(factor) == ex_kind::number)
            continue;
        if (ex_kind_of(factor) == ex_kind::power && ex_kind_of(factor.op(1)) == ex_kind::number)
            exponents[factor.op(0)] += GiNaC::ex_to<numeric>(factor.op(1));
        else
            exponents[factor] += 1;
    }
    return exponents;
}

numeric coefficient_of(const ex& term)
{
    numeric c = 1;
    for (const ex& factor : factors_of(term))
        if (ex_kind_of(factor) == ex_kind::number)
            c *= GiNaC::ex_to<numeric>(factor);
    return c;
}

/// True if every term is a number times at most one non-numeric factor of degree 1.
bool is_linear(const exvector& terms)
{
    for (const ex& term : terms) {
        const monomial_exponents exponents = exponents_of(term);
        if (exponents.size() > 1 || (exponents.size() == 1 && !exponents.begin()->second.is_equal(1)))
            return false;
    }
    return true;
}

/// GiNaC's factor() with the non-polynomial parts (cos(theta - phi), sqrt(M), ...)
/// replaced by temporary symbols, which factor() would otherwise refuse to look into.
ex factor_polynomial(const ex& p)
{
    exmap replacements;
    const ex rational = p.to_rational(replacements);
    const ex parts = rational.numer_denom();
    const ex factored = factor_if_quick(parts.op(0)) / factor_if_quick(parts.op(1));
    return factored.subs(replacements, GiNaC::subs_options::no_pattern);
}

/// The factors of a compact form of the expanded sum `c`: its numeric and monomial
/// content, then the remaining sum, factored if it is small and not linear.
exvector compact_factors(const ex& c)
{
    const exvector terms = terms_of(c);
    if (terms.size() <= 1)
        return {c};
    if (has_compound_denominator(c))
        return {factor_polynomial(c)};

    numeric numerator_gcd = 0;
    numeric denominator_lcm = 1;
    bool all_negative = true;
    monomial_exponents common;
    for (size_t i = 0; i < terms.size(); ++i) {
        const numeric coefficient = coefficient_of(terms[i]);
        numerator_gcd = GiNaC::gcd(numerator_gcd, coefficient.numer());
        denominator_lcm = GiNaC::lcm(denominator_lcm, coefficient.denom());
        all_negative = all_negative && coefficient.is_negative();
        const monomial_exponents exponents = exponents_of(terms[i]);
        if (i == 0) {
            common = exponents;
            continue;
        }
        for (auto it = common.begin(); it != common.end();) {
            auto found = exponents.find(it->first);
            if (found == exponents.end() || !found->second.is_rational() || !it->second.is_rational()) {
                it = common.erase(it);
                continue;
            }
            if (found->second < it->second)
                it->second = found->second;
            ++it;
        }
    }
    numeric content = numerator_gcd / denominator_lcm;
    if (all_negative)
        content = -content;
    exvector content_factors;
    for (const auto& [base, exponent] : common)
        if (!exponent.is_zero())
            content_factors.push_back(GiNaC::pow(base, exponent));
    const ex content_monomial = product_of(content_factors);

    exvector cofactor_terms;
    cofactor_terms.reserve(terms.size());
    for (const ex& term : terms)
        cofactor_terms.push_back((term / content_monomial) * content.inverse());
    ex cofactor = sum_of(cofactor_terms);
    if (cofactor_terms.size() <= factor_term_limit && !is_linear(cofactor_terms))
        cofactor = factor_polynomial(cofactor);

    exvector result = content_factors;
    if (!content.is_equal(numeric(1)))
        result.push_back(content);
    for (const ex& factor : factors_of(cofactor))
        result.push_back(factor);
    return result;
}

struct key_hash {
    size_t operator()(const std::vector<std::int32_t>& key) const
    {
        std::uint64_t h = 0x9e3779b97f4a7c15ULL;
        for (std::int32_t x : key) {
            h ^= static_cast<std::uint32_t>(x);
            h *= 0xff51afd7ed558ccdULL;
            h ^= h >> 32;
        }
        return static_cast<size_t>(h);
    }
};

/// The terms of one group of collect_compact over a harmonic polynomial: indices of
/// the polynomial's terms that share their monomial in the variables and harmonics.
struct harmonic_group {
    std::vector<size_t> terms;
};

/// compact_factors for a coefficient given as terms of a harmonic polynomial whose
/// exponents count only for the symbols not in `variable`: the same factors, with
/// the content taken out without building the expanded coefficient first.
exvector compact_factors(const harmonic_polynomial& p, const std::vector<size_t>& terms,
                         const std::vector<bool>& variable)
{
    const harmonic_space& space = p.space();
    const size_t symbols = p.symbol_count();
    auto term_ex = [&](size_t i, const cln::cl_RA& divisor, const std::vector<std::int32_t>& subtracted) {
        const harmonic_term t = p.term(i);
        exvector factors;
        const cln::cl_RA c = *t.coefficient / divisor;
        if (!cln::equal(c, cln::cl_RA(1)))
            factors.push_back(harmonic_space::number(c));
        for (size_t s = 0; s < symbols; ++s) {
            if (variable[s])
                continue;
            const std::int32_t e = t.exponents[s] - subtracted[s];
            if (e != 0)
                factors.push_back(space.power(s, e));
        }
        return product_of(factors);
    };
    const std::vector<std::int32_t> none(symbols, 0);
    if (terms.size() == 1)
        return {term_ex(terms.front(), 1, none)};

    cln::cl_I numerator_gcd = 0;
    cln::cl_I denominator_lcm = 1;
    bool all_negative = true;
    std::vector<std::int32_t> common(symbols, 0);
    std::vector<bool> in_all(symbols, true);
    for (size_t k = 0; k < terms.size(); ++k) {
        const harmonic_term t = p.term(terms[k]);
        numerator_gcd = cln::gcd(numerator_gcd, cln::numerator(*t.coefficient));
        denominator_lcm = cln::lcm(denominator_lcm, cln::denominator(*t.coefficient));
        all_negative = all_negative && cln::minusp(*t.coefficient);
        for (size_t s = 0; s < symbols; ++s) {
            if (variable[s] || !in_all[s])
                continue;
            const std::int32_t e = t.exponents[s];
            if (e == 0) {
                in_all[s] = false;
                common[s] = 0;
            } else if (k == 0 || e < common[s]) {
                common[s] = e;
            }
        }
    }
    cln::cl_RA content = numerator_gcd / denominator_lcm;
    if (all_negative)
        content = -content;
    exvector content_factors;
    for (size_t s = 0; s < symbols; ++s)
        if (!variable[s] && in_all[s] && common[s] != 0)
            content_factors.push_back(space.power(s, common[s]));
        else
            common[s] = 0;

    exvector cofactor_terms;
    cofactor_terms.reserve(terms.size());
    bool linear = true;
    for (size_t i : terms) {
        cofactor_terms.push_back(term_ex(i, content, common));
        const harmonic_term t = p.term(i);
        int degree_symbols = 0;
        for (size_t s = 0; s < symbols && linear; ++s) {
            if (variable[s])
                continue;
            const std::int32_t e = t.exponents[s] - common[s];
            if (e != 0 && (e != 1 || ++degree_symbols > 1))
                linear = false;
        }
    }
    ex cofactor = sum_of(cofactor_terms);
    if (cofactor_terms.size() <= factor_term_limit && !linear)
        cofactor = factor_polynomial(cofactor);

    exvector result = content_factors;
    if (!cln::equal(content, cln::cl_RA(1)))
        result.push_back(harmonic_space::number(content));
    for (const ex& factor : factors_of(cofactor))
        result.push_back(factor);
    return result;
}

/// collect_compact over a harmonic polynomial;
/// nullopt if a variable is not a symbol (then only the general path applies).
std::optional<ex> collect_compact_harmonic(const harmonic_polynomial& p, const GiNaC::lst& variables,
                                           const GiNaC::lst& angles)
{
    const harmonic_space& space = p.space();
    const size_t symbols = p.symbol_count();
    std::vector<bool> variable(symbols, false);
    for (const ex& v : variables) {
        if (ex_kind_of(v) != ex_kind::symbol)
            return std::nullopt;
        if (auto index = space.index_of(v); index && *index < symbols)
            variable[*index] = true;
    }
    // A harmonic is an angle function for collect_compact if one of `angles` is in its argument.
    std::vector<bool> listed_angle(space.angle_count(), false);
    for (const ex& q : angles)
        if (auto index = space.index_of(q); index && *index < space.angle_count())
            listed_angle[*index] = true;
    auto is_angle_function = [&](const harmonic_term& t) {
        if (t.kind == wave::none)
            return false;
        for (size_t i = 0; i < space.angle_count(); ++i)
            if (t.frequency[i] != 0 && listed_angle[i])
                return true;
        return false;
    };

    // Groups keyed by the monomial: harmonic (if an angle function) and variable exponents.
    std::unordered_map<std::vector<std::int32_t>, size_t, key_hash> index;
    std::vector<std::vector<std::int32_t>> keys;
    std::vector<harmonic_group> groups;
    std::vector<bool> harmonic_in_monomial;
    std::vector<std::int32_t> key;
    for (size_t i = 0; i < p.size(); ++i) {
        const harmonic_term t = p.term(i);
        const bool angle_function = is_angle_function(t);
        if (t.kind != wave::none && !angle_function)
            return std::nullopt; // a harmonic in a coefficient: only the general path handles it
        key.assign(1, angle_function ? static_cast<std::int32_t>(t.kind) : 0);
        for (size_t a = 0; a < space.angle_count(); ++a)
            key.push_back(angle_function ? t.frequency[a] : 0);
        for (size_t s = 0; s < symbols; ++s)
            key.push_back(variable[s] ? t.exponents[s] : 0);
        auto [it, inserted] = index.emplace(key, groups.size());
        if (inserted) {
            groups.emplace_back();
            keys.push_back(key);
            harmonic_in_monomial.push_back(angle_function);
        }
        groups[it->second].terms.push_back(i);
    }
    exvector result;
    result.reserve(groups.size());
    for (size_t g = 0; g < groups.size(); ++g) {
        exvector factors = compact_factors(p, groups[g].terms, variable);
        exvector monomial;
        const harmonic_term t = p.term(groups[g].terms.front());
        for (size_t s = 0; s < symbols; ++s)
            if (variable[s] && t.exponents[s] != 0)
                monomial.push_back(space.power(s, t.exponents[s]));
        if (harmonic_in_monomial[g])
            monomial.push_back(space.wave_function(t.kind, t.frequency));
        factors.push_back(product_of(monomial));
        result.push_back(product_of(factors));
    }
    return sum_of(result);
}

} // namespace

GiNaC::ex trig_canonical(const GiNaC::ex& e, const GiNaC::lst& angles)
{
    if (std::optional<ex> fast = harmonic_canonical(e, angles))
        return *fast;
    return canonicalizer(angles).canonical(e);
}

GiNaC::ex trig_canonical_general(const GiNaC::ex& e, const GiNaC::lst& angles)
{
    return canonicalizer(angles).canonical(e);
}

bool trig_equal(const GiNaC::ex& a, const GiNaC::ex& b, const GiNaC::lst& angles)
{
    const ex difference = trig_canonical(a - b, angles);
    return difference.is_zero() || difference.normal().is_zero();
}

GiNaC::ex collect_compact(const GiNaC::ex& e, const GiNaC::lst& variables, const GiNaC::lst& angles)
{
    const std::set<ex, GiNaC::ex_is_less> variable_set(variables.begin(), variables.end());
    auto is_angle_function = [&](const ex& f) {
        if (ex_kind_of(f) != ex_kind::function)
            return false;
        for (const ex& angle : angles)
            if (f.has(angle))
                return true;
        return false;
    };
    auto is_variable_power = [&](const ex& f) {
        if (variable_set.count(f) != 0 || is_angle_function(f))
            return true;
        return (ex_kind_of(f) == ex_kind::power) &&
               (variable_set.count(f.op(0)) != 0 || is_angle_function(f.op(0))) &&
               f.op(1).info(GiNaC::info_flags::integer);
    };
    std::map<ex, exvector, GiNaC::ex_is_less> by_monomial;
    for (const ex& term : terms_of(e.expand())) {
        exvector monomial;
        exvector coefficient;
        for (const ex& factor : factors_of(term))
            (is_variable_power(factor) ? monomial : coefficient).push_back(factor);
        by_monomial[product_of(monomial)].push_back(product_of(coefficient));
    }
    exvector result;
    for (const auto& [monomial, coefficient_terms] : by_monomial) {
        const ex coefficient = sum_of(coefficient_terms);
        if (coefficient.is_zero())
            continue;
        exvector factors = compact_factors(coefficient);
        factors.push_back(monomial);
        result.push_back(product_of(factors));
    }
    return sum_of(result);
}

GiNaC::ex collect_compact(const harmonic_polynomial& p, const GiNaC::lst& variables, const GiNaC::lst& angles)
{
    if (std::optional<ex> grouped = collect_compact_harmonic(p, variables, angles))
        return *grouped;
    return collect_compact(to_ex(p), variables, angles);
}

GiNaC::ex simplifier::canonical(const GiNaC::ex& e) const { return trig_canonical(e, angles); }

GiNaC::ex simplifier::compact(const GiNaC::ex& canonical_form) const
{
    return collect_compact(rewrite(canonical_form, rules), variables, angles);
}

GiNaC::ex simplifier::compact(const harmonic_polynomial& canonical_form) const
{
    rewrite_screen screen(rules);
    return compact_harmonic(canonical_form, screen);
}

std::vector<GiNaC::ex> simplifier::compact(const std::vector<harmonic_polynomial>& canonical_forms) const
{
    rewrite_screen screen(rules);
    std::vector<GiNaC::ex> compact_forms;
    compact_forms.reserve(canonical_forms.size());
    for (const harmonic_polynomial& p : canonical_forms)
        compact_forms.push_back(compact_harmonic(p, screen));
    return compact_forms;
}

GiNaC::ex simplifier::compact_harmonic(const harmonic_polynomial& canonical_form, rewrite_screen& screen) const
{
    // The rewrite changes nothing if no rule can fire at any node: then group the
    // polynomial directly, without building its expanded expression.
    const harmonic_space& space = canonical_form.space();
    std::unordered_map<const GiNaC::basic*, size_t> index;
    exvector atoms;
    std::vector<std::vector<size_t>> term_atoms(canonical_form.size());
    auto note = [&](const ex& atom, std::vector<size_t>& term) {
        auto [it, inserted] = index.emplace(&GiNaC::ex_to<GiNaC::basic>(atom), atoms.size());
        if (inserted)
            atoms.push_back(atom);
        term.push_back(it->second);
    };
    for (size_t i = 0; i < canonical_form.size(); ++i) {
        const harmonic_term t = canonical_form.term(i);
        for (size_t s = 0; s < canonical_form.symbol_count(); ++s)
            if (t.exponents[s] != 0)
                note(space.power(s, t.exponents[s]), term_atoms[i]);
        if (t.kind != wave::none)
            note(space.wave_function(t.kind, t.frequency), term_atoms[i]);
    }
    if (!screen.may_fire(atoms, term_atoms))
        if (std::optional<ex> grouped = collect_compact_harmonic(canonical_form, variables, angles))
            return *grouped;
    return compact(to_ex(canonical_form));
}

GiNaC::ex simplifier::operator()(const GiNaC::ex& e) const { return compact(canonical(e)); }

} // namespace lagrange
