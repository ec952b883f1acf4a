// SPDX-License-Identifier: GPL-2.0-or-later
/** @file damping.cpp
 *  The damping matrix, det(K + s(C − G) + s²M) and its closed forms, proportional damping. */
#include "mechanics/damping.h"
#include "core/names.h"

#include "algebra/calculus.h"
#include "algebra/exact_matrix.h"
#include "algebra/factor.h"
#include "algebra/sign.h"
#include "core/errors.h"
#include "mechanics/equilibrium.h"
#include "mechanics/forces.h"

#include <algorithm>
#include <sstream>

namespace lagrange {

namespace {

using GiNaC::ex;

/// The coefficients of the primitive polynomial det(pencil) in `s`, lowest degree first:
/// every factor common to all coefficients removed and the leading one positive.
std::vector<ex> primitive_determinant(GiNaC::matrix pencil, const GiNaC::symbol& s)
{
    // gcd and divide take polynomials over the rationals: decimals (the bicycle's
    // benchmark matrices) and functions of the parameters become symbols here and are put
    // back at the end
    GiNaC::exmap atoms;
    for (unsigned i = 0; i < pencil.rows(); ++i)
        for (unsigned j = 0; j < pencil.cols(); ++j)
            pencil(i, j) = pencil(i, j).to_rational(atoms);
    ex det = fraction_free_determinant(pencil).normal();
    ex fraction = det.numer_denom();
    ex numerator = fraction.op(0).expand();
    std::optional<int> denominator_sign = sign_of(fraction.op(1).subs(atoms));
    std::vector<ex> coefficients;
    for (int k = 0; k <= numerator.degree(s); ++k)
        coefficients.push_back(numerator.coeff(s, k).expand());
    ex content = 0;
    for (const ex& c : coefficients)
        if (!c.is_zero())
            content = content.is_zero() ? c : GiNaC::gcd(content, c);
    if (content.is_zero()) {
        for (ex& c : coefficients)
            c = c.subs(atoms);
        return coefficients;
    }
    int flip = (denominator_sign.value_or(1) < 0) ? -1 : 1;
    std::optional<int> leading = sign_of((coefficients.back() / content).subs(atoms));
    if (leading && *leading < 0)
        flip = -flip;
    for (ex& c : coefficients) {
        ex quotient;
        if (!GiNaC::divide(c, content, quotient))
            quotient = (c / content).normal();
        c = factor_if_quick(flip * quotient).subs(atoms);
    }
    return coefficients;
}

std::string printed(const ex& e)
{
    std::ostringstream out;
    out << e;
    return out.str();
}

/// The roots of a factor of degree ≤ 2 in s, with γ, ω₀² and the regime of a quadratic.
damped_factor solve_factor(const ex& factor, const GiNaC::symbol& s)
{
    damped_factor f;
    f.factor = factor;
    ex expanded = factor.expand();
    if (expanded.degree(s) == 1) {
        f.roots.push_back(tidy(-expanded.coeff(s, 0) / expanded.coeff(s, 1)));
        return f;
    }
    ex a = expanded.coeff(s, 2), b = expanded.coeff(s, 1), c = expanded.coeff(s, 0);
    f.decay = tidy(b / (2 * a));
    f.natural_squared = tidy(c / a);
    f.discriminant = tidy((4 * a * c - b * b) / (4 * a * a));
    std::optional<int> sign = vanishes(f.discriminant) ? std::optional<int>(0) : sign_of(f.discriminant);
    if (sign && *sign == 0) {
        f.regime = "critical";
        f.roots = {-f.decay, -f.decay};
    } else if (sign && *sign > 0) {
        f.regime = "underdamped";
        ex imaginary = tidy(GiNaC::sqrt(f.discriminant));
        f.roots = {-f.decay - GiNaC::I * imaginary, -f.decay + GiNaC::I * imaginary};
    } else {
        // Overdamped, or a regime that depends on the parameters: the real form.
        f.regime = sign ? "overdamped" : "";
        ex real = tidy(GiNaC::sqrt(tidy(-f.discriminant)));
        f.roots = {-f.decay - real, -f.decay + real};
    }
    return f;
}

/// The factors of `polynomial` in s with their multiplicities, or nothing when one has a
/// degree above 2.
std::optional<std::vector<damped_factor>> closed_forms(const ex& polynomial, const GiNaC::symbol& s)
{
    GiNaC::exmap atoms; // decimals: factor() takes rational coefficients (primitive_determinant)
    ex factored = factor_if_quick(polynomial.to_rational(atoms)).subs(atoms);
    std::vector<std::pair<ex, int>> parts;
    auto add = [&](const ex& e) {
        if (GiNaC::is_a<GiNaC::power>(e) && e.op(1).info(GiNaC::info_flags::posint))
            parts.emplace_back(e.op(0), GiNaC::ex_to<GiNaC::numeric>(e.op(1)).to_int());
        else
            parts.emplace_back(e, 1);
    };
    if (GiNaC::is_a<GiNaC::mul>(factored))
        for (const ex& e : factored)
            add(e);
    else
        add(factored);
    // A quadratic whole stays whole: its regime (two real roots: overdamped) is the point.
    if (polynomial.expand().degree(s) == 2)
        parts = {{polynomial, 1}};
    std::vector<damped_factor> factors;
    for (const auto& [base, multiplicity] : parts) {
        if (!base.has(s))
            continue;
        const int degree = base.expand().degree(s);
        if (!base.is_polynomial(s) || degree > 2)
            return std::nullopt;
        // A double linear factor is a critically damped quadratic.
        int k = 0;
        if (degree == 1)
            for (; k + 1 < multiplicity; k += 2)
                factors.push_back(solve_factor(GiNaC::pow(base, 2), s));
        for (; k < multiplicity; ++k)
            factors.push_back(solve_factor(base, s));
    }
    // A fixed order: by degree, then by the printed factor.
    std::stable_sort(factors.begin(), factors.end(), [&](const damped_factor& x, const damped_factor& y) {
        int dx = x.factor.expand().degree(s), dy = y.factor.expand().degree(s);
        return dx != dy ? dx < dy : printed(x.factor) < printed(y.factor);
    });
    return factors;
}

} // namespace

GiNaC::matrix damping_matrix(const model& scene, const std::vector<ex>& at, const simplifier& simplify)
{
    const unsigned n = static_cast<unsigned>(scene.coordinates.size());
    GiNaC::matrix damping(n, n);
    if (!scene.has_generalized_forces())
        return damping;
    if (at.size() != n)
        throw computation_error("the damping matrix needs a value of every coordinate at the equilibrium");
    generalized_forces forces = derive_generalized_forces(scene, simplify);
    GiNaC::exmap inputs_off;
    for (const input_signal& u : scene.inputs)
        inputs_off[u.symbol] = 0;
    for (unsigned i = 0; i < n; ++i)
        for (unsigned j = 0; j < n; ++j) {
            ex rate = -differentiate(forces.total[i], scene.coordinates[j].velocity);
            ex entry = tidy(evaluate_at(rate.subs(inputs_off), scene, at));
            if (entry.has(scene.time))
                throw computation_error("the damping of `" + scene.coordinates[i].name +
                                        "` at the equilibrium changes with time: no damped small oscillations");
            damping(i, j) = entry;
        }
    return damping;
}

damping_result damped_oscillations(const model& scene, const linearization_result& linear,
                                   const simplifier& simplify, const modes_result* modes)
{
    const unsigned n = static_cast<unsigned>(scene.coordinates.size());
    damping_result result{damping_matrix(scene, linear.at, simplify), GiNaC::possymbol(unused_name(scene, "s")), 0};
    const GiNaC::symbol& s = result.s;
    GiNaC::matrix pencil(n, n);
    for (unsigned i = 0; i < n; ++i)
        for (unsigned j = 0; j < n; ++j)
            pencil(i, j) = linear.potential(i, j) + s * (result.damping(i, j) - linear.gyroscopic(i, j)) +
                           s * s * linear.kinetic(i, j);
    result.gyroscopic = linear.has_gyroscopic();
    std::vector<ex> coefficients = primitive_determinant(pencil, s);
    for (std::size_t k = 0; k < coefficients.size(); ++k)
        result.polynomial += coefficients[k] * GiNaC::pow(s, static_cast<int>(k));
    if (std::optional<std::vector<damped_factor>> factors = closed_forms(result.polynomial, s)) {
        result.closed_form = true;
        result.factors = std::move(*factors);
    }

    // Proportional (classical) damping: C M⁻¹ K symmetric, i.e. C M⁻¹ K = K M⁻¹ C. With G
    // the undamped modes are complex already: the notion does not apply.
    if (result.gyroscopic)
        return result;
    GiNaC::matrix inverse_mass = linear.kinetic.inverse();
    GiNaC::matrix left = result.damping.mul(inverse_mass).mul(linear.potential);
    GiNaC::matrix right = linear.potential.mul(inverse_mass).mul(result.damping);
    result.proportional = is_zero_matrix(left.sub(right));
    if (!result.proportional || !modes || !modes->closed_form || modes->modes.size() != n)
        return result;
    for (const ex& w2 : modes->frequencies)
        if (vanishes(w2))
            return result; // a zero mode has no damping ratio
    for (std::size_t k = 0; k < n; ++k) {
        GiNaC::matrix a(n, 1);
        for (unsigned i = 0; i < n; ++i)
            a(i, 0) = modes->modes[k][i];
        ex damped = a.transpose().mul(result.damping).mul(a)(0, 0);
        ex mass = a.transpose().mul(linear.kinetic).mul(a)(0, 0);
        result.modal_damping_ratios.push_back(tidy(damped / (2 * GiNaC::sqrt(modes->frequencies[k]) * mass)));
    }
    return result;
}

} // namespace lagrange
