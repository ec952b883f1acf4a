// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_corpus.cpp
 *  Every example and test scene through the products it supports. A default run prints
 *  every result it computes, or a note says why not (pinned by the 5-mass ring, whose
 *  frequencies were computed and dropped without a note). Each numeric result is checked
 *  against an independent route: a one-point `--sweep` against `numeric` at the same
 *  values (two paths to the modes), and a simulation started along a linearized mode at
 *  small amplitude against that mode's motion (the integrator against the eigenproblem). */
#include "engine/analysis.h"
#include "output/document.h"
#include "numeric/values.h"
#include "helpers/cli_runner.h"
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <complex>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

using namespace lagrange;

namespace {

/// The .lag files of examples/ and tests/scenes/, sorted.
std::vector<std::string> corpus()
{
    std::vector<std::string> scenes = lagrange_test::example_scenes();
    std::vector<std::string> tests;
    for (const auto& entry : std::filesystem::directory_iterator(std::string(LAGRANGE_SOURCE_DIR) + "/tests/scenes"))
        if (entry.path().extension() == ".lag")
            tests.push_back(entry.path().string());
    std::sort(tests.begin(), tests.end());
    scenes.insert(scenes.end(), tests.begin(), tests.end());
    return scenes;
}

std::string exact_text(double x)
{
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", x);
    return text;
}

/// The JSON document has `key`, or a note mentions `word`.
bool shown_or_noted(const nlohmann::json& document, const std::string& key, const std::string& word)
{
    if (document.contains(key))
        return true;
    if (document.contains("notes"))
        for (const auto& note : document.at("notes"))
            if (note.get<std::string>().find(word) != std::string::npos)
                return true;
    return false;
}

/// The scene's numeric modes at its one `values` line; nothing if it has none.
std::optional<analysis> numeric_analysis(const model& scene)
{
    if (scene.values.size() != 1 || scene.coordinates.empty())
        return std::nullopt;
    try {
        analysis a = analyze(scene, {product::numeric});
        if (a.numeric && a.numeric->size() == 1 && a.linearization)
            return a;
    } catch (const computation_error&) {
        // a scene without the product (no static equilibrium, a free body): not in this test
    }
    return std::nullopt;
}

} // namespace

TEST_CASE("products: every result of a default run is printed or noted, over the corpus", "[products]")
{
    for (const std::string& path : corpus()) {
        INFO(path);
        const model scene = lagrange_test::load(lagrange_test::read_file(path));
        analysis a;
        try {
            a = analyze(scene);
        } catch (const std::exception& error) {
            FAIL(error.what());
        }
        const nlohmann::json document = nlohmann::json::parse(document_text(a, "json"));
        // What a run computes for a product it was asked for (a `want` line narrows them).
        auto asked = [&](product p) { return a.wanted.count(p) > 0; };
        auto require = [&](bool computed, const std::string& key, const std::string& word) {
            INFO(key);
            if (computed)
                CHECK(shown_or_noted(document, key, word));
        };
        require(asked(product::equations) && a.equations.has_value(), "equations", "equations");
        require(asked(product::linearization) && a.linearization.has_value(), "T", "linearization");
        require(asked(product::characteristic) && a.characteristic.has_value(), "characteristic", "characteristic");
        require(asked(product::frequencies) && a.modes.has_value(), "frequencies", "frequencies");
        require(asked(product::numeric) && a.numeric && !a.numeric->empty(), "numeric", "numeric");
        require(asked(product::floquet) && a.floquet && !a.floquet->empty(), "floquet", "floquet");
        require(asked(product::damping) && a.damping.has_value(), "damping", "damping");
        require(asked(product::simulation) && a.simulation.has_value(), "simulation", "simulation");
        require(a.steady.has_value(), "steady_motion", "steady");
        require(asked(product::conserved) && a.conserved.has_value(), "conserved", "conserved");
        require(asked(product::hamiltonian) && a.hamiltonian.has_value(), "hamiltonian", "hamiltonian");
        require(asked(product::reduced) && a.reduced.has_value(), "reduced", "reduced");
        require(asked(product::multipliers) && a.multipliers.has_value(), "multipliers", "multipliers");
        require(asked(product::verification) && a.verification.has_value(), "verification", "verification");
    }
}

TEST_CASE("products: the 5-mass ring's repeated frequencies are printed with a note on the modes",
          "[products][regression]")
{
    lagrange_test::cli_result r = lagrange_test::run_cli(std::string(LAGRANGE_SOURCE_DIR) + "/tests/scenes/ring_of_five.lag --format json");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const nlohmann::json j = nlohmann::json::parse(r.out);
    REQUIRE(j.contains("frequencies"));
    const auto& w2 = j.at("frequencies");
    REQUIRE(w2.size() == 5);
    // ω² = 0, (5 − √5)/2 twice and (5 + √5)/2 twice in k/m: the numeric modes are the reference.
    const auto& numeric = j.at("numeric").at(0).at("omega");
    REQUIRE(numeric.size() == 5);
    for (std::size_t i = 0; i < 5; ++i) {
        const double omega = numeric[i].get<double>();
        CHECK(omega * omega == Approx(i == 0 ? 0.0 : i < 3 ? (5 - std::sqrt(5.0)) / 2 : (5 + std::sqrt(5.0)) / 2)
                                   .margin(1e-12));
    }
    bool noted = false;
    for (const auto& note : j.at("notes"))
        noted = noted || note.get<std::string>().find("a repeated ω²") != std::string::npos;
    CHECK(noted);
}

TEST_CASE("corpus: a one-point sweep gives the numeric modes at the same values", "[corpus][sweep]")
{
    int compared = 0;
    for (const std::string& path : corpus()) {
        INFO(path);
        const model scene = lagrange_test::load(lagrange_test::read_file(path));
        std::optional<analysis> a = numeric_analysis(scene);
        if (!a)
            continue;
        const numeric_modes& reference = a->numeric->front();
        const auto& [name, value] = reference.values.front();
        const std::string at = exact_text(value);
        lagrange_test::cli_result r = lagrange_test::run_cli(path + " --sweep " + name + "=" + at + ".." + at + ":1 --format json");
        INFO(r.err);
        REQUIRE(r.exit_code == 0);
        const nlohmann::json rows = nlohmann::json::parse(r.out).at("sweep").at("points");
        REQUIRE(rows.size() == 1);
        const std::size_t n = reference.omega.size();
        REQUIRE(rows[0].size() >= 1 + n);
        for (std::size_t k = 0; k < n; ++k) {
            INFO("mode " << k + 1);
            const double scale = std::max(std::abs(reference.omega[k]), 1e-6 * std::abs(reference.omega.back()));
            CHECK(std::abs(rows[0][1 + k].get<double>() - reference.omega[k]) <= 1e-9 * scale);
        }
        ++compared;
    }
    CHECK(compared >= 20);
}

TEST_CASE("corpus: a simulation along a linearized mode at small amplitude follows it", "[corpus][simulation]")
{
    int compared = 0;
    for (const std::string& path : corpus()) {
        INFO(path);
        model scene = lagrange_test::load(lagrange_test::read_file(path));
        if (!scene.constraints.empty() || !scene.inputs.empty() || scene.has_generalized_forces())
            continue;
        std::optional<analysis> a = numeric_analysis(scene);
        if (!a)
            continue;
        const numeric_modes& modes = a->numeric->front();
        const std::size_t n = modes.omega.size();
        // undamped, not gyroscopic, every mode oscillating, and not stiff (one run must
        // resolve the fastest mode over half a period of the slowest)
        if (modes.damped || !modes.eigenvalues.empty() || modes.modes.cols() != static_cast<Eigen::Index>(n) ||
            modes.omega.front() <= 0 || modes.omega.back() / modes.omega.front() > 100)
            continue;
        const std::map<std::string, GiNaC::ex> values = merged_values(scene);
        std::vector<double> rest;
        for (const GiNaC::ex& q : a->linearization->at) {
            std::optional<double> x = real_at(at_values(q, scene, values), {});
            REQUIRE(x);
            rest.push_back(*x);
        }
        for (std::size_t k : {std::size_t{0}, n - 1}) {
            INFO("mode " << k + 1);
            Eigen::VectorXd shape = modes.modes.col(static_cast<Eigen::Index>(k));
            shape /= shape.cwiseAbs().maxCoeff();
            const double amplitude = 1e-5;
            initial_state start;
            for (std::size_t i = 0; i < n; ++i) {
                start.positions[scene.coordinates[i].name] =
                    GiNaC::numeric(rest[i] + amplitude * shape[static_cast<Eigen::Index>(i)]);
                start.velocities[scene.coordinates[i].name] = 0;
            }
            model moved = scene;
            moved.initial = start;
            simulation_settings settings;
            settings.until = M_PI / modes.omega[k]; // half a period: q − q₀ = −amplitude · shape
            settings.estimate_error = false;
            settings.native = false;
            analysis run = analyze(moved, {product::simulation}, settings);
            REQUIRE(run.simulation);
            const std::vector<double>& end = run.simulation->run.final_state;
            for (std::size_t i = 0; i < n; ++i) {
                INFO(scene.coordinates[i].name);
                // the nonlinear terms shift the motion by a relative O(amplitude)
                CHECK(std::abs(end[i] - rest[i] + amplitude * shape[static_cast<Eigen::Index>(i)]) <=
                      1e-2 * amplitude);
            }
        }
        ++compared;
    }
    CHECK(compared >= 10);
}

TEST_CASE("corpus: the damped characteristic polynomial vanishes at the numeric damped eigenvalues",
          "[corpus][damping]")
{
    // Two routes to the damped eigenvalues: det(K + s(C − G) + s²M) derived symbolically,
    // and the numeric quadratic eigenproblem through its first-order (companion) form.
    int compared = 0;
    for (const std::string& path : corpus()) {
        INFO(path);
        model scene = lagrange_test::load(lagrange_test::read_file(path));
        if (!scene.has_generalized_forces() || !scene.constraints.empty() || scene.values.size() != 1)
            continue;
        std::optional<analysis> a;
        try {
            a = analyze(scene, {product::damping, product::numeric});
        } catch (const computation_error&) {
            continue; // no damped small oscillations here (forces that do not vanish at rest, t in L)
        }
        if (!a->damping || !a->numeric || a->numeric->size() != 1 || a->numeric->front().eigenvalues.empty())
            continue;
        GiNaC::exmap point;
        const std::map<std::string, GiNaC::ex> values = merged_values(scene); // inputs too: left out
        for (const parameter& q : scene.parameters)
            if (values.count(q.name))
                point[lagrange_test::symbol_of(scene, q.name)] = values.at(q.name);
        const GiNaC::ex p = GiNaC::evalf(a->damping->polynomial.subs(point)).expand();
        const GiNaC::ex& s = a->damping->s;
        for (const std::complex<double>& root : a->numeric->front().eigenvalues) {
            INFO("s = " << root.real() << " + " << root.imag() << "i");
            std::complex<double> value = 0;
            double scale = 0;
            for (int k = p.degree(s); k >= 0; --k) {
                const GiNaC::ex c = p.coeff(s, k);
                REQUIRE(GiNaC::is_a<GiNaC::numeric>(c));
                const double ck = GiNaC::ex_to<GiNaC::numeric>(c).to_double();
                value = value * root + ck;
                scale = scale * std::abs(root) + std::abs(ck);
            }
            CHECK(std::abs(value) <= 1e-9 * scale);
        }
        ++compared;
    }
    CHECK(compared >= 3);
}

namespace {

/// The numbers of a CSV line.
std::vector<double> csv_numbers(const std::string& line)
{
    std::vector<double> numbers;
    std::size_t start = 0;
    while (start <= line.size()) {
        const std::size_t comma = std::min(line.find(',', start), line.size());
        numbers.push_back(std::stod(line.substr(start, comma - start)));
        start = comma + 1;
    }
    return numbers;
}

} // namespace

TEST_CASE("corpus: an ensemble's final state at one point is `simulate`'s at the same values",
          "[corpus][ensemble]")
{
    // Two routes to one run: the ensemble's integrator, measure and CSV, against `simulate`
    // and its JSON, at one grid point that moves a parameter and the first coordinate off the
    // scene's own values. Both target a relative error of `tolerance`.
    const double tolerance = 1e-9;
    int compared = 0;
    for (const std::string& path : corpus()) {
        INFO(path);
        const model scene = lagrange_test::load(lagrange_test::read_file(path));
        if (!scene.simulation || !scene.constraints.empty() || scene.coordinates.empty() || !scene.inputs.empty())
            continue;
        const std::map<std::string, GiNaC::ex> values = merged_values(scene);
        std::string grid, simulate_values, initial;
        for (const parameter& p : scene.parameters)
            if (values.count(p.name)) {
                std::optional<double> value = real_at(values.at(p.name), {});
                if (!value)
                    continue;
                const std::string moved = exact_text(*value * 1.0625);
                grid = p.name + "=" + moved + ".." + moved + ":1, ";
                simulate_values = " --values " + p.name + "=" + moved;
                break;
            }
        const std::string& q = scene.coordinates.front().name;
        const std::string start = "0.25";
        grid += q + "=" + start + ".." + start + ":1";
        initial = " --initial " + q + "=" + start;
        const std::string common = " --until 1 --tolerance " + exact_text(tolerance);
        lagrange_test::cli_result ensemble =
            lagrange_test::run_cli("ensemble " + path + " --grid \"" + grid + "\" --threads 1" + common + simulate_values);
        if (ensemble.exit_code == 1 && ensemble.err.find("not supported") != std::string::npos)
            continue; // a free body's Euler equations: no ensemble of them yet
        INFO(ensemble.err);
        REQUIRE(ensemble.exit_code == 0);
        lagrange_test::cli_result simulate =
            lagrange_test::run_cli("simulate " + path + common + simulate_values + initial + " --format json");
        INFO(simulate.err);
        REQUIRE(simulate.exit_code == 0);
        // the CSV's columns `final_q`, `final_q_dot` against the simulation's states `q`, `q_dot`
        const std::string& csv = ensemble.out;
        const std::size_t header_end = csv.find('\n');
        REQUIRE(header_end != std::string::npos);
        std::vector<std::string> columns;
        std::stringstream header(csv.substr(0, header_end));
        for (std::string column; std::getline(header, column, ',');)
            columns.push_back(column);
        std::string row = csv.substr(header_end + 1);
        row = row.substr(0, row.find('\n'));
        const std::vector<double> numbers = csv_numbers(row);
        REQUIRE(numbers.size() == columns.size());
        const nlohmann::json run = nlohmann::json::parse(simulate.out).at("simulation");
        CHECK(run.at("t").back().get<double>() == 1.0);
        const std::size_t n = scene.coordinates.size();
        std::size_t k = 0;
        for (std::size_t c = 0; c < columns.size(); ++c) {
            if (columns[c].rfind("final_", 0) != 0)
                continue;
            const std::string name = columns[c].substr(6);
            INFO(name);
            REQUIRE(run.at("states").contains(name));
            const double expected = run.at("states").at(name).back().get<double>(), got = numbers[c];
            CHECK(std::abs(got - expected) <= tolerance * std::max(1.0, std::abs(expected)));
            ++k;
        }
        CHECK(k == 2 * n);
        ++compared;
    }
    CHECK(compared >= 10);
}
