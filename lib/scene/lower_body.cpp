// SPDX-License-Identifier: GPL-2.0-or-later
/** @file lower_body.cpp
 *  The statements `body`, `omega` and `torque`: shapes, regions and densities, given
 *  inertia tensors checked, orientations, and `attached to` chains composed. */
#include "scene/lower_body.h"

#include "algebra/budget.h"
#include "algebra/rotation.h"
#include "scene/lexer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <set>
#include <vector>

namespace lagrange {

namespace {

/// The value of `e` at `at` as a real number, if it is one.
std::optional<double> number_at(const GiNaC::ex& e, const GiNaC::exmap& at)
{
    try {
        const GiNaC::ex value = (at.empty() ? e : e.subs(at)).evalf();
        if (!GiNaC::is_a<GiNaC::numeric>(value) || !GiNaC::ex_to<GiNaC::numeric>(value).is_real())
            return std::nullopt;
        const double x = GiNaC::ex_to<GiNaC::numeric>(value).to_double();
        return std::isfinite(x) ? std::optional<double>(x) : std::nullopt;
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

using numeric_tensor = std::array<std::array<double, 3>, 3>;

std::optional<numeric_tensor> tensor_at(const GiNaC::matrix& tensor, const GiNaC::exmap& at)
{
    numeric_tensor result{};
    for (unsigned i = 0; i < 3; ++i)
        for (unsigned j = 0; j < 3; ++j) {
            std::optional<double> x = number_at(tensor(i, j), at);
            if (!x)
                return std::nullopt;
            result[i][j] = *x;
        }
    return result;
}

/// The index of a negative moment, if any, within rounding of the tensor's size.
std::optional<std::size_t> negative_moment(const numeric_tensor& I, double tolerance)
{
    for (std::size_t k = 0; k < 3; ++k)
        if (I[k][k] < -tolerance)
            return k;
    return std::nullopt;
}

/// Whether the second moments J = ½ tr(I) 1 − I are positive semidefinite: every
/// principal minor of J non-negative (Sylvester's criterion for semidefinite matrices).
bool second_moments_semidefinite(const numeric_tensor& I, double scale)
{
    const double half_trace = (I[0][0] + I[1][1] + I[2][2]) / 2;
    numeric_tensor J{};
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j)
            J[i][j] = (i == j ? half_trace : 0.0) - I[i][j];
    const double tolerance = 1e-12;
    for (std::size_t k = 0; k < 3; ++k)
        if (J[k][k] < -tolerance * scale)
            return false;
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = i + 1; j < 3; ++j)
            if (J[i][i] * J[j][j] - J[i][j] * J[j][i] < -tolerance * scale * scale)
                return false;
    const double det = J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) -
                       J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
                       J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
    return det >= -tolerance * scale * scale * scale;
}

/// The tensor about the centre of mass from the one about the point `offset` from it
/// (parallel axes): I_cm = I_P − M (|a|² 1 − a aᵀ).
GiNaC::matrix tensor_about_centre(const GiNaC::matrix& tensor, const GiNaC::ex& mass,
                                  const std::vector<GiNaC::ex>& offset)
{
    const GiNaC::ex length2 = offset[0] * offset[0] + offset[1] * offset[1] + offset[2] * offset[2];
    GiNaC::matrix centre(3, 3);
    for (unsigned i = 0; i < 3; ++i)
        for (unsigned j = 0; j < 3; ++j)
            centre(i, j) = tensor(i, j) - mass * ((i == j ? length2 : GiNaC::ex(0)) - offset[i] * offset[j]);
    return centre;
}

double size_of(const numeric_tensor& I)
{
    double scale = 0;
    for (const auto& row : I)
        for (double x : row)
            scale = std::max(scale, std::abs(x));
    return scale;
}

/// Shapes and regions with their number of dimensions.
const std::map<std::string, std::size_t>& shape_arities(bool region)
{
    static const std::map<std::string, std::size_t> shapes = {
        {"stick", 1}, {"ring", 1},     {"disk", 1}, {"sphere", 1},   {"ball", 1},
        {"box", 3},   {"cylinder", 2}, {"cone", 2}, {"ellipsoid", 3}};
    static const std::map<std::string, std::size_t> regions = {
        {"segment", 1}, {"circle", 1}, {"disk", 1}, {"shell", 1}, {"ball", 1}, {"box", 3}, {"cylinder", 2}};
    return region ? regions : shapes;
}

std::string list_of(const std::map<std::string, std::size_t>& m)
{
    std::string all;
    for (const auto& [name, arity] : m)
        all += (all.empty() ? "`" : ", `") + name + "`";
    return all;
}

/// An upper bound of the polynomial degree of `e` in `variables` (without expanding).
long degree_bound(const GiNaC::ex& e, const std::vector<GiNaC::ex>& variables)
{
    for (const GiNaC::ex& v : variables)
        if (e.is_equal(v))
            return 1;
    if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e)) {
        long total = 0;
        for (const GiNaC::ex& operand : e) {
            long d = degree_bound(operand, variables);
            total = GiNaC::is_a<GiNaC::add>(e) ? std::max(total, d) : total + d;
        }
        return total;
    }
    if (GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_a<GiNaC::numeric>(e.op(1))) {
        const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(e.op(1));
        long base = degree_bound(e.op(0), variables);
        return n.is_integer() ? base * std::abs(n.to_long()) : base;
    }
    long inner = 0;
    for (const GiNaC::ex& operand : e)
        inner = std::max(inner, degree_bound(operand, variables));
    return inner;
}

void collect_symbols(const GiNaC::ex& e, std::set<GiNaC::ex, GiNaC::ex_is_less>& found)
{
    if (GiNaC::is_a<GiNaC::symbol>(e)) {
        found.insert(e);
        return;
    }
    for (const GiNaC::ex& operand : e)
        collect_symbols(operand, found);
}

/// Whether two entries of a tensor (parameters and numbers) are equal: expanded when that
/// stays small, otherwise compared at seeded random values of their parameters.
bool same_entry(const GiNaC::ex& a, const GiNaC::ex& b)
{
    if (a.is_equal(b))
        return true;
    const GiNaC::ex difference = a - b;
    constexpr std::size_t max_expanded_terms = 2000;
    if (expanded_terms(difference, max_expanded_terms) < max_expanded_terms)
        return difference.expand().is_zero();
    std::set<GiNaC::ex, GiNaC::ex_is_less> parameters;
    collect_symbols(difference, parameters);
    std::mt19937 random(1);
    std::uniform_real_distribution<double> value(0.5, 1.5);
    for (int trial = 0; trial < 3; ++trial) {
        GiNaC::exmap at;
        for (const GiNaC::ex& p : parameters)
            at[p] = value(random);
        std::optional<double> x = number_at(a, at), y = number_at(b, at);
        if (!x || !y || std::abs(*x - *y) > 1e-9 * std::max({1.0, std::abs(*x), std::abs(*y)}))
            return false;
    }
    return true;
}

} // namespace

GiNaC::matrix given_tensor(const rigid_body& body)
{
    if (body.tensor.size() == 9) {
        GiNaC::matrix tensor(3, 3);
        for (unsigned i = 0; i < 3; ++i)
            for (unsigned j = 0; j < 3; ++j)
                tensor(i, j) = body.tensor[3 * i + j];
        return tensor;
    }
    GiNaC::matrix tensor(3, 3);
    for (unsigned k = 0; k < 3 && k < body.moments.size(); ++k)
        tensor(k, k) = body.moments[k];
    return tensor;
}

std::optional<inertia_problem> check_inertia(const rigid_body& body, const GiNaC::exmap& at)
{
    if (body.body_kind != rigid_body::kind::inertia)
        return std::nullopt;
    const GiNaC::matrix given = given_tensor(body);
    // Moments one by one first: a negative number shows at its entry even when others are symbols.
    for (unsigned k = 0; k < 3; ++k) {
        std::optional<double> moment = number_at(given(k, k), at);
        if (moment && *moment < 0)
            return inertia_problem{inertia_problem::place::entry, k};
    }
    std::optional<numeric_tensor> I = tensor_at(given, at);
    if (!I)
        return std::nullopt;
    const double scale = size_of(*I);
    if (negative_moment(*I, 1e-12 * scale))
        return inertia_problem{inertia_problem::place::entry, *negative_moment(*I, 1e-12 * scale)};
    if (!second_moments_semidefinite(*I, scale))
        return inertia_problem{inertia_problem::place::tensor, 0};
    if (!body.about)
        return std::nullopt;
    // About the centre of mass: I_cm = I_P − M (|a|² 1 − a aᵀ), a the point from the centre.
    const GiNaC::matrix centre = tensor_about_centre(given, body.mass, *body.about);
    std::optional<numeric_tensor> I_cm = tensor_at(centre, at);
    if (!I_cm)
        return std::nullopt;
    const double centre_scale = std::max(scale, size_of(*I_cm));
    if (negative_moment(*I_cm, 1e-12 * centre_scale) || !second_moments_semidefinite(*I_cm, centre_scale))
        return inertia_problem{inertia_problem::place::about, 0};
    return std::nullopt;
}

std::string inertia_message(const inertia_problem& problem, const std::string& body, bool at_values)
{
    const std::string of = " of body " + quote(body);
    switch (problem.at) {
    case inertia_problem::place::entry:
        return at_values ? "a moment of inertia" + of + " negative; it must not be negative"
                         : "a moment of inertia cannot be negative";
    case inertia_problem::place::tensor:
        return (at_values ? "the moments of inertia" + of + " break" : std::string("these moments break")) +
               " the triangle inequality: no mass distribution has them (each principal moment is at "
               "most the sum of the other two)";
    case inertia_problem::place::about:
    default:
        return (at_values ? "the tensor" + of + " impossible" : std::string("this point makes the tensor impossible")) +
               " about the centre of mass: I_cm = I - M (|a|^2 1 - a a^T) has a negative moment or breaks "
               "the triangle inequality";
    }
}

void check_tensor_symmetric(const std::vector<GiNaC::ex>& entries, const body_statement& b)
{
    for (unsigned i = 0; i < 3; ++i)
        for (unsigned j = i + 1; j < 3; ++j)
            if (!same_entry(entries[3 * i + j], entries[3 * j + i]))
                throw scene_error(b.tensor_rows[j].components[i]->where,
                                  "an inertia tensor is symmetric: this entry (row " + std::to_string(j + 1) +
                                      ", column " + std::to_string(i + 1) + ") differs from its mirror in row " +
                                      std::to_string(i + 1) + ", column " + std::to_string(j + 1));
}

void resolve_attachments(model& scene, const std::map<std::size_t, name_ref>& attachments)
{
    enum class state { open, visiting, done };
    std::vector<state> states(scene.bodies.size(), state::open);
    auto index_of = [&](const name_ref& n) {
        for (std::size_t k = 0; k < scene.bodies.size(); ++k)
            if (scene.bodies[k].name == n.name)
                return k;
        throw scene_error(n.where, "unknown body " + quote(n.name) + " after `attached to`: declare it with `body`");
    };
    // Parents first, depth first; a body met again while its chain is open closes a cycle.
    std::vector<std::size_t> pending;
    for (const auto& entry : attachments) {
        pending.assign(1, entry.first);
        while (!pending.empty()) {
            const std::size_t k = pending.back();
            auto found = attachments.find(k);
            if (states[k] == state::done || found == attachments.end()) {
                states[k] = state::done;
                pending.pop_back();
                continue;
            }
            const name_ref& parent_name = found->second;
            const std::size_t parent = index_of(parent_name);
            rigid_body& body = scene.bodies[k];
            if (parent == k)
                throw scene_error(parent_name.where, "body " + quote(body.name) + " cannot be attached to itself");
            if (states[k] == state::open) {
                states[k] = state::visiting;
                if (states[parent] == state::visiting)
                    throw scene_error(parent_name.where, "the attachments make a cycle: " + quote(parent_name.name) +
                                                             " is attached, in turn, to " + quote(body.name));
                if (states[parent] == state::open) {
                    pending.push_back(parent);
                    continue;
                }
            }
            const rigid_body& base = scene.bodies[parent];
            if (base.omega)
                throw scene_error(parent_name.where, "body " + quote(base.name) + " is free (its `omega` is named), "
                                                     "so its frame is not in the coordinates to attach to");
            if (body.omega)
                throw scene_error(parent_name.where, "body " + quote(body.name) + " is free (its `omega` is named); an "
                                                     "attached body moves with the one it is attached to");
            // r = r_A + R_A at, R = R_A R_own.
            const GiNaC::matrix turn = base.orientation ? rotation_sequence(base.rotation_axes, *base.orientation)
                                                        : GiNaC::matrix{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
            if (base.position || base.orientation || body.position) {
                const std::vector<GiNaC::ex> origin = base.position.value_or(std::vector<GiNaC::ex>{0, 0, 0});
                const std::vector<GiNaC::ex> own = body.position.value_or(std::vector<GiNaC::ex>{0, 0, 0});
                std::vector<GiNaC::ex> placed(3);
                for (unsigned i = 0; i < 3; ++i) {
                    placed[i] = origin[i];
                    for (unsigned j = 0; j < 3; ++j)
                        placed[i] += turn(i, j) * own[j];
                }
                body.position = placed;
            }
            if (base.orientation) {
                std::vector<GiNaC::ex> angles = *base.orientation;
                std::vector<char> axes = base.rotation_axes;
                if (body.orientation) {
                    angles.insert(angles.end(), body.orientation->begin(), body.orientation->end());
                    axes.insert(axes.end(), body.rotation_axes.begin(), body.rotation_axes.end());
                }
                body.orientation = angles;
                body.rotation_axes = axes;
            }
            body.attached_to = base.name;
            states[k] = state::done;
            pending.pop_back();
        }
    }
}

/// A constant of a body (dimension, mass, moment): parameters and numbers; a number must be positive.
GiNaC::ex body_lowering::body_constant(const expr_node& node, const char* what)
{
    GiNaC::ex value = lower(node, expr_context{what, false, false, true, false});
    GiNaC::ex number = value.evalf();
    if (GiNaC::is_a<GiNaC::numeric>(number) && !GiNaC::ex_to<GiNaC::numeric>(number).is_positive())
        throw scene_error(node.where, std::string(what) + " must be positive");
    return value;
}

rigid_body* body_lowering::body_named(const name_ref& n)
{
    for (rigid_body& b : scene_.bodies)
        if (b.name == n.name)
            return &b;
    throw scene_error(n.where, "unknown body " + quote(n.name) + ": declare it with `body` first");
}

void body_lowering::lower_body(const statement& s)
{
    const body_statement& b = *s.body;
    if (reserved_names().count(b.name.name))
        throw scene_error(b.name.where, quote(b.name.name) + " is reserved and cannot name a body");
    for (const rigid_body& other : scene_.bodies)
        if (other.name == b.name.name)
            throw scene_error(b.name.where, "body " + quote(b.name.name) + " is already declared at line " +
                                                std::to_string(other.where.line));
    rigid_body body;
    body.name = b.name.name;
    body.where = b.name.where;
    if (b.body_kind == body_statement::kind::inertia) {
        body.body_kind = rigid_body::kind::inertia;
        lower_given_inertia(b, body);
    } else {
        const bool region = b.body_kind == body_statement::kind::region;
        body.body_kind = region ? rigid_body::kind::region : rigid_body::kind::shape;
        const auto& arities = shape_arities(region);
        auto found = arities.find(b.shape->name.name);
        if (found == arities.end())
            throw scene_error(b.shape->name.where, std::string("unknown ") + (region ? "region " : "shape ") +
                                                       quote(b.shape->name.name) + "; the " +
                                                       (region ? "regions" : "shapes") + " are " + list_of(arities));
        body.shape = found->first;
        if (b.shape->arguments.size() != found->second)
            throw scene_error(b.shape->name.where, quote(body.shape) + " takes " + std::to_string(found->second) +
                                                       (found->second == 1 ? " dimension" : " dimensions"));
        for (const expr_ptr& a : b.shape->arguments)
            body.dimensions.push_back(body_constant(*a, "a dimension"));
        if (region) {
            body.density = lower_density(*b.density, body);
            if (body.density.is_zero())
                throw scene_error(b.density->where, "the density is zero");
        } else {
            body.mass = body_constant(*b.mass, "a mass");
        }
    }
    if (b.axis) {
        if (body.body_kind == rigid_body::kind::inertia)
            throw scene_error(b.axis->where, "`axis` applies to shapes and regions; a body given by "
                                             "`inertia` is already in its principal axes");
        if (b.axis->name != "x" && b.axis->name != "y" && b.axis->name != "z")
            throw scene_error(b.axis->where, "the axis is `x`, `y` or `z`, not " + quote(b.axis->name));
        body.axis = b.axis->name[0];
    }
    if (b.at) {
        if (b.at->components.size() != 3)
            throw scene_error(b.at->where, "a body's position has three components `(x, y, z)`");
        body.position = lower_vector(*b.at, expr_context{"a position"});
    }
    if (b.orientation) {
        const bool sequence = b.orientation->name.name == "rotations";
        if (!sequence && b.orientation->name.name != "zxz")
            throw scene_error(b.orientation->name.where, "the orientation is given as Euler angles "
                                                         "`zxz(phi, theta, psi)` or as `rotations(z q1, x q2, ...)`");
        if (!sequence && b.orientation->arguments.size() != 3)
            throw scene_error(b.orientation->name.where, "`zxz` takes three angles");
        std::vector<GiNaC::ex> angles;
        for (const expr_ptr& a : b.orientation->arguments)
            angles.push_back(lower(*a, expr_context{"an angle", true, false, true, true}));
        body.rotation_axes = {'z', 'x', 'z'};
        if (sequence) {
            body.rotation_axes.clear();
            for (const name_ref& axis : b.rotation_axes) {
                if (axis.name != "x" && axis.name != "y" && axis.name != "z")
                    throw scene_error(axis.where, "a rotation is about the body axis `x`, `y` or `z`, not " +
                                                      quote(axis.name));
                body.rotation_axes.push_back(axis.name[0]);
            }
        }
        body.orientation = angles;
    }
    if (b.about) {
        if (body.body_kind != rigid_body::kind::inertia)
            throw scene_error(b.about->where, "`about` names the point of a tensor given by `inertia`; this "
                                              "body's inertia is derived about its centre of mass");
        if (b.about->components.size() != 3)
            throw scene_error(b.about->where, "the point `about` has three components `(x, y, z)`");
        body.about = lower_vector(*b.about, expr_context{"a body point", false, false, true, false});
    }
    if (b.attached_to)
        attachments_[scene_.bodies.size()] = *b.attached_to;
    if (std::optional<inertia_problem> problem = check_inertia(body, {}))
        throw scene_error(problem->at == inertia_problem::place::about ? b.about->where
                          : problem->at == inertia_problem::place::entry
                              ? (b.tensor_rows.empty() ? b.moments->components[problem->entry]->where
                                                       : b.tensor_rows[problem->entry].components[problem->entry]->where)
                              : (b.tensor_rows.empty() ? b.moments->where : b.tensor_where),
                          inertia_message(*problem, body.name, false));
    scene_.bodies.push_back(std::move(body));
}

/// `inertia (I1, I2, I3)` or `inertia ((Ixx, Ixy, Ixz), …)` and the mass: parameters and
/// numbers, moments non-negative (thin bodies have zero moments), the tensor symmetric.
void body_lowering::lower_given_inertia(const body_statement& b, rigid_body& body)
{
    const expr_context context{"a moment of inertia", false, false, true, false};
    if (b.tensor_rows.empty()) {
        if (b.moments->components.size() != 3)
            throw scene_error(b.moments->where, "give the three principal moments `(I1, I2, I3)`");
        for (const expr_ptr& c : b.moments->components)
            body.moments.push_back(lower(*c, context));
    } else {
        if (b.tensor_rows.size() != 3)
            throw scene_error(b.tensor_where, "an inertia tensor has three rows `((Ixx, Ixy, Ixz), (Ixy, Iyy, "
                                              "Iyz), (Ixz, Iyz, Izz))`");
        for (const vector_expr& row : b.tensor_rows) {
            if (row.components.size() != 3)
                throw scene_error(row.where, "a row of an inertia tensor has three entries");
            for (const expr_ptr& c : row.components)
                body.tensor.push_back(lower(*c, context));
        }
        check_tensor_symmetric(body.tensor, b);
    }
    body.mass = body_constant(*b.mass, "a mass");
}

/// The density of a region body: parameters, numbers and the body coordinates x, y, z, r
/// (which hide any scene name of the same spelling inside the density).
GiNaC::ex body_lowering::lower_density(const expr_node& node, const rigid_body& body)
{
    std::map<std::string, name_entry> saved = names_;
    names_["x"] = {name_entry::kind::parameter, body.x, 0, {}};
    names_["y"] = {name_entry::kind::parameter, body.y, 0, {}};
    names_["z"] = {name_entry::kind::parameter, body.z, 0, {}};
    names_["r"] = {name_entry::kind::parameter, body.r, 0, {}};
    try {
        GiNaC::ex value = lower(node, expr_context{"a density", false, false, true, false});
        names_ = std::move(saved);
        // Integration expands the density: keep its degree in x, y, z, r small enough to expand.
        constexpr long max_density_degree = 8;
        if (degree_bound(value, {body.x, body.y, body.z, body.r}) > max_density_degree)
            throw scene_error(node.where, "the density's degree in x, y, z, r is above " +
                                              std::to_string(max_density_degree));
        return value;
    } catch (...) {
        names_ = std::move(saved);
        throw;
    }
}

void body_lowering::lower_omega(const statement& s)
{
    rigid_body& body = *body_named(s.names[0]);
    if (body.omega)
        throw scene_error(s.where, "the angular velocity of " + quote(body.name) + " is named twice");
    if (body.orientation)
        throw scene_error(s.where, "body " + quote(body.name) + " has an orientation in the coordinates, so its "
                                   "angular velocity is derived from them; `omega` names that of a free body");
    for (const auto& [index, parent] : attachments_)
        if (scene_.bodies[index].name == body.name)
            throw scene_error(s.where, "body " + quote(body.name) + " is attached to " + quote(parent.name) +
                                       " and moves with it; `omega` names the angular velocity of a free body");
    if (s.vector->components.size() != 3)
        throw scene_error(s.vector->where, "name the three body-frame components, as `(w1, w2, w3)`");
    std::vector<GiNaC::realsymbol> omega;
    for (const expr_ptr& c : s.vector->components) {
        if (c->node_kind != expr_node::kind::name)
            throw scene_error(c->where, "a component of `omega` is a new name, such as `w1`");
        name_ref n{c->text, c->where};
        declare_name(n, "angular velocity");
        GiNaC::realsymbol w(n.name);
        names_[n.name] = {name_entry::kind::angular, w, 0, n.where};
        omega.push_back(w);
        body.omega_rates.push_back(GiNaC::realsymbol(n.name + "_dot"));
    }
    body.omega = omega;
}

void body_lowering::lower_torque(const statement& s)
{
    rigid_body& body = *body_named(s.names[0]);
    if (!body.omega)
        throw scene_error(s.where, "a torque acts on a free body: name its angular velocity first, as "
                                   "`omega " + body.name + " (w1, w2, w3)`");
    if (s.vector->components.size() != 3)
        throw scene_error(s.vector->where, "a torque has three body-frame components `(N1, N2, N3)`");
    expr_context context{"a torque", false, false, true, true};
    context.angular = true;
    body.torque = lower_vector(*s.vector, context);
}

void body_lowering::lower_rolls(const statement& s)
{
    rolling_.push_back({s.names[0], std::nullopt, s.axis, s.where});
    if (s.value)
        rolling_.back().radius = lower(*s.value, expr_context{"a radius", false, false, true, false});
}

void body_lowering::resolve_body_attachments()
{
    resolve_attachments(scene_, attachments_);
    for (const rolling_request& request : rolling_)
        add_rolling_constraints(scene_, request, rolling_, [&](const std::string& n) { return names_.count(n) > 0; });
}

} // namespace lagrange
