// SPDX-License-Identifier: GPL-2.0-or-later
/** @file state_space.cpp
 *  A, B and the transfer functions of the linearized system. */
#include "mechanics/state_space.h"

#include "algebra/calculus.h"
#include "algebra/exact_matrix.h"
#include "algebra/factor.h"
#include "algebra/sign.h"
#include "core/errors.h"
#include "core/names.h"
#include "mechanics/equilibrium.h"
#include "mechanics/forces.h"

#include <string>

namespace lagrange {

namespace {

using GiNaC::ex;

/// The polynomial `e` in s with every coefficient factored where that is quick.
ex collected(const ex& e, const GiNaC::symbol& s)
{
    const ex expanded = e.expand();
    ex result = 0;
    for (int k = expanded.ldegree(s); k <= expanded.degree(s); ++k)
        result += factor_if_quick(expanded.coeff(s, k)) * GiNaC::pow(s, k);
    return result;
}

/// numerator/denominator with common factors cancelled, the denominator's coefficients'
/// greatest common divisor moved into the numerator and its leading coefficient positive.
std::pair<ex, ex> primitive_ratio(const ex& numerator, const ex& denominator, const GiNaC::symbol& s)
{
    ex fraction = (numerator / denominator).normal().numer_denom();
    ex top = fraction.op(0).expand(), bottom = fraction.op(1).expand();
    ex content = 0;
    for (int k = 0; k <= bottom.degree(s); ++k) {
        const ex c = bottom.coeff(s, k).expand();
        if (!c.is_zero())
            content = content.is_zero() ? c : GiNaC::gcd(content, c);
    }
    const ex leading = bottom.coeff(s, bottom.degree(s));
    if (std::optional<int> sign = sign_of((leading / content).normal()); sign && *sign < 0)
        content = -content;
    if (!content.is_zero() && content != 1) {
        top = (top / content).normal();
        bottom = (bottom / content).normal();
    }
    // What is left of the content in the numerator's denominator goes back below.
    const ex top_parts = top.numer_denom();
    return {collected(top_parts.op(0), s), collected((bottom * top_parts.op(1)).expand(), s)};
}

/// H(s) = minor/determinant of one input and coordinate, made primitive (0 where the minor is).
transfer_function transfer_entry(std::size_t input, unsigned coordinate, const ex& minor, const ex& determinant,
                                 const GiNaC::symbol& s)
{
    transfer_function h;
    h.input = input;
    h.coordinate = coordinate;
    if (minor.is_zero()) {
        h.numerator = 0;
        h.denominator = 1;
    } else {
        std::tie(h.numerator, h.denominator) = primitive_ratio(minor, determinant, s);
    }
    return h;
}

} // namespace

GiNaC::matrix input_matrix(const model& scene, const std::vector<ex>& at, const simplifier& simplify)
{
    const unsigned n = static_cast<unsigned>(scene.coordinates.size());
    const unsigned m = static_cast<unsigned>(scene.inputs.size());
    GiNaC::matrix result(n, m);
    if (m == 0)
        return result;
    const generalized_forces forces = derive_generalized_forces(scene, simplify);
    const GiNaC::exmap rest = at_rest(scene);
    for (unsigned i = 0; i < n; ++i)
        for (unsigned j = 0; j < m; ++j) {
            const ex rate = differentiate(forces.total[i], scene.inputs[j].symbol).subs(rest);
            const ex entry = tidy(evaluate_at(rate, scene, at));
            if (entry.has(scene.time))
                throw computation_error("the force of input `" + scene.inputs[j].name + "` on `" +
                                        scene.coordinates[i].name +
                                        "` at the equilibrium changes with time: no linear time-invariant system");
            result(i, j) = entry;
        }
    return result;
}

state_space_result derive_state_space(const model& scene, const linearization_result& linear,
                                      const GiNaC::matrix& damping, const simplifier& simplify, bool allow_no_inputs)
{
    if (scene.inputs.empty() && !allow_no_inputs)
        throw computation_error("`state_space` and `transfer` need an input: declare one with `input u` and let it "
                                "act through a force (`force q = u`, `force on P (u, 0)`)");
    const unsigned n = static_cast<unsigned>(scene.coordinates.size());
    const unsigned m = static_cast<unsigned>(scene.inputs.size());
    state_space_result result;
    for (const coordinate& c : scene.coordinates)
        result.state.push_back(c.position);
    for (const coordinate& c : scene.coordinates)
        result.state.push_back(c.velocity);
    for (const input_signal& u : scene.inputs)
        result.inputs.push_back(u.symbol);
    result.damping = damping;
    result.input_matrix = input_matrix(scene, linear.at, simplify);
    GiNaC::matrix inverse_mass;
    try {
        inverse_mass = linear.kinetic.inverse();
    } catch (const std::exception&) {
        throw computation_error("the kinetic matrix at the equilibrium cannot be inverted");
    }
    const GiNaC::matrix stiffness = inverse_mass.mul(linear.potential);
    const GiNaC::matrix velocity = inverse_mass.mul(linear.gyroscopic.sub(damping));
    const GiNaC::matrix forcing = inverse_mass.mul(result.input_matrix);
    result.a = GiNaC::matrix(2 * n, 2 * n);
    result.b = GiNaC::matrix(2 * n, m);
    for (unsigned i = 0; i < n; ++i) {
        result.a(i, n + i) = 1;
        for (unsigned j = 0; j < n; ++j) {
            result.a(n + i, j) = tidy(-stiffness(i, j));
            result.a(n + i, n + j) = tidy(velocity(i, j));
        }
        for (unsigned j = 0; j < m; ++j)
            result.b(n + i, j) = tidy(forcing(i, j));
    }
    return result;
}

transfer_result transfer_functions(const model& scene, const linearization_result& linear,
                                   const state_space_result& system)
{
    const unsigned n = static_cast<unsigned>(scene.coordinates.size());
    transfer_result result{GiNaC::possymbol(unused_name(scene, "s")), {}};
    const GiNaC::symbol& s = result.s;
    // P(s) = s²M + s(C − G) + K.
    GiNaC::matrix pencil(n, n);
    for (unsigned i = 0; i < n; ++i)
        for (unsigned j = 0; j < n; ++j)
            pencil(i, j) = s * s * linear.kinetic(i, j) +
                           s * (system.damping(i, j) - linear.gyroscopic(i, j)) + linear.potential(i, j);
    const ex determinant = fraction_free_determinant(pencil).normal();
    if (determinant.is_zero())
        throw computation_error("det(s²M + sC + K) vanishes for every s: no transfer function");
    for (std::size_t input = 0; input < scene.inputs.size(); ++input)
        for (unsigned coordinate = 0; coordinate < n; ++coordinate) {
            GiNaC::matrix replaced = pencil;
            for (unsigned i = 0; i < n; ++i)
                replaced(i, coordinate) = system.input_matrix(i, static_cast<unsigned>(input));
            result.entries.push_back(
                transfer_entry(input, coordinate, fraction_free_determinant(replaced).normal(), determinant, s));
        }
    return result;
}

state_space_result operating_state_space(const model& scene, const operating_linearization& point)
{
    state_space_result result;
    result.state = point.state;
    for (const input_signal& u : scene.inputs)
        result.inputs.push_back(u.symbol);
    result.a = point.a;
    result.b = point.b;
    return result;
}

transfer_result operating_transfer(const model& scene, const operating_linearization& point,
                                   const state_space_result& system)
{
    if (scene.inputs.empty())
        throw computation_error("`transfer` needs an input: declare one with `input u` and let it act through a "
                                "force (`force q = u`, `force on P (u, 0)`)");
    const unsigned size = system.a.rows();
    transfer_result result{GiNaC::possymbol(unused_name(scene, "s")), {}};
    const GiNaC::symbol& s = result.s;
    GiNaC::matrix pencil(size, size); // sI − A
    for (unsigned i = 0; i < size; ++i)
        for (unsigned j = 0; j < size; ++j)
            pencil(i, j) = (i == j ? ex(s) : ex(0)) - system.a(i, j);
    const ex determinant = fraction_free_determinant(pencil).normal();
    if (determinant.is_zero())
        throw computation_error("det(sI − A) vanishes for every s: no transfer function");
    const unsigned free_coordinates = static_cast<unsigned>(point.coordinates.size());
    for (std::size_t input = 0; input < scene.inputs.size(); ++input) {
        std::vector<ex> minors; // X_i(s)·det(sI − A)/U(s) of each independent coordinate
        for (unsigned i = 0; i < free_coordinates; ++i) {
            GiNaC::matrix replaced = pencil;
            for (unsigned r = 0; r < size; ++r)
                replaced(r, i) = system.b(r, static_cast<unsigned>(input));
            minors.push_back(fraction_free_determinant(replaced).normal());
        }
        for (unsigned coordinate = 0; coordinate < scene.coordinates.size(); ++coordinate) {
            ex minor = 0;
            for (unsigned i = 0; i < free_coordinates; ++i)
                minor += point.configuration(coordinate, i) * minors[i];
            result.entries.push_back(transfer_entry(input, coordinate, minor.normal(), determinant, s));
        }
    }
    return result;
}

} // namespace lagrange
