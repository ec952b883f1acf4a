// SPDX-License-Identifier: GPL-2.0-or-later
/** @file cln_eigen.cpp
 *  Cholesky, K = L⁻¹ V L⁻ᵀ and cyclic Jacobi rotations in cln::cl_F. */
#include "numeric/cln_eigen.h"

#include <algorithm>
#include <numeric>

namespace lagrange {

cln_eigen_result cln_generalized_eigen(const cln_matrix& T, const cln_matrix& V, const cln::float_format_t& format,
                                       bool modes)
{
    using cln::cl_F;
    const std::size_t n = T.size();
    cln_eigen_result result;
    const cl_F zero = cln::cl_float(0, format), one = cln::cl_float(1, format);
    const cl_F epsilon = cln::float_epsilon(format);

    // T = L Lᵀ; a pivot at the level of rounding means T is singular.
    cln_matrix L(n, std::vector<cl_F>(n, zero)), K, Y = L;
    for (std::size_t i = 0; i < n; ++i) {
        cl_F d = T[i][i];
        for (std::size_t k = 0; k < i; ++k)
            d = d - L[i][k] * L[i][k];
        if (!(d > cln::abs(T[i][i]) * epsilon * 64 * n)) {
            result.failed_pivot = i;
            return result;
        }
        L[i][i] = cln::sqrt(d);
        for (std::size_t j = i + 1; j < n; ++j) {
            cl_F s = T[j][i];
            for (std::size_t k = 0; k < i; ++k)
                s = s - L[j][k] * L[i][k];
            L[j][i] = s / L[i][i];
        }
    }
    // K = L⁻¹ V L⁻ᵀ by two forward substitutions (V symmetric).
    auto forward = [&](const cln_matrix& B) {
        cln_matrix X = B;
        for (std::size_t c = 0; c < n; ++c)
            for (std::size_t i = 0; i < n; ++i) {
                cl_F s = B[i][c];
                for (std::size_t k = 0; k < i; ++k)
                    s = s - L[i][k] * X[k][c];
                X[i][c] = s / L[i][i];
            }
        return X;
    };
    cln_matrix X = forward(V), Xt = X;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j)
            Xt[i][j] = X[j][i];
    K = forward(Xt);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j)
            Y[i][j] = i == j ? one : zero;

    // Cyclic Jacobi rotations until the off-diagonal part is below rounding.
    cl_F frobenius = zero;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j)
            frobenius = frobenius + K[i][j] * K[i][j];
    frobenius = cln::sqrt(frobenius);
    for (int sweep = 0; sweep < 100; ++sweep) {
        cl_F off = zero;
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j)
                off = off + K[i][j] * K[i][j];
        if (cln::sqrt(off) <= frobenius * epsilon)
            break;
        for (std::size_t a = 0; a < n; ++a)
            for (std::size_t b = a + 1; b < n; ++b) {
                if (cln::zerop(K[a][b]))
                    continue;
                cl_F tau = (K[b][b] - K[a][a]) / (2 * K[a][b]);
                cl_F t = one / (cln::abs(tau) + cln::sqrt(one + tau * tau));
                if (cln::minusp(tau))
                    t = -t;
                cl_F c = one / cln::sqrt(one + t * t), s = t * c;
                for (std::size_t k = 0; k < n; ++k) {
                    cl_F ka = K[k][a], kb = K[k][b];
                    K[k][a] = c * ka - s * kb;
                    K[k][b] = s * ka + c * kb;
                }
                for (std::size_t k = 0; k < n; ++k) {
                    cl_F ak = K[a][k], bk = K[b][k];
                    K[a][k] = c * ak - s * bk;
                    K[b][k] = s * ak + c * bk;
                    cl_F ya = Y[k][a], yb = Y[k][b];
                    Y[k][a] = c * ya - s * yb;
                    Y[k][b] = s * ya + c * yb;
                }
            }
    }
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return K[i][i] < K[j][j]; });

    // Error: rounding at this precision, amplified by the conditioning of T.
    cl_F smallest = L[0][0], largest = L[0][0];
    for (std::size_t i = 1; i < n; ++i) {
        smallest = cln::min(smallest, L[i][i]);
        largest = cln::max(largest, L[i][i]);
    }
    double conditioning = cln::double_approx(largest / smallest);
    double eps = cln::double_approx(epsilon);
    double dw_relative = 64.0 * n * eps * conditioning * conditioning;
    result.error = dw_relative * cln::double_approx(frobenius);
    if (modes)
        result.modes.resize(n * n);
    for (std::size_t k = 0; k < n; ++k) {
        result.eigenvalues.push_back(K[order[k]][order[k]]);
        if (modes) {
            // a = L⁻ᵀ y by back substitution.
            std::vector<cl_F> a(n, zero);
            for (std::size_t i = n; i-- > 0;) {
                cl_F s = Y[i][order[k]];
                for (std::size_t j = i + 1; j < n; ++j)
                    s = s - L[j][i] * a[j];
                a[i] = s / L[i][i];
            }
            for (std::size_t i = 0; i < n; ++i)
                result.modes[k * n + i] = cln::double_approx(a[i]);
        }
    }
    return result;
}

} // namespace lagrange
