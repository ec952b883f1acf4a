// SPDX-License-Identifier: GPL-2.0-or-later
/** @file harmonic.cpp
 *  Harmonic polynomials as a flat table of terms with a hash index. Written by hand
 *  because GiNaC builds, evaluates and hashes a tree object for every intermediate
 *  term (which dominated the derivation of the equations of motion), and neither
 *  GiNaC nor CLN has a sparse polynomial type whose monomials carry harmonics. */
#include "algebra/harmonic.h"

#include "algebra/budget.h"
#include "algebra/expression.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

namespace lagrange {

namespace {

using GiNaC::ex;
using GiNaC::exvector;

/// Largest |exponent| or |frequency entry| taken from an expression, and largest
/// power of a sum expanded: keeps every sum of entries far from int32 overflow.
constexpr std::int32_t largest_entry = 1 << 16;
constexpr std::int32_t largest_sum_power = 64;

std::uint64_t hash_key(const std::int32_t* key, std::size_t n)
{
    std::uint64_t h = 0x9e3779b97f4a7c15ULL;
    for (std::size_t i = 0; i < n; ++i) {
        h ^= static_cast<std::uint32_t>(key[i]);
        h *= 0xff51afd7ed558ccdULL;
        h ^= h >> 32;
    }
    return h;
}

/// Sign of the first nonzero entry (0 if all are zero).
int leading_sign(const std::int32_t* n, std::size_t count)
{
    for (std::size_t i = 0; i < count; ++i)
        if (n[i] != 0)
            return n[i] < 0 ? -1 : 1;
    return 0;
}

/// The value of an integer number within the entry limit.
bool small_integer(const ex& e, std::int32_t& value)
{
    if (ex_kind_of(e) != ex_kind::number)
        return false;
    const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(e);
    if (!n.is_integer() || GiNaC::abs(n) > largest_entry)
        return false;
    value = n.to_int();
    return true;
}

} // namespace

// ---------------------------------------------------------------- harmonic_space

harmonic_space::harmonic_space(const GiNaC::lst& angles)
{
    for (const ex& q : angles) {
        if (index_of(q))
            continue;
        add_symbol(q);
    }
    angle_count_ = symbols_.size();
}

std::size_t harmonic_space::add_symbol(const GiNaC::ex& symbol)
{
    if (ex_kind_of(symbol) != ex_kind::symbol)
        throw std::invalid_argument("harmonic_space: not a symbol");
    if (auto known = index_of(symbol))
        return *known;
    by_hash_.emplace(symbol.gethash(), symbols_.size());
    symbols_.push_back(symbol);
    return symbols_.size() - 1;
}

std::optional<std::size_t> harmonic_space::index_of(const GiNaC::ex& symbol) const
{
    auto range = by_hash_.equal_range(symbol.gethash());
    for (auto it = range.first; it != range.second; ++it)
        if (symbols_[it->second].is_equal(symbol))
            return it->second;
    return std::nullopt;
}

bool harmonic_space::add_symbols_of(const GiNaC::ex& e)
{
    switch (ex_kind_of(e)) {
    case ex_kind::symbol:
        add_symbol(e);
        return true;
    case ex_kind::number:
        return GiNaC::ex_to<GiNaC::numeric>(e).is_rational();
    case ex_kind::sum:
    case ex_kind::product:
        for (std::size_t i = 0; i < e.nops(); ++i)
            if (!add_symbols_of(e.op(i)))
                return false;
        return true;
    case ex_kind::power:
        return e.op(1).info(GiNaC::info_flags::integer) && add_symbols_of(e.op(0));
    case ex_kind::function:
        return is_sin_or_cos(e) && add_symbols_of(e.op(0));
    default:
        return false;
    }
}

// ---------------------------------------------------------------- harmonic_polynomial

harmonic_polynomial::harmonic_polynomial(const harmonic_space& space)
    : space_(&space), angle_count_(space.angle_count()), symbol_count_(space.symbol_count())
{
}

harmonic_polynomial harmonic_polynomial::constant(const harmonic_space& space, const cln::cl_RA& c)
{
    harmonic_polynomial p(space);
    const std::vector<std::int32_t> key(p.key_size(), 0);
    p.add_term(key.data(), c);
    return p;
}

harmonic_polynomial harmonic_polynomial::variable(const harmonic_space& space, std::size_t index)
{
    harmonic_polynomial p(space);
    if (index >= p.symbol_count_)
        throw std::invalid_argument("harmonic_polynomial: symbol index out of range");
    std::vector<std::int32_t> key(p.key_size(), 0);
    key[1 + p.angle_count_ + index] = 1;
    p.add_term(key.data(), 1);
    return p;
}

harmonic_term harmonic_polynomial::term(std::size_t i) const
{
    const std::int32_t* k = key(i);
    return harmonic_term{&coefficients_[i], static_cast<wave>(k[0]), k + 1, k + 1 + angle_count_};
}

void harmonic_polynomial::grow_table()
{
    std::size_t size = std::max<std::size_t>(16, table_.size() * 2);
    while (size < 2 * (hashes_.size() + 1))
        size *= 2;
    table_.assign(size, 0);
    const std::size_t mask = size - 1;
    for (std::size_t i = 0; i < hashes_.size(); ++i) {
        std::size_t slot = hashes_[i] & mask;
        while (table_[slot] != 0)
            slot = (slot + 1) & mask;
        table_[slot] = static_cast<std::uint32_t>(i + 1);
    }
}

void harmonic_polynomial::add_term(const std::int32_t* key, const cln::cl_RA& c)
{
    if (cln::zerop(c))
        return;
    if ((coefficients_.size() + 1) * 2 > table_.size())
        grow_table();
    const std::size_t n = key_size();
    const std::uint64_t h = hash_key(key, n);
    const std::size_t mask = table_.size() - 1;
    for (std::size_t slot = h & mask;; slot = (slot + 1) & mask) {
        const std::uint32_t entry = table_[slot];
        if (entry == 0) {
            table_[slot] = static_cast<std::uint32_t>(coefficients_.size() + 1);
            keys_.insert(keys_.end(), key, key + n);
            coefficients_.push_back(c);
            hashes_.push_back(h);
            return;
        }
        const std::size_t i = entry - 1;
        if (hashes_[i] == h && std::equal(key, key + n, keys_.data() + i * n)) {
            coefficients_[i] = coefficients_[i] + c;
            return;
        }
    }
}

void harmonic_polynomial::prune()
{
    const std::size_t n = key_size();
    std::size_t kept = 0;
    for (std::size_t i = 0; i < coefficients_.size(); ++i) {
        if (cln::zerop(coefficients_[i]))
            continue;
        if (kept != i) {
            std::copy(keys_.begin() + i * n, keys_.begin() + (i + 1) * n, keys_.begin() + kept * n);
            coefficients_[kept] = coefficients_[i];
            hashes_[kept] = hashes_[i];
        }
        ++kept;
    }
    if (kept == coefficients_.size())
        return;
    keys_.resize(kept * n);
    coefficients_.resize(kept);
    hashes_.resize(kept);
    table_.clear();
    grow_table();
}

void harmonic_polynomial::check_same_space(const harmonic_polynomial& other) const
{
    if (space_ != other.space_ || symbol_count_ != other.symbol_count_)
        throw std::invalid_argument("harmonic_polynomial: operands over different spaces");
}

harmonic_polynomial& harmonic_polynomial::operator+=(const harmonic_polynomial& other)
{
    check_same_space(other);
    if (&other == this)
        return *this *= 2;
    for (std::size_t i = 0; i < other.size(); ++i)
        add_term(other.key(i), other.coefficients_[i]);
    prune();
    return *this;
}

harmonic_polynomial& harmonic_polynomial::operator-=(const harmonic_polynomial& other)
{
    check_same_space(other);
    if (&other == this)
        return *this *= 0;
    for (std::size_t i = 0; i < other.size(); ++i)
        add_term(other.key(i), -other.coefficients_[i]);
    prune();
    return *this;
}

harmonic_polynomial& harmonic_polynomial::operator*=(const cln::cl_RA& c)
{
    if (cln::zerop(c)) {
        *this = harmonic_polynomial(*space_);
        return *this;
    }
    for (cln::cl_RA& x : coefficients_)
        x = x * c;
    return *this;
}

harmonic_polynomial harmonic_polynomial::operator*(const harmonic_polynomial& other) const
{
    check_same_space(other);
    harmonic_polynomial product(*space_);
    const std::size_t n = key_size();
    const std::size_t a = angle_count_;
    std::vector<std::int32_t> difference(n), sum(n);
    const cln::cl_RA half = cln::cl_RA(1) / 2;
    budget_check_count(size() * other.size(), "a product of trigonometric polynomials");
    for (std::size_t i = 0; i < size(); ++i) {
        if (i % 64 == 0)
            budget_check_count(product.size(), "a product of trigonometric polynomials");
        const std::int32_t* x = key(i);
        const wave x_wave = static_cast<wave>(x[0]);
        for (std::size_t j = 0; j < other.size(); ++j) {
            const std::int32_t* y = other.key(j);
            const wave y_wave = static_cast<wave>(y[0]);
            for (std::size_t k = 1 + a; k < n; ++k)
                sum[k] = x[k] + y[k];
            const cln::cl_RA c = coefficients_[i] * other.coefficients_[j];
            if (x_wave == wave::none || y_wave == wave::none) {
                const std::int32_t* harmonic = x_wave == wave::none ? y : x;
                std::copy(harmonic, harmonic + 1 + a, sum.begin());
                product.add_term(sum.data(), c);
                continue;
            }
            std::copy(sum.begin() + 1 + a, sum.end(), difference.begin() + 1 + a);
            for (std::size_t k = 1; k <= a; ++k) {
                difference[k] = x[k] - y[k];
                sum[k] = x[k] + y[k];
            }
            // cos p cos q = (cos(p-q) + cos(p+q))/2, sin p sin q = (cos(p-q) - cos(p+q))/2,
            // sin p cos q = (sin(p+q) + sin(p-q))/2, cos p sin q = (sin(p+q) - sin(p-q))/2.
            const cln::cl_RA c_half = c * half;
            wave difference_wave = wave::cos;
            int difference_sign = 1;
            int sum_sign = 1;
            if (x_wave == wave::cos && y_wave == wave::cos) {
                sum[0] = static_cast<std::int32_t>(wave::cos);
            } else if (x_wave == wave::sin && y_wave == wave::sin) {
                sum[0] = static_cast<std::int32_t>(wave::cos);
                sum_sign = -1;
            } else {
                sum[0] = static_cast<std::int32_t>(wave::sin);
                difference_wave = wave::sin;
                difference_sign = x_wave == wave::sin ? 1 : -1;
            }
            // p + q keeps a positive leading entry; p - q may need its sign flipped.
            product.add_term(sum.data(), sum_sign > 0 ? c_half : -c_half);
            const int lead = leading_sign(difference.data() + 1, a);
            if (lead == 0) {
                if (difference_wave == wave::sin)
                    continue;
                difference_wave = wave::none;
            } else if (lead < 0) {
                for (std::size_t k = 1; k <= a; ++k)
                    difference[k] = -difference[k];
                if (difference_wave == wave::sin)
                    difference_sign = -difference_sign;
            }
            difference[0] = static_cast<std::int32_t>(difference_wave);
            product.add_term(difference.data(), difference_sign > 0 ? c_half : -c_half);
        }
    }
    product.prune();
    return product;
}

void harmonic_polynomial::add_partial(std::vector<std::int32_t>& scratch, const cln::cl_RA& c,
                                      std::size_t index, std::optional<std::size_t> rate)
{
    std::int32_t* exponents = scratch.data() + 1 + angle_count_;
    const std::int32_t e = exponents[index];
    if (rate)
        ++exponents[*rate];
    if (e != 0) {
        --exponents[index];
        add_term(scratch.data(), c * cln::cl_RA(e));
        ++exponents[index];
    }
    const std::int32_t n = index < angle_count_ ? scratch[1 + index] : 0;
    const wave kind = static_cast<wave>(scratch[0]);
    if (n != 0 && kind != wave::none) {
        // d cos(n·q)/dq_i = -n_i sin(n·q), d sin(n·q)/dq_i = n_i cos(n·q).
        scratch[0] = static_cast<std::int32_t>(kind == wave::cos ? wave::sin : wave::cos);
        add_term(scratch.data(), kind == wave::cos ? -c * cln::cl_RA(n) : c * cln::cl_RA(n));
        scratch[0] = static_cast<std::int32_t>(kind);
    }
    if (rate)
        --exponents[*rate];
}

harmonic_polynomial harmonic_polynomial::derivative(std::size_t index) const
{
    if (index >= symbol_count_)
        throw std::invalid_argument("harmonic_polynomial: symbol index out of range");
    harmonic_polynomial result(*space_);
    std::vector<std::int32_t> scratch(key_size());
    for (std::size_t i = 0; i < size(); ++i) {
        std::copy(key(i), key(i) + key_size(), scratch.begin());
        result.add_partial(scratch, coefficients_[i], index, std::nullopt);
    }
    result.prune();
    return result;
}

harmonic_polynomial harmonic_polynomial::total_derivative(
    const std::vector<std::pair<std::size_t, std::size_t>>& rates, std::optional<std::size_t> time) const
{
    for (const auto& [variable, rate] : rates)
        if (variable >= symbol_count_ || rate >= symbol_count_)
            throw std::invalid_argument("harmonic_polynomial: symbol index out of range");
    if (time && *time >= symbol_count_)
        throw std::invalid_argument("harmonic_polynomial: symbol index out of range");
    harmonic_polynomial result(*space_);
    std::vector<std::int32_t> scratch(key_size());
    for (std::size_t i = 0; i < size(); ++i) {
        std::copy(key(i), key(i) + key_size(), scratch.begin());
        for (const auto& [variable, rate] : rates)
            result.add_partial(scratch, coefficients_[i], variable, rate);
        if (time)
            result.add_partial(scratch, coefficients_[i], *time, std::nullopt);
    }
    result.prune();
    return result;
}

// ---------------------------------------------------------------- conversion from GiNaC

/// Turns GiNaC expressions into harmonic polynomials (a friend: it fills the term table).
struct harmonic_builder {
    explicit harmonic_builder(const harmonic_space& s)
        : space(s), angle_count(s.angle_count()), key_size(1 + s.angle_count() + s.symbol_count())
    {
    }

    /// What a factor contributes to a single term.
    enum class outcome { absorbed, compound, impossible };

    /// A term being built from the factors of a product.
    struct monomial {
        std::vector<std::int32_t> key;
        cln::cl_RA coefficient = 1;
    };

    bool convert(const ex& e, harmonic_polynomial& out) const
    {
        switch (ex_kind_of(e)) {
        case ex_kind::sum: {
            monomial m;
            for (std::size_t i = 0; i < e.nops(); ++i) {
                const ex& term = e.op(i);
                reset(m);
                const outcome o = single_term(term, m);
                if (o == outcome::impossible)
                    return false;
                if (o == outcome::absorbed) {
                    out.add_term(m.key.data(), m.coefficient);
                    continue;
                }
                harmonic_polynomial part(space);
                if (!convert(term, part))
                    return false;
                for (std::size_t k = 0; k < part.size(); ++k)
                    out.add_term(part.key(k), part.coefficients_[k]);
            }
            out.prune();
            return true;
        }
        case ex_kind::product: {
            monomial m;
            reset(m);
            exvector compound;
            for (std::size_t i = 0; i < e.nops(); ++i) {
                const outcome o = absorb(e.op(i), m);
                if (o == outcome::impossible)
                    return false;
                if (o == outcome::compound)
                    compound.push_back(e.op(i));
            }
            harmonic_polynomial product(space);
            product.add_term(m.key.data(), m.coefficient);
            for (const ex& factor : compound) {
                harmonic_polynomial part(space);
                if (!convert(factor, part))
                    return false;
                product = product * part;
            }
            out += product;
            return true;
        }
        case ex_kind::power: {
            monomial m;
            reset(m);
            const outcome o = absorb(e, m);
            if (o == outcome::impossible)
                return false;
            if (o == outcome::absorbed) {
                out.add_term(m.key.data(), m.coefficient);
                return true;
            }
            std::int32_t exponent = 0;
            if (!small_integer(e.op(1), exponent) || exponent < 0 || exponent > largest_sum_power)
                return false;
            harmonic_polynomial base(space);
            if (!convert(e.op(0), base))
                return false;
            harmonic_polynomial power = harmonic_polynomial::constant(space, 1);
            for (std::int32_t k = 0; k < exponent; ++k)
                power = power * base;
            out += power;
            return true;
        }
        default: {
            monomial m;
            reset(m);
            if (absorb(e, m) != outcome::absorbed)
                return false;
            out.add_term(m.key.data(), m.coefficient);
            return true;
        }
        }
    }

private:
    void reset(monomial& m) const
    {
        m.key.assign(key_size, 0);
        m.coefficient = 1;
    }

    /// `e` as one term if it is a product of absorbable factors (at most one harmonic).
    outcome single_term(const ex& e, monomial& m) const
    {
        if (ex_kind_of(e) != ex_kind::product)
            return absorb(e, m);
        for (std::size_t i = 0; i < e.nops(); ++i) {
            const outcome o = absorb(e.op(i), m);
            if (o != outcome::absorbed)
                return o;
        }
        return outcome::absorbed;
    }

    /// Multiplies the term by the factor `e` if it is a number, a power of a symbol or
    /// a first harmonic; `compound` if it needs polynomial arithmetic.
    outcome absorb(const ex& e, monomial& m) const
    {
        std::int32_t* exponents = m.key.data() + 1 + angle_count;
        switch (ex_kind_of(e)) {
        case ex_kind::number: {
            const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(e);
            if (!n.is_rational())
                return outcome::impossible;
            m.coefficient = m.coefficient * cln::the<cln::cl_RA>(n.to_cl_N());
            return outcome::absorbed;
        }
        case ex_kind::symbol: {
            const auto index = space.index_of(e);
            if (!index || std::abs(exponents[*index]) >= largest_entry)
                return outcome::impossible;
            ++exponents[*index];
            return outcome::absorbed;
        }
        case ex_kind::power: {
            std::int32_t exponent = 0;
            if (!small_integer(e.op(1), exponent))
                return outcome::impossible;
            if (ex_kind_of(e.op(0)) != ex_kind::symbol)
                return outcome::compound;
            const auto index = space.index_of(e.op(0));
            if (!index || (*index < angle_count && exponent < 0) ||
                std::abs(exponents[*index]) >= largest_entry)
                return outcome::impossible;
            exponents[*index] += exponent;
            return outcome::absorbed;
        }
        case ex_kind::function: {
            if (m.key[0] != static_cast<std::int32_t>(wave::none))
                return outcome::compound;
            return harmonic(e, m) ? outcome::absorbed : outcome::impossible;
        }
        case ex_kind::sum:
            return outcome::compound;
        default:
            return outcome::impossible;
        }
    }

    /// Multiplies the term (without harmonic) by sin or cos of an integer combination
    /// of the angles; false if `e` is not one.
    bool harmonic(const ex& e, monomial& m) const
    {
        if (!is_sin_or_cos(e))
            return false;
        std::int32_t* frequency = m.key.data() + 1;
        const ex& argument = e.op(0);
        const bool single = ex_kind_of(argument) != ex_kind::sum;
        const std::size_t count = single ? 1 : argument.nops();
        for (std::size_t i = 0; i < count; ++i) {
            const ex term = single ? argument : argument.op(i);
            ex angle = term;
            std::int32_t multiple = 1;
            if (ex_kind_of(term) == ex_kind::product) {
                if (term.nops() != 2)
                    return false;
                const bool first_is_number = ex_kind_of(term.op(0)) == ex_kind::number;
                angle = term.op(first_is_number ? 1 : 0);
                if (!small_integer(term.op(first_is_number ? 0 : 1), multiple))
                    return false;
            }
            if (ex_kind_of(angle) != ex_kind::symbol)
                return false;
            const auto index = space.index_of(angle);
            if (!index || *index >= angle_count)
                return false;
            frequency[*index] += multiple;
        }
        const int lead = leading_sign(frequency, angle_count);
        if (lead == 0)
            return false;
        const bool is_cos = GiNaC::is_the_function<GiNaC::cos_SERIAL>(e);
        if (lead < 0) {
            for (std::size_t i = 0; i < angle_count; ++i)
                frequency[i] = -frequency[i];
            if (!is_cos)
                m.coefficient = -m.coefficient;
        }
        m.key[0] = static_cast<std::int32_t>(is_cos ? wave::cos : wave::sin);
        return true;
    }

    const harmonic_space& space;
    std::size_t angle_count;
    std::size_t key_size;
};

std::optional<harmonic_polynomial> to_harmonic(const GiNaC::ex& e, const harmonic_space& space)
{
    harmonic_polynomial p(space);
    if (!harmonic_builder(space).convert(e, p))
        return std::nullopt;
    return p;
}

// ---------------------------------------------------------------- conversion to GiNaC

const GiNaC::ex& harmonic_space::wave_function(wave kind, const std::int32_t* frequency) const
{
    static const ex one = 1;
    if (kind == wave::none)
        return one;
    const std::size_t count = angle_count_;
    std::vector<std::int32_t> key(frequency, frequency + count);
    key.push_back(static_cast<std::int32_t>(kind));
    auto& bucket = waves_[hash_key(key.data(), key.size())];
    for (const auto& [known, function] : bucket)
        if (known == key)
            return function;
    exvector terms;
    for (std::size_t i = 0; i < count; ++i)
        if (frequency[i] != 0)
            terms.push_back(ex(GiNaC::numeric(frequency[i])) * symbols_[i]);
    const ex argument = sum_of(terms);
    bucket.emplace_back(std::move(key), kind == wave::cos ? GiNaC::cos(argument) : GiNaC::sin(argument));
    return bucket.back().second;
}

const GiNaC::ex& harmonic_space::power(std::size_t index, std::int32_t exponent) const
{
    const std::uint64_t key = (static_cast<std::uint64_t>(index) << 32) | static_cast<std::uint32_t>(exponent);
    auto found = powers_.find(key);
    if (found != powers_.end())
        return found->second;
    const ex& symbol = symbols_[index];
    return powers_.emplace(key, exponent == 1 ? symbol : GiNaC::pow(symbol, exponent)).first->second;
}

GiNaC::ex harmonic_space::number(const cln::cl_RA& c)
{
    return GiNaC::numeric(cln::cl_N(c));
}

GiNaC::ex to_ex(const harmonic_polynomial& p)
{
    const harmonic_space& space = p.space();
    exvector terms;
    terms.reserve(p.size());
    exvector factors;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const harmonic_term t = p.term(i);
        factors.clear();
        if (!cln::equal(*t.coefficient, cln::cl_RA(1)))
            factors.push_back(harmonic_space::number(*t.coefficient));
        for (std::size_t s = 0; s < p.symbol_count(); ++s)
            if (t.exponents[s] != 0)
                factors.push_back(space.power(s, t.exponents[s]));
        if (t.kind != wave::none)
            factors.push_back(space.wave_function(t.kind, t.frequency));
        terms.push_back(product_of(factors));
    }
    return sum_of(terms);
}

} // namespace lagrange
