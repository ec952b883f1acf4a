// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_normal_modes.cpp
 *  Numeric normal modes: the double pendulum over 32 decades of mass ratio against
 *  a 50-digit CLN reference, a stiff spring chain, zero and unstable modes, errors. */
#include "numeric/compiled_modes.h"
#include "program/double_double.h"
#include "numeric/point_modes.h"
#include "scene/lower.h"

#include <catch2/catch.hpp>

#include <cln/cln.h>

#include <cmath>
#include <random>

namespace {

using lagrange::compiled_modes;
using lagrange::modes_method;

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

/// ω∓ of the double pendulum at 50 digits: roots of M l² W² − 2(M+m) g l W + (M+m) g² = 0.
std::pair<cln::cl_F, cln::cl_F> pendulum_reference(double M, double m, double l, double g)
{
    cln::float_format_t f = cln::float_format(50);
    auto F = [&](double x) { return cln::cl_float(cln::rational(cln::cl_DF(x)), f); };
    cln::cl_F a = F(M) * F(l) * F(l), b = F(2) * (F(M) + F(m)) * F(g) * F(l), c = (F(M) + F(m)) * F(g) * F(g);
    cln::cl_F root = cln::sqrt(b * b - F(4) * a * c);
    return {cln::sqrt((b - root) / (F(2) * a)), cln::sqrt((b + root) / (F(2) * a))};
}

double relative_error(double x, const cln::cl_F& exact)
{
    cln::cl_F e = cln::cl_float(cln::rational(cln::cl_DF(x)), cln::float_format(50));
    return cln::double_approx(cln::abs((e - exact) / exact));
}

/// max |Aᵀ T A − I| / (|A|ᵀ|T||A|) entrywise (rounding A to double alone errs by u·|A|ᵀ|T||A|,
/// which exceeds 1e-14 when the modes are badly scaled), and max |V A − T A diag(ω²)| scaled.
std::pair<double, double> residuals(const Eigen::MatrixXd& T, const Eigen::MatrixXd& V, const lagrange::numeric_modes& r)
{
    Eigen::MatrixXd A = r.modes;
    Eigen::VectorXd w2 = Eigen::Map<const Eigen::VectorXd>(r.omega_squared.data(), r.omega_squared.size());
    Eigen::MatrixXd size = A.cwiseAbs().transpose() * T.cwiseAbs() * A.cwiseAbs();
    double orthonormal = (A.transpose() * T * A - Eigen::MatrixXd::Identity(A.cols(), A.cols()))
                             .cwiseAbs().cwiseQuotient(size).maxCoeff();
    Eigen::MatrixXd R = V * A - T * A * w2.asDiagonal();
    double scale = (V.norm() + w2.cwiseAbs().maxCoeff() * T.norm()) * A.norm();
    return {orthonormal, R.cwiseAbs().maxCoeff() / scale};
}

lagrange::linearization_result chain(const std::vector<GiNaC::ex>& masses, const std::vector<GiNaC::ex>& springs)
{
    std::size_t n = masses.size();
    lagrange::linearization_result linear;
    linear.kinetic = GiNaC::matrix(n, n);
    linear.potential = GiNaC::matrix(n, n);
    for (std::size_t i = 0; i < n; ++i) {
        linear.kinetic(i, i) = masses[i];
        linear.potential(i, i) = springs[i] + springs[i + 1];
        if (i + 1 < n)
            linear.potential(i, i + 1) = linear.potential(i + 1, i) = -springs[i + 1];
    }
    return linear;
}

} // namespace

TEST_CASE("normal modes: double pendulum for m/M from 1e-16 to 1e16", "[normal_modes]")
{
    pendulum system;
    compiled_modes modes(system.parameters, system.linear);
    std::mt19937 random(20240611);
    std::uniform_real_distribution<double> scale(0.3, 3.0);
    double worst = 0, worst_bound = 0;
    for (int k = 0; k <= 320; ++k) {
        double rho = std::pow(10.0, -16.0 + 0.1 * k);
        double M = scale(random), l = scale(random), g = 9.81;
        double point[] = {M, rho * M, l, g};
        lagrange::numeric_modes r = modes.evaluate(point);
        auto [slow, fast] = pendulum_reference(M, rho * M, l, g);
        INFO("rho = " << rho << " method " << r.method);
        REQUIRE(r.omega.size() == 2);
        double e0 = relative_error(r.omega[0], slow), e1 = relative_error(r.omega[1], fast);
        CHECK(e0 <= 4e-16);
        CHECK(e1 <= 4e-16);
        CHECK(r.error[0] >= e0);
        CHECK(r.error[1] >= e1);
        CHECK(r.error[0] <= 4e-16);
        CHECK(r.error[1] <= 4e-16);
        worst = std::max({worst, e0, e1});
        worst_bound = std::max({worst_bound, r.error[0], r.error[1]});
        {
            Eigen::MatrixXd T(2, 2), V(2, 2);
            T << (M + rho * M) * l * l, rho * M * l * l, rho * M * l * l, rho * M * l * l;
            V << (M + rho * M) * g * l, 0, 0, rho * M * g * l;
            auto [orthonormal, residual] = residuals(T, V, r);
            INFO("orthonormality " << orthonormal << ", residual " << residual);
            CHECK(orthonormal <= 1e-14);
            CHECK(residual <= 1e-14);
        }
    }
    INFO("double pendulum sweep: max relative error " << worst << ", max bound " << worst_bound);
    CHECK(worst <= worst_bound);
}

TEST_CASE("normal modes: every route agrees at a moderate point", "[normal_modes]")
{
    pendulum system;
    double point[] = {1.0, 0.3, 1.2, 9.81};
    auto [slow, fast] = pendulum_reference(1.0, 0.3, 1.2, 9.81);
    for (modes_method method : {modes_method::closed_form, modes_method::symbolic_normalized,
                                modes_method::eigen_generalized, modes_method::high_precision}) {
        lagrange::compiled_modes_options options;
        options.method = method;
        compiled_modes modes(system.parameters, system.linear, options);
        lagrange::numeric_modes r = modes.evaluate(point);
        INFO(r.method << ": errors " << r.error[0] << ", " << r.error[1]);
        CHECK(relative_error(r.omega[0], slow) <= r.error[0]);
        CHECK(relative_error(r.omega[1], fast) <= r.error[1]);
        CHECK(r.error[0] <= 1e-13);
        Eigen::MatrixXd T(2, 2), V(2, 2);
        T << 1.3 * 1.44, 0.3 * 1.44, 0.3 * 1.44, 0.3 * 1.44;
        V << 1.3 * 9.81 * 1.2, 0, 0, 0.3 * 9.81 * 1.2;
        auto [orthonormal, residual] = residuals(T, V, r);
        CHECK(orthonormal <= 1e-14);
        CHECK(residual <= 1e-14);
    }
}

TEST_CASE("normal modes: spring chain with springs 1, 1e8, 1", "[normal_modes]")
{
    // Two masses 1 and 2 between walls: ω² = (3(k+1) ∓ √(9(k+1)² − 8(2k+1)))/4 with k = 1e8.
    lagrange::linearization_result linear = chain({1, 2}, {1, 100000000, 1});
    compiled_modes modes({}, linear);
    lagrange::numeric_modes r = modes.evaluate(nullptr);
    cln::float_format_t f = cln::float_format(50);
    auto F = [&](int x) { return cln::cl_float(x, f); };
    cln::cl_F k = F(100000000), b = F(3) * (k + F(1)), disc = F(9) * (k + F(1)) * (k + F(1)) - F(8) * (F(2) * k + F(1));
    cln::cl_F slow = cln::sqrt((b - cln::sqrt(disc)) / F(4)), fast = cln::sqrt((b + cln::sqrt(disc)) / F(4));
    CHECK(relative_error(r.omega[0], slow) <= 1e-13);
    CHECK(relative_error(r.omega[1], fast) <= 1e-13);
    CHECK(relative_error(r.omega[0], slow) <= r.error[0]);

    // Three masses, springs 1, 1e8, 1e8, 1: symmetric route, checked against high precision.
    GiNaC::possymbol k1("k1"), k2("k2");
    std::vector<lagrange::parameter> parameters{{"k1", k1}, {"k2", k2}};
    lagrange::linearization_result three = chain({1, 2, 3}, {k1, k2, k2, k1});
    double point[] = {1, 1e8};
    compiled_modes automatic(parameters, three);
    lagrange::compiled_modes_options precise;
    precise.method = modes_method::high_precision;
    compiled_modes reference(parameters, three, precise);
    lagrange::numeric_modes a = automatic.evaluate(point), exact = reference.evaluate(point);
    for (std::size_t i = 0; i < 3; ++i) {
        INFO("mode " << i << " by " << a.method);
        CHECK_THAT(a.omega[i], Catch::Matchers::WithinRel(exact.omega[i], 1e-13));
        CHECK(exact.error[i] <= 2e-16);
    }
}

TEST_CASE("normal modes: free three-mass molecule has a zero mode", "[normal_modes]")
{
    // Masses m, M, m on a line joined by two springs k, no walls: ω² = 0, k/m, k/m (1 + 2m/M).
    GiNaC::possymbol m("m"), M("M"), k("k");
    lagrange::linearization_result linear;
    linear.kinetic = GiNaC::matrix{{m, 0, 0}, {0, M, 0}, {0, 0, m}};
    linear.potential = GiNaC::matrix{{k, -k, 0}, {-k, 2 * k, -k}, {0, -k, k}};
    compiled_modes modes({{"m", m}, {"M", M}, {"k", k}}, linear);
    double point[] = {1.0, 16.0, 2.5};
    lagrange::numeric_modes r = modes.evaluate(point);
    CHECK(r.omega[0] == 0);
    CHECK(r.omega_squared[0] == 0);
    CHECK(r.error[0] <= 1e-6);
    CHECK_THAT(r.omega[1], Catch::Matchers::WithinRel(std::sqrt(2.5), 1e-14));
    CHECK_THAT(r.omega[2], Catch::Matchers::WithinRel(std::sqrt(2.5 * (1 + 2.0 / 16)), 1e-14));
    CHECK(r.error[1] <= 1e-13);
}

TEST_CASE("normal modes: inverted pendulum gives a negative omega squared", "[normal_modes]")
{
    GiNaC::possymbol M("M"), m("m"), l("l"), g("g");
    lagrange::linearization_result linear;
    linear.kinetic = GiNaC::matrix{{(M + m) * l * l, m * l * l}, {m * l * l, m * l * l}};
    linear.potential = GiNaC::matrix{{-(M + m) * g * l, 0}, {0, -m * g * l}};
    compiled_modes modes({{"M", M}, {"m", m}, {"l", l}, {"g", g}}, linear);
    double point[] = {1.0, 0.5, 1.0, 9.81};
    lagrange::numeric_modes r = modes.evaluate(point);
    auto [slow, fast] = pendulum_reference(1.0, 0.5, 1.0, 9.81);
    // V → −V: ω² → −ω², ascending order puts the fast growth first.
    CHECK(r.omega_squared[0] < 0);
    CHECK(r.omega_squared[1] < 0);
    CHECK(relative_error(-r.omega[0], fast) <= 4e-16);
    CHECK(relative_error(-r.omega[1], slow) <= 4e-16);
    CHECK(r.omega[0] == -std::sqrt(-r.omega_squared[0]));
}

TEST_CASE("normal modes: from a scene's values", "[normal_modes]")
{
    lagrange::model scene = lagrange::load_model(lagrange::source_text(
        "t.lag", "parameters M m l g\ncoordinates theta phi\nT = 1/2*M*l^2*theta'^2\nvalues M = 1, m = 0.01, l = 1, g = 9.81\n"));
    GiNaC::ex M = scene.parameters[0].symbol, m = scene.parameters[1].symbol, l = scene.parameters[2].symbol,
              g = scene.parameters[3].symbol;
    lagrange::linearization_result linear;
    linear.kinetic = GiNaC::matrix{{(M + m) * l * l, m * l * l}, {m * l * l, m * l * l}};
    linear.potential = GiNaC::matrix{{(M + m) * g * l, 0}, {0, m * g * l}};
    std::vector<lagrange::numeric_modes> all = lagrange::numeric_normal_modes(scene, linear);
    REQUIRE(all.size() == 1);
    auto [slow, fast] = pendulum_reference(1.0, 0.01, 1.0, 9.81);
    CHECK(relative_error(all[0].omega[0], slow) <= 4e-16);
    CHECK(relative_error(all[0].omega[1], fast) <= 4e-16);
    CHECK(all[0].values.size() == 4);
}

TEST_CASE("normal modes: the values echo every value given, also those not needed", "[normal_modes]")
{
    lagrange::model scene = lagrange::load_model(lagrange::source_text(
        "t.lag", "parameters M m l g c\ncoordinates theta phi\nT = 1/2*M*l^2*theta'^2\n"
                 "values c = 7, M = 1, m = 0.01, l = 1, g = 9.81\n"));
    GiNaC::ex M = scene.parameters[0].symbol, m = scene.parameters[1].symbol, l = scene.parameters[2].symbol,
              g = scene.parameters[3].symbol;
    lagrange::linearization_result linear;
    linear.kinetic = GiNaC::matrix{{(M + m) * l * l, m * l * l}, {m * l * l, m * l * l}};
    linear.potential = GiNaC::matrix{{(M + m) * g * l, 0}, {0, m * g * l}};
    std::vector<lagrange::numeric_modes> all = lagrange::numeric_normal_modes(scene, linear);
    REQUIRE(all.size() == 1);
    // in the declared order of the parameters
    std::vector<std::pair<std::string, double>> expected{{"M", 1}, {"m", 0.01}, {"l", 1}, {"g", 9.81}, {"c", 7}};
    CHECK(all[0].values == expected);
}

TEST_CASE("normal modes: errors", "[normal_modes]")
{
    SECTION("a parameter without a value")
    {
        lagrange::model scene = lagrange::load_model(lagrange::source_text(
            "t.lag", "parameters M m l g\ncoordinates theta phi\nT = 1/2*M*l^2*theta'^2\nvalues M = 1, l = 1, g = 9.81\n"));
        GiNaC::ex M = scene.parameters[0].symbol, m = scene.parameters[1].symbol, l = scene.parameters[2].symbol;
        lagrange::linearization_result linear;
        linear.kinetic = GiNaC::matrix{{(M + m) * l * l, m * l * l}, {m * l * l, m * l * l}};
        linear.potential = GiNaC::matrix{{M * l, 0}, {0, m * l}};
        REQUIRE_THROWS_AS(lagrange::numeric_normal_modes(scene, linear), lagrange::computation_error);
        REQUIRE_THROWS_WITH(lagrange::numeric_normal_modes(scene, linear), Catch::Contains("`m`"));
    }
    SECTION("a singular kinetic matrix")
    {
        GiNaC::possymbol a("a"), b("b");
        lagrange::linearization_result linear;
        linear.kinetic = GiNaC::matrix{{a, b}, {b, b * b / a}};
        linear.potential = GiNaC::matrix{{1, 0}, {0, 1}};
        double point[] = {2.0, 3.0};
        for (modes_method method : {modes_method::automatic, modes_method::symbolic_normalized,
                                    modes_method::eigen_generalized, modes_method::high_precision}) {
            lagrange::compiled_modes_options options;
            options.method = method;
            compiled_modes modes({{"a", a}, {"b", b}}, linear, options, {"x", "y"});
            REQUIRE_THROWS_AS(modes.evaluate(point), lagrange::computation_error);
        }
    }
    SECTION("an indefinite kinetic matrix")
    {
        lagrange::linearization_result linear = chain({1, -1, 1}, {1, 1, 1, 1});
        REQUIRE_THROWS_AS(compiled_modes({}, linear).evaluate(nullptr), lagrange::computation_error);
    }
}

TEST_CASE("normal modes: batch evaluation gives the same numbers as one point at a time", "[normal_modes]")
{
    // The double pendulum (closed form, blocks of 32 with a partial last block) over the
    // ρ sweep, and a 4-mass chain (symbolic normalization): bit for bit equal, and the
    // batch's ω against the 50-digit reference.
    pendulum system;
    compiled_modes single(system.parameters, system.linear), batch(system.parameters, system.linear);
    std::mt19937 random(77);
    std::uniform_real_distribution<double> scale(0.3, 3.0);
    const std::size_t sweep = 201;
    std::vector<double> points;
    for (std::size_t k = 0; k < sweep; ++k) {
        double rho = std::pow(10.0, -16.0 + 32.0 * static_cast<double>(k) / (sweep - 1)), M = scale(random);
        points.insert(points.end(), {M, rho * M, scale(random), 9.81});
    }
    // Points the a priori bounds leave to the running bound (g < 0: a negative parameter) or
    // to high precision (a value under- or overflows), amid ordinary ones in one block.
    points.insert(points.end(), {1, 0.5, 1, -9.81, 1, 1e-120, 1, 9.81, 2, 1, 1.5, 9.81, 1e150, 1e-150, 1, 9.81,
                                 1.5, 1e-3, 0.5, 9.81, 1, 2, 3, -1, 1e-20, 1e-20, 1, 9.81, 3, 0.2, 1, 9.81});
    const std::size_t count = points.size() / 4;
    std::vector<double> w2(2 * count), w(2 * count), error(2 * count), shapes(4 * count);
    std::vector<modes_method> used(count);
    batch.evaluate_batch(count, points.data(), 4, w2.data(), w.data(), error.data(), shapes.data(), used.data());
    for (std::size_t k = 0; k < count; ++k) {
        lagrange::numeric_modes r = single.evaluate(&points[4 * k]);
        INFO("point " << k);
        CHECK(lagrange::to_string(used[k]) == r.method);
        for (std::size_t i = 0; i < 2; ++i) {
            CHECK(w[2 * k + i] == r.omega[i]);
            CHECK(w2[2 * k + i] == r.omega_squared[i]);
            CHECK(error[2 * k + i] == r.error[i]);
        }
        for (std::size_t i = 0; i < 4; ++i)
            CHECK(shapes[4 * k + i] == r.modes.data()[i]);
        if (points[4 * k + 3] < 0)
            continue; // unstable: ω² < 0
        auto [slow, fast] = pendulum_reference(points[4 * k], points[4 * k + 1], points[4 * k + 2], 9.81);
        CHECK(relative_error(w[2 * k], slow) <= 4e-16);
        CHECK(relative_error(w[2 * k + 1], fast) <= 4e-16);
    }
    CHECK(used[sweep] == modes_method::closed_form);        // g < 0: the running bound
    CHECK(used[sweep + 1] == modes_method::high_precision); // m³ underflows
    // 4 l⁶ (M + m) g² m³ underflows at M = 1e150, m = 1e-150 too; high precision, with T
    // equilibrated, meets the tolerance there
    CHECK(used[sweep + 3] == modes_method::high_precision);

    GiNaC::possymbol m1("m1"), m2("m2"), m3("m3"), m4("m4"), k1("k1"), k2("k2"), k3("k3"), k4("k4"), k5("k5");
    std::vector<lagrange::parameter> parameters{{"m1", m1}, {"m2", m2}, {"m3", m3}, {"m4", m4}, {"k1", k1},
                                                {"k2", k2}, {"k3", k3}, {"k4", k4}, {"k5", k5}};
    lagrange::linearization_result linear = chain({m1, m2, m3, m4}, {k1, k2, k3, k4, k5});
    compiled_modes chain_single(parameters, linear), chain_batch(parameters, linear);
    std::vector<double> chain_points;
    for (std::size_t k = 0; k < 40 * 9; ++k)
        chain_points.push_back(scale(random));
    std::vector<double> cw2(4 * 40), cw(4 * 40), cerror(4 * 40);
    chain_batch.evaluate_batch(40, chain_points.data(), 9, cw2.data(), cw.data(), cerror.data(), nullptr);
    for (std::size_t k = 0; k < 40; ++k) {
        lagrange::numeric_modes r = chain_single.evaluate(&chain_points[9 * k]);
        for (std::size_t i = 0; i < 4; ++i)
            CHECK(cw[4 * k + i] == r.omega[i]);
    }
}

TEST_CASE("normal modes: the closed form's a priori bounds, and where they hand over", "[normal_modes]")
{
    // At m/M = 1e-120 the discriminant 4 l⁶ (M + m) g² m³ underflows; in double-double the
    // two roots then come out equal and the modes would be an arbitrary T-orthonormal pair.
    // The a priori check sends the point to high precision, whose modes are the true
    // ones, (∓√ρ, 1)-shaped: |a₁/a₂| = √ρ = 1e-60.
    pendulum system;
    compiled_modes modes(system.parameters, system.linear);
    const double point[] = {1, 1e-120, 1, 9.81};
    lagrange::numeric_modes r = modes.evaluate(point);
    CHECK(r.method == lagrange::to_string(modes_method::high_precision));
    for (int i = 0; i < 2; ++i) {
        INFO("mode " << i);
        CHECK(std::abs(r.modes(0, i) / r.modes(1, i)) == Approx(1e-60).epsilon(1e-8));
    }
    // one in phase, one in antiphase (whatever sign each vector has)
    CHECK(r.modes(0, 0) * r.modes(1, 0) * r.modes(0, 1) * r.modes(1, 1) < 0);
    auto [slow, fast] = pendulum_reference(1, 1e-120, 1, 9.81);
    CHECK(relative_error(r.omega[0], slow) <= 4e-16);
    CHECK(relative_error(r.omega[1], fast) <= 4e-16);
    // Where the bounds hold, the reported error bounds the actual one and is the rounding of
    // ω to double alone, give or take its 1e-6 safety factor and a few 1e-30.
    const double ordinary[] = {1.3, 0.01, 0.7, 9.81};
    lagrange::numeric_modes o = modes.evaluate(ordinary);
    CHECK(o.method == lagrange::to_string(modes_method::closed_form));
    auto [s2, f2] = pendulum_reference(1.3, 0.01, 0.7, 9.81);
    CHECK(relative_error(o.omega[0], s2) <= o.error[0]);
    CHECK(relative_error(o.omega[1], f2) <= o.error[1]);
    CHECK(o.error[0] <= 0x1p-53);
    CHECK(o.error[0] <= relative_error(o.omega[0], s2) * (1 + 2e-6) + 1e-28);
    // An overflowing entry is still an error (the point is not quietly handed on).
    const double huge[] = {1e200, 1, 1e200, 1};
    CHECK_THROWS_AS(modes.evaluate(huge), lagrange::computation_error);
}

TEST_CASE("normal modes: the FMA and portable kernels give the same numbers bit for bit", "[normal_modes]")
{
    // Both kernels' double-double products are exact (one FMA, or Dekker's splitting), and
    // nothing is contracted: the same numbers on CPUs with and without FMA. On a CPU
    // without FMA both runs take the portable kernels and the test still checks the sweep.
    pendulum system;
    compiled_modes fast(system.parameters, system.linear), portable(system.parameters, system.linear);
    std::mt19937 random(5);
    std::uniform_real_distribution<double> scale(0.3, 3.0);
    const std::size_t count = 301;
    std::vector<double> points;
    for (std::size_t k = 0; k < count; ++k) {
        double rho = std::pow(10.0, -16.0 + 32.0 * static_cast<double>(k) / (count - 1)), M = scale(random);
        points.insert(points.end(), {M, rho * M, scale(random), scale(random) * 10});
    }
    std::vector<double> w2(2 * count), w(2 * count), error(2 * count), shapes(4 * count);
    std::vector<double> pw2(2 * count), pw(2 * count), perror(2 * count), pshapes(4 * count);
    bool had_fma = lagrange::fma_kernels();
    fast.evaluate_batch(count, points.data(), 4, w2.data(), w.data(), error.data(), shapes.data());
    lagrange::use_fma_kernels(false);
    CHECK_FALSE(lagrange::fma_kernels());
    portable.evaluate_batch(count, points.data(), 4, pw2.data(), pw.data(), perror.data(), pshapes.data());
    lagrange::numeric_modes one = portable.evaluate(&points[4 * 7]);
    lagrange::use_fma_kernels(had_fma);
    for (std::size_t k = 0; k < 2 * count; ++k) {
        INFO("entry " << k);
        CHECK(w[k] == pw[k]);
        CHECK(w2[k] == pw2[k]);
        CHECK(error[k] == perror[k]);
    }
    for (std::size_t k = 0; k < 4 * count; ++k)
        CHECK(shapes[k] == pshapes[k]);
    CHECK(one.omega[0] == w[14]);
    CHECK(one.omega[1] == w[15]);
    for (std::size_t k = 0; k < count; ++k) {
        auto [slow, quick] = pendulum_reference(points[4 * k], points[4 * k + 1], points[4 * k + 2], points[4 * k + 3]);
        CHECK(relative_error(w[2 * k], slow) <= 4e-16);
        CHECK(relative_error(w[2 * k + 1], quick) <= 4e-16);
        CHECK(relative_error(w[2 * k], slow) <= error[2 * k]);
        CHECK(relative_error(w[2 * k + 1], quick) <= error[2 * k + 1]);
    }
}
