// SPDX-License-Identifier: GPL-2.0-or-later
/** @file lagrangian.cpp
 *  L = T − V and the Euler–Lagrange equations. */
#include "mechanics/lagrangian.h"

#include "mechanics/harmonic_lagrangian.h"
#include "mechanics/time_dependence.h"
#include "bodies/inertia.h"
#include "bodies/orientation.h"

#include <map>
#include <memory>
#include <optional>

namespace lagrange {



namespace {

GiNaC::ex squared_length(const std::vector<GiNaC::ex>& v)
{
    GiNaC::ex sum = 0;
    for (const GiNaC::ex& component : v)
        sum += component * component;
    return sum;
}

/// Splits L by its degree in the velocities: L = L2 + L1 + L0, T = L2, V = −L0 (the
/// effective potential U: V minus the velocity-free part of T, such as a rotating frame's
/// centrifugal term).
void split_by_velocity_degree(const model& scene, lagrangian_result& result)
{
    GiNaC::symbol scale("scale");
    GiNaC::exmap scaled;
    for (const coordinate& c : scene.coordinates)
        scaled[c.velocity] = scale * c.velocity;
    GiNaC::ex l = result.lagrangian_canonical.subs(scaled).expand();
    if (!l.is_polynomial(scale) || l.degree(scale) > 2) {
        result.split = false;
        return;
    }
    result.kinetic = l.coeff(scale, 2);
    result.gyroscopic = l.coeff(scale, 1);
    result.potential = -l.coeff(scale, 0);
}

/// Whether T is a quadratic form in the velocities and V free of them, as built from
/// the scene: no position or orientation moves with t, the `T` lines are homogeneous of
/// degree 2 in the velocities and the `V` lines hold none. Otherwise L is split by degree.
bool kinetic_is_quadratic_form(const model& scene)
{
    auto moves = [&](const std::vector<GiNaC::ex>& position) {
        for (const GiNaC::ex& x : position)
            if (x.has(scene.time))
                return true;
        return false;
    };
    for (const point_mass& p : scene.points)
        if (moves(p.position))
            return false;
    for (const rigid_body& b : scene.bodies)
        if ((b.position && moves(*b.position)) || (b.orientation && moves(*b.orientation)))
            return false;
    for (const coordinate& c : scene.coordinates)
        if (scene.potential_terms.has(c.velocity))
            return false;
    if (scene.kinetic_terms.is_zero())
        return true;
    GiNaC::symbol scale("scale");
    GiNaC::exmap scaled;
    for (const coordinate& c : scene.coordinates)
        scaled[c.velocity] = scale * c.velocity;
    GiNaC::ex t = scene.kinetic_terms.subs(scaled).expand();
    return t.is_polynomial(scale) && t.degree(scale) == 2 && t.ldegree(scale) == 2;
}

} // namespace

GiNaC::ex gravity_potential(const model& scene, const GiNaC::ex& mass, const std::vector<GiNaC::ex>& position)
{
    if (!scene.gravity)
        return 0;
    GiNaC::ex height_along = 0;
    for (std::size_t k = 0; k < 3; ++k)
        height_along += scene.gravity->direction[k] * position[k];
    return -mass * scene.gravity->strength * height_along;
}

lagrangian_result derive_lagrangian(const model& scene, const simplifier& simplify)
{
    lagrangian_result result;
    GiNaC::ex kinetic = scene.kinetic_terms;
    GiNaC::ex potential = scene.potential_terms;
    for (const point_mass& p : scene.points) {
        std::vector<GiNaC::ex> velocity;
        for (const GiNaC::ex& x : p.position)
            velocity.push_back(time_derivative(x, scene));
        kinetic += GiNaC::numeric(1, 2) * p.mass * squared_length(velocity);
        potential += gravity_potential(scene, p.mass, p.position);
    }
    // Rigid bodies placed in the coordinates: ½ M v² of the centre of mass, ½ ωᵀ I ω with
    // ω from the rates of the rotation sequence (bodies/orientation.cpp), and gravity on the
    // centre. The reference T replaces ½ ωᵀ I ω by ½ tr(Ṙ J Ṙᵀ), which does not use ω.
    GiNaC::ex kinetic_reference = 0;
    for (const rigid_body& b : scene.bodies) {
        if (b.omega || (!b.position && !b.orientation))
            continue;
        const inertia_result inertia = derive_inertia(b);
        if (b.position) {
            std::vector<GiNaC::ex> velocity;
            for (const GiNaC::ex& x : *b.position)
                velocity.push_back(time_derivative(x, scene));
            kinetic += GiNaC::numeric(1, 2) * inertia.mass * squared_length(velocity);
            potential += gravity_potential(scene, inertia.mass, *b.position);
        }
        if (b.orientation) {
            const std::vector<GiNaC::ex>& angles = *b.orientation;
            // z-x-z Euler angles keep the axial vector of Rᵀ Ṙ, the form their results were
            // first computed in; other sequences sum the rates about each axis.
            std::vector<GiNaC::ex> omega =
                b.rotation_axes == std::vector<char>{'z', 'x', 'z'}
                    ? body_angular_velocity(euler_rotation(angles[0], angles[1], angles[2]), scene)
                    : sequence_angular_velocity(b.rotation_axes, angles, scene);
            for (GiNaC::ex& w : omega)
                w = simplify.canonical(w);
            GiNaC::ex rotational = 0;
            for (unsigned i = 0; i < 3; ++i)
                for (unsigned j = 0; j < 3; ++j)
                    rotational += GiNaC::numeric(1, 2) * omega[i] * inertia.tensor(i, j) * omega[j];
            kinetic += rotational;
            kinetic_reference += rotational_energy_from_rate(rotation_sequence(b.rotation_axes, angles),
                                                             inertia.tensor, scene) - rotational;
        }
    }
    for (const spring& s : scene.springs) {
        std::vector<GiNaC::ex> difference;
        for (std::size_t k = 0; k < 3; ++k)
            difference.push_back(s.end_a[k] - s.end_b[k]);
        GiNaC::ex length2 = squared_length(difference);
        if (s.rest_length.is_zero()) {
            potential += GiNaC::numeric(1, 2) * s.stiffness * length2;
        } else {
            GiNaC::ex length = GiNaC::sqrt(simplify(length2));
            potential += GiNaC::numeric(1, 2) * s.stiffness * GiNaC::pow(length - s.rest_length, 2);
        }
    }
    result.kinetic_built = kinetic;
    result.kinetic_reference = kinetic + kinetic_reference;
    result.potential_built = potential;
    result.gyroscopic = 0;
    // With explicit time (a moving support, a turning frame) the velocity-free part of
    // T belongs to V as well (the hoop's centrifugal term): split L as for an `L` line.
    if (scene.lagrangian_terms || !kinetic_is_quadratic_form(scene) || mentions_time(scene)) {
        result.lagrangian_canonical =
            simplify.canonical(scene.lagrangian_terms.value_or(GiNaC::ex(0)) + kinetic - potential);
        result.lagrangian = simplify.compact(result.lagrangian_canonical);
        split_by_velocity_degree(scene, result);
        if (result.split) {
            result.kinetic = simplify.compact(result.kinetic);
            result.gyroscopic = simplify.compact(result.gyroscopic);
            result.potential = simplify.compact(result.potential);
        }
        return result;
    }
    if (all_symbols(simplify.angles)) {
        auto h = std::make_shared<harmonic_lagrangian>(scene, simplify.angles);
        if (h->space.add_symbols_of(kinetic) && h->space.add_symbols_of(potential)) {
            std::optional<harmonic_polynomial> kinetic_harmonic = to_harmonic(kinetic, h->space);
            std::optional<harmonic_polynomial> potential_harmonic = to_harmonic(potential, h->space);
            if (kinetic_harmonic && potential_harmonic) {
                // What trig_canonical and compact give for T and V, without GiNaC's expansion.
                h->lagrangian = *kinetic_harmonic;
                h->lagrangian -= *potential_harmonic;
                result.lagrangian_canonical = to_ex(h->lagrangian);
                const std::vector<GiNaC::ex> compact = simplify.compact({*kinetic_harmonic, *potential_harmonic});
                result.kinetic = compact[0];
                result.potential = compact[1];
                result.lagrangian = result.kinetic - result.potential;
                result.harmonic = std::move(h);
                return result;
            }
        }
    }
    GiNaC::ex kinetic_canonical = simplify.canonical(kinetic);
    GiNaC::ex potential_canonical = simplify.canonical(potential);
    result.lagrangian_canonical = kinetic_canonical - potential_canonical;
    result.kinetic = simplify.compact(kinetic_canonical);
    result.potential = simplify.compact(potential_canonical);
    // T's terms are quadratic in the velocities and V's free of them: no rule or
    // grouping joins the two, so the compact L is the compact T minus the compact V.
    result.lagrangian = result.kinetic - result.potential;
    return result;
}

} // namespace lagrange
