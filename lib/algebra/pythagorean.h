// SPDX-License-Identifier: GPL-2.0-or-later
/** @file pythagorean.h
 *  sin² a + cos² a = 1 for an angle a made of parameters only (th0), which the canonical
 *  form keeps as an offset (trig_canonical.h): it never rewrites sines of parameters into
 *  harmonics, so that sin th0, cos th0 and tan th0 cancel as atoms. Only the identity is
 *  used, which holds for every value of a: nothing that holds on a branch (acos(cos a) = a
 *  only for a in [0, π]) is ever rewritten. */
#pragma once

#include <ginac/ginac.h>

namespace lagrange {

/// `e` with each sum (at any depth) written with fewer terms where sin² a + cos² a = 1
/// allows, for every argument a whose symbols are all positive parameters: the terms that
/// share all other factors are taken as a polynomial in s = sin a, c = cos a and reduced to
/// degree ≤ 1 in s, or in c, whichever has fewer terms, and kept as they were unless that
/// is fewer than before (2·k − 2·k·cos² th0 → 2·k·sin² th0, m·sin² th0 + m·cos² th0 → m).
/// Equal to `e` for every value of the parameters; zero when such a sum vanishes identically.
GiNaC::ex pythagorean(const GiNaC::ex& e);

} // namespace lagrange
