// SPDX-License-Identifier: GPL-2.0-or-later
/** @file products.cpp
 *  The default products: the by_default column of core/products.inc. */
#include "engine/products.h"

#include "mechanics/time_dependence.h"

namespace lagrange {

namespace {

// The predicates that products.inc names, one per kind of scene.
bool with_coordinates(const model& scene) { return !scene.coordinates.empty(); }
/// Static equilibria and their modes: not for a scene whose `equilibrium` line names a
/// steady rate (that motion is studied on the reduced system).
bool with_static_point(const model& scene) { return with_coordinates(scene) && !scene.steady; }
bool with_steady_motion(const model& scene) { return with_coordinates(scene) && scene.steady; }
bool with_limit(const model& scene) { return with_coordinates(scene) && scene.limit; }
bool with_values(const model& scene) { return with_coordinates(scene) && !scene.values.empty(); }
bool with_time_and_values(const model& scene) { return with_values(scene) && mentions_time(scene); }
bool with_generalized_forces(const model& scene) { return with_coordinates(scene) && scene.has_generalized_forces(); }
bool with_inputs(const model& scene) { return with_coordinates(scene) && !scene.inputs.empty(); }
bool with_critical(const model& scene) { return with_static_point(scene) && scene.critical; }
bool with_constraints(const model& scene) { return with_coordinates(scene) && !scene.constraints.empty(); }
/// An input, a `linearize about` line that names the operating point, or a steady motion
/// with constraints (the operating point of its state space).
bool with_inputs_or_operating_point(const model& scene)
{
    return with_inputs(scene) ||
           (with_coordinates(scene) && (scene.operating_point || (scene.steady && !scene.constraints.empty())));
}
bool with_simulate_line(const model& scene) { return with_coordinates(scene) && scene.simulation; }
bool with_bodies(const model& scene) { return !scene.bodies.empty(); }
bool with_free_body(const model& scene)
{
    for (const rigid_body& b : scene.bodies)
        if (b.omega)
            return true;
    return false;
}
bool never(const model&) { return false; }

} // namespace

std::set<product> default_products(const model& scene)
{
    std::set<product> products;
#define LAGRANGE_PRODUCT(id, name, scope, by_default)                                                         \
    if (by_default(scene))                                                                                    \
        products.insert(product::id);
#include "core/products.inc"
#undef LAGRANGE_PRODUCT
    return products;
}

} // namespace lagrange
