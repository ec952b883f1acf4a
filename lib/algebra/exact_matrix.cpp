/** @file exact_matrix.cpp
 *  Fraction-free determinants, leading minors and null spaces (see exact_matrix.h). */
#include "algebra/exact_matrix.h"

#include "algebra/budget.h"
#include "algebra/sign.h"
#include "core/errors.h"

#include <algorithm>
#include <stdexcept>

namespace lagrange {

namespace {

using GiNaC::ex;

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
