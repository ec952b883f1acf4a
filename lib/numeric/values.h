/** @file values.h
 *  Small helpers shared by the numeric stages: an expression at the parameter values
 *  as a double, with a message naming what it was when it is not a finite real number,
 *  and numbers for messages. */
#pragma once

#include <ginac/ginac.h>

#include <string>

namespace lagrange {

/// `e` evaluated (evalf) to a double; throws computation_error "`what` is not a real
/// number" (a symbol left, or a complex value) or "… is not a finite number".
double real_value(const GiNaC::ex& e, const std::string& what);

/// x with `digits` significant digits (printf's %g), for messages.
std::string message_number(double x, int digits = 6);

} // namespace lagrange
