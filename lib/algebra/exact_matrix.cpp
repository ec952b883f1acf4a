/** @file exact_matrix.cpp
 *  Fraction-free determinants, leading minors and null spaces (see exact_matrix.h). */
#include "algebra/exact_matrix.h"

#include "algebra/budget.h"
#include "algebra/sign.h"
#include "core/errors.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <stdexcept>

namespace lagrange {

namespace {

using GiNaC::ex;

/// Polynomials with integer coefficients in at most 16 symbols of degree at most 255, for
/// the minor expansion: a monomial is its exponents packed in 128 bits (a product is a sum
/// of keys), a polynomial a hash map from monomial to coefficient. GiNaC's expand of the
/// same products spends most of its time building and hashing expression trees.
using monomial_key = unsigned __int128;

struct key_hash {
    std::size_t operator()(monomial_key k) const
    {
        const std::uint64_t low = static_cast<std::uint64_t>(k), high = static_cast<std::uint64_t>(k >> 64);
        return static_cast<std::size_t>(low * 0x9E3779B97F4A7C15ULL ^ (high + 0x632BE59BD9B4E019ULL) * 0xC2B2AE3D27D4EB4FULL);
    }
};

using sparse_polynomial = std::unordered_map<monomial_key, long long, key_hash>;

/// `p` as a sparse polynomial in `symbols`; nothing if it is not one with integer
/// coefficients and exponents below 256.
std::optional<sparse_polynomial> to_sparse(const ex& p, const std::vector<ex>& symbols)
{
    sparse_polynomial result;
    const GiNaC::exvector terms = GiNaC::is_a<GiNaC::add>(p) ? GiNaC::exvector(p.begin(), p.end()) : GiNaC::exvector{p};
    for (const ex& term : terms) {
        if (term.is_zero())
            continue;
        ex rest = term;
        monomial_key key = 0;
        for (std::size_t k = 0; k < symbols.size(); ++k) {
            const int degree = rest.degree(symbols[k]);
            if (degree < 0 || degree > 255 || rest.ldegree(symbols[k]) != degree)
                return std::nullopt;
            if (degree > 0) {
                key |= static_cast<monomial_key>(degree) << (8 * k);
                rest = rest.coeff(symbols[k], degree);
            }
        }
        if (!GiNaC::is_a<GiNaC::numeric>(rest) || !GiNaC::ex_to<GiNaC::numeric>(rest).is_integer())
            return std::nullopt;
        const GiNaC::numeric& c = GiNaC::ex_to<GiNaC::numeric>(rest);
        if (GiNaC::abs(c) > GiNaC::numeric(1L << 40))
            return std::nullopt;
        result[key] += c.to_long();
    }
    return result;
}

ex from_sparse(const sparse_polynomial& p, const std::vector<ex>& symbols)
{
    GiNaC::exvector terms;
    terms.reserve(p.size());
    for (const auto& [key, coefficient] : p) {
        if (coefficient == 0)
            continue;
        ex term = GiNaC::numeric(coefficient);
        for (std::size_t k = 0; k < symbols.size(); ++k)
            if (const int degree = static_cast<int>((key >> (8 * k)) & 0xFF); degree > 0)
                term *= GiNaC::pow(symbols[k], degree);
        terms.push_back(term);
    }
    return GiNaC::add(terms);
}

/// det by minor expansion in sparse polynomials; nothing if the entries are not such
/// polynomials, or an exponent or a coefficient could overflow.
std::optional<ex> sparse_expansion_determinant(const std::vector<std::vector<ex>>& entries)
{
    const std::size_t n = entries.size();
    GiNaC::exset found;
    for (const auto& row : entries)
        for (const ex& e : row)
            for (GiNaC::const_preorder_iterator i = e.preorder_begin(); i != e.preorder_end(); ++i)
                if (GiNaC::is_a<GiNaC::symbol>(*i))
                    found.insert(*i);
    if (found.size() > 16)
        return std::nullopt;
    const std::vector<ex> symbols(found.begin(), found.end());
    std::vector<std::vector<sparse_polynomial>> sparse(n);
    // exponent bound: a term of the determinant takes one entry from each row
    std::vector<int> bound(symbols.size(), 0);
    long double magnitude = 1;
    for (std::size_t i = 0; i < n; ++i) {
        std::vector<int> row_degree(symbols.size(), 0);
        long double row_magnitude = 0;
        for (std::size_t j = 0; j < n; ++j) {
            std::optional<sparse_polynomial> p = to_sparse(entries[i][j], symbols);
            if (!p)
                return std::nullopt;
            long double size = 0;
            for (const auto& [key, c] : *p)
                size += std::abs(static_cast<long double>(c));
            row_magnitude = std::max(row_magnitude, size);
            for (std::size_t k = 0; k < symbols.size(); ++k)
                row_degree[k] = std::max(row_degree[k], entries[i][j].degree(symbols[k]));
            sparse[i].push_back(std::move(*p));
        }
        for (std::size_t k = 0; k < symbols.size(); ++k)
            bound[k] += row_degree[k];
        magnitude *= row_magnitude * static_cast<long double>(n);
    }
    for (int b : bound)
        if (b > 255)
            return std::nullopt;
    if (magnitude > 1e18L) // a bound on every coefficient of every minor
        return std::nullopt;
    std::vector<sparse_polynomial> minor(std::size_t(1) << n);
    minor[0][0] = 1;
    for (std::size_t size = 1; size <= n; ++size) {
        const std::size_t row = n - size;
        for (std::size_t columns = 1; columns < minor.size(); ++columns) {
            if (static_cast<std::size_t>(__builtin_popcountll(columns)) != size)
                continue;
            sparse_polynomial sum;
            long long sign = 1;
            for (std::size_t j = 0; j < n; ++j) {
                if (!(columns >> j & 1))
                    continue;
                budget_check();
                for (const auto& [entry_key, entry_coefficient] : sparse[row][j])
                    for (const auto& [rest_key, rest_coefficient] : minor[columns & ~(std::size_t(1) << j)])
                        sum[entry_key + rest_key] += sign * entry_coefficient * rest_coefficient;
                sign = -sign;
            }
            for (auto i = sum.begin(); i != sum.end();)
                i = i->second == 0 ? sum.erase(i) : std::next(i);
            budget_check_count(sum.size(), "a minor of the determinant");
            minor[columns] = std::move(sum);
        }
        for (std::size_t columns = 1; columns < minor.size(); ++columns)
            if (static_cast<std::size_t>(__builtin_popcountll(columns)) == size - 1)
                sparse_polynomial().swap(minor[columns]);
    }
    return from_sparse(minor.back(), symbols);
}

} // namespace

std::vector<ex> leading_minors(const GiNaC::matrix& a)
{
    std::size_t n = a.rows();
    std::vector<std::vector<ex>> m(n, std::vector<ex>(n));
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j)
            m[i][j] = a(i, j).expand();
    std::vector<ex> minors;
    ex previous = 1;
    for (std::size_t k = 0; k < n; ++k) {
        minors.push_back(m[k][k]);
        if (k + 1 == n || vanishes(m[k][k]))
            break;
        for (std::size_t i = k + 1; i < n; ++i)
            for (std::size_t j = k + 1; j < n; ++j) {
                budget_check_terms(m[k][k] * m[i][j] - m[i][k] * m[k][j], "a minor of the determinant");
                ex numerator = (m[k][k] * m[i][j] - m[i][k] * m[k][j]).expand();
                budget_check_terms(numerator, "a minor of the determinant");
                ex quotient;
                bool exact = false;
                try {
                    exact = GiNaC::divide(numerator, previous, quotient);
                } catch (const std::invalid_argument&) {
                    exact = false; // rational entries (a parameter in a denominator): divide by normal()
                }
                m[i][j] = exact ? quotient : (numerator / previous).normal();
            }
        previous = m[k][k];
    }
    return minors;
}

ex fraction_free_determinant(const GiNaC::matrix& a)
{
    if (a.rows() == 0)
        return 1;
    std::vector<ex> minors = leading_minors(a);
    if (minors.size() == a.rows())
        return minors.back();
    budget_check();
    if (a.rows() > 8)
        throw computation_error("the determinant has a zero leading minor and is too large to expand by minors");
    return a.determinant(GiNaC::determinant_algo::laplace).expand();
}

ex expansion_determinant(const GiNaC::matrix& a)
{
    const std::size_t n = a.rows();
    if (n == 0)
        return 1;
    if (n > 16)
        throw computation_error("the determinant is too large to expand by minors");
    std::vector<std::vector<ex>> entries(n, std::vector<ex>(n));
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j)
            entries[i][j] = a(i, j).expand();
    if (std::optional<ex> quick = sparse_expansion_determinant(entries))
        return *quick;
    // minor[S]: the determinant of rows n − |S| … n − 1 and the columns in the bit set S,
    // expanded along its first row; built up from the last row.
    std::vector<ex> minor(std::size_t(1) << n);
    minor[0] = 1;
    for (std::size_t size = 1; size <= n; ++size) {
        const std::size_t row = n - size;
        for (std::size_t columns = 1; columns < minor.size(); ++columns) {
            if (static_cast<std::size_t>(__builtin_popcountll(columns)) != size)
                continue;
            ex sum = 0;
            int sign = 1;
            for (std::size_t j = 0; j < n; ++j) {
                if (!(columns >> j & 1))
                    continue;
                const ex& rest = minor[columns & ~(std::size_t(1) << j)];
                if (!entries[row][j].is_zero() && !rest.is_zero())
                    sum += sign * entries[row][j] * rest;
                sign = -sign;
            }
            // each product is at most (terms of an entry) × (terms of a checked minor):
            // the size budget is on what the minor is, not on what cancels in it
            budget_check();
            minor[columns] = sum.expand();
            budget_check_terms(minor[columns], "a minor of the determinant");
        }
        // the minors of the row below are no longer needed
        for (std::size_t columns = 1; columns < minor.size(); ++columns)
            if (static_cast<std::size_t>(__builtin_popcountll(columns)) == size - 1)
                minor[columns] = ex();
    }
    return minor.back();
}

std::vector<std::vector<ex>> null_space(GiNaC::matrix a)
{
    std::size_t rows = a.rows(), columns = a.cols();
    std::vector<std::size_t> pivot_columns;
    std::size_t row = 0;
    for (std::size_t column = 0; column < columns && row < rows; ++column) {
        std::size_t pivot = rows;
        for (std::size_t i = row; i < rows; ++i)
            if (!vanishes(a(i, column))) {
                pivot = i;
                break;
            }
        if (pivot == rows)
            continue;
        for (std::size_t j = 0; j < columns; ++j)
            std::swap(a(row, j), a(pivot, j));
        for (std::size_t i = 0; i < rows; ++i) {
            if (i == row || vanishes(a(i, column)))
                continue;
            ex ratio = a(i, column) / a(row, column);
            for (std::size_t j = 0; j < columns; ++j)
                a(i, j) = (a(i, j) - ratio * a(row, j)).normal();
        }
        pivot_columns.push_back(column);
        ++row;
    }
    std::vector<std::vector<ex>> basis;
    for (std::size_t free = 0; free < columns; ++free) {
        if (std::find(pivot_columns.begin(), pivot_columns.end(), free) != pivot_columns.end())
            continue;
        std::vector<ex> v(columns, 0);
        v[free] = 1;
        for (std::size_t r = 0; r < pivot_columns.size(); ++r)
            v[pivot_columns[r]] = (-a(r, free) / a(r, pivot_columns[r])).normal();
        basis.push_back(v);
    }
    return basis;
}

} // namespace lagrange
