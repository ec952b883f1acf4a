// SPDX-License-Identifier: GPL-2.0-or-later
/** @file linearization.cpp
 *  T, V and G at an equilibrium (with a check that T is positive definite there),
 *  and the primitive characteristic polynomial det(V − ω²T + iωG). */
#include "mechanics/linearization.h"
#include "core/names.h"

#include "algebra/budget.h"
#include "algebra/calculus.h"
#include "algebra/exact_matrix.h"
#include "algebra/factor.h"
#include "algebra/integer_polynomial.h"
#include "algebra/sorted_terms.h"
#include "algebra/sign.h"
#include "core/errors.h"
#include "mechanics/equilibrium.h"
#include "mechanics/forces.h"
#include "mechanics/gyroscopic.h"

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

namespace lagrange {

namespace {

using GiNaC::ex;

/// Whether e is a number times a product of powers of symbols.
bool is_monomial(const ex& e)
{
    if (GiNaC::is_a<GiNaC::numeric>(e) || GiNaC::is_a<GiNaC::symbol>(e))
        return true;
    if (GiNaC::is_a<GiNaC::power>(e))
        return GiNaC::is_a<GiNaC::symbol>(e.op(0)) && e.op(1).info(GiNaC::info_flags::posint);
    if (!GiNaC::is_a<GiNaC::mul>(e))
        return false;
    for (const ex& factor : e)
        if (!is_monomial(factor))
            return false;
    return true;
}

/// Coefficients without a common factor (lowest degree first) with the leading one made
/// positive; `denominator_sign` is the sign of the denominator that was cleared to get
/// them, `atoms` the functions of the parameters that to_rational made symbols (put back
/// at the end). Each coefficient is factored; with `factored`, the factoring has half the
/// stage's remaining time, and past it the coefficients are left unfactored and
/// *factored is set to false.
std::vector<ex> signed_and_factored(std::vector<ex> coefficients, std::optional<int> denominator_sign,
                                    const GiNaC::exmap& atoms, bool* factored,
                                    const std::function<ex(std::size_t)>& factor_of)
{
    int flip = (denominator_sign && *denominator_sign < 0) ? -1 : 1;
    std::optional<int> leading = sign_of(coefficients.back().subs(atoms));
    if (leading && *leading < 0)
        flip = -flip;
    if (!leading) {
        // sign undecidable (−l·cos(th0)): at least no leading coefficient whose every term is negative
        ex top = coefficients.back().normal().numer().expand();
        bool all_negative = true;
        for (const ex& term : GiNaC::is_a<GiNaC::add>(top) ? GiNaC::exvector(top.begin(), top.end())
                                                            : GiNaC::exvector{top}) {
            ex factor = GiNaC::is_a<GiNaC::mul>(term) ? term.op(term.nops() - 1) : term;
            all_negative = all_negative && GiNaC::is_a<GiNaC::numeric>(factor) &&
                           GiNaC::ex_to<GiNaC::numeric>(factor).is_negative();
        }
        if (all_negative)
            flip = -flip;
    }
    if (!factored) {
        for (std::size_t k = 0; k < coefficients.size(); ++k)
            coefficients[k] = (flip * factor_of(k)).subs(atoms);
        return coefficients;
    }
    std::vector<ex> factors;
    try {
        budget_share share(0.5);
        for (std::size_t k = 0; k < coefficients.size(); ++k)
            factors.push_back((flip * factor_of(k)).subs(atoms));
    } catch (const budget_exceeded&) {
        *factored = false;
        for (ex& c : coefficients)
            c = (flip * c).subs(atoms);
        return coefficients;
    }
    return factors;
}

/// The coefficients of a polynomial, lowest degree first, with every common factor
/// removed, then signed_and_factored.
std::vector<ex> primitive(std::vector<ex> coefficients, std::optional<int> denominator_sign,
                          const GiNaC::exmap& atoms, bool* factored)
{
    ex content = polynomial_content(coefficients);
    if (content.is_zero()) {
        for (ex& c : coefficients)
            c = c.subs(atoms);
        return coefficients;
    }
    for (ex& c : coefficients) {
        ex quotient;
        if (is_monomial(content))
            quotient = (c / content).expand(); // term by term
        else if (!GiNaC::divide(c, content, quotient))
            quotient = (c / content).normal();
        c = quotient;
    }
    const std::vector<ex> parts = coefficients;
    return signed_and_factored(std::move(coefficients), denominator_sign, atoms, factored,
                               [&](std::size_t k) { return factor_if_quick(parts[k]); });
}

/// The coefficients of an expanded polynomial in w, lowest degree first, in one pass
/// over its terms.
std::vector<ex> coefficients_in(const ex& p, const GiNaC::symbol& w)
{
    std::vector<GiNaC::exvector> terms(std::max(p.degree(w), 0) + 1);
    for (const ex& term : GiNaC::is_a<GiNaC::add>(p) ? GiNaC::exvector(p.begin(), p.end()) : GiNaC::exvector{p}) {
        const int k = term.degree(w);
        terms.at(k).push_back(k == 0 ? term : term.coeff(w, k));
    }
    std::vector<ex> coefficients;
    for (const GiNaC::exvector& t : terms)
        coefficients.push_back(ex(GiNaC::add(t)).expand());
    return coefficients;
}

/// det(pencil) as {numerator, denominator} with a numerator of integer coefficients: by
/// minor expansion when every entry is a polynomial, else by fraction-free elimination
/// brought over one denominator.
ex pencil_determinant(const GiNaC::matrix& pencil)
{
    bool polynomial = true;
    for (std::size_t i = 0; i < pencil.rows() && polynomial; ++i)
        for (std::size_t j = 0; j < pencil.cols() && polynomial; ++j)
            polynomial = pencil(i, j).info(GiNaC::info_flags::rational_polynomial);
    if (polynomial) {
        // integer coefficients with no common factor, as normal() would leave them
        ex det = expansion_determinant(pencil);
        return GiNaC::lst{det.is_zero() ? det : (det / det.integer_content()).expand(), 1};
    }
    return fraction_free_determinant(pencil).normal().numer_denom();
}

} // namespace

bool linearization_result::has_gyroscopic() const { return !is_zero_matrix(gyroscopic); }

bool linearization_result::has_force_stiffness() const { return !is_zero_matrix(force_stiffness); }

bool linearization_result::circulatory() const
{
    if (!has_force_stiffness())
        return false;
    for (unsigned i = 0; i < potential.rows(); ++i)
        for (unsigned j = i + 1; j < potential.cols(); ++j)
            if (!vanishes(potential(i, j) - potential(j, i)))
                return true;
    return false;
}

std::vector<ex> characteristic_coefficients(const GiNaC::matrix& kinetic, const GiNaC::matrix& potential,
                                            const GiNaC::symbol& w, bool* factored)
{
    std::size_t n = kinetic.rows();
    // gcd and divide take polynomials: functions of the parameters (cos(th0) at an
    // equilibrium given through a parameter) become symbols here and are put back below
    GiNaC::exmap atoms;
    GiNaC::matrix pencil(n, n);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j)
            pencil(i, j) = (potential(i, j) - w * kinetic(i, j)).to_rational(atoms);
    std::vector<std::vector<ex>> entries(n, std::vector<ex>(n));
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j)
            entries[i][j] = pencil(i, j);
    if (std::optional<polynomial_by_powers> split = determinant_by_powers(entries, w)) {
        if (split->content().is_zero())
            return std::vector<ex>{0};
        return signed_and_factored(split->parts(), std::nullopt, atoms, factored,
                                   [&](std::size_t k) { return split->factored_part(k); });
    }
    ex fraction = pencil_determinant(pencil);
    std::vector<ex> coefficients = coefficients_in(fraction.op(0).expand(), w);
    return primitive(coefficients, sign_of(fraction.op(1)), atoms, factored);
}

std::vector<ex> characteristic_coefficients(const GiNaC::matrix& kinetic, const GiNaC::matrix& potential,
                                            const GiNaC::matrix& gyroscopic, const GiNaC::symbol& w, bool* factored)
{
    std::size_t n = kinetic.rows();
    GiNaC::symbol x("x");
    GiNaC::exmap atoms;
    GiNaC::matrix pencil(n, n);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j)
            pencil(i, j) = (potential(i, j) + x * gyroscopic(i, j) + x * x * kinetic(i, j)).to_rational(atoms);
    ex fraction = pencil_determinant(pencil);
    ex numerator = fraction.op(0).expand();
    std::vector<ex> coefficients;
    for (int k = 0; k <= numerator.degree(x); ++k) {
        ex c = numerator.coeff(x, k).expand();
        if (k % 2 == 1) {
            if (!vanishes(c))
                throw std::logic_error("characteristic_coefficients: G is not antisymmetric");
            continue;
        }
        coefficients.push_back((k % 4 == 0 ? c : -c).expand());
    }
    return primitive(coefficients, sign_of(fraction.op(1)), atoms, factored);
}

linearization_result linearize(const model& scene, const lagrangian_result& lagrangian, const std::vector<ex>& at,
                               const simplifier& simplify)
{
    if (!lagrangian.split)
        throw computation_error("the Lagrangian is not quadratic in the velocities: no small-oscillation analysis");
    std::size_t n = scene.coordinates.size();
    if (at.size() != n)
        throw std::invalid_argument("linearize: the equilibrium has " + std::to_string(at.size()) +
                                    " values for " + std::to_string(n) + " coordinates");
    linearization_result result{at, GiNaC::matrix(n, n), GiNaC::matrix(n, n), GiNaC::matrix(n, n)};
    result.kinetic = kinetic_matrix(scene, simplify.canonical(lagrangian.kinetic), at);
    result.potential = potential_hessian(scene, simplify.canonical(lagrangian.potential), at);
    if (!lagrangian.gyroscopic.is_zero())
        result.gyroscopic = gyroscopic_matrix(scene, simplify.canonical(lagrangian.gyroscopic), at);
    result.force_stiffness = force_stiffness(scene, at, simplify);
    if (result.has_force_stiffness())
        for (unsigned i = 0; i < n; ++i)
            for (unsigned j = 0; j < n; ++j)
                result.potential(i, j) = tidy(result.potential(i, j) + result.force_stiffness(i, j));
    for (std::size_t i = 0; i < n; ++i)
        if (vanishes(result.kinetic(i, i)))
            throw computation_error("coordinate `" + scene.coordinates[i].name +
                                    "` has no kinetic energy at the equilibrium");
    std::vector<ex> minors = leading_minors(result.kinetic);
    for (std::size_t k = 0; k < minors.size(); ++k) {
        std::optional<int> sign = sign_of(minors[k]);
        if (sign && *sign <= 0)
            throw computation_error("the kinetic matrix is not positive definite at the equilibrium: the kinetic energy "
                                    "of " + scene.coordinates[0].name + " … " + scene.coordinates[k].name +
                                    " can vanish (leading minor " + message_text(minors[k].expand()) + ")");
    }
    return result;
}

characteristic_result characteristic_polynomial(const model& scene, const linearization_result& linear)
{
    if (linear.circulatory() && linear.has_gyroscopic())
        throw computation_error("with circulatory forces (a non-symmetric stiffness) and a gyroscopic matrix G, "
                                "det(V − ω²T + iωG) is not a real polynomial in ω: the eigenvalues s are given "
                                "by `numeric`");
    characteristic_result result{GiNaC::possymbol(unused_name(scene, "omega")), 0};
    GiNaC::possymbol w("W");
    std::vector<ex> coefficients =
        linear.has_gyroscopic()
            ? characteristic_coefficients(linear.kinetic, linear.potential, linear.gyroscopic, w, &result.factored)
            : characteristic_coefficients(linear.kinetic, linear.potential, w, &result.factored);
    ex polynomial = 0;
    for (std::size_t k = 0; k < coefficients.size(); ++k)
        polynomial += coefficients[k] * GiNaC::pow(result.omega, static_cast<int>(2 * k));
    result.polynomial = polynomial;
    return result;
}

} // namespace lagrange
