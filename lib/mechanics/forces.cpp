// SPDX-License-Identifier: GPL-2.0-or-later
/** @file forces.cpp
 *  Rayleigh dissipation, dampers and applied forces as generalized forces. */
#include "mechanics/forces.h"

#include "algebra/calculus.h"
#include "algebra/sign.h"
#include "algebra/sorted_terms.h"
#include "core/errors.h"
#include "mechanics/equilibrium.h"

namespace lagrange {

namespace {

/// A rational expression with its numerator and denominator in canonical trig form.
GiNaC::ex canonical_ratio(const GiNaC::ex& e, const simplifier& simplify)
{
    // numer_denom() gives both parts of one normal form; numer() and denom() separately
    // may each pick another sign.
    GiNaC::ex fraction = e.numer_denom();
    GiNaC::ex numerator = simplify.canonical(fraction.op(0));
    GiNaC::ex denominator = simplify.canonical(fraction.op(1));
    return (numerator / denominator).normal();
}

} // namespace

GiNaC::exmap at_rest(const model& scene)
{
    GiNaC::exmap rest;
    for (const coordinate& c : scene.coordinates)
        rest[c.velocity] = 0;
    for (const input_signal& u : scene.inputs)
        rest[u.symbol] = 0;
    return rest;
}

GiNaC::ex damper_rayleigh(const model& scene, const damper& d, const simplifier& simplify)
{
    // d/dt |d| = (d·ḋ)/|d|, so ½ b (d/dt |d|)² = ½ b (d·ḋ)²/(d·d): no square root.
    GiNaC::ex along = 0, length2 = 0;
    for (std::size_t k = 0; k < 3; ++k) {
        GiNaC::ex separation = d.end_a[k] - d.end_b[k];
        along += separation * time_derivative(separation, scene);
        length2 += separation * separation;
    }
    GiNaC::ex numerator = simplify.canonical(GiNaC::pow(along, 2));
    GiNaC::ex denominator = simplify.canonical(length2);
    return (d.coefficient * numerator / (2 * denominator)).normal();
}

void require_forces_vanish_at_rest(const model& scene, const simplifier& simplify)
{
    if (scene.forces.empty() && scene.point_forces.empty())
        return;
    generalized_forces q = derive_generalized_forces(scene, simplify);
    const GiNaC::exmap rest = at_rest(scene);
    // A named static equilibrium: force_stiffness checks the forces there.
    if (scene.equilibrium && !scene.steady && scene.constraints.empty())
        return;
    for (std::size_t j = 0; j < scene.coordinates.size(); ++j)
        if (!canonical_ratio(q.applied[j].subs(rest), simplify).is_zero())
            throw computation_error("the applied force on `" + scene.coordinates[j].name +
                                    "` does not vanish at rest (with the inputs at 0), so an equilibrium of V "
                                    "is not one of the motion: small oscillations are not computed" +
                                    std::string(scene.constraints.empty() && !scene.steady
                                                    ? " (name a point where it vanishes with an `equilibrium` line)"
                                                    : ""));
}

GiNaC::matrix force_stiffness(const model& scene, const std::vector<GiNaC::ex>& at, const simplifier& simplify)
{
    const unsigned n = static_cast<unsigned>(scene.coordinates.size());
    GiNaC::matrix stiffness(n, n);
    if (scene.forces.empty() && scene.point_forces.empty())
        return stiffness; // dissipation alone has no stiffness at rest
    const generalized_forces q = derive_generalized_forces(scene, simplify);
    const GiNaC::exmap rest = at_rest(scene);
    for (unsigned i = 0; i < n; ++i) {
        const GiNaC::ex at_rest = q.total[i].subs(rest);
        const GiNaC::ex residual = tidy(evaluate_at(at_rest, scene, at));
        if (!vanishes(residual))
            throw computation_error("the applied force on `" + scene.coordinates[i].name + "` is " +
                                    message_text(residual) +
                                    " at the equilibrium (at rest, inputs 0), not 0: the point is not an "
                                    "equilibrium of the motion, so small oscillations about it are not computed");
        for (unsigned j = 0; j < n; ++j) {
            const GiNaC::ex entry =
                tidy(evaluate_at(-differentiate(at_rest, scene.coordinates[j].position), scene, at));
            if (entry.has(scene.time))
                throw computation_error("the stiffness of the force on `" + scene.coordinates[i].name +
                                        "` at the equilibrium changes with time: no small oscillations");
            stiffness(i, j) = entry;
        }
    }
    return stiffness;
}

generalized_forces derive_generalized_forces(const model& scene, const simplifier& simplify)
{
    generalized_forces q;
    const std::size_t n = scene.coordinates.size();
    q.rayleigh = scene.dissipation;
    for (const damper& d : scene.dampers)
        q.rayleigh += damper_rayleigh(scene, d, simplify);
    q.applied.assign(n, 0);
    for (const generalized_force& f : scene.forces)
        q.applied[f.coordinate] += f.value;
    for (const point_force& f : scene.point_forces)
        for (std::size_t j = 0; j < n; ++j)
            for (std::size_t k = 0; k < 3; ++k)
                q.applied[j] += f.force[k] * differentiate(f.position[k], scene.coordinates[j].position);
    for (std::size_t j = 0; j < n; ++j) {
        q.dissipative.push_back(canonical_ratio(-differentiate(q.rayleigh, scene.coordinates[j].velocity), simplify));
        q.applied[j] = canonical_ratio(q.applied[j], simplify);
        q.total.push_back((q.dissipative[j] + q.applied[j]).normal());
        q.any = q.any || !q.total[j].is_zero();
    }
    return q;
}

} // namespace lagrange
