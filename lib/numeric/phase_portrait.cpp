// SPDX-License-Identifier: GPL-2.0-or-later
/** @file phase_portrait.cpp
 *  The phase portrait's grid and energies (see phase_portrait.h). */
#include "numeric/phase_portrait.h"

#include "numeric/compiled_motion.h"
#include "numeric/values.h"
#include "program/expression_program.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace lagrange {

namespace {

constexpr double pi = 3.141592653589793238462643383279502884;

struct numeric_equilibrium {
    std::vector<double> q;
    bool stable = false;
};

} // namespace

std::size_t phase_coordinate(const std::string& name, const model& scene)
{
    std::string list;
    for (std::size_t k = 0; k < scene.coordinates.size(); ++k) {
        if (scene.coordinates[k].name == name)
            return k;
        list += (list.empty() ? "" : ", ") + scene.coordinates[k].name;
    }
    scene_error error({"--coordinate", 1, 1}, "`" + name + "` is not a coordinate of the scene (its coordinates: " +
                                                   list + ")");
    error.attach_line_text(name);
    throw error;
}

phase_portrait compute_phase_portrait(const model& scene, const equations_of_motion& equations,
                                      const equilibria_result* equilibria, const phase_settings& settings)
{
    const std::size_t n = scene.coordinates.size(), c = settings.coordinate;
    if (n == 0 || c >= n)
        throw computation_error("the scene has no coordinate to draw the phase portrait of");
    if (equations.constraints)
        throw computation_error("phase portraits of scenes with constraints are not implemented");
    const std::map<std::string, GiNaC::ex> values = merged_values(scene);
    if (equations.forces.any || at_values(equations.lagrangian, scene, values).has(scene.time))
        throw computation_error("a phase portrait by energy needs a conserved energy: the scene has forces or an L "
                                "that depends on t");
    if (settings.grid < 3 || settings.levels == 0)
        throw std::invalid_argument("a phase portrait needs a grid of at least 3 points and one level");
    expression_program program;
    try {
        program = expression_program({at_values(equations.energy, scene, values)}, state_symbols(scene));
    } catch (const std::invalid_argument& error) {
        throw computation_error(std::string("the energy cannot be compiled: ") + error.what());
    }
    std::vector<double> symbols(2 * n + 1, 0.0), scratch;
    auto energy = [&](const std::vector<double>& q, double velocity) {
        std::fill(symbols.begin(), symbols.end(), 0.0);
        std::copy(q.begin(), q.end(), symbols.begin());
        symbols[n + c] = velocity;
        double h = 0;
        program.run(symbols.data(), scratch, &h);
        return h;
    };

    // The equilibria at the parameter values, stable where the potential's Hessian (central
    // differences) is positive definite.
    std::vector<numeric_equilibrium> points;
    if (equilibria)
        for (const equilibrium_point& point : equilibria->points) {
            numeric_equilibrium e;
            try {
                for (const GiNaC::ex& x : point.position)
                    e.q.push_back(real_value(at_values(x, scene, values), "an equilibrium"));
            } catch (const std::exception&) {
                continue;
            }
            Eigen::MatrixXd hessian(n, n);
            const double v0 = energy(e.q, 0);
            for (std::size_t a = 0; a < n; ++a)
                for (std::size_t b = 0; b < n; ++b) {
                    const double da = 1e-4 * (1 + std::abs(e.q[a])), db = 1e-4 * (1 + std::abs(e.q[b]));
                    auto at = [&](double sa, double sb) {
                        std::vector<double> q = e.q;
                        q[a] += sa * da;
                        q[b] += sb * db;
                        return energy(q, 0);
                    };
                    hessian(a, b) = a == b ? (at(1, 0) - 2 * v0 + at(-1, 0)) / (da * da)
                                           : (at(1, 1) - at(1, -1) - at(-1, 1) + at(-1, -1)) / (4 * da * db);
                }
            e.stable = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(hessian, Eigen::EigenvaluesOnly)
                           .eigenvalues()
                           .minCoeff() > 0;
            points.push_back(e);
        }
    // The slice goes through the lowest stable equilibrium (else the initial state, else 0).
    std::vector<double> base(n, 0.0);
    if (scene.initial)
        for (std::size_t k = 0; k < n; ++k) {
            auto found = scene.initial->positions.find(scene.coordinates[k].name);
            if (found != scene.initial->positions.end())
                base[k] = real_value(at_values(found->second, scene, values), "the initial value");
        }
    const std::vector<double> initial = base;
    bool have_stable = false;
    double lowest = 0;
    for (const numeric_equilibrium& e : points)
        if (e.stable && (!have_stable || energy(e.q, 0) < lowest)) {
            have_stable = true;
            lowest = energy(e.q, 0);
            base = e.q;
        }
    // Whether the energy is 2π-periodic in the coordinate (an angle).
    bool periodic = true;
    for (double shift : {0.3, -1.1, 2.4}) {
        std::vector<double> q = base, r = base;
        q[c] += shift;
        r[c] += shift + 2 * pi;
        const double a = energy(q, 0.7), b = energy(r, 0.7);
        periodic = periodic && std::abs(a - b) <= 1e-9 * (1 + std::abs(a));
    }
    // The equilibria on the slice (the other coordinates at the base's values).
    std::vector<const numeric_equilibrium*> on_slice;
    for (const numeric_equilibrium& e : points) {
        bool same = true;
        for (std::size_t k = 0; k < n; ++k)
            same = same && (k == c || std::abs(e.q[k] - base[k]) <= 1e-9 * (1 + std::abs(base[k])));
        if (same)
            on_slice.push_back(&e);
    }

    phase_portrait portrait;
    portrait.coordinate = scene.coordinates[c].name;
    portrait.grid = settings.grid;
    const double centre = base[c];
    if (periodic) {
        portrait.q_low = centre - pi;
        portrait.q_high = centre + pi;
    } else {
        double low = centre, high = centre;
        for (const numeric_equilibrium* e : on_slice)
            low = std::min(low, e->q[c]), high = std::max(high, e->q[c]);
        double margin = high > low ? (high - low) / 2 : std::max(2 * std::abs(initial[c] - centre), 1.0);
        if (high > low && std::abs(initial[c] - centre) * 2 > margin)
            margin = std::abs(initial[c] - centre) * 2;
        portrait.q_low = low - margin;
        portrait.q_high = high + margin;
    }
    auto potential = [&](double q) {
        std::vector<double> x = base;
        x[c] = q;
        return energy(x, 0);
    };
    portrait.minimum = potential(centre);
    for (const numeric_equilibrium* e : on_slice) {
        const double q = e->q[c];
        if (q < portrait.q_low - 1e-12 || q > portrait.q_high + 1e-12)
            continue;
        (e->stable ? portrait.stable : portrait.unstable).push_back(q);
        if (!e->stable && potential(q) > portrait.minimum)
            portrait.separatrices.push_back(potential(q));
    }
    // The picture's top energy: half again above the highest separatrix, else where the
    // level curves still close inside the range.
    std::sort(portrait.separatrices.begin(), portrait.separatrices.end());
    portrait.separatrices.erase(std::unique(portrait.separatrices.begin(), portrait.separatrices.end(),
                                            [](double a, double b) { return std::abs(a - b) <= 1e-12 * (1 + std::abs(a)); }),
                                portrait.separatrices.end());
    double top = portrait.separatrices.empty()
                     ? std::min(potential(portrait.q_low), potential(portrait.q_high))
                     : portrait.separatrices.back() + (portrait.separatrices.back() - portrait.minimum) / 2;
    if (!(top > portrait.minimum))
        top = portrait.minimum + 1;
    // The velocities reached below the top: q̇² = 2 (top − V)/m(q), m from h at unit velocity.
    double widest = 0;
    for (std::size_t i = 0; i < settings.grid; ++i) {
        const double q = portrait.q(i);
        std::vector<double> x = base;
        x[c] = q;
        const double v = energy(x, 0), mass = 2 * (energy(x, 1) - v);
        if (mass > 0 && v < top)
            widest = std::max(widest, std::sqrt(2 * (top - v) / mass));
    }
    if (!(widest > 0))
        widest = 1;
    portrait.v_low = -1.1 * widest;
    portrait.v_high = 1.1 * widest;
    portrait.energy.resize(settings.grid * settings.grid);
    for (std::size_t r = 0; r < settings.grid; ++r)
        for (std::size_t i = 0; i < settings.grid; ++i) {
            std::vector<double> x = base;
            x[c] = portrait.q(i);
            portrait.energy[r * settings.grid + i] = energy(x, portrait.v(r));
        }
    for (std::size_t l = 1; l <= settings.levels; ++l) {
        const double level = portrait.minimum + (top - portrait.minimum) * static_cast<double>(l) /
                                                    static_cast<double>(settings.levels + 1);
        bool separatrix = false;
        for (double s : portrait.separatrices)
            separatrix = separatrix || std::abs(level - s) <= 1e-9 * (1 + std::abs(s));
        if (!separatrix)
            portrait.levels.push_back(level);
    }
    return portrait;
}

} // namespace lagrange
