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

#include <Eigen/Cholesky>
#include <Eigen/Core>

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
#include <type_traits>

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

/// Per-thread scratch for n coordinates: the programs take the caller's.
struct workspace {
    explicit workspace(std::size_t n) : symbols(2 * n + 1), outputs(n * n + n), factor(n * n) {}
    std::vector<double> symbols, outputs, factor;
    std::vector<double> scratch;
};

/// The compiled scene: M and f, and the energy function, in (q, q̇, t).
class section_problem {
public:
    section_problem(const model& scene, const equations_of_motion& equations, bool native)
        : n_(scene.coordinates.size())
    {
        const std::map<std::string, GiNaC::ex> values = merged_values(scene);
        const std::vector<GiNaC::ex> symbols = state_symbols(scene);
        const motion_expressions motion = motion_at_values(scene, equations, values);
        std::vector<GiNaC::ex> rhs_outputs = motion.mass;
        rhs_outputs.insert(rhs_outputs.end(), motion.force.begin(), motion.force.end());
        identity_mass = true;
        for (std::size_t i = 0; i < n_; ++i)
            for (std::size_t j = 0; j < n_; ++j)
                identity_mass = identity_mass && motion.mass[i * n_ + j].is_equal(i == j ? 1 : 0);
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

    std::size_t coordinates() const { return n_; }

    /// M (row-major) then f at (t, x) into work.outputs. Inline, with the state copied entry
    /// by entry (std::copy called memmove): it runs at every stage of every step.
    [[gnu::always_inline]] void mass_and_force(double t, const double* x, workspace& work) const
    {
        double* symbols = work.symbols.data();
        for (std::size_t i = 0; i < 2 * n_; ++i)
            symbols[i] = x[i];
        symbols[2 * n_] = t;
        if (native_rhs_)
            native_rhs_(work.symbols.data(), work.outputs.data());
        else
            rhs_.run(work.symbols.data(), work.scratch, work.outputs.data());
    }

    double energy(const double* x, workspace& work) const
    {
        std::copy(x, x + 2 * n_, work.symbols.begin());
        work.symbols[2 * n_] = 0;
        double h = 0;
        energy_.run(work.symbols.data(), work.scratch, &h);
        return h;
    }

    /// Whether the equations and the energy are 2π-periodic in coordinate c (an angle):
    /// checked at a few fixed states.
    bool periodic(std::size_t c, workspace& work) const
    {
        for (int s = 0; s < 3; ++s) {
            // Fixed, unremarkable states (no symmetry of the scene should hold at them by chance).
            std::vector<double> x(2 * n_), y;
            for (std::size_t i = 0; i < 2 * n_; ++i)
                x[i] = 1.3 * std::sin(1.7 * (s + 1) * (i + 1) + 0.3);
            y = x;
            y[c] += 2 * pi;
            mass_and_force(0, x.data(), work);
            std::vector<double> a = work.outputs;
            double ha = energy(x.data(), work);
            mass_and_force(0, y.data(), work);
            double hb = energy(y.data(), work);
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
    std::size_t n_;
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
        const std::size_t n = problem->coordinates();
        problem->mass_and_force(t, x, *work);
        std::copy(x + n, x + 2 * n, dxdt);
        if (problem->identity_mass) { // the solve's own numbers for M = 1, without its division
            std::copy(work->outputs.data() + n * n, work->outputs.data() + n * n + n, dxdt + n);
            return;
        }
        if (!solve_mass_matrix(work->outputs.data(), n, work->factor.data(), dxdt + n))
            throw computation_error(singular_mass_matrix_message(t, x, 2 * n));
    }
};

/// visit(q) at every point of a grid of `points` values of each free coordinate from low to
/// high (q's other entries as they are), the first free coordinate the fastest.
template <class Visit>
void for_each_grid_point(std::vector<double>& q, const std::vector<std::size_t>& free, const std::vector<double>& low,
                         const std::vector<double>& high, std::size_t points, Visit&& visit)
{
    std::vector<std::size_t> index(free.size(), 0);
    for (bool more = true; more;) {
        for (std::size_t i = 0; i < free.size(); ++i)
            q[free[i]] = low[free[i]] + (high[free[i]] - low[free[i]]) * index[i] / (points - 1);
        visit(q);
        more = false;
        for (std::size_t i = 0; i < free.size() && !more; ++i) {
            if (++index[i] < points)
                more = true;
            else
                index[i] = 0;
        }
    }
}

/// The largest speed of one free coordinate where ½ s v² ≤ room (0 where none is allowed).
double widest_speed(double room, double stiff)
{
    return room >= 0 && stiff > 0 ? std::sqrt(2 * room / stiff) : 0.0;
}

/// The volume of the velocity ellipsoid ½ vᵀ S v ≤ room, up to a constant factor:
/// room^(m/2) / sqrt(det S), with S = L Lᵀ from `factor`.
double ellipsoid_weight(double room, const Eigen::LLT<Eigen::MatrixXd>& factor)
{
    return std::pow(room, 0.5 * static_cast<double>(factor.rows())) / factor.matrixLLT().diagonal().prod();
}

/// Where the orbits start: a box of the free coordinates on the section that holds the part
/// of it the energy reaches, and a bound on each free coordinate's speed there.
struct start_region {
    std::vector<double> low, high; ///< per coordinate (the section's own: its level)
    std::vector<double> widest;    ///< the largest |q̇_j| allowed anywhere in the box (a bound)
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

poincare_axes parse_poincare_axes(const std::string& text, const model& scene, const poincare_section& section)
{
    auto bad = [&](std::size_t column, const std::string& message) {
        scene_error error({"--axes", 1, static_cast<int>(column) + 1}, message);
        error.attach_line_text(text);
        throw error;
    };
    const std::size_t n = scene.coordinates.size();
    std::size_t columns[2] = {0, 0};
    std::size_t at = 0;
    for (int axis = 0; axis < 2; ++axis) {
        at = skip_blanks(text, at);
        const std::size_t end = name_end(text, at);
        if (end == at)
            bad(at, "give the axes as two of the section's coordinates or velocities, such as `y, y'`");
        std::string name = text.substr(at, end - at);
        std::size_t after = end;
        bool velocity = after < text.size() && text[after] == '\'';
        if (velocity)
            ++after;
        else if (name.size() > 4 && name.compare(name.size() - 4, 4, "_dot") == 0 &&
                 std::none_of(scene.coordinates.begin(), scene.coordinates.end(),
                              [&](const coordinate& c) { return c.name == name; })) {
            name.resize(name.size() - 4);
            velocity = true;
        }
        std::size_t c = 0;
        while (c < n && scene.coordinates[c].name != name)
            ++c;
        if (c == n) {
            std::string list;
            for (const coordinate& q : scene.coordinates)
                list += (list.empty() ? "" : ", ") + q.name;
            bad(at, "`" + name + "` is not a coordinate of the scene (its coordinates: " + list + ")");
        }
        if (c == section.coordinate && !velocity)
            bad(at, "`" + name + "` is the section's coordinate: it is " + shortest(section.level) +
                        " at every crossing; choose two of the other coordinates or the velocities");
        columns[axis] = 1 + (velocity ? n : 0) + c;
        at = skip_blanks(text, after);
        if (axis == 0) {
            if (at >= text.size() || text[at] != ',')
                bad(at, "expected `,` and the vertical axis");
            ++at;
        } else if (at != text.size()) {
            bad(at, "expected the end after two axes");
        }
    }
    return {columns[0], columns[1]};
}

poincare_axes default_poincare_axes(const model& scene, const poincare_section& section)
{
    const std::size_t n = scene.coordinates.size();
    const std::size_t j = section.coordinate == 0 ? 1 : 0;
    return {1 + j, 1 + n + j};
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
    const std::size_t n = scene.coordinates.size();
    if (n < 2)
        throw computation_error("a Poincaré section is drawn for two or more degrees of freedom, and the scene has " +
                                std::to_string(n) + (n == 1 ? " coordinate" : " coordinates"));
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
    const std::size_t k = section.coordinate;
    std::vector<std::size_t> free; // the section's other coordinates, in order
    for (std::size_t c = 0; c < n; ++c)
        if (c != k)
            free.push_back(c);
    const std::size_t m = free.size(); // n − 1: the section has 2m dimensions
    result.axes = default_poincare_axes(scene, section);
    const double E = settings.energy;
    const section_problem problem(scene, equations, settings.native);
    result.evaluation = problem.evaluation;
    workspace work(n);
    std::vector<bool> periodic(n);
    for (std::size_t c = 0; c < n; ++c)
        periodic[c] = problem.periodic(c, work);
    // h(q, 0): the potential part of the energy at a configuration.
    auto potential_in = [&](const std::vector<double>& q, workspace& w) {
        std::vector<double> x(2 * n, 0.0);
        std::copy(q.begin(), q.end(), x.begin());
        return problem.energy(x.data(), w);
    };
    auto potential = [&](const std::vector<double>& q) { return potential_in(q, work); };
    auto at_text = [&](const std::vector<double>& q) {
        std::string text;
        for (std::size_t c = 0; c < n; ++c)
            text += (c ? ", " : "") + scene.coordinates[c].name + " = " + shortest(q[c]);
        return text;
    };

    // The minimum of the energy: the lowest equilibrium where the potential's Hessian (by
    // central differences) is positive definite. It is also the well's centre.
    std::vector<double> centre(n, 0.0);
    if (scene.initial)
        for (std::size_t c = 0; c < n; ++c) {
            auto found = scene.initial->positions.find(scene.coordinates[c].name);
            if (found != scene.initial->positions.end())
                centre[c] = real_value(at_values(found->second, scene, values), "the initial value");
        }
    if (equilibria)
        for (const equilibrium_point& point : equilibria->points) {
            std::vector<double> q(n);
            try {
                for (std::size_t c = 0; c < n; ++c)
                    q[c] = real_value(at_values(point.position[c], scene, values), "an equilibrium");
            } catch (const std::exception&) {
                continue;
            }
            auto v = [&](std::size_t a, double da, std::size_t b, double db) {
                std::vector<double> p = q;
                p[a] += da;
                p[b] += db;
                return potential(p);
            };
            std::vector<double> d(n);
            for (std::size_t c = 0; c < n; ++c)
                d[c] = 1e-4 * (1 + std::abs(q[c]));
            const double v0 = potential(q);
            Eigen::MatrixXd hessian(n, n);
            for (std::size_t a = 0; a < n; ++a) {
                hessian(a, a) = (v(a, d[a], a, 0) - 2 * v0 + v(a, -d[a], a, 0)) / (d[a] * d[a]);
                for (std::size_t b = a + 1; b < n; ++b)
                    hessian(a, b) = hessian(b, a) = (v(a, d[a], b, d[b]) - v(a, d[a], b, -d[b]) -
                                                     v(a, -d[a], b, d[b]) + v(a, -d[a], b, -d[b])) /
                                                    (4 * d[a] * d[b]);
            }
            if (hessian.llt().info() != Eigen::Success || (result.has_minimum && v0 >= result.minimum))
                continue;
            result.has_minimum = true;
            result.minimum = v0;
            centre = q;
        }
    if (result.has_minimum && E < result.minimum)
        throw poincare_request_error("the energy " + shortest(E) + " is below the minimum of the energy, " +
                                     shortest(result.minimum) + " at " + at_text(centre) + ": no motion has it");
    result.energy_scale = result.has_minimum && E > result.minimum ? E - result.minimum : std::max(std::abs(E), 1.0);

    // The edge of {V ≤ E} from p (where V ≤ E) along the direction u (free coordinates only),
    // by doubling steps and TOMS 748; where an angle has turned by π when it never leaves the set.
    auto edge = [&](const std::vector<double>& p, const std::vector<double>& u) {
        auto along = [&](double s) {
            std::vector<double> q = p;
            for (std::size_t c = 0; c < n; ++c)
                q[c] += s * u[c];
            return q;
        };
        auto g = [&](double s) { return potential(along(s)) - E; };
        double cap = HUGE_VAL, start = 0;
        std::string names;
        for (std::size_t c = 0; c < n; ++c)
            if (u[c] != 0) {
                if (periodic[c])
                    cap = std::min(cap, pi / std::abs(u[c]));
                start += p[c] * u[c];
                names += (names.empty() ? "`" : ", `") + scene.coordinates[c].name + "`";
            }
        double inside = 0, d = 1e-3 * (1 + std::abs(start));
        for (;;) {
            if (d >= cap)
                d = cap;
            double value = g(d);
            if (value > 0) {
                boost::uintmax_t iterations = 100;
                auto root = boost::math::tools::toms748_solve(g, inside, d, g(inside), value,
                                                              boost::math::tools::eps_tolerance<double>(50), iterations);
                return along(root.first); // inside the set
            }
            if (d >= cap)
                return along(cap);
            inside = d;
            d *= 2;
            if (d > 1e6)
                throw computation_error("the energy surface is unbounded along " + names +
                                        " on the section: the orbits would escape");
        }
    };
    auto axis = [&](std::size_t c, double sign) {
        std::vector<double> u(n, 0.0);
        u[c] = sign;
        return u;
    };
    auto outside = [&](std::string why) {
        result.no_crossings = std::move(why);
        result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        return result;
    };
    // The well's extent along each free coordinate through its centre, widened by half, is
    // where the section's lowest point is looked for.
    std::vector<double> window_low(n), window_high(n);
    const bool centre_inside = potential(centre) <= E;
    for (std::size_t j : free) {
        window_low[j] = centre[j] - pi, window_high[j] = centre[j] + pi;
        if (!centre_inside)
            continue;
        const double a = edge(centre, axis(j, -1))[j], b = edge(centre, axis(j, 1))[j];
        window_low[j] = centre[j] - 1.5 * (centre[j] - a);
        window_high[j] = centre[j] + 1.5 * (b - centre[j]);
        if (periodic[j]) {
            window_low[j] = std::max(window_low[j], centre[j] - pi);
            window_high[j] = std::min(window_high[j], centre[j] + pi);
        }
    }
    const double L = section.level;
    // A start must lie in the well, not in another part of {V ≤ E} (Hénon–Heiles' outer
    // region, where orbits escape): the segment from the well's centre to it must stay in the
    // set (the wells of interest are star-shaped about their minimum). Angles take the copy
    // of the point nearest the centre.
    auto visible = [&](const std::vector<double>& q, workspace& w) {
        std::vector<double> target = q, between(n);
        for (std::size_t c = 0; c < n; ++c)
            if (periodic[c])
                target[c] = centre[c] + std::remainder(target[c] - centre[c], 2 * pi);
        for (int s = 1; s <= 64; ++s) {
            const double u = s / 64.0;
            for (std::size_t c = 0; c < n; ++c)
                between[c] = centre[c] + u * (target[c] - centre[c]);
            if (potential_in(between, w) > E)
                return false;
        }
        return true;
    };
    // The section's lowest point in the window that the centre sees: on a grid of about 400
    // points (401 on a line), then refined by Brent's method one coordinate at a time within
    // a grid spacing (once for one free coordinate, three sweeps for more).
    const std::size_t grid = m == 1 ? 401 : static_cast<std::size_t>(std::ceil(std::pow(400.0, 1.0 / m))) + 1;
    std::vector<double> lowest(n), q(n);
    q[k] = lowest[k] = L;
    double lowest_v = HUGE_VAL;
    for_each_grid_point(q, free, window_low, window_high, grid, [&](const std::vector<double>& at) {
        const double v = potential(at);
        if (v < lowest_v && v <= E && visible(at, work))
            lowest = at, lowest_v = v;
    });
    const std::string& qk_name = scene.coordinates[k].name;
    if (lowest_v > E)
        return outside("the section " + qk_name + " = " + shortest(L) + " lies outside the energy surface h = " +
                       shortest(E) + " around the well at " + at_text(centre) +
                       ": no orbit of that energy there reaches it");
    const std::vector<double> grid_lowest = lowest;
    for (int sweep = 0; sweep < (m == 1 ? 1 : 3); ++sweep)
        for (std::size_t j : free) {
            const double spacing = (window_high[j] - window_low[j]) / (grid - 1);
            std::vector<double> p = lowest;
            const auto best = boost::math::tools::brent_find_minima(
                [&](double y) {
                    p[j] = y;
                    return potential(p);
                },
                std::max(window_low[j], grid_lowest[j] - spacing), std::min(window_high[j], grid_lowest[j] + spacing),
                40);
            lowest[j] = best.first;
        }

    // The box: the edges of the section's part {V ≤ E} from its lowest point, along each free
    // coordinate both ways and, with more than one, along the 2^m diagonals (scaled by the
    // window), widened by a quarter of its width on each side (the region need not be a box:
    // the starts are drawn by rejection, and only a box too small would bias them).
    start_region region;
    region.low.assign(n, L), region.high.assign(n, L);
    auto include = [&](const std::vector<double>& p) {
        for (std::size_t j : free) {
            region.low[j] = std::min(region.low[j], p[j]);
            region.high[j] = std::max(region.high[j], p[j]);
        }
    };
    for (std::size_t j : free)
        region.low[j] = region.high[j] = lowest[j];
    for (std::size_t j : free)
        for (double sign : {-1.0, 1.0})
            include(edge(lowest, axis(j, sign)));
    if (m > 1) {
        for (std::size_t signs = 0; signs < (std::size_t{1} << m); ++signs) {
            std::vector<double> u(n, 0.0);
            double norm = 0;
            for (std::size_t i = 0; i < m; ++i) {
                const double width = window_high[free[i]] - window_low[free[i]];
                u[free[i]] = (signs >> i & 1 ? -1 : 1) * width;
                norm += width * width;
            }
            for (double& c : u)
                c /= std::sqrt(norm);
            include(edge(lowest, u));
        }
        for (std::size_t j : free) {
            const double widen = (region.high[j] - region.low[j]) / 4;
            region.low[j] -= widen, region.high[j] += widen;
            if (periodic[j]) {
                region.low[j] = std::max(region.low[j], lowest[j] - pi);
                region.high[j] = std::min(region.high[j], lowest[j] + pi);
            }
        }
    }

    // The velocities at q: h = ½ q̇ᵀ A(q) q̇ + V(q), A from h at unit velocities and their sums.
    struct quadratic {
        double v = 0;
        Eigen::MatrixXd a;
    };
    auto velocity_form = [&](const std::vector<double>& at, workspace& w) {
        quadratic form;
        std::vector<double> x(2 * n, 0.0);
        std::copy(at.begin(), at.end(), x.begin());
        form.v = problem.energy(x.data(), w);
        form.a.resize(n, n);
        for (std::size_t a = 0; a < n; ++a) {
            x[n + a] = 1;
            form.a(a, a) = 2 * (problem.energy(x.data(), w) - form.v);
            x[n + a] = 0;
        }
        for (std::size_t a = 0; a < n; ++a)
            for (std::size_t b = a + 1; b < n; ++b) {
                x[n + a] = x[n + b] = 1;
                const double both = 2 * (problem.energy(x.data(), w) - form.v);
                x[n + a] = x[n + b] = 0;
                form.a(a, b) = form.a(b, a) = (both - form.a(a, a) - form.a(b, b)) / 2;
            }
        return form;
    };
    // The free velocities v allowed at q: with a direction, q̇k must keep its sign, so
    // ½ vᵀ A_JJ v ≤ E − V (then q̇k = 0 leaves room, and a root of each sign exists); else any
    // q̇k, so ½ vᵀ S v ≤ E − V with S = A_JJ − A_Jk A_kJ / a_kk (q̇k at its best).
    auto stiffness = [&](const quadratic& f) {
        Eigen::MatrixXd s(m, m);
        for (std::size_t a = 0; a < m; ++a)
            for (std::size_t b = 0; b < m; ++b)
                s(a, b) = f.a(free[a], free[b]) -
                          (section.direction != 0 ? 0.0 : f.a(free[a], k) * f.a(k, free[b]) / f.a(k, k));
        return s;
    };
    // One free coordinate: the largest |v| there, sqrt(2 (E − V) / S), bounds the velocity's
    // draw. More: the volume of the velocity ellipsoid at q, ∝ w(q) = (E − V)^(m/2) / sqrt(det S),
    // weighs the positions' draw (its largest, over the grid, bounds it).
    region.widest.assign(n, 0.0);
    double heaviest = 0;
    const std::size_t speed_grid =
        m == 1 ? 257 : static_cast<std::size_t>(std::ceil(std::pow(256.0, 1.0 / m))) + 1;
    for_each_grid_point(q, free, region.low, region.high, speed_grid, [&](const std::vector<double>& at) {
        const quadratic f = velocity_form(at, work);
        const double room = std::max(0.0, E - f.v);
        const Eigen::MatrixXd s = stiffness(f);
        if (m == 1) {
            region.widest[free[0]] = std::max(region.widest[free[0]], widest_speed(room, s(0, 0)));
        } else if (room > 0) {
            Eigen::LLT<Eigen::MatrixXd> factor(s);
            if (factor.info() == Eigen::Success)
                heaviest = std::max(heaviest, ellipsoid_weight(room, factor));
        }
    });
    for (double& w : region.widest)
        w *= 1.05; // the grid misses the peak between its points
    heaviest *= 1.25;
    std::atomic<std::size_t> overweight{0}; // starts whose weight passed the bound (a bias)

    auto wrap = [&](std::size_t c, double value) {
        if (!periodic[c])
            return value;
        const double reference = c == k ? L : centre[c];
        return reference + std::remainder(value - reference, 2 * pi);
    };

    // Orbit `index`'s start: uniform in the free coordinates and velocities (q_J, q̇_J) over
    // the part of the section where the centre sees q and ½ q̇_Jᵀ S q̇_J ≤ E − V(q); then q̇k
    // solves h = E with the section's sign (+ without one). One free coordinate: (q_J, q̇_J)
    // by rejection from the box and the speed bound, 2 numbers a try. More: q_J by rejection
    // from the box, kept with probability w(q)/bound (the velocity ellipsoid's volume), then
    // q̇_J uniformly in that ellipsoid — a Gaussian direction (Box–Muller) and a radius
    // u^(1/m) — so the velocities' dimensions cost no rejection; m + 2 + 2⌈m/2⌉ numbers a try.
    const std::size_t per_try = m == 1 ? 2 : m + 2 + 2 * ((m + 1) / 2);
    const std::size_t tries = m == 1 ? 10000 : 100000;
    auto draw_start = [&](std::size_t index, std::vector<double>& x0, workspace& w) {
        std::vector<double> at(n);
        Eigen::VectorXd speeds(m);
        for (std::size_t draw = 0; draw < tries * per_try; draw += per_try) {
            at[k] = L;
            for (std::size_t i = 0; i < m; ++i) {
                const std::size_t j = free[i];
                at[j] = region.low[j] + (region.high[j] - region.low[j]) * uniform(settings.seed, index, draw + i);
                if (m == 1)
                    speeds(0) = region.widest[j] * (2 * uniform(settings.seed, index, draw + 1) - 1);
            }
            const quadratic f = velocity_form(at, w);
            const double room = E - f.v;
            if (m == 1) {
                // One free coordinate: |v| against the bound itself (as sqrt(2 room / s)).
                if (!(std::abs(speeds(0)) <= widest_speed(room, stiffness(f)(0, 0))) || !visible(at, w))
                    continue;
            } else {
                if (!(room > 0))
                    continue;
                const Eigen::LLT<Eigen::MatrixXd> factor(stiffness(f));
                if (factor.info() != Eigen::Success)
                    continue;
                const double weight = ellipsoid_weight(room, factor);
                if (weight > heaviest)
                    ++overweight;
                if (!(uniform(settings.seed, index, draw + m) * heaviest <= weight) || !visible(at, w))
                    continue;
                // A point uniform in the unit m-ball: a Gaussian direction, the radius u^(1/m).
                Eigen::VectorXd y(m);
                for (std::size_t i = 0; i < m; i += 2) {
                    const double u1 = uniform(settings.seed, index, draw + m + 1 + i);
                    const double u2 = uniform(settings.seed, index, draw + m + 2 + i);
                    const double r = std::sqrt(-2 * std::log1p(-u1)), angle = 2 * pi * u2;
                    y(static_cast<Eigen::Index>(i)) = r * std::cos(angle);
                    if (i + 1 < m)
                        y(static_cast<Eigen::Index>(i + 1)) = r * std::sin(angle);
                }
                if (!(y.norm() > 0))
                    continue;
                const double radius = std::pow(uniform(settings.seed, index, draw + per_try - 1), 1.0 / static_cast<double>(m));
                y *= radius / y.norm();
                // ½ vᵀ S v = room |y|² for v = sqrt(2 room) L^{-T} y, S = L Lᵀ.
                speeds = std::sqrt(2 * room) * factor.matrixU().solve(y);
            }
            // ½ a_kk q̇k² + b q̇k + c = E − V, b = A_kJ v, c = ½ vᵀ A_JJ v.
            double b = 0, c = 0;
            for (std::size_t i = 0; i < m; ++i) {
                b += f.a(k, free[i]) * speeds(static_cast<Eigen::Index>(i));
                for (std::size_t i2 = 0; i2 < m; ++i2)
                    c += 0.5 * f.a(free[i], free[i2]) * speeds(static_cast<Eigen::Index>(i)) *
                         speeds(static_cast<Eigen::Index>(i2));
            }
            const double discriminant = std::max(0.0, b * b - 2 * f.a(k, k) * (c - room));
            std::fill(x0.begin(), x0.end(), 0.0);
            std::copy(at.begin(), at.end(), x0.begin());
            for (std::size_t i = 0; i < m; ++i)
                x0[n + free[i]] = speeds(static_cast<Eigen::Index>(i));
            x0[n + k] = (-b + (section.direction < 0 ? -1 : 1) * std::sqrt(discriminant)) / f.a(k, k);
            return true;
        }
        return false;
    };

    // One orbit: drawn, then integrated by DOP853 (a fixed dimension for two coordinates, as
    // the ensembles' common case) and cut.
    auto integrate_orbit = [&](auto dimension, const std::vector<double>& x0, poincare_orbit& orbit, workspace& w) {
        constexpr int Dim = decltype(dimension)::value;
        std::size_t count = 1;
        orbit_rhs f{&problem, &w};
        auto record = [&](double t, const double* x) {
            orbit.points.push_back(t);
            for (std::size_t c = 0; c < n; ++c)
                orbit.points.push_back(wrap(c, x[c]));
            orbit.points.insert(orbit.points.end(), x + n, x + 2 * n);
        };
        record(0, x0.data());
        dop853_stepper<Dim> stepper(2 * n, std::max(settings.tolerance / 12, 1e-15)); // per step ÷12, as simulate
        stepper.start(f, 0.0, x0.data(), settings.until);
        std::vector<double> before(2 * n), at(2 * n);
        struct crossing {
            double t;
            std::vector<double> x;
        };
        std::vector<crossing> found_now;
        while (count < settings.crossings && stepper.time() < settings.until) {
            const double t0 = stepper.time();
            std::copy(stepper.state(), stepper.state() + 2 * n, before.begin());
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
            for (int copy = 0; copy < (levels[1] != levels[0] ? 2 : 1); ++copy) {
                const double level = levels[copy];
                // On the stack: a vector here was a malloc and a free per step.
                double times[9] = {t0, t1}, sides[9] = {before[k] - level, after[k] - level};
                std::size_t samples = 2;
                // Both ends on one side, moving towards the level at the start and away at the
                // end: the orbit may have dipped through and back; look inside the step.
                if (sides[0] * sides[1] > 0 && sides[0] * before[n + k] < 0 && sides[1] * after[n + k] > 0) {
                    for (int s = 1; s < 8; ++s) {
                        const double t = t0 + (t1 - t0) * s / 8;
                        stepper.interpolate(f, t, at.data());
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
                    crossing c{times[s + 1], std::vector<double>(2 * n)};
                    if (sides[s + 1] != 0) {
                        // The root of q_k(t) − level on the dense output, to the rounding of t.
                        boost::uintmax_t iterations = 200;
                        auto side = [&](double t) {
                            stepper.interpolate(f, t, at.data());
                            return at[k] - level;
                        };
                        auto root = boost::math::tools::toms748_solve(side, times[s], times[s + 1], sides[s],
                                                                      sides[s + 1],
                                                                      boost::math::tools::eps_tolerance<double>(53),
                                                                      iterations);
                        c.t = root.first + (root.second - root.first) / 2;
                    }
                    if (c.t == t1)
                        std::copy(after, after + 2 * n, c.x.begin());
                    else
                        stepper.interpolate(f, c.t, c.x.data());
                    found_now.push_back(std::move(c));
                }
            }
            std::sort(found_now.begin(), found_now.end(), [](const crossing& a, const crossing& b) { return a.t < b.t; });
            for (const crossing& c : found_now)
                if (count < settings.crossings) {
                    record(c.t, c.x.data());
                    ++count;
                }
        }
    };
    auto run_orbit = [&](std::size_t index, workspace& w) {
        poincare_orbit orbit;
        std::vector<double> x0(2 * n);
        if (!draw_start(index, x0, w)) {
            orbit.failure = "no start on the energy surface was drawn";
            return orbit;
        }
        try {
            if (n == 2)
                integrate_orbit(std::integral_constant<int, 4>{}, x0, orbit, w);
            else
                integrate_orbit(std::integral_constant<int, 0>{}, x0, orbit, w);
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
            workspace w(n);
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
    result.overweight_starts = overweight;

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
