// SPDX-License-Identifier: GPL-2.0-or-later
/** @file constraints.cpp
 *  The constraint matrix and its derivative, integrability by Frobenius at random
 *  points, and the multipliers and constraint forces solved symbolically. */
#include "mechanics/constraints.h"

#include "algebra/budget.h"
#include "algebra/calculus.h"

#include <Eigen/Dense>

#include <cmath>
#include <optional>
#include <random>

namespace lagrange {

namespace {

/// The value of `e` at `at` as a double, or NaN.
double number_at(const GiNaC::ex& e, const GiNaC::exmap& at)
{
    try {
        GiNaC::ex v = e.subs(at).evalf();
        if (GiNaC::is_a<GiNaC::numeric>(v) && GiNaC::ex_to<GiNaC::numeric>(v).is_real())
            return GiNaC::ex_to<GiNaC::numeric>(v).to_double();
    } catch (const std::exception&) {
    }
    return std::nan("");
}

/// Frobenius at random points for the one-forms ω_k = Σ a_kj dq_j + b_k dt of the constraints
/// `which`: their common kernel N is involutive when Nᵀ dω_k N = 0 for each k.
bool involutive(const model& scene, const std::vector<std::size_t>& which)
{
    const std::size_t n = scene.coordinates.size(), dim = n + 1;
    std::vector<GiNaC::ex> variables; // kept as ex: a copy into a plain symbol would be another type
    for (const coordinate& c : scene.coordinates)
        variables.push_back(c.position);
    variables.push_back(scene.time);
    auto d = [&](const GiNaC::ex& e, std::size_t i) { return differentiate(e, GiNaC::ex_to<GiNaC::symbol>(variables[i])); };
    // ω and dω: W_ij = ∂_i ω_j − ∂_j ω_i.
    std::vector<std::vector<GiNaC::ex>> forms;
    std::vector<std::vector<GiNaC::ex>> curls;
    for (std::size_t k : which) {
        const constraint& c = scene.constraints[k];
        std::vector<GiNaC::ex> omega = c.coefficients;
        omega.push_back(c.rest);
        std::vector<GiNaC::ex> w(dim * dim, 0);
        for (std::size_t i = 0; i < dim; ++i)
            for (std::size_t j = i + 1; j < dim; ++j) {
                w[i * dim + j] = d(omega[j], i) - d(omega[i], j);
                w[j * dim + i] = -w[i * dim + j];
            }
        forms.push_back(omega);
        curls.push_back(w);
    }
    std::mt19937 random(112026);
    std::uniform_real_distribution<double> centred(-1.0, 1.0), positive(0.5, 2.0);
    int tested = 0;
    for (int attempt = 0; attempt < 12 && tested < 3; ++attempt) {
        GiNaC::exmap at;
        for (const parameter& p : scene.parameters)
            at[p.symbol] = positive(random);
        for (const input_signal& u : scene.inputs)
            at[u.symbol] = centred(random);
        for (const GiNaC::ex& v : variables)
            at[v] = centred(random);
        Eigen::MatrixXd omega(static_cast<Eigen::Index>(which.size()), static_cast<Eigen::Index>(dim));
        std::vector<Eigen::MatrixXd> w(which.size(), Eigen::MatrixXd(dim, dim));
        bool finite = true;
        for (std::size_t k = 0; k < which.size(); ++k)
            for (std::size_t j = 0; j < dim; ++j) {
                omega(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(j)) = number_at(forms[k][j], at);
                for (std::size_t i = 0; i < dim; ++i)
                    w[k](static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
                        number_at(curls[k][i * dim + j], at);
            }
        for (std::size_t k = 0; k < which.size(); ++k)
            finite = finite && omega.allFinite() && w[k].allFinite();
        if (!finite)
            continue;
        ++tested;
        Eigen::JacobiSVD<Eigen::MatrixXd> svd(omega, Eigen::ComputeFullV);
        const auto rank = svd.rank();
        Eigen::MatrixXd kernel = svd.matrixV().rightCols(static_cast<Eigen::Index>(dim) - rank);
        for (const Eigen::MatrixXd& curl : w) {
            double scale = 1 + curl.lpNorm<Eigen::Infinity>() + omega.lpNorm<Eigen::Infinity>();
            if ((kernel.transpose() * curl * kernel).lpNorm<Eigen::Infinity>() > 1e-9 * scale)
                return false;
        }
    }
    return true;
}

/// The coordinates a position depends on, in coordinate order.
std::vector<std::size_t> coordinates_in(const model& scene, const std::vector<GiNaC::ex>& position)
{
    std::vector<std::size_t> used;
    for (std::size_t j = 0; j < scene.coordinates.size(); ++j)
        for (const GiNaC::ex& x : position)
            if (x.has(scene.coordinates[j].position)) {
                used.push_back(j);
                break;
            }
    return used;
}

/// A q̈ = −c solved for one pivot coordinate per constraint: q̈ = N u + p, with u the
/// accelerations of the other (free) coordinates in coordinate order.
struct embedded_constraints {
    std::vector<unsigned> pivots; ///< per row of the reduced A, its pivot coordinate
    GiNaC::matrix basis;          ///< N (n × (n − m)): the accelerations the constraints allow
    GiNaC::matrix particular;     ///< p (n × 1): the pivots' share of −c
};

/// Gauss–Jordan on [A | −c] with numbers as pivots, so that the mass matrix is reduced to
/// the n − m free coordinates before anything is solved: GiNaC's solve of the whole
/// (n + m)-square system [M −Aᵀ; A 0] spends its time in normal() of the fractions that the
/// λ rows bring in. Only numbers: a pivot such as cos θ leaves a removable 0/0 where it
/// vanishes (sin θ over sin θ, which the trigonometric canonical form does not cancel), and
/// a parameter (the Chaplygin sleigh's a) a power of itself over itself. Nothing if some row
/// has no number left to pivot on.
std::optional<embedded_constraints> embed_constraints(const constraint_equations& constraints)
{
    const unsigned m = constraints.matrix.rows(), n = constraints.matrix.cols();
    GiNaC::matrix rows(m, n + 1);
    for (unsigned k = 0; k < m; ++k) {
        for (unsigned j = 0; j < n; ++j)
            rows(k, j) = constraints.matrix(k, j);
        rows(k, n) = -constraints.bias[k];
    }
    std::vector<bool> done_row(m, false), pivot_column(n, false);
    std::vector<unsigned> pivot_of_row(m);
    for (unsigned step = 0; step < m; ++step) {
        std::optional<std::pair<unsigned, unsigned>> found;
        for (unsigned k = 0; k < m && !found; ++k)
            for (unsigned j = 0; j < n && !done_row[k] && !found; ++j)
                if (!pivot_column[j] && GiNaC::is_a<GiNaC::numeric>(rows(k, j)) && !rows(k, j).is_zero())
                    found = {k, j};
        if (!found)
            return std::nullopt;
        const auto [row, column] = *found;
        done_row[row] = true;
        pivot_column[column] = true;
        pivot_of_row[row] = column;
        const GiNaC::ex pivot = rows(row, column);
        for (unsigned j = 0; j <= n; ++j)
            rows(row, j) = (rows(row, j) / pivot).normal();
        for (unsigned k = 0; k < m; ++k) {
            const GiNaC::ex factor = rows(k, column);
            if (k == row || factor.is_zero())
                continue;
            for (unsigned j = 0; j <= n; ++j)
                rows(k, j) = (rows(k, j) - factor * rows(row, j)).normal();
            budget_check();
        }
    }
    embedded_constraints result;
    result.basis = GiNaC::matrix(n, n - m);
    result.particular = GiNaC::matrix(n, 1);
    std::vector<unsigned> free;
    for (unsigned j = 0; j < n; ++j)
        if (!pivot_column[j]) {
            result.basis(j, static_cast<unsigned>(free.size())) = 1;
            free.push_back(j);
        }
    for (unsigned k = 0; k < m; ++k) {
        result.pivots.push_back(pivot_of_row[k]);
        for (unsigned f = 0; f < free.size(); ++f)
            result.basis(pivot_of_row[k], f) = -rows(k, free[f]);
        result.particular(pivot_of_row[k], 0) = rows(k, n);
    }
    return result;
}

/// q̈ (n × 1) and λ (m × 1), unsimplified.
struct solved_motion {
    GiNaC::matrix accelerations;
    GiNaC::matrix multipliers;
};

/// The whole system [M −Aᵀ; A 0] [q̈; λ] = [f; −c] by GiNaC's solve.
solved_motion solve_whole(const model& scene, const GiNaC::matrix& mass, const GiNaC::matrix& force,
                          const constraint_equations& constraints)
{
    const unsigned n = mass.rows(), m = constraints.matrix.rows();
    GiNaC::matrix system(n + m, n + m), unknowns(n + m, 1), right(n + m, 1);
    for (unsigned i = 0; i < n; ++i) {
        for (unsigned j = 0; j < n; ++j)
            system(i, j) = mass(i, j);
        for (unsigned k = 0; k < m; ++k) {
            system(i, n + k) = -constraints.matrix(k, i);
            system(n + k, i) = constraints.matrix(k, i);
        }
        right(i, 0) = force(i, 0);
        unknowns(i, 0) = scene.coordinates[i].acceleration;
    }
    for (unsigned k = 0; k < m; ++k) {
        right(n + k, 0) = -constraints.bias[k];
        unknowns(n + k, 0) = scene.constraints[k].multiplier;
    }
    GiNaC::matrix solution;
    try {
        solution = system.solve(unknowns, right);
    } catch (const std::runtime_error&) {
        throw computation_error("the constraints and the mass matrix give no unique accelerations and multipliers "
                                "(the matrix [M −Aᵀ; A 0] is singular)");
    }
    solved_motion result{GiNaC::matrix(n, 1), GiNaC::matrix(m, 1)};
    for (unsigned i = 0; i < n; ++i)
        result.accelerations(i, 0) = solution(i, 0);
    for (unsigned k = 0; k < m; ++k)
        result.multipliers(k, 0) = solution(n + k, 0);
    return result;
}

/// The same by embedding: Nᵀ M N u = Nᵀ (f − M p) for the free accelerations u, q̈ = N u + p,
/// and Aᵀλ = M q̈ − f on the pivot coordinates, λ = A_d⁻ᵀ (M q̈ − f)_d. Simplified first, the
/// reduced entries are short (sin² + cos² = 1 comes back), and GiNaC's solve is quick on
/// them; the budgets are checked between its calls, which cannot be interrupted.
solved_motion solve_embedded(const model& scene, const GiNaC::matrix& mass, const GiNaC::matrix& force,
                             const constraint_equations& constraints, const embedded_constraints& embedded,
                             const simplifier& simplify)
{
    const unsigned m = constraints.matrix.rows(), free_count = embedded.basis.cols();
    GiNaC::matrix reduced = embedded.basis.transpose().mul(mass).mul(embedded.basis);
    GiNaC::matrix right = embedded.basis.transpose().mul(force.sub(mass.mul(embedded.particular)));
    GiNaC::matrix free_accelerations(free_count, 1), unknowns(free_count, 1);
    for (unsigned i = 0; i < free_count; ++i) {
        unknowns(i, 0) = GiNaC::symbol();
        budget_check_terms(right(i, 0), "a reduced force");
        right(i, 0) = simplify(right(i, 0));
        for (unsigned j = 0; j < free_count; ++j) {
            budget_check_terms(reduced(i, j), "a reduced mass");
            reduced(i, j) = simplify(reduced(i, j));
        }
    }
    if (free_count > 0) {
        try {
            free_accelerations = reduced.solve(unknowns, right);
        } catch (const std::runtime_error&) {
            throw computation_error("the constraints and the mass matrix give no unique accelerations and multipliers "
                                    "(the mass matrix is singular on the motions the constraints allow)");
        }
        budget_check();
    }
    solved_motion result{embedded.basis.mul(free_accelerations).add(embedded.particular), GiNaC::matrix(m, 1)};
    const GiNaC::matrix residual = mass.mul(result.accelerations).sub(force);
    GiNaC::matrix pivot_block(m, m), pivot_residual(m, 1), multipliers(m, 1);
    for (unsigned k = 0; k < m; ++k) {
        const unsigned d = embedded.pivots[k];
        pivot_residual(k, 0) = residual(d, 0);
        for (unsigned j = 0; j < m; ++j)
            pivot_block(k, j) = constraints.matrix(j, d);
        multipliers(k, 0) = scene.constraints[k].multiplier;
    }
    result.multipliers = pivot_block.solve(multipliers, pivot_residual);
    return result;
}

} // namespace

GiNaC::ex simplify_ratio(const GiNaC::ex& e, const simplifier& simplify)
{
    GiNaC::ex fraction = e.normal().numer_denom();
    GiNaC::ex numerator = simplify(fraction.op(0));
    GiNaC::ex denominator = simplify(fraction.op(1));
    if (denominator.is_equal(1))
        return numerator;
    return numerator / denominator;
}

constraint_equations derive_constraint_equations(const model& scene)
{
    const std::size_t n = scene.coordinates.size(), m = scene.constraints.size();
    constraint_equations result;
    result.matrix = GiNaC::matrix(static_cast<unsigned>(m), static_cast<unsigned>(n));
    GiNaC::exmap no_acceleration;
    for (const coordinate& c : scene.coordinates)
        no_acceleration[c.acceleration] = 0;
    std::vector<std::size_t> all;
    for (std::size_t k = 0; k < m; ++k) {
        const constraint& c = scene.constraints[k];
        GiNaC::ex velocity_form = c.rest;
        for (std::size_t j = 0; j < n; ++j) {
            result.matrix(static_cast<unsigned>(k), static_cast<unsigned>(j)) = c.coefficients[j];
            velocity_form += c.coefficients[j] * scene.coordinates[j].velocity;
        }
        result.bias.push_back(time_derivative(velocity_form, scene).subs(no_acceleration));
        result.integrable.push_back(c.constraint_kind == constraint::kind::holonomic || involutive(scene, {k}));
        all.push_back(k);
    }
    result.jointly_integrable = m == 0 || involutive(scene, all);
    return result;
}

multipliers_result derive_multipliers(const model& scene, const GiNaC::matrix& mass,
                                      const std::vector<GiNaC::ex>& forcing, const constraint_equations& constraints,
                                      const simplifier& simplify)
{
    const unsigned n = static_cast<unsigned>(scene.coordinates.size());
    const unsigned m = static_cast<unsigned>(scene.constraints.size());
    const GiNaC::matrix force(n, 1, GiNaC::lst(forcing.begin(), forcing.end()));
    const std::optional<embedded_constraints> embedded = embed_constraints(constraints);
    const solved_motion solved = embedded ? solve_embedded(scene, mass, force, constraints, *embedded, simplify)
                                          : solve_whole(scene, mass, force, constraints);
    multipliers_result result;
    for (unsigned i = 0; i < n; ++i)
        result.accelerations.push_back(solved.accelerations(i, 0));
    std::vector<GiNaC::ex> lambda;
    // GiNaC's solve and normal() cannot be interrupted: check the budgets between them.
    for (unsigned k = 0; k < m; ++k) {
        budget_check_terms(solved.multipliers(k, 0), "a multiplier");
        lambda.push_back(simplify_ratio(solved.multipliers(k, 0), simplify));
        result.constraints.push_back({scene.constraints[k].name, lambda.back(), {}});
    }

    // Forces on points that own their coordinates.
    bool planar = scene.bodies.empty();
    for (const point_mass& p : scene.points)
        planar = planar && p.position.size() >= 3 && p.position[2].is_zero();
    for (std::size_t p = 0; p < scene.points.size(); ++p) {
        const point_mass& point = scene.points[p];
        const std::vector<std::size_t> own = coordinates_in(scene, point.position);
        bool acted_on = false;
        for (unsigned k = 0; k < m; ++k)
            for (std::size_t j : own)
                acted_on = acted_on || !constraints.matrix(k, static_cast<unsigned>(j)).is_zero();
        if (!acted_on)
            continue;
        bool owned = true;
        for (std::size_t j : own) {
            const GiNaC::ex& q = scene.coordinates[j].position;
            for (std::size_t other = 0; other < scene.points.size(); ++other)
                for (const GiNaC::ex& x : scene.points[other].position)
                    owned = owned && (other == p || !x.has(q));
            for (const rigid_body& b : scene.bodies) {
                if (b.position)
                    for (const GiNaC::ex& x : *b.position)
                        owned = owned && !x.has(q);
                if (b.orientation)
                    for (const GiNaC::ex& x : *b.orientation)
                        owned = owned && !x.has(q);
            }
        }
        const unsigned s = static_cast<unsigned>(own.size());
        GiNaC::matrix jacobian(3, s);
        for (unsigned r = 0; r < 3; ++r)
            for (unsigned j = 0; j < s; ++j)
                jacobian(r, j) = differentiate(point.position[r], scene.coordinates[own[j]].position);
        GiNaC::matrix gram = jacobian.transpose().mul(jacobian);
        if (!owned || gram.determinant().normal().is_zero()) {
            result.unattributed.push_back(point.name);
            continue;
        }
        GiNaC::matrix pseudo = jacobian.mul(gram.inverse()); // J (JᵀJ)⁻¹
        for (unsigned k = 0; k < m; ++k) {
            GiNaC::matrix generalized(s, 1);
            bool any = false;
            for (unsigned j = 0; j < s; ++j) {
                generalized(j, 0) = constraints.matrix(k, static_cast<unsigned>(own[j])) * lambda[k];
                any = any || !generalized(j, 0).is_zero();
            }
            if (!any)
                continue;
            GiNaC::matrix force = pseudo.mul(generalized);
            constraint_point_force entry{point.name, {}};
            for (unsigned r = 0; r < (planar ? 2u : 3u); ++r) {
                budget_check_terms(force(r, 0), "a constraint force");
                entry.force.push_back(simplify_ratio(force(r, 0), simplify));
            }
            result.constraints[k].forces.push_back(entry);
        }
    }
    return result;
}

} // namespace lagrange
