// SPDX-License-Identifier: GPL-2.0-or-later
/** @file compiled_motion.cpp
 *  Equations of motion compiled to straight-line code and solved per evaluation. */
#include "numeric/compiled_motion.h"

#include "algebra/budget.h"
#include "algebra/calculus.h"
#include "numeric/point_tree.h"
#include "numeric/mass_matrix.h"
#include "numeric/values.h"
#include "program/angle_sums.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lagrange {

std::vector<GiNaC::ex> state_symbols(const model& scene)
{
    std::vector<GiNaC::ex> symbols;
    for (const coordinate& c : scene.coordinates)
        symbols.push_back(c.position);
    for (const coordinate& c : scene.coordinates)
        symbols.push_back(c.velocity);
    symbols.push_back(scene.time);
    return symbols;
}

namespace {

std::size_t nodes(const GiNaC::ex& e)
{
    std::size_t count = 1;
    for (const GiNaC::ex& operand : e)
        count += nodes(operand);
    return count;
}

} // namespace

GiNaC::ex cancelled(const GiNaC::ex& f)
{
    const std::size_t written = nodes(f);
    if (expanded_terms(f, 2 * written) >= 2 * written)
        return f;
    GiNaC::ex expanded = f.expand();
    return nodes(expanded) < written ? expanded : f;
}

motion_expressions motion_at_values(const model& scene, const equations_of_motion& equations,
                                    const std::map<std::string, GiNaC::ex>& values)
{
    const std::size_t n = scene.coordinates.size();
    motion_expressions motion{std::vector<GiNaC::ex>(n * n), std::vector<GiNaC::ex>(n)};
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = 0; j < n; ++j)
            motion.mass[i * n + j] =
                j < i ? motion.mass[j * n + i]
                      : at_values(equations.mass(static_cast<unsigned>(i), static_cast<unsigned>(j)), scene, values);
        motion.force[i] = cancelled(at_values(equations.forcing[i], scene, values));
    }
    return motion;
}

std::vector<GiNaC::ex> motion_jacobian(const model& scene, const motion_expressions& motion)
{
    std::vector<GiNaC::ex> outputs;
    for (const coordinate& c : scene.coordinates)
        for (const GiNaC::ex& m : motion.mass)
            outputs.push_back(differentiate(m, c.position));
    for (const GiNaC::ex& f : motion.force)
        for (const coordinate& c : scene.coordinates)
            outputs.push_back(differentiate(f, c.position));
    for (const GiNaC::ex& f : motion.force)
        for (const coordinate& c : scene.coordinates)
            outputs.push_back(differentiate(f, c.velocity));
    return outputs;
}

compiled_motion::compiled_motion(const model& scene, const equations_of_motion& equations,
                                 const std::map<std::string, GiNaC::ex>& values, motion_form form)
{
    n_ = scene.coordinates.size();
    if (n_ == 0)
        throw computation_error("the scene has no coordinates to simulate");
    const bool lagrangian_has_time = at_values(equations.lagrangian, scene, values).has(scene.time);
    conservative_ = !lagrangian_has_time && !equations.forces.any;
    accumulates_work_ = !lagrangian_has_time && equations.forces.any;

    // Symbols in the state's order, time last: without explicit time the programs read x directly.
    const std::vector<GiNaC::ex> symbols = state_symbols(scene);

    const motion_expressions motion = motion_at_values(scene, equations, values);
    for (const GiNaC::ex& e : motion.mass)
        explicit_time_ = explicit_time_ || e.has(scene.time);
    for (const GiNaC::ex& e : motion.force)
        explicit_time_ = explicit_time_ || e.has(scene.time);
    std::vector<GiNaC::ex> rhs_outputs = motion.mass;
    rhs_outputs.insert(rhs_outputs.end(), motion.force.begin(), motion.force.end());
    single_angles_ = form == motion_form::single_angles ||
                     (form != motion_form::expanded && n_ >= single_angles_coordinates);
    if (single_angles_)
        for (GiNaC::ex& e : rhs_outputs)
            e = expand_angle_sums(e);
    const std::vector<GiNaC::ex> jacobian_outputs = motion_jacobian(scene, motion);

    const GiNaC::ex energy = at_values(equations.energy, scene, values);
    // A cyclic coordinate (L holds its velocity, not itself) conserves its momentum.
    std::vector<GiNaC::ex> cyclic_momenta;
    const GiNaC::ex lagrangian_at_values = at_values(equations.lagrangian, scene, values);
    for (std::size_t i = 0; i < n_ && !equations.forces.any; ++i) {
        const coordinate& c = scene.coordinates[i];
        if (!lagrangian_at_values.has(c.position) && lagrangian_at_values.has(c.velocity)) {
            cyclic_momenta.push_back(at_values(equations.momenta[i], scene, values));
            momentum_names_.push_back("p_" + c.name);
        }
    }
    std::vector<GiNaC::ex> power_outputs;
    if (accumulates_work_) {
        GiNaC::ex power = 0;
        for (std::size_t i = 0; i < n_; ++i)
            power += at_values(equations.forces.total[i], scene, values) * scene.coordinates[i].velocity;
        power_outputs.push_back(power);
        for (const coordinate& c : scene.coordinates)
            power_outputs.push_back(differentiate(power, c.position));
        for (const coordinate& c : scene.coordinates)
            power_outputs.push_back(differentiate(power, c.velocity));
    }

    try {
        rhs_program_ = expression_program(rhs_outputs, symbols);
        if (form == motion_form::recursive || (form == motion_form::automatic && n_ >= recursive_coordinates))
            if (std::optional<expression_program> rates = recursive_rates(scene, equations, values, symbols)) {
                recursive_program_ = std::move(*rates);
                recursive_ = true;
            }
        jacobian_program_ = expression_program(jacobian_outputs, symbols);
        energy_program_ = expression_program({energy}, symbols);
        momentum_program_ = expression_program(cyclic_momenta, symbols);
        if (accumulates_work_)
            power_program_ = expression_program(power_outputs, symbols);
    } catch (const std::invalid_argument& error) {
        throw computation_error(std::string("the equations of motion cannot be compiled: ") + error.what());
    }
    symbols_.resize(1 + 2 * n_);
    outputs_.resize(n_ * n_ + n_);
    factor_.resize(n_ * n_);
    jacobian_outputs_.resize(jacobian_outputs.size());
    // A guard on the recursion's derivation: it must give M's q̈ at a few fixed states, or
    // M q̈ = f stays in use (the tests require the recursion where the scene is a tree).
    if (recursive_ && !recursion_agrees(recursive_program_, rhs_program_, n_))
        recursive_ = false;
}

std::optional<expression_program> recursive_rates(const model& scene, const equations_of_motion& equations,
                                                  const std::map<std::string, GiNaC::ex>& values,
                                                  const std::vector<GiNaC::ex>& symbols)
{
    const std::optional<point_tree_recursion> tree =
        point_tree_accelerations(scene, equations, [&](const GiNaC::ex& e) { return at_values(e, scene, values); });
    if (!tree)
        return std::nullopt;
    const auto n = static_cast<std::ptrdiff_t>(scene.coordinates.size());
    std::vector<GiNaC::ex> rates(symbols.begin() + n, symbols.begin() + 2 * n);
    rates.insert(rates.end(), tree->accelerations.begin(), tree->accelerations.end());
    return expression_program(tree->definitions, rates, symbols);
}

bool recursion_agrees(const expression_program& recursion, const expression_program& mass_and_force, std::size_t n)
{
    std::vector<double> symbols(2 * n + 1), by_recursion(2 * n), outputs(n * n + n), factor(n * n), by_mass(n),
        scratch;
    for (int s = 0; s < 3; ++s) {
        for (std::size_t i = 0; i < 2 * n; ++i)
            symbols[i] = 1.3 * std::sin(1.7 * (s + 1) * static_cast<double>(i + 1) + 0.3);
        symbols[2 * n] = 0.3 * (s + 1);
        recursion.run(symbols.data(), scratch, by_recursion.data());
        mass_and_force.run(symbols.data(), scratch, outputs.data());
        if (!solve_mass_matrix(outputs.data(), n, factor.data(), by_mass.data()))
            continue; // M singular here: nothing to compare
        double gap = 0, size = 0;
        for (std::size_t i = 0; i < n; ++i) {
            gap = std::max(gap, std::abs(by_recursion[n + i] - by_mass[i]));
            size = std::max(size, std::abs(by_mass[i]));
        }
        if (!(gap <= 1e-8 * size + 1e-300))
            return false;
    }
    return true;
}

void compiled_motion::solve(double t, const double* x, double* acceleration, bool keep_factor) const
{
    const double* symbols = x;
    if (explicit_time_) {
        std::copy(x, x + 2 * n_, symbols_.begin());
        symbols_[2 * n_] = t;
        symbols = symbols_.data();
    }
    if (native_.rhs && !recursive_)
        native_.rhs(symbols, outputs_.data());
    else
        rhs_program_.run(symbols, scratch_, outputs_.data());
    if (!solve_mass_matrix(outputs_.data(), n_, factor_.data(), acceleration, keep_factor))
        throw computation_error(singular_mass_matrix_message(t, x, 2 * n_));
}

void compiled_motion::rhs(double t, const double* x, double* dxdt) const
{
    if (recursive_) {
        const double* symbols = x;
        if (explicit_time_) {
            std::copy(x, x + 2 * n_, symbols_.begin());
            symbols_[2 * n_] = t;
            symbols = symbols_.data();
        }
        if (native_.rhs)
            native_.rhs(symbols, dxdt);
        else
            recursive_program_.run(symbols, scratch_, dxdt);
        // A zero pivot: M is singular here, and its solve says so.
        if (std::any_of(dxdt + n_, dxdt + 2 * n_, [](double a) { return !std::isfinite(a); }))
            solve(t, x, dxdt + n_);
    } else {
        std::copy(x + n_, x + 2 * n_, dxdt);
        solve(t, x, dxdt + n_);
    }
    if (accumulates_work_)
        dxdt[2 * n_] = power(t, x);
}

double compiled_motion::power(double t, const double* x) const
{
    if (!accumulates_work_)
        return 0;
    std::vector<double> symbols(1 + 2 * n_), outputs(1 + 2 * n_), scratch;
    std::copy(x, x + 2 * n_, symbols.begin());
    symbols[2 * n_] = t;
    power_program_.run(symbols.data(), scratch, outputs.data());
    return outputs[0];
}

void compiled_motion::jacobian(double t, const double* x, double* out) const
{
    const std::size_t n = n_, d = dimension();
    std::vector<double> acceleration(n);
    solve(t, x, acceleration.data(), true); // leaves the LDLᵀ factor of M in factor_
    std::copy(x, x + 2 * n_, symbols_.begin());
    symbols_[2 * n_] = t;
    if (native_.jacobian)
        native_.jacobian(symbols_.data(), jacobian_outputs_.data());
    else
        jacobian_program_.run(symbols_.data(), scratch_, jacobian_outputs_.data());
    const double* mass_derivative = jacobian_outputs_.data();        // [k][i][j]: ∂M_ij/∂q_k
    const double* force_position = mass_derivative + n * n * n;      // [i][k]: ∂f_i/∂q_k
    const double* force_velocity = force_position + n * n;           // [i][k]: ∂f_i/∂q̇_k
    std::fill(out, out + d * d, 0.0);
    for (std::size_t i = 0; i < n; ++i)
        out[i * d + n + i] = 1;
    std::vector<double> column(n);
    for (std::size_t k = 0; k < 2 * n; ++k) { // nothing depends on the work W, the last state
        for (std::size_t i = 0; i < n; ++i) {
            if (k < n) {
                double s = force_position[i * n + k];
                for (std::size_t j = 0; j < n; ++j)
                    s -= mass_derivative[(k * n + i) * n + j] * acceleration[j];
                column[i] = s;
            } else {
                column[i] = force_velocity[i * n + (k - n)];
            }
        }
        ldlt_solve(factor_.data(), n, column.data());
        for (std::size_t i = 0; i < n; ++i)
            out[(n + i) * d + k] = column[i];
    }
    if (accumulates_work_) {
        // The last row: ∂P/∂(q, q̇); W itself appears nowhere.
        std::vector<double> outputs(1 + 2 * n);
        power_program_.run(symbols_.data(), scratch_, outputs.data());
        for (std::size_t k = 0; k < 2 * n; ++k)
            out[2 * n * d + k] = outputs[1 + k];
    }
}

bool compiled_motion::compile_native(const native_limits& limits, std::string* why)
{
    return native_.compile(recursive_ ? recursive_program_ : rhs_program_, jacobian_program_, limits, why);
}

bool compiled_motion::compile_native_rhs(const native_limits& limits, std::string* why)
{
    return native_.compile(recursive_ ? recursive_program_ : rhs_program_, limits, why);
}

bool compiled_motion::compile_native_jacobian(const native_limits& limits, std::string* why)
{
    return native_.compile_jacobian(jacobian_program_, limits, why);
}

double compiled_motion::energy(const double* x) const
{
    std::vector<double> symbols(1 + 2 * n_, 0.0);
    std::copy(x, x + 2 * n_, symbols.begin());
    std::vector<double> scratch;
    double e = 0;
    energy_program_.run(symbols.data(), scratch, &e);
    return e;
}

ode_system compiled_motion::system(double energy_scale) const
{
    ode_system s;
    s.dimension = dimension();
    s.rhs = [this](double t, const double* x, double* dxdt) { rhs(t, x, dxdt); };
    s.jacobian = [this](double t, const double* x, double* out) { jacobian(t, x, out); };
    if (conservative_)
        s.invariants.push_back({"energy", [this](const double* x) { return energy(x); }, energy_scale});
    for (std::size_t k = 0; k < momentum_names_.size(); ++k)
        s.invariants.push_back({momentum_names_[k], [this, k](const double* x) {
                                    std::vector<double> symbols(1 + 2 * n_, 0.0), scratch, out(momentum_names_.size());
                                    std::copy(x, x + 2 * n_, symbols.begin());
                                    momentum_program_.run(symbols.data(), scratch, out.data());
                                    return out[k];
                                }});
    if (accumulates_work_)
        s.invariants.push_back(
            {"energy_balance", [this](const double* x) { return energy(x) - x[2 * n_]; }, energy_scale});
    // The compiled right-hand side knows the state (q, q̇) only, not the work W.
    if (native_.rhs && !accumulates_work_)
        s.compiled = ode_system::compiled_rhs{native_.rhs, recursive_ ? 0 : n_, explicit_time_};
    return s;
}

std::map<std::string, GiNaC::ex> first_value_point(const model& scene)
{
    std::map<std::string, GiNaC::ex> values;
    if (!scene.values.empty())
        for (const auto& [name, value] : scene.values.front().values)
            values[name] = value;
    return values;
}

std::vector<double> initial_state_vector(const model& scene, const std::map<std::string, GiNaC::ex>& values)
{
    std::size_t n = scene.coordinates.size();
    std::vector<double> x(2 * n, 0.0);
    if (!scene.initial)
        return x;
    for (std::size_t i = 0; i < n; ++i) {
        const std::string& name = scene.coordinates[i].name;
        auto p = scene.initial->positions.find(name);
        if (p != scene.initial->positions.end())
            x[i] = real_value(at_values(p->second, scene, values), "the initial value of `" + name + "`");
        auto v = scene.initial->velocities.find(name);
        if (v != scene.initial->velocities.end())
            x[n + i] = real_value(at_values(v->second, scene, values), "the initial value of `" + name + "'`");
    }
    return x;
}

} // namespace lagrange
