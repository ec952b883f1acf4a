// SPDX-License-Identifier: GPL-2.0-or-later
/** @file numeric_modes.cpp
 *  Benchmark: numeric normal modes per second with compiled_modes (double pendulum,
 *  and a 6-mass chain with 7 springs between walls, all parameters distinct), then
 *  for each numeric route the maximum relative error of ω on the double pendulum's
 *  sweep m/M = 1e-16 … 1e16 against a 60-digit reference, and the time per point.
 *  Usage: numeric_modes [points] [runs] */
#include "numeric/compiled_modes.h"
#include "program/double_double.h"

#include <cln/cln.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

namespace {

/// This thread's CPU time: the machine is shared, and wall time would count other
/// processes' turns on the core.
struct clock_type {
    using duration = std::chrono::nanoseconds;
    using time_point = std::chrono::time_point<clock_type, duration>;
    static time_point now()
    {
        timespec t{};
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
        return time_point(duration(static_cast<long long>(t.tv_sec) * 1000000000LL + t.tv_nsec));
    }
};

struct system_under_test {
    std::vector<lagrange::parameter> parameters;
    lagrange::linearization_result linear;
};

system_under_test double_pendulum()
{
    system_under_test s;
    GiNaC::possymbol M("M"), m("m"), l("l"), g("g");
    s.parameters = {{"M", M}, {"m", m}, {"l", l}, {"g", g}};
    s.linear.kinetic = GiNaC::matrix{{(M + m) * l * l, m * l * l}, {m * l * l, m * l * l}};
    s.linear.potential = GiNaC::matrix{{(M + m) * g * l, 0}, {0, m * g * l}};
    return s;
}

system_under_test spring_chain(int masses)
{
    system_under_test s;
    std::vector<GiNaC::ex> m, k;
    for (int i = 1; i <= masses; ++i) {
        GiNaC::possymbol symbol("m" + std::to_string(i));
        s.parameters.push_back({"m" + std::to_string(i), symbol});
        m.push_back(symbol);
    }
    for (int i = 1; i <= masses + 1; ++i) {
        GiNaC::possymbol symbol("k" + std::to_string(i));
        s.parameters.push_back({"k" + std::to_string(i), symbol});
        k.push_back(symbol);
    }
    s.linear.kinetic = GiNaC::matrix(masses, masses);
    s.linear.potential = GiNaC::matrix(masses, masses);
    for (int i = 0; i < masses; ++i) {
        s.linear.kinetic(i, i) = m[i];
        s.linear.potential(i, i) = k[i] + k[i + 1];
        if (i + 1 < masses)
            s.linear.potential(i, i + 1) = s.linear.potential(i + 1, i) = -k[i + 1];
    }
    return s;
}

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

/// Median nanoseconds per point of evaluating `points` (row-major, one row per point).
double time_per_point(lagrange::compiled_modes& modes, const std::vector<double>& points, std::size_t width,
                      int runs, bool with_modes, bool batch)
{
    std::size_t n = modes.size(), count = points.size() / width;
    constexpr std::size_t block = 1024;
    std::vector<double> w2(n * block), w(n * block), error(n * block), shapes(n * n * block);
    std::vector<double> times;
    double sink = 0;
    for (int r = 0; r < runs; ++r) {
        auto start = clock_type::now();
        if (batch) {
            for (std::size_t p = 0; p < count; p += block) {
                modes.evaluate_batch(std::min(block, count - p), &points[p * width], width, w2.data(), w.data(),
                                     error.data(), with_modes ? shapes.data() : nullptr);
                sink += w[0];
            }
        } else {
            for (std::size_t p = 0; p < count; ++p) {
                modes.evaluate(&points[p * width], w2.data(), w.data(), error.data(),
                               with_modes ? shapes.data() : nullptr);
                sink += w[0];
            }
        }
        std::chrono::duration<double, std::nano> elapsed = clock_type::now() - start;
        times.push_back(elapsed.count() / count);
    }
    if (sink == 42)
        std::puts("");
    return median(times);
}

std::vector<double> random_points(std::size_t width, std::size_t count, unsigned seed)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> scale(0.5, 2.0);
    std::vector<double> points(width * count);
    for (double& x : points)
        x = scale(random);
    return points;
}

} // namespace

int main(int argc, char** argv)
{
    if (std::getenv("LAGRANGE_PORTABLE_KERNELS")) // the kernels without FMA, for comparison
        lagrange::use_fma_kernels(false);
    std::size_t count = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 1000000;
    int runs = argc > 2 ? std::atoi(argv[2]) : 5;

    std::printf("throughput (median of %d runs, %zu random points)\n", runs, count);
    std::printf("%-24s %-30s %12s %14s\n", "system", "route", "ns/point", "points/s");
    // numeric_modes N RUNS pendulum|chain: that system's throughput only (for profiling);
    // numeric_modes N RUNS all DIR: everything, and the points written to DIR (one point
    // per line) for bench/modes.sh to run scipy on the same matrices.
    std::string only = argc > 3 && std::string(argv[3]) != "all" ? argv[3] : "";
    std::string dump = argc > 4 ? argv[4] : "";
    auto write_points = [&](const std::string& name, const std::vector<double>& points, std::size_t width,
                            std::size_t limit) {
        if (dump.empty())
            return;
        std::FILE* out = std::fopen((dump + "/" + name).c_str(), "w");
        if (!out)
            return;
        for (std::size_t p = 0; p < points.size() / width && p < limit; ++p)
            for (std::size_t k = 0; k < width; ++k)
                std::fprintf(out, "%.17g%c", points[p * width + k], k + 1 < width ? ' ' : '\n');
        std::fclose(out);
    };
    for (bool chain : {false, true}) {
        if ((only == "pendulum" && chain) || (only == "chain" && !chain))
            continue;
        system_under_test s = chain ? spring_chain(6) : double_pendulum();
        lagrange::compiled_modes modes(s.parameters, s.linear);
        std::vector<double> points = random_points(s.parameters.size(), count, 7);
        write_points(chain ? "chain6.txt" : "pendulum.txt", points, s.parameters.size(), 20000);
        std::vector<double> w2(modes.size()), w(modes.size()), error(modes.size());
        std::string route = lagrange::to_string(modes.evaluate(points.data(), w2.data(), w.data(), error.data(), nullptr));
        for (bool batch : {false, true})
            for (bool with_modes : {false, true}) {
                double ns = time_per_point(modes, points, s.parameters.size(), runs, with_modes, batch);
                std::string name = std::string(chain ? "chain6" : "pendulum") + (with_modes ? "+modes" : "") +
                                   (batch ? "/batch" : "/single");
                std::printf("%-24s %-30s %12.1f %14.3g\n", name.c_str(), route.c_str(), ns, 1e9 / ns);
            }
    }

    if (!only.empty())
        return 0;

    // The ρ sweep: M and l random in [0.5, 2], g = 9.81, m = ρM.
    std::vector<double> sweep;
    std::mt19937 random(11);
    std::uniform_real_distribution<double> scale(0.5, 2.0);
    for (int k = 0; k <= 320; ++k) {
        double rho = std::pow(10.0, -16.0 + 0.1 * k), M = scale(random), l = scale(random);
        sweep.insert(sweep.end(), {M, rho * M, l, 9.81});
    }
    std::size_t points = sweep.size() / 4;
    write_points("sweep.txt", sweep, 4, points);
    cln::float_format_t f = cln::float_format(60);
    std::vector<cln::cl_F> reference;
    for (std::size_t p = 0; p < points; ++p) {
        auto F = [&](double x) { return cln::cl_float(cln::rational(cln::cl_DF(x)), f); };
        const double* x = &sweep[4 * p];
        cln::cl_F a = F(x[0]) * F(x[2]) * F(x[2]), b = F(2) * (F(x[0]) + F(x[1])) * F(x[3]) * F(x[2]);
        cln::cl_F c = (F(x[0]) + F(x[1])) * F(x[3]) * F(x[3]), root = cln::sqrt(b * b - F(4) * a * c);
        reference.push_back(cln::sqrt((b - root) / (F(2) * a)));
        reference.push_back(cln::sqrt((b + root) / (F(2) * a)));
    }
    std::printf("\ndouble pendulum, m/M = 1e-16 ... 1e16 (%zu points), error against a 60-digit reference\n", points);
    std::printf("%-34s %14s %14s %12s %8s\n", "route", "max rel error", "max bound", "ns/point", "failed");
    struct route {
        std::string name;
        lagrange::modes_method method;
        int digits;
    };
    using lagrange::modes_method;
    for (const route& r : {route{"automatic", modes_method::automatic, 50},
                           route{"closed form (double-double)", modes_method::closed_form, 50},
                           route{"symbolic normalization", modes_method::symbolic_normalized, 50},
                           route{"Eigen generalized", modes_method::eigen_generalized, 50},
                           route{"CLN 30 digits", modes_method::high_precision, 30},
                           route{"CLN 50 digits", modes_method::high_precision, 50}}) {
        lagrange::compiled_modes_options options;
        options.method = r.method;
        options.digits = r.digits;
        system_under_test s = double_pendulum();
        lagrange::compiled_modes modes(s.parameters, s.linear, options);
        double worst = 0, bound = 0;
        int failed = 0;
        std::vector<double> w2(2), w(2 * points), error(2 * points);
        std::vector<bool> ok(points, true);
        auto start = clock_type::now();
        for (std::size_t p = 0; p < points; ++p) {
            try {
                modes.evaluate(&sweep[4 * p], w2.data(), &w[2 * p], &error[2 * p], nullptr);
            } catch (const lagrange::computation_error&) {
                ok[p] = false;
                ++failed;
            }
        }
        std::chrono::duration<double, std::nano> elapsed = clock_type::now() - start;
        for (std::size_t p = 0; p < points; ++p)
            for (std::size_t k = 2 * p; ok[p] && k < 2 * p + 2; ++k) {
                cln::cl_F x = cln::cl_float(cln::rational(cln::cl_DF(w[k])), f);
                double e = cln::double_approx(cln::abs((x - reference[k]) / reference[k]));
                worst = std::max(worst, e);
                bound = std::max(bound, error[k]);
            }
        std::printf("%-34s %14.3g %14.3g %12.1f %8d\n", r.name.c_str(), worst, bound, elapsed.count() / points, failed);
    }
    return 0;
}
