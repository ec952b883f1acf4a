/** @file factor.cpp
 *  GiNaC's factor() where it is quick, and a quicker route for the large sparse
 *  polynomials of characteristic polynomials (see factor.h). */
#include "algebra/factor.h"

#include "algebra/budget.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <map>
#include <string>
#include <vector>

namespace lagrange {

namespace {

using GiNaC::ex;
using GiNaC::ex_to;
using GiNaC::is_a;

/// The symbols of e ordered by name (then by GiNaC's order of creation), so that
/// every choice below is the same from run to run.
std::vector<ex> symbols_of(const ex& e)
{
    GiNaC::exset found;
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

/// The coefficient of the highest power of the first symbol, of the second, … : a
/// number, whose sign fixes the sign of a polynomial's irreducible factors.
GiNaC::numeric leading_number(ex p, const std::vector<ex>& symbols)
{
    for (const ex& x : symbols)
        p = p.lcoeff(x);
    return is_a<GiNaC::numeric>(p) ? ex_to<GiNaC::numeric>(p) : GiNaC::numeric(1);
}

/// A small integer for the k-th coordinate of the attempt-th evaluation point.
int point_value(std::size_t k, int attempt)
{
    return 2 + static_cast<int>((k * 7919 + static_cast<std::size_t>(attempt) * 104729 + 13) % 89);
}

/// An expanded polynomial p at `point` (every symbol but y) as a polynomial in y, read off
/// term by term (GiNaC's subs would rebuild every term).
ex image_at(const ex& p, const ex& y, const GiNaC::exmap& point)
{
    std::map<int, GiNaC::numeric> coefficients;
    const GiNaC::exvector terms = is_a<GiNaC::add>(p) ? GiNaC::exvector(p.begin(), p.end()) : GiNaC::exvector{p};
    for (const ex& term : terms) {
        GiNaC::numeric value = 1;
        int degree = 0;
        const GiNaC::exvector factors = is_a<GiNaC::mul>(term) ? GiNaC::exvector(term.begin(), term.end())
                                                               : GiNaC::exvector{term};
        for (const ex& f : factors) {
            const bool is_power = is_a<GiNaC::power>(f);
            const ex base = is_power ? f.op(0) : f;
            if (is_a<GiNaC::numeric>(f)) {
                value *= ex_to<GiNaC::numeric>(f);
                continue;
            }
            if (!is_a<GiNaC::symbol>(base) || (is_power && !f.op(1).info(GiNaC::info_flags::posint)))
                return p.subs(point).expand(); // not a plain polynomial term
            const int exponent = is_power ? ex_to<GiNaC::numeric>(f.op(1)).to_int() : 1;
            if (base.is_equal(y)) {
                degree += exponent;
                continue;
            }
            auto at = point.find(base);
            if (at == point.end())
                return p.subs(point).expand();
            value *= ex_to<GiNaC::numeric>(at->second).power(exponent);
        }
        coefficients[degree] += value;
    }
    ex image = 0;
    for (const auto& [degree, c] : coefficients)
        image += c * GiNaC::pow(y, degree);
    return image;
}

/// Arithmetic modulo the prime 2³¹ − 1, for images of polynomials in one symbol.
constexpr std::uint64_t modulus = 2147483647;

std::uint64_t power_mod(std::uint64_t base, std::uint64_t exponent)
{
    std::uint64_t result = 1;
    base %= modulus;
    for (; exponent > 0; exponent >>= 1, base = base * base % modulus)
        if (exponent & 1)
            result = result * base % modulus;
    return result;
}

/// An expanded polynomial read once: per term its coefficient modulo the prime and its
/// exponents (symbol index, exponent).
struct term_list {
    std::vector<std::uint64_t> coefficients;
    std::vector<std::vector<std::pair<std::size_t, int>>> exponents;
};

std::optional<term_list> read_terms(const ex& p, const std::map<ex, std::size_t, GiNaC::ex_is_less>& index)
{
    term_list list;
    const GiNaC::exvector terms = is_a<GiNaC::add>(p) ? GiNaC::exvector(p.begin(), p.end()) : GiNaC::exvector{p};
    for (const ex& term : terms) {
        GiNaC::numeric value = 1;
        std::vector<std::pair<std::size_t, int>> exponents;
        const GiNaC::exvector factors = is_a<GiNaC::mul>(term) ? GiNaC::exvector(term.begin(), term.end())
                                                               : GiNaC::exvector{term};
        for (const ex& f : factors) {
            if (is_a<GiNaC::numeric>(f)) {
                value *= ex_to<GiNaC::numeric>(f);
                continue;
            }
            const bool is_power = is_a<GiNaC::power>(f);
            const ex base = is_power ? f.op(0) : f;
            if (is_power && !f.op(1).info(GiNaC::info_flags::posint))
                return std::nullopt;
            auto at = index.find(base);
            if (at == index.end())
                return std::nullopt;
            exponents.push_back({at->second, is_power ? ex_to<GiNaC::numeric>(f.op(1)).to_int() : 1});
        }
        if (!value.is_rational())
            return std::nullopt;
        const GiNaC::numeric p_ = static_cast<long>(modulus);
        const std::uint64_t denominator = GiNaC::mod(value.denom(), p_).to_long();
        if (denominator == 0)
            return std::nullopt;
        const std::uint64_t numerator = GiNaC::mod(value.numer(), p_).to_long();
        list.coefficients.push_back(numerator * power_mod(denominator, modulus - 2) % modulus);
        list.exponents.push_back(std::move(exponents));
    }
    return list;
}

/// The image in y (index `y`) at `point`, coefficients lowest degree first, trimmed.
std::vector<std::uint64_t> image_mod(const term_list& list, std::size_t y, const std::vector<std::uint64_t>& point)
{
    std::vector<std::uint64_t> image;
    for (std::size_t t = 0; t < list.coefficients.size(); ++t) {
        std::uint64_t value = list.coefficients[t];
        std::size_t degree = 0;
        for (const auto& [k, e] : list.exponents[t]) {
            if (k == y)
                degree += static_cast<std::size_t>(e);
            else
                value = value * power_mod(point[k], static_cast<std::uint64_t>(e)) % modulus;
        }
        if (image.size() <= degree)
            image.resize(degree + 1, 0);
        image[degree] = (image[degree] + value) % modulus;
    }
    while (!image.empty() && image.back() == 0)
        image.pop_back();
    return image;
}

/// The degree of gcd(a, b) over the integers modulo the prime (Euclid); −1 if both are 0.
int gcd_degree_mod(std::vector<std::uint64_t> a, std::vector<std::uint64_t> b)
{
    while (!b.empty()) {
        // a mod b
        const std::uint64_t inverse = power_mod(b.back(), modulus - 2);
        while (a.size() >= b.size()) {
            const std::uint64_t factor = a.back() * inverse % modulus;
            const std::size_t shift = a.size() - b.size();
            for (std::size_t i = 0; i < b.size(); ++i)
                a[shift + i] = (a[shift + i] + modulus - factor * b[i] % modulus) % modulus;
            while (!a.empty() && a.back() == 0)
                a.pop_back();
            if (a.empty())
                break;
        }
        std::swap(a, b);
    }
    return static_cast<int>(a.size()) - 1;
}

/// coprime_by_images on images modulo the prime: nothing if a or b is not a polynomial
/// in plain symbols with rational coefficients.
std::optional<bool> coprime_by_modular_images(const ex& a, const ex& b, const std::vector<ex>& symbols)
{
    std::map<ex, std::size_t, GiNaC::ex_is_less> index;
    for (std::size_t k = 0; k < symbols.size(); ++k)
        index[symbols[k]] = k;
    std::optional<term_list> ta = read_terms(a, index), tb = read_terms(b, index);
    if (!ta || !tb)
        return std::nullopt;
    std::vector<int> degree_a(symbols.size(), 0), degree_b(symbols.size(), 0);
    for (const auto& exponents : ta->exponents)
        for (const auto& [k, e] : exponents)
            degree_a[k] = std::max(degree_a[k], e);
    for (const auto& exponents : tb->exponents)
        for (const auto& [k, e] : exponents)
            degree_b[k] = std::max(degree_b[k], e);
    for (std::size_t y = 0; y < symbols.size(); ++y) {
        const int degree = degree_a[y];
        if (degree == 0 || degree_b[y] == 0)
            continue;
        bool proven = false;
        for (int attempt = 0; attempt < 3 && !proven; ++attempt) {
            budget_check();
            std::vector<std::uint64_t> point(symbols.size());
            for (std::size_t k = 0; k < symbols.size(); ++k)
                point[k] = static_cast<std::uint64_t>(point_value(k, attempt));
            const std::vector<std::uint64_t> image_a = image_mod(*ta, y, point);
            if (static_cast<int>(image_a.size()) - 1 != degree)
                continue; // the leading coefficient vanished there
            proven = gcd_degree_mod(image_a, image_mod(*tb, y, point)) == 0;
        }
        if (!proven)
            return false;
    }
    return true;
}

} // namespace

bool coprime_by_images(const ex& a, const ex& b)
{
    if (is_a<GiNaC::numeric>(a) || is_a<GiNaC::numeric>(b))
        return !a.is_zero() && !b.is_zero();
    // A common factor of positive degree in y divides the images of a and b at any point
    // of the other symbols, with its degree in y kept wherever the leading coefficient of
    // a in y does not vanish: so images without a common factor in y, for every y,
    // prove that there is none.
    const std::vector<ex> symbols = symbols_of(GiNaC::lst{a, b});
    if (std::optional<bool> modular = coprime_by_modular_images(a, b, symbols))
        return *modular;
    for (std::size_t index = 0; index < symbols.size(); ++index) {
        const ex& y = symbols[index];
        const int degree = a.degree(y);
        if (degree == 0 || b.degree(y) == 0)
            continue;
        bool proven = false;
        for (int attempt = 0; attempt < 3 && !proven; ++attempt) {
            budget_check();
            GiNaC::exmap point;
            for (std::size_t k = 0; k < symbols.size(); ++k)
                if (k != index)
                    point[symbols[k]] = point_value(k, attempt);
            const ex image_a = image_at(a, y, point);
            if (image_a.degree(y) != degree)
                continue;
            proven = GiNaC::gcd(image_a, image_at(b, y, point)).degree(y) == 0;
        }
        if (!proven)
            return false;
    }
    return true;
}

namespace {

ex factor_expanded(const ex& p);

/// The factors of a primitive polynomial with integer coefficients, no monomial factor
/// and a positive leading number: where it has degree 1 in some symbol x, p = a x + b
/// is its content gcd(a, b) times an irreducible polynomial (degree 1 in x, primitive),
/// and only the content, smaller and free of x, is factored further.
ex factor_primitive(const ex& p, const std::vector<ex>& symbols)
{
    for (const ex& x : symbols) {
        if (p.degree(x) != 1)
            continue;
        const ex a = p.coeff(x, 1), b = p.coeff(x, 0);
        if (coprime_by_images(a, b))
            return p;
        budget_check();
        const ex content = GiNaC::gcd(a, b);
        ex cofactor;
        if (is_a<GiNaC::numeric>(content) || !GiNaC::divide(p, content, cofactor))
            return p;
        // the cofactor is irreducible; its sign and integer content go to a number
        GiNaC::numeric unit = cofactor.integer_content();
        if (leading_number(cofactor, symbols).is_negative())
            unit = -unit;
        return factor_expanded(content.expand()) * unit * (cofactor / unit).expand();
    }
    budget_check();
    return GiNaC::factor(p);
}

/// The factors of an expanded polynomial with rational coefficients: its number, its
/// monomial factor and the factors of the rest (factor_primitive).
ex factor_expanded(const ex& p)
{
    budget_check();
    if (!is_a<GiNaC::add>(p))
        return p;
    const std::vector<ex> symbols = symbols_of(p);
    GiNaC::numeric number = p.integer_content();
    if (leading_number(p, symbols).is_negative())
        number = -number;
    ex monomial = 1;
    for (const ex& x : symbols)
        if (int k = p.ldegree(x); k > 0)
            monomial *= GiNaC::pow(x, k);
    const ex rest = (p / (number * monomial)).expand();
    return number * monomial * factor_primitive(rest, symbols);
}

/// Whether GiNaC's factor() is left to do a polynomial: few terms or few symbols, where
/// it is quick (its forms are those every example prints).
bool small_for_factor(const ex& expanded)
{
    if (!is_a<GiNaC::add>(expanded) || expanded.nops() <= 4)
        return true;
    return symbols_of(expanded).size() <= 3;
}

/// One factor of an explicit product.
ex factor_one(const ex& f)
{
    if (!f.info(GiNaC::info_flags::rational_polynomial))
        return GiNaC::factor(f);
    const ex expanded = f.expand();
    if (small_for_factor(expanded))
        return GiNaC::factor(f);
    return factor_expanded(expanded);
}

} // namespace

bool too_large_to_factor(const GiNaC::ex& e)
{
    if (GiNaC::is_a<GiNaC::power>(e)) {
        const GiNaC::ex& exponent = e.op(1);
        if (GiNaC::is_a<GiNaC::numeric>(exponent)) {
            const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(exponent);
            if (n.is_integer() && GiNaC::abs(n) > factor_max_degree)
                return true;
        }
    }
    for (const GiNaC::ex& operand : e)
        if (too_large_to_factor(operand))
            return true;
    return false;
}

GiNaC::ex factor_if_quick(const GiNaC::ex& e)
{
    budget_check();
    if (too_large_to_factor(e))
        return e;
    if (!e.info(GiNaC::info_flags::rational_polynomial))
        return GiNaC::factor(e);
    // each explicit factor on its own, as GiNaC's factor() does
    const GiNaC::exvector factors = is_a<GiNaC::mul>(e) ? GiNaC::exvector(e.begin(), e.end()) : GiNaC::exvector{e};
    ex result = 1;
    for (const ex& f : factors) {
        if (is_a<GiNaC::power>(f) && f.op(1).info(GiNaC::info_flags::posint))
            result *= GiNaC::pow(factor_one(f.op(0)), f.op(1));
        else
            result *= factor_one(f);
    }
    return result;
}

GiNaC::ex polynomial_content(const std::vector<GiNaC::ex>& polynomials)
{
    std::vector<ex> nonzero;
    for (const ex& p : polynomials)
        if (!p.is_zero())
            nonzero.push_back(p.expand());
    if (nonzero.empty())
        return 0;
    bool integral = true;
    for (const ex& p : nonzero)
        integral = integral && p.info(GiNaC::info_flags::rational_polynomial) &&
                   p.integer_content().is_integer();
    if (!integral) {
        ex content = nonzero.front();
        for (std::size_t k = 1; k < nonzero.size(); ++k)
            content = GiNaC::gcd(content, nonzero[k]);
        return content;
    }
    // the common number and monomial first: cheap, and what GiNaC's gcd is slowest at
    GiNaC::numeric number = nonzero.front().integer_content();
    GiNaC::lst all;
    for (const ex& p : nonzero) {
        number = GiNaC::gcd(number, p.integer_content());
        all.append(p);
    }
    ex monomial = 1;
    for (const ex& x : symbols_of(all)) {
        int k = nonzero.front().ldegree(x);
        for (const ex& p : nonzero)
            k = std::min(k, p.ldegree(x));
        if (k > 0)
            monomial *= GiNaC::pow(x, k);
    }
    std::vector<ex> rest;
    for (const ex& p : nonzero)
        rest.push_back((p / (number * monomial)).expand());
    std::stable_sort(rest.begin(), rest.end(), [](const ex& a, const ex& b) {
        return (is_a<GiNaC::add>(a) ? a.nops() : 1) < (is_a<GiNaC::add>(b) ? b.nops() : 1);
    });
    if (rest.size() == 1)
        return number * monomial * rest.front();
    if (coprime_by_images(rest[0], rest[1]))
        return number * monomial;
    ex content = rest.front();
    for (std::size_t k = 1; k < rest.size() && !is_a<GiNaC::numeric>(content); ++k) {
        budget_check();
        content = GiNaC::gcd(content, rest[k]);
    }
    return number * monomial * content;
}

namespace {

GiNaC::ex with_pi_as_symbol(const GiNaC::ex& e, GiNaC::ex (*f)(const GiNaC::ex&))
{
    static const GiNaC::possymbol pi("Pi");
    return f(e.subs(GiNaC::Pi == pi)).subs(pi == GiNaC::Pi);
}

GiNaC::ex normal_of(const GiNaC::ex& e) { return e.normal(); }
GiNaC::ex factor_of(const GiNaC::ex& e) { return factor_if_quick(e.normal()); }

} // namespace

GiNaC::ex normal_with_pi(const GiNaC::ex& e) { return with_pi_as_symbol(e, normal_of); }
GiNaC::ex factor_with_pi(const GiNaC::ex& e) { return with_pi_as_symbol(e, factor_of); }

} // namespace lagrange
