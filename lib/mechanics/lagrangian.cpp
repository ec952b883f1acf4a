/** @file lagrangian.cpp
 *  L = T − V and the Euler–Lagrange equations. */
#include "mechanics/lagrangian.h"

#include "scene/lower.h"

namespace lagrange {

simplifier make_simplifier(const model& scene)
{
    simplifier s;
    s.angles = scene.positions();
    for (const GiNaC::ex& a : scene.accelerations())
        s.variables.append(a);
    for (const GiNaC::ex& v : scene.velocities())
        s.variables.append(v);
    s.rules = embedded_rules();
    s.rules.insert(s.rules.end(), scene.rules.begin(), scene.rules.end());
    return s;
}

GiNaC::ex time_derivative(const GiNaC::ex& e, const model& scene)
{
    GiNaC::ex result = e.diff(scene.time);
    for (const coordinate& c : scene.coordinates) {
        result += e.diff(c.position) * c.velocity;
        result += e.diff(c.velocity) * c.acceleration;
    }
    return result;
}

namespace {

GiNaC::ex squared_length(const std::vector<GiNaC::ex>& v)
{
    GiNaC::ex sum = 0;
    for (const GiNaC::ex& component : v)
        sum += component * component;
    return sum;
}

/// Splits L by its degree in the velocities: L = L2 + L1 + L0, T = L2, V = −L0.
void split_by_velocity_degree(const model& scene, lagrangian_result& result)
{
    GiNaC::symbol scale("scale");
    GiNaC::exmap scaled;
    for (const coordinate& c : scene.coordinates)
        scaled[c.velocity] = scale * c.velocity;
    GiNaC::ex l = result.lagrangian.subs(scaled).expand();
    if (!l.is_polynomial(scale) || l.degree(scale) > 2) {
        result.split = false;
        return;
    }
    result.kinetic = l.coeff(scale, 2);
    result.gyroscopic = l.coeff(scale, 1);
    result.potential = -l.coeff(scale, 0);
}

} // namespace

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
        if (scene.gravity) {
            GiNaC::ex height_along = 0;
            for (std::size_t k = 0; k < 3; ++k)
                height_along += scene.gravity->direction[k] * p.position[k];
            potential -= p.mass * scene.gravity->strength * height_along;
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
    result.potential_built = potential;
    result.gyroscopic = 0;
    if (scene.lagrangian_terms) {
        result.lagrangian = simplify(*scene.lagrangian_terms + kinetic - potential);
        split_by_velocity_degree(scene, result);
        if (result.split) {
            result.kinetic = simplify(result.kinetic);
            result.gyroscopic = simplify(result.gyroscopic);
            result.potential = simplify(result.potential);
        }
        return result;
    }
    result.kinetic = simplify(kinetic);
    result.potential = simplify(potential);
    result.lagrangian = simplify(kinetic - potential);
    return result;
}

std::vector<GiNaC::ex> derive_equations(const model& scene, const lagrangian_result& lagrangian,
                                        const simplifier& simplify)
{
    std::vector<GiNaC::ex> equations;
    const GiNaC::ex& l = lagrangian.lagrangian;
    for (const coordinate& c : scene.coordinates) {
        GiNaC::ex momentum = l.diff(c.velocity);
        equations.push_back(simplify(time_derivative(momentum, scene) - l.diff(c.position)));
    }
    return equations;
}

} // namespace lagrange
