// SPDX-License-Identifier: GPL-2.0-or-later
/** @file simulation.cpp
 *  Simulation and work-precision runs of a scene's equations of motion. */
#include "numeric/simulation.h"

#include "numeric/free_body_motion.h"
#include "numeric/values.h"

#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <memory>

namespace lagrange {

namespace {

GiNaC::ex substitute(const GiNaC::ex& e, const model& scene, const std::map<std::string, GiNaC::ex>& values)
{
    GiNaC::lst substitutions;
    for (const parameter& p : scene.parameters) {
        auto found = values.find(p.name);
        if (found != values.end())
            substitutions.append(p.symbol == found->second);
    }
    return e.subs(substitutions);
}

} // namespace

std::vector<double> linearized_frequencies(const ode_system& system, const std::vector<double>& x,
                                           std::vector<double>* growth_rates)
{
    if (growth_rates)
        growth_rates->clear();
    const auto d = static_cast<Eigen::Index>(system.dimension);
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> jacobian(d, d);
    system.jacobian(0, x.data(), jacobian.data());
    if (!jacobian.allFinite())
        return {};
    Eigen::EigenSolver<Eigen::MatrixXd> solver(jacobian);
    if (solver.info() != Eigen::Success)
        return {};
    std::vector<double> frequencies;
    double largest = 0;
    for (Eigen::Index k = 0; k < d; ++k)
        largest = std::max(largest, std::abs(solver.eigenvalues()[k]));
    for (Eigen::Index k = 0; k < d; ++k) {
        std::complex<double> lambda = solver.eigenvalues()[k];
        double size = std::abs(lambda);
        if (size <= 1e-9 * largest || size == 0)
            continue;
        // ±iω (or ±γ for an unstable mode): keep the one with a positive part once. A
        // damped motion has −γ ± iω (the one with positive imaginary part) and decay rates
        // −γ without a partner +γ: each is a rate of its own (a stiff damper).
        bool decay_alone = lambda.imag() == 0 && lambda.real() < 0;
        for (Eigen::Index j = 0; j < d && decay_alone; ++j)
            if (std::abs(solver.eigenvalues()[j] + lambda) <= 1e-9 * largest)
                decay_alone = false;
        if (lambda.imag() > 0 || (lambda.imag() == 0 && lambda.real() > 0) || decay_alone)
            frequencies.push_back(size);
        if (growth_rates && lambda.imag() == 0 && lambda.real() > 0)
            growth_rates->push_back(size);
    }
    std::sort(frequencies.begin(), frequencies.end());
    if (growth_rates)
        std::sort(growth_rates->begin(), growth_rates->end());
    return frequencies;
}

std::function<void(double, double*)> normal_mode_solution(const ode_system& system, std::size_t coordinates,
                                                          const std::vector<double>& x0)
{
    const auto d = static_cast<Eigen::Index>(system.dimension);
    using row_major = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    row_major j0(d, d), j1(d, d), j2(d, d);
    std::vector<double> zero(system.dimension, 0.0), other(system.dimension);
    for (std::size_t i = 0; i < system.dimension; ++i)
        other[i] = 0.37 + 1.3 * x0[i] - 0.11 * static_cast<double>(i);
    try {
        system.jacobian(0, x0.data(), j0.data());
        system.jacobian(0, zero.data(), j1.data());
        system.jacobian(1.7, other.data(), j2.data());
    } catch (const computation_error&) {
        return {};
    }
    double scale = j0.norm();
    if (!j0.allFinite() || scale == 0 || (j0 - j1).norm() > 1e-13 * scale || (j0 - j2).norm() > 1e-13 * scale)
        return {};
    // Linear: also f(0) must vanish (no constant force), checked on the rhs.
    std::vector<double> f0(system.dimension);
    system.rhs(0, zero.data(), f0.data());
    for (double v : f0)
        if (std::abs(v) > 1e-14 * scale)
            return {};
    Eigen::EigenSolver<Eigen::MatrixXd> solver(j0);
    if (solver.info() != Eigen::Success)
        return {};
    Eigen::MatrixXcd vectors = solver.eigenvectors();
    Eigen::VectorXcd values = solver.eigenvalues();
    Eigen::MatrixXcd rebuilt = vectors * values.asDiagonal() * vectors.inverse();
    if ((rebuilt - j0.cast<std::complex<double>>()).norm() > 1e-12 * scale)
        return {};
    Eigen::VectorXcd weights =
        vectors.partialPivLu().solve(Eigen::Map<const Eigen::VectorXd>(x0.data(), d).cast<std::complex<double>>());
    (void)coordinates;
    return [vectors, values, weights, d](double t, double* x) {
        Eigen::VectorXcd scaled(d);
        for (Eigen::Index k = 0; k < d; ++k)
            scaled[k] = std::exp(values[k] * t) * weights[k];
        Eigen::VectorXcd state = vectors * scaled;
        for (Eigen::Index k = 0; k < d; ++k)
            x[k] = state[k].real();
    };
}

beat_measurement measure_beats(const std::vector<double>& times, const std::vector<double>& signal)
{
    beat_measurement result;
    // The envelope: the local maxima of |signal|, refined by a parabola through three samples.
    std::vector<double> peak_times, peaks;
    for (std::size_t k = 1; k + 1 < signal.size(); ++k) {
        double a = std::abs(signal[k - 1]), b = std::abs(signal[k]), c = std::abs(signal[k + 1]);
        if (b > a && b >= c) {
            double curvature = a - 2 * b + c;
            double offset = curvature != 0 ? 0.5 * (a - c) / curvature : 0;
            double h = times[k + 1] - times[k];
            peak_times.push_back(times[k] + offset * h);
            peaks.push_back(b - 0.25 * (a - c) * offset);
        }
    }
    // The minima of the envelope's square (smooth where the envelope has a corner).
    std::vector<double> minima;
    for (std::size_t k = 1; k + 1 < peaks.size(); ++k) {
        double a = peaks[k - 1] * peaks[k - 1], b = peaks[k] * peaks[k], c = peaks[k + 1] * peaks[k + 1];
        if (b < a && b <= c) {
            // Parabola through three unevenly spaced points.
            double t0 = peak_times[k - 1], t1 = peak_times[k], t2 = peak_times[k + 1];
            double d1 = (b - a) / (t1 - t0), d2 = (c - b) / (t2 - t1);
            double second = (d2 - d1) / (t2 - t0);
            double at = second > 0 ? 0.5 * (t0 + t1) - d1 / (2 * second) : t1;
            if (at < t0 || at > t2)
                at = t1;
            minima.push_back(at);
        }
    }
    result.minima = minima.size();
    if (minima.size() >= 2)
        result.measured = (minima.back() - minima.front()) / static_cast<double>(minima.size() - 1);
    return result;
}

namespace {

/// The scene's motion at its parameter point, ready to integrate.
struct prepared_motion {
    std::map<std::string, GiNaC::ex> values;
    std::unique_ptr<compiled_motion> motion;      ///< a Lagrangian scene
    std::unique_ptr<free_body_motion> free_body;  ///< or a free body (Euler's equations)
    std::size_t coordinates = 0;                  ///< n (the state is (q, q̇)); 0 for a free body
    std::vector<std::string> names;               ///< coordinate names, or ω's for a free body
    std::string evaluation;                       ///< empty when native code runs, else why not
    std::vector<double> x0;
    double until = 0;
    double tolerance = 1e-9;
    double absolute_scale = 1;                    ///< integration_options::absolute_scale
    std::vector<double> frequencies;
    std::vector<double> growth_rates;             ///< those of `frequencies` that are real λ > 0
    double stiffness = 1;
    double rate = 0;                              ///< fastest rate of the motion (0: the largest frequency)
    ode_system system;
};

/// The absolute tolerance's scale (integration_options::absolute_scale): 1, unless the motion
/// is small, S = max |x0 − reference| < 1/32 over positions and velocities; then 32 S, so
/// that at any amplitude the control is never looser, relative to the motion, than at
/// S = 1/32. (With an absolute tolerance fixed at the tolerance itself, a motion of size
/// 1e-300 went unresolved: true error 2.7e-6 at tolerance 1e-9, and the reference run,
/// no better, made the estimate 0.) A state at rest at the reference keeps 1.
double absolute_scale(const std::vector<double>& x0, const std::vector<double>& reference)
{
    constexpr double knee = 1.0 / 32;
    double size = 0;
    for (std::size_t i = 0; i < std::min(x0.size(), reference.size()); ++i)
        size = std::max(size, std::abs(x0[i] - reference[i]));
    return size == 0 || size >= knee ? 1.0 : size / knee;
}

/// The end time and tolerance of the `simulate` line, or their overrides.
void read_span(prepared_motion& p, const model& scene, const simulation_settings& settings)
{
    const simulation_span span = simulation_span_of(scene, settings);
    p.until = span.until;
    p.tolerance = span.tolerance;
}

prepared_motion prepare(const model& scene, const equations_of_motion& equations,
                        const std::optional<std::vector<GiNaC::ex>>& equilibrium, const simulation_settings& settings)
{
    prepared_motion p;
    p.values = merged_values(scene);
    p.motion = std::make_unique<compiled_motion>(scene, equations, p.values);
    if (!settings.native)
        p.evaluation = "interpreted (as asked)";
    else if (std::string why; !p.motion->compile_native_rhs(native_limits{settings.compile_seconds}, &why))
        p.evaluation = "interpreted: " + why;
    p.x0 = initial_state_vector(scene, p.values);
    if (p.motion->accumulates_work())
        p.x0.push_back(0); // the work of the generalized forces starts at 0
    const std::size_t n = p.motion->coordinates();
    p.coordinates = n;
    p.names = coordinate_names(scene);
    read_span(p, scene, settings);

    // The linearization about the equilibrium (or the initial position) for the choice of method.
    std::vector<double> reference_state(p.motion->dimension(), 0.0);
    if (equilibrium && equilibrium->size() == n) {
        for (std::size_t i = 0; i < n; ++i)
            reference_state[i] = real_value(substitute((*equilibrium)[i], scene, p.values), "the equilibrium");
    } else {
        std::copy(p.x0.begin(), p.x0.begin() + static_cast<std::ptrdiff_t>(n), reference_state.begin());
    }
    p.absolute_scale = absolute_scale(p.x0, reference_state);
    double energy_scale = 0;
    if ((p.motion->conservative() || p.motion->accumulates_work()) && equilibrium)
        energy_scale = std::abs(p.motion->energy(p.x0.data()) - p.motion->energy(reference_state.data()));
    p.system = p.motion->system(energy_scale);
    p.frequencies = linearized_frequencies(p.system, reference_state, &p.growth_rates);
    if (p.frequencies.size() >= 2)
        p.stiffness = p.frequencies.back() / p.frequencies.front();
    return p;
}

/// A free body: Euler's equations from the rigid-body derivation, with the exact
/// solution (elliptic or symmetric closed form) when it is torque-free.
prepared_motion prepare_free_body(const model& scene, const simulation_settings& settings)
{
    prepared_motion p;
    p.values = merged_values(scene);
    p.free_body = std::make_unique<free_body_motion>(scene, p.values);
    if (!settings.native)
        p.evaluation = "interpreted (as asked)";
    else if (std::string why; !p.free_body->compile_native(native_limits{settings.compile_seconds}, &why))
        p.evaluation = "interpreted: " + why;
    p.names = p.free_body->names();
    p.x0 = p.free_body->initial();
    read_span(p, scene, settings);
    p.system = p.free_body->system();
    p.frequencies = linearized_frequencies(p.system, p.x0, &p.growth_rates);
    // The body turns at |ω|; the linearization about ω0 gives the wobble (polhode) rate.
    double spin = std::sqrt(p.x0[0] * p.x0[0] + p.x0[1] * p.x0[1] + p.x0[2] * p.x0[2]);
    if (p.frequencies.size() >= 2)
        p.stiffness = p.frequencies.back() / p.frequencies.front();
    p.rate = std::max(spin, p.frequencies.empty() ? 0.0 : p.frequencies.back());
    return p;
}

} // namespace

namespace {

simulation_result run_simulation(const model& scene, prepared_motion& prepared, const simulation_settings& settings)
{
    simulation_result result;
    result.coordinates = prepared.names;
    result.first_order = static_cast<bool>(prepared.free_body);
    result.evaluation = prepared.evaluation;
    result.values = prepared.values;
    const std::size_t n = prepared.coordinates;
    const std::vector<double>& x0 = prepared.x0;
    const double until = prepared.until;
    result.tolerance = prepared.tolerance;
    // the growth rates apart: an unstable mode is not a frequency
    result.growth_rates = prepared.growth_rates;
    std::vector<double> growing = prepared.growth_rates;
    for (double rate : prepared.frequencies) {
        auto found = std::find(growing.begin(), growing.end(), rate);
        if (found != growing.end())
            growing.erase(found);
        else
            result.frequencies.push_back(rate);
    }
    result.stiffness = prepared.stiffness;
    ode_system& system = prepared.system;

    std::string method_name = settings.method ? *settings.method : scene.simulation ? scene.simulation->method : "auto";
    ode_method method;
    if (method_name == "auto") {
        if (result.stiffness > stiffness_threshold) {
            method = ode_method::bdf;
            result.choice = "auto: the linearized frequencies spread over a factor " +
                            message_number(result.stiffness, 3) + " (> " + message_number(stiffness_threshold, 3) +
                            "): stiff, implicit BDF";
        } else {
            // our fastest at most levels of bench/work_precision, with a 7th-order dense output
            method = ode_method::dop853;
            result.choice = "auto: the linearized frequencies spread over a factor " +
                            message_number(result.stiffness, 3) + " (≤ " + message_number(stiffness_threshold, 3) +
                            "): not stiff, explicit " + to_string(method);
        }
    } else {
        std::optional<ode_method> named = ode_method_from_name(method_name);
        if (!named)
            throw computation_error("unknown method `" + method_name +
                                    "` (auto, dopri5, rkf78, dop853, bulirsch-stoer, bdf, implicit-midpoint)");
        method = *named;
        result.choice = "as asked";
    }
    result.method = to_string(method);
    // The implicit methods (and BDF as a reference) evaluate the Jacobian on every Newton
    // iteration: compiled then too. The explicit ones never do, so their run waits only for
    // the right-hand side's compile.
    const bool implicit = method == ode_method::bdf || method == ode_method::implicit_midpoint;
    if (implicit && prepared.motion && prepared.motion->native()) {
        const auto started = std::chrono::steady_clock::now();
        if (std::string why; !prepared.motion->compile_native_jacobian(native_limits{settings.compile_seconds}, &why))
            result.evaluation = "native right-hand side, interpreted Jacobian: " + why;
        result.jacobian_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    }

    integration_options options;
    options.until = until;
    options.tolerance = result.tolerance;
    options.absolute_scale = prepared.absolute_scale;
    result.absolute_tolerance = result.tolerance * prepared.absolute_scale;
    if (scene.simulation && scene.simulation->step)
        options.output_step = real_value(*scene.simulation->step, "the output step");
    options.frequency = prepared.rate > 0 ? prepared.rate : result.frequencies.empty() ? 1.0 : result.frequencies.back();
    options.max_seconds = settings.max_seconds;
    // Each run reports its progress under its own name.
    auto labelled = [&settings](std::string what) -> std::function<void(double)> {
        if (!settings.progress)
            return nullptr;
        return [what = std::move(what), &settings](double fraction) { settings.progress(what, fraction); };
    };
    options.progress = labelled("simulating with " + to_string(method));

    // Every integration of the stage, counted and its run time added up (`--timings`).
    auto timed_integrate = [&result](const ode_system& which, ode_method how, const std::vector<double>& start,
                                     const integration_options& with) {
        trajectory run = integrate(which, how, start, with);
        result.integration_seconds += run.seconds;
        ++result.integration_runs;
        return run;
    };
    std::string exact_basis = "against the exact normal-mode solution of the linear equations";
    if (prepared.free_body)
        exact_basis = "against " + prepared.free_body->exact_kind() + " of Euler's equations";
    else
        system.exact = normal_mode_solution(system, n, x0);
    // The error of a run: against the exact solution when there is one, else against a
    // run of the same method (or rkf78/BDF for implicit midpoint) at a 1000 times tighter
    // tolerance, when asked for and when time allows. No value: the basis says why.
    struct error_estimate {
        std::optional<double> value;
        std::string basis;
    };
    auto estimate = [&](const trajectory& run, double tolerance, double seconds_left) -> error_estimate {
        if (run.exact_error)
            return {run.exact_error, exact_basis};
        if (!settings.estimate_error)
            return {};
        if (run.seconds > seconds_left / 4)
            return {std::nullopt, "no estimate: the run took " + message_number(run.seconds, 3) +
                                      " s, and a reference run at a tighter tolerance would exceed the time limit"};
        integration_options fine = options;
        fine.tolerance = std::max(tolerance / 1000, 1e-14);
        fine.max_seconds = std::max(1.0, seconds_left - run.seconds);
        ode_method reference = method == ode_method::implicit_midpoint
                                   ? (result.stiffness > stiffness_threshold ? ode_method::bdf : ode_method::rkf78)
                                   : method;
        const std::string reference_name =
            "error estimate: " + to_string(reference) + " at tolerance " + message_number(fine.tolerance, 3);
        fine.progress = labelled(reference_name);
        error_estimate found;
        trajectory check;
        try {
            check = timed_integrate(system, reference, x0, fine);
            found = {trajectory_difference(run, check),
                     "against " + to_string(reference) + " at tolerance " + message_number(fine.tolerance, 3)};
        } catch (const computation_error& error) {
            return {std::nullopt, std::string("no estimate: the reference run stopped: ") + error.what()};
        }
        if (tolerance / 1000 >= 1e-14)
            return found;
        // At the floor the reference is less than 1000 times tighter, and rounding may rule
        // both runs: two runs can then agree by chance far better than either agrees with the
        // motion (a pendulum just below its separatrix). The reference twice more, from the
        // start moved by one rounding up and down, gives three runs that rounding alone sets
        // apart, each off the motion by about the same random amount σ. Their largest
        // difference (the range of three samples, about 1.7σ on average) is one sample of that
        // spread and may fall short of the run's true error; twice it is the estimate when that
        // is larger (3.4σ on average).
        fine.max_seconds = std::max(1.0, seconds_left - run.seconds - check.seconds);
        try {
            std::vector<trajectory> moved_runs;
            for (double direction : {1.0, -1.0}) {
                fine.progress = labelled(reference_name + (direction > 0 ? ", start moved up" : ", start moved down"));
                std::vector<double> moved = x0;
                for (double& v : moved)
                    v += direction * v * 0x1p-52;
                moved_runs.push_back(timed_integrate(system, reference, moved, fine));
                fine.max_seconds = std::max(1.0, fine.max_seconds - moved_runs.back().seconds);
            }
            double rounding = 2 * std::max({trajectory_difference(check, moved_runs[0]),
                                            trajectory_difference(check, moved_runs[1]),
                                            trajectory_difference(moved_runs[0], moved_runs[1])});
            if (rounding > *found.value) {
                found.value = rounding;
                found.basis += " and from starts moved by one rounding up and down (twice their largest "
                               "difference): rounding rules the error";
            }
        } catch (const computation_error& error) {
            found.basis += "; rounding not checked: " + std::string(error.what());
        }
        return found;
    };
    const auto started = std::chrono::steady_clock::now();
    auto seconds_spent = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    };
    result.run = timed_integrate(system, method, x0, options);
    result.run_tolerance = options.tolerance;
    error_estimate first = estimate(result.run, options.tolerance, settings.max_seconds - seconds_spent());
    result.error_estimate = first.value;
    result.error_basis = first.basis;

    // The tolerance is a target for the global error, and each method's per-step setting
    // is derived from it by a factor found on a model problem (ode.cpp). When the
    // estimate says a run missed it (long runs collect more error), run again tighter by
    // the factor it missed by, twice over, at most twice, while the time limit allows a
    // run and its reference at the tighter setting (reckoned at 5 times the time spent so
    // far). The tightest run is at 1e-13, whose reference (at the floor 1e-14) is still 10
    // times tighter: an unstable motion (a pendulum near its separatrix, where errors grow
    // like e^t while it lingers at the top) can miss by 10⁸ and gets the most accurate run
    // there is, with its estimate. A tighter run without an estimate of its own leaves the
    // last one standing.
    for (int retry = 0; retry < 2; ++retry) {
        if (!result.error_estimate || *result.error_estimate <= result.tolerance)
            break;
        double factor = std::max(2 * *result.error_estimate / result.tolerance, 4.0);
        double tighter = std::max(result.run_tolerance / factor, 1e-13);
        double spent = seconds_spent(), left = settings.max_seconds - spent;
        if (tighter >= result.run_tolerance || 5 * spent > left)
            break;
        integration_options again = options;
        again.tolerance = tighter;
        again.max_seconds = std::max(1.0, left);
        again.progress = labelled("rerunning with " + to_string(method) + " at tolerance " + message_number(tighter, 3));
        try {
            trajectory run = timed_integrate(system, method, x0, again);
            error_estimate next = estimate(run, tighter, settings.max_seconds - seconds_spent());
            if (!next.value)
                break;
            if (!result.missed_error)
                result.missed_error = result.error_estimate;
            result.run = std::move(run);
            result.run_tolerance = tighter;
            result.error_estimate = next.value;
            result.error_basis = next.basis;
        } catch (const computation_error&) {
            break; // the last run stands, with its estimate
        }
    }

    // Beats: two close linearized frequencies.
    if (!result.first_order && n >= 2 && result.frequencies.size() >= 2) {
        double w1 = result.frequencies[0], w2 = result.frequencies[1];
        double predicted = 2 * M_PI / (w2 - w1);
        if (w2 > w1 && (w2 - w1) < 0.5 * w2 && until >= 1.5 * predicted && !result.run.states.empty()) {
            double best_depth = -1;
            for (std::size_t i = 0; i < n; ++i) {
                std::vector<double> signal;
                for (const auto& state : result.run.states)
                    signal.push_back(state[i]);
                beat_measurement b = measure_beats(result.run.times, signal);
                double top = 0;
                for (double v : signal)
                    top = std::max(top, std::abs(v));
                if (b.minima >= 2 && top > 0 && top > best_depth) {
                    best_depth = top;
                    b.coordinate = scene.coordinates[i].name;
                    b.predicted = predicted;
                    result.beats = b;
                }
            }
        }
    }
    return result;
}

} // namespace

namespace {

/// The motion that `prepare_motion` makes, run, with the preparation's time (`--timings`).
template <class Prepare>
simulation_result prepared_and_run(const model& scene, const simulation_settings& settings, Prepare&& prepare_motion)
{
    const auto started = std::chrono::steady_clock::now();
    prepared_motion prepared = prepare_motion();
    const std::chrono::duration<double> preparation = std::chrono::steady_clock::now() - started;
    simulation_result result = run_simulation(scene, prepared, settings);
    result.preparation_seconds = preparation.count();
    return result;
}

} // namespace

simulation_result simulate(const model& scene, const equations_of_motion& equations,
                           const std::optional<std::vector<GiNaC::ex>>& equilibrium,
                           const simulation_settings& settings)
{
    return prepared_and_run(scene, settings, [&] { return prepare(scene, equations, equilibrium, settings); });
}

simulation_result simulate_free_body(const model& scene, const simulation_settings& settings)
{
    return prepared_and_run(scene, settings, [&] { return prepare_free_body(scene, settings); });
}

workprecision_result free_body_work_precision(const model& scene, const simulation_settings& settings)
{
    prepared_motion prepared = prepare_free_body(scene, settings);
    workprecision_result result = work_precision(prepared.system, prepared.x0, prepared.until, 0, {prepared.rate}, {},
                                                 settings.max_seconds / 6, settings.progress);
    if (result.exact)
        result.reference = "exact: " + prepared.free_body->exact_kind() + " of Euler's equations";
    result.evaluation = prepared.evaluation;
    return result;
}

workprecision_result scene_work_precision(const model& scene, const equations_of_motion& equations,
                                          const std::optional<std::vector<GiNaC::ex>>& equilibrium,
                                          const simulation_settings& settings)
{
    prepared_motion prepared = prepare(scene, equations, equilibrium, settings);
    // Every method runs, the implicit ones with the Jacobian.
    if (prepared.motion->native())
        if (std::string why; !prepared.motion->compile_native_jacobian(native_limits{settings.compile_seconds}, &why))
            prepared.evaluation = "native right-hand side, interpreted Jacobian: " + why;
    workprecision_result result = work_precision(prepared.system, prepared.x0, prepared.until,
                                                 prepared.motion->coordinates(), prepared.frequencies, {},
                                                 settings.max_seconds / 6, settings.progress);
    result.evaluation = prepared.evaluation;
    return result;
}

workprecision_result work_precision(const ode_system& system, const std::vector<double>& x0, double until,
                                    std::size_t coordinates, const std::vector<double>& frequencies,
                                    const std::vector<double>& tolerances, double max_seconds,
                                    const progress_callback& progress)
{
    workprecision_result result;
    result.until = until;
    ode_system measured = system;
    if (!measured.exact && coordinates > 0)
        measured.exact = normal_mode_solution(system, coordinates, x0);
    ode_system timed = measured;
    timed.exact = nullptr;
    timed.invariants.clear();
    integration_options options;
    options.until = until;
    options.max_seconds = max_seconds;
    options.frequency = frequencies.empty() ? 1.0 : frequencies.back();
    options.max_steps = 5'000'000;
    bool stiff = frequencies.size() >= 2 && frequencies.back() / frequencies.front() > stiffness_threshold;

    trajectory reference;
    integration_options fine = options;
    fine.tolerance = stiff ? 1e-12 : 1e-13;
    fine.max_seconds = 4 * max_seconds;
    const ode_method reference_method = stiff ? ode_method::bdf : ode_method::rkf78;
    if (measured.exact) {
        result.exact = true;
        result.reference = "exact: the normal-mode solution of the linear equations";
    } else {
        if (progress)
            fine.progress = [&](double fraction) {
                progress("workprecision: reference " + to_string(reference_method) + " at tolerance " +
                             message_number(fine.tolerance, 3),
                         fraction);
            };
        reference = integrate(system, reference_method, x0, fine);
        fine.progress = nullptr;
        result.reference = "reference (not exact): " + to_string(reference_method) + " at tolerance " +
                           message_number(fine.tolerance, 3);
    }
    std::vector<double> ladder = tolerances;
    if (ladder.empty())
        for (int k = 3; k <= 12; ++k)
            ladder.push_back(std::pow(10.0, -k));
    // Progress: the share of the table's runs done (each method at each tolerance).
    const std::size_t runs = all_ode_methods().size() * ladder.size();
    for (ode_method method : all_ode_methods()) {
        std::string skip;
        for (double tol : ladder) {
            if (progress)
                progress("workprecision: " + to_string(method) + " at tolerance " + message_number(tol, 3),
                         static_cast<double>(result.points.size()) / static_cast<double>(runs));
            workprecision_point point;
            point.method = to_string(method);
            point.tolerance = tol;
            options.tolerance = tol;
            if (!skip.empty()) {
                point.failure = skip;
                result.points.push_back(point);
                continue;
            }
            try {
                // Timed without the measuring (no states kept, no invariants, no exact
                // solution evaluated, no output times: as SciPy's solve_ivp is timed without
                // t_eval); measured by one more run that takes the same steps.
                double best = HUGE_VAL, total = 0;
                integration_options quiet = options;
                quiet.keep_states = false;
                quiet.outputs = false; // dopri5 and Bulirsch–Stoer: the same steps, no interpolation
                for (int repeat = 0; repeat < 7 && (repeat == 0 || total < 0.2); ++repeat) {
                    trajectory timed_run = integrate(timed, method, x0, quiet);
                    best = std::min(best, timed_run.seconds);
                    total += timed_run.seconds;
                }
                // rkf78 has no interpolant: its own steps, as timed, and the error at their ends
                // (against the exact solution there, or the reference integrated to them)
                integration_options measure = options;
                measure.outputs = !steps_to_outputs(method);
                trajectory run = integrate(measured, method, x0, measure);
                point.seconds = best;
                point.steps = run.steps;
                if (run.exact_error) {
                    point.error = *run.exact_error;
                } else if (measure.outputs) {
                    point.error = trajectory_difference(run, reference);
                } else {
                    point.error = trajectory_difference(run, integrate_at(system, reference_method, x0, fine, run.times));
                }
                for (const auto& [name, drift] : run.invariant_drift)
                    if (name == "energy")
                        point.energy_drift = drift;
                if (best > max_seconds / 4)
                    skip = "left out: the looser tolerance " + message_number(tol, 3) + " already took " +
                           message_number(best, 3) + " s";
            } catch (const computation_error& error) {
                point.failure = error.what();
                skip = "left out: the looser tolerance " + message_number(tol, 3) + " already failed";
            }
            result.points.push_back(point);
        }
    }
    return result;
}

simulation_span simulation_span_of(const model& scene, const simulation_settings& settings)
{
    simulation_span span;
    span.until = settings.until     ? *settings.until
                 : scene.simulation ? real_value(scene.simulation->until, "the end time")
                                    : 0;
    if (!(span.until > 0) || !std::isfinite(span.until))
        throw computation_error("the simulation needs an end time: a `simulate until T` line or --until");
    span.tolerance = settings.tolerance ? *settings.tolerance
                     : scene.simulation && scene.simulation->tolerance
                         ? real_value(*scene.simulation->tolerance, "the tolerance")
                         : 1e-9;
    if (!(span.tolerance >= 1e-14 && span.tolerance < 1))
        throw computation_error("the tolerance " + message_number(span.tolerance, 3) + " is outside 1e-14 … 1");
    return span;
}

} // namespace lagrange
