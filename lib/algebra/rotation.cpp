// SPDX-License-Identifier: GPL-2.0-or-later
/** @file rotation.cpp
 *  Rotations about coordinate axes and their products. */
#include "algebra/rotation.h"

#include <stdexcept>
#include <string>

namespace lagrange {

GiNaC::matrix axis_rotation(char axis, const GiNaC::ex& angle)
{
    const GiNaC::ex c = GiNaC::cos(angle), s = GiNaC::sin(angle);
    switch (axis) {
    case 'x':
        return GiNaC::matrix{{1, 0, 0}, {0, c, -s}, {0, s, c}};
    case 'y':
        return GiNaC::matrix{{c, 0, s}, {0, 1, 0}, {-s, 0, c}};
    case 'z':
        return GiNaC::matrix{{c, -s, 0}, {s, c, 0}, {0, 0, 1}};
    default:
        throw std::invalid_argument(std::string("a rotation axis is x, y or z, not ") + axis);
    }
}

GiNaC::matrix rotation_sequence(const std::vector<char>& axes, const std::vector<GiNaC::ex>& angles)
{
    if (axes.size() != angles.size())
        throw std::invalid_argument("a rotation sequence has one axis per angle");
    GiNaC::matrix product{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (std::size_t k = 0; k < axes.size(); ++k)
        product = product.mul(axis_rotation(axes[k], angles[k]));
    return product;
}

} // namespace lagrange
