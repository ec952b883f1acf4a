// SPDX-License-Identifier: GPL-2.0-or-later
/** @file print_pieces.h
 *  The pieces the expression printers (print.cpp) build output from: a printed
 *  subexpression in plain form (its sort key) and in the requested syntax, each with how
 *  tightly it binds, and numbers as such pieces. Internal to output/. */
#pragma once

#include "output/print.h"

#include <ginac/ginac.h>

#include <string>

namespace lagrange::print_pieces {

/// How tightly a printed piece binds; a piece is parenthesized where its
/// surroundings need a tighter one.
enum level : int {
    relation_level = 0,
    sum_level = 1,     ///< a sum or a leading minus sign
    product_level = 2, ///< a product, a quotient, a rational number
    power_level = 3,
    atom_level = 4,
};

/// One printed subexpression: its plain form (also the sort key) and its form in
/// the requested syntax, each with its binding level.
struct piece {
    std::string plain;
    std::string out;
    int plain_level = atom_level;
    int out_level = atom_level;
    /// LaTeX only: the same as `out` with the function argument in parentheses
    /// (`\sin\left(\theta\right)` for `\sin\theta`); empty when not applicable.
    std::string closed;
};

/// `s` in parentheses of the syntax (`\left( … \right)` in LaTeX).
std::string parenthesize(const std::string& s, syntax syn);

/// The piece, parenthesized in each syntax where it binds less tightly than `needed`.
piece wrap(const piece& p, int needed, syntax syn);

/// −p, binding as a sum.
piece negated(const piece& p);

/// The integer as decimal digits.
std::string integer_string(const GiNaC::numeric& n);

/// A real or complex number in each syntax: integers as digits, rationals as fractions,
/// floats to round trip (exponents as 10^k in text and LaTeX).
piece number_piece(const GiNaC::numeric& n, syntax syn);

} // namespace lagrange::print_pieces
