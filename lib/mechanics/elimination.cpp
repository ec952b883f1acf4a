// SPDX-License-Identifier: GPL-2.0-or-later
/** @file elimination.cpp
 *  Explicit elimination of holonomic constraints, and the reduced equations. */
#include "mechanics/elimination.h"

#include "algebra/budget.h"
#include "algebra/calculus.h"

namespace lagrange {

namespace {

using GiNaC::ex;

bool free_of_coordinates(const model& scene, const ex& e)
{
    for (const coordinate& c : scene.coordinates)
        if (e.has(c.position) || e.has(c.velocity) || e.has(c.acceleration))
            return false;
    return true;
}

} // namespace

elimination_result find_eliminations(const model& scene, const simplifier& simplify)
{
    elimination_result result;
    std::vector<bool> solved(scene.coordinates.size(), false);
    GiNaC::exmap solutions; // coordinate -> value, substituted into later constraints
    for (std::size_t k = 0; k < scene.constraints.size(); ++k) {
        const constraint& c = scene.constraints[k];
        if (c.constraint_kind != constraint::kind::holonomic)
            continue;
        const ex f = c.function.subs(solutions).expand();
        for (std::size_t j = scene.coordinates.size(); j-- > 0;) {
            const GiNaC::realsymbol& q = scene.coordinates[j].position;
            // not polynomial in q (q under a square root): not linear, and GiNaC's degree throws
            if (solved[j] || !f.is_polynomial(q) || f.degree(q) != 1)
                continue;
            const ex coefficient = f.coeff(q, 1);
            if (coefficient.is_zero() || !free_of_coordinates(scene, coefficient))
                continue;
            const ex value = simplify(-f.coeff(q, 0) / coefficient);
            GiNaC::exmap update = {{q, value}};
            for (auto& [symbol, earlier] : solutions)
                earlier = simplify(earlier.subs(update));
            solutions[q] = value;
            solved[j] = true;
            result.eliminated.push_back({j, k, value});
            break;
        }
    }
    for (eliminated_coordinate& e : result.eliminated)
        e.value = solutions[scene.coordinates[e.coordinate].position];
    result.complete = !scene.constraints.empty() && result.eliminated.size() == scene.constraints.size();
    for (std::size_t j = 0; j < scene.coordinates.size(); ++j)
        if (!solved[j])
            result.kept.push_back(j);
    return result;
}

std::vector<ex> reduced_equations(const model& scene, const equations_of_motion& equations,
                                  const elimination_result& elimination, const simplifier& simplify)
{
    if (!elimination.complete)
        throw computation_error("the constraints cannot all be eliminated explicitly: each must be linear in a "
                                "coordinate with a coefficient free of the coordinates");
    const std::size_t n = scene.coordinates.size();
    // q, q̇, q̈ of the eliminated coordinates along the manifold.
    GiNaC::exmap along;
    for (const eliminated_coordinate& e : elimination.eliminated) {
        const coordinate& c = scene.coordinates[e.coordinate];
        const ex velocity = time_derivative(e.value, scene);
        along[c.position] = e.value;
        along[c.velocity] = velocity;
        along[c.acceleration] = time_derivative(velocity, scene);
    }
    std::vector<ex> residual(n); // M q̈ − f − Q along the manifold
    for (std::size_t i = 0; i < n; ++i) {
        ex sum = -equations.forcing[i];
        for (std::size_t j = 0; j < n; ++j)
            sum += equations.mass(static_cast<unsigned>(i), static_cast<unsigned>(j)) *
                   scene.coordinates[j].acceleration;
        residual[i] = sum.subs(along);
        budget_check_terms(residual[i], "a reduced equation");
    }
    std::vector<ex> reduced;
    for (std::size_t kept : elimination.kept) {
        const GiNaC::realsymbol& q = scene.coordinates[kept].position;
        ex sum = residual[kept];
        for (const eliminated_coordinate& e : elimination.eliminated)
            sum += differentiate(e.value, q) * residual[e.coordinate];
        budget_check_terms(sum, "a reduced equation");
        reduced.push_back(simplify(sum));
    }
    return reduced;
}

} // namespace lagrange
