// SPDX-License-Identifier: GPL-2.0-or-later
/** @file equations_of_motion.cpp
 *  The Euler–Lagrange equations: the simplified residuals and the form M q̈ = f. */
#include "mechanics/equations_of_motion.h"

#include "algebra/calculus.h"
#include "mechanics/harmonic_lagrangian.h"

#include <memory>

namespace lagrange {

namespace {

/// True if `e` is a polynomial in sin/cos (of any argument), the coordinates,
/// velocities and time, with coefficients that may divide by parameters only.
bool is_harmonic_polynomial(const GiNaC::ex& e, const model& scene)
{
    auto moves = [&](const GiNaC::ex& x) {
        if (x.has(scene.time))
            return true;
        for (const coordinate& c : scene.coordinates)
            if (x.has(c.position) || x.has(c.velocity) || x.has(c.acceleration))
                return true;
        return false;
    };
    if (GiNaC::is_a<GiNaC::symbol>(e) || GiNaC::is_a<GiNaC::numeric>(e) || GiNaC::is_a<GiNaC::constant>(e))
        return true;
    if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e)) {
        for (const GiNaC::ex& operand : e)
            if (!is_harmonic_polynomial(operand, scene))
                return false;
        return true;
    }
    if (GiNaC::is_a<GiNaC::power>(e)) {
        if (!moves(e))
            return true;
        return e.op(1).info(GiNaC::info_flags::nonnegint) && is_harmonic_polynomial(e.op(0), scene);
    }
    if (GiNaC::is_a<GiNaC::function>(e)) {
        const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
        return !moves(e) || name == "sin" || name == "cos";
    }
    return false;
}

/// Throws when the equation of `c`, expanded in canonical form, has too many terms to print.
void check_printable(const coordinate& c, std::size_t terms)
{
    if (terms > printed_equation_terms)
        throw equations_too_large(
            "the equations of motion are too large to print: the equation of `" + c.name + "` has " +
            std::to_string(terms) + " terms expanded (more than " + std::to_string(printed_equation_terms) +
            "), too large to read; ask for what they are for instead: `state_space` or `critical` (the "
            "equations linearized about a point)");
}

std::size_t term_count(const GiNaC::ex& e) { return GiNaC::is_a<GiNaC::add>(e) ? e.nops() : 1; }

} // namespace

std::vector<GiNaC::ex> derive_equations(const model& scene, const lagrangian_result& lagrangian,
                                        const simplifier& simplify)
{
    std::vector<GiNaC::ex> equations;
    const GiNaC::ex& l = lagrangian.lagrangian_canonical;
    // Derivatives of a polynomial in sines and cosines of single harmonics stay in
    // that form once expanded; anything else goes through the canonical form again.
    std::shared_ptr<const harmonic_lagrangian> harmonic = lagrangian.harmonic;
    if (!harmonic)
        harmonic = harmonic_lagrangian::of(scene, simplify.angles, l);
    if (harmonic && harmonic->is_polynomial_in_motion()) {
        // The same expanded derivatives as below, in harmonic polynomial arithmetic.
        const harmonic_space& space = harmonic->space;
        const harmonic_polynomial& h = harmonic->lagrangian;
        std::vector<harmonic_polynomial> expanded;
        for (const coordinate& c : scene.coordinates) {
            harmonic_polynomial equation =
                h.derivative(*space.index_of(c.velocity)).total_derivative(harmonic->rates, harmonic->time);
            equation -= h.derivative(*space.index_of(c.position));
            check_printable(c, equation.size());
            expanded.push_back(std::move(equation));
        }
        return simplify.compact(expanded);
    }
    bool stays_canonical = is_harmonic_polynomial(l, scene);
    std::vector<GiNaC::ex> canonical_forms;
    for (const coordinate& c : scene.coordinates) {
        GiNaC::ex momentum = differentiate(l, c.velocity);
        GiNaC::ex equation = time_derivative(momentum, scene) - differentiate(l, c.position);
        canonical_forms.push_back(stays_canonical ? equation.expand() : simplify.canonical(equation));
        check_printable(c, term_count(canonical_forms.back()));
    }
    for (const GiNaC::ex& form : canonical_forms)
        equations.push_back(simplify.compact(form));
    return equations;
}

std::optional<acceleration_form> group_by_accelerations(const model& scene, const std::vector<GiNaC::ex>& equations)
{
    const std::size_t n = scene.coordinates.size();
    GiNaC::exmap no_acceleration;
    for (const coordinate& c : scene.coordinates)
        no_acceleration[c.acceleration] = 0;
    acceleration_form form{GiNaC::matrix(static_cast<unsigned>(n), static_cast<unsigned>(n)), {}};
    for (std::size_t i = 0; i < n && i < equations.size(); ++i) {
        for (std::size_t j = 0; j < n; ++j) {
            GiNaC::ex coefficient = equations[i].diff(scene.coordinates[j].acceleration);
            for (const coordinate& c : scene.coordinates)
                if (coefficient.has(c.acceleration))
                    return std::nullopt;
            form.mass(static_cast<unsigned>(i), static_cast<unsigned>(j)) = coefficient;
        }
        form.rest.push_back(equations[i].subs(no_acceleration));
    }
    return form;
}

equations_of_motion derive_equations_of_motion(const model& scene, const lagrangian_result& lagrangian,
                                               const simplifier& simplify, bool printed)
{
    equations_of_motion result;
    const std::size_t n = scene.coordinates.size();
    const GiNaC::ex& l = lagrangian.lagrangian;
    result.lagrangian = l;
    result.mass = GiNaC::matrix(static_cast<unsigned>(n), static_cast<unsigned>(n));
    for (const coordinate& c : scene.coordinates)
        result.momenta.push_back(differentiate(l, c.velocity));
    result.energy = -l;
    result.potential = lagrangian.potential_built;
    result.forces = derive_generalized_forces(scene, simplify);
    for (std::size_t i = 0; i < n; ++i) {
        const GiNaC::ex& p = result.momenta[i];
        for (std::size_t j = 0; j < n; ++j) {
            const auto row = static_cast<unsigned>(i), column = static_cast<unsigned>(j);
            result.mass(row, column) = j < i ? result.mass(column, row) : differentiate(p, scene.coordinates[j].velocity);
        }
        GiNaC::ex f = differentiate(l, scene.coordinates[i].position) - differentiate(p, scene.time);
        for (const coordinate& c : scene.coordinates)
            f -= differentiate(p, c.position) * c.velocity;
        result.forcing.push_back(f + result.forces.total[i]);
        result.energy += scene.coordinates[i].velocity * p;
    }
    if (!scene.constraints.empty())
        result.constraints = derive_constraint_equations(scene);
    if (printed) {
        try {
            result.residuals = derive_equations(scene, lagrangian, simplify);
        } catch (const equations_too_large& error) {
            result.too_large_to_print = error.what();
            return result;
        }
        if (result.forces.any)
            for (std::size_t i = 0; i < n; ++i)
                (*result.residuals)[i] = simplify((*result.residuals)[i] - result.forces.total[i]);
        if (result.constraints)
            for (std::size_t i = 0; i < n; ++i) {
                GiNaC::ex reaction = 0;
                for (std::size_t k = 0; k < scene.constraints.size(); ++k)
                    reaction += result.constraints->matrix(static_cast<unsigned>(k), static_cast<unsigned>(i)) *
                                scene.constraints[k].multiplier;
                (*result.residuals)[i] = simplify((*result.residuals)[i] - reaction);
            }
        result.grouped = group_by_accelerations(scene, *result.residuals);
    }
    return result;
}

} // namespace lagrange
