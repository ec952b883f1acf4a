// SPDX-License-Identifier: GPL-2.0-or-later
/** @file constrained_linearization.cpp
 *  The reduction of T and V to the tangent space of holonomic constraints. */
#include "mechanics/constrained_linearization.h"

#include "algebra/calculus.h"
#include "mechanics/constraints.h"

#include <Eigen/Dense>

#include <cmath>
#include <random>

namespace lagrange {

namespace {

bool vanishes(const GiNaC::ex& e) { return e.expand().normal().is_zero(); }

/// Parameters at random positive values.
GiNaC::exmap random_parameters(const model& scene, std::mt19937& random)
{
    std::uniform_real_distribution<double> positive(0.5, 2.0);
    GiNaC::exmap at;
    for (const parameter& p : scene.parameters)
        at[p.symbol] = positive(random);
    return at;
}

Eigen::MatrixXd numeric(const GiNaC::matrix& m, const GiNaC::exmap& at)
{
    Eigen::MatrixXd result(m.rows(), m.cols());
    for (unsigned i = 0; i < m.rows(); ++i)
        for (unsigned j = 0; j < m.cols(); ++j) {
            GiNaC::ex v = m(i, j).subs(at).evalf();
            result(i, j) = GiNaC::is_a<GiNaC::numeric>(v) && GiNaC::ex_to<GiNaC::numeric>(v).is_real()
                               ? GiNaC::ex_to<GiNaC::numeric>(v).to_double()
                               : std::nan("");
        }
    return result;
}

} // namespace

constrained_linearization linearize_with_constraints(const model& scene, const lagrangian_result& lagrangian,
                                                     const simplifier& simplify)
{
    if (!scene.equilibrium)
        throw computation_error("with constraints the equilibrium is not searched for: give it with an "
                                "`equilibrium` line that names every coordinate");
    for (const constraint& c : scene.constraints)
        if (c.constraint_kind != constraint::kind::holonomic)
            throw computation_error("small oscillations with a Pfaffian constraint (`" + c.name +
                                    "`) are not computed by this version");
    const std::vector<GiNaC::ex>& at = *scene.equilibrium;
    const std::size_t n = scene.coordinates.size(), m = scene.constraints.size();
    for (const constraint& c : scene.constraints) {
        if (c.function.has(scene.time))
            throw computation_error("constraint `" + c.name + "` depends on t: there is no static equilibrium");
        if (!vanishes(evaluate_at(c.function, scene, at)))
            throw computation_error("the equilibrium given is not on constraint `" + c.name + "`");
    }
    // T and the Hessian of V in all coordinates at the point.
    linearization_result full = linearize(scene, lagrangian, at, simplify);
    if (full.has_gyroscopic())
        throw computation_error("small oscillations with constraints and gyroscopic terms are not computed");
    GiNaC::ex potential = simplify.canonical(lagrangian.potential);
    GiNaC::matrix a(static_cast<unsigned>(m), static_cast<unsigned>(n));
    std::vector<GiNaC::ex> gradient;
    for (std::size_t j = 0; j < n; ++j)
        gradient.push_back(evaluate_at(differentiate(potential, scene.coordinates[j].position), scene, at).normal());
    for (std::size_t k = 0; k < m; ++k)
        for (std::size_t j = 0; j < n; ++j)
            a(static_cast<unsigned>(k), static_cast<unsigned>(j)) =
                evaluate_at(scene.constraints[k].coefficients[j], scene, at).normal();

    // Dependent coordinates: m columns of A, chosen from the last coordinate back, that are
    // independent at random parameter values; the others are the independent coordinates.
    std::mt19937 random(20261124);
    const GiNaC::exmap sample = random_parameters(scene, random);
    const Eigen::MatrixXd a_value = numeric(a, sample);
    std::vector<std::size_t> dependent;
    Eigen::MatrixXd chosen(static_cast<Eigen::Index>(m), 0);
    for (std::size_t j = n; j-- > 0 && dependent.size() < m;) {
        Eigen::MatrixXd trial(static_cast<Eigen::Index>(m), chosen.cols() + 1);
        trial << chosen, a_value.col(static_cast<Eigen::Index>(j));
        Eigen::FullPivLU<Eigen::MatrixXd> lu(trial);
        lu.setThreshold(1e-10);
        if (lu.rank() == trial.cols()) {
            chosen = trial;
            dependent.push_back(j);
        }
    }
    if (dependent.size() < m)
        throw computation_error("the constraints are dependent at the equilibrium (A has rank below " +
                                std::to_string(m) + " there)");
    std::sort(dependent.begin(), dependent.end());
    constrained_linearization result;
    for (std::size_t j = 0; j < n; ++j)
        if (!std::binary_search(dependent.begin(), dependent.end(), j))
            result.independent.push_back(j);
    const std::size_t r = result.independent.size();

    // A_D δq_D + A_I δq_I = 0, so δq_D = −A_D⁻¹ A_I δq_I; and A_Dᵀ λ* = ∇_D V.
    GiNaC::matrix a_dependent(static_cast<unsigned>(m), static_cast<unsigned>(m));
    GiNaC::matrix a_independent(static_cast<unsigned>(m), static_cast<unsigned>(r));
    GiNaC::matrix gradient_dependent(static_cast<unsigned>(m), 1);
    for (unsigned k = 0; k < m; ++k) {
        for (unsigned d = 0; d < m; ++d)
            a_dependent(k, d) = a(k, static_cast<unsigned>(dependent[d]));
        for (unsigned i = 0; i < r; ++i)
            a_independent(k, i) = a(k, static_cast<unsigned>(result.independent[i]));
        gradient_dependent(k, 0) = gradient[dependent[k]];
    }
    GiNaC::matrix inverse = a_dependent.inverse();
    GiNaC::matrix lambda = inverse.transpose().mul(gradient_dependent);
    for (unsigned k = 0; k < m; ++k)
        result.multipliers.push_back(lambda(k, 0).normal());
    for (std::size_t i : result.independent) {
        GiNaC::ex reaction = 0;
        for (unsigned k = 0; k < m; ++k)
            reaction += a(k, static_cast<unsigned>(i)) * lambda(k, 0);
        if (!vanishes(gradient[i] - reaction))
            throw computation_error("the point given is not an equilibrium on the constraints: ∂V/∂" +
                                    scene.coordinates[i].name + " is not balanced by the constraint forces there");
    }
    GiNaC::matrix basis(static_cast<unsigned>(n), static_cast<unsigned>(r));
    GiNaC::matrix solved = inverse.mul(a_independent);
    for (unsigned i = 0; i < r; ++i) {
        basis(static_cast<unsigned>(result.independent[i]), i) = 1;
        for (unsigned d = 0; d < m; ++d)
            basis(static_cast<unsigned>(dependent[d]), i) = -solved(d, i);
    }
    GiNaC::matrix curvature = full.potential;
    for (std::size_t k = 0; k < m; ++k) {
        GiNaC::matrix h = potential_hessian(scene, simplify.canonical(scene.constraints[k].function), at);
        curvature = curvature.sub(h.mul_scalar(result.multipliers[k]));
    }
    GiNaC::matrix kinetic = basis.transpose().mul(full.kinetic).mul(basis);
    GiNaC::matrix potential_reduced = basis.transpose().mul(curvature).mul(basis);
    for (unsigned i = 0; i < r; ++i)
        for (unsigned j = 0; j < r; ++j) {
            kinetic(i, j) = simplify_ratio(kinetic(i, j), simplify);
            potential_reduced(i, j) = simplify_ratio(potential_reduced(i, j), simplify);
        }
    std::vector<GiNaC::ex> reduced_at;
    for (std::size_t i : result.independent)
        reduced_at.push_back(at[i]);
    result.linear = linearization_result{reduced_at, kinetic, potential_reduced,
                                         GiNaC::matrix(static_cast<unsigned>(r), static_cast<unsigned>(r))};

    // Stability from the reduced V at a few parameter points: the same verdict at each, else unknown.
    std::optional<stability> verdict;
    for (int trial = 0; trial < 3; ++trial) {
        const GiNaC::exmap values = trial == 0 ? sample : random_parameters(scene, random);
        Eigen::MatrixXd v = numeric(potential_reduced, values);
        stability here = stability::unknown;
        if (v.allFinite()) {
            Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(v);
            const double scale = 1 + eigen.eigenvalues().cwiseAbs().maxCoeff();
            const double lowest = eigen.eigenvalues().minCoeff();
            here = lowest > 1e-12 * scale ? stability::stable : lowest < -1e-12 * scale ? stability::unstable
                                                                                       : stability::unknown;
        }
        verdict = !verdict || *verdict == here ? here : stability::unknown;
    }
    result.equilibria.points.push_back({at, verdict.value_or(stability::unknown)});
    result.equilibria.given = true;
    return result;
}

} // namespace lagrange
