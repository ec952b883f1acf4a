// SPDX-License-Identifier: GPL-2.0-or-later
/** @file exact_matrix.cpp
 *  Fraction-free determinants, leading minors and null spaces (see exact_matrix.h). */
#include "algebra/exact_matrix.h"

#include "algebra/budget.h"
#include "algebra/integer_polynomial.h"
#include "algebra/sign.h"
#include "core/errors.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace lagrange {

using GiNaC::ex;

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
    if (std::optional<ex> quick = polynomial_determinant(entries))
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
