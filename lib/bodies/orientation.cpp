// SPDX-License-Identifier: GPL-2.0-or-later
/** @file orientation.cpp
 *  Rotation sequences about body axes, their angular velocity and rotational energy. */
#include "bodies/orientation.h"

#include "algebra/calculus.h"

#include <stdexcept>

namespace lagrange {

std::vector<GiNaC::ex> sequence_angular_velocity(const std::vector<char>& axes, const std::vector<GiNaC::ex>& angles,
                                                 const model& scene)
{
    if (axes.size() != angles.size())
        throw std::invalid_argument("a rotation sequence has one axis per angle");
    // Rotation k turns about its axis e_k, as seen in the frame after rotations 1 … k − 1;
    // in the body frame that axis is (R_{k+1} ⋯ R_n)ᵀ e_k. The rates add.
    std::vector<GiNaC::ex> omega{0, 0, 0};
    GiNaC::matrix tail{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (std::size_t k = axes.size(); k-- > 0;) {
        const unsigned a = static_cast<unsigned>(axes[k] - 'x');
        const GiNaC::ex rate = time_derivative(angles[k], scene);
        if (!rate.is_zero())
            for (unsigned i = 0; i < 3; ++i)
                omega[i] += tail(a, i) * rate;
        tail = axis_rotation(axes[k], angles[k]).mul(tail);
    }
    return omega;
}

GiNaC::ex rotational_energy_from_rate(const GiNaC::matrix& rotation, const GiNaC::matrix& tensor, const model& scene)
{
    const GiNaC::ex half_trace = (tensor(0, 0) + tensor(1, 1) + tensor(2, 2)) / 2;
    GiNaC::matrix second_moments(3, 3);
    for (unsigned i = 0; i < 3; ++i)
        for (unsigned j = 0; j < 3; ++j)
            second_moments(i, j) = (i == j ? half_trace : GiNaC::ex(0)) - tensor(i, j);
    GiNaC::matrix rate(3, 3);
    for (unsigned i = 0; i < 3; ++i)
        for (unsigned j = 0; j < 3; ++j)
            rate(i, j) = time_derivative(rotation(i, j), scene);
    const GiNaC::matrix product = rate.mul(second_moments).mul(rate.transpose());
    return (product(0, 0) + product(1, 1) + product(2, 2)) / 2;
}

} // namespace lagrange
