// SPDX-License-Identifier: GPL-2.0-or-later
/** @file assumptions.cpp
 *  The check of a parameter value against the derivation's assumptions (assumptions.h). */
#include "core/assumptions.h"

#include "core/number_text.h"

#include <cmath>

namespace lagrange {

namespace {

std::string assumed(const std::string& name)
{
    return "parameter `" + name + "` is assumed real and positive in the derivation (so that, e.g., sqrt(" + name +
           "^2) simplifies to " + name + ")";
}

} // namespace

std::optional<std::string> parameter_value_contradiction(const std::string& name, double value)
{
    if (std::isnan(value))
        return assumed(name) + ", so its value cannot be NaN";
    if (!std::isfinite(value))
        return assumed(name) + ", so its value must be finite, not " + std::string(value > 0 ? "" : "-") + "inf";
    if (value <= 0)
        return assumed(name) + ", so the value " + shortest(value) +
               " contradicts it: give a positive value, or write the sign into the scene's expressions (-" + name +
               " for a negative one)";
    return std::nullopt;
}

std::optional<std::string> parameter_value_contradiction(const std::string& name, const GiNaC::ex& value)
{
    GiNaC::ex number;
    try {
        number = value.evalf();
    } catch (const std::exception&) {
        return assumed(name) + ", so its value must be a real number, and this one cannot be evaluated";
    }
    if (!GiNaC::is_a<GiNaC::numeric>(number))
        return assumed(name) + ", so its value must be a number";
    const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(number);
    if (!n.is_real())
        return assumed(name) + ", so its value must be a real number, not a complex one";
    if (!n.is_positive())
        return assumed(name) + ", so the value " + (n.is_zero() ? std::string("0") : shortest(n.to_double())) +
               " contradicts it: give a positive value, or write the sign into the scene's expressions (-" + name +
               " for a negative one)";
    return parameter_value_contradiction(name, n.to_double());
}

} // namespace lagrange
