// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_ensemble.cpp
 *  Ensembles (numeric/ensemble.h, ensemble_run.h, output/ensemble_output.h, `lagrange
 *  ensemble`): measures against closed forms, rows independent of the thread count, the
 *  double pendulum's energy bound on flips, resuming, and bad input. */
#include "helpers/cli_runner.h"
#include "engine/analysis.h"
#include "ensemble/run.h"
#include "helpers/scene_helpers.h"
#include "numeric/compiled_motion.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include <unistd.h>

using namespace lagrange_test;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

const std::string scenes = std::string(LAGRANGE_SOURCE_DIR) + "/tests/scenes/";
const std::string pendulum = scenes + "ensemble_double_pendulum.lag";

/// One coordinate q with T = ½ m q̇² and V = ½ SIGN m w² q²: a harmonic oscillator (+) or the
/// linearized inverted pendulum (−), whose solutions are known in closed form.
std::string linear_scene(const std::string& sign)
{
    return "parameters m w\ncoordinates q\nT = 1/2*m*q'^2\nV = " + sign +
           "1/2*m*w^2*q^2\nvalues m = 2, w = 3\ninitial q = 0.1, q' = 0.2\n";
}

struct computed {
    std::vector<std::vector<double>> rows;
    lagrange::ensemble_summary summary;
};

/// Runs the ensemble of `scene` and keeps every row.
computed run(const lagrange::model& scene, const std::string& grid, const std::string& measure, double until,
             std::size_t threads = 1, std::size_t random = 0)
{
    lagrange::analysis a = lagrange::analyze(scene, {lagrange::product::equations});
    lagrange::ensemble_settings settings;
    settings.until = until;
    settings.random = random;
    lagrange::ensemble_problem problem(scene, *a.equations, lagrange::parse_ensemble_grid(grid, scene, random > 0),
                                       lagrange::parse_ensemble_measure(measure, scene), settings);
    computed result;
    std::size_t expected = 0;
    lagrange::ensemble_sink sink;
    sink.row = [&](std::size_t index, const double* row) {
        CHECK(index == expected++);
        result.rows.emplace_back(row, row + problem.columns().size());
    };
    lagrange::ensemble_run_options options;
    options.threads = threads;
    result.summary = lagrange::run_ensemble(problem, options, sink);
    REQUIRE(result.rows.size() == problem.points());
    return result;
}

/// The CSV rows of a file or text, as numbers (the header line dropped).
std::vector<std::vector<double>> csv_rows(const std::string& text)
{
    std::vector<std::vector<double>> rows;
    std::istringstream in(text);
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line)) {
        std::vector<double> row;
        std::istringstream cells(line);
        std::string cell;
        while (std::getline(cells, cell, ','))
            row.push_back(std::strtod(cell.c_str(), nullptr));
        rows.push_back(row);
    }
    return rows;
}

} // namespace

TEST_CASE("ensemble: max_lyapunov of linear systems is the closed form's growth rate", "[ensemble]")
{
    // Benettin's renormalizations multiply up to |Φ(T) v0| for a linear system, so the finite-time
    // exponent is log|Φ(T) v0| / T exactly, with v0 = (1, 1)/√2 and Φ the closed-form flow.
    const double w = 3, until = 12;
    const double a = 1 / std::sqrt(2.0), b = a;
    double unstable = std::log(std::hypot(a * std::cosh(w * until) + b / w * std::sinh(w * until),
                                          a * w * std::sinh(w * until) + b * std::cosh(w * until))) / until;
    double stable = std::log(std::hypot(a * std::cos(w * until) + b / w * std::sin(w * until),
                                        -a * w * std::sin(w * until) + b * std::cos(w * until))) / until;
    computed inverted = run(load(linear_scene("-")), "q=0.1..0.1:1", "max_lyapunov", until);
    CHECK_THAT(inverted.rows[0][1], WithinRel(unstable, 1e-7));
    CHECK_THAT(inverted.rows[0][1], WithinAbs(w, 0.1)); // λ = w = sqrt(g/l), up to the O(1/T) transient
    computed harmonic = run(load(linear_scene("")), "q=0.1..0.1:1", "max_lyapunov", until);
    CHECK_THAT(harmonic.rows[0][1], WithinAbs(stable, 1e-8));
    CHECK(std::abs(harmonic.rows[0][1]) < 0.1); // λ = 0
}

TEST_CASE("ensemble: floquet_stable of the Kapitza pendulum agrees with the floquet product", "[ensemble]")
{
    // Upright and driven: unstable at gamma = 60, stable at 120 (a²γ² > 2gl above γ ≈ 88.6).
    lagrange::model scene = load(read_file(std::string(LAGRANGE_SOURCE_DIR) + "/examples/kapitza_pendulum.lag"));
    lagrange::analysis a = lagrange::analyze(scene, {lagrange::product::equations, lagrange::product::floquet});
    REQUIRE(a.time);
    REQUIRE(a.floquet);
    lagrange::ensemble_settings settings;
    lagrange::ensemble_problem problem(scene, *a.equations, lagrange::parse_ensemble_grid("gamma=60..120:2", scene),
                                       lagrange::parse_ensemble_measure("floquet_stable", scene), settings, &*a.time);
    CHECK(problem.columns() == std::vector<std::string>{"gamma", "floquet_stable", "max_multiplier"});
    std::vector<std::vector<double>> rows;
    lagrange::ensemble_sink sink;
    sink.row = [&](std::size_t, const double* row) { rows.emplace_back(row, row + 3); };
    lagrange::run_ensemble(problem, {}, sink);
    REQUIRE(rows.size() == 2);
    CHECK(rows[0][1] == 0);
    CHECK(rows[1][1] == 1);
    // The floquet product (its own linearization and integration) at the scene's two values lines.
    for (const lagrange::floquet_point& f : *a.floquet) {
        double gamma = 0, largest = 0;
        for (const auto& [name, value] : f.values)
            if (name == "gamma")
                gamma = value;
        for (const std::complex<double>& mu : f.multipliers)
            largest = std::max(largest, std::abs(mu));
        INFO("gamma = " << gamma);
        CHECK_THAT(rows[gamma == 60 ? 0 : 1][2], WithinRel(largest, 1e-6));
    }
    lagrange::model still = load(linear_scene(""));
    lagrange::analysis b = lagrange::analyze(still, {lagrange::product::equations});
    CHECK_THROWS_WITH(lagrange::ensemble_problem(still, *b.equations, lagrange::parse_ensemble_grid("w=1..2:2", still),
                                                 lagrange::parse_ensemble_measure("floquet_stable", still), settings),
                      Catch::Contains("periodic in t"));
}

TEST_CASE("ensemble: final states of the harmonic oscillator and flip times of a free rotor", "[ensemble]")
{
    const double w = 3, until = 2.5;
    computed finals = run(load(linear_scene("")), "q=-1..1:5, q'=0..2:3", "final", until, 2);
    REQUIRE(finals.rows.size() == 15);
    for (const std::vector<double>& r : finals.rows) {
        double q0 = r[0], v0 = r[1];
        CHECK_THAT(r[2], WithinAbs(q0 * std::cos(w * until) + v0 / w * std::sin(w * until), 1e-8));
        CHECK_THAT(r[3], WithinAbs(-q0 * w * std::sin(w * until) + v0 * std::cos(w * until), 1e-7));
    }
    CHECK(finals.summary.sampled == 15); // a small ensemble checks every point at tolerance/1000
    CHECK(finals.summary.worst_error < 1e-7);
    CHECK(finals.summary.steps > 0);

    // q = q0 + v t: q reaches π at (π − q0)/v, −π at (−π − q0)/v; never when |v| is too small.
    lagrange::model rotor = load("parameters I\ncoordinates q\nT = 1/2*I*q'^2\nvalues I = 1\n");
    computed flips = run(rotor, "q=-3..3:7, q'=-2..2:5", "flip_time", 4, 3);
    for (const std::vector<double>& r : flips.rows) {
        double q0 = r[0], v = r[1];
        const double pi = std::acos(-1.0);
        double t = v > 0 ? (pi - q0) / v : v < 0 ? (-pi - q0) / v : HUGE_VAL;
        INFO("q0 = " << q0 << ", v = " << v);
        if (t <= 4)
            CHECK_THAT(r[2], WithinAbs(t, 1e-12));
        else
            CHECK(std::isinf(r[2]));
    }
}

TEST_CASE("ensemble: a tree's final states by the recursion agree with the expanded form", "[ensemble]")
{
    // A 3-link chain gridded over its first angle and the middle mass (a parameter symbol in
    // the recursion): each final state against compiled_motion's expanded form at that point.
    const std::string text = chain_scene(3) +
                             "values g = 9.81, m1 = 1, m2 = 1.5, m3 = 0.7, l1 = 1, l2 = 0.8, l3 = 1.2\n"
                             "initial q1 = 0.5, q2 = -0.3, q3 = 0.2, q2' = 1\n";
    lagrange::model scene = load(text);
    const double until = 1.5;
    lagrange::analysis a = lagrange::analyze(scene, {lagrange::product::equations});
    lagrange::ensemble_settings settings;
    settings.until = until;
    lagrange::ensemble_problem problem(scene, *a.equations, lagrange::parse_ensemble_grid("q1=-1..1:3, m2=0.5..2:2", scene, false),
                                       lagrange::parse_ensemble_measure("final", scene), settings);
    CHECK(problem.recursive());
    computed finals = run(scene, "q1=-1..1:3, m2=0.5..2:2", "final", until);
    CHECK(finals.summary.worst_error < 1e-7);
    for (const std::vector<double>& r : finals.rows) {
        auto values = lagrange::first_value_point(scene);
        values["m2"] = GiNaC::numeric(std::to_string(r[1]).c_str());
        lagrange::compiled_motion expanded(scene, *a.equations, values, lagrange::motion_form::expanded);
        lagrange::integration_options options;
        options.until = until;
        options.tolerance = 1e-12;
        const lagrange::trajectory reference = lagrange::integrate(
            expanded.system(), lagrange::ode_method::dop853, {r[0], -0.3, 0.2, 0, 1, 0}, options);
        INFO("q1 = " << r[0] << ", m2 = " << r[1]);
        for (std::size_t i = 0; i < 6; ++i)
            CHECK_THAT(r[2 + i], WithinAbs(reference.final_state[i], 1e-6));
    }
}

TEST_CASE("ensemble: the rows do not depend on the number of threads, and random points are reproducible",
          "[ensemble]")
{
    lagrange::model scene = load(read_file(pendulum));
    computed one = run(scene, "theta=-3..3:7, phi=-3..3:6", "flip_time", 6, 1);
    computed three = run(scene, "theta=-3..3:7, phi=-3..3:6", "flip_time", 6, 3);
    REQUIRE(one.rows.size() == three.rows.size());
    for (std::size_t k = 0; k < one.rows.size(); ++k)
        CHECK(std::memcmp(one.rows[k].data(), three.rows[k].data(), one.rows[k].size() * sizeof(double)) == 0);
    CHECK(one.summary.steps == three.summary.steps);
    CHECK(one.summary.worst_error == three.summary.worst_error);

    computed random_one = run(scene, "g=1..20:log, phi=-1..1", "final", 1, 1, 50);
    computed random_two = run(scene, "g=1..20:log, phi=-1..1", "final", 1, 2, 50);
    for (std::size_t k = 0; k < random_one.rows.size(); ++k) {
        CHECK(random_one.rows[k] == random_two.rows[k]);
        CHECK(random_one.rows[k][0] >= 1);
        CHECK(random_one.rows[k][0] <= 20);
        CHECK(std::abs(random_one.rows[k][1]) <= 1);
    }
}

TEST_CASE("ensemble: bad --grid and --measure are errors located in the option", "[ensemble]")
{
    lagrange::model scene = load(read_file(pendulum));
    auto require_grid_error = [&](const std::string& grid, int column, const std::string& fragment,
                                  bool random = false) {
        require_option_error("--grid", grid, [&] { lagrange::parse_ensemble_grid(grid, scene, random); }, column,
                             fragment);
    };
    require_grid_error("theta", 1, "name=from..to:count");
    require_grid_error("psi=0..1:3", 1, "`psi` is neither a coordinate");
    require_grid_error("theta=0..1:0", 12, "whole number");
    require_grid_error("theta=0..1:2.5", 12, "whole number");
    require_grid_error("theta=0..1", 11, "expected `:count`");
    require_grid_error("theta=1..0:3", 7, "runs backwards");
    require_grid_error("g=-1..2:3:log", 3, "both ends positive");
    require_grid_error("g=1..2:3:lin", 10, "expected `log`");
    require_grid_error("theta=a..1:3", 7, "`a` is not a number");
    require_grid_error("theta=0..1:3,, phi=0..1:2", 14, "empty grid entry");
    require_grid_error("theta=0..1:3, theta=0..2:2", 15, "already in the grid");
    require_grid_error("theta'=0..1:3, phi_dot=0..1:2, M=1..2:2, theta=0..nan:2", 51, "not a number");
    require_grid_error("g=0..1:log", 3, "both ends positive", true);
    CHECK(lagrange::parse_ensemble_grid("theta'=0..1:3, phi_dot=0..1:2, M=1..2:2", scene)[1].kind ==
          lagrange::ensemble_axis::target::velocity);
    CHECK_THROWS_WITH(lagrange::parse_ensemble_measure("flips", scene), Catch::Contains("unknown measure"));
    CHECK_THROWS_WITH(lagrange::parse_ensemble_measure("flip_time:psi", scene), Catch::Contains("not a coordinate"));
    CHECK(lagrange::parse_ensemble_measure("flip_time:phi", scene).coordinate == 1);
}

TEST_CASE("ensemble cli: the flip map is the same on 1 and 2 threads, and no flip where the energy forbids it",
          "[ensemble][cli]")
{
    const std::string args = "ensemble " + pendulum + " --grid \"theta=-3.1..3.1:21, phi=-3.1..3.1:21\" --until 8 "
                             "--measure flip_time";
    cli_result one = run_cli(args + " --threads 1", "", 60);
    cli_result two = run_cli(args + " --threads 2", "", 60);
    REQUIRE(one.exit_code == 0);
    REQUIRE(two.exit_code == 0);
    CHECK(one.out == two.out);
    CHECK(one.out.rfind("theta,phi,flip_time\n", 0) == 0);
    CHECK(one.err.find("integration steps") != std::string::npos);
    CHECK(one.err.find("worst error estimate") != std::string::npos);
    std::vector<std::vector<double>> rows = csv_rows(one.out);
    REQUIRE(rows.size() == 441);
    std::size_t flipped = 0, low_energy = 0;
    for (const std::vector<double>& r : rows) {
        // From rest the energy is −m g l (2 cos θ + cos φ); a flip of either bob needs at least
        // −m g l (the lower bob over the top, the upper one hanging): none where 2 cos θ + cos φ > 1,
        // a region that holds the 3 cos θ + cos φ > 2.
        double theta = r[0], phi = r[1];
        if (3 * std::cos(theta) + std::cos(phi) > 2 || 2 * std::cos(theta) + std::cos(phi) > 1) {
            ++low_energy;
            INFO("theta = " << theta << ", phi = " << phi);
            CHECK(std::isinf(r[2]));
        }
        flipped += std::isfinite(r[2]) ? 1 : 0;
    }
    CHECK(low_energy > 50);
    CHECK(flipped > 50); // the map is not empty: high-energy points do flip
}

TEST_CASE("ensemble cli: JSON, PNG, resume, and bad input", "[ensemble][cli][gnuplot]")
{
    const std::string grid = " --grid \"theta=-3..3:6, phi=-3..3:5\" --until 3 --measure flip_time";
    // JSON: the same numbers as CSV, null for no flip.
    std::string json_path = temporary_file("ensemble.json", "");
    cli_result csv = run_cli("ensemble " + pendulum + grid, "", 60);
    REQUIRE(csv.exit_code == 0);
    REQUIRE(run_cli("ensemble " + pendulum + grid + " -o " + json_path, "", 60).exit_code == 0);
    nlohmann::json j = nlohmann::json::parse(read_file(json_path));
    std::vector<std::vector<double>> rows = csv_rows(csv.out);
    REQUIRE(j["ensemble"]["rows"].size() == rows.size());
    CHECK(j["ensemble"]["columns"] == nlohmann::json({"theta", "phi", "flip_time"}));
    CHECK(j["ensemble"]["steps"].get<std::size_t>() > 0);
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const nlohmann::json& cell = j["ensemble"]["rows"][k][2];
        if (std::isinf(rows[k][2]))
            CHECK(cell.is_null());
        else
            CHECK(cell.get<double>() == rows[k][2]);
    }

    // --resume: a file cut in the middle of a row goes on to the same bytes as a whole run.
    std::string partial = csv.out.substr(0, csv.out.size() * 2 / 3);
    std::string resumed = temporary_file("resumed.csv", partial);
    cli_result again = run_cli("ensemble " + pendulum + grid + " --resume -o " + resumed, "", 60);
    REQUIRE(again.exit_code == 0);
    CHECK(read_file(resumed) == csv.out);
    std::string other = temporary_file("other.csv", "theta,phi,final_theta\n");
    cli_result wrong = run_cli("ensemble " + pendulum + grid + " --resume -o " + other, "", 60);
    CHECK(wrong.exit_code == 2);
    CHECK(wrong.err.find("header") != std::string::npos);

    // PNG (with gnuplot): a map with its colour scale.
    std::string png = temporary_file("map.png", "");
    cli_result map = run_cli("ensemble " + pendulum + grid + " -o " + png, "", 60);
    REQUIRE(map.exit_code == 0);
    std::string bytes = read_file(png);
    REQUIRE(bytes.size() > 1000);
    CHECK(bytes.compare(1, 3, "PNG") == 0);
    cli_result one_axis = run_cli("ensemble " + pendulum + " --grid \"theta=0..1:3\" --until 1 -o " + png, "", 60);
    CHECK(one_axis.exit_code == 1);
    CHECK(one_axis.err.find("two entries") != std::string::npos);

    // Bad input: exit 2 with the error located in the option.
    for (const char* bad : {"--grid \"theta=0..1\"", "--grid \"nothing=0..1:2\"", "--grid \"theta=0..1:0\"",
                            "--grid \"g=2..1:3:log\"", "--grid \"theta=0..1:2\" --measure flips",
                            "--grid \"theta=0..1:2\" --until -1", "--grid \"theta=0..1:2\" -o map.txt",
                            "--grid \"theta=0..1:2\" --resume", "--grid \"theta=0..1:2\" --seed 4"}) {
        cli_result r = run_cli("ensemble " + pendulum + " " + bad);
        INFO(bad << ": " << r.err);
        CHECK(r.exit_code == 2);
        CHECK(!r.err.empty());
    }
    cli_result located = run_cli("ensemble " + pendulum + " --grid \"theta=0..1:3, psi=0..1:2\"");
    CHECK(located.err.find("--grid:1:15: error: `psi`") != std::string::npos);
}

// AddressSanitizer reserves terabytes of address space, so no address-space limit can hold
// the sanitized program: the case exists in the other builds only.
#if defined(__SANITIZE_ADDRESS__)
#define LAGRANGE_TEST_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define LAGRANGE_TEST_ADDRESS_SANITIZER 1
#endif
#endif
#ifndef LAGRANGE_TEST_ADDRESS_SANITIZER
TEST_CASE("ensemble cli: threads the system refuses make a smaller pool, not an abort", "[ensemble][cli]")
{
    // Under a 4 GB address-space limit, 1000 threads' stacks do not fit: the system refuses
    // some, and the run goes on with the ones it started (it aborted with exit 134).
    cli_result r = run_cli("ensemble " + pendulum + " --grid \"phi=0.1..0.2:8\" --until 1 --threads 1000", "", 60,
                           "ulimit -v 4000000");
    REQUIRE(r.exit_code == 0);
    CHECK(r.err.find("of 1000 asked: the system refused to start more") != std::string::npos);
    CHECK(std::count(r.out.begin(), r.out.end(), '\n') == 9); // the header and the 8 points
}
#endif

TEST_CASE("ensemble cli: a full disc stops the run at once, and JSON is replaced only whole", "[ensemble][cli]")
{
    // /dev/full fails every write with ENOSPC, as a full disc does.
    const std::string probe = temporary_file("probe.txt", "");
    const std::string full = probe.substr(0, probe.rfind('/')) + "/full.csv";
    REQUIRE(::symlink("/dev/full", full.c_str()) == 0);
    const std::string many = "ensemble " + pendulum + " --grid \"phi=0.1..0.2:100000\" --until 20 --threads 2";
    cli_result r = run_cli(many + " -o " + full, "", 60);
    CHECK(r.exit_code == 1);
    CHECK(r.err == "lagrange: error: cannot write `" + full + "`: the disc may be full\n");
    CHECK(r.seconds < 10 * time_scale()); // all the points would take minutes

    // Killed, a JSON output leaves the file it would replace as it was.
    const std::string json = temporary_file("ensemble.json", "{\"old\": true}\n");
    cli_result stopped = run_cli(many + " -o " + json, "", 1);
    CHECK(stopped.exit_code == 128 + 9);
    std::ifstream in(json);
    std::stringstream kept;
    kept << in.rdbuf();
    CHECK(kept.str() == "{\"old\": true}\n");

    // An output that cannot be opened says why.
    cli_result missing = run_cli("ensemble " + pendulum + " --grid \"phi=0.1..0.2:2\" --until 1 -o /nonexistent/x.csv");
    CHECK(missing.exit_code == 2);
    CHECK(missing.err == "lagrange: error: cannot write `/nonexistent/x.csv`: No such file or directory\n");
}
