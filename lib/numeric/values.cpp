/** @file values.cpp
 *  Expressions at the parameter values as doubles, and numbers for messages. */
#include "numeric/values.h"

#include "core/errors.h"

#include <cmath>
#include <cstdio>

namespace lagrange {

double real_value(const GiNaC::ex& e, const std::string& what)
{
    GiNaC::ex value = e.evalf();
    if (!GiNaC::is_a<GiNaC::numeric>(value) || !GiNaC::ex_to<GiNaC::numeric>(value).is_real())
        throw computation_error(what + " is not a real number");
    double d = GiNaC::ex_to<GiNaC::numeric>(value).to_double();
    if (!std::isfinite(d))
        throw computation_error(what + " is not a finite number");
    return d;
}

std::string message_number(double x, int digits)
{
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, x);
    return buffer;
}

} // namespace lagrange
