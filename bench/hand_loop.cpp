// SPDX-License-Identifier: GPL-2.0-or-later
/** @file hand_loop.cpp
 *  The hand-written DOP853 loops that the engine is held against (bench/hand_dop853.h, with
 *  hand-written right-hand sides): what a programmer would write for one problem in C++, at the
 *  engine's tolerance convention (per step tolerance/12, atol = rtol).
 *
 *    hand_loop flip COUNT UNTIL TOLERANCE THREADS OUT.csv
 *        the flip-time map of the equal-mass double pendulum over theta, phi = -3.1..3.1:COUNT
 *        (as `lagrange ensemble … --measure flip_time`); prints `seconds points steps rerun_steps`
 *        (rerun_steps, untimed: those of the points lagrange reruns for its error estimate)
 *    hand_loop poincare STARTS.csv TOLERANCE CROSSINGS UNTIL THREADS OUT.csv
 *        Hénon–Heiles cut by x = 0, x' > 0 from each orbit's first row of STARTS.csv (a CSV of
 *        `lagrange poincare`), as many crossings (the start counts) or until UNTIL; writes the
 *        crossings as `lagrange poincare` does; prints `seconds crossings steps`
 *    hand_loop simulate TOLERANCE UNTIL OUTPUTS REPEATS M m l g THETA PHI
 *        the double pendulum from rest at (THETA, PHI), its state at OUTPUTS + 1 equally spaced
 *        times kept and its energy checked there (as `lagrange simulate`); prints `seconds steps
 *        error energy_drift theta phi theta' phi'` at the end (seconds: the fastest of REPEATS
 *        runs; error: against the same loop at TOLERANCE/1000, max over the times of the state's
 *        difference over the largest state, as simulate's) */
#include "hand_dop853.h"

#include <boost/math/tools/roots.hpp>

#include <atomic>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

constexpr double pi = 3.141592653589793238462643383279502884;

/// The planar double pendulum in absolute angles: M θ̈-row and φ̈-row of the Lagrange
/// equations solved by Cramer's rule.
struct double_pendulum {
    double M = 1, m = 1, l = 1, g = 9.81;
    void operator()(double, const double* y, double* dy) const
    {
        const double theta = y[0], phi = y[1], w1 = y[2], w2 = y[3];
        const double s = std::sin(theta - phi), c = std::cos(theta - phi);
        const double r1 = -m * l * s * w2 * w2 - (M + m) * g * std::sin(theta);
        const double r2 = l * s * w1 * w1 - g * std::sin(phi);
        const double det = l * l * (M + m * s * s);
        dy[0] = w1;
        dy[1] = w2;
        dy[2] = (r1 * l - m * l * c * r2) / det;
        dy[3] = ((M + m) * l * r2 - l * c * r1) / det;
    }
    double energy(const double* y) const
    {
        const double w1 = y[2], w2 = y[3];
        return 0.5 * (M + m) * l * l * w1 * w1 + m * l * l * std::cos(y[0] - y[1]) * w1 * w2 +
               0.5 * m * l * l * w2 * w2 - (M + m) * g * l * std::cos(y[0]) - m * g * l * std::cos(y[1]);
    }
};

/// Hénon–Heiles: V = (x² + y²)/2 + x²y − y³/3.
struct henon_heiles {
    void operator()(double, const double* s, double* ds) const
    {
        const double x = s[0], y = s[1];
        ds[0] = s[2];
        ds[1] = s[3];
        ds[2] = -x - 2 * x * y;
        ds[3] = -y - x * x + y * y;
    }
};

double seconds_since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string shortest(double x)
{
    char buffer[32];
    auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, x);
    return std::string(buffer, end);
}

double grid(double from, double to, std::size_t count, std::size_t k)
{
    if (count <= 1 || k == 0)
        return from;
    if (k + 1 == count)
        return to;
    return from + static_cast<double>(k) / static_cast<double>(count - 1) * (to - from);
}

/// Runs work(index) for 0 … count−1 on `threads` threads, handing out chunks of 16.
template <class W>
void parallel(std::size_t count, std::size_t threads, W work)
{
    std::atomic<std::size_t> next{0};
    auto worker = [&] {
        for (;;) {
            std::size_t begin = next.fetch_add(16);
            if (begin >= count)
                return;
            for (std::size_t i = begin; i < std::min(count, begin + 16); ++i)
                work(i);
        }
    };
    std::vector<std::thread> pool;
    for (std::size_t k = 1; k < threads; ++k)
        pool.emplace_back(worker);
    worker();
    for (std::thread& t : pool)
        t.join();
}

double band(double q) { return std::floor((q + pi) / (2 * pi)); }

/// The first time either angle passes an odd multiple of π (inf if none before `until`).
double flip_time(double theta, double phi, double until, double tolerance, long& steps)
{
    hand::dop853<4, double_pendulum> run(double_pendulum{}, tolerance);
    const double y0[4] = {theta, phi, 0, 0};
    run.start(0, y0, until);
    const double bands[2] = {band(theta), band(phi)};
    double flip = std::numeric_limits<double>::infinity();
    while (run.t() < until) {
        const double t0 = run.t();
        if (!run.step(until)) {
            flip = std::nan("");
            break;
        }
        for (int c = 0; c < 2; ++c) {
            const double now = band(run.y()[c]);
            if (now == bands[c])
                continue;
            const double level = now > bands[c] ? pi * (2 * bands[c] + 1) : pi * (2 * bands[c] - 1);
            double at[4];
            auto side = [&](double t) {
                run.dense(t, at);
                return at[c] - level;
            };
            boost::uintmax_t iterations = 200;
            auto root = boost::math::tools::toms748_solve(side, t0, run.t(), side(t0), run.y()[c] - level,
                                                          boost::math::tools::eps_tolerance<double>(53), iterations);
            flip = std::min(flip, root.second);
        }
        if (flip < std::numeric_limits<double>::infinity())
            break;
    }
    steps += run.steps();
    return flip;
}

int flip(int argc, char** argv)
{
    if (argc != 7)
        throw std::invalid_argument("hand_loop flip COUNT UNTIL TOLERANCE THREADS OUT.csv");
    const std::size_t count = std::stoul(argv[2]), threads = std::stoul(argv[5]);
    const double until = std::stod(argv[3]), tolerance = std::max(std::stod(argv[4]) / 12, 1e-15);
    const std::size_t points = count * count;
    std::vector<double> flips(points);
    std::vector<long> steps(points);
    const auto started = std::chrono::steady_clock::now();
    parallel(points, threads, [&](std::size_t i) {
        flips[i] = flip_time(grid(-3.1, 3.1, count, i / count), grid(-3.1, 3.1, count, i % count), until,
                             tolerance, steps[i]);
    });
    const double seconds = seconds_since(started);
    // Untimed: the steps of lagrange's error-estimate reruns (every min(61, points/100)-th point
    // again at a tolerance 1000 times tighter), so that the steps of both sides can be matched.
    const std::size_t every = std::max<std::size_t>(1, std::min<std::size_t>(61, points / 100));
    long rerun_steps = 0;
    for (std::size_t i = 0; i < points; i += every)
        if (!std::isnan(flips[i]))
            flip_time(grid(-3.1, 3.1, count, i / count), grid(-3.1, 3.1, count, i % count), until,
                      std::max(tolerance / 1000, 1e-15), rerun_steps);
    std::ofstream out(argv[6]);
    out << "theta,phi,flip_time\n";
    long total = 0;
    for (std::size_t i = 0; i < points; ++i) {
        out << shortest(grid(-3.1, 3.1, count, i / count)) << ',' << shortest(grid(-3.1, 3.1, count, i % count))
            << ',' << shortest(flips[i]) << '\n';
        total += steps[i];
    }
    std::printf("%.6f %zu %ld %ld\n", seconds, points, total, rerun_steps);
    return 0;
}

/// One Hénon–Heiles orbit cut by x = 0 upwards: rows `t, x, y, x', y'`, the start first.
std::vector<double> orbit(const double* start, double tolerance, std::size_t crossings, double until, long& steps)
{
    std::vector<double> rows(start, start + 4);
    rows.insert(rows.begin(), 0.0);
    hand::dop853<4, henon_heiles> run(henon_heiles{}, tolerance);
    run.start(0, start, until);
    std::size_t count = 1;
    while (count < crossings && run.t() < until) {
        double before[4], at[4];
        std::copy(run.y(), run.y() + 4, before);
        const double t0 = run.t();
        if (!run.step(until))
            break;
        const double t1 = run.t();
        const double* after = run.y();
        double times[9] = {t0, t1}, sides[9] = {before[0], after[0]};
        int samples = 2;
        // Both ends on one side, going towards x = 0 at the start and away at the end: the
        // orbit may have passed through and back within the step, so look inside it.
        if (sides[0] * sides[1] > 0 && sides[0] * before[2] < 0 && sides[1] * after[2] > 0) {
            for (int s = 1; s < 8; ++s) {
                times[s] = t0 + (t1 - t0) * s / 8;
                run.dense(times[s], at);
                sides[s] = at[0];
            }
            times[8] = t1;
            sides[8] = after[0];
            samples = 9;
        }
        for (int s = 0; s + 1 < samples && count < crossings; ++s) {
            if (!(sides[s] < 0 && sides[s + 1] >= 0))
                continue;
            double t = times[s + 1], x[4];
            if (sides[s + 1] != 0) {
                boost::uintmax_t iterations = 200;
                auto root = boost::math::tools::toms748_solve(
                    [&](double u) {
                        run.dense(u, at);
                        return at[0];
                    },
                    times[s], times[s + 1], sides[s], sides[s + 1], boost::math::tools::eps_tolerance<double>(53),
                    iterations);
                t = root.first + (root.second - root.first) / 2;
            }
            if (t == t1)
                std::copy(after, after + 4, x);
            else
                run.dense(t, x);
            rows.push_back(t);
            rows.insert(rows.end(), x, x + 4);
            ++count;
        }
    }
    steps += run.steps();
    return rows;
}

int poincare(int argc, char** argv)
{
    if (argc != 8)
        throw std::invalid_argument("hand_loop poincare STARTS.csv TOLERANCE CROSSINGS UNTIL THREADS OUT.csv");
    const double tolerance = std::max(std::stod(argv[3]) / 12, 1e-15), until = std::stod(argv[5]);
    const std::size_t crossings = std::stoul(argv[4]), threads = std::stoul(argv[6]);
    // Each orbit's first row: `orbit,t,x,y,x_dot,y_dot`.
    std::ifstream in(argv[2]);
    std::string line;
    std::getline(in, line);
    std::vector<std::vector<double>> starts;
    long last = -1;
    while (std::getline(in, line)) {
        std::vector<double> fields;
        std::stringstream text(line);
        for (std::string field; std::getline(text, field, ',');)
            fields.push_back(std::stod(field));
        if (fields.size() < 6 || static_cast<long>(fields[0]) == last)
            continue;
        last = static_cast<long>(fields[0]);
        starts.emplace_back(fields.begin() + 2, fields.begin() + 6);
    }
    std::vector<std::vector<double>> rows(starts.size());
    std::vector<long> steps(starts.size());
    const auto started = std::chrono::steady_clock::now();
    parallel(starts.size(), threads,
             [&](std::size_t k) { rows[k] = orbit(starts[k].data(), tolerance, crossings, until, steps[k]); });
    const double seconds = seconds_since(started);
    std::ofstream out(argv[7]);
    out << "orbit,t,x,y,x_dot,y_dot\n";
    std::size_t total = 0;
    long total_steps = 0;
    for (std::size_t k = 0; k < rows.size(); ++k) {
        for (std::size_t p = 0; p + 5 <= rows[k].size(); p += 5, ++total) {
            out << k;
            for (int j = 0; j < 5; ++j)
                out << ',' << shortest(rows[k][p + j]);
            out << '\n';
        }
        total_steps += steps[k];
    }
    std::printf("%.6f %zu %ld\n", seconds, total, total_steps);
    return 0;
}

/// The double pendulum's states at outputs + 1 times, as simulate keeps them, with the
/// largest drift of the energy there relative to its height above the equilibrium at rest.
std::vector<std::vector<double>> trajectory(const double_pendulum& f, const double* y0, double tolerance,
                                            double until, std::size_t outputs, long& steps, double& drift)
{
    const double rest[4] = {0, 0, 0, 0}, e0 = f.energy(y0), scale = std::abs(e0 - f.energy(rest));
    drift = 0;
    hand::dop853<4, double_pendulum> run(f, tolerance);
    run.start(0, y0, until);
    std::vector<std::vector<double>> states;
    states.reserve(outputs + 1);
    states.emplace_back(y0, y0 + 4);
    std::vector<double> at(4);
    for (std::size_t k = 1; k <= outputs; ++k) {
        const double t = k == outputs ? until : until * static_cast<double>(k) / static_cast<double>(outputs);
        while (run.t() < t)
            if (!run.step(until))
                throw std::runtime_error("the step size collapsed");
        if (run.t() == t)
            states.emplace_back(run.y(), run.y() + 4);
        else {
            run.dense(t, at.data());
            states.push_back(at);
        }
        drift = std::max(drift, std::abs(f.energy(states.back().data()) - e0) / scale);
    }
    steps = run.steps();
    return states;
}

int simulate(int argc, char** argv)
{
    if (argc != 12)
        throw std::invalid_argument("hand_loop simulate TOLERANCE UNTIL OUTPUTS REPEATS M m l g THETA PHI");
    const double tolerance = std::stod(argv[2]), until = std::stod(argv[3]);
    const std::size_t outputs = std::stoul(argv[4]), repeats = std::stoul(argv[5]);
    const double_pendulum f{std::stod(argv[6]), std::stod(argv[7]), std::stod(argv[8]), std::stod(argv[9])};
    const double y0[4] = {std::stod(argv[10]), std::stod(argv[11]), 0, 0};
    const double step_tolerance = std::max(tolerance / 12, 1e-15);
    double best = std::numeric_limits<double>::infinity();
    long steps = 0;
    double drift = 0, reference_drift = 0;
    std::vector<std::vector<double>> states;
    for (std::size_t r = 0; r < repeats; ++r) {
        const auto started = std::chrono::steady_clock::now();
        states = trajectory(f, y0, step_tolerance, until, outputs, steps, drift);
        best = std::min(best, seconds_since(started));
    }
    long reference_steps = 0;
    const auto reference =
        trajectory(f, y0, std::max(step_tolerance / 1000, 1e-15), until, outputs, reference_steps, reference_drift);
    double difference = 0, size = 0;
    for (std::size_t k = 0; k < states.size(); ++k) {
        double d = 0, s = 0;
        for (int i = 0; i < 4; ++i) {
            d += (states[k][i] - reference[k][i]) * (states[k][i] - reference[k][i]);
            s += reference[k][i] * reference[k][i];
        }
        difference = std::max(difference, std::sqrt(d));
        size = std::max(size, std::sqrt(s));
    }
    const std::vector<double>& end = states.back();
    std::printf("%.9f %ld %.3g %.3g %.17g %.17g %.17g %.17g\n", best, steps, difference / size, drift, end[0], end[1],
                end[2], end[3]);
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    try {
        const std::string mode = argc > 1 ? argv[1] : "";
        if (mode == "flip")
            return flip(argc, argv);
        if (mode == "poincare")
            return poincare(argc, argv);
        if (mode == "simulate")
            return simulate(argc, argv);
        std::cerr << "usage: hand_loop flip|poincare|simulate … (see bench/hand_loop.cpp)\n";
        return 2;
    } catch (const std::exception& error) {
        std::cerr << "hand_loop: " << error.what() << '\n';
        return 1;
    }
}
