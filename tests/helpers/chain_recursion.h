// SPDX-License-Identifier: GPL-2.0-or-later
/** @file chain_recursion.h
 *  The planar chain of chain_scene.h (absolute angles q1 … qN, point masses on massless rods,
 *  gravity g along −y) evaluated by hand in O(N): the independent reference of the compiled
 *  equations in the tests, and the peer of bench/large_systems.cpp. Without Catch2. */
#pragma once

#include <cmath>
#include <vector>

namespace lagrange_test {

/// The chain's q̈ by the rod tensions: with e_k = (sin q_k, −cos q_k) the direction of rod k,
/// m_k a_k = −T_k e_k + T_{k+1} e_{k+1} + m_k g, and each rod keeps its length,
/// (a_k − a_{k−1})·e_k = −l_k q̇_k², a tridiagonal system in T (solved by Thomas' algorithm);
/// then l_k q̈_k = (a_k − a_{k−1})·e_k'. O(N): one sine and cosine per link.
struct tension_chain {
    int n;
    double gravity;
    std::vector<double> inverse_mass, length;
    mutable std::vector<double> sine, cosine, c, s, lower, diagonal, upper, rhs, tension;

    /// Link k (from 0) has mass masses[k] at the end of a massless rod of length lengths[k].
    tension_chain(const std::vector<double>& masses, const std::vector<double>& lengths, double g)
        : n(static_cast<int>(masses.size())), gravity(g), inverse_mass(masses.size()), length(lengths),
          sine(masses.size()), cosine(masses.size()), c(masses.size()), s(masses.size()), lower(masses.size()),
          diagonal(masses.size()), upper(masses.size()), rhs(masses.size()), tension(masses.size() + 1)
    {
        for (int k = 0; k < n; ++k)
            inverse_mass[k] = 1 / masses[k];
    }

    /// dxdt = (q̇, q̈) at x = (q, q̇); not inlined, as an integrator calls through a function.
    __attribute__((noinline)) void operator()(const double* x, double* dxdt) const
    {
        const double* q = x;
        const double* v = x + n;
        for (int k = 0; k < n; ++k) {
            sine[k] = std::sin(q[k]);
            cosine[k] = std::cos(q[k]);
        }
        // C_k = e_k·e_{k+1} = cos(q_k − q_{k+1}), S_k = e_{k+1}·e_k' = sin(q_{k+1} − q_k)
        for (int k = 0; k + 1 < n; ++k) {
            c[k] = cosine[k] * cosine[k + 1] + sine[k] * sine[k + 1];
            s[k] = sine[k + 1] * cosine[k] - cosine[k + 1] * sine[k];
        }
        for (int k = 0; k < n; ++k) {
            lower[k] = k > 0 ? inverse_mass[k - 1] * c[k - 1] : 0;
            diagonal[k] = -(inverse_mass[k] + (k > 0 ? inverse_mass[k - 1] : 0));
            upper[k] = k + 1 < n ? inverse_mass[k] * c[k] : 0;
            rhs[k] = -length[k] * v[k] * v[k] - (k == 0 ? gravity * cosine[0] : 0);
        }
        // Thomas' algorithm (the system is diagonally dominant).
        for (int k = 1; k < n; ++k) {
            double w = lower[k] / diagonal[k - 1];
            diagonal[k] -= w * upper[k - 1];
            rhs[k] -= w * rhs[k - 1];
        }
        tension[n] = 0;
        for (int k = n - 1; k >= 0; --k)
            tension[k] = (rhs[k] - upper[k] * tension[k + 1]) / diagonal[k];
        for (int k = 0; k < n; ++k) {
            double along = k + 1 < n ? inverse_mass[k] * tension[k + 1] * s[k] : 0;
            double before = k > 0 ? inverse_mass[k - 1] * tension[k - 1] * s[k - 1] : gravity * sine[0];
            dxdt[k] = v[k];
            dxdt[n + k] = (along - before) / length[k];
        }
    }
};

} // namespace lagrange_test
