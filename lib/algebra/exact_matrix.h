// SPDX-License-Identifier: GPL-2.0-or-later
/** @file exact_matrix.h
 *  Exact linear algebra on symbolic matrices: leading principal minors and the
 *  determinant by fraction-free (Bareiss) elimination, the determinant of a
 *  polynomial matrix by minor expansion, and a null space basis. */
#pragma once

#include <ginac/ginac.h>

#include <vector>

namespace lagrange {

/// The determinant and the leading principal minors of a square matrix by
/// fraction-free (Bareiss) elimination without pivoting: minors[k] is the
/// determinant of the leading (k+1)×(k+1) block. Stops at the first zero minor.
/// Checks the size budget on each entry of the elimination.
std::vector<GiNaC::ex> leading_minors(const GiNaC::matrix& a);

/// det(a) of a matrix whose entries are polynomials: by leading_minors, or by
/// expansion in minors when a leading minor is zero (computation_error above 8 rows).
GiNaC::ex fraction_free_determinant(const GiNaC::matrix& a);

/// det(a) of a matrix whose entries are polynomials, by Laplace expansion along the rows
/// with every minor of the lower rows kept (2ⁿ of them, each found once): only products
/// and sums, no polynomial division, so on the sparse pencils V − ω²T of chains it is far
/// quicker than elimination, whose exact divisions of large polynomials dominate.
/// Checks the size budget on each minor; computation_error above 16 rows.
GiNaC::ex expansion_determinant(const GiNaC::matrix& a);

/// A basis of the null space of a by elimination (zero tests by vanishes).
std::vector<std::vector<GiNaC::ex>> null_space(GiNaC::matrix a);

} // namespace lagrange
