// SPDX-License-Identifier: GPL-2.0-or-later
/** @file expressions.h
 *  Comparing and evaluating expressions in tests: by meaning, never by printed form. */
#pragma once

#include <ginac/ginac.h>

#include <vector>

namespace lagrange_test {

/// True if a − b is zero: its expansion, or failing that its normal form, vanishes.
bool same(const GiNaC::ex& a, const GiNaC::ex& b);

/// The real value of `e` at a numeric `point` (REQUIREs a real number).
double value_at(const GiNaC::ex& e, const GiNaC::exmap& point);

/// CHECKs each entry of `got` to be the same as `expected`'s (REQUIREs the shape).
void check_matrix(const GiNaC::matrix& got, const std::vector<std::vector<GiNaC::ex>>& expected);

} // namespace lagrange_test
