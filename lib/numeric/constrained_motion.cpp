// SPDX-License-Identifier: GPL-2.0-or-later
/** @file constrained_motion.cpp
 *  Constrained equations of motion compiled once, integrated piecewise with projection. */
#include "numeric/constrained_motion.h"

#include "algebra/calculus.h"
#include "numeric/compiled_motion.h"
#include "numeric/values.h"
#include "core/number_text.h"

#include <Eigen/Dense>

#include <chrono>
#include <cmath>
#include <stdexcept>

namespace lagrange {

constrained_motion::constrained_motion(const model& scene, const equations_of_motion& equations,
                                       const std::map<std::string, GiNaC::ex>& values)
{
    n_ = scene.coordinates.size();
    m_ = scene.constraints.size();
    const constraint_equations& constraints = *equations.constraints;
    const std::vector<GiNaC::ex> symbols = state_symbols(scene);

    std::vector<GiNaC::ex> dynamics, residuals(2 * m_);
    for (std::size_t i = 0; i < n_; ++i)
        for (std::size_t j = 0; j < n_; ++j)
            dynamics.push_back(at_values(equations.mass(static_cast<unsigned>(i), static_cast<unsigned>(j)), scene, values));
    for (std::size_t i = 0; i < n_; ++i)
        dynamics.push_back(at_values(equations.forcing[i], scene, values));
    bool explicit_time = at_values(equations.lagrangian, scene, values).has(scene.time);
    for (std::size_t k = 0; k < m_; ++k) {
        const constraint& c = scene.constraints[k];
        GiNaC::ex velocity_form = at_values(c.rest, scene, values);
        for (std::size_t j = 0; j < n_; ++j) {
            GiNaC::ex a = at_values(constraints.matrix(static_cast<unsigned>(k), static_cast<unsigned>(j)), scene, values);
            dynamics.push_back(a);
            velocity_form += a * scene.coordinates[j].velocity;
            explicit_time = explicit_time || a.has(scene.time);
        }
        explicit_time = explicit_time || velocity_form.has(scene.time);
        holonomic_.push_back(c.constraint_kind == constraint::kind::holonomic);
        residuals[k] = holonomic_.back() ? at_values(c.function, scene, values) : GiNaC::ex(0);
        residuals[m_ + k] = velocity_form;
    }
    for (std::size_t k = 0; k < m_; ++k)
        dynamics.push_back(at_values(constraints.bias[k], scene, values));
    conservative_ = !explicit_time && !equations.forces.any;
    try {
        dynamics_ = expression_program(dynamics, symbols);
        residuals_ = expression_program(residuals, symbols);
        energy_ = expression_program({at_values(equations.energy, scene, values)}, symbols);
    } catch (const std::invalid_argument& error) {
        throw computation_error(std::string("the constrained equations of motion cannot be compiled: ") +
                                error.what());
    }
    symbols_.resize(2 * n_ + 1);
    outputs_.resize(n_ * n_ + n_ + m_ * n_ + m_);
}

void constrained_motion::evaluate(const expression_program& program, double t, const double* x, double* out) const
{
    std::copy(x, x + 2 * n_, symbols_.begin());
    symbols_[2 * n_] = t;
    program.run(symbols_.data(), scratch_, out);
}

void constrained_motion::solve(double t, const double* x, double* acceleration, double* multipliers) const
{
    evaluate(dynamics_, t, x, outputs_.data());
    const auto n = static_cast<Eigen::Index>(n_), m = static_cast<Eigen::Index>(m_);
    Eigen::MatrixXd system = Eigen::MatrixXd::Zero(n + m, n + m);
    Eigen::VectorXd right(n + m);
    const double* mass = outputs_.data();
    const double* force = mass + n_ * n_;
    const double* a = force + n_;
    const double* bias = a + m_ * n_;
    for (Eigen::Index i = 0; i < n; ++i) {
        for (Eigen::Index j = 0; j < n; ++j)
            system(i, j) = mass[i * n + j];
        right[i] = force[i];
    }
    for (Eigen::Index k = 0; k < m; ++k) {
        for (Eigen::Index j = 0; j < n; ++j) {
            system(n + k, j) = a[k * n + j];
            system(j, n + k) = -a[k * n + j];
        }
        right[n + k] = -bias[k];
    }
    Eigen::FullPivLU<Eigen::MatrixXd> lu(system);
    if (!right.allFinite() || !system.allFinite() || !lu.isInvertible())
        throw computation_error("at t = " + message_number(t) + " the constrained equations have no unique "
                                "accelerations (the matrix [M −Aᵀ; A 0] is singular or not finite)");
    Eigen::VectorXd solution = lu.solve(right);
    for (Eigen::Index i = 0; i < n; ++i)
        acceleration[i] = solution[i];
    if (multipliers)
        for (Eigen::Index k = 0; k < m; ++k)
            multipliers[k] = solution[n + k];
}

std::vector<double> constrained_motion::residuals(double t, const double* x) const
{
    std::vector<double> values(2 * m_);
    evaluate(residuals_, t, x, values.data());
    return values;
}

double constrained_motion::residual(double t, const double* x) const
{
    double largest = 0;
    for (double v : residuals(t, x))
        largest = std::max(largest, std::abs(v));
    return largest;
}

void constrained_motion::project(double t, double* x) const
{
    const auto n = static_cast<Eigen::Index>(n_), m = static_cast<Eigen::Index>(m_);
    std::vector<double> values(2 * m_);
    auto rows = [&](bool holonomic_only) {
        evaluate(dynamics_, t, x, outputs_.data());
        const double* a = outputs_.data() + n_ * n_ + n_;
        Eigen::MatrixXd matrix = Eigen::MatrixXd::Zero(m, n);
        for (Eigen::Index k = 0; k < m; ++k)
            if (!holonomic_only || holonomic_[static_cast<std::size_t>(k)])
                for (Eigen::Index j = 0; j < n; ++j)
                    matrix(k, j) = a[k * n + j];
        return matrix;
    };
    for (int iteration = 0; iteration < 8; ++iteration) {
        evaluate(residuals_, t, x, values.data());
        Eigen::VectorXd g = Eigen::Map<Eigen::VectorXd>(values.data(), m);
        if (g.lpNorm<Eigen::Infinity>() < 1e-14)
            break;
        Eigen::VectorXd step = rows(true).completeOrthogonalDecomposition().solve(g);
        for (Eigen::Index j = 0; j < n; ++j)
            x[j] -= step[j];
    }
    evaluate(residuals_, t, x, values.data());
    Eigen::VectorXd velocity_residual = Eigen::Map<Eigen::VectorXd>(values.data() + m_, m);
    Eigen::VectorXd change = rows(false).completeOrthogonalDecomposition().solve(velocity_residual);
    for (Eigen::Index j = 0; j < n; ++j)
        x[n + j] -= change[j];
}

double constrained_motion::energy(const double* x) const
{
    double e = 0;
    evaluate(energy_, 0, x, &e);
    return e;
}

ode_system constrained_motion::system() const
{
    ode_system s;
    s.dimension = 2 * n_;
    s.rhs = [this](double t, const double* x, double* dxdt) {
        std::copy(x + n_, x + 2 * n_, dxdt);
        solve(t, x, dxdt + n_, nullptr);
    };
    return s;
}

/// The bad input of an initial state `given` off the constraints: located at the written
/// value that the projection (`projected`, null when it did not converge) moves most, else
/// at the `initial` line, else at the `simulate` line; it names each constraint missed and
/// by how much, and suggests the projected state as an `initial` line.
scene_error off_constraints(const model& scene, const constrained_motion& motion, const std::vector<double>& given,
                            const std::vector<double>* projected, double tolerance)
{
    const std::size_t n = motion.coordinates(), m = motion.constraints();
    const std::vector<double> residuals = motion.residuals(0, given.data());
    std::string missed;
    for (std::size_t k = 0; k < m; ++k) {
        const double position = std::abs(residuals[k]), velocity = std::abs(residuals[m + k]);
        if (position > tolerance)
            missed += (missed.empty() ? "`" : ", `") + scene.constraints[k].name + "` by " + message_number(position, 3);
        else if (velocity > tolerance)
            missed += (missed.empty() ? "`" : ", `") + scene.constraints[k].name + "` by " +
                      message_number(velocity, 3) + " in the velocities";
    }
    std::string message = "the initial state is off the constraints (" + missed + ")";
    if (projected) {
        std::string line;
        for (std::size_t i = 0; i < 2 * n; ++i)
            if (i < n || (*projected)[i] != 0)
                line += (line.empty() ? "" : ", ") + scene.coordinates[i % n].name + (i < n ? "" : "'") + " = " +
                        round_trip((*projected)[i]);
        message += "; projected onto them by least change it is `initial " + line +
                   "`: start from a state on the constraints, or pass --project-initial (Python: "
                   "project_initial=True) to start from the projected one";
    } else {
        message += ", and projecting it onto them by least change does not converge: start from a state on the "
                   "constraints";
    }
    written_at at{{scene.file, 1, 1}, ""};
    if (scene.simulation)
        at = scene.simulation->statement;
    if (scene.initial) {
        at = scene.initial->statement;
        double moved = -1;
        for (std::size_t i = 0; i < 2 * n; ++i) {
            const auto& written = i < n ? scene.initial->position_written : scene.initial->velocity_written;
            auto found = written.find(scene.coordinates[i % n].name);
            const double change = projected ? std::abs((*projected)[i] - given[i]) : 0;
            if (found != written.end() && change > moved) {
                moved = change;
                at = found->second;
            }
        }
    }
    scene_error error(at.where, message);
    if (!at.line_text.empty())
        error.attach_line_text(at.line_text);
    return error;
}


simulation_result simulate_constrained(const model& scene, const equations_of_motion& equations,
                                       const simulation_settings& settings)
{
    simulation_result result;
    result.values = merged_values(scene);
    for (const coordinate& c : scene.coordinates)
        result.coordinates.push_back(c.name);
    result.evaluation = "interpreted: constrained motion";
    constrained_motion motion(scene, equations, result.values);
    const std::size_t n = motion.coordinates(), m = motion.constraints();

    const simulation_span span = simulation_span_of(scene, settings);
    const double until = span.until;
    result.tolerance = span.tolerance;
    result.run_tolerance = result.tolerance;
    result.absolute_tolerance = result.tolerance; // projected pieces: absolute as relative
    const std::string method_name =
        settings.method ? *settings.method : scene.simulation ? scene.simulation->method : "auto";
    ode_method method = ode_method::dop853;
    if (method_name == "auto") {
        result.choice = "auto: constrained motion, explicit dop853 between output times, projected onto the "
                        "constraints after each";
    } else {
        std::optional<ode_method> named = ode_method_from_name(method_name);
        if (!named)
            throw computation_error("unknown method `" + method_name + "`");
        if (*named == ode_method::bdf || *named == ode_method::implicit_midpoint)
            throw computation_error("a constrained simulation uses an explicit method (dopri5, rkf78, dop853, "
                                    "bulirsch-stoer), not `" + method_name + "`");
        method = *named;
        result.choice = "as asked, projected onto the constraints after each output time";
    }
    result.method = to_string(method);

    // A state off the constraints is not the motion the user wrote: run from it only when
    // asked to project it, and then say where it was moved to.
    std::vector<double> x0 = initial_state_vector(scene, result.values);
    const double initial_residual = motion.residual(0, x0.data());
    if (initial_residual > result.tolerance) {
        const std::vector<double> given = x0;
        motion.project(0, x0.data());
        const bool converged = motion.residual(0, x0.data()) <= result.tolerance;
        if (!settings.project_initial || !converged)
            throw off_constraints(scene, motion, given, converged ? &x0 : nullptr, result.tolerance);
        result.initial_residual = initial_residual;
        result.projected_initial = x0;
    }
    double output_step = until / 1000;
    if (scene.simulation && scene.simulation->step)
        output_step = real_value(*scene.simulation->step, "the output step");
    std::vector<double> times;
    for (std::size_t k = 0;; ++k) {
        double t = static_cast<double>(k) * output_step;
        if (t >= until * (1 - 1e-12)) {
            times.push_back(until);
            break;
        }
        times.push_back(t);
    }
    const ode_system system = motion.system();
    auto piece = [&](const std::vector<double>& from, double start, double end, double tolerance,
                     trajectory* totals) {
        integration_options options;
        options.start = start;
        options.until = end;
        options.tolerance = tolerance;
        options.outputs = false;
        options.keep_states = false;
        options.max_seconds = settings.max_seconds;
        trajectory run = integrate(system, method, from, options);
        if (totals) {
            totals->steps += run.steps;
            totals->evaluations += run.evaluations;
        }
        return run.final_state;
    };
    auto multipliers_at = [&](double t, const std::vector<double>& x) {
        std::vector<double> qdd(n), lambda(m);
        motion.solve(t, x.data(), qdd.data(), lambda.data());
        return lambda;
    };

    // One run at `tolerance` with `pieces` integrations (and projections) per output interval:
    // the states at the output times, the residual, the sign changes.
    auto run_at = [&](double tolerance, bool find_events, int pieces) {
        const auto started = std::chrono::steady_clock::now();
        trajectory run;
        run.method = result.method;
        std::vector<double> x = x0;
        run.times.push_back(times[0]);
        run.states.push_back(x);
        double residual = 0;
        std::vector<double> lambda = multipliers_at(times[0], x);
        std::vector<bool> changed(m, false);
        for (std::size_t k = 1; k < times.size(); ++k) {
            std::vector<double> next = x;
            for (int p = 1; p <= pieces; ++p) {
                const double from = times[k - 1] + (times[k] - times[k - 1]) * (p - 1) / pieces;
                const double to = p == pieces ? times[k] : times[k - 1] + (times[k] - times[k - 1]) * p / pieces;
                next = piece(next, from, to, tolerance, &run);
                residual = std::max(residual, motion.residual(to, next.data()));
                motion.project(to, next.data());
            }
            std::vector<double> next_lambda = multipliers_at(times[k], next);
            for (std::size_t c = 0; c < m && find_events; ++c) {
                if (changed[c] || !(lambda[c] * next_lambda[c] < 0))
                    continue;
                changed[c] = true;
                // Bisection on the time after times[k - 1] where λ_c changes sign.
                double low = 0, high = times[k] - times[k - 1];
                std::vector<double> at_event = next;
                for (int i = 0; i < 60 && high - low > 1e-13 * std::max(1.0, until); ++i) {
                    double middle = 0.5 * (low + high);
                    std::vector<double> there = piece(x, times[k - 1], times[k - 1] + middle, tolerance, nullptr);
                    if (multipliers_at(times[k - 1] + middle, there)[c] * lambda[c] > 0) {
                        low = middle;
                    } else {
                        high = middle;
                        at_event = there;
                    }
                }
                result.constraint_events.push_back({scene.constraints[c].name, times[k - 1] + high, at_event});
            }
            x = next;
            lambda = next_lambda;
            run.times.push_back(times[k]);
            run.states.push_back(x);
        }
        run.final_state = x;
        run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        if (motion.conservative()) {
            const double e0 = motion.energy(x0.data());
            double drift = 0;
            for (const std::vector<double>& state : run.states)
                drift = std::max(drift, std::abs(motion.energy(state.data()) - e0));
            run.invariant_drift.push_back({"energy", e0 != 0 ? drift / std::abs(e0) : drift});
        }
        return std::make_pair(run, residual);
    };
    auto [run, residual] = run_at(result.tolerance, true, 1);
    result.run = run;
    result.constraint_residual = residual;
    if (settings.estimate_error && run.seconds < settings.max_seconds / 4) {
        const double fine = std::max(result.tolerance / 1000, 1e-14);
        trajectory check = run_at(fine, false, 2).first;
        result.error_estimate = trajectory_difference(result.run, check);
        result.error_basis = "against " + result.method + " at tolerance " + message_number(fine, 3) +
                             " with two projected pieces per output interval";
    }
    return result;
}

} // namespace lagrange
