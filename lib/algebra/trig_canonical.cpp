// SPDX-License-Identifier: GPL-2.0-or-later
/** @file trig_canonical.cpp
 *  The canonical form of trigonometric polynomials in the coordinates: products of
 *  sines and cosines of linear combinations of the angles linearized into sums of
 *  harmonics, by harmonic polynomials where the expression is one (harmonic.h), else
 *  by the general path. */
#include "algebra/trig_canonical.h"

#include "algebra/budget.h"
#include "algebra/expression.h"
#include "algebra/harmonic.h"

#include <deque>
#include <functional>
#include <map>
#include <algorithm>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <unordered_map>
#include <utility>

namespace lagrange {

namespace {

using GiNaC::ex;
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

/// A term of an expanded sum as a rational coefficient times the rest (1 for a number).
std::pair<numeric, ex> split_coefficient(const ex& term)
{
    if (ex_kind_of(term) == ex_kind::number && GiNaC::ex_to<numeric>(term).is_rational())
        return {GiNaC::ex_to<numeric>(term), 1};
    if (ex_kind_of(term) != ex_kind::product)
        return {1, term};
    numeric coefficient = 1;
    exvector rest;
    for (size_t i = 0; i < term.nops(); ++i) {
        const ex& factor = term.op(i);
        if (ex_kind_of(factor) == ex_kind::number && GiNaC::ex_to<numeric>(factor).is_rational())
            coefficient = coefficient.mul(GiNaC::ex_to<numeric>(factor));
        else
            rest.push_back(factor);
    }
    return {coefficient, product_of(rest)};
}

/// True if `e` holds a symbol not declared positive (a coordinate, time t): a monomial
/// of constant parameters alone (a possymbol such as an angle th0) stays an offset, so
/// that expressions in sin th0, cos th0, tan th0 keep them as atoms.
bool varies(const ex& e)
{
    if (ex_kind_of(e) == ex_kind::symbol)
        return !e.info(GiNaC::info_flags::positive);
    for (size_t i = 0; i < e.nops(); ++i)
        if (varies(e.op(i)))
            return true;
    return false;
}

bool has_symbol(const ex& e)
{
    if (ex_kind_of(e) == ex_kind::symbol)
        return true;
    for (size_t i = 0; i < e.nops(); ++i)
        if (has_symbol(e.op(i)))
            return true;
    return false;
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
                all_symbols_ = all_symbols_ && ex_kind_of(q) == ex_kind::symbol;
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
    /// True if `e` is one of the angles (a symbol, or a monomial such as w*t or x/R).
    bool is_angle(const ex& e) const
    {
        return (ex_kind_of(e) == ex_kind::symbol || !all_symbols_) && index_.count(e) != 0;
    }

    bool has_angle(const ex& e) const
    {
        if (ex_kind_of(e) == ex_kind::symbol)
            return index_.count(e) != 0;
        if (!all_symbols_ && index_.count(e) != 0)
            return true;
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
            if (!all_symbols_) {
                const auto [coefficient, monomial] = split_coefficient(term);
                if (is_angle(monomial)) {
                    n[index_.at(monomial)] += coefficient;
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
    bool all_symbols_ = true; ///< every angle is a symbol (no monomial angles)
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

} // namespace

GiNaC::ex trig_canonical(const GiNaC::ex& e, const GiNaC::lst& angles)
{
    if (std::optional<ex> fast = harmonic_canonical(e, angles))
        return *fast;
    return trig_canonical_general(e, angles);
}

namespace {

/// The monomials (w*t, x/R, a parameter) of the arguments of sines and cosines that
/// are not among `angles`: they become further angles, so that products of sines and
/// cosines of any argument are linearized too. Arguments that are not linear in the
/// angles are put in canonical form first. Returns `e` with those arguments.
class argument_monomials {
public:
    explicit argument_monomials(const GiNaC::lst& angles) : angles_(angles)
    {
        for (const ex& q : angles)
            known_.insert(q);
    }

    ex scan(const ex& e)
    {
        if (e.nops() == 0)
            return e;
        map_each recurse([this](const ex& x) { return scan(x); });
        const ex mapped = e.map(recurse);
        if (!is_sin_or_cos(mapped))
            return mapped;
        ex argument = mapped.op(0).expand();
        bool linear = true;
        for (const ex& term : terms_of(argument)) {
            const auto [coefficient, monomial] = split_coefficient(term);
            linear = linear && (!has_symbol(monomial) || known_.count(monomial) != 0);
        }
        if (!linear)
            argument = trig_canonical(argument, angles_);
        for (const ex& term : terms_of(argument)) {
            const ex monomial = split_coefficient(term).second;
            if (varies(monomial) && known_.insert(monomial).second)
                found_.push_back(monomial);
        }
        return GiNaC::is_the_function<GiNaC::cos_SERIAL>(mapped) ? GiNaC::cos(argument) : GiNaC::sin(argument);
    }

    /// The angles, then the monomials found, ordered by their printed form.
    GiNaC::lst extended_angles() const
    {
        std::vector<std::pair<std::string, ex>> named;
        for (const ex& m : found_) {
            std::ostringstream text;
            text << m;
            named.emplace_back(text.str(), m);
        }
        std::stable_sort(named.begin(), named.end(),
                         [](const auto& a, const auto& b) { return a.first < b.first; });
        GiNaC::lst all = angles_;
        for (const auto& entry : named)
            all.append(entry.second);
        return all;
    }

    bool found_any() const { return !found_.empty(); }

private:
    GiNaC::lst angles_;
    std::set<ex, GiNaC::ex_is_less> known_;
    exvector found_;
};

} // namespace

GiNaC::ex trig_canonical_general(const GiNaC::ex& e, const GiNaC::lst& angles)
{
    argument_monomials monomials(angles);
    const ex prepared = monomials.scan(e);
    if (!monomials.found_any())
        return canonicalizer(angles).canonical(prepared);
    return canonicalizer(monomials.extended_angles()).canonical(prepared);
}

bool trig_equal(const GiNaC::ex& a, const GiNaC::ex& b, const GiNaC::lst& angles)
{
    const ex difference = trig_canonical(a - b, angles);
    return difference.is_zero() || difference.normal().is_zero();
}

std::optional<GiNaC::ex> trigonometric_polynomial(const GiNaC::ex& e, const GiNaC::ex& q, const GiNaC::ex& s,
                                                  const GiNaC::ex& c)
{
    bool representable = true;
    std::function<ex(const ex&)> convert = [&](const ex& x) -> ex {
        if (!representable || !x.has(q))
            return x;
        if (x.is_equal(q)) {
            representable = false;
            return x;
        }
        if (is_sin_or_cos(x)) {
            const ex argument = x.op(0).expand();
            const ex k = argument.coeff(q, 1);
            const ex rest = (argument - k * q).expand();
            if (argument.degree(q) != 1 || rest.has(q) || !k.info(GiNaC::info_flags::integer)) {
                representable = false;
                return x;
            }
            const long multiple = GiNaC::ex_to<GiNaC::numeric>(k).to_long();
            const ex power = GiNaC::pow(c + GiNaC::I * s, multiple < 0 ? -multiple : multiple).expand();
            const ex cos_n = power.real_part().expand();
            const ex sin_n = ((multiple < 0 ? -1 : 1) * power.imag_part()).expand();
            if (GiNaC::is_the_function<GiNaC::sin_SERIAL>(x))
                return sin_n * GiNaC::cos(rest) + cos_n * GiNaC::sin(rest);
            return cos_n * GiNaC::cos(rest) - sin_n * GiNaC::sin(rest);
        }
        map_each recurse(convert);
        return x.map(recurse);
    };
    const ex p = convert(e);
    if (!representable || p.has(q))
        return std::nullopt;
    return p.expand();
}

} // namespace lagrange
