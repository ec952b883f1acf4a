// SPDX-License-Identifier: GPL-2.0-or-later
/** @file print_pieces.cpp
 *  Printed pieces and numbers (see print_pieces.h). */
#include "output/print_pieces.h"

#include "core/number_text.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace lagrange::print_pieces {

using GiNaC::ex;
using GiNaC::numeric;

std::string parenthesize(const std::string& s, syntax syn)
{
    if (syn == syntax::latex)
        return "\\left(" + s + "\\right)";
    return "(" + s + ")";
}

piece wrap(const piece& p, int needed, syntax syn)
{
    piece w = p;
    if (p.plain_level < needed) {
        w.plain = "(" + p.plain + ")";
        w.plain_level = atom_level;
    }
    if (p.out_level < needed) {
        w.out = parenthesize(p.out, syn);
        w.out_level = atom_level;
        w.closed.clear();
    }
    return w;
}

piece negated(const piece& p)
{
    piece n;
    n.plain = "-" + p.plain;
    n.out = "-" + p.out;
    n.plain_level = sum_level;
    n.out_level = sum_level;
    return n;
}

namespace {

/// A nonnegative float in each syntax.
piece float_piece(const numeric& n, syntax syn)
{
    double value = n.to_double();
    std::string plain;
    if (std::isfinite(value)) {
        plain = float_decimal(value);
    } else { // beyond the range of a double: CLN's own digits, "1.0E400"
        std::ostringstream os;
        os << ex(n);
        plain = os.str();
        std::replace(plain.begin(), plain.end(), 'E', 'e');
    }
    piece p;
    p.plain = plain;
    p.out = plain;
    std::size_t e = plain.find('e');
    if (e != std::string::npos) {
        p.plain_level = product_level;
        p.out_level = product_level;
        if (syn == syntax::latex)
            p.out = latex_exponent(plain);
        else if (syn == syntax::text)
            p.out = text_exponent(plain);
    }
    return p;
}

} // namespace

std::string integer_string(const numeric& n)
{
    static const numeric small(1L << 30);
    if (n < small && -n < small)
        return std::to_string(n.to_long());
    std::ostringstream os;
    os << ex(n);
    return os.str();
}

piece number_piece(const numeric& n, syntax syn)
{
    if (!n.is_real()) {
        const numeric re = n.real();
        const numeric im = n.imag();
        piece unit;
        unit.plain = "I";
        unit.out = syn == syntax::plain ? "I" : "i";
        piece imaginary = unit;
        numeric magnitude = GiNaC::abs(im);
        if (magnitude != 1) {
            piece m = wrap(number_piece(magnitude, syn), product_level, syn);
            imaginary.plain = m.plain + "*I";
            imaginary.out = m.out + (syn == syntax::plain ? "*" : syn == syntax::text ? "·" : " ") + unit.out;
            imaginary.plain_level = product_level;
            imaginary.out_level = product_level;
        }
        if (re.is_zero())
            return im < 0 ? negated(imaginary) : imaginary;
        piece sum = number_piece(re, syn);
        const char* sign = im < 0 ? "-" : "+";
        sum.plain += sign + imaginary.plain;
        sum.out += (syn == syntax::plain ? std::string(sign) : " " + std::string(sign) + " ") + imaginary.out;
        sum.plain_level = sum_level;
        sum.out_level = sum_level;
        return sum;
    }
    if (n < 0)
        return negated(number_piece(-n, syn));
    piece p;
    if (n.is_integer()) {
        p.plain = integer_string(n);
        p.out = p.plain;
    } else if (n.is_rational()) {
        const std::string numer = integer_string(n.numer());
        const std::string denom = integer_string(n.denom());
        p.plain = numer + "/" + denom;
        p.out = syn == syntax::latex ? "\\frac{" + numer + "}{" + denom + "}" : p.plain;
        p.plain_level = product_level;
        p.out_level = product_level;
    } else {
        p = float_piece(n, syn);
    }
    return p;
}

} // namespace lagrange::print_pieces
