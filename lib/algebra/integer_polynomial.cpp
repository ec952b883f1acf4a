// SPDX-License-Identifier: GPL-2.0-or-later
/** @file integer_polynomial.cpp
 *  GiNaC expressions to and from FLINT's fmpz_mpoly (see integer_polynomial.h). */
#include "algebra/integer_polynomial.h"

#include "algebra/budget.h"
#include "algebra/factor.h"

#include <flint/fmpz.h>
#include <flint/fmpz_mpoly.h>
#include <flint/fmpz_mpoly_factor.h>

#include <algorithm>
#include <climits>
#include <map>
#include <sstream>
#include <string>
#include <utility>

namespace lagrange {

namespace {

using GiNaC::ex;
using GiNaC::ex_to;
using GiNaC::is_a;
using GiNaC::numeric;

/// A FLINT context of polynomials in the given number of variables, lexicographic order
/// (variable 0 most significant).
class context {
public:
    explicit context(std::size_t variables) { fmpz_mpoly_ctx_init(ctx_, static_cast<slong>(variables), ORD_LEX); }
    ~context() { fmpz_mpoly_ctx_clear(ctx_); }
    context(const context&) = delete;
    context& operator=(const context&) = delete;
    const fmpz_mpoly_ctx_struct* get() const { return ctx_; }

private:
    fmpz_mpoly_ctx_t ctx_;
};

/// One fmpz_mpoly, owned.
class polynomial {
public:
    explicit polynomial(const context& c) : context_(&c) { fmpz_mpoly_init(value_, c.get()); }
    ~polynomial() { fmpz_mpoly_clear(value_, context_->get()); }
    polynomial(polynomial&& other) noexcept : context_(other.context_)
    {
        fmpz_mpoly_init(value_, context_->get());
        fmpz_mpoly_swap(value_, other.value_, context_->get());
    }
    polynomial& operator=(polynomial&& other) noexcept
    {
        fmpz_mpoly_swap(value_, other.value_, context_->get());
        return *this;
    }
    polynomial(const polynomial&) = delete;
    polynomial& operator=(const polynomial&) = delete;
    fmpz_mpoly_struct* get() { return value_; }
    const fmpz_mpoly_struct* get() const { return value_; }

private:
    const context* context_;
    fmpz_mpoly_t value_;
};

/// An owned fmpz.
class integer {
public:
    integer() { fmpz_init(value_); }
    ~integer() { fmpz_clear(value_); }
    integer(const integer&) = delete;
    integer& operator=(const integer&) = delete;
    fmpz* get() { return value_; }
    const fmpz* get() const { return value_; }

private:
    fmpz_t value_;
};

void set_integer(fmpz* z, const numeric& n)
{
    static const numeric small(1L << 62);
    if (GiNaC::abs(n) < small) {
        fmpz_set_si(z, n.to_long());
        return;
    }
    std::ostringstream digits;
    digits << n;
    fmpz_set_str(z, digits.str().c_str(), 10);
}

numeric to_numeric(const fmpz* z)
{
    if (fmpz_fits_si(z))
        return numeric(fmpz_get_si(z));
    char* digits = fmpz_get_str(nullptr, 10, z);
    numeric n(digits);
    flint_free(digits);
    return n;
}

/// The plain symbols of the expressions, ordered by name (then by GiNaC's order of
/// creation, for two symbols of one name).
std::vector<ex> symbols_of(const std::vector<ex>& expressions)
{
    GiNaC::exset found;
    for (const ex& e : expressions)
        for (GiNaC::const_preorder_iterator i = e.preorder_begin(); i != e.preorder_end(); ++i)
            if (is_a<GiNaC::symbol>(*i))
                found.insert(*i);
    std::vector<ex> symbols(found.begin(), found.end());
    std::sort(symbols.begin(), symbols.end(), [](const ex& a, const ex& b) {
        const std::string& na = ex_to<GiNaC::symbol>(a).get_name();
        const std::string& nb = ex_to<GiNaC::symbol>(b).get_name();
        return na != nb ? na < nb : a.compare(b) < 0;
    });
    return symbols;
}

/// The symbols of one ring and their indices.
struct ring {
    explicit ring(std::vector<ex> symbols_) : symbols(std::move(symbols_)), flint(symbols.size())
    {
        for (std::size_t k = 0; k < symbols.size(); ++k)
            index[symbols[k]] = k;
    }
    std::vector<ex> symbols;
    std::map<ex, std::size_t, GiNaC::ex_is_less> index;
    context flint;
};

GiNaC::exvector terms_of(const ex& p)
{
    return is_a<GiNaC::add>(p) ? GiNaC::exvector(p.begin(), p.end()) : GiNaC::exvector{p};
}

/// The rational number and the exponents of one term of an expanded polynomial; false if
/// the term is not a rational number times powers of the ring's symbols.
bool read_term(const ring& r, const ex& term, numeric& coefficient, std::vector<ulong>& exponents)
{
    coefficient = 1;
    std::fill(exponents.begin(), exponents.end(), 0);
    const GiNaC::exvector factors = is_a<GiNaC::mul>(term) ? GiNaC::exvector(term.begin(), term.end())
                                                           : GiNaC::exvector{term};
    for (const ex& f : factors) {
        if (is_a<GiNaC::numeric>(f)) {
            coefficient *= ex_to<numeric>(f);
            continue;
        }
        const bool is_power = is_a<GiNaC::power>(f);
        const ex base = is_power ? f.op(0) : f;
        if (is_power && !f.op(1).info(GiNaC::info_flags::posint))
            return false;
        auto at = r.index.find(base);
        if (at == r.index.end())
            return false;
        exponents[at->second] += is_power ? static_cast<ulong>(ex_to<numeric>(f.op(1)).to_long()) : 1;
    }
    return coefficient.is_rational();
}

/// An expanded polynomial with rational coefficients as `scale` times an integer
/// polynomial, where `scale` is its rational content (positive): the integer polynomial
/// has coefficients of gcd 1. Nothing if p is not such a polynomial in the ring's symbols.
std::optional<polynomial> to_flint(const ring& r, const ex& p, numeric& scale)
{
    const GiNaC::exvector terms = terms_of(p);
    std::vector<numeric> coefficients;
    std::vector<std::vector<ulong>> exponents;
    coefficients.reserve(terms.size());
    exponents.reserve(terms.size());
    numeric numerator_gcd = 0, denominator_lcm = 1;
    for (const ex& term : terms) {
        if (term.is_zero())
            continue;
        numeric c;
        std::vector<ulong> e(r.symbols.size());
        if (!read_term(r, term, c, e))
            return std::nullopt;
        numerator_gcd = GiNaC::gcd(numerator_gcd, c.numer());
        denominator_lcm = GiNaC::lcm(denominator_lcm, c.denom());
        coefficients.push_back(c);
        exponents.push_back(std::move(e));
    }
    scale = coefficients.empty() ? numeric(1) : GiNaC::abs(numerator_gcd) / denominator_lcm;
    polynomial result(r.flint);
    integer z;
    for (std::size_t t = 0; t < coefficients.size(); ++t) {
        set_integer(z.get(), coefficients[t] / scale);
        fmpz_mpoly_push_term_fmpz_ui(result.get(), z.get(), exponents[t].data(), r.flint.get());
    }
    fmpz_mpoly_sort_terms(result.get(), r.flint.get());
    fmpz_mpoly_combine_like_terms(result.get(), r.flint.get());
    return result;
}

/// p as a GiNaC sum, built from pairs (monomial, number) as GiNaC stores it: building
/// each term as a product first and letting GiNaC split it again is what dominates the
/// conversion of a polynomial of thousands of terms.
ex to_ex(const ring& r, const polynomial& p)
{
    const slong length = fmpz_mpoly_length(p.get(), r.flint.get());
    GiNaC::epvector terms;
    terms.reserve(static_cast<std::size_t>(length));
    ex constant = 0;
    std::vector<ulong> exponents(r.symbols.size());
    integer c;
    for (slong t = 0; t < length; ++t) {
        fmpz_mpoly_get_term_coeff_fmpz(c.get(), p.get(), t, r.flint.get());
        fmpz_mpoly_get_term_exp_ui(exponents.data(), p.get(), t, r.flint.get());
        GiNaC::epvector powers;
        for (std::size_t k = 0; k < r.symbols.size(); ++k)
            if (exponents[k] > 0)
                powers.push_back(GiNaC::expair(r.symbols[k], numeric(static_cast<long>(exponents[k]))));
        const numeric coefficient = to_numeric(c.get());
        if (powers.empty())
            constant = coefficient;
        else if (powers.size() == 1)
            terms.push_back(GiNaC::expair(GiNaC::pow(powers[0].rest, powers[0].coeff), coefficient));
        else
            terms.push_back(GiNaC::expair(GiNaC::dynallocate<GiNaC::mul>(std::move(powers), ex(1)), coefficient));
    }
    if (terms.empty())
        return constant;
    return GiNaC::dynallocate<GiNaC::add>(std::move(terms), constant);
}

/// The sign of p's leading coefficient (its first term in lexicographic order).
int leading_sign(const ring& r, const polynomial& p)
{
    if (fmpz_mpoly_length(p.get(), r.flint.get()) == 0)
        return 0;
    integer c;
    fmpz_mpoly_get_term_coeff_fmpz(c.get(), p.get(), 0, r.flint.get());
    return fmpz_sgn(c.get());
}

/// The product that a FLINT factorization stands for, times `scale`: each base made to
/// lead with a positive coefficient, expanded, to its power.
ex product_of_factors(const ring& r, fmpz_mpoly_factor_t factors, const numeric& scale)
{
    integer constant;
    fmpz_mpoly_factor_get_constant_fmpz(constant.get(), factors, r.flint.get());
    numeric unit = scale * to_numeric(constant.get());
    GiNaC::exvector product;
    const slong count = fmpz_mpoly_factor_length(factors, r.flint.get());
    for (slong k = 0; k < count; ++k) {
        polynomial base(r.flint);
        fmpz_mpoly_factor_get_base(base.get(), factors, k, r.flint.get());
        const slong exponent = fmpz_mpoly_factor_get_exp_si(factors, k, r.flint.get());
        if (leading_sign(r, base) < 0) {
            fmpz_mpoly_neg(base.get(), base.get(), r.flint.get());
            if (exponent % 2 != 0)
                unit = -unit;
        }
        product.push_back(GiNaC::pow(to_ex(r, base), exponent));
    }
    product.push_back(unit);
    return GiNaC::mul(product);
}

numeric rational_gcd(const numeric& a, const numeric& b)
{
    if (a.is_zero())
        return GiNaC::abs(b);
    if (b.is_zero())
        return GiNaC::abs(a);
    return GiNaC::gcd(a.numer(), b.numer()) / GiNaC::lcm(a.denom(), b.denom());
}

} // namespace

std::optional<ex> polynomial_gcd(const std::vector<ex>& polynomials)
{
    std::vector<ex> nonzero;
    for (const ex& p : polynomials)
        if (!p.is_zero())
            nonzero.push_back(p.expand());
    if (nonzero.empty())
        return ex(0);
    const ring r(symbols_of(nonzero));
    numeric number = 0;
    std::optional<polynomial> result;
    for (const ex& p : nonzero) {
        budget_check();
        numeric scale;
        std::optional<polynomial> f = to_flint(r, p, scale);
        if (!f)
            return std::nullopt;
        number = rational_gcd(number, scale);
        if (!result) {
            result = std::move(f);
            continue;
        }
        polynomial g(r.flint);
        if (!fmpz_mpoly_gcd(g.get(), result->get(), f->get(), r.flint.get()))
            return std::nullopt;
        *result = std::move(g);
    }
    if (leading_sign(r, *result) < 0)
        fmpz_mpoly_neg(result->get(), result->get(), r.flint.get());
    return number * to_ex(r, *result);
}

std::optional<ex> polynomial_factor(const ex& p)
{
    const ex expanded = p.expand();
    if (expanded.is_zero())
        return ex(0);
    const ring r(symbols_of({expanded}));
    numeric scale;
    std::optional<polynomial> f = to_flint(r, expanded, scale);
    if (!f)
        return std::nullopt;
    budget_check();
    fmpz_mpoly_factor_t factors;
    fmpz_mpoly_factor_init(factors, r.flint.get());
    if (!fmpz_mpoly_factor(factors, f->get(), r.flint.get())) {
        fmpz_mpoly_factor_clear(factors, r.flint.get());
        return std::nullopt;
    }
    const ex result = product_of_factors(r, factors, scale);
    fmpz_mpoly_factor_clear(factors, r.flint.get());
    return result;
}

std::optional<bool> polynomials_coprime(const ex& a, const ex& b)
{
    if (a.is_zero() || b.is_zero())
        return false;
    std::optional<ex> g = polynomial_gcd({a, b});
    if (!g)
        return std::nullopt;
    return is_a<numeric>(*g);
}

namespace {

/// det(entries) = scale · det_flint in the ring `r` (which holds every symbol of the
/// entries); false if an entry is not a polynomial with rational coefficients.
bool determinant_in(const ring& r, const std::vector<std::vector<ex>>& entries, polynomial& det, numeric& scale)
{
    const std::size_t n = entries.size();
    // each row over a common integer scale: det = Π scale_i · det(integer rows)
    scale = 1;
    std::vector<std::vector<polynomial>> rows(n);
    for (std::size_t i = 0; i < n; ++i) {
        std::vector<numeric> scales;
        numeric row_lcm = 1;
        for (std::size_t j = 0; j < n; ++j) {
            numeric entry_scale;
            std::optional<polynomial> f = to_flint(r, entries[i][j].expand(), entry_scale);
            if (!f)
                return false;
            rows[i].push_back(std::move(*f));
            scales.push_back(entry_scale);
            row_lcm = GiNaC::lcm(row_lcm, entry_scale.denom());
        }
        numeric row_gcd = 0;
        for (const numeric& s : scales)
            row_gcd = GiNaC::gcd(row_gcd, (s * row_lcm).numer());
        if (row_gcd.is_zero()) {
            fmpz_mpoly_zero(det.get(), r.flint.get());
            return true;
        }
        for (std::size_t j = 0; j < n; ++j) {
            integer z;
            set_integer(z.get(), scales[j] * row_lcm / row_gcd);
            fmpz_mpoly_scalar_mul_fmpz(rows[i][j].get(), rows[i][j].get(), z.get(), r.flint.get());
        }
        scale *= row_gcd / row_lcm;
    }
    // minor[S]: the determinant of rows n − |S| … n − 1 and the columns in the bit set S,
    // expanded along its first row; built up from the last row.
    std::vector<std::optional<polynomial>> minor(std::size_t(1) << n);
    minor[0].emplace(r.flint);
    fmpz_mpoly_one(minor[0]->get(), r.flint.get());
    polynomial product(r.flint);
    for (std::size_t size = 1; size <= n; ++size) {
        const std::size_t row = n - size;
        for (std::size_t columns = 1; columns < minor.size(); ++columns) {
            if (static_cast<std::size_t>(__builtin_popcountll(columns)) != size)
                continue;
            polynomial sum(r.flint);
            bool negative = false;
            for (std::size_t j = 0; j < n; ++j) {
                if (!(columns >> j & 1))
                    continue;
                const polynomial& rest = *minor[columns & ~(std::size_t(1) << j)];
                budget_check();
                fmpz_mpoly_mul(product.get(), rows[row][j].get(), rest.get(), r.flint.get());
                if (negative)
                    fmpz_mpoly_sub(sum.get(), sum.get(), product.get(), r.flint.get());
                else
                    fmpz_mpoly_add(sum.get(), sum.get(), product.get(), r.flint.get());
                negative = !negative;
            }
            budget_check_count(static_cast<std::size_t>(fmpz_mpoly_length(sum.get(), r.flint.get())),
                               "a minor of the determinant");
            minor[columns] = std::move(sum);
        }
        for (std::size_t columns = 1; columns < minor.size(); ++columns)
            if (static_cast<std::size_t>(__builtin_popcountll(columns)) == size - 1)
                minor[columns].reset();
    }
    det = std::move(*minor.back());
    return true;
}

std::vector<ex> all_entries(const std::vector<std::vector<ex>>& entries)
{
    std::vector<ex> all;
    for (const auto& row : entries)
        all.insert(all.end(), row.begin(), row.end());
    return all;
}

} // namespace

std::optional<ex> polynomial_determinant(const std::vector<std::vector<ex>>& entries)
{
    if (entries.empty())
        return ex(1);
    if (entries.size() > 16)
        return std::nullopt;
    const ring r(symbols_of(all_entries(entries)));
    polynomial det(r.flint);
    numeric scale;
    if (!determinant_in(r, entries, det, scale))
        return std::nullopt;
    return scale * to_ex(r, det);
}

struct polynomial_by_powers::state {
    explicit state(std::vector<ex> symbols) : r(std::move(symbols)) {}
    ring r;
    std::vector<polynomial> parts;
    ex content;
    std::vector<ex> expanded;
};

polynomial_by_powers::polynomial_by_powers(std::unique_ptr<state> s) : state_(std::move(s)) {}
polynomial_by_powers::~polynomial_by_powers() = default;
polynomial_by_powers::polynomial_by_powers(polynomial_by_powers&&) noexcept = default;
polynomial_by_powers& polynomial_by_powers::operator=(polynomial_by_powers&&) noexcept = default;

const ex& polynomial_by_powers::content() const { return state_->content; }
const std::vector<ex>& polynomial_by_powers::parts() const { return state_->expanded; }

ex polynomial_by_powers::factored_part(std::size_t k) const
{
    budget_check();
    const ring& r = state_->r;
    const polynomial& part = state_->parts.at(k);
    std::vector<slong> degrees(r.symbols.size());
    fmpz_mpoly_degrees_si(degrees.data(), part.get(), r.flint.get());
    const auto present = std::count_if(degrees.begin(), degrees.end(), [](slong d) { return d > 0; });
    if (fmpz_mpoly_length(part.get(), r.flint.get()) <= 4 || present <= 3)
        return factor_if_quick(state_->expanded.at(k));
    fmpz_mpoly_factor_t factors;
    fmpz_mpoly_factor_init(factors, r.flint.get());
    std::optional<ex> result;
    if (fmpz_mpoly_factor(factors, part.get(), r.flint.get()))
        result = product_of_factors(r, factors, 1);
    fmpz_mpoly_factor_clear(factors, r.flint.get());
    return result ? *result : factor_if_quick(state_->expanded.at(k));
}

std::optional<polynomial_by_powers> determinant_by_powers(const std::vector<std::vector<ex>>& entries,
                                                          const GiNaC::symbol& variable)
{
    if (entries.empty() || entries.size() > 16)
        return std::nullopt;
    std::vector<ex> all = all_entries(entries);
    all.push_back(variable);
    auto s = std::make_unique<polynomial_by_powers::state>(symbols_of(all));
    const ring& r = s->r;
    polynomial det(r.flint);
    numeric scale;
    if (!determinant_in(r, entries, det, scale))
        return std::nullopt;
    s->content = 0;
    if (fmpz_mpoly_is_zero(det.get(), r.flint.get()))
        return polynomial_by_powers(std::move(s));
    const slong v = static_cast<slong>(r.index.at(variable));
    const slong degree = fmpz_mpoly_degree_si(det.get(), v, r.flint.get());
    polynomial content(r.flint);
    for (slong k = 0; k <= degree; ++k) {
        budget_check();
        polynomial part(r.flint);
        const ulong exponent = static_cast<ulong>(k);
        fmpz_mpoly_get_coeff_vars_ui(part.get(), det.get(), &v, &exponent, 1, r.flint.get());
        if (!fmpz_mpoly_is_zero(part.get(), r.flint.get())) {
            polynomial g(r.flint);
            if (!fmpz_mpoly_gcd(g.get(), content.get(), part.get(), r.flint.get()))
                return std::nullopt;
            content = std::move(g);
        }
        s->parts.push_back(std::move(part));
    }
    if (leading_sign(r, content) < 0)
        fmpz_mpoly_neg(content.get(), content.get(), r.flint.get());
    s->content = scale * to_ex(r, content);
    for (polynomial& part : s->parts) {
        budget_check();
        polynomial quotient(r.flint);
        if (!fmpz_mpoly_divides(quotient.get(), part.get(), content.get(), r.flint.get()))
            return std::nullopt;
        part = std::move(quotient);
        s->expanded.push_back(to_ex(r, part));
    }
    return polynomial_by_powers(std::move(s));
}

} // namespace lagrange
