// SPDX-License-Identifier: GPL-2.0-or-later
/** @file equilibrium_family.cpp
 *  Sets of equilibria f = 0 of V = c·f² + V₀, and equilibria on the coordinate axes
 *  (see equilibrium_family.h). */
#include "mechanics/equilibrium_family.h"

#include "mechanics/equilibrium.h"
#include "mechanics/equilibrium_candidates.h"

#include "algebra/budget.h"
#include "algebra/calculus.h"
#include "algebra/sign.h"
#include "algebra/sorted_terms.h"

namespace lagrange {

using GiNaC::ex;
using GiNaC::is_a;

namespace {

/// V = c·f² + V₀ with c and V₀ free of the coordinates.
struct square_form {
    ex c, f, v0;
};

bool has_coordinates(const model& scene, const ex& e)
{
    for (const coordinate& q : scene.coordinates)
        if (e.has(q.position))
            return true;
    return false;
}

std::optional<square_form> as_square(const model& scene, const ex& potential)
{
    ex v0 = 0, term = potential;
    if (is_a<GiNaC::add>(potential)) {
        int dependent = 0;
        for (const ex& op : potential) {
            if (has_coordinates(scene, op)) {
                term = op;
                ++dependent;
            } else {
                v0 += op;
            }
        }
        if (dependent != 1)
            return std::nullopt;
    }
    const GiNaC::exvector factors = is_a<GiNaC::mul>(term) ? GiNaC::exvector(term.begin(), term.end())
                                                           : GiNaC::exvector{term};
    ex c = 1, f;
    for (const ex& factor : factors) {
        if (!has_coordinates(scene, factor))
            c *= factor;
        else if (f.is_zero() && is_a<GiNaC::power>(factor) && factor.op(1).is_equal(2))
            f = factor.op(0);
        else
            return std::nullopt;
    }
    if (f.is_zero())
        return std::nullopt;
    return square_form{c, f, v0};
}

/// e at `point`, tidied; nothing where it is not defined there (a pole).
std::optional<ex> value_at(const model& scene, const ex& e, const std::vector<ex>& point)
{
    try {
        return tidy(evaluate_at(e, scene, point));
    } catch (const budget_exceeded&) {
        throw;
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

bool zero_at(const model& scene, const ex& e, const std::vector<ex>& point)
{
    const std::optional<ex> value = value_at(scene, e, point);
    return value && vanishes(*value);
}

} // namespace

std::optional<equilibrium_family> family_through(const model& scene, const ex& potential, const std::vector<ex>& point)
{
    if (scene.coordinates.size() < 2)
        return std::nullopt;
    const std::optional<square_form> square = as_square(scene, potential);
    if (!square)
        return std::nullopt;
    const std::optional<int> sign = sign_of(square->c);
    if (!sign || *sign == 0 || !zero_at(scene, square->f, point))
        return std::nullopt;
    bool regular = false; // ∇f ≠ 0: f = 0 is a hypersurface through the point
    for (const coordinate& q : scene.coordinates) {
        const std::optional<ex> slope = value_at(scene, differentiate(square->f, q.position), point);
        if (!slope)
            return std::nullopt;
        const std::optional<int> slope_sign = sign_of(*slope);
        regular = regular || (slope_sign && *slope_sign != 0);
    }
    if (!regular)
        return std::nullopt;
    equilibrium_family family;
    // f's numerator, of the sign whose sorted text comes first (normal() picks a sign by
    // GiNaC's hash order, which changes from process to process)
    const ex numerator = tidy(square->f.normal().numer()), negated = tidy(-numerator);
    family.relation = message_text(negated) < message_text(numerator) ? negated : numerator;
    family.dimension = scene.coordinates.size() - 1;
    family.across = *sign;
    family.potential = square->v0;
    return family;
}

bool on_family(const model& scene, const equilibrium_family& family, const std::vector<ex>& point)
{
    return zero_at(scene, family.relation, point);
}

std::vector<std::vector<ex>> axis_equilibria(const model& scene, const std::vector<ex>& gradient)
{
    const std::size_t n = scene.coordinates.size();
    std::vector<std::vector<ex>> points;
    for (std::size_t i = 0; i < n; ++i) {
        budget_check();
        const GiNaC::symbol& q = scene.coordinates[i].position;
        GiNaC::exmap others;
        for (std::size_t j = 0; j < n; ++j)
            if (j != i)
                others[scene.coordinates[j].position] = 0;
        ex on_axis;
        try {
            on_axis = gradient[i].subs(others);
        } catch (const std::exception&) {
            continue; // a pole on this axis (ρ = 0 of C/ρ)
        }
        const ex on_branch =
            on_axis.subs(GiNaC::pow(GiNaC::pow(q, 2), GiNaC::wild(0)) == GiNaC::pow(q, 2 * GiNaC::wild(0)));
        const bool branch = !on_branch.is_equal(on_axis);
        for (const ex& root : solve_one(on_branch, q)) {
            if (branch && sign_of(root) != std::optional<int>(1))
                continue;
            std::vector<ex> point(n, 0);
            point[i] = root;
            bool solves = true;
            for (const ex& g : gradient)
                solves = solves && zero_at(scene, g, point);
            bool known = false;
            for (const std::vector<ex>& p : points) {
                bool same = true;
                for (std::size_t k = 0; k < n; ++k)
                    same = same && vanishes(p[k] - point[k]);
                known = known || same;
            }
            if (solves && !known)
                points.push_back(point);
        }
    }
    return points;
}

} // namespace lagrange
