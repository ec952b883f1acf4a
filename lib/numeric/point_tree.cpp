// SPDX-License-Identifier: GPL-2.0-or-later
/** @file point_tree.cpp
 *  The articulated-body recursion of a tree of point masses (see point_tree.h). Written
 *  here: the multibody libraries (Pinocchio, RBDL) run the recursion on numbers, where the
 *  engine needs its steps as expressions to compile with everything else. */
#include "numeric/point_tree.h"

#include "algebra/calculus.h"
#include "mechanics/lagrangian.h"

#include <algorithm>
#include <map>
#include <string>

namespace lagrange {

namespace {

using vector = std::vector<GiNaC::ex>;

/// A position as a constant plus one displacement per coordinate it moves with; nothing
/// when a term moves with t or with two coordinates at once.
std::optional<std::map<std::size_t, vector>> displacements(const vector& position, const model& scene)
{
    std::map<std::size_t, vector> moves;
    for (std::size_t c = 0; c < position.size(); ++c) {
        const GiNaC::ex e = position[c].expand();
        const vector terms = GiNaC::is_a<GiNaC::add>(e) ? vector(e.begin(), e.end()) : vector{e};
        for (const GiNaC::ex& term : terms) {
            if (term.has(scene.time))
                return std::nullopt;
            std::optional<std::size_t> coordinate;
            for (std::size_t j = 0; j < scene.coordinates.size(); ++j) {
                if (term.has(scene.coordinates[j].velocity))
                    return std::nullopt;
                if (!term.has(scene.coordinates[j].position))
                    continue;
                if (coordinate)
                    return std::nullopt;
                coordinate = j;
            }
            if (!coordinate)
                continue;
            vector& d = moves[*coordinate];
            d.resize(position.size(), 0);
            d[c] += term;
        }
    }
    return moves;
}

/// The recursion's steps as definitions: a value that is a number or a symbol stays inline.
class steps {
public:
    GiNaC::ex define(const GiNaC::ex& value)
    {
        if (GiNaC::is_a<GiNaC::numeric>(value) || GiNaC::is_a<GiNaC::symbol>(value))
            return value;
        GiNaC::realsymbol s("$" + std::to_string(definitions.size()));
        definitions.push_back({s, value});
        return s;
    }
    vector define(const vector& values)
    {
        vector out;
        for (const GiNaC::ex& v : values)
            out.push_back(define(v));
        return out;
    }
    std::vector<program_definition> definitions;
};

GiNaC::ex dot(const vector& a, const vector& b)
{
    GiNaC::ex s = 0;
    for (std::size_t c = 0; c < a.size(); ++c)
        s += a[c] * b[c];
    return s;
}

} // namespace

std::optional<point_tree_recursion> point_tree_accelerations(const model& scene, const equations_of_motion& equations,
                                                              const std::function<GiNaC::ex(const GiNaC::ex&)>& at)
{
    const std::size_t n = scene.coordinates.size();
    if (n == 0 || scene.points.empty() || !scene.bodies.empty() || !scene.kinetic_terms.is_zero() ||
        scene.lagrangian_terms || !scene.constraints.empty() || !scene.contacts.empty())
        return std::nullopt;
    for (const coordinate& c : scene.coordinates)
        if (scene.potential_terms.has(c.velocity))
            return std::nullopt;

    // Each coordinate's displacement, the same in every point that moves with it, and each
    // point's coordinates.
    const std::size_t dimension = scene.points.front().position.size();
    std::vector<std::optional<vector>> displacement(n);
    std::vector<std::vector<std::size_t>> moved_by;
    GiNaC::ex gravity = 0; // the points' part of V, which the root's acceleration stands for
    for (const point_mass& p : scene.points) {
        const auto moves = displacements(p.position, scene);
        if (!moves || p.position.size() != dimension)
            return std::nullopt;
        std::vector<std::size_t> set;
        for (const auto& [j, d] : *moves) {
            if (!displacement[j])
                displacement[j] = d;
            for (std::size_t c = 0; c < dimension; ++c)
                if (!(d[c] - (*displacement[j])[c]).expand().is_zero())
                    return std::nullopt;
            set.push_back(j);
        }
        moved_by.push_back(set);
        gravity += gravity_potential(scene, p.mass, p.position);
    }

    // The tree: the path of coordinate j is what every point moving with j moves with; its
    // parent is the coordinate whose path is that path less j.
    std::vector<std::optional<std::vector<std::size_t>>> path(n);
    for (const std::vector<std::size_t>& set : moved_by)
        for (std::size_t j : set) {
            if (!path[j]) {
                path[j] = set;
                continue;
            }
            std::vector<std::size_t> common;
            std::set_intersection(path[j]->begin(), path[j]->end(), set.begin(), set.end(), std::back_inserter(common));
            path[j] = common;
        }
    std::vector<std::optional<std::size_t>> parent(n);
    for (std::size_t j = 0; j < n; ++j) {
        if (!path[j])
            return std::nullopt; // a coordinate that moves no point
        std::vector<std::size_t> ancestors;
        std::copy_if(path[j]->begin(), path[j]->end(), std::back_inserter(ancestors),
                     [&](std::size_t a) { return a != j; });
        if (ancestors.empty())
            continue;
        for (std::size_t a : ancestors)
            if (*path[a] == ancestors)
                parent[j] = a;
        if (!parent[j])
            return std::nullopt;
    }
    // Each point hangs at the deepest coordinate it moves with, and moves with its path.
    std::vector<GiNaC::ex> node_mass(n, 0);
    for (std::size_t k = 0; k < scene.points.size(); ++k) {
        const std::vector<std::size_t>& set = moved_by[k];
        if (set.empty())
            continue; // a fixed point
        const std::size_t deepest = *std::max_element(
            set.begin(), set.end(), [&](std::size_t a, std::size_t b) { return path[a]->size() < path[b]->size(); });
        if (*path[deepest] != set)
            return std::nullopt;
        node_mass[deepest] += at(scene.points[k].mass);
    }
    for (GiNaC::ex& m : node_mass)
        if (GiNaC::is_a<GiNaC::numeric>(m) && !(GiNaC::ex_to<GiNaC::numeric>(m).is_positive()))
            return std::nullopt;

    // Outward order: by depth, then by the scene's order.
    std::vector<std::size_t> order(n);
    for (std::size_t j = 0; j < n; ++j)
        order[j] = j;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return path[a]->size() < path[b]->size(); });
    std::vector<bool> has_children(n, false);
    for (std::size_t j = 0; j < n; ++j)
        if (parent[j])
            has_children[*parent[j]] = true;

    const GiNaC::ex rest_of_potential = (equations.potential - gravity).expand();
    steps recursion;
    std::vector<vector> axis(n), bias_acceleration(n), u_vector(n);
    std::vector<GiNaC::ex> force(n), inverse_pivot(n);
    std::vector<std::vector<vector>> inertia(n, std::vector<vector>(dimension, vector(dimension, 0)));
    std::vector<vector> bias(n, vector(dimension, 0));
    for (std::size_t j = 0; j < n; ++j) {
        const coordinate& c = scene.coordinates[j];
        vector s, a;
        for (const GiNaC::ex& d : *displacement[j]) {
            const GiNaC::ex derivative = differentiate(at(d), c.position);
            s.push_back(derivative);
            a.push_back(differentiate(derivative, c.position) * GiNaC::pow(c.velocity, 2));
        }
        axis[j] = recursion.define(s);
        bias_acceleration[j] = recursion.define(a);
        for (std::size_t r = 0; r < dimension; ++r)
            inertia[j][r][r] = node_mass[j];
        force[j] = at(equations.forces.total[j] - differentiate(rest_of_potential, c.position));
    }

    // Inwards: each node's articulated inertia and bias, passed to its parent.
    std::vector<GiNaC::ex> rest_force(n);
    for (auto it = order.rbegin(); it != order.rend(); ++it) {
        const std::size_t j = *it;
        std::vector<vector>& inertia_j = inertia[j];
        for (std::size_t r = 0; r < dimension; ++r)
            for (std::size_t k = r; k < dimension; ++k)
                inertia_j[r][k] = inertia_j[k][r] = recursion.define(inertia_j[r][k]);
        const vector p = recursion.define(bias[j]);
        vector u(dimension);
        for (std::size_t r = 0; r < dimension; ++r)
            u[r] = dot(inertia_j[r], axis[j]);
        u_vector[j] = recursion.define(u);
        inverse_pivot[j] = recursion.define(1 / recursion.define(dot(axis[j], u_vector[j])));
        rest_force[j] = recursion.define(force[j] - dot(axis[j], p));
        if (!parent[j])
            continue;
        // I − U Uᵀ/D and p + (I − U Uᵀ/D) c + U u/D, added to the parent's.
        const GiNaC::ex weight = recursion.define(rest_force[j] * inverse_pivot[j]);
        std::vector<vector> articulated(dimension, vector(dimension));
        for (std::size_t r = 0; r < dimension; ++r)
            for (std::size_t k = r; k < dimension; ++k)
                articulated[r][k] = articulated[k][r] =
                    recursion.define(inertia_j[r][k] - u_vector[j][r] * u_vector[j][k] * inverse_pivot[j]);
        std::vector<vector>& inertia_parent = inertia[*parent[j]];
        vector& bias_parent = bias[*parent[j]];
        for (std::size_t r = 0; r < dimension; ++r) {
            for (std::size_t k = 0; k < dimension; ++k)
                inertia_parent[r][k] += articulated[r][k];
            bias_parent[r] += p[r] + dot(articulated[r], bias_acceleration[j]) + u_vector[j][r] * weight;
        }
    }

    // Outwards: the accelerations, with gravity as the root's acceleration −g.
    vector root(dimension, 0);
    if (scene.gravity)
        for (std::size_t r = 0; r < dimension; ++r)
            root[r] = -at(scene.gravity->strength * scene.gravity->direction[r]);
    std::vector<vector> acceleration(n);
    point_tree_recursion result;
    result.accelerations.resize(n);
    for (std::size_t j : order) {
        const vector& base = parent[j] ? acceleration[*parent[j]] : root;
        vector before(dimension);
        for (std::size_t r = 0; r < dimension; ++r)
            before[r] = base[r] + bias_acceleration[j][r];
        before = recursion.define(before);
        const GiNaC::ex q2 = recursion.define((rest_force[j] - dot(u_vector[j], before)) * inverse_pivot[j]);
        result.accelerations[j] = q2;
        if (!has_children[j])
            continue;
        acceleration[j].resize(dimension);
        for (std::size_t r = 0; r < dimension; ++r)
            acceleration[j][r] = before[r] + axis[j][r] * q2;
        acceleration[j] = recursion.define(acceleration[j]);
    }
    result.definitions = std::move(recursion.definitions);
    return result;
}

} // namespace lagrange
