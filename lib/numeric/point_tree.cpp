// SPDX-License-Identifier: GPL-2.0-or-later
/** @file point_tree.cpp
 *  The articulated-body recursion of a tree of point masses (see point_tree.h). Written
 *  here: the multibody libraries (Pinocchio, RBDL) run the recursion on numbers, where the
 *  engine needs its steps as expressions to compile with everything else. */
#include "numeric/point_tree.h"

#include "algebra/calculus.h"
#include "algebra/rotation.h"
#include "bodies/inertia.h"
#include "bodies/orientation.h"
#include "mechanics/lagrangian.h"

#include <algorithm>
#include <map>
#include <set>
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
    if (n == 0 || (scene.points.empty() && scene.bodies.empty()) || !scene.kinetic_terms.is_zero() ||
        scene.lagrangian_terms || !scene.constraints.empty() || !scene.contacts.empty())
        return std::nullopt;
    for (const coordinate& c : scene.coordinates)
        if (scene.potential_terms.has(c.velocity))
            return std::nullopt;

    // What moves: the points, and each body as its mass at its centre and its rotational
    // energy ½ tr(Ṙ J Ṙᵀ) (bodies/orientation.h), which must move with one coordinate alone.
    struct item {
        GiNaC::ex mass;
        std::map<std::size_t, vector> displacement; ///< by coordinate
        std::vector<std::size_t> set;               ///< the coordinates it moves with
        GiNaC::ex rotational = 0;
        std::vector<std::size_t> turns_with;        ///< the coordinates in `rotational`
    };
    std::vector<item> items;
    GiNaC::ex gravity = 0; // the items' part of V, which the root's acceleration stands for
    auto add = [&](const GiNaC::ex& mass, const vector& position) {
        const auto moves = displacements(position, scene);
        if (!moves || position.size() != 3)
            return false;
        item i{mass, *moves, {}, 0, {}};
        for (const auto& entry : *moves)
            i.set.push_back(entry.first);
        items.push_back(i);
        gravity += gravity_potential(scene, mass, position);
        return true;
    };
    for (const point_mass& p : scene.points)
        if (!add(p.mass, p.position))
            return std::nullopt;
    for (const rigid_body& b : scene.bodies) {
        if (b.omega)
            return std::nullopt;
        if (!b.position && !b.orientation)
            continue;
        const inertia_result inertia = derive_inertia(b);
        if (!add(inertia.mass, b.position ? *b.position : vector(3, 0)))
            return std::nullopt;
        if (!b.orientation)
            continue;
        item& i = items.back();
        i.rotational = at(rotational_energy_from_rate(rotation_sequence(b.rotation_axes, *b.orientation),
                                                     inertia.tensor, scene))
                           .expand();
        for (std::size_t j = 0; j < n; ++j)
            if (i.rotational.has(scene.coordinates[j].position) || i.rotational.has(scene.coordinates[j].velocity))
                i.turns_with.push_back(j);
        std::vector<std::size_t> both;
        std::set_union(i.set.begin(), i.set.end(), i.turns_with.begin(), i.turns_with.end(), std::back_inserter(both));
        i.set = both;
        if (i.rotational.has(scene.time))
            return std::nullopt;
    }

    // The tree: the path of coordinate j is what every item moving with j moves with; its
    // parent is the coordinate whose path is that path less j.
    std::vector<std::optional<std::vector<std::size_t>>> path(n);
    for (const item& i : items)
        for (std::size_t j : i.set) {
            if (!path[j]) {
                path[j] = i.set;
                continue;
            }
            std::vector<std::size_t> common;
            std::set_intersection(path[j]->begin(), path[j]->end(), i.set.begin(), i.set.end(),
                                  std::back_inserter(common));
            path[j] = common;
        }
    std::vector<std::optional<std::size_t>> parent(n);
    for (std::size_t j = 0; j < n; ++j) {
        if (!path[j])
            return std::nullopt; // a coordinate that moves nothing
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

    // Each node's attachments: the distinct displacements of what hangs at it (its items,
    // where an item's node is the deepest coordinate it moves with) and of where each child's
    // subtree hangs on it, which must be one attachment for the whole subtree.
    struct attachment {
        vector displacement;
        GiNaC::ex mass = 0;
        vector axis, bias_acceleration;
        std::vector<vector> inertia;
        vector bias;
    };
    std::vector<std::vector<attachment>> attachments(n);
    std::vector<GiNaC::ex> rotational(n, 0);
    auto attach = [&](std::size_t j, const vector& d) {
        for (std::size_t a = 0; a < attachments[j].size(); ++a) {
            bool same = true;
            for (std::size_t c = 0; c < 3 && same; ++c)
                same = (d[c] - attachments[j][a].displacement[c]).expand().is_zero();
            if (same)
                return a;
        }
        attachments[j].push_back(attachment{d});
        return attachments[j].size() - 1;
    };
    auto displacement_of = [](const item& i, std::size_t j) {
        auto found = i.displacement.find(j);
        return found == i.displacement.end() ? vector(3, 0) : found->second;
    };
    std::vector<std::optional<std::size_t>> hangs_at(n); // the attachment on the parent
    for (const item& i : items) {
        if (i.set.empty())
            continue; // fixed
        const std::size_t node = *std::max_element(i.set.begin(), i.set.end(), [&](std::size_t a, std::size_t b) {
            return path[a]->size() < path[b]->size();
        });
        if (*path[node] != i.set)
            return std::nullopt;
        if (std::any_of(i.turns_with.begin(), i.turns_with.end(), [&](std::size_t j) { return j != node; }))
            return std::nullopt; // turns with another coordinate than the one it hangs at
        attachments[node][attach(node, displacement_of(i, node))].mass += at(i.mass);
        rotational[node] += i.rotational;
        // Along its path, each coordinate's subtree hangs at one attachment of its parent.
        for (std::size_t j : i.set) {
            if (!parent[j])
                continue;
            const std::size_t a = attach(*parent[j], displacement_of(i, *parent[j]));
            if (hangs_at[j] && *hangs_at[j] != a)
                return std::nullopt;
            hangs_at[j] = a;
        }
    }
    // Each node needs mass that it moves, or a rotation, and no mass below zero: then its
    // pivot D ≥ Σ m_a |s_a|² + k is positive wherever M is regular, and not finite where it is
    // singular. A node of massless rods, D = s·(Σ articulated inertia)·s alone, can round to a
    // small number where M is singular.
    for (std::size_t j = 0; j < n; ++j) {
        GiNaC::ex moved = rotational[j];
        for (const attachment& a : attachments[j]) {
            if (GiNaC::is_a<GiNaC::numeric>(a.mass) && GiNaC::ex_to<GiNaC::numeric>(a.mass).is_negative())
                return std::nullopt;
            if (std::any_of(a.displacement.begin(), a.displacement.end(), [](const GiNaC::ex& d) { return !d.is_zero(); }))
                moved += a.mass;
        }
        if (moved.is_zero())
            return std::nullopt;
    }

    // Outward order: by depth, then by the scene's order.
    std::vector<std::size_t> order(n);
    for (std::size_t j = 0; j < n; ++j)
        order[j] = j;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return path[a]->size() < path[b]->size(); });

    const GiNaC::ex rest_of_potential = (equations.potential - gravity).expand();
    steps recursion;
    std::vector<GiNaC::ex> force(n), turning(n); // τ_j, and k of the bodies turning with q_j
    for (std::size_t j = 0; j < n; ++j) {
        const coordinate& c = scene.coordinates[j];
        for (attachment& a : attachments[j]) {
            vector s, b;
            for (const GiNaC::ex& d : a.displacement) {
                const GiNaC::ex derivative = differentiate(at(d), c.position);
                s.push_back(derivative);
                b.push_back(differentiate(derivative, c.position) * GiNaC::pow(c.velocity, 2));
            }
            a.axis = recursion.define(s);
            a.bias_acceleration = recursion.define(b);
            a.inertia.assign(3, vector(3, 0));
            for (std::size_t r = 0; r < 3; ++r)
                a.inertia[r][r] = a.mass;
            a.bias.assign(3, 0);
        }
        // A rotation ½ k(q) q̇² adds k q̈ + ½ k′ q̇² to the coordinate's equation.
        const GiNaC::ex k = rotational[j].diff(c.velocity, 2);
        turning[j] = recursion.define(k);
        force[j] = at(equations.forces.total[j] - differentiate(rest_of_potential, c.position)) -
                   differentiate(k, c.position) * GiNaC::pow(c.velocity, 2) / 2;
    }

    // Inwards: each node's articulated inertia Σ I_a − U Uᵀ/D and bias Σ (I_a c_a + p_a) + U u/D,
    // passed to the attachment its parent carries it at.
    std::vector<vector> u_vector(n);
    std::vector<GiNaC::ex> rest_force(n), inverse_pivot(n);
    for (auto it = order.rbegin(); it != order.rend(); ++it) {
        const std::size_t j = *it;
        vector coupling(3, 0), carried(3, 0);
        std::vector<vector> total(3, vector(3, 0));
        GiNaC::ex pivot = turning[j], rest = force[j];
        for (attachment& a : attachments[j]) {
            for (std::size_t r = 0; r < 3; ++r)
                for (std::size_t k = r; k < 3; ++k)
                    a.inertia[r][k] = a.inertia[k][r] = recursion.define(a.inertia[r][k]);
            a.bias = recursion.define(a.bias);
            vector along(3), load(3);
            for (std::size_t r = 0; r < 3; ++r) {
                along[r] = dot(a.inertia[r], a.axis);
                load[r] = dot(a.inertia[r], a.bias_acceleration) + a.bias[r];
            }
            load = recursion.define(load);
            for (std::size_t r = 0; r < 3; ++r) {
                coupling[r] += along[r];
                carried[r] += load[r];
                for (std::size_t k = 0; k < 3; ++k)
                    total[r][k] += a.inertia[r][k];
            }
            pivot += dot(a.axis, along);
            rest -= dot(a.axis, load);
        }
        u_vector[j] = recursion.define(coupling);
        if (pivot.is_zero()) // displacements whose derivatives cancel: M is singular everywhere
            return std::nullopt;
        inverse_pivot[j] = recursion.define(1 / recursion.define(pivot));
        rest_force[j] = recursion.define(rest);
        if (!parent[j])
            continue;
        const GiNaC::ex weight = recursion.define(rest_force[j] * inverse_pivot[j]);
        attachment& on = attachments[*parent[j]][*hangs_at[j]];
        for (std::size_t r = 0; r < 3; ++r) {
            for (std::size_t k = r; k < 3; ++k) {
                const GiNaC::ex articulated =
                    recursion.define(total[r][k] - u_vector[j][r] * u_vector[j][k] * inverse_pivot[j]);
                on.inertia[r][k] += articulated;
                if (k != r)
                    on.inertia[k][r] += articulated;
            }
            on.bias[r] += carried[r] + u_vector[j][r] * weight;
        }
    }

    // Outwards: the accelerations, with gravity as the root's acceleration −g.
    vector root(3, 0);
    if (scene.gravity)
        for (std::size_t r = 0; r < 3; ++r)
            root[r] = -at(scene.gravity->strength * scene.gravity->direction[r]);
    std::vector<std::vector<vector>> acceleration(n); // of each attachment that carries a child
    std::set<std::pair<std::size_t, std::size_t>> carrying; // (coordinate, attachment)
    for (std::size_t j = 0; j < n; ++j)
        if (parent[j])
            carrying.insert({*parent[j], *hangs_at[j]});
    point_tree_recursion result;
    result.accelerations.resize(n);
    for (std::size_t j : order) {
        const vector& base = parent[j] ? acceleration[*parent[j]][*hangs_at[j]] : root;
        const GiNaC::ex q2 = recursion.define((rest_force[j] - dot(u_vector[j], base)) * inverse_pivot[j]);
        result.accelerations[j] = q2;
        acceleration[j].resize(attachments[j].size());
        for (std::size_t a = 0; a < attachments[j].size(); ++a) {
            if (!carrying.count({j, a}))
                continue;
            const attachment& at_a = attachments[j][a];
            vector next(3);
            for (std::size_t r = 0; r < 3; ++r)
                next[r] = base[r] + at_a.bias_acceleration[r] + at_a.axis[r] * q2;
            acceleration[j][a] = recursion.define(next);
        }
    }
    result.definitions = std::move(recursion.definitions);
    return result;
}

} // namespace lagrange
