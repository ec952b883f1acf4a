// SPDX-License-Identifier: GPL-2.0-or-later
/** @file lower_rolling.cpp
 *  The constraints of a wheel rolling on the ground (lower_rolling.h). */
#include "scene/lower_rolling.h"

#include "algebra/calculus.h"
#include "algebra/rotation.h"
#include "scene/lexer.h"
#include "scene/lower_constraint.h"

#include <array>
#include <cmath>
#include <random>
#include <string>

namespace lagrange {

namespace {

using GiNaC::ex;
using vector3 = std::array<ex, 3>;

ex dot(const vector3& a, const vector3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

vector3 cross(const vector3& a, const vector3& b)
{
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

vector3 column(const GiNaC::matrix& m, unsigned j) { return {m(0, j), m(1, j), m(2, j)}; }

unsigned axis_index(char axis) { return static_cast<unsigned>(axis - 'x'); }

/// √(1 − (k·a)²) = |k × a|, the length of the rim's radius seen from above over r. Where
/// k·a is ±sin X (a wheel leaning by X) it is cos X, exactly, for |X| < π/2 — a wheel
/// leaning further would lie through the ground; otherwise the square root itself.
ex rim_root(const ex& ka)
{
    const ex e = ka.expand();
    if (e.is_zero())
        return 1;
    for (const ex& sign : {ex(1), ex(-1)}) {
        const ex term = (sign * e).expand();
        if (GiNaC::is_a<GiNaC::function>(term) && GiNaC::ex_to<GiNaC::function>(term).get_name() == "sin")
            return GiNaC::cos(term.op(0));
    }
    return GiNaC::sqrt((1 - e * e).expand());
}

/// Whether f vanishes identically: symbolically, or at a few random points with the
/// angles small (where the wheel stands) and the parameters positive.
bool vanishes_identically(const ex& f, const model& scene)
{
    if (f.expand().is_zero())
        return true;
    std::mt19937 random(20261201);
    std::uniform_real_distribution<double> small(-0.5, 0.5), positive(0.5, 2.0);
    for (int trial = 0; trial < 4; ++trial) {
        GiNaC::exmap at;
        for (const parameter& p : scene.parameters)
            at[p.symbol] = positive(random);
        for (const coordinate& c : scene.coordinates)
            at[c.position] = small(random);
        at[scene.time] = positive(random);
        try {
            const ex v = f.subs(at).evalf();
            if (!GiNaC::is_a<GiNaC::numeric>(v) || std::abs(GiNaC::ex_to<GiNaC::numeric>(v).to_double()) > 1e-12)
                return false;
        } catch (const std::exception&) {
            return false;
        }
    }
    return true;
}

/// The two horizontal directions the no-slip constraints are taken along, each with the
/// name of the scene axis it comes from: the axes other than the one closest to k,
/// made horizontal (exactly those two axes when gravity is along an axis).
std::vector<std::pair<char, vector3>> horizontal_directions(const vector3& up)
{
    unsigned vertical = 0;
    double largest = -1;
    for (unsigned i = 0; i < 3; ++i) {
        const double size = std::abs(GiNaC::ex_to<GiNaC::numeric>(up[i].evalf()).to_double());
        if (size > largest) {
            largest = size;
            vertical = i;
        }
    }
    std::vector<std::pair<char, vector3>> directions;
    for (unsigned i = 0; i < 3; ++i) {
        if (i == vertical)
            continue;
        vector3 e{0, 0, 0};
        e[i] = 1;
        const ex along = up[i];
        for (unsigned j = 0; j < 3; ++j)
            e[j] = (e[j] - along * up[j]).normal();
        directions.emplace_back(static_cast<char>('x' + i), e);
    }
    return directions;
}

/// A `rolls` statement lowered: its constraints, and its contact for the `contact` product.
struct rolled {
    std::vector<constraint> constraints;
    rolling_contact contact;
};

rolled lower_rolls(const model& scene, const rolling_request& request)
{
    const std::string& name = request.body.name;
    const rigid_body* found = body_named(scene, name);
    if (!found)
        throw scene_error(request.body.where, "unknown body " + quote(name) + ": declare it with `body`");
    const rigid_body& wheel = *found;
    if (wheel.omega)
        throw scene_error(request.body.where, "body " + quote(name) + " is free (its `omega` is named): a rolling "
                                              "wheel's pose is given in the coordinates, with `at` and `orientation`");
    if (!wheel.orientation)
        throw scene_error(request.body.where, "body " + quote(name) + " has no orientation: a rolling wheel turns "
                                              "with the coordinates, as `orientation rotations(z q1, x q2, y q3)`");
    if (!wheel.position)
        throw scene_error(request.body.where, "body " + quote(name) + " has no position: give its centre with `at`");
    const bool round = wheel.body_kind == rigid_body::kind::shape && (wheel.shape == "disk" || wheel.shape == "ring");
    if (!round && (!request.radius || !request.axis))
        throw scene_error(request.body.where,
                          "body " + quote(name) + " is not a `disk` or `ring`: give its rim's radius and axis, as "
                          "`rolls " + name + " on ground radius r axis y`");
    char axis = wheel.axis;
    if (request.axis) {
        const std::string& a = request.axis->name;
        if (a != "x" && a != "y" && a != "z")
            throw scene_error(request.axis->where, "the axis is `x`, `y` or `z`, not " + quote(a));
        if (round && a[0] != wheel.axis)
            throw scene_error(request.axis->where, "the rim of " + quote(name) + " is about its own axis `" +
                                                       std::string(1, wheel.axis) + "`");
        axis = a[0];
    }
    const ex radius = request.radius ? *request.radius : wheel.dimensions.at(0);
    if (!scene.gravity || scene.gravity->direction.size() != 3)
        throw scene_error(request.where, "`rolls … on ground` needs three-dimensional gravity (`gravity g along "
                                         "(0, 0, -1)`): the ground is the plane through the origin across it");

    const vector3 up{-scene.gravity->direction[0], -scene.gravity->direction[1], -scene.gravity->direction[2]};
    for (const ex& component : up)
        if (!GiNaC::is_a<GiNaC::numeric>(component.evalf()))
            throw scene_error(request.where, "`rolls … on ground` needs the direction of gravity in numbers, as "
                                             "`gravity g along (0, 0, -1)`: the ground lies across it");
    const std::vector<ex>& angles = *wheel.orientation;
    const GiNaC::matrix turn = rotation_sequence(wheel.rotation_axes, angles);
    const vector3 centre{(*wheel.position)[0], (*wheel.position)[1], (*wheel.position)[2]};
    const vector3 a = column(turn, axis_index(axis));

    // The contact point's offset from the centre, p − c = −r (k − (k·a) a) / √(1 − (k·a)²).
    const ex ka = dot(up, a);
    const ex root = rim_root(ka);
    vector3 offset;
    for (unsigned i = 0; i < 3; ++i)
        offset[i] = -radius * (up[i] - ka * a[i]) / root;

    // ω = Σ_k (R_1 ⋯ R_{k−1} e_{a_k}) d/dt(angle_k): each rotation about its axis as turned
    // by those before it.
    vector3 omega{0, 0, 0};
    GiNaC::matrix before{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (std::size_t k = 0; k < angles.size(); ++k) {
        const vector3 turned = column(before, axis_index(wheel.rotation_axes[k]));
        const ex rate = time_derivative(angles[k], scene);
        for (unsigned i = 0; i < 3; ++i)
            omega[i] += turned[i] * rate;
        before = before.mul(axis_rotation(wheel.rotation_axes[k], angles[k]));
    }
    const vector3 spin = cross(omega, offset);
    vector3 slip;
    for (unsigned i = 0; i < 3; ++i)
        slip[i] = time_derivative(centre[i], scene) + spin[i];

    rolled result;
    result.contact.body = name;
    result.contact.where = request.body.where;
    for (unsigned i = 0; i < 3; ++i)
        result.contact.point.push_back(centre[i] + offset[i]);
    const auto add = [&](const std::string& constraint_name, const ex& f, const vector3& along) {
        result.constraints.push_back(classify_constraint({constraint_name, request.body.where}, f,
                                                         request.body.where, scene));
        result.contact.constraints.push_back(constraint_name);
        result.contact.directions.push_back({along[0], along[1], along[2]});
    };
    const ex height = dot(up, centre) - radius * root;
    result.contact.normal_by_construction = vanishes_identically(height, scene);
    if (!result.contact.normal_by_construction)
        add(name + "_contact", height, up);
    for (const auto& [letter, e] : horizontal_directions(up))
        add(name + "_roll_" + std::string(1, letter), dot(e, slip), e);
    return result;
}

} // namespace

std::vector<constraint> rolling_constraints(const model& scene, const rolling_request& request)
{
    return lower_rolls(scene, request).constraints;
}

void add_rolling_constraints(model& scene, const rolling_request& request, const std::vector<rolling_request>& all,
                             const std::function<bool(const std::string&)>& declared)
{
    for (const rolling_request& other : all) {
        if (&other == &request)
            break;
        if (other.body.name == request.body.name)
            throw scene_error(request.body.where, "body " + quote(request.body.name) + " already rolls (line " +
                                                      std::to_string(other.where.line) + ")");
    }
    if (request.radius) {
        const ex number = request.radius->evalf();
        if (GiNaC::is_a<GiNaC::numeric>(number) && !GiNaC::ex_to<GiNaC::numeric>(number).is_positive())
            throw scene_error(request.where, "the radius of a rolling rim must be positive");
    }
    rolled lowered = lower_rolls(scene, request);
    for (constraint& c : lowered.constraints) {
        for (const constraint& other : scene.constraints)
            if (other.name == c.name)
                throw scene_error(request.body.where, "`rolls` names its constraint " + quote(c.name) +
                                                          ", which is already declared at line " +
                                                          std::to_string(other.where.line));
        if (declared("lambda_" + c.name))
            throw scene_error(request.body.where, "`rolls` names the multiplier of its constraint `lambda_" + c.name +
                                                      "`, which is already declared");
        scene.constraints.push_back(std::move(c));
    }
    scene.contacts.push_back(std::move(lowered.contact));
}

} // namespace lagrange
