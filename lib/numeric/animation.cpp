// SPDX-License-Identifier: GPL-2.0-or-later
/** @file animation.cpp
 *  An animation's frames (see animation.h). */
#include "numeric/animation.h"

#include "algebra/rotation.h"
#include "bodies/inertia.h"
#include "core/number_text.h"

#include "numeric/compiled_motion.h"
#include "numeric/constrained_motion.h"
#include "numeric/ode.h"
#include "numeric/values.h"
#include "program/expression_program.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>

namespace lagrange {

namespace {

/// A position as three components (a planar one with z = 0).
std::vector<GiNaC::ex> three(const std::vector<GiNaC::ex>& r)
{
    std::vector<GiNaC::ex> out = r;
    out.resize(3, GiNaC::ex(0));
    return out;
}

/// The animation's length: --until, or the scene's `simulate until`; at most a million frames,
/// which the page or the video could not hold anyway.
double animation_length(const model& scene, const animation_settings& settings)
{
    if (!(settings.fps > 0) || !std::isfinite(settings.fps))
        throw std::invalid_argument("the frame rate must be positive");
    double until = 0;
    if (settings.until)
        until = *settings.until;
    else if (scene.simulation)
        until = real_value(scene.simulation->until, "the scene's `simulate until`");
    else
        throw computation_error("give the length of the animation with --until T (the scene has no `simulate until`)");
    constexpr double most_frames = 1e6;
    if (!(until * settings.fps < most_frames))
        throw computation_error("the animation would have " + shortest(std::floor(until * settings.fps) + 1) +
                                " frames, more than a million: shorten it (--until), or lower --fps (or raise --speed)");
    return until;
}

using point3 = std::array<double, 3>;
using polyline = std::vector<point3>;

constexpr double pi = 3.141592653589793238462643383279502884;

/// The ellipse a cos u e1 + b sin u e2 + offset (48 chords), in the shape's own axes.
polyline ellipse(double a, double b, int e1, int e2, point3 offset = {0, 0, 0})
{
    polyline out;
    for (int k = 0; k <= 48; ++k) {
        point3 r = offset;
        r[e1] += a * std::cos(2 * pi * k / 48);
        r[e2] += b * std::sin(2 * pi * k / 48);
        out.push_back(r);
    }
    return out;
}

/// A body's outline in its own axes about its centre of mass: lines along its shape (a stick's
/// segment, a disk's rim and two diameters, a ball's or a hollow sphere's three great circles,
/// a box's edges, a cylinder's and a cone's rims and sides, an ellipsoid's principal ellipses),
/// or, for a body given by its inertia or a region, the ellipsoid of the uniform solid with the
/// same mass and moments (semi-axes a_i² = 5 (I_j + I_k − I_i) / 2M along the principal axes).
animation_frames::body_drawing body_outline(const rigid_body& b, const model& scene,
                                            const std::map<std::string, GiNaC::ex>& values)
{
    animation_frames::body_drawing body;
    body.name = b.name;
    std::vector<double> d;
    for (const GiNaC::ex& x : b.dimensions)
        d.push_back(real_value(at_values(x, scene, values), "a body's dimension"));
    std::vector<polyline>& out = body.outline;
    const std::string& s = b.shape;
    const bool shaped = b.body_kind == rigid_body::kind::shape;
    if (shaped && (s == "stick" || s == "segment") && d.size() >= 1) {
        body.shape = "stick";
        out.push_back({{0, 0, -d[0] / 2}, {0, 0, d[0] / 2}});
    } else if (shaped && (s == "ring" || s == "circle" || s == "disk") && d.size() >= 1) {
        body.shape = s == "disk" ? "disk" : "ring";
        out.push_back(ellipse(d[0], d[0], 0, 1));
        out.push_back({{-d[0], 0, 0}, {d[0], 0, 0}}); // diameters: the spin shows
        if (s == "disk")
            out.push_back({{0, -d[0], 0}, {0, d[0], 0}});
    } else if (shaped && (s == "sphere" || s == "shell" || s == "ball") && d.size() >= 1) {
        body.shape = s == "ball" ? "ball" : "hollow sphere";
        out = {ellipse(d[0], d[0], 0, 1), ellipse(d[0], d[0], 1, 2), ellipse(d[0], d[0], 2, 0)};
    } else if (shaped && s == "ellipsoid" && d.size() >= 3) {
        body.shape = "ellipsoid";
        out = {ellipse(d[0], d[1], 0, 1), ellipse(d[1], d[2], 1, 2), ellipse(d[2], d[0], 2, 0)};
    } else if (shaped && s == "box" && d.size() >= 3) {
        body.shape = "box";
        const double h[3] = {d[0] / 2, d[1] / 2, d[2] / 2};
        for (int axis = 0; axis < 3; ++axis)
            for (double u : {-1.0, 1.0})
                for (double v : {-1.0, 1.0}) {
                    point3 a{}, c{};
                    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
                    a[axis] = -h[axis], c[axis] = h[axis];
                    a[i] = c[i] = u * h[i];
                    a[j] = c[j] = v * h[j];
                    out.push_back({a, c});
                }
    } else if (shaped && (s == "cylinder" || s == "cone") && d.size() >= 2) {
        body.shape = s;
        // The cone's base is a quarter of its height below its centre of mass.
        const double bottom = s == "cone" ? -d[1] / 4 : -d[1] / 2, top = s == "cone" ? 3 * d[1] / 4 : d[1] / 2;
        out.push_back(ellipse(d[0], d[0], 0, 1, {0, 0, bottom}));
        if (s == "cylinder")
            out.push_back(ellipse(d[0], d[0], 0, 1, {0, 0, top}));
        for (int k = 0; k < 4; ++k) {
            const double u = k * pi / 2, x = d[0] * std::cos(u), y = d[0] * std::sin(u);
            out.push_back({{x, y, bottom}, s == "cone" ? point3{0, 0, top} : point3{x, y, top}});
        }
    } else {
        body.shape = "inertia ellipsoid";
        const inertia_result inertia = derive_inertia(b);
        const double mass = real_value(at_values(inertia.mass, scene, values), "a body's mass");
        Eigen::Matrix3d tensor;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                tensor(i, j) = real_value(at_values(inertia.tensor(i, j), scene, values), "a body's inertia");
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> principal(tensor);
        const Eigen::Vector3d I = principal.eigenvalues();
        double axes[3];
        for (int i = 0; i < 3; ++i)
            axes[i] = std::sqrt(std::max(5 * (I.sum() - 2 * I(i)) / (2 * mass), 0.0));
        const double largest = std::max({axes[0], axes[1], axes[2], 1e-300});
        for (double& a : axes)
            a = std::max(a, 1e-3 * largest); // a flat body: a thin ellipsoid, still drawn
        for (int i = 0; i < 3; ++i) {
            polyline line = ellipse(axes[i], axes[(i + 1) % 3], i, (i + 1) % 3);
            for (point3& r : line) {
                const Eigen::Vector3d turned = principal.eigenvectors() * Eigen::Vector3d(r[0], r[1], r[2]);
                r = {turned(0), turned(1), turned(2)};
            }
            out.push_back(line);
        }
        for (const polyline& line : out)
            for (const point3& r : line)
                body.size = std::max(body.size, std::hypot(r[0], r[1], r[2]));
        return body; // already in the body's axes
    }
    // The shape's symmetry axis (its own z) is the body's `axis`, as bodies/inertia.cpp turns it.
    for (polyline& line : out)
        for (point3& r : line) {
            if (b.axis == 'x')
                r = {r[2], r[0], r[1]};
            else if (b.axis == 'y')
                r = {r[1], r[2], r[0]};
            body.size = std::max(body.size, std::hypot(r[0], r[1], r[2]));
        }
    return body;
}

/// The terms of a position that hold no coordinate: where a point's support is, when they
/// move with t (a Kapitza pendulum's a cos γt); empty when they do not.
std::vector<GiNaC::ex> moving_support(const std::vector<GiNaC::ex>& position, const model& scene)
{
    std::vector<GiNaC::ex> support;
    bool moves = false;
    for (const GiNaC::ex& component : position) {
        const GiNaC::ex expanded = component.expand();
        GiNaC::ex free = 0;
        auto take = [&](const GiNaC::ex& term) {
            for (const coordinate& c : scene.coordinates)
                if (term.has(c.position) || term.has(c.velocity))
                    return;
            free += term;
        };
        if (GiNaC::is_a<GiNaC::add>(expanded))
            for (const GiNaC::ex& term : expanded)
                take(term);
        else
            take(expanded);
        moves = moves || free.has(scene.time);
        support.push_back(free);
    }
    return moves ? support : std::vector<GiNaC::ex>{};
}

} // namespace

animation_frames compute_body_animation(const model& scene, const euler_result& body,
                                        const animation_settings& settings)
{
    poinsot_settings construction;
    construction.until = animation_length(scene, settings);
    construction.step = 1 / settings.fps;
    construction.tolerance = std::max(settings.tolerance / 12, 1e-15); // per step ÷12, as simulate's DOP853
    animation_frames frames;
    frames.poinsot = compute_poinsot(body, construction);
    const poinsot_motion& m = *frames.poinsot;
    frames.dimensions = 3;
    frames.step = construction.step;
    frames.times = m.times;
    frames.method = m.method;
    frames.steps = m.steps;
    for (const auto& w : m.omega) {
        double two_t = 0;
        for (std::size_t k = 0; k < 3; ++k)
            two_t += m.moments[k] * w[k] * w[k];
        frames.energy_drift.push_back((0.5 * two_t - m.energy) / m.energy);
    }
    return frames;
}

animation_frames compute_animation(const model& scene, const equations_of_motion& equations,
                                   const animation_settings& settings)
{
    std::vector<const rigid_body*> placed; // bodies placed in the coordinates (free ones have `omega`)
    for (const rigid_body& b : scene.bodies)
        if (!b.omega && (b.position || b.orientation))
            placed.push_back(&b);
    if (scene.points.empty() && placed.empty())
        throw computation_error("the scene has no points or placed bodies to animate (a free body is drawn by "
                                "Poinsot's construction)");
    const double until = animation_length(scene, settings);
    const std::map<std::string, GiNaC::ex> values = merged_values(scene);

    animation_frames frames;
    frames.step = 1 / settings.fps;
    std::vector<GiNaC::ex> outputs, turns;
    for (const point_mass& p : scene.points) {
        frames.markers.push_back({p.name, real_value(at_values(p.mass, scene, values), "a point's mass"), true});
        for (const GiNaC::ex& x : three(p.position))
            outputs.push_back(at_values(x, scene, values));
    }
    for (const rigid_body* b : placed) {
        animation_frames::body_drawing body = body_outline(*b, scene, values);
        body.centre = frames.markers.size();
        frames.markers.push_back({b->name, 0, false});
        for (const GiNaC::ex& x : b->position ? three(*b->position) : std::vector<GiNaC::ex>{0, 0, 0})
            outputs.push_back(at_values(x, scene, values));
        const GiNaC::matrix R = b->orientation ? rotation_sequence(b->rotation_axes, *b->orientation)
                                               : GiNaC::matrix{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        for (unsigned i = 0; i < 3; ++i)
            for (unsigned j = 0; j < 3; ++j)
                turns.push_back(at_values(R(i, j), scene, values));
        frames.bodies.push_back(std::move(body));
    }
    const std::size_t pivot = frames.markers.size();
    frames.markers.push_back({"pivot", 0, false});
    for (int k = 0; k < 3; ++k)
        outputs.push_back(0);
    // Moving supports: the part of a point's position that moves with t alone; one marker each.
    std::vector<std::size_t> support_of(scene.points.size(), 0);
    std::vector<std::vector<GiNaC::ex>> supports;
    for (std::size_t p = 0; p < scene.points.size(); ++p) {
        std::vector<GiNaC::ex> position;
        for (const GiNaC::ex& x : three(scene.points[p].position))
            position.push_back(at_values(x, scene, values));
        const std::vector<GiNaC::ex> support = moving_support(position, scene);
        if (support.empty())
            continue;
        auto same = [&](const std::vector<GiNaC::ex>& other) {
            for (std::size_t k = 0; k < 3; ++k)
                if (!(other[k] - support[k]).expand().is_zero())
                    return false;
            return true;
        };
        std::size_t s = 0;
        while (s < supports.size() && !same(supports[s]))
            ++s;
        if (s == supports.size()) {
            supports.push_back(support);
            frames.markers.push_back({"support", 0, false});
            outputs.insert(outputs.end(), support.begin(), support.end());
        }
        support_of[p] = pivot + 1 + s;
    }
    for (std::size_t s = 0; s < scene.springs.size(); ++s) {
        const spring& sp = scene.springs[s];
        for (const auto* end : {&sp.end_a, &sp.end_b}) {
            frames.markers.push_back({"spring " + std::to_string(s + 1), 0, false});
            for (const GiNaC::ex& x : three(*end))
                outputs.push_back(at_values(x, scene, values));
        }
        frames.springs.push_back({frames.markers.size() - 2, frames.markers.size() - 1});
    }
    expression_program positions, rotations;
    try {
        positions = expression_program(outputs, state_symbols(scene));
        if (!turns.empty())
            rotations = expression_program(turns, state_symbols(scene));
    } catch (const std::invalid_argument& error) {
        throw computation_error(std::string("the positions cannot be compiled: ") + error.what());
    }

    // The motion at the frame times: from DOP853's dense output; with constraints, as
    // `simulate` runs them (constrained_motion.h): DOP853 from one frame to the next, the state
    // projected back onto the constraints after each.
    const std::size_t count = static_cast<std::size_t>(std::floor(until * settings.fps + 1e-9)) + 1;
    std::vector<double> times;
    for (std::size_t f = 0; f < count; ++f)
        times.push_back(std::min(until, static_cast<double>(f) / settings.fps));
    if (times.back() < until)
        times.push_back(until);
    const double tolerance = std::max(settings.tolerance / 12, 1e-15); // per step ÷12, as simulate's DOP853
    trajectory run;
    std::function<double(const double*)> energy_of;
    if (equations.constraints) {
        auto motion = std::make_shared<constrained_motion>(scene, equations, values);
        std::vector<double> x = initial_state_vector(scene, values);
        if (motion->residual(0, x.data()) > settings.tolerance) { // bad input, located as simulate does
            std::vector<double> projected = x;
            motion->project(0, projected.data());
            const bool converged = motion->residual(0, projected.data()) <= settings.tolerance;
            if (!settings.project_initial || !converged)
                throw off_constraints(scene, *motion, x, converged ? &projected : nullptr, settings.tolerance);
            x = projected;
        }
        run.method = "dop853, projected onto the constraints after each frame";
        run.times.push_back(times[0]);
        run.states.push_back(x);
        for (std::size_t f = 1; f < times.size(); ++f) {
            integration_options options;
            options.start = times[f - 1];
            options.until = times[f];
            options.tolerance = tolerance;
            options.outputs = false;
            options.keep_states = false;
            const trajectory piece = integrate(motion->system(), ode_method::dop853, x, options);
            run.steps += piece.steps;
            x = piece.final_state;
            motion->project(times[f], x.data());
            run.times.push_back(times[f]);
            run.states.push_back(x);
        }
        if (motion->conservative())
            energy_of = [motion](const double* state) { return motion->energy(state); };
    } else {
        auto motion = std::make_shared<compiled_motion>(scene, equations, values);
        if (settings.native)
            motion->compile_native_rhs(); // DOP853 never calls the Jacobian
        std::vector<double> start = initial_state_vector(scene, values);
        start.resize(motion->dimension(), 0.0);
        integration_options options;
        options.until = until;
        options.tolerance = tolerance;
        options.times = times;
        run = integrate(motion->system(), ode_method::dop853, start, options);
        if (motion->conservative())
            energy_of = [motion](const double* state) { return motion->energy(state); };
    }
    frames.method = run.method;
    frames.steps = run.steps;
    frames.times = run.times;
    const std::size_t m = frames.markers.size(), n = scene.coordinates.size(), nb = frames.bodies.size();
    frames.positions.resize(run.times.size() * m * 3);
    frames.rotations.resize(run.times.size() * nb * 9);
    std::vector<double> symbols(2 * n + 1), scratch;
    const double h0 = energy_of ? energy_of(run.states.front().data()) : 0;
    for (std::size_t f = 0; f < run.times.size(); ++f) {
        std::copy(run.states[f].begin(), run.states[f].begin() + static_cast<long>(2 * n), symbols.begin());
        symbols[2 * n] = run.times[f];
        positions.run(symbols.data(), scratch, frames.positions.data() + f * m * 3);
        if (nb)
            rotations.run(symbols.data(), scratch, frames.rotations.data() + f * nb * 9);
        if (energy_of)
            frames.energy_drift.push_back(energy_of(run.states[f].data()) - h0);
    }
    // Planar when nothing drawn ever leaves z = 0 (the model may keep planar points in three
    // components): no marker, and no body outline once turned.
    for (std::size_t k = 2; k < frames.positions.size(); k += 3)
        if (frames.positions[k] != 0)
            frames.dimensions = 3;
    for (std::size_t f = 0; f < frames.times.size() && frames.dimensions == 2; ++f)
        for (std::size_t b = 0; b < nb; ++b) {
            const double* R = frames.rotation(f, b);
            for (const auto& line : frames.bodies[b].outline)
                for (const point3& r : line)
                    if (std::abs(R[6] * r[0] + R[7] * r[1] + R[8] * r[2]) > 1e-12 * frames.bodies[b].size)
                        frames.dimensions = 3;
        }
    if (!frames.energy_drift.empty()) {
        const double scale = std::max(std::abs(h0), 1e-300);
        for (double& d : frames.energy_drift)
            d /= scale;
    }

    // Rods: two markers (points, or a point and the pivot or its moving support) whose distance
    // stays the same at every frame, to a millionth, and is not zero; springs' pairs are
    // springs, not rods.
    auto distance = [&](std::size_t f, std::size_t a, std::size_t b) {
        const double *p = frames.at(f, a), *q = frames.at(f, b);
        return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
    };
    auto moves = [&](std::size_t a) {
        const double* p0 = frames.at(0, a);
        for (std::size_t f = 1; f < frames.times.size(); ++f) {
            const double* p = frames.at(f, a);
            if (p[0] != p0[0] || p[1] != p0[1] || p[2] != p0[2])
                return true;
        }
        return false;
    };
    auto rigid = [&](std::size_t a, std::size_t b) {
        const double d0 = distance(0, a, b);
        if (!(d0 > 0))
            return false;
        for (std::size_t f = 1; f < frames.times.size(); ++f)
            if (std::abs(distance(f, a, b) - d0) > 1e-6 * d0)
                return false;
        return true;
    };
    std::vector<bool> held(m, false); // pivot and supports that hold something
    const std::size_t points = scene.points.size();
    for (std::size_t a = 0; a < points; ++a) {
        if (!moves(a))
            continue;
        for (std::size_t b = a + 1; b < points; ++b)
            if (rigid(a, b))
                frames.rods.push_back({a, b});
        for (std::size_t b : {pivot, support_of[a]})
            if (b != 0 && rigid(a, b)) { // b = 0: the point has no moving support
                frames.rods.push_back({a, b});
                held[b] = true;
                break;
            }
    }
    // A body turning about a fixed point (the origin stays at one point of the body, R_fᵀ(0 − c_f)
    // the same at every frame): the pivot holds it, by a rod to its centre when that is apart.
    for (std::size_t b = 0; b < nb; ++b) {
        const std::size_t c = frames.bodies[b].centre;
        bool fixed = frames.times.size() > 1;
        double first[3] = {0, 0, 0};
        bool turns_or_moves = moves(c);
        for (std::size_t f = 0; f < frames.times.size() && fixed; ++f) {
            const double *R = frames.rotation(f, b), *p = frames.at(f, c);
            double local[3];
            for (int i = 0; i < 3; ++i)
                local[i] = -(R[i] * p[0] + R[3 + i] * p[1] + R[6 + i] * p[2]);
            if (f == 0)
                std::copy(local, local + 3, first);
            const double scale = frames.bodies[b].size + std::hypot(first[0], first[1], first[2]);
            fixed = std::hypot(local[0] - first[0], local[1] - first[1], local[2] - first[2]) <= 1e-6 * scale;
            for (int i = 0; i < 9 && f > 0; ++i)
                turns_or_moves = turns_or_moves || R[i] != frames.rotation(0, b)[i];
        }
        if (!fixed || !turns_or_moves)
            continue;
        held[pivot] = true;
        // A rod to the centre, unless the outline already reaches the pivot (a stick hung by its end).
        bool reaches = false;
        for (const auto& line : frames.bodies[b].outline)
            for (const point3& r : line)
                reaches = reaches || std::hypot(r[0] - first[0], r[1] - first[1], r[2] - first[2]) <=
                                         1e-6 * frames.bodies[b].size;
        if (!reaches && distance(0, c, pivot) > 1e-9 * frames.bodies[b].size)
            frames.rods.push_back({c, pivot});
    }
    frames.markers[pivot].name = held[pivot] ? "pivot" : "";
    // The ground: where the pivot is fixed, normal to gravity (its direction is normalized);
    // without a pivot, the plane a body keeps resting or rolling on.
    if (scene.gravity) {
        double g[3] = {0, 0, 0};
        for (std::size_t k = 0; k < scene.gravity->direction.size() && k < 3; ++k)
            g[k] = real_value(at_values(scene.gravity->direction[k], scene, values), "gravity's direction");
        std::optional<point3> centre;
        double reach = 0;
        if (held[pivot]) {
            centre = point3{frames.at(0, pivot)[0], frames.at(0, pivot)[1], frames.at(0, pivot)[2]};
            for (std::size_t f = 0; f < frames.times.size(); ++f)
                for (std::size_t k = 0; k < m; ++k)
                    if (k != pivot && !frames.markers[k].name.empty())
                        reach = std::max(reach, distance(f, k, pivot));
            for (const auto& body : frames.bodies)
                reach = std::max(reach, body.size);
        } else {
            // A moving body whose lowest point along g stays at one height (to a hundredth of its
            // size, the outline's sampling): the ground through that point's mean, under all of
            // the lowest points.
            auto depth_of = [&](const point3& w) { return w[0] * g[0] + w[1] * g[1] + w[2] * g[2]; };
            for (std::size_t b = 0; b < nb && !centre && frames.times.size() > 1; ++b) {
                const double size = frames.bodies[b].size;
                std::vector<point3> lowest;
                for (std::size_t f = 0; f < frames.times.size(); ++f) {
                    const double *R = frames.rotation(f, b), *c = frames.at(f, frames.bodies[b].centre);
                    point3 low{};
                    double depth = -std::numeric_limits<double>::infinity();
                    for (const auto& line : frames.bodies[b].outline)
                        for (const point3& r : line) {
                            point3 w;
                            for (std::size_t i = 0; i < 3; ++i)
                                w[i] = c[i] + R[3 * i] * r[0] + R[3 * i + 1] * r[1] + R[3 * i + 2] * r[2];
                            if (const double d = depth_of(w); d > depth) {
                                depth = d;
                                low = w;
                            }
                        }
                    lowest.push_back(low);
                }
                bool level = moves(frames.bodies[b].centre);
                for (const auto& w : lowest)
                    level = level && std::abs(depth_of(w) - depth_of(lowest.front())) <= 1e-2 * size;
                if (!level)
                    continue;
                point3 mean{};
                for (const auto& w : lowest)
                    for (std::size_t i = 0; i < 3; ++i)
                        mean[i] += w[i] / static_cast<double>(lowest.size());
                for (const auto& w : lowest)
                    reach = std::max(reach, 4 * (std::hypot(w[0] - mean[0], w[1] - mean[1], w[2] - mean[2]) + size));
                centre = mean;
            }
        }
        if (centre) {
            // u: the coordinate axis least along g, made normal to it; v = g × u.
            std::size_t least = 0;
            for (std::size_t k = 1; k < 3; ++k)
                if (std::abs(g[k]) < std::abs(g[least]))
                    least = k;
            double u[3] = {0, 0, 0};
            u[least] = 1;
            for (int k = 0; k < 3; ++k)
                u[k] -= g[least] * g[k];
            const double norm = std::hypot(u[0], u[1], u[2]);
            animation_frames::ground_square ground;
            for (int k = 0; k < 3; ++k)
                ground.u[static_cast<std::size_t>(k)] = u[k] / norm;
            ground.v = {g[1] * ground.u[2] - g[2] * ground.u[1], g[2] * ground.u[0] - g[0] * ground.u[2],
                        g[0] * ground.u[1] - g[1] * ground.u[0]};
            ground.centre = *centre;
            ground.half_width = reach / 4;
            frames.ground = ground;
        }
    }
    for (std::size_t s = 0; s < supports.size(); ++s)
        frames.markers[pivot + 1 + s].name = held[pivot + 1 + s] ? "support" : "";
    return frames;
}

} // namespace lagrange
