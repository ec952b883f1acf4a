// SPDX-License-Identifier: GPL-2.0-or-later
/** @file angle_sums.h
 *  Sines and cosines of sums written through those of their terms, the shape of a
 *  recursive multibody evaluation: a chain's mass matrix and forcing hold the sine and
 *  cosine of every angle difference q_i − q_j (n² of them), where the recursion needs only
 *  the direction (sin q_k, cos q_k) of each link (n), and products of those. */
#pragma once

#include <ginac/ginac.h>

namespace lagrange {

/// e with sin(a + b) = sin a cos b + cos a sin b and cos(a + b) = cos a cos b − sin a sin b
/// applied to every sine and cosine of a sum, down to single terms (cos(q1 − q2) becomes
/// cos q1 cos q2 + sin q1 sin q2). The terms are split in the order of their canonical keys
/// (algebra/canonical_order.h), so the result is the same in every process.
GiNaC::ex expand_angle_sums(const GiNaC::ex& e);

} // namespace lagrange
