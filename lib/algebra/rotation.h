// SPDX-License-Identifier: GPL-2.0-or-later
/** @file rotation.h
 *  Rotation matrices about the coordinate axes, and sequences of them about a body's
 *  own axes (`rotations(z q1, x q2, …)`). */
#pragma once

#include <ginac/ginac.h>

#include <vector>

namespace lagrange {

/// The rotation by `angle` about the coordinate axis `axis` ('x', 'y' or 'z'): body
/// components to the components of the frame it turns in.
GiNaC::matrix axis_rotation(char axis, const GiNaC::ex& angle);

/// R = R_{a1}(q1) R_{a2}(q2) ⋯: successive rotations about the body's own axes, in turn.
/// The identity for an empty sequence.
GiNaC::matrix rotation_sequence(const std::vector<char>& axes, const std::vector<GiNaC::ex>& angles);

} // namespace lagrange
