// SPDX-License-Identifier: GPL-2.0-or-later
/** @file poincare.cpp
 *  Poincaré sections (see poincare.h): the section option, the orbits' starts on the
 *  energy surface, and each orbit cut by the section on DOP853's dense output. */
#include "ensemble/poincare.h"

#include "ensemble/scheduler.h"
#include "numeric/compiled_motion.h"
#include "numeric/dop853.h"
#include "numeric/mass_matrix.h"
#include "numeric/values.h"
#include "core/number_text.h"
#include "program/expression_program.h"
#include "program/native_code.h"

#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/toms748_solve.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <limits>
#include <memory>
#include <mutex>
#include <thread>

namespace lagrange {

namespace {

constexpr double pi = 3.141592653589793238462643383279502884;

[[noreturn]] void bad_section(const std::string& text, std::size_t column, const std::string& message)
{
    scene_error error({"--section", 1, static_cast<int>(column) + 1}, message);
    error.attach_line_text(text);
    throw error;
}

std::size_t skip_blanks(const std::string& text, std::size_t at)
{
    while (at < text.size() && text[at] == ' ')
        ++at;
    return at;
}

/// A name [A-Za-z][A-Za-z0-9_]* at `at`; its end.
std::size_t name_end(const std::string& text, std::size_t at)
{
    if (at >= text.size() || !std::isalpha(static_cast<unsigned char>(text[at])))
        return at;
    while (at < text.size() && (std::isalnum(static_cast<unsigned char>(text[at])) || text[at] == '_'))
        ++at;
    return at;
}

/// The index of coordinate `name`, or bad_section at `column`.
std::size_t coordinate_index(const std::string& text, std::size_t column, const std::string& name, const model& scene)
{
    for (std::size_t k = 0; k < scene.coordinates.size(); ++k)
        if (scene.coordinates[k].name == name)
            return k;
    std::string list;
    for (const coordinate& c : scene.coordinates)
        list += (list.empty() ? "" : ", ") + c.name;
    bad_section(text, column, "`" + name + "` is not a coordinate of the scene (its coordinates: " + list + ")");
}

/// SplitMix64 (Steele, Lea, Flood 2014), as ensemble.cpp's random points: orbit k's start
/// depends on the seed and k only, on any thread and platform.
std::uint64_t splitmix64(std::uint64_t x)
{
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

/// A uniform number in [0, 1) for draw `draw` of orbit `orbit`.
double uniform(std::uint64_t seed, std::size_t orbit, std::size_t draw)
{
    std::uint64_t bits = splitmix64(splitmix64(splitmix64(seed) ^ static_cast<std::uint64_t>(orbit)) + draw);
    return static_cast<double>(bits >> 11) * 0x1p-53;
}

/// Per-thread scratch: the programs take the caller's.
struct workspace {
    std::vector<double> symbols = std::vector<double>(5), outputs = std::vector<double>(6), factor = std::vector<double>(4);
    std::vector<double> scratch;
};

/// The compiled scene: M and f, and the energy function, in (q1, q2, q̇1, q̇2, t).
class section_problem {
public:
    section_problem(const model& scene, const equations_of_motion& equations, bool native)
    {
        const std::map<std::string, GiNaC::ex> values = merged_values(scene);
        const std::vector<GiNaC::ex> symbols = state_symbols(scene);
        const motion_expressions motion = motion_at_values(scene, equations, values);
        std::vector<GiNaC::ex> rhs_outputs = motion.mass;
        rhs_outputs.insert(rhs_outputs.end(), motion.force.begin(), motion.force.end());
        identity_mass = motion.mass.size() == 4 && motion.mass[0].is_equal(1) && motion.mass[1].is_zero() &&
                        motion.mass[2].is_zero() && motion.mass[3].is_equal(1);
        try {
            rhs_ = expression_program(rhs_outputs, symbols);
            energy_ = expression_program({at_values(equations.energy, scene, values)}, symbols);
        } catch (const std::invalid_argument& error) {
            throw computation_error(std::string("the equations of motion cannot be compiled: ") + error.what());
        }
        if (!native) {
            evaluation = "interpreter (--interpret)";
            return;
        }
        std::string why;
        module_ = native_module::compile({&rhs_}, {}, &why);
        if (module_) {
            native_rhs_ = module_->get(0);
            evaluation = "native code";
        } else {
            evaluation = "interpreter (" + why + ")";
        }
    }

    /// M (row-major) then f at (t, x) into work.outputs. Inline, with the state copied entry
    /// by entry (std::copy called memmove): it runs at every stage of every step.
    [[gnu::always_inline]] void mass_and_force(double t, const double* x, workspace& work) const
    {
        double* symbols = work.symbols.data();
        for (int i = 0; i < 4; ++i)
            symbols[i] = x[i];
        symbols[4] = t;
        if (native_rhs_)
            native_rhs_(work.symbols.data(), work.outputs.data());
        else
            rhs_.run(work.symbols.data(), work.scratch, work.outputs.data());
    }

    double energy(const double* x, workspace& work) const
    {
        std::copy(x, x + 4, work.symbols.begin());
        work.symbols[4] = 0;
        double h = 0;
        energy_.run(work.symbols.data(), work.scratch, &h);
        return h;
    }

    /// Whether the equations and the energy are 2π-periodic in coordinate c (an angle):
    /// checked at a few fixed states.
    bool periodic(std::size_t c, workspace& work) const
    {
        const double states[3][4] = {{0.3, -0.7, 0.2, 0.5}, {1.1, 0.4, -0.6, 0.1}, {-0.9, 2.3, 0.8, -1.2}};
        for (const auto& state : states) {
            double x[4], y[4];
            std::copy(state, state + 4, x);
            std::copy(state, state + 4, y);
            y[c] += 2 * pi;
            mass_and_force(0, x, work);
            std::vector<double> a = work.outputs;
            double ha = energy(x, work);
            mass_and_force(0, y, work);
            double hb = energy(y, work);
            auto close = [](double u, double v) { return std::abs(u - v) <= 1e-9 * (1 + std::abs(u)); };
            if (!close(ha, hb))
                return false;
            for (std::size_t i = 0; i < a.size(); ++i)
                if (!close(a[i], work.outputs[i]))
                    return false;
        }
        return true;
    }

private:
    expression_program rhs_, energy_;
    std::shared_ptr<native_module> module_;
    native_module::function native_rhs_ = nullptr;

public:
    std::string evaluation;
    /// M is the identity (Cartesian coordinates of unit mass, as Hénon–Heiles): q̈ = f.
    bool identity_mass = false;
};

/// The right-hand side for DOP853: (q̇, q̈) with M q̈ = f.
struct orbit_rhs {
    const section_problem* problem = nullptr;
    workspace* work = nullptr;
    [[gnu::always_inline]] void operator()(double t, const double* x, double* dxdt) const
    {
        problem->mass_and_force(t, x, *work);
        dxdt[0] = x[2];
        dxdt[1] = x[3];
        if (problem->identity_mass) { // the solve's own numbers for M = 1, without its division
            dxdt[2] = work->outputs[4];
            dxdt[3] = work->outputs[5];
            return;
        }
        if (!solve_mass_matrix(work->outputs.data(), 2, work->factor.data(), dxdt + 2))
            throw computation_error(singular_mass_matrix_message(t, x, 4));
    }
};

/// Where the orbits start: the interval [low, high] of the free coordinate on the section
/// that the energy reaches, and how fast the free coordinate may move there.
struct start_region {
    double low = 0, high = 0;
    double widest = 0; ///< the largest |q̇_free| allowed anywhere in [low, high] (a bound)
};

} // namespace

poincare_section parse_poincare_section(const std::string& text, const model& scene)
{
    poincare_section section;
    section.text = text;
    std::size_t at = skip_blanks(text, 0);
    std::size_t end = name_end(text, at);
    if (end == at)
        bad_section(text, at, "give the section as `q = level` or `q = level, q' > 0`");
    const std::string name = text.substr(at, end - at);
    section.coordinate = coordinate_index(text, at, name, scene);
    at = skip_blanks(text, end);
    if (at >= text.size() || text[at] != '=')
        bad_section(text, at, "expected `=` after `" + name + "`");
    at = skip_blanks(text, at + 1);
    std::size_t comma = text.find(',', at);
    std::string number = text.substr(at, (comma == std::string::npos ? text.size() : comma) - at);
    while (!number.empty() && number.back() == ' ')
        number.pop_back();
    char* stop = nullptr;
    section.level = std::strtod(number.c_str(), &stop);
    if (number.empty() || stop != number.c_str() + number.size() || number.find_first_of("xXpPnN") != std::string::npos ||
        !std::isfinite(section.level))
        bad_section(text, at, "the level `" + number + "` is not a number");
    if (comma == std::string::npos)
        return section;
    // The direction: `q' > 0`, `q' < 0` (or q_dot), of the section's coordinate.
    at = skip_blanks(text, comma + 1);
    end = name_end(text, at);
    std::string velocity = text.substr(at, end - at);
    bool primed = end < text.size() && text[end] == '\'';
    if (!primed && velocity.size() > 4 && velocity.compare(velocity.size() - 4, 4, "_dot") == 0)
        velocity.resize(velocity.size() - 4);
    else if (!primed)
        bad_section(text, at, "expected the direction as `" + name + "' > 0` or `" + name + "' < 0`");
    if (velocity != name) {
        coordinate_index(text, at, velocity, scene); // an unknown name is told as such
        bad_section(text, at, "the direction must be that of the section's coordinate, `" + name + "'`");
    }
    at = skip_blanks(text, end + (primed ? 1 : 0));
    if (at >= text.size() || (text[at] != '>' && text[at] != '<'))
        bad_section(text, at, "expected `> 0` or `< 0`");
    section.direction = text[at] == '>' ? 1 : -1;
    std::size_t zero = skip_blanks(text, at + 1);
    if (zero >= text.size() || text[zero] != '0' || skip_blanks(text, zero + 1) != text.size())
        bad_section(text, zero, "expected `0` (the direction is the sign of the velocity)");
    return section;
}

std::size_t poincare_result::crossings() const
{
    std::size_t total = 0;
    for (const poincare_orbit& o : orbits)
        total += o.points.size() / width();
    return total;
}

std::size_t poincare_result::steps() const
{
    std::size_t total = 0;
    for (const poincare_orbit& o : orbits)
        total += o.steps;
    return total;
}

std::size_t poincare_result::failures() const
{
    return static_cast<std::size_t>(
        std::count_if(orbits.begin(), orbits.end(), [](const poincare_orbit& o) { return !o.failure.empty(); }));
}

poincare_result compute_poincare(const model& scene, const equations_of_motion& equations,
                                 const equilibria_result* equilibria, const poincare_section& section,
                                 const poincare_settings& settings)
{
    const auto started = std::chrono::steady_clock::now();
    if (scene.coordinates.size() != 2)
        throw computation_error("a Poincaré section is drawn for two degrees of freedom, and the scene has " +
                                std::to_string(scene.coordinates.size()) + " coordinates");
    if (equations.constraints)
        throw computation_error("Poincaré sections of scenes with constraints are not implemented");
    const std::map<std::string, GiNaC::ex> values = merged_values(scene);
    if (equations.forces.any || at_values(equations.lagrangian, scene, values).has(scene.time))
        throw computation_error("a Poincaré section at fixed energy needs a conserved energy: the scene has "
                                "forces or an L that depends on t");
    if (!(settings.until > 0) || !(settings.tolerance > 0) || settings.orbits == 0 || settings.crossings == 0)
        throw std::invalid_argument("a Poincaré section needs orbits, crossings, an end time and a tolerance");

    poincare_result result;
    for (const coordinate& c : scene.coordinates)
        result.coordinates.push_back(c.name);
    result.section = section;
    result.energy = settings.energy;
    const std::size_t k = section.coordinate, j = 1 - k;
    result.free = j;
    const double E = settings.energy;
    const section_problem problem(scene, equations, settings.native);
    result.evaluation = problem.evaluation;
    workspace work;
    const bool periodic[2] = {problem.periodic(0, work), problem.periodic(1, work)};
    auto potential_in = [&](double qk, double qj, workspace& w) {
        double x[4] = {0, 0, 0, 0};
        x[k] = qk, x[j] = qj;
        return problem.energy(x, w);
    };
    auto potential = [&](double qk, double qj) { return potential_in(qk, qj, work); };

    // The minimum of the energy: the lowest equilibrium where the potential's Hessian (by
    // central differences) is positive definite. It is also the well's centre.
    double centre[2] = {0, 0};
    if (scene.initial)
        for (std::size_t c = 0; c < 2; ++c) {
            auto found = scene.initial->positions.find(scene.coordinates[c].name);
            if (found != scene.initial->positions.end())
                centre[c] = real_value(at_values(found->second, scene, values), "the initial value");
        }
    if (equilibria)
        for (const equilibrium_point& point : equilibria->points) {
            double q[2];
            try {
                for (std::size_t c = 0; c < 2; ++c)
                    q[c] = real_value(at_values(point.position[c], scene, values), "an equilibrium");
            } catch (const std::exception&) {
                continue;
            }
            auto v = [&](double a, double b) {
                double x[4] = {a, b, 0, 0};
                return problem.energy(x, work);
            };
            const double d0 = 1e-4 * (1 + std::abs(q[0])), d1 = 1e-4 * (1 + std::abs(q[1]));
            const double v0 = v(q[0], q[1]);
            const double h00 = (v(q[0] + d0, q[1]) - 2 * v0 + v(q[0] - d0, q[1])) / (d0 * d0);
            const double h11 = (v(q[0], q[1] + d1) - 2 * v0 + v(q[0], q[1] - d1)) / (d1 * d1);
            const double h01 = (v(q[0] + d0, q[1] + d1) - v(q[0] + d0, q[1] - d1) - v(q[0] - d0, q[1] + d1) +
                                v(q[0] - d0, q[1] - d1)) / (4 * d0 * d1);
            if (!(h00 > 0 && h00 * h11 - h01 * h01 > 0) || (result.has_minimum && v0 >= result.minimum))
                continue;
            result.has_minimum = true;
            result.minimum = v0;
            centre[0] = q[0], centre[1] = q[1];
        }
    if (result.has_minimum && E < result.minimum)
        throw poincare_request_error("the energy " + shortest(E) + " is below the minimum of the energy, " +
                                     shortest(result.minimum) + " at " + scene.coordinates[0].name + " = " +
                                     shortest(centre[0]) + ", " + scene.coordinates[1].name + " = " +
                                     shortest(centre[1]) + ": no motion has it");
    result.energy_scale = result.has_minimum && E > result.minimum ? E - result.minimum : std::max(std::abs(E), 1.0);

    // The edge of {V ≤ E} along the free coordinate from y0 (where V ≤ E) in direction `way`,
    // by doubling steps and TOMS 748; an angle's whole circle when it never leaves the set.
    auto edge = [&](double qk, double y0, double way) {
        auto g = [&](double y) { return potential(qk, y) - E; };
        double inside = 0, d = 1e-3 * (1 + std::abs(y0));
        for (;;) {
            if (periodic[j] && d >= pi)
                d = pi;
            double value = g(y0 + way * d);
            if (value > 0) {
                boost::uintmax_t iterations = 100;
                auto root = boost::math::tools::toms748_solve(
                    [&](double s) { return g(y0 + way * s); }, inside, d, g(y0 + way * inside), value,
                    boost::math::tools::eps_tolerance<double>(50), iterations);
                return y0 + way * root.first; // inside the set
            }
            if (periodic[j] && d >= pi)
                return y0 + way * pi;
            inside = d;
            d *= 2;
            if (d > 1e6)
                throw computation_error("the energy surface is unbounded along `" + scene.coordinates[j].name +
                                        "` on the section: the orbits would escape");
        }
    };
    auto outside = [&](std::string why) {
        result.no_crossings = std::move(why);
        result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        return result;
    };
    // The well's extent along the free coordinate through its centre, widened by half, is
    // where the section's lowest point is looked for.
    double window_low = centre[j] - pi, window_high = centre[j] + pi;
    if (potential(centre[k], centre[j]) <= E) {
        const double a = edge(centre[k], centre[j], -1), b = edge(centre[k], centre[j], 1);
        window_low = centre[j] - 1.5 * (centre[j] - a);
        window_high = centre[j] + 1.5 * (b - centre[j]);
        if (periodic[j]) {
            window_low = std::max(window_low, centre[j] - pi);
            window_high = std::min(window_high, centre[j] + pi);
        }
    }
    const double L = section.level;
    // A start must lie in the well, not in another part of {V ≤ E} (Hénon–Heiles' outer
    // region, where orbits escape): the segment from the well's centre to it must stay in the
    // set (the wells of interest are star-shaped about their minimum). Angles take the copy
    // of the point nearest the centre.
    auto visible = [&](double qk, double qj, workspace& w) {
        double target[2];
        target[k] = qk, target[j] = qj;
        for (std::size_t c = 0; c < 2; ++c)
            if (periodic[c])
                target[c] = centre[c] + std::remainder(target[c] - centre[c], 2 * pi);
        for (int s = 1; s <= 64; ++s) {
            const double u = s / 64.0;
            if (potential_in(centre[k] + u * (target[k] - centre[k]), centre[j] + u * (target[j] - centre[j]), w) > E)
                return false;
        }
        return true;
    };
    // The section's lowest point in the window that the centre sees.
    double lowest_y = 0, lowest_v = HUGE_VAL;
    for (int s = 0; s <= 400; ++s) {
        const double y = window_low + (window_high - window_low) * s / 400;
        const double v = potential(L, y);
        if (v < lowest_v && v <= E && visible(L, y, work))
            lowest_y = y, lowest_v = v;
    }
    const std::string& qk_name = scene.coordinates[k].name;
    if (lowest_v > E)
        return outside("the section " + qk_name + " = " + shortest(L) + " lies outside the energy surface h = " +
                       shortest(E) + " around the well at " + scene.coordinates[0].name + " = " + shortest(centre[0]) +
                       ", " + scene.coordinates[1].name + " = " + shortest(centre[1]) +
                       ": no orbit of that energy there reaches it");
    const auto lowest = boost::math::tools::brent_find_minima(
        [&](double y) { return potential(L, y); }, std::max(window_low, lowest_y - (window_high - window_low) / 400),
        std::min(window_high, lowest_y + (window_high - window_low) / 400), 40);
    start_region region;
    region.low = edge(L, lowest.first, -1);
    region.high = edge(L, lowest.first, 1);

    // The velocities at (L, y): h = ½ (a_kk q̇k² + 2 a_kj q̇k q̇j + a_jj q̇j²) + V, from h at unit velocities.
    struct quadratic {
        double v = 0, kk = 0, kj = 0, jj = 0;
    };
    auto velocity_form = [&](double y, workspace& w) {
        quadratic form;
        double x[4] = {0, 0, 0, 0};
        x[k] = L, x[j] = y;
        form.v = problem.energy(x, w);
        x[2 + k] = 1;
        form.kk = 2 * (problem.energy(x, w) - form.v);
        x[2 + j] = 1;
        const double both = 2 * (problem.energy(x, w) - form.v);
        x[2 + k] = 0;
        form.jj = 2 * (problem.energy(x, w) - form.v);
        form.kj = (both - form.kk - form.jj) / 2;
        return form;
    };
    // How fast the free coordinate may move at y: with a direction, q̇k must keep its sign,
    // so q̇j² ≤ 2(E − V)/a_jj; else any q̇k, so q̇j² ≤ 2(E − V)/(a_jj − a_kj²/a_kk).
    auto widest_at = [&](const quadratic& f) {
        const double room = std::max(0.0, E - f.v);
        const double stiffness = section.direction != 0 ? f.jj : f.jj - f.kj * f.kj / f.kk;
        return stiffness > 0 ? std::sqrt(2 * room / stiffness) : 0.0;
    };
    for (int s = 0; s <= 256; ++s)
        region.widest = std::max(region.widest,
                                 widest_at(velocity_form(region.low + (region.high - region.low) * s / 256, work)));
    region.widest *= 1.05;

    auto wrap = [&](std::size_t c, double q) {
        if (!periodic[c])
            return q;
        const double reference = c == k ? L : centre[c];
        return reference + std::remainder(q - reference, 2 * pi);
    };

    // One orbit: its start drawn uniformly over the region (by rejection), then integrated and cut.
    auto run_orbit = [&](std::size_t index, workspace& w) {
        poincare_orbit orbit;
        double x0[4] = {0, 0, 0, 0};
        bool found = false;
        for (std::size_t draw = 0; draw < 20000 && !found; draw += 2) {
            const double y = region.low + (region.high - region.low) * uniform(settings.seed, index, draw);
            const double v = region.widest * (2 * uniform(settings.seed, index, draw + 1) - 1);
            const quadratic f = velocity_form(y, w);
            if (!(std::abs(v) <= widest_at(f)) || !visible(L, y, w))
                continue;
            const double discriminant = std::max(0.0, 2 * f.kk * (E - f.v) - (f.kk * f.jj - f.kj * f.kj) * v * v);
            x0[k] = L, x0[j] = y, x0[2 + j] = v;
            x0[2 + k] = (-f.kj * v + (section.direction < 0 ? -1 : 1) * std::sqrt(discriminant)) / f.kk;
            found = true;
        }
        if (!found) {
            orbit.failure = "no start on the energy surface was drawn";
            return orbit;
        }
        auto record = [&](double t, const double* x) {
            orbit.points.push_back(t);
            for (std::size_t c = 0; c < 2; ++c)
                orbit.points.push_back(wrap(c, x[c]));
            orbit.points.push_back(x[2]);
            orbit.points.push_back(x[3]);
        };
        record(0, x0);
        std::size_t count = 1;
        orbit_rhs f{&problem, &w};
        dop853_stepper<4> stepper(4, std::max(settings.tolerance / 12, 1e-15)); // per step ÷12, as simulate
        try {
            stepper.start(f, 0.0, x0, settings.until);
            double before[4], at[4];
            struct crossing {
                double t;
                double x[4];
            };
            std::vector<crossing> found_now;
            while (count < settings.crossings && stepper.time() < settings.until) {
                const double t0 = stepper.time();
                std::copy(stepper.state(), stepper.state() + 4, before);
                if (!stepper.step(f, settings.until))
                    throw computation_error("the step size of dop853 collapsed at t = " + message_number(t0));
                if (++orbit.steps > settings.max_steps)
                    throw computation_error("the orbit took more than " + std::to_string(settings.max_steps) + " steps");
                const double t1 = stepper.time();
                const double* after = stepper.state();
                // The copies of the level the step may have met: for an angle, those next to both ends.
                double levels[2] = {L, L};
                if (periodic[k]) {
                    levels[0] = L + 2 * pi * std::round((before[k] - L) / (2 * pi));
                    levels[1] = L + 2 * pi * std::round((after[k] - L) / (2 * pi));
                }
                found_now.clear();
                for (int m = 0; m < (levels[1] != levels[0] ? 2 : 1); ++m) {
                    const double level = levels[m];
                    // On the stack: a vector here was a malloc and a free per step.
                    double times[9] = {t0, t1}, sides[9] = {before[k] - level, after[k] - level};
                    std::size_t samples = 2;
                    // Both ends on one side, moving towards the level at the start and away at the
                    // end: the orbit may have dipped through and back; look inside the step.
                    if (sides[0] * sides[1] > 0 && sides[0] * before[2 + k] < 0 && sides[1] * after[2 + k] > 0) {
                        for (int s = 1; s < 8; ++s) {
                            const double t = t0 + (t1 - t0) * s / 8;
                            stepper.interpolate(f, t, at);
                            times[s] = t;
                            sides[s] = at[k] - level;
                        }
                        times[8] = t1;
                        sides[8] = after[k] - level;
                        samples = 9;
                    }
                    for (std::size_t s = 0; s + 1 < samples; ++s) {
                        const bool up = sides[s] < 0 && sides[s + 1] >= 0, down = sides[s] > 0 && sides[s + 1] <= 0;
                        if (!(up && section.direction >= 0) && !(down && section.direction <= 0))
                            continue;
                        crossing c;
                        if (sides[s + 1] == 0) {
                            c.t = times[s + 1];
                        } else {
                            // The root of q_k(t) − level on the dense output, to the rounding of t.
                            boost::uintmax_t iterations = 200;
                            auto side = [&](double t) {
                                stepper.interpolate(f, t, at);
                                return at[k] - level;
                            };
                            auto root = boost::math::tools::toms748_solve(
                                side, times[s], times[s + 1], sides[s], sides[s + 1],
                                boost::math::tools::eps_tolerance<double>(53), iterations);
                            c.t = root.first + (root.second - root.first) / 2;
                        }
                        if (c.t == t1)
                            std::copy(after, after + 4, c.x);
                        else
                            stepper.interpolate(f, c.t, c.x);
                        found_now.push_back(c);
                    }
                }
                std::sort(found_now.begin(), found_now.end(),
                          [](const crossing& a, const crossing& b) { return a.t < b.t; });
                for (const crossing& c : found_now)
                    if (count < settings.crossings) {
                        record(c.t, c.x);
                        ++count;
                    }
            }
        } catch (const computation_error& error) {
            orbit.failure = error.what();
        }
        return orbit;
    };

    // The orbits on threads, each taking the next orbit not yet taken; stored by index.
    result.orbits.resize(settings.orbits);
    std::atomic<std::size_t> next{0};
    std::exception_ptr error;
    std::mutex error_mutex;
    auto worker = [&] {
        try {
            workspace w;
            for (std::size_t index = next++; index < settings.orbits; index = next++)
                result.orbits[index] = run_orbit(index, w);
        } catch (...) {
            std::lock_guard<std::mutex> lock(error_mutex);
            if (!error)
                error = std::current_exception();
            next = settings.orbits;
        }
    };
    const std::size_t threads = std::max<std::size_t>(
        1, std::min(settings.threads ? settings.threads : default_ensemble_threads(), settings.orbits));
    std::vector<std::thread> pool = start_threads(threads - 1, worker);
    worker();
    for (std::thread& t : pool)
        t.join();
    if (error)
        std::rethrow_exception(error);
    result.threads = pool.size() + 1;

    // The energy at every crossing, against E.
    for (const poincare_orbit& orbit : result.orbits)
        for (std::size_t p = 0; p + result.width() <= orbit.points.size(); p += result.width()) {
            const double h = problem.energy(orbit.points.data() + p + 1, work);
            result.worst_energy_error = std::max(result.worst_energy_error, std::abs(h - E) / result.energy_scale);
        }
    if (result.crossings() == 0)
        result.no_crossings = "no orbit could be started on the section";
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return result;
}

} // namespace lagrange
