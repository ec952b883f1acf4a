// SPDX-License-Identifier: GPL-2.0-or-later
/** @file integer_polynomial.h
 *  Exact multivariate polynomial arithmetic with integer coefficients by FLINT
 *  (fmpz_mpoly): products, the greatest common divisor, factoring. GiNaC's own gcd and
 *  factor() work on expression trees and are far slower on the polynomials of
 *  thousands of terms in a dozen symbols that characteristic polynomials of chains
 *  are; FLINT's sparse algorithms are made for them.
 *
 *  Expressions go in and come out as GiNaC expressions: expanded polynomials in plain
 *  symbols with rational coefficients. Each function returns nothing when its input is
 *  not one. Symbols are ordered by name, so every normalization (the sign of a factor,
 *  the order of factors) is the same from run to run. */
#pragma once

#include <ginac/ginac.h>

#include <memory>
#include <optional>
#include <vector>

namespace lagrange {

/// The greatest common divisor of the nonzero polynomials among `polynomials` (0 if all
/// are zero): its rational number is the gcd of their rational contents, and its
/// polynomial part has a positive leading coefficient in the lexicographic order of
/// the symbols' names.
std::optional<GiNaC::ex> polynomial_gcd(const std::vector<GiNaC::ex>& polynomials);

/// p factored over the integers: a rational number times powers of irreducible
/// polynomials, each expanded, with integer coefficients of gcd 1 and a positive leading
/// coefficient in the lexicographic order of the symbols' names.
std::optional<GiNaC::ex> polynomial_factor(const GiNaC::ex& p);

/// Whether a and b have no common factor of positive degree (exactly, by their gcd).
std::optional<bool> polynomials_coprime(const GiNaC::ex& a, const GiNaC::ex& b);

/// The determinant of a square matrix of polynomials, by expansion in minors (each of
/// the 2ⁿ minors of the lower rows found once): products and sums only, no division, so
/// on the sparse pencils V − ω²T of chains it beats elimination. Checks the time budget
/// between products and the size budget on each minor.
std::optional<GiNaC::ex> polynomial_determinant(const std::vector<std::vector<GiNaC::ex>>& entries);

/// det(entries) = content · Σₖ parts[k] · variableᵏ, where the parts (lowest degree
/// first) are integer polynomials whose gcd is 1 and `content` is a rational number times
/// a polynomial with a positive leading coefficient: the determinant made primitive in
/// `variable`. The parts stay in FLINT, so that factoring them needs no conversion back.
class polynomial_by_powers {
public:
    struct state;
    explicit polynomial_by_powers(std::unique_ptr<state> s);
    ~polynomial_by_powers();
    polynomial_by_powers(polynomial_by_powers&&) noexcept;
    polynomial_by_powers& operator=(polynomial_by_powers&&) noexcept;

    const GiNaC::ex& content() const;
    /// The parts, expanded (none if det = 0).
    const std::vector<GiNaC::ex>& parts() const;
    /// Part k factored as factor_if_quick would (algebra/factor.h): GiNaC's factor()
    /// for few terms or few symbols, FLINT's otherwise. Checks the time budget.
    GiNaC::ex factored_part(std::size_t k) const;

private:
    std::unique_ptr<state> state_;
};

/// Nothing if an entry is not a polynomial with rational coefficients.
std::optional<polynomial_by_powers> determinant_by_powers(const std::vector<std::vector<GiNaC::ex>>& entries,
                                                          const GiNaC::symbol& variable);

} // namespace lagrange
