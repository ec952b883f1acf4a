// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_extremes.cpp
 *  Extremes with honest answers (issue 24): the double pendulum's numeric modes at
 *  parameters spanning 600 decades against 80-digit CLN references, the stated error
 *  bound against the true error over random well- and ill-conditioned points, and the
 *  simulation's error estimate at amplitude 1e-300 against a reference solution. */
#include "helpers/cli_runner.h"
#include "numeric/compiled_modes.h"
#include "core/errors.h"

#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <cln/cln.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace lagrange_test;

namespace {

const std::string double_pendulum = std::string(LAGRANGE_SOURCE_DIR) + "/examples/double_pendulum.lag";

const cln::float_format_t reference_digits = cln::float_format(80);

cln::cl_F exact(double x) { return cln::cl_float(cln::rational(cln::cl_DF(x)), reference_digits); }

/// ω∓ of the double pendulum (examples/double_pendulum.lag: T = [[(M+m)l², m l²], [m l², m l²]],
/// V = diag((M+m) g l, m g l)) at 80 digits: with μ = m/M, det(V − W T) = 0 gives
/// W± = (g/l)(1 + μ ± √(μ(1 + μ))); the smaller root as (g/l)(1 + μ)/((1 + μ) + √(μ(1 + μ)))
/// (Vieta: W₊W₋ = (g/l)²(1 + μ)), free of cancellation at any μ.
std::pair<cln::cl_F, cln::cl_F> pendulum_reference(double M, double m, double l, double g)
{
    cln::cl_F mu = exact(m) / exact(M), one = exact(1), rate = exact(g) / exact(l);
    cln::cl_F sum = (one + mu) + cln::sqrt(mu * (one + mu));
    return {cln::sqrt(rate * (one + mu) / sum), cln::sqrt(rate * sum)};
}

double relative_error(double x, const cln::cl_F& reference)
{
    return cln::double_approx(cln::abs((exact(x) - reference) / reference));
}

struct pendulum {
    lagrange::parameter M{"M", GiNaC::possymbol("M")}, m{"m", GiNaC::possymbol("m")}, l{"l", GiNaC::possymbol("l")},
        g{"g", GiNaC::possymbol("g")};
    std::vector<lagrange::parameter> parameters{M, m, l, g};
    lagrange::linearization_result linear;
    pendulum()
    {
        GiNaC::ex Ms = M.symbol, ms = m.symbol, ls = l.symbol, gs = g.symbol;
        linear.kinetic = GiNaC::matrix{{(Ms + ms) * ls * ls, ms * ls * ls}, {ms * ls * ls, ms * ls * ls}};
        linear.potential = GiNaC::matrix{{(Ms + ms) * gs * ls, 0}, {0, ms * gs * ls}};
    }
};

/// The numeric modes of examples/double_pendulum.lag at `values`, through the program.
nlohmann::json numeric_modes_of(const std::string& values, cli_result& run)
{
    run = run_cli("'" + double_pendulum + "' --want numeric --format json --values " + values, "", 60);
    if (run.exit_code != 0)
        return {};
    return nlohmann::json::parse(run.out).at("numeric").back(); // after the scene's own point
}

/// Every printed ω within its stated bound of the reference, and that bound an answer.
void check_against_reference(const nlohmann::json& modes, double M, double m, double l, double g)
{
    auto [slow, fast] = pendulum_reference(M, m, l, g);
    std::vector<double> omega = modes.at("omega"), error = modes.at("error");
    REQUIRE(omega.size() == 2);
    INFO("method " << modes.at("method") << ", ω = " << omega[0] << ", " << omega[1] << ", bounds " << error[0]
                   << ", " << error[1]);
    double e0 = relative_error(omega[0], slow), e1 = relative_error(omega[1], fast);
    CHECK(e0 <= error[0]);
    CHECK(e1 <= error[1]);
    CHECK(error[0] <= 1e-15);
    CHECK(error[1] <= 1e-15);
}

} // namespace

TEST_CASE("extremes: m = 1e-300 gives the true frequencies, not zero", "[extremes]")
{
    // Before: ω = [0, 0] with an error bound of 4.6e45, exit 0. True: both ≈ √9.81 = 3.132,
    // 1.5e-150 apart, the slower mode in phase and the faster in antiphase, |a₁/a₂| = √μ.
    cli_result run;
    nlohmann::json modes = numeric_modes_of("M=1,m=1e-300,l=1,g=9.81", run);
    INFO(run.err);
    REQUIRE(run.exit_code == 0);
    check_against_reference(modes, 1, 1e-300, 1, 9.81);
    CHECK(modes.at("omega")[0].get<double>() == Approx(3.1320919526731650).epsilon(1e-15));
    for (int k = 0; k < 2; ++k) {
        double a1 = modes.at("modes")[k][0], a2 = modes.at("modes")[k][1];
        INFO("mode " << k << ": (" << a1 << ", " << a2 << ")");
        CHECK(std::abs(a1 / a2) == Approx(1e-150).epsilon(1e-6));
        CHECK((a1 * a2 > 0) == (k == 0));
    }
}

TEST_CASE("extremes: a bound too wide to be an answer is refused", "[extremes]")
{
    // M = 1, m = 1e120: T's condition number is 1e120 even equilibrated, and high precision's
    // bound (rounding times its square) stays above every ω at 200 digits. The numbers must
    // not be printed as an answer (before the fallback they were ω = 0 with a bound of 1e40).
    cli_result run = run_cli("'" + double_pendulum + "' --want numeric --values M=1,m=1e120,l=1,g=1", "", 60);
    INFO(run.out << run.err);
    CHECK(run.exit_code == 1);
    CHECK(run.err.find("cannot be computed reliably") != std::string::npos);
    CHECK(run.out.find("ω = 0") == std::string::npos);
    // m = 1e60 is within reach: both frequencies, with relative bounds
    nlohmann::json modes = numeric_modes_of("M=1,m=1e60,l=1,g=1", run);
    INFO(run.err);
    REQUIRE(run.exit_code == 0);
    check_against_reference(modes, 1, 1e60, 1, 1);
}

TEST_CASE("extremes: M = m = 1e±300 with l = g = 1e∓150 is positive definite", "[extremes]")
{
    // T = [[2, 1], [1, 1]] and V = diag(2, 1) at both points, but l⁴ M m and the like leave
    // the range of double inside the closed form: before, "the kinetic matrix is not positive
    // definite".
    for (const char* values : {"M=1e-300,m=1e-300,l=1e150,g=1e150", "M=1e300,m=1e300,l=1e-150,g=1e-150"}) {
        INFO(values);
        cli_result run;
        nlohmann::json modes = numeric_modes_of(values, run);
        INFO(run.err);
        REQUIRE(run.exit_code == 0);
        bool small = std::string(values).find("e-300") != std::string::npos;
        double M = small ? 1e-300 : 1e300, l = small ? 1e150 : 1e-150;
        check_against_reference(modes, M, M, l, l);
        // ω² = 2 ∓ √2
        CHECK(modes.at("omega")[0].get<double>() == Approx(std::sqrt(2 - std::sqrt(2.0))).epsilon(1e-15));
    }
    // A T whose entries overflow double is still refused with the entry named.
    cli_result run = run_cli("'" + double_pendulum + "' --want numeric --values M=1e300,m=1e300,l=1e150,g=1e150");
    CHECK(run.exit_code == 1);
    CHECK(run.err.find("overflows double precision") != std::string::npos);
}

TEST_CASE("extremes: the stated bound holds at random well- and ill-conditioned points", "[extremes]")
{
    pendulum system;
    lagrange::compiled_modes single(system.parameters, system.linear), batch(system.parameters, system.linear);
    std::mt19937 random(20261124);
    std::uniform_real_distribution<double> unit(0, 1);
    std::vector<double> points;
    int ill = 0;
    for (int k = 0; k < 600; ++k) {
        double M, m, l, g;
        if (k % 2 == 0) { // well-conditioned: moderate values, μ from 1e-8 to 1e8
            M = 0.3 + 3 * unit(random);
            m = M * std::pow(10.0, -8 + 16 * unit(random));
            l = 0.3 + 3 * unit(random);
            g = 1 + 20 * unit(random);
        } else { // ill-conditioned: every parameter over hundreds of decades, T and V representable
            double a = -140 + 280 * unit(random), c = -70 + 140 * unit(random), d = -70 + 140 * unit(random);
            double mu = -290 + 580 * unit(random);
            if (std::abs(a + mu) > 290 || std::max(a, a + mu) + 2 * std::abs(c) + std::abs(d) > 280 ||
                std::min(a, a + mu) - 2 * std::abs(c) - std::abs(d) < -280 || std::abs(d - c) + std::abs(mu) > 280) {
                --k;
                continue;
            }
            M = std::pow(10.0, a);
            m = std::pow(10.0, a + mu);
            l = std::pow(10.0, c);
            g = std::pow(10.0, d);
            ++ill;
        }
        points.insert(points.end(), {M, m, l, g});
    }
    // the well-conditioned points (even j) once more as a batch
    const std::size_t count = points.size() / 4;
    std::vector<double> well;
    for (std::size_t j = 0; j < count; j += 2)
        well.insert(well.end(), &points[4 * j], &points[4 * j] + 4);
    std::vector<double> w2(count + 1), w(count + 1), error(count + 1);
    batch.evaluate_batch(well.size() / 4, well.data(), 4, w2.data(), w.data(), error.data(), nullptr);
    int answered = 0, refused = 0;
    double worst_ratio = 0;
    for (std::size_t j = 0; j < count; ++j) {
        const double* p = &points[4 * j];
        INFO("M = " << p[0] << ", m = " << p[1] << ", l = " << p[2] << ", g = " << p[3]);
        lagrange::numeric_modes r;
        try {
            r = single.evaluate(p);
        } catch (const lagrange::computation_error& e) {
            // only an ill-conditioned T may be refused (T's condition grows like μ), never a
            // well-conditioned point
            INFO(e.what());
            CHECK(j % 2 == 1);
            ++refused;
            continue;
        }
        ++answered;
        auto [slow, fast] = pendulum_reference(p[0], p[1], p[2], p[3]);
        const cln::cl_F* reference[] = {&slow, &fast};
        for (int i = 0; i < 2; ++i) {
            // the bound of ω = 0 is absolute (numeric_modes::error)
            double e = r.omega[i] != 0 ? relative_error(r.omega[i], *reference[i])
                                       : cln::double_approx(*reference[i]);
            INFO("method " << r.method << ": ω" << i << " = " << r.omega[i] << ", error " << e << ", bound "
                           << r.error[i]);
            CHECK(e <= r.error[i]);
            if (j % 2 == 0) {
                CHECK(r.omega[i] != 0);
                CHECK(r.error[i] <= 1e-13);
            }
            if (r.omega[i] != 0)
                worst_ratio = std::max(worst_ratio, e / r.error[i]);
        }
        if (j % 2 == 0) { // the batch gives the same numbers
            CHECK(w[j] == r.omega[0]);
            CHECK(w[j + 1] == r.omega[1]);
            CHECK(error[j] == r.error[0]);
        }
    }
    INFO("random points: " << answered << " answered, " << refused << " refused (" << ill
                           << " ill-conditioned), largest true error / bound " << worst_ratio);
    CHECK(answered >= 300 + 100);
    CHECK(worst_ratio <= 1);
}

namespace {

/// The double pendulum of examples/double_pendulum.lag (M = 1, m = 0.01, l = 1, g = 9.81)
/// released from φ = `phi` at rest, simulated over 10 time units.
std::string pendulum_scene(const std::string& phi, const std::string& extra = "")
{
    return "parameters M m l g\ncoordinates theta phi\n"
           "point upper mass M at (l*sin(theta), -l*cos(theta))\n"
           "point lower mass m at (l*sin(theta) + l*sin(phi), -l*cos(theta) - l*cos(phi))\n"
           "gravity g along (0, -1)\nequilibrium theta = 0, phi = 0\n"
           "values M = 1, m = 0.01, l = 1, g = 9.81\n"
           "initial theta = 0, phi = " + phi + ", theta' = 0, phi' = 0\nsimulate until 10" + extra + "\n";
}

/// The rows of a --csv file: t, then the state.
std::vector<std::vector<double>> read_csv(const std::string& path)
{
    std::vector<std::vector<double>> rows;
    std::istringstream in(read_file(path));
    std::string line;
    std::getline(in, line); // header
    while (std::getline(in, line)) {
        std::vector<double> row;
        std::istringstream fields(line);
        std::string field;
        while (std::getline(fields, field, ','))
            row.push_back(std::stod(field));
        rows.push_back(row);
    }
    return rows;
}

/// max_k ‖x_k − reference_k‖ / max_k ‖reference_k‖ over the states (t left out), as the
/// simulation measures its error.
double trajectory_error(const std::vector<std::vector<double>>& run, const std::vector<std::vector<double>>& reference,
                        double unit = 1)
{
    REQUIRE(run.size() == reference.size());
    double difference = 0, size = 0;
    for (std::size_t k = 0; k < run.size(); ++k) {
        double d = 0, s = 0;
        for (std::size_t i = 1; i < run[k].size(); ++i) { // in units of `unit`: no underflow in the squares
            double x = run[k][i] / unit, y = reference[k][i] / unit;
            d += (x - y) * (x - y);
            s += y * y;
        }
        difference = std::max(difference, std::sqrt(d));
        size = std::max(size, std::sqrt(s));
    }
    return difference / size;
}

/// The program's simulation of `scene`: its JSON `simulation` and its --csv rows.
nlohmann::json simulate(const std::string& scene, const std::string& name, const std::string& options,
                        std::vector<std::vector<double>>& rows)
{
    std::string path = temporary_file(name + ".lag", scene), csv = path + ".csv";
    cli_result run = run_cli("simulate '" + path + "' --format json --csv '" + csv + "' " + options, "", 120);
    INFO(run.err);
    REQUIRE(run.exit_code == 0);
    rows = read_csv(csv);
    return nlohmann::json::parse(run.out).at("simulation");
}

} // namespace

TEST_CASE("extremes: the simulation's error estimate holds at amplitude 1e-300", "[extremes]")
{
    // Before: the absolute tolerance was the tolerance itself, 1e-9 against a motion of
    // 1e-300, so nothing was resolved (true error 2.7e-6) and the reference run, no better,
    // agreed with the run exactly: an estimate of 0. The reference here is the closed form
    // of the linearized pendulum, exact at this amplitude (the nonlinear terms are 1e-600 of
    // the linear ones): q(t) = A cos(Ωt) Aᵀ T q₀ with V A = T A Ω², Aᵀ T A = I (Eigen).
    std::vector<std::vector<double>> rows;
    nlohmann::json s = simulate(pendulum_scene("1e-300"), "tiny", "", rows);
    INFO(s.dump().substr(0, 200));
    REQUIRE(s.contains("error_estimate"));
    CHECK(s.at("absolute_tolerance").get<double>() <= 1e-300 * 1e-9 * 32 * 1.0000001);
    Eigen::Matrix2d T, V;
    T << 1.01, 0.01, 0.01, 0.01;
    V << 1.01 * 9.81, 0, 0, 0.01 * 9.81;
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> modes(V, T);
    const Eigen::Matrix2d A = modes.eigenvectors();
    const Eigen::Vector2d omega = modes.eigenvalues().cwiseSqrt();
    const Eigen::Vector2d start = A.transpose() * T * Eigen::Vector2d(0, 1e-300);
    std::vector<std::vector<double>> reference;
    for (const std::vector<double>& row : rows) {
        double t = row[0];
        Eigen::Vector2d cosine(std::cos(omega[0] * t), std::cos(omega[1] * t));
        Eigen::Vector2d sine(-omega[0] * std::sin(omega[0] * t), -omega[1] * std::sin(omega[1] * t));
        Eigen::Vector2d q = A * cosine.cwiseProduct(start), v = A * sine.cwiseProduct(start);
        reference.push_back({t, q[0], q[1], v[0], v[1]});
    }
    double truth = trajectory_error(rows, reference, 1e-300), estimate = s.at("error_estimate");
    INFO("true error " << truth << ", estimate " << estimate << " (" << s.at("error_basis") << ")");
    // an estimate, not a bound: within a tenth of the truth, or above it
    CHECK(truth <= 1.1 * estimate);
    CHECK(truth <= 1e-8);
    CHECK(estimate <= 1e-8);
}

TEST_CASE("extremes: the simulation's error estimate holds at normal amplitude", "[extremes]")
{
    // φ(0) = 0.05, nonlinear: the reference is rkf78 at tolerance 1e-13 (another method,
    // ten thousand times tighter), at the same output times.
    std::vector<std::vector<double>> rows, reference;
    nlohmann::json s = simulate(pendulum_scene("0.05"), "normal", "", rows);
    simulate(pendulum_scene("0.05"), "normal_reference", "--method rkf78 --tolerance 1e-13", reference);
    REQUIRE(s.contains("error_estimate"));
    CHECK(s.at("absolute_tolerance").get<double>() == s.at("tolerance").get<double>());
    double truth = trajectory_error(rows, reference), estimate = s.at("error_estimate");
    INFO("true error " << truth << ", estimate " << estimate << " (" << s.at("error_basis") << ")");
    CHECK(truth <= 1.1 * estimate);
    CHECK(estimate <= 2 * truth);
    CHECK(estimate <= 1e-8);
}
