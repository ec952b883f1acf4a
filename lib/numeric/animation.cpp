// SPDX-License-Identifier: GPL-2.0-or-later
/** @file animation.cpp
 *  An animation's frames (see animation.h). */
#include "numeric/animation.h"

#include "core/number_text.h"

#include "numeric/compiled_motion.h"
#include "numeric/ode.h"
#include "numeric/values.h"
#include "program/expression_program.h"

#include <algorithm>
#include <cmath>

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
    if (scene.points.empty())
        throw computation_error("the scene has no points to animate (rigid bodies are drawn only when free: by Poinsot's construction)");
    if (equations.constraints)
        throw computation_error("animations of scenes with constraints are not implemented");
    const double until = animation_length(scene, settings);
    const std::map<std::string, GiNaC::ex> values = merged_values(scene);

    animation_frames frames;
    frames.step = 1 / settings.fps;
    std::vector<GiNaC::ex> outputs;
    for (const point_mass& p : scene.points) {
        frames.markers.push_back({p.name, real_value(at_values(p.mass, scene, values), "a point's mass"), true});
        for (const GiNaC::ex& x : three(p.position))
            outputs.push_back(at_values(x, scene, values));
    }
    const std::size_t pivot = frames.markers.size();
    frames.markers.push_back({"pivot", 0, false});
    for (int k = 0; k < 3; ++k)
        outputs.push_back(0);
    for (std::size_t s = 0; s < scene.springs.size(); ++s) {
        const spring& sp = scene.springs[s];
        for (const auto* end : {&sp.end_a, &sp.end_b}) {
            frames.markers.push_back({"spring " + std::to_string(s + 1), 0, false});
            for (const GiNaC::ex& x : three(*end))
                outputs.push_back(at_values(x, scene, values));
        }
        frames.springs.push_back({frames.markers.size() - 2, frames.markers.size() - 1});
    }
    expression_program positions;
    try {
        positions = expression_program(outputs, state_symbols(scene));
    } catch (const std::invalid_argument& error) {
        throw computation_error(std::string("the positions cannot be compiled: ") + error.what());
    }

    // The motion at the frame times, from DOP853's dense output.
    compiled_motion motion(scene, equations, values);
    if (settings.native)
        motion.compile_native_rhs(); // DOP853 never calls the Jacobian
    const std::vector<double> x0 = initial_state_vector(scene, values);
    std::vector<double> start = x0;
    start.resize(motion.dimension(), 0.0);
    const std::size_t count = static_cast<std::size_t>(std::floor(until * settings.fps + 1e-9)) + 1;
    integration_options options;
    options.until = until;
    options.tolerance = std::max(settings.tolerance / 12, 1e-15); // per step ÷12, as simulate's DOP853
    for (std::size_t f = 0; f < count; ++f)
        options.times.push_back(std::min(until, static_cast<double>(f) / settings.fps));
    if (options.times.back() < until)
        options.times.push_back(until);
    const trajectory run = integrate(motion.system(), ode_method::dop853, start, options);
    frames.method = run.method;
    frames.steps = run.steps;
    frames.times = run.times;
    const std::size_t m = frames.markers.size(), n = scene.coordinates.size();
    frames.positions.resize(run.times.size() * m * 3);
    std::vector<double> symbols(2 * n + 1), scratch;
    const double h0 = motion.conservative() ? motion.energy(run.states.front().data()) : 0;
    for (std::size_t f = 0; f < run.times.size(); ++f) {
        std::copy(run.states[f].begin(), run.states[f].begin() + static_cast<long>(2 * n), symbols.begin());
        symbols[2 * n] = run.times[f];
        positions.run(symbols.data(), scratch, frames.positions.data() + f * m * 3);
        if (motion.conservative())
            frames.energy_drift.push_back(motion.energy(run.states[f].data()) - h0);
    }
    // Planar when no marker ever leaves z = 0 (the model may keep planar points in three components).
    for (std::size_t k = 2; k < frames.positions.size(); k += 3)
        if (frames.positions[k] != 0)
            frames.dimensions = 3;
    if (!frames.energy_drift.empty()) {
        const double scale = std::max(std::abs(h0), 1e-300);
        for (double& d : frames.energy_drift)
            d /= scale;
    }

    // Rods: two markers (points, or a point and the pivot) whose distance stays the same at
    // every frame, to a millionth, and is not zero; springs' pairs are springs, not rods.
    auto distance = [&](std::size_t f, std::size_t a, std::size_t b) {
        const double *p = frames.at(f, a), *q = frames.at(f, b);
        return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
    };
    bool pivot_used = false;
    for (std::size_t a = 0; a <= pivot; ++a)
        for (std::size_t b = a + 1; b <= pivot; ++b) {
            if (a == pivot || (b != pivot && !frames.markers[b].point))
                continue;
            const double d0 = distance(0, a, b);
            bool moves = false, constant = d0 > 0;
            for (std::size_t f = 1; f < frames.times.size() && constant; ++f) {
                constant = std::abs(distance(f, a, b) - d0) <= 1e-6 * d0;
                const double* p = frames.at(f, a);
                const double* p0 = frames.at(0, a);
                moves = moves || p[0] != p0[0] || p[1] != p0[1] || p[2] != p0[2];
            }
            if (!constant || !moves)
                continue;
            frames.rods.push_back({a, b});
            pivot_used = pivot_used || b == pivot;
        }
    frames.markers[pivot].name = pivot_used ? "pivot" : "";
    return frames;
}

} // namespace lagrange
