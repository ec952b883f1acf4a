// SPDX-License-Identifier: GPL-2.0-or-later
/** @file work_precision.cpp
 *  Benchmark: error against run time of our integrators on the four problems of the
 *  peer script ../shared/peers/work_precision_scipy.py, with the same error measure
 *  (max over 1001 uniform times of ‖y − y_ref‖₂ / max ‖y_ref‖₂) and tolerances
 *  1e-3 … 1e-12. Timed as the peer times solve_ivp: without output (dopri5 and Bulirsch–Stoer
 *  then interpolate nothing; BDF and implicit midpoint step to the 1001 output times
 *  regardless), the error from one more, untimed run that takes the same steps. rkf78 has no
 *  interpolant: it is timed on its own steps and its error measured at their ends (rows with
 *  "err_at": "step ends"), against the exact solution there or rkf78 at 1e-14 to those times.
 *  The time of a row is the peer's statistic, a median of repeated runs (see below; the
 *  fastest of them is in "time_min_s").
 *  Prints one JSON object (rows like the peer's) for bench/work_precision.py.
 *    rigid     free asymmetric body, I = (1, 2, 3), ω0 = (1, 0.1, 0.5), t ∈ [0, 100]: the
 *              engine's Euler equations and Jacobi elliptic solution (free_body_motion.h)
 *    lindp     linearized double pendulum from a scene (ρ = 0.01, l = g = 1), q0 = (0.05, 0),
 *              t ∈ [0, 200]; exact: normal modes
 *    dp_small  double pendulum from a scene, M = m = l = g = 1, θ0 = φ0 = 0.05, t ∈ [0, 100]
 *    dp_large  the same at 1.5 rad, t ∈ [0, 20]; reference: rkf78 at 1e-14 (labelled)
 *  Usage: work_precision [max_seconds_per_run [problem [method]]] (the last two: only those rows) */
#include "engine/analysis.h"
#include "numeric/compiled_motion.h"
#include "numeric/free_body_motion.h"
#include "numeric/simulation.h"
#include "scene/lower.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>

namespace {

struct problem {
    std::string name;
    std::string reference_kind;
    lagrange::ode_system system;
    std::vector<double> x0;
    double until = 0;
    std::vector<double> frequencies;
    std::shared_ptr<lagrange::compiled_motion> motion; // keeps the compiled system alive
    std::shared_ptr<lagrange::free_body_motion> body;  // (the free body's)
    std::shared_ptr<lagrange::model> scene;
};

problem rigid_body()
{
    // The engine's own free body: Euler's equations from the rigid-body derivation,
    // compiled with their symbolic Jacobian, and its Jacobi elliptic solution.
    problem p;
    p.name = "rigid";
    p.until = 100;
    p.scene = std::make_shared<lagrange::model>(lagrange::load_model(
        lagrange::source_text("rigid.lag", "body X inertia (1, 2, 3) mass 1\nomega X (w1, w2, w3)\n"
                                           "initial w1 = 1, w2 = 0.1, w3 = 0.5\n")));
    p.body = std::make_shared<lagrange::free_body_motion>(*p.scene, lagrange::first_value_point(*p.scene));
    if (!p.body->compile_native())
        std::cerr << "work_precision: no C compiler, the interpreter evaluates the equations\n";
    p.reference_kind = "exact (" + p.body->exact_kind() + ", Boost.Math)";
    p.x0 = p.body->initial();
    p.system = p.body->system();
    p.system.invariants.resize(1); // T, as the peer reports its energy drift
    return p;
}

problem from_scene(const std::string& name, const std::string& text, double until)
{
    problem p;
    p.name = name;
    p.until = until;
    p.scene = std::make_shared<lagrange::model>(lagrange::load_model(lagrange::source_text(name + ".lag", text)));
    lagrange::analysis a = lagrange::analyze(*p.scene, {lagrange::product::equations});
    p.motion = std::make_shared<lagrange::compiled_motion>(*p.scene, *a.equations,
                                                           lagrange::first_value_point(*p.scene));
    if (!p.motion->compile_native())
        std::cerr << "work_precision: no C compiler, the interpreter evaluates the equations\n";
    p.x0 = lagrange::initial_state_vector(*p.scene, lagrange::first_value_point(*p.scene));
    std::vector<double> rest(p.x0.size(), 0.0);
    // Energy above the equilibrium, as the peer scales it.
    p.system = p.motion->system(std::abs(p.motion->energy(p.x0.data()) - p.motion->energy(rest.data())));
    p.frequencies = lagrange::linearized_frequencies(p.system, rest);
    p.system.exact = lagrange::normal_mode_solution(p.system, p.motion->coordinates(), p.x0);
    p.reference_kind = p.system.exact ? "exact (normal modes)" : "numerical: rkf78 at tolerance 1e-14";
    return p;
}

const std::string pendulum = "parameters M m l g\ncoordinates theta phi\n"
                             "point upper mass M at (l*sin(theta), -l*cos(theta))\n"
                             "point lower mass m at (l*sin(theta) + l*sin(phi), -l*cos(theta) - l*cos(phi))\n"
                             "gravity g along (0, -1)\nvalues M = 1, m = 1, l = 1, g = 1\n";

} // namespace

int main(int argc, char** argv)
{
    double max_seconds = argc > 1 ? std::atof(argv[1]) : 10;
    std::string only_problem = argc > 2 ? argv[2] : "", only_method = argc > 3 ? argv[3] : "";
    std::vector<problem> problems;
    problems.push_back(rigid_body());
    problems.push_back(from_scene("lindp",
                                  "parameters M m l g\ncoordinates theta phi\n"
                                  "T = 1/2*(M+m)*l^2*theta'^2 + m*l^2*theta'*phi' + 1/2*m*l^2*phi'^2\n"
                                  "V = 1/2*(M+m)*g*l*theta^2 + 1/2*m*g*l*phi^2\n"
                                  "values M = 1, m = 0.01, l = 1, g = 1\ninitial theta = 0.05\n",
                                  200));
    problems.push_back(from_scene("dp_small", pendulum + "initial theta = 0.05, phi = 0.05\n", 100));
    problems.push_back(from_scene("dp_large", pendulum + "initial theta = 1.5, phi = 1.5\n", 20));

    nlohmann::ordered_json out;
    out["problems"] = nlohmann::ordered_json::object();
    out["rows"] = nlohmann::ordered_json::array();
    for (problem& p : problems) {
        if (!only_problem.empty() && p.name != only_problem)
            continue;
        lagrange::integration_options options;
        options.until = p.until;
        options.max_seconds = max_seconds;
        options.max_steps = 20'000'000;
        options.frequency = p.frequencies.empty() ? 1.0 : p.frequencies.back();
        lagrange::integration_options fine = options;
        fine.tolerance = 1e-14;
        // The exact solution at `times`, where there is one.
        auto exact_at = [&](const std::vector<double>& times) {
            lagrange::trajectory at;
            for (double t : times) {
                std::vector<double> x(p.system.dimension);
                p.system.exact(t, x.data());
                at.states.push_back(x);
            }
            return at;
        };
        // The reference at the 1001 output times, computed once (not inside the timed runs).
        lagrange::trajectory reference;
        if (p.system.exact) {
            std::vector<double> times;
            for (int k = 0; k <= 1000; ++k)
                times.push_back(k == 1000 ? p.until : p.until * k / 1000.0);
            reference = exact_at(times);
        } else {
            reference = lagrange::integrate(p.system, lagrange::ode_method::rkf78, p.x0, fine);
        }
        // The reference at other times (rkf78's step ends): exact, or rkf78 at 1e-14 to them.
        auto reference_at = [&](const std::vector<double>& times) {
            return p.system.exact ? exact_at(times)
                                  : lagrange::integrate_at(p.system, lagrange::ode_method::rkf78, p.x0, fine, times);
        };
        // Timed as the peer times solve_ivp: no states kept, no invariants evaluated; the
        // error and the energy drift come from one more, untimed run with the same steps.
        lagrange::ode_system timed = p.system;
        timed.exact = nullptr;
        timed.invariants.clear();
        lagrange::ode_system measured = p.system;
        measured.exact = nullptr;
        if (p.name == "rigid") {
            std::vector<double> start(3);
            p.system.exact(0, start.data());
            double d = 0;
            for (int i = 0; i < 3; ++i)
                d = std::max(d, std::abs(start[i] - p.x0[i]));
            out["problems"][p.name]["exact_at_0_maxabs"] = d;
        }
        out["problems"][p.name]["reference"] = p.reference_kind;
        for (lagrange::ode_method method : lagrange::all_ode_methods()) {
            if (!only_method.empty() && lagrange::to_string(method) != only_method)
                continue;
            bool give_up = false;
            for (int e = 3; e <= 12; ++e) {
                double tol = std::pow(10.0, -e);
                nlohmann::ordered_json row;
                row["problem"] = p.name;
                row["method"] = lagrange::to_string(method);
                row["tol"] = tol;
                if (give_up) {
                    row["failure"] = "left out";
                    out["rows"].push_back(row);
                    continue;
                }
                options.tolerance = tol;
                try {
                    lagrange::trajectory run;
                    lagrange::integration_options quiet = options;
                    quiet.keep_states = false;
                    quiet.outputs = false; // dense output: no interpolation, the same steps; rkf78: its own
                    // The peer's statistic: the median after a warm-up run, of 3 runs when a run takes
                    // 0.2 s or more, else of at least 7 — and here of as many as fill 0.1 s (at most
                    // 1001), so that our runs, about 100 times shorter, face the host's bursts of
                    // load over a time like the peer's 7 runs do, not over 1–2 ms.
                    run = lagrange::integrate(timed, method, p.x0, quiet);
                    std::size_t timed_steps = run.steps;
                    std::vector<double> seconds;
                    double total = 0;
                    bool slow = run.seconds >= 0.2;
                    while (seconds.size() < (slow ? 3u : 7u) || (!slow && total < 0.1 && seconds.size() < 1001)) {
                        run = lagrange::integrate(timed, method, p.x0, quiet);
                        seconds.push_back(run.seconds);
                        total += run.seconds;
                    }
                    std::sort(seconds.begin(), seconds.end());
                    double median = seconds[seconds.size() / 2], best = seconds.front();
                    // rkf78 has no interpolant: its own steps, as timed, and the error at their ends
                    lagrange::integration_options measure = options;
                    measure.outputs = !lagrange::steps_to_outputs(method);
                    run = lagrange::integrate(measured, method, p.x0, measure);
                    if (run.steps != timed_steps) // the error below would not be the timed run's
                        throw std::runtime_error("the timed run took " + std::to_string(timed_steps) +
                                                 " steps, the measured one " + std::to_string(run.steps));
                    row["time_s"] = median;
                    row["time_min_s"] = best;
                    row["repeats"] = seconds.size();
                    row["steps"] = run.steps;
                    row["nfev"] = run.evaluations;
                    if (measure.outputs) {
                        row["err_traj"] = lagrange::trajectory_difference(run, reference);
                    } else {
                        row["err_at"] = "step ends";
                        row["err_traj"] = lagrange::trajectory_difference(run, reference_at(run.times));
                    }
                    if (!run.invariant_drift.empty())
                        row["energy_drift"] = run.invariant_drift[0].second;
                    if (median > max_seconds / 3)
                        give_up = true;
                } catch (const std::exception& error) {
                    row["failure"] = error.what();
                    give_up = true;
                }
                std::cerr << p.name << ' ' << row.dump() << '\n';
                out["rows"].push_back(row);
            }
        }
    }
    std::cout << out.dump(1) << '\n';
    return 0;
}
