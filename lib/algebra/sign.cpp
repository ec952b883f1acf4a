/** @file sign.cpp
 *  The sign and the value of an expression at a parameter point (see sign.h). */
#include "algebra/sign.h"

#include "algebra/factor.h"

#include <cmath>

namespace lagrange {

std::optional<double> number_at(const GiNaC::ex& e, const GiNaC::exmap& values)
{
    GiNaC::ex n = e.subs(values).evalf();
    if (!GiNaC::is_a<GiNaC::numeric>(n) || !GiNaC::ex_to<GiNaC::numeric>(n).is_real())
        return std::nullopt;
    return GiNaC::ex_to<GiNaC::numeric>(n).to_double();
}

std::optional<int> sign_at(const GiNaC::ex& e, const GiNaC::exmap& values)
{
    GiNaC::ex n = factor_with_pi(e);
    if (n.is_zero())
        return 0;
    if (n.info(GiNaC::info_flags::positive))
        return 1;
    if ((-n).info(GiNaC::info_flags::positive))
        return -1;
    if (std::optional<double> x = number_at(n, values)) {
        if (std::abs(*x) < 1e-14 * (1 + std::abs(*x)))
            return 0;
        return *x > 0 ? 1 : -1;
    }
    return std::nullopt;
}

} // namespace lagrange
