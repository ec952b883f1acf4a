// SPDX-License-Identifier: GPL-2.0-or-later
/** @file symmetries.cpp
 *  Conserved quantities, the Hamiltonian and Routh's reduction. */
#include "mechanics/symmetries.h"

#include "algebra/budget.h"
#include "algebra/calculus.h"
#include "algebra/expression.h"
#include "algebra/sorted_terms.h"
#include "algebra/sign.h"
#include "mechanics/equilibrium.h"

#include <algorithm>
#include <string>

namespace lagrange {

namespace {

using GiNaC::ex;

/// Every velocity set to 0.
GiNaC::exmap velocities_at_rest(const model& scene)
{
    GiNaC::exmap rest;
    for (const coordinate& c : scene.coordinates)
        rest[c.velocity] = 0;
    return rest;
}

/// The cofactor matrix of a symmetric matrix (its adjugate), entries as they come.
GiNaC::matrix adjugate(const GiNaC::matrix& m)
{
    const unsigned n = m.rows();
    GiNaC::matrix adj(n, n);
    if (n == 1) {
        adj(0, 0) = 1;
        return adj;
    }
    for (unsigned i = 0; i < n; ++i)
        for (unsigned j = 0; j < n; ++j)
            adj(j, i) = (((i + j) % 2) ? -1 : 1) * GiNaC::ex_to<GiNaC::matrix>(GiNaC::reduced_matrix(m, i, j)).determinant();
    return adj;
}

/// xᵀ A y for vectors of expressions.
ex bilinear(const std::vector<ex>& x, const GiNaC::matrix& a, const std::vector<ex>& y)
{
    ex sum = 0;
    for (unsigned i = 0; i < x.size(); ++i)
        for (unsigned j = 0; j < y.size(); ++j)
            sum += x[i] * a(i, j) * y[j];
    return sum;
}

/// True if e holds any of the scene's coordinates.
bool has_position(const model& scene, const ex& e)
{
    for (const coordinate& c : scene.coordinates)
        if (e.has(c.position))
            return true;
    return false;
}

/// num/den for printing: the simplified quotient when den holds no coordinate, else the
/// compact numerator over the compact denominator, so that the trigonometric canonical
/// form (a polynomial form) is never asked to expand a quotient.
ex quotient_display(const model& scene, const simplifier& simplify, const ex& num, const ex& den)
{
    const ex d = simplify.canonical(den);
    if (!has_position(scene, d))
        return simplify(num / den);
    return simplify(num) / simplify.compact(d);
}

/// P with every factor that holds none of `unknowns` divided out: the coefficients of P's
/// monomials in the unknowns, sines and cosines taken as symbols, share their gcd.
ex without_free_factors(const ex& p, const std::vector<ex>& unknowns)
{
    GiNaC::exmap to_symbols, back;
    for (GiNaC::const_preorder_iterator i = p.preorder_begin(); i != p.preorder_end(); ++i)
        if (GiNaC::is_a<GiNaC::function>(*i) && !to_symbols.count(*i)) {
            GiNaC::symbol s;
            to_symbols[*i] = s;
            back[s] = *i;
        }
    ex polynomial = p.subs(to_symbols).expand();
    ex common = 0;
    std::vector<ex> coefficients{polynomial};
    for (const ex& u : unknowns) {
        std::vector<ex> next;
        for (const ex& c : coefficients)
            for (int k = c.ldegree(u); k <= c.degree(u); ++k)
                next.push_back(c.coeff(u, k));
        coefficients = next;
    }
    for (const ex& c : coefficients)
        if (!c.is_zero())
            common = common.is_zero() ? c : GiNaC::gcd(common, c);
    if (common.is_zero())
        return p;
    return (polynomial / common).normal().subs(back);
}

} // namespace

ex tidy_trigonometric(const ex& e)
{
    ex reduced = e;
    try {
        reduced = reduce_trigonometric(e);
    } catch (const budget_exceeded&) {
        throw;
    } catch (const std::exception&) {
        reduced = e;
    }
    return tidy(reduced);
}

std::vector<std::size_t> cyclic_coordinates(const model& scene, const lagrangian_result& lagrangian)
{
    std::vector<std::size_t> cyclic;
    for (std::size_t i = 0; i < scene.coordinates.size(); ++i) {
        const coordinate& c = scene.coordinates[i];
        if (!lagrangian.lagrangian_canonical.has(c.position) && lagrangian.lagrangian_canonical.has(c.velocity))
            cyclic.push_back(i);
    }
    return cyclic;
}

conserved_result conserved_quantities(const model& scene, const lagrangian_result& lagrangian,
                                      const equations_of_motion& equations, const simplifier& simplify)
{
    if (scene.has_generalized_forces())
        throw computation_error("`conserved` is for a Lagrangian alone: with dissipation, dampers, applied forces "
                                "or inputs the energy and the cyclic momenta need not be conserved");
    conserved_result result;
    if (!lagrangian.lagrangian_canonical.has(scene.time))
        result.energy = simplify(equations.energy);
    result.cyclic = cyclic_coordinates(scene, lagrangian);
    for (std::size_t i : result.cyclic)
        result.momenta.push_back(simplify(equations.momenta[i]));
    return result;
}

GiNaC::realsymbol momentum_symbol(const coordinate& c) { return GiNaC::realsymbol("p_" + c.name); }

hamiltonian_result derive_hamiltonian(const model& scene, const lagrangian_result& lagrangian,
                                      const equations_of_motion& equations, const simplifier& simplify)
{
    if (!lagrangian.split)
        throw computation_error("the Lagrangian is not quadratic in the velocities, so its Legendre transform has "
                                "no closed form here");
    const std::size_t n = scene.coordinates.size();
    const GiNaC::matrix& mass = equations.mass;
    for (std::size_t i = 0; i < n; ++i) {
        bool empty = true;
        for (std::size_t j = 0; j < n; ++j)
            empty = empty && simplify.canonical(mass(i, j)).is_zero();
        if (empty)
            throw computation_error("the velocity Hessian ∂²L/∂q̇² is singular: coordinate `" +
                                    scene.coordinates[i].name +
                                    "` has no kinetic energy, so its momentum does not determine its velocity "
                                    "and there is no Hamiltonian");
    }
    budget_check();
    const ex determinant = mass.determinant();
    if (simplify.canonical(determinant).is_zero())
        throw computation_error("the velocity Hessian ∂²L/∂q̇² is singular (its determinant is 0), so the momenta "
                                "do not determine the velocities and there is no Hamiltonian");
    const GiNaC::matrix adj = adjugate(mass);
    const GiNaC::exmap rest = velocities_at_rest(scene);
    hamiltonian_result result;
    std::vector<ex> w; // p − b
    for (std::size_t i = 0; i < n; ++i) {
        result.momenta.push_back(momentum_symbol(scene.coordinates[i]));
        w.push_back(result.momenta[i] - equations.momenta[i].subs(rest));
    }
    const ex potential = -lagrangian.lagrangian_canonical.subs(rest);
    const ex kinetic_numerator = bilinear(w, adj, w);
    result.hamiltonian_raw = kinetic_numerator / (2 * determinant) + potential;
    for (std::size_t i = 0; i < n; ++i) {
        ex numerator = 0;
        for (std::size_t j = 0; j < n; ++j)
            numerator += adj(i, j) * w[j];
        result.velocities_raw.push_back(numerator / determinant);
        result.forces_raw.push_back(-differentiate(result.hamiltonian_raw, scene.coordinates[i].position));
    }
    // For printing: H = ½ Σ c_ij w_i w_j + U with c = M⁻¹, each entry the compact cofactor
    // over the compact determinant, common factors cancelled.
    const ex determinant_shown = simplify.compact(simplify.canonical(determinant));
    GiNaC::matrix inverse(n, n);
    std::vector<ex> w_shown;
    for (std::size_t i = 0; i < n; ++i) {
        w_shown.push_back(result.momenta[i] - simplify(equations.momenta[i].subs(rest)));
        for (std::size_t j = 0; j < n; ++j)
            inverse(i, j) = (simplify.compact(simplify.canonical(adj(i, j))) / determinant_shown).normal();
    }
    result.hamiltonian = lagrangian.potential;
    for (std::size_t i = 0; i < n; ++i) {
        result.hamiltonian += inverse(i, i) * w_shown[i] * w_shown[i] / 2;
        for (std::size_t j = i + 1; j < n; ++j)
            result.hamiltonian += inverse(i, j) * w_shown[i] * w_shown[j];
        ex velocity = 0;
        for (std::size_t j = 0; j < n; ++j)
            velocity += inverse(i, j) * w_shown[j];
        result.velocities.push_back(velocity);
    }
    for (std::size_t i = 0; i < n; ++i) {
        const ex force = (-differentiate(result.hamiltonian, scene.coordinates[i].position)).expand();
        ex shown = 0;
        for (const ex& term : GiNaC::is_a<GiNaC::add>(force) ? terms_of(force) : GiNaC::exvector{force})
            shown += term.normal();
        result.forces.push_back(shown);
    }
    return result;
}

reduced_result reduce_cyclic(const model& scene, const lagrangian_result& lagrangian,
                             const equations_of_motion& equations, const simplifier& simplify)
{
    if (!lagrangian.split)
        throw computation_error("the Lagrangian is not quadratic in the velocities, so Routh's reduction has no "
                                "closed form here");
    reduced_result result;
    result.cyclic = cyclic_coordinates(scene, lagrangian);
    if (result.cyclic.empty())
        throw computation_error("no coordinate is cyclic (each appears in L), so there is nothing to reduce");
    for (std::size_t i = 0; i < scene.coordinates.size(); ++i)
        if (std::find(result.cyclic.begin(), result.cyclic.end(), i) == result.cyclic.end())
            result.kept.push_back(i);
    const ex& l = lagrangian.lagrangian_canonical;
    const GiNaC::exmap rest = velocities_at_rest(scene);
    const auto& coords = scene.coordinates;
    const unsigned k = static_cast<unsigned>(result.cyclic.size()), m = static_cast<unsigned>(result.kept.size());
    // M's blocks of the cyclic (c) and kept (a) coordinates, in canonical form as L's
    auto second = [&](std::size_t i, std::size_t j) {
        return simplify.canonical(equations.mass(static_cast<unsigned>(i), static_cast<unsigned>(j)));
    };
    GiNaC::matrix mcc(k, k), mca(k, m), maa(m, m);
    for (unsigned i = 0; i < k; ++i) {
        for (unsigned j = 0; j < k; ++j)
            mcc(i, j) = second(result.cyclic[i], result.cyclic[j]);
        for (unsigned j = 0; j < m; ++j)
            mca(i, j) = second(result.cyclic[i], result.kept[j]);
    }
    for (unsigned i = 0; i < m; ++i)
        for (unsigned j = 0; j < m; ++j)
            maa(i, j) = second(result.kept[i], result.kept[j]);
    const ex determinant = mcc.determinant();
    if (simplify.canonical(determinant).is_zero())
        throw computation_error("the kinetic matrix of the cyclic coordinates is singular, so their momenta do not "
                                "determine their velocities");
    const GiNaC::matrix adj = adjugate(mcc);
    std::vector<ex> w, mca_rate, rates_a;
    for (unsigned i = 0; i < k; ++i) {
        const coordinate& c = coords[result.cyclic[i]];
        result.momenta.push_back(momentum_symbol(c));
        w.push_back(result.momenta[i] - differentiate(l, c.velocity).subs(rest));
        ex sum = 0;
        for (unsigned j = 0; j < m; ++j)
            sum += mca(i, j) * coords[result.kept[j]].velocity;
        mca_rate.push_back(sum);
    }
    ex quadratic_a = 0, linear_a = 0;
    for (unsigned i = 0; i < m; ++i) {
        const GiNaC::symbol& v = coords[result.kept[i]].velocity;
        linear_a += differentiate(l, v).subs(rest) * v;
        for (unsigned j = 0; j < m; ++j)
            quadratic_a += GiNaC::numeric(1, 2) * v * maa(i, j) * coords[result.kept[j]].velocity;
    }
    const ex potential = -l.subs(rest);
    result.quadratic_raw = quadratic_a - bilinear(mca_rate, adj, mca_rate) / (2 * determinant);
    result.linear_raw = linear_a + bilinear(mca_rate, adj, w) / determinant;
    result.potential_raw = potential + bilinear(w, adj, w) / (2 * determinant);
    // z = w − M_ca ȧ: R = ½ȧᵀM_aaȧ + b_a·ȧ − U − ½ zᵀ M_cc⁻¹ z.
    std::vector<ex> z;
    for (unsigned i = 0; i < k; ++i)
        z.push_back(w[i] - mca_rate[i]);
    const ex centrifugal = quotient_display(scene, simplify, bilinear(w, adj, w), 2 * determinant);
    result.effective_potential = lagrangian.potential + centrifugal;
    result.routhian = simplify(quadratic_a + linear_a) - lagrangian.potential -
                      quotient_display(scene, simplify, bilinear(z, adj, z), 2 * determinant);

    // The family of steady motions: ∂L/∂a = 0 at ȧ = 0, solved for one cyclic rate.
    std::vector<ex> rates;
    for (std::size_t c : result.cyclic)
        rates.push_back(coords[c].velocity);
    GiNaC::exmap kept_rest;
    for (std::size_t a : result.kept)
        kept_rest[coords[a].velocity] = 0;
    for (std::size_t a : result.kept) {
        budget_check();
        const ex condition = tidy_trigonometric(differentiate(l, coords[a].position).subs(kept_rest));
        if (condition.is_zero())
            continue;
        const ex p = without_free_factors(condition.numer(), rates);
        for (const ex& u : rates) {
            if (!p.is_polynomial(u))
                continue;
            const int degree = p.degree(u);
            const ex c0 = p.coeff(u, 0), c1 = p.coeff(u, 1), c2 = p.coeff(u, 2);
            if (degree == 1) {
                result.family.push_back({a, u, {tidy_trigonometric(-c0 / c1)}});
                break;
            }
            if (degree == 2 && c1.is_zero()) {
                result.family.push_back({a, GiNaC::pow(u, 2), {tidy_trigonometric(-c0 / c2)}});
                break;
            }
        }
    }
    // Circular orbits: a kept coordinate outside every sine and cosine, U_eff' = 0 linear in it.
    for (std::size_t a : result.kept) {
        const GiNaC::symbol& q = coords[a].position;
        if (result.kept.size() != 1 || inside_trigonometric(l, q))
            break;
        const ex numerator = differentiate(result.potential_raw, q).normal().numer().expand();
        if (!numerator.is_polynomial(q) || numerator.degree(q) != 1)
            continue;
        const ex value = tidy(-numerator.coeff(q, 0) / numerator.coeff(q, 1));
        if (!value.is_zero() && !value.has(q))
            result.circular_orbits.push_back({a, {value}});
    }
    return result;
}

} // namespace lagrange
