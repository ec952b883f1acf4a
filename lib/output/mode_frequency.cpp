// SPDX-License-Identifier: GPL-2.0-or-later
/** @file mode_frequency.cpp
 *  A numeric mode's frequency, or its growth rate, as printed (mode_frequency.h). */
#include "output/mode_frequency.h"

#include "core/number_text.h"

namespace lagrange {

namespace {

/// ω² < 0 (or a real s with G): the frequency is imaginary, i·|ω|.
bool imaginary(const numeric_modes& n, std::size_t k) { return n.omega[k] < 0; }

} // namespace

double mode_growth_rate(const numeric_modes& n, std::size_t k)
{
    if (k < n.growth_rate.size())
        return n.growth_rate[k];
    return k < n.omega.size() && n.omega[k] < 0 ? -n.omega[k] : 0.0;
}

bool mode_grows(const numeric_modes& n, std::size_t k) { return mode_growth_rate(n, k) > 0; }

std::string mode_frequency_text(const numeric_modes& n, std::size_t k,
                                const std::function<std::string(double)>& number)
{
    auto show = [&](double x) { return number ? number(x) : round_trip(x); };
    const double w = n.omega[k];
    std::string text = "ω = " + (imaginary(n, k) ? show(-w) + "i" : show(w));
    if (mode_grows(n, k))
        text += std::string(", growth rate ") + (imaginary(n, k) ? "s" : "Re s") + " = +" + show(mode_growth_rate(n, k)) +
                " (unstable)";
    return text;
}

std::string omega_value_latex(const numeric_modes& n, std::size_t k, const std::function<std::string(double)>& number)
{
    const double w = n.omega[k];
    return imaginary(n, k) ? number(-w) + "\\,i" : number(w);
}

std::string growth_sentence_latex(const numeric_modes& n, std::size_t k,
                                  const std::function<std::string(double)>& number)
{
    if (!mode_grows(n, k))
        return "";
    return "Mode " + std::to_string(k + 1) + " is unstable: it grows as $e^{\\gamma t}$ with growth rate $\\gamma = " +
           std::string(imaginary(n, k) ? "" : "\\operatorname{Re} s = ") + number(mode_growth_rate(n, k)) + "$. ";
}

} // namespace lagrange
