// SPDX-License-Identifier: GPL-2.0-or-later
/** @file exported_system.cpp
 *  The programs behind exported code (see exported_system.h). */
#include "numeric/exported_system.h"

#include "program/angle_sums.h"

#include "numeric/compiled_motion.h"
#include "numeric/point_tree.h"
#include "algebra/calculus.h"
#include "algebra/budget.h"
#include "algebra/canonical_order.h"
#include "core/errors.h"
#include "numeric/values.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace lagrange {

namespace {

/// The equilibrium's state, T and V as one program, when they depend on the parameters only.
std::optional<expression_program> linear_program(const model& scene, const linearization_result& linear,
                                                 const std::vector<GiNaC::ex>& symbols)
{
    const std::size_t n = scene.coordinates.size();
    if (linear.at.size() != n || linear.kinetic.rows() != n || linear.potential.rows() != n)
        return std::nullopt;
    std::vector<GiNaC::ex> entries(linear.at.begin(), linear.at.end());
    entries.resize(2 * n, 0);
    for (const GiNaC::matrix* m : {&linear.kinetic, &linear.potential})
        for (unsigned i = 0; i < n; ++i)
            for (unsigned j = 0; j < n; ++j)
                entries.push_back((*m)(i, j));
    for (const GiNaC::ex& e : entries) {
        if (e.has(scene.time))
            return std::nullopt;
        for (const coordinate& c : scene.coordinates)
            if (e.has(c.position) || e.has(c.velocity))
                return std::nullopt;
        for (const input_signal& u : scene.inputs)
            if (e.has(u.symbol))
                return std::nullopt;
    }
    try {
        return expression_program(entries, symbols);
    } catch (const std::invalid_argument&) {
        return std::nullopt; // not compilable: the export goes without it
    }
}

/// e as Σ c_k(p) x_k: its expanded terms grouped by their factors that vary (x_k, in the
/// state, t and u), and each group's parameter factors summed (c_k, a value of the parameters
/// alone that the program computes once). The engine's own code has this by folding the
/// values into one number per x_k; without it a 10-link chain's M and F multiply each mass
/// in apart. e as it is when its expansion would have over 2·(its operands) + 64 terms.
GiNaC::ex collected_by_state(const GiNaC::ex& e, const std::vector<GiNaC::ex>& varying)
{
    if (expanded_terms(e, 2 * e.nops() + 64) > 2 * e.nops() + 64)
        return e;
    const GiNaC::ex expanded = e.expand();
    if (!GiNaC::is_a<GiNaC::add>(expanded))
        return e;
    auto varies = [&](const GiNaC::ex& f) {
        return std::any_of(varying.begin(), varying.end(), [&](const GiNaC::ex& v) { return f.has(v); });
    };
    canonical_keys keys;
    std::map<std::string, std::pair<GiNaC::ex, GiNaC::ex>> groups; // x_k's key → (x_k, c_k)
    for (const GiNaC::ex& term : expanded) {
        GiNaC::ex constant = 1, variable = 1;
        for (const GiNaC::ex& f : GiNaC::is_a<GiNaC::mul>(term) ? GiNaC::exvector(term.begin(), term.end())
                                                                 : GiNaC::exvector{term})
            (varies(f) ? variable : constant) *= f;
        auto [at, fresh] = groups.try_emplace(keys.key(variable), variable, 0);
        at->second.second += constant;
    }
    GiNaC::ex out = 0;
    for (const auto& [key, group] : groups)
        out += GiNaC::collect_common_factors(group.second) * group.first;
    return out;
}

} // namespace

exported_system export_system(const model& scene, const equations_of_motion& equations,
                              const linearization_result* linearization, const conserved_result* conserved)
{
    exported_system out;
    const std::size_t n = scene.coordinates.size();
    if (n == 0)
        throw computation_error("the scene has no coordinates to export");
    out.coordinates = n;
    std::vector<GiNaC::ex> symbols;
    for (const coordinate& c : scene.coordinates) {
        symbols.push_back(c.position);
        out.state_names.push_back(c.name);
    }
    for (const coordinate& c : scene.coordinates) {
        symbols.push_back(c.velocity);
        out.state_names.push_back(c.name + "_dot");
    }
    symbols.push_back(scene.time);
    for (const parameter& p : scene.parameters) {
        symbols.push_back(p.symbol);
        out.parameter_names.push_back(p.name);
    }
    for (const input_signal& u : scene.inputs) {
        symbols.push_back(u.symbol);
        out.input_names.push_back(u.name);
    }

    std::vector<GiNaC::ex> mass(n * n);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j)
            mass[i * n + j] = equations.mass(static_cast<unsigned>(std::min(i, j)), static_cast<unsigned>(std::max(i, j)));
    // The simulation's Jacobian parts, with the parameters left symbols, then ∂F/∂u.
    std::vector<GiNaC::ex> derivatives = motion_jacobian(scene, {mass, equations.forcing});
    for (const GiNaC::ex& f : equations.forcing)
        for (const input_signal& u : scene.inputs)
            derivatives.push_back(differentiate(f, u.symbol));
    // M and F as the engine compiles them: F without its cancelling terms, and both through the
    // sines and cosines of the single angles (fewer of them, each dearer than the products that
    // replace them), then collected by their varying factors (docs/benchmarks.md, "Exported code").
    std::vector<GiNaC::ex> varying(symbols.begin(), symbols.begin() + static_cast<std::ptrdiff_t>(2 * n + 1));
    for (const input_signal& u : scene.inputs)
        varying.push_back(u.symbol);
    std::vector<GiNaC::ex> forcing;
    for (const GiNaC::ex& f : equations.forcing)
        forcing.push_back(collected_by_state(expand_angle_sums(cancelled(f)), varying));
    for (GiNaC::ex& e : mass)
        e = collected_by_state(expand_angle_sums(e), varying);
    std::vector<GiNaC::ex> constraint_parts, constraint_derivatives;
    if (equations.constraints) {
        const constraint_equations& c = *equations.constraints;
        // ∂A/∂q_k (k slowest), then ∂c/∂q, ∂c/∂q̇ and ∂c/∂u, row r = c_r
        for (const coordinate& q : scene.coordinates)
            for (unsigned r = 0; r < c.matrix.rows(); ++r)
                for (unsigned j = 0; j < c.matrix.cols(); ++j)
                    constraint_derivatives.push_back(differentiate(c.matrix(r, j), q.position));
        for (bool velocity : {false, true})
            for (const GiNaC::ex& bias : c.bias)
                for (const coordinate& q : scene.coordinates)
                    constraint_derivatives.push_back(differentiate(bias, velocity ? q.velocity : q.position));
        for (const GiNaC::ex& bias : c.bias)
            for (const input_signal& u : scene.inputs)
                constraint_derivatives.push_back(differentiate(bias, u.symbol));
        for (unsigned k = 0; k < c.matrix.rows(); ++k)
            for (unsigned j = 0; j < c.matrix.cols(); ++j)
                constraint_parts.push_back(c.matrix(k, j));
        constraint_parts.insert(constraint_parts.end(), c.bias.begin(), c.bias.end());
        for (const constraint& k : scene.constraints) {
            constraint_parts.push_back(k.function);
            out.constraint_names.push_back(k.name);
        }
    }
    // The parameters keep their values from call to call: each product's parameter factors
    // are one value, shared, that the state is multiplied onto.
    const std::vector<GiNaC::ex> parameters(symbols.begin() + static_cast<std::ptrdiff_t>(2 * n + 1),
                                            symbols.begin() + static_cast<std::ptrdiff_t>(2 * n + 1 + scene.parameters.size()));
    auto program = [&](const std::vector<GiNaC::ex>& outputs) {
        return expression_program(outputs, symbols, parameters);
    };
    try {
        out.mass = program(mass);
        std::vector<GiNaC::ex> both = mass;
        both.insert(both.end(), forcing.begin(), forcing.end());
        out.mass_and_forcing = program(both);
        out.forcing = program(forcing);
        out.energy = program({equations.energy});
        out.derivatives = program(derivatives);
        // The recursion with the parameters left symbols (`at` the identity), as the engine
        // takes it from recursive_coordinates on (compiled_motion.cpp).
        if (n >= recursive_coordinates)
            if (std::optional<point_tree_recursion> tree = point_tree_accelerations(scene, equations))
                out.recursion = expression_program(tree->definitions, tree->accelerations, symbols, parameters);
        if (!constraint_parts.empty()) {
            out.constraint_parts = program(constraint_parts);
            out.constraint_derivatives = program(constraint_derivatives);
        }
    } catch (const std::invalid_argument& error) {
        throw computation_error(std::string("the equations of motion cannot be exported: ") + error.what());
    }
    if (linearization)
        out.linear = linear_program(scene, *linearization, symbols);
    if (conserved) {
        std::vector<GiNaC::ex> quantities;
        if (conserved->energy) {
            quantities.push_back(*conserved->energy);
            out.conserved_names.push_back("energy");
        }
        for (std::size_t k = 0; k < conserved->cyclic.size(); ++k) {
            quantities.push_back(conserved->momenta[k]);
            out.conserved_names.push_back("p_" + scene.coordinates[conserved->cyclic[k]].name);
        }
        if (!quantities.empty())
            out.conserved = program(quantities);
    }

    // Defaults: the first `values` line, where it gives a number (an expression in other
    // parameters is evaluated with theirs).
    out.defaults.assign(scene.parameters.size(), std::numeric_limits<double>::quiet_NaN());
    if (!scene.values.empty()) {
        GiNaC::exmap given = value_map(scene, scene.values.front());
        for (std::size_t k = 0; k < scene.parameters.size(); ++k) {
            const GiNaC::ex& symbol = scene.parameters[k].symbol;
            auto found = given.find(symbol);
            if (found == given.end())
                continue;
            GiNaC::ex value = GiNaC::evalf(found->second.subs(given).subs(given));
            if (GiNaC::is_a<GiNaC::numeric>(value) && GiNaC::ex_to<GiNaC::numeric>(value).is_real())
                out.defaults[k] = GiNaC::ex_to<GiNaC::numeric>(value).to_double();
        }
    }
    return out;
}

} // namespace lagrange
