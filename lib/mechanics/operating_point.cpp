// SPDX-License-Identifier: GPL-2.0-or-later
/** @file operating_point.cpp
 *  The constrained linearization about an operating point (operating_point.h). */
#include "mechanics/operating_point.h"

#include "algebra/calculus.h"
#include "algebra/exact_matrix.h"
#include "algebra/factor.h"
#include "algebra/sign.h"
#include "algebra/sorted_terms.h"
#include "core/errors.h"
#include "core/names.h"
#include "mechanics/constraints.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <string>

namespace lagrange {

namespace {

using GiNaC::ex;
using GiNaC::matrix;

/// Where a matrix's dependent columns are chosen and checked: the parameters and the free
/// coordinates at random values in [0.5, 2] (fixed seed, so the choice is the same every run).
GiNaC::exmap sample_point(const model& scene)
{
    std::mt19937 random(20261128);
    std::uniform_real_distribution<double> value(0.5, 2.0);
    GiNaC::exmap at;
    for (const parameter& p : scene.parameters)
        at[p.symbol] = value(random);
    for (const coordinate& c : scene.coordinates)
        at[c.position] = value(random);
    return at;
}

Eigen::MatrixXd numbers(const matrix& m, const GiNaC::exmap& at)
{
    Eigen::MatrixXd result(m.rows(), m.cols());
    for (unsigned i = 0; i < m.rows(); ++i)
        for (unsigned j = 0; j < m.cols(); ++j) {
            const ex v = m(i, j).subs(at).evalf();
            result(i, j) = GiNaC::is_a<GiNaC::numeric>(v) && GiNaC::ex_to<GiNaC::numeric>(v).is_real()
                               ? GiNaC::ex_to<GiNaC::numeric>(v).to_double()
                               : std::nan("");
        }
    return result;
}

/// The columns to solve for: the first `rank` pivots of a column-pivoted QR, the best
/// conditioned choice; empty when the rows are not independent.
std::vector<std::size_t> pivot_columns(const Eigen::MatrixXd& m)
{
    if (m.rows() == 0)
        return {};
    if (!m.allFinite() || m.cols() < m.rows())
        return {};
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(m);
    qr.setThreshold(1e-10);
    if (qr.rank() < m.rows())
        return {};
    std::vector<std::size_t> columns;
    for (Eigen::Index k = 0; k < m.rows(); ++k)
        columns.push_back(static_cast<std::size_t>(qr.colsPermutation().indices()(k)));
    std::sort(columns.begin(), columns.end());
    return columns;
}

bool invertible(const Eigen::MatrixXd& m)
{
    if (!m.allFinite())
        return false;
    Eigen::FullPivLU<Eigen::MatrixXd> lu(m);
    lu.setThreshold(1e-10);
    return lu.rank() == m.rows();
}

std::vector<std::size_t> complement(std::size_t n, const std::vector<std::size_t>& taken)
{
    std::vector<std::size_t> rest;
    for (std::size_t j = 0; j < n; ++j)
        if (std::find(taken.begin(), taken.end(), j) == taken.end())
            rest.push_back(j);
    return rest;
}

matrix columns_of(const matrix& m, const std::vector<std::size_t>& columns)
{
    matrix result(m.rows(), static_cast<unsigned>(columns.size()));
    for (unsigned i = 0; i < m.rows(); ++i)
        for (unsigned j = 0; j < columns.size(); ++j)
            result(i, j) = m(i, static_cast<unsigned>(columns[j]));
    return result;
}

/// Bad input at the `independent` line, with its text.
scene_error at_independent_line(const model& scene, const std::string& message)
{
    scene_error error(scene.independent->where, message);
    error.attach_line_text(scene.independent->line_text);
    return error;
}

/// Bad input in the `linearize about` line, with the text of the line at `where`.
scene_error at_operating_point(const model& scene, const source_location& where, const std::string& message)
{
    scene_error error(where, message);
    if (!scene.operating_point)
        return error;
    auto line = scene.operating_point->line_texts.find(where.line);
    if (line != scene.operating_point->line_texts.end())
        error.attach_line_text(line->second);
    return error;
}

std::string names(const model& scene, const std::vector<std::size_t>& indices, const char* suffix)
{
    std::string out;
    for (std::size_t i : indices)
        out += (out.empty() ? "`" : ", `") + scene.coordinates[i].name + suffix + "`";
    return out;
}

/// Sorted by index, the dependent set of a request (its complement), or chosen here.
std::vector<std::size_t> dependent_set(const model& scene, const matrix& jacobian, const GiNaC::exmap& sample,
                                       const std::vector<std::size_t>& requested, const std::vector<bool>& named,
                                       const char* what, const char* suffix)
{
    const std::size_t n = scene.coordinates.size(), m = jacobian.rows();
    const Eigen::MatrixXd values = numbers(jacobian, sample);
    if (requested.empty()) {
        // Prefer to solve for what the point leaves unnamed: the pivots among those columns
        // when they span the constraints, else among all.
        std::vector<std::size_t> candidates;
        for (std::size_t j = 0; j < n; ++j)
            if (!named[j])
                candidates.push_back(j);
        Eigen::MatrixXd preferred(values.rows(), static_cast<Eigen::Index>(candidates.size()));
        for (std::size_t k = 0; k < candidates.size(); ++k)
            preferred.col(static_cast<Eigen::Index>(k)) = values.col(static_cast<Eigen::Index>(candidates[k]));
        std::vector<std::size_t> chosen = pivot_columns(preferred);
        if (chosen.size() == m && m > 0) {
            for (std::size_t& j : chosen)
                j = candidates[j];
            return chosen;
        }
        chosen = pivot_columns(values);
        if (chosen.size() != m)
            throw computation_error(std::string("the constraints' ") + what +
                                    " Jacobian has rank below the number of constraints at the operating point, "
                                    "so no set of independent " + what + "s exists there");
        return chosen;
    }
    if (requested.size() != n - m)
        throw at_independent_line(scene, "the constraints leave " + std::to_string(n - m) + " independent " + what + "s, and " +
                                     std::to_string(requested.size()) + " are named (" +
                                     names(scene, requested, suffix) + ")");
    std::vector<std::size_t> dependent = complement(n, requested);
    Eigen::MatrixXd block(values.rows(), static_cast<Eigen::Index>(dependent.size()));
    for (std::size_t k = 0; k < dependent.size(); ++k)
        block.col(static_cast<Eigen::Index>(k)) = values.col(static_cast<Eigen::Index>(dependent[k]));
    if (!invertible(block))
        throw at_independent_line(scene, "the independent " + std::string(what) + "s " + names(scene, requested, suffix) +
                                     " do not span the constraints: the dependent ones, " +
                                     names(scene, dependent, suffix) +
                                     ", cannot be solved from the constraints at the operating point (their "
                                     "columns of the constraint Jacobian are singular there)");
    return dependent;
}

/// The gradient of `e` with respect to `variables` at `at` (which gives every symbol of `e`
/// that is not left free), term by term and factor by factor: the value of each factor at
/// the point once, and a derivative only of the factors that hold a variable. A term with
/// two factors that vanish there has no part in it (most of the bicycle's forcing, quadratic
/// in the rates); one with a single such factor contributes through that factor only. This
/// linearizes before it simplifies: no derivative of the whole expression is ever formed.
std::vector<ex> gradient_at(const ex& e, const std::vector<ex>& variables, const GiNaC::exmap& at)
{
    std::vector<ex> gradient(variables.size(), 0);
    GiNaC::exvector terms;
    if (GiNaC::is_a<GiNaC::add>(e))
        for (std::size_t t = 0; t < e.nops(); ++t)
            terms.push_back(e.op(t));
    else
        terms.push_back(e);
    for (const ex& term : terms) {
        GiNaC::exvector factors;
        if (GiNaC::is_a<GiNaC::mul>(term))
            for (std::size_t k = 0; k < term.nops(); ++k)
                factors.push_back(term.op(k));
        else
            factors.push_back(term);
        GiNaC::exvector values;
        std::vector<std::size_t> zeros;
        for (std::size_t k = 0; k < factors.size() && zeros.size() < 2; ++k) {
            values.push_back(factors[k].subs(at));
            if (values.back().is_zero())
                zeros.push_back(k);
        }
        if (zeros.size() >= 2)
            continue;
        for (std::size_t i = 0; i < factors.size(); ++i) {
            if (!zeros.empty() && zeros.front() != i)
                continue;
            ex others = 1;
            for (std::size_t j = 0; j < factors.size(); ++j)
                if (j != i)
                    others *= values[j];
            for (std::size_t z = 0; z < variables.size(); ++z) {
                if (!factors[i].has(variables[z]))
                    continue;
                const ex d = differentiate(factors[i], GiNaC::ex_to<GiNaC::symbol>(variables[z])).subs(at);
                if (!d.is_zero())
                    gradient[z] += d * others;
            }
        }
    }
    return gradient;
}

/// Above this many expression nodes in sI − A's coupled block, det(sI − A) is left
/// unexpanded: the bicycle's 4 × 4 block in v and λ takes seconds and fills pages, while a
/// rolling disc's is a few dozen nodes.
constexpr std::size_t largest_expanded_pencil = 4000;

ex simplified(const ex& e, const simplifier& simplify) { return simplify_ratio(e, simplify); }

/// Whether e is 0: exactly, or (where the simplifier falls short) at the sample point to
/// near rounding.
bool is_zero_at(const ex& e, const GiNaC::exmap& sample)
{
    if (vanishes(e))
        return true;
    const ex v = e.subs(sample).evalf();
    return GiNaC::is_a<GiNaC::numeric>(v) && std::abs(GiNaC::ex_to<GiNaC::numeric>(v).to_double()) < 1e-11;
}

} // namespace

bool linearizes_about_operating_point(const model& scene)
{
    return !scene.coordinates.empty() && (!scene.constraints.empty() || scene.operating_point);
}

std::vector<std::size_t> coupled_states(const matrix& a)
{
    // Which entries are 0, decided once: literally, else nonzero where a value at random
    // symbols says so clearly, else by vanishes() (expanded and normalized).
    std::mt19937 random(20261203);
    std::uniform_real_distribution<double> value(0.5, 2.0);
    GiNaC::exmap sample;
    const std::size_t n = a.rows();
    std::vector<std::vector<bool>> zero(n, std::vector<bool>(n, true));
    for (unsigned i = 0; i < n; ++i)
        for (unsigned j = 0; j < n; ++j) {
            const ex& e = a(i, j);
            if (e.is_zero())
                continue;
            for (auto k = e.preorder_begin(); k != e.preorder_end(); ++k)
                if (GiNaC::is_a<GiNaC::symbol>(*k) && !sample.count(*k))
                    sample[*k] = value(random);
            const ex v = e.subs(sample).evalf();
            const bool clearly =
                GiNaC::is_a<GiNaC::numeric>(v) && GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(v)).to_double() > 1e-6;
            zero[i][j] = !clearly && vanishes(e);
        }
    std::vector<std::size_t> kept;
    for (std::size_t i = 0; i < n; ++i)
        kept.push_back(i);
    for (bool removed = true; removed;) {
        removed = false;
        for (std::size_t k = 0; k < kept.size() && !removed; ++k) {
            bool row = true, column = true;
            for (std::size_t other : kept) {
                row = row && zero[kept[k]][other];
                column = column && zero[other][kept[k]];
            }
            if (row || column) {
                kept.erase(kept.begin() + static_cast<std::ptrdiff_t>(k));
                removed = true;
            }
        }
    }
    return kept;
}

operating_linearization linearize_about(const model& scene, const equations_of_motion& equations,
                                        const simplifier& simplify)
{
    const std::size_t n = scene.coordinates.size(), p = scene.inputs.size();
    const std::size_t m = scene.constraints.size();
    if (!scene.operating_point && !scene.equilibrium && !scene.steady)
        throw computation_error("`state_space` of a scene with constraints needs an operating point: give it with "
                                "`linearize about q1 = …, q1' = …` or an `equilibrium` line");
    // Without `linearize about`: the `equilibrium` line at rest, or its steady motion (the
    // coordinates given a rate move at it, those given no value stay free).
    auto given_position = [&](std::size_t i) -> std::optional<ex> {
        if (scene.operating_point)
            return scene.operating_point->positions[i];
        if (scene.steady)
            return scene.steady->positions[i];
        return (*scene.equilibrium)[i];
    };
    operating_linearization result;
    // The point as given: positions (free where not named), velocities, inputs.
    std::vector<std::optional<ex>> velocity(n);
    result.position.resize(n);
    result.inputs.assign(p, 0);
    GiNaC::exmap at;
    for (std::size_t i = 0; i < n; ++i) {
        const coordinate& c = scene.coordinates[i];
        const std::optional<ex> value = given_position(i);
        result.position[i] = value ? *value : ex(c.position);
        if (value)
            at[c.position] = *value;
        if (scene.operating_point)
            velocity[i] = scene.operating_point->velocities[i];
        else if (scene.steady)
            velocity[i] = scene.steady->rates[i];
    }
    if (scene.operating_point)
        for (std::size_t k = 0; k < p && k < scene.operating_point->inputs.size(); ++k)
            result.inputs[k] = scene.operating_point->inputs[k];
    for (std::size_t k = 0; k < p; ++k)
        at[scene.inputs[k].symbol] = result.inputs[k];
    auto located = [&](std::size_t i, bool speed) {
        if (!scene.operating_point)
            return source_location{};
        return speed ? scene.operating_point->velocity_where[i] : scene.operating_point->position_where[i];
    };
    const source_location statement =
        scene.operating_point ? scene.operating_point->where : source_location{};
    const GiNaC::exmap sample = sample_point(scene);

    // The holonomic constraints must hold at the point.
    std::vector<std::size_t> holonomic;
    for (std::size_t k = 0; k < m; ++k) {
        const constraint& c = scene.constraints[k];
        if (c.constraint_kind != constraint::kind::holonomic)
            continue;
        holonomic.push_back(k);
        const ex residual = simplified(c.function.subs(at), simplify);
        if (is_zero_at(residual, sample))
            continue;
        source_location where = statement;
        for (std::size_t i = 0; i < n; ++i)
            if (c.function.has(scene.coordinates[i].position) && at.count(scene.coordinates[i].position)) {
                where = located(i, false);
                break;
            }
        const std::string message = "the operating point violates constraint `" + c.name + "`: " +
                                    message_text(c.function) + " is " + message_text(residual) +
                                    " there, not 0";
        if (!scene.operating_point)
            throw computation_error(message);
        throw at_operating_point(scene, where, message);
    }
    for (std::size_t k = 0; k < m; ++k)
        if (scene.constraints[k].function.has(scene.time))
            throw computation_error("constraint `" + scene.constraints[k].name +
                                    "` depends on t: the linearization would change with time");
    const constraint_equations& constrained =
        equations.constraints ? *equations.constraints : constraint_equations{matrix(0, static_cast<unsigned>(n)), {}, {}, true};

    // Independent coordinates: the holonomic Jacobian's pivots are the dependent ones.
    matrix holonomic_jacobian(static_cast<unsigned>(holonomic.size()), static_cast<unsigned>(n));
    for (unsigned r = 0; r < holonomic.size(); ++r)
        for (unsigned j = 0; j < n; ++j)
            holonomic_jacobian(r, j) = simplified(scene.constraints[holonomic[r]].coefficients[j].subs(at), simplify);
    matrix velocity_jacobian(static_cast<unsigned>(m), static_cast<unsigned>(n));
    for (unsigned k = 0; k < m; ++k)
        for (unsigned j = 0; j < n; ++j)
            velocity_jacobian(k, j) = simplified(constrained.matrix(k, j).subs(at), simplify);
    std::vector<std::size_t> requested_coordinates, requested_speeds;
    if (scene.independent) {
        requested_coordinates = scene.independent->coordinates;
        requested_speeds = scene.independent->speeds;
        std::sort(requested_coordinates.begin(), requested_coordinates.end());
        std::sort(requested_speeds.begin(), requested_speeds.end());
        // Coordinates alone name the speeds too where every constraint is holonomic.
        if (requested_speeds.empty() && holonomic.size() == m)
            requested_speeds = requested_coordinates;
    }
    result.chosen = !scene.independent;
    std::vector<bool> position_named(n), velocity_named(n);
    for (std::size_t i = 0; i < n; ++i) {
        position_named[i] = at.count(scene.coordinates[i].position) > 0;
        velocity_named[i] = velocity[i].has_value();
    }
    const std::vector<std::size_t> dependent_coordinates =
        dependent_set(scene, holonomic_jacobian, sample, requested_coordinates, position_named, "coordinate", "");
    const std::vector<std::size_t> dependent_speeds =
        dependent_set(scene, velocity_jacobian, sample, requested_speeds, velocity_named, "speed", "'");
    result.coordinates = complement(n, dependent_coordinates);
    result.speeds = complement(n, dependent_speeds);

    // Velocities: those not named are 0, the dependent ones solved from A q̇ + b = 0.
    const matrix a_dependent = columns_of(velocity_jacobian, dependent_speeds);
    const matrix a_dependent_inverse = m ? a_dependent.inverse() : matrix(0, 0);
    result.velocity.assign(n, 0);
    for (std::size_t j : result.speeds)
        result.velocity[j] = velocity[j] ? *velocity[j] : ex(0);
    matrix known(static_cast<unsigned>(m), 1);
    for (unsigned k = 0; k < m; ++k) {
        ex sum = scene.constraints[k].rest;
        for (std::size_t j : result.speeds)
            sum += constrained.matrix(k, static_cast<unsigned>(j)) * result.velocity[j];
        known(k, 0) = simplified(sum.subs(at), simplify);
    }
    const matrix solved_speeds = m ? a_dependent_inverse.mul(known).mul_scalar(-1) : matrix(0, 1);
    for (unsigned d = 0; d < dependent_speeds.size(); ++d) {
        const std::size_t j = dependent_speeds[d];
        const ex value = simplified(solved_speeds(d, 0), simplify);
        if (velocity[j] && !is_zero_at(simplified(*velocity[j] - value, simplify), sample))
            throw at_operating_point(scene, located(j, true), "the operating point violates the velocity constraints: with the "
                                                "independent speeds given, `" + scene.coordinates[j].name +
                                                "'` must be " + message_text(value) + ", not " +
                                                message_text(*velocity[j]));
        result.velocity[j] = value;
    }
    for (std::size_t i = 0; i < n; ++i)
        at[scene.coordinates[i].velocity] = result.velocity[i];

    // q̈ and λ at the point: [M −Aᵀ; A 0] [q̈; λ] = [f + Q; −c].
    for (const ex& e : equations.forcing)
        if (e.subs(at).has(scene.time))
            throw computation_error("the equations of motion depend on t at the operating point: the linearization "
                                    "would change with time");
    const unsigned size = static_cast<unsigned>(n + m);
    matrix system(size, size), right(size, 1);
    for (unsigned i = 0; i < n; ++i) {
        for (unsigned j = 0; j < n; ++j)
            system(i, j) = simplified(equations.mass(i, j).subs(at), simplify);
        for (unsigned k = 0; k < m; ++k) {
            system(i, static_cast<unsigned>(n) + k) = -velocity_jacobian(k, i);
            system(static_cast<unsigned>(n) + k, i) = velocity_jacobian(k, i);
        }
        right(i, 0) = simplified(equations.forcing[i].subs(at), simplify);
    }
    for (unsigned k = 0; k < m; ++k)
        right(static_cast<unsigned>(n) + k, 0) = simplified(-constrained.bias[k].subs(at), simplify);
    matrix system_inverse;
    try {
        system_inverse = system.inverse();
    } catch (const std::exception&) {
        throw computation_error("the mass matrix with the constraints, [M −Aᵀ; A 0], is singular at the operating "
                                "point: the accelerations are not determined there");
    }
    const matrix solution = system_inverse.mul(right);
    for (unsigned i = 0; i < n; ++i)
        result.accelerations.push_back(simplified(solution(i, 0), simplify));
    for (unsigned k = 0; k < m; ++k)
        result.multipliers.push_back(simplified(solution(static_cast<unsigned>(n) + k, 0), simplify));

    // The Jacobians of R = M(q) α − A(q)ᵀ μ − f(q, q̇, u) and S = A(q) α + c(q, q̇), with α and μ
    // held at q̈ and λ of the point (placeholders, so that a free coordinate in them is not
    // differentiated).
    std::vector<GiNaC::symbol> alpha(n), mu(m);
    GiNaC::exmap held;
    for (std::size_t i = 0; i < n; ++i)
        held[alpha[i]] = result.accelerations[i];
    for (std::size_t k = 0; k < m; ++k)
        held[mu[k]] = result.multipliers[k];
    std::vector<ex> residual(n + m);
    for (std::size_t i = 0; i < n; ++i) {
        ex r = -equations.forcing[i];
        for (std::size_t j = 0; j < n; ++j)
            r += equations.mass(static_cast<unsigned>(i), static_cast<unsigned>(j)) * alpha[j];
        for (std::size_t k = 0; k < m; ++k)
            r -= constrained.matrix(static_cast<unsigned>(k), static_cast<unsigned>(i)) * mu[k];
        residual[i] = r;
    }
    for (std::size_t k = 0; k < m; ++k) {
        ex s = constrained.bias[k];
        for (std::size_t j = 0; j < n; ++j)
            s += constrained.matrix(static_cast<unsigned>(k), static_cast<unsigned>(j)) * alpha[j];
        residual[n + k] = s;
    }
    std::vector<ex> variables;
    for (const coordinate& c : scene.coordinates)
        variables.push_back(c.position);
    for (const coordinate& c : scene.coordinates)
        variables.push_back(c.velocity);
    for (const input_signal& u : scene.inputs)
        variables.push_back(u.symbol);
    // Linearize before differentiating: the gradient at the point, term by term.
    GiNaC::exmap at_point = at;
    for (const auto& [symbol, value] : held)
        at_point[symbol] = value;
    matrix jacobian(size, static_cast<unsigned>(variables.size()));
    for (unsigned r = 0; r < size; ++r) {
        const std::vector<ex> row = gradient_at(residual[r], variables, at_point);
        for (unsigned z = 0; z < variables.size(); ++z)
            jacobian(r, z) = -row[z];
    }
    const matrix rates = system_inverse.mul(jacobian); // [φ_q, φ_q̇, φ_u; λ_…]
    auto phi = [&](std::size_t i, std::size_t z) { return rates(static_cast<unsigned>(i), static_cast<unsigned>(z)); };

    // C₀, C₁, C₂.
    const std::size_t free_coordinates = result.coordinates.size(), free_speeds = result.speeds.size();
    matrix c0(static_cast<unsigned>(n), static_cast<unsigned>(free_coordinates));
    {
        const matrix f_dependent = columns_of(holonomic_jacobian, dependent_coordinates);
        const matrix f_independent = columns_of(holonomic_jacobian, result.coordinates);
        const matrix solved = holonomic.empty() ? matrix(0, static_cast<unsigned>(free_coordinates))
                                                : f_dependent.inverse().mul(f_independent);
        for (unsigned i = 0; i < free_coordinates; ++i) {
            c0(static_cast<unsigned>(result.coordinates[i]), i) = 1;
            for (unsigned d = 0; d < dependent_coordinates.size(); ++d)
                c0(static_cast<unsigned>(dependent_coordinates[d]), i) = -solved(d, i);
        }
    }
    matrix c1(static_cast<unsigned>(n), static_cast<unsigned>(n));
    matrix c2(static_cast<unsigned>(n), static_cast<unsigned>(free_speeds));
    {
        // K = ∂(A q̇ + b)/∂q at the point.
        matrix k_matrix(static_cast<unsigned>(m), static_cast<unsigned>(n));
        for (unsigned k = 0; k < m; ++k) {
            ex form = scene.constraints[k].rest;
            for (unsigned j = 0; j < n; ++j)
                form += constrained.matrix(k, j) * scene.coordinates[j].velocity;
            for (unsigned j = 0; j < n; ++j)
                k_matrix(k, j) = differentiate(form, scene.coordinates[j].position).subs(at);
        }
        const matrix from_positions = m ? a_dependent_inverse.mul(k_matrix) : matrix(0, static_cast<unsigned>(n));
        const matrix from_speeds =
            m ? a_dependent_inverse.mul(columns_of(velocity_jacobian, result.speeds)) : matrix(0, 0);
        for (unsigned d = 0; d < dependent_speeds.size(); ++d) {
            for (unsigned j = 0; j < n; ++j)
                c1(static_cast<unsigned>(dependent_speeds[d]), j) = -from_positions(d, j);
            for (unsigned j = 0; j < free_speeds; ++j)
                c2(static_cast<unsigned>(dependent_speeds[d]), j) = -from_speeds(d, j);
        }
        for (unsigned j = 0; j < free_speeds; ++j)
            c2(static_cast<unsigned>(result.speeds[j]), j) = 1;
    }
    matrix phi_q(static_cast<unsigned>(n), static_cast<unsigned>(n)), phi_v(static_cast<unsigned>(n), static_cast<unsigned>(n));
    for (unsigned i = 0; i < n; ++i)
        for (unsigned j = 0; j < n; ++j) {
            phi_q(i, j) = phi(i, j);
            phi_v(i, j) = phi(i, n + j);
        }
    const matrix position_rows = c1.mul(c0);                       // δq̇ per δq_I
    const matrix acceleration_rows = phi_q.add(phi_v.mul(c1)).mul(c0); // δq̈ per δq_I
    const matrix acceleration_speed = phi_v.mul(c2);                // δq̈ per δq̇_J
    const unsigned states = static_cast<unsigned>(free_coordinates + free_speeds);
    result.a = matrix(states, states);
    result.b = matrix(states, static_cast<unsigned>(p));
    for (unsigned r = 0; r < free_coordinates; ++r) {
        const unsigned i = static_cast<unsigned>(result.coordinates[r]);
        for (unsigned j = 0; j < free_coordinates; ++j)
            result.a(r, j) = simplified(position_rows(i, j), simplify);
        for (unsigned j = 0; j < free_speeds; ++j)
            result.a(r, static_cast<unsigned>(free_coordinates) + j) = simplified(c2(i, j), simplify);
        result.state.push_back(scene.coordinates[i].position);
        result.residual.push_back(result.velocity[i]);
    }
    for (unsigned r = 0; r < free_speeds; ++r) {
        const unsigned i = static_cast<unsigned>(result.speeds[r]);
        const unsigned row = static_cast<unsigned>(free_coordinates) + r;
        for (unsigned j = 0; j < free_coordinates; ++j)
            result.a(row, j) = simplified(acceleration_rows(i, j), simplify);
        for (unsigned j = 0; j < free_speeds; ++j)
            result.a(row, static_cast<unsigned>(free_coordinates) + j) = simplified(acceleration_speed(i, j), simplify);
        for (unsigned k = 0; k < p; ++k)
            result.b(row, k) = simplified(phi(i, 2 * n + k), simplify);
        result.state.push_back(scene.coordinates[i].velocity);
        result.residual.push_back(result.accelerations[i]);
    }
    for (unsigned i = 0; i < n; ++i)
        for (unsigned j = 0; j < free_coordinates; ++j)
            c0(i, j) = simplified(c0(i, j), simplify);
    result.configuration = c0;

    // det(sI − A), cleared of denominators: s^z det(sI − A') with A' the rest of A.
    result.s = GiNaC::realsymbol(unused_name(scene, "s"));
    {
        const std::vector<std::size_t> kept = coupled_states(result.a);
        unsigned size = static_cast<unsigned>(kept.size());
        matrix pencil(size, size);
        for (unsigned i = 0; i < size; ++i)
            for (unsigned j = 0; j < size; ++j)
                pencil(i, j) = (i == j ? ex(result.s) : ex(0)) -
                               result.a(static_cast<unsigned>(kept[i]), static_cast<unsigned>(kept[j]));
        std::size_t nodes = 0;
        for (unsigned i = 0; i < size; ++i)
            for (unsigned j = 0; j < size; ++j)
                for (auto k = pencil(i, j).preorder_begin(); k != pencil(i, j).preorder_end(); ++k)
                    ++nodes;
        if (nodes > largest_expanded_pencil) {
            result.characteristic_left_out = "A's coupled " + std::to_string(size) + " × " + std::to_string(size) +
                                             " block has " + std::to_string(nodes) + " nodes, so det(sI − A) is not "
                                             "expanded symbolically; its roots are the eigenvalues at the `values` "
                                             "points";
            size = 0;
        }
        const ex fraction = (GiNaC::pow(result.s, static_cast<int>(states - size)) *
                             (size ? fraction_free_determinant(pencil) : ex(1)))
                                .normal()
                                .numer_denom();
        ex polynomial = fraction.op(0);
        if (std::optional<int> sign = sign_of(fraction.op(1)); sign && *sign < 0)
            polynomial = -polynomial;
        if (result.characteristic_left_out.empty())
            result.characteristic = factor_if_quick(polynomial);
    }

    // What kind of point it is.
    bool resting = true, steady = true;
    for (std::size_t i = 0; i < n; ++i) {
        if (!is_zero_at(result.velocity[i], sample)) {
            resting = false;
            result.moving.push_back(i);
        }
        steady = steady && is_zero_at(result.accelerations[i], sample);
    }
    result.point_kind = !steady ? operating_linearization::kind::moving
                        : resting ? operating_linearization::kind::equilibrium
                                  : operating_linearization::kind::steady;
    if (result.point_kind == operating_linearization::kind::steady) {
        GiNaC::lst everything{equations.mass};
        for (const ex& e : equations.forcing)
            everything.append(e);
        everything.append(constrained.matrix);
        for (const ex& e : constrained.bias)
            everything.append(e);
        for (const constraint& c : scene.constraints)
            everything.append(c.rest);
        result.moving_cyclic = true;
        for (std::size_t i : result.moving)
            result.moving_cyclic = result.moving_cyclic && !everything.has(scene.coordinates[i].position);
    }
    return result;
}

} // namespace lagrange
