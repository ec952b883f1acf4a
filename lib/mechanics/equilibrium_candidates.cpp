// SPDX-License-Identifier: GPL-2.0-or-later
/** @file equilibrium_candidates.cpp
 *  Points where a system of equations in the coordinates holds, found in closed form
 *  (see equilibrium_candidates.h). */
#include "mechanics/equilibrium_candidates.h"

#include "algebra/budget.h"
#include "algebra/canonical_order.h"
#include "algebra/expression.h"
#include "algebra/factor.h"
#include "algebra/sign.h"
#include "algebra/trig_canonical.h"

#include <algorithm>
#include <functional>

namespace lagrange {

using GiNaC::ex;
using GiNaC::ex_to;
using GiNaC::exvector;
using GiNaC::is_a;

namespace {

/// The distinct irreducible factors of `polynomial` (powers taken to their base), in canonical
/// order: a GiNaC product keeps its factors in hash order, which would order the roots
/// differently from process to process.
exvector factor_bases(const ex& polynomial)
{
    const ex factored = factor_if_quick(polynomial);
    exvector factors = is_a<GiNaC::mul>(factored) ? exvector(factored.begin(), factored.end()) : exvector{factored};
    for (ex& factor : factors)
        if (is_a<GiNaC::power>(factor))
            factor = factor.op(0);
    std::sort(factors.begin(), factors.end(), canonical_less);
    return factors;
}

} // namespace

std::vector<ex> solve_one(const ex& gradient, const GiNaC::symbol& q)
{
    std::vector<ex> roots;
    ex g = gradient.expand();
    if (g.is_zero())
        return {ex(0)};
    if (!g.info(GiNaC::info_flags::polynomial)) {
        // a rational function: its zeros are among those of its numerator (checked by the caller)
        ex numerator = g.normal().numer().expand();
        if (numerator.info(GiNaC::info_flags::polynomial) || inside_function(numerator, q))
            g = numerator;
    }
    bool trigonometric = false;
    for (GiNaC::const_preorder_iterator i = g.preorder_begin(); i != g.preorder_end(); ++i)
        if (is_a<GiNaC::function>(*i) && i->has(q))
            trigonometric = true;
    auto add_root = [&](const ex& value) {
        for (const ex& known : roots)
            if (vanishes(known - value))
                return;
        roots.push_back(value);
    };
    if (!trigonometric) {
        if (!g.info(GiNaC::info_flags::polynomial))
            return {};
        for (const ex& factor : factor_bases(g)) {
            if (factor.degree(q) == 1) {
                add_root(tidy(-factor.coeff(q, 0) / factor.coeff(q, 1)));
            } else if (factor.degree(q) == 2) {
                // a quadratic factor: its two roots, when they are known to be real
                const ex a2 = factor.coeff(q, 2), a1 = factor.coeff(q, 1), a0 = factor.coeff(q, 0);
                const ex discriminant = (a1 * a1 - 4 * a2 * a0).expand();
                const std::optional<int> sign = sign_of(discriminant);
                if (!sign || *sign < 0)
                    continue;
                for (int branch : {-1, 1})
                    add_root(tidy((-a1 + branch * GiNaC::sqrt(discriminant)) / (2 * a2)));
            }
        }
        return roots;
    }
    // Write the gradient as a polynomial in s = sin q, c = cos q, then as A(c) + s B(c).
    GiNaC::realsymbol s("s"), c("c");
    const std::optional<ex> polynomial = trigonometric_polynomial(g, q, s, c);
    if (!polynomial)
        return {};
    const ex p = *polynomial;
    ex a = 0, b = 0;
    for (int k = 0; k <= p.degree(s); ++k) {
        ex part = p.coeff(s, k) * GiNaC::pow(1 - c * c, k / 2);
        (k % 2 == 0 ? a : b) += part;
    }
    a = a.expand();
    b = b.expand();
    auto roots_in_cos = [&](const ex& polynomial) {
        for (const ex& factor : factor_bases(polynomial)) {
            if (factor.degree(c) != 1)
                continue;
            ex value = tidy(-factor.coeff(c, 0) / factor.coeff(c, 1));
            if (vanishes(value - 1))
                add_root(0);
            else if (vanishes(value + 1))
                add_root(GiNaC::Pi);
            else if (is_a<GiNaC::numeric>(value) && GiNaC::abs(ex_to<GiNaC::numeric>(value)) > 1)
                continue;
            else
                add_root(GiNaC::acos(value));
        }
    };
    if (a.is_zero()) {
        add_root(0);
        add_root(GiNaC::Pi);
        if (!b.is_zero())
            roots_in_cos(b);
    } else if (b.is_zero()) {
        roots_in_cos(a);
    } else {
        for (const ex& candidate : {ex(0), ex(GiNaC::Pi)})
            if (vanishes(gradient.subs(q == candidate)))
                add_root(candidate);
    }
    return roots;
}

angle_split split_angles(const model& scene, const std::vector<ex>& equations)
{
    angle_split split;
    for (std::size_t i = 0; i < scene.coordinates.size(); ++i) {
        bool angle = false;
        for (const ex& e : equations)
            angle = angle || inside_function(e, scene.coordinates[i].position);
        (angle ? split.angles : split.others).push_back(i);
    }
    return split;
}

/// The point with the angle coordinates at `fixed` (0 or π) and the others solved
/// from the linear system that remains (free directions set to 0), if `solves` accepts it.
std::optional<std::vector<ex>> point_with_angles(const model& scene, const std::vector<ex>& gradient,
                                                 const GiNaC::exmap& fixed, const std::vector<std::size_t>& others,
                                                 const point_check& solves)
{
    std::size_t n = scene.coordinates.size();
    GiNaC::lst equations, unknowns;
    for (std::size_t i : others)
        unknowns.append(scene.coordinates[i].position);
    bool linear = true;
    for (const ex& g : gradient) {
        ex reduced = g.subs(fixed).expand();
        if (reduced.is_zero())
            continue;
        if (!reduced.info(GiNaC::info_flags::polynomial))
            reduced = reduced.normal().numer().expand(); // zeros of a rational function: of its numerator
        // degree() throws on a non-polynomial in the unknowns (a root of ρ² + z² left in the numerator)
        linear = linear && reduced.is_polynomial(unknowns);
        for (const ex& u : unknowns)
            linear = linear && !inside_function(reduced, u) && reduced.degree(u) <= 1;
        equations.append(reduced == 0);
    }
    std::vector<ex> point(n, 0);
    for (const auto& [coordinate, value] : fixed)
        for (std::size_t i = 0; i < n; ++i)
            if (ex(scene.coordinates[i].position).is_equal(coordinate))
                point[i] = value;
    if (equations.nops() > 0 && unknowns.nops() > 0) {
        if (!linear)
            return std::nullopt;
        ex solution;
        try {
            solution = GiNaC::lsolve(equations, unknowns);
        } catch (const budget_exceeded&) {
            throw; // out of budget: the stage stops, no fallback
        } catch (const std::exception&) {
            return std::nullopt;
        }
        if (solution.nops() == 0)
            return std::nullopt;
        GiNaC::exmap free_to_zero;
        for (const ex& u : unknowns)
            free_to_zero[u] = 0;
        for (const ex& equation : solution)
            for (std::size_t i : others)
                if (equation.lhs().is_equal(scene.coordinates[i].position))
                    point[i] = tidy(equation.rhs().subs(free_to_zero));
    }
    if (!solves(point))
        return std::nullopt;
    return point;
}

namespace {

/// The points with the angle coordinates at `fixed` where ∂V/∂q = 0 is a polynomial system
/// in two other coordinates x, y (Hénon–Heiles' x + 2xy = 0, y + x² − y² = 0): the roots y
/// of the resultant in x of two equations, then x from the first equation that y leaves
/// (x = 0 when none does). Each point found is checked by `solves`.
std::vector<std::vector<ex>> polynomial_points(const model& scene, const std::vector<ex>& gradient,
                                               const GiNaC::exmap& fixed, const std::vector<std::size_t>& others,
                                               const point_check& solves)
{
    if (others.size() != 2)
        return {};
    const GiNaC::symbol& x = scene.coordinates[others[0]].position;
    const GiNaC::symbol& y = scene.coordinates[others[1]].position;
    std::vector<ex> equations;
    for (const ex& g : gradient) {
        ex reduced = g.subs(fixed).expand();
        if (!reduced.info(GiNaC::info_flags::polynomial))
            reduced = reduced.normal().numer().expand();
        if (reduced.is_zero())
            continue;
        if (!reduced.info(GiNaC::info_flags::polynomial) || inside_function(reduced, x) || inside_function(reduced, y))
            return {};
        equations.push_back(reduced);
    }
    if (equations.size() < 2)
        return {};
    ex eliminated;
    try {
        eliminated = GiNaC::resultant(equations[0], equations[1], x).expand();
    } catch (const budget_exceeded&) {
        throw;
    } catch (const std::exception&) {
        return {};
    }
    if (eliminated.is_zero() || eliminated.has(x))
        return {};
    std::vector<ex> base(scene.coordinates.size(), 0);
    for (const auto& [coordinate, value] : fixed)
        for (std::size_t i = 0; i < base.size(); ++i)
            if (ex(scene.coordinates[i].position).is_equal(coordinate))
                base[i] = value;
    std::vector<std::vector<ex>> points;
    for (const ex& y0 : solve_one(eliminated, y)) {
        std::vector<ex> xs{0};
        for (const ex& e : equations) {
            const ex in_x = e.subs(y == y0).expand();
            if (!vanishes(in_x)) {
                xs = solve_one(in_x, x);
                break;
            }
        }
        for (const ex& x0 : xs) {
            std::vector<ex> point = base;
            point[others[0]] = x0;
            point[others[1]] = y0;
            if (solves(point))
                points.push_back(point);
        }
    }
    return points;
}

} // namespace

std::vector<std::vector<ex>> points_at_angle_choices(const model& scene, const std::vector<ex>& equations,
                                                     const angle_split& split, const point_check& solves)
{
    std::vector<std::vector<ex>> points;
    for (unsigned long choice = 0; choice < (1UL << split.angles.size()); ++choice) {
        budget_check();
        GiNaC::exmap fixed;
        for (std::size_t a = 0; a < split.angles.size(); ++a)
            fixed[scene.coordinates[split.angles[a]].position] = (choice >> a & 1) ? ex(GiNaC::Pi) : ex(0);
        if (std::optional<std::vector<ex>> point = point_with_angles(scene, equations, fixed, split.others, solves))
            points.push_back(*point);
        else
            for (std::vector<ex>& point : polynomial_points(scene, equations, fixed, split.others, solves))
                points.push_back(std::move(point));
    }
    return points;
}

} // namespace lagrange
