// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_compiled_motion.cpp
 *  The forms of the compiled right-hand side (motion_form): the single-angle form and the
 *  recursion of a tree of points against the expanded one, and against the chain's O(N)
 *  recursion by hand, at random states. */
#include "engine/analysis.h"
#include "numeric/compiled_motion.h"
#include "numeric/point_tree.h"
#include "numeric/values.h"
#include "helpers/chain_recursion.h"
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

using lagrange_test::load;

namespace {

/// max_i |a_i − b_i| / max_i |b_i|
double relative_difference(const std::vector<double>& a, const std::vector<double>& b)
{
    double gap = 0, size = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        gap = std::max(gap, std::abs(a[i] - b[i]));
        size = std::max(size, std::abs(b[i]));
    }
    return gap / size;
}

/// The chain of chain_scene.h with masses[k] and lengths[k] on link k + 1, under g = 9.81.
std::string chain_with(const std::vector<double>& masses, const std::vector<double>& lengths)
{
    std::string values = "values g = 9.81";
    for (std::size_t k = 0; k < masses.size(); ++k)
        values += ", m" + std::to_string(k + 1) + " = " + std::to_string(masses[k]) + ", l" + std::to_string(k + 1) +
                  " = " + std::to_string(lengths[k]);
    return lagrange_test::chain_scene(static_cast<int>(masses.size())) + values + "\n";
}

} // namespace

TEST_CASE("compiled_motion: single angles agree with the expanded form and the hand recursion", "[compiled_motion]")
{
    for (int links : {2, 5, 8}) {
        INFO(links << " links");
        std::vector<double> masses, lengths;
        for (int k = 1; k <= links; ++k) {
            masses.push_back(0.5 + 0.25 * k);
            lengths.push_back(1.5 - 0.125 * k);
        }
        lagrange::model scene = load(chain_with(masses, lengths));
        lagrange::analysis a = lagrange::analyze(scene, {lagrange::product::equations});
        const auto point = lagrange::first_value_point(scene);
        lagrange::compiled_motion expanded(scene, *a.equations, point, lagrange::motion_form::expanded);
        lagrange::compiled_motion single(scene, *a.equations, point, lagrange::motion_form::single_angles);
        lagrange::compiled_motion automatic(scene, *a.equations, point);
        CHECK_FALSE(expanded.single_angles());
        CHECK(single.single_angles());
        CHECK(automatic.single_angles() == (static_cast<std::size_t>(links) >= lagrange::single_angles_coordinates));
        const lagrange_test::tension_chain hand(masses, lengths, 9.81);
        const std::size_t d = 2 * static_cast<std::size_t>(links);
        std::mt19937_64 random(39);
        std::uniform_real_distribution<double> angle(-3, 3), rate(-2, 2);
        for (int state = 0; state < 20; ++state) {
            std::vector<double> x(d), by_expanded(d), by_single(d), by_hand(d);
            for (std::size_t i = 0; i < d; ++i)
                x[i] = i < d / 2 ? angle(random) : rate(random);
            expanded.rhs(0, x.data(), by_expanded.data());
            single.rhs(0, x.data(), by_single.data());
            hand(x.data(), by_hand.data());
            CHECK(relative_difference(by_single, by_expanded) < 1e-13);
            CHECK(relative_difference(by_expanded, by_hand) < 1e-12);
        }
    }
}

TEST_CASE("compiled_motion: native code in parts gives the numbers of one function", "[compiled_motion][cc]")
{
    // An 8-link chain's right-hand side (about 500 statements) in parts of 40, in two
    // translation units compiled side by side, against the same program as one function
    // (the same operations in the same order: equal to the bit) and the hand recursion.
    const int links = 8;
    std::vector<double> masses, lengths;
    for (int k = 1; k <= links; ++k) {
        masses.push_back(1 + 0.1 * k);
        lengths.push_back(1 - 0.01 * k);
    }
    lagrange::model scene = load(chain_with(masses, lengths));
    lagrange::analysis a = lagrange::analyze(scene, {lagrange::product::equations});
    const auto point = lagrange::first_value_point(scene);
    lagrange::compiled_motion in_parts(scene, *a.equations, point), whole(scene, *a.equations, point);
    REQUIRE(in_parts.instructions() > 3 * 40);
    lagrange::native_limits parts_limits, whole_limits;
    parts_limits.part_statements = 40;
    whole_limits.part_statements = 0;
    std::string why;
    REQUIRE(in_parts.compile_native_rhs(parts_limits, &why));
    REQUIRE(whole.compile_native_rhs(whole_limits, &why));
    const lagrange_test::tension_chain hand(masses, lengths, 9.81);
    const std::size_t d = 2 * static_cast<std::size_t>(links);
    std::mt19937_64 random(40);
    std::uniform_real_distribution<double> angle(-3, 3), rate(-2, 2);
    for (int state = 0; state < 50; ++state) {
        std::vector<double> x(d), by_parts(d), by_whole(d), by_hand(d);
        for (std::size_t i = 0; i < d; ++i)
            x[i] = i < d / 2 ? angle(random) : rate(random);
        in_parts.rhs(0, x.data(), by_parts.data());
        whole.rhs(0, x.data(), by_whole.data());
        hand(x.data(), by_hand.data());
        CHECK(by_parts == by_whole);
        CHECK(relative_difference(by_parts, by_hand) < 1e-12);
    }
}

namespace {

/// The recursive form (numeric/point_tree.h) against the expanded one at random states
/// (angles and rates both in [−2, 2]), at the scene's first values and t = 0.7; whether the
/// scene is such a tree is `tree`. Both interpreted, and with `native` both compiled too.
void check_recursion(const std::string& text, bool tree, bool native = false)
{
    lagrange::model scene = load(text);
    lagrange::analysis a = lagrange::analyze(scene, {lagrange::product::equations});
    const auto point = lagrange::merged_values(scene); // with the inputs
    lagrange::compiled_motion expanded(scene, *a.equations, point, lagrange::motion_form::expanded);
    lagrange::compiled_motion recursive(scene, *a.equations, point, lagrange::motion_form::recursive);
    REQUIRE(recursive.recursive() == tree);
    if (!tree)
        return;
    if (native) {
        std::string why;
        REQUIRE(expanded.compile_native_rhs({}, &why));
        REQUIRE(recursive.compile_native_rhs({}, &why));
    }
    const std::size_t d = expanded.dimension();
    std::mt19937_64 random(41);
    std::uniform_real_distribution<double> value(-2, 2);
    for (int state = 0; state < 30; ++state) {
        std::vector<double> x(d, 0.0), by_expanded(d), by_recursion(d);
        for (std::size_t i = 0; i < 2 * expanded.coordinates(); ++i)
            x[i] = value(random);
        expanded.rhs(0.7, x.data(), by_expanded.data());
        recursive.rhs(0.7, x.data(), by_recursion.data());
        CHECK(relative_difference(by_recursion, by_expanded) < 1e-13);
    }
}

const std::string branching = R"(parameters g m1 m2 m3 m4 l1 l2 l3 l4 k c
coordinates q1 q2 q3 q4
point P1 mass m1 at (l1*sin(q1), -l1*cos(q1))
point P2 mass m2 at (l1*sin(q1) + l2*sin(q2), -l1*cos(q1) - l2*cos(q2))
point P3 mass m3 at (l1*sin(q1) + l3*sin(q3), -l1*cos(q1) - l3*cos(q3))
point P4 mass m4 at (l1*sin(q1) + l3*sin(q3) + l4*sin(q4), -l1*cos(q1) - l3*cos(q3) - l4*cos(q4))
gravity g along (0, -1)
spring k between P2 and P4 rest l1
dissipation F = 1/2*c*(q2' - q1')^2
values g = 9.81, m1 = 1.5, m2 = 0.7, m3 = 1.1, m4 = 0.4, l1 = 1, l2 = 0.8, l3 = 1.2, l4 = 0.5, k = 30, c = 0.3
)";

const std::string spatial = R"(parameters g m M l L k b F0 w
coordinates z a e
input u
point A mass M at (0, 0, z)
point B mass m at (l*sin(a), 0, z - l*cos(a))
point C mass m at (l*sin(a), L*sin(e), z - l*cos(a) - L*cos(e))
gravity g along (0, 0, -1)
spring k between A and (0, 0, 0)
damper b between B and C
force on C (u, 0, 0)
values g = 9.81, m = 0.6, M = 2, l = 1.1, L = 0.7, k = 40, b = 0.2, F0 = 1, w = 3, u = F0*cos(w*t)
)";

} // namespace

TEST_CASE("compiled_motion: the recursion agrees with the expanded form", "[compiled_motion]")
{
    SECTION("chains from 2 to 20 links, and the hand recursion")
    {
        for (int links : {2, 3, 6, 13, 20}) {
            std::vector<double> masses, lengths;
            for (int k = 1; k <= links; ++k) {
                masses.push_back(1 + 0.1 * k);
                lengths.push_back(1 - 0.01 * k);
            }
            const std::string text = chain_with(masses, lengths);
            check_recursion(text, true);
            lagrange::model scene = load(text);
            lagrange::analysis a = lagrange::analyze(scene, {lagrange::product::equations});
            lagrange::compiled_motion automatic(scene, *a.equations, lagrange::first_value_point(scene));
            CHECK(automatic.recursive() == (static_cast<std::size_t>(links) >= lagrange::recursive_coordinates));
            const lagrange_test::tension_chain hand(masses, lengths, 9.81);
            const std::size_t d = 2 * static_cast<std::size_t>(links);
            std::vector<double> x(d), ours(d), theirs(d);
            for (std::size_t i = 0; i < d; ++i)
                x[i] = i < d / 2 ? 0.3 * std::sin(1.0 + static_cast<double>(i)) : std::cos(static_cast<double>(i));
            automatic.rhs(0, x.data(), ours.data());
            hand(x.data(), theirs.data());
            CHECK(relative_difference(ours, theirs) < 1e-12);
        }
    }
    SECTION("a branching tree with a spring between branches and dissipation")
    {
        check_recursion(branching, true);
    }
    SECTION("in space: a bead on a spring carrying a pendulum in two planes, a damper and a driven input")
    {
        check_recursion(spatial, true);
    }
    SECTION("the cart-pole: a rail and a pendulum upright")
    {
        check_recursion(R"(parameters mc mp l g
coordinates x theta
input F
point C mass mc at (x, 0)
point B mass mp at (x + l*sin(theta), l*cos(theta))
gravity g along (0, -1)
force on C (F, 0)
values mc = 1, mp = 0.2, l = 0.5, g = 9.81, F = 0.3
)",
                        true);
    }
    SECTION("two masses on one rod, and a compound chain of rods in absolute angles")
    {
        check_recursion(R"(parameters m l g
coordinates a b c
point P mass m at (l/2*sin(a), -l/2*cos(a))
point Q mass 2*m at (l*sin(a), -l*cos(a))
point R mass m at (l*sin(a) + l*sin(b), -l*cos(a) - l*cos(b))
point S mass m at (l*sin(a) + l/3*sin(b) + l*sin(c), -l*cos(a) - l/3*cos(b) - l*cos(c))
gravity g along (0, -1)
values m = 1.3, l = 0.9, g = 9.81
)",
                        true);
        check_recursion(R"(parameters m l g
coordinates a b c
body A stick(l) mass m axis y at (l/2*sin(a), -l/2*cos(a), 0) orientation rotations(z a)
body B stick(l) mass m axis y at (l*sin(a) + l/2*sin(b), -l*cos(a) - l/2*cos(b), 0) orientation rotations(z b)
body C stick(l) mass 2*m axis y at (l*sin(a) + l*sin(b) + l/2*sin(c), -l*cos(a) - l*cos(b) - l/2*cos(c), 0) \
    orientation rotations(z c)
gravity g along (0, -1, 0)
values m = 1.1, l = 0.8, g = 9.81
)",
                        true);
    }
    SECTION("a cart carrying a wheel that turns about its centre and a physical pendulum")
    {
        check_recursion(R"(parameters M m l g k
coordinates x phi theta
point C mass 3*M at (x, 0, 0)
body W stick(l) mass M axis y at (x, 0, 0) orientation rotations(z phi)
body P stick(l) mass m at (x, l/2*sin(theta), -l/2*cos(theta)) orientation zxz(0, theta, 0)
spring k between (x, 0, 0) and (0, 0, 0)
gravity g along (0, 0, -1)
values M = 2, m = 0.7, l = 0.6, g = 9.81, k = 5
)",
                        true);
        // An angle that is not the coordinate itself: k(q) q̇²/2 with k′ ≠ 0.
        check_recursion(R"(parameters M l
coordinates x a
point C mass M at (x, 0, 0)
body W stick(l) mass M axis y at (x + sin(a), 0, 0) orientation rotations(z a^2/2 + a)
values M = 2, l = 0.6
)",
                        true);
    }
    SECTION("no tree: relative angles, a spherical pendulum, a body turning with two angles")
    {
        check_recursion(R"(parameters m l g
coordinates a b c
point P mass m at (l*sin(a), -l*cos(a))
point Q mass m at (l*sin(a) + l*sin(a + b), -l*cos(a) - l*cos(a + b))
point R mass m at (l*sin(a) + l*sin(a + b) + l*sin(c), -l*cos(a) - l*cos(a + b) - l*cos(c))
gravity g along (0, -1)
values m = 1, l = 1, g = 9.81
)",
                        false);
        check_recursion(R"(parameters m l g
coordinates theta phi z
point P mass m at (l*sin(theta)*cos(phi), l*sin(theta)*sin(phi), -l*cos(theta))
point Q mass m at (0, 0, z)
point R mass m at (1, 0, z)
gravity g along (0, 0, -1)
values m = 1, l = 1, g = 9.81
)",
                        false);
        check_recursion(R"(parameters m l g
coordinates a b c
body A stick(l) mass m at (l/2*sin(a), -l/2*cos(a), 0) orientation rotations(z a, x b)
point Q mass m at (l*sin(a) + l*sin(b), -l*cos(a) - l*cos(b), 0)
point R mass m at (0, 0, c)
gravity g along (0, -1, 0)
values m = 1, l = 1, g = 9.81
)",
                        false);
    }
    SECTION("a displacement that does not move keeps the expanded form")
    {
        // sin(c)² + cos(c)² is 1: R never moves with c, and M is singular.
        lagrange::model scene = load(R"(parameters m l g
coordinates a b c
point P mass m at (l*sin(a), -l*cos(a))
point Q mass m at (l*sin(a) + l*sin(b), -l*cos(a) - l*cos(b))
point R mass m at (l*sin(a) + l*sin(b) + sin(c)^2 + cos(c)^2, -l*cos(a) - l*cos(b))
gravity g along (0, -1)
values m = 1, l = 1, g = 9.81
)");
        REQUIRE(scene.points[2].position[0].has(scene.coordinates[2].position)); // as written
        lagrange::analysis a = lagrange::analyze(scene, {lagrange::product::equations});
        CHECK_FALSE(lagrange::point_tree_accelerations(scene, *a.equations).has_value());
    }
    SECTION("a massless node keeps the expanded form")
    {
        check_recursion(R"(parameters m l g
coordinates a b c
point Q mass m at (l*sin(a) + l*sin(b), -l*cos(a) - l*cos(b))
point R mass m at (l*sin(a) + l*sin(b) + l*sin(c), -l*cos(a) - l*cos(b) - l*cos(c))
gravity g along (0, -1)
values m = 1, l = 1, g = 9.81
)",
                        false);
    }
}

TEST_CASE("compiled_motion: the compiled recursion agrees with the compiled expanded form", "[compiled_motion][cc]")
{
    check_recursion(branching, true, true);
    check_recursion(spatial, true, true);
}

TEST_CASE("compiled_motion: where the recursion's pivot vanishes, M's solve refuses the state", "[compiled_motion]")
{
    // s = ∂(q³)/∂q = 0 at q = 0: M is singular there, and the recursion divides by zero.
    lagrange::model scene = load(R"(parameters m
coordinates q r s
point A mass m at (q^3, 0)
point B mass m at (q^3, r)
point C mass m at (q^3 + s, r)
values m = 1
)");
    lagrange::analysis a = lagrange::analyze(scene, {lagrange::product::equations});
    const auto point = lagrange::first_value_point(scene);
    lagrange::compiled_motion recursive(scene, *a.equations, point, lagrange::motion_form::recursive);
    lagrange::compiled_motion expanded(scene, *a.equations, point, lagrange::motion_form::expanded);
    REQUIRE(recursive.recursive());
    std::vector<double> x{0, 0.5, 0.2, 1, 0.3, -0.4}, by_recursion(6), by_expanded(6);
    CHECK_THROWS_AS(recursive.rhs(0, x.data(), by_recursion.data()), lagrange::computation_error);
    x[0] = 0.5;
    recursive.rhs(0, x.data(), by_recursion.data());
    expanded.rhs(0, x.data(), by_expanded.data());
    CHECK(relative_difference(by_recursion, by_expanded) < 1e-13);
}

TEST_CASE("compiled_motion: DOP853 on the compiled recursion follows the expanded form", "[compiled_motion][cc]")
{
    // The integrator calls the compiled recursion directly (it writes dxdt): a five-link
    // chain swinging moderately (not chaotic enough for rounding to grow past the tolerance),
    // to t = 5 at tolerance 1e-12, against the expanded form interpreted; the energy is kept.
    const std::string text = lagrange_test::chain_scene(5) +
                             "values g = 9.81, m1 = 1, m2 = 1.2, m3 = 0.8, m4 = 1.1, m5 = 0.6, l1 = 1, l2 = 0.9, "
                             "l3 = 1.1, l4 = 0.7, l5 = 1.2\n";
    lagrange::model scene = load(text);
    lagrange::analysis a = lagrange::analyze(scene, {lagrange::product::equations});
    const auto point = lagrange::first_value_point(scene);
    lagrange::compiled_motion expanded(scene, *a.equations, point, lagrange::motion_form::expanded);
    lagrange::compiled_motion recursive(scene, *a.equations, point);
    REQUIRE(recursive.recursive());
    std::string why;
    REQUIRE(recursive.compile_native_rhs({}, &why));
    REQUIRE(recursive.system().compiled);
    lagrange::integration_options options;
    options.until = 5;
    options.tolerance = 1e-12;
    const std::vector<double> x0{0.2, -0.1, 0.3, 0.05, -0.2, 0.1, 0, -0.3, 0.1, 0};
    const lagrange::trajectory by_recursion =
        lagrange::integrate(recursive.system(), lagrange::ode_method::dop853, x0, options);
    const lagrange::trajectory by_expanded =
        lagrange::integrate(expanded.system(), lagrange::ode_method::dop853, x0, options);
    CHECK(relative_difference(by_recursion.final_state, by_expanded.final_state) < 1e-7);
    REQUIRE(by_recursion.invariant_drift.size() == 1);
    CHECK(by_recursion.invariant_drift[0].second < 1e-10);
}

TEST_CASE("compiled_motion: the recursion agrees on generated trees", "[compiled_motion]")
{
    // Random trees of 3 to 7 coordinates: each coordinate moves a node from a random earlier
    // one (or the ground) along a pendulum arc in one of two planes, a straight rail or a
    // parabola; a point of random mass hangs at each node, some with a second point at
    // another place on the same arc; random springs join random points, and gravity pulls
    // along a random direction.
    std::mt19937_64 random(2026);
    std::uniform_real_distribution<double> size(0.5, 1.5);
    auto number = [&] { return std::to_string(size(random)); };
    for (int scene_number = 0; scene_number < 12; ++scene_number) {
        const int n = 3 + static_cast<int>(random() % 5);
        std::string coordinates = "coordinates", points;
        std::vector<std::vector<std::string>> position(n); // x, y, z of each node
        for (int j = 0; j < n; ++j) {
            const std::string q = "q" + std::to_string(j + 1), l = number();
            coordinates += " " + q;
            const int from = static_cast<int>(random() % static_cast<unsigned>(j + 1)) - 1;
            std::vector<std::string> base = from < 0 ? std::vector<std::string>{"0", "0", "0"} : position[from];
            std::vector<std::string> step;
            switch (random() % 4) {
            case 0: step = {l + "*sin(" + q + ")", "-" + l + "*cos(" + q + ")", "0"}; break;
            case 1: step = {"0", l + "*sin(" + q + ")", "-" + l + "*cos(" + q + ")"}; break;
            case 2: step = {q, "0", "0"}; break;
            default: step = {q, l + "*" + q + "^2", "0"}; break;
            }
            for (int c = 0; c < 3; ++c)
                position[j].push_back(base[c] + " + " + step[c]);
            points += "point P" + std::to_string(j + 1) + " mass " + number() + " at (" + position[j][0] + ", " +
                      position[j][1] + ", " + position[j][2] + ")\n";
            if (random() % 3 == 0) // a second mass at half the step
                points += "point H" + std::to_string(j + 1) + " mass " + number() + " at (" + base[0] + " + (" +
                          step[0] + ")/2, " + base[1] + " + (" + step[1] + ")/2, " + base[2] + " + (" + step[2] +
                          ")/2)\n";
        }
        for (int k = 0; k < 2; ++k) {
            const unsigned a = static_cast<unsigned>(random() % static_cast<unsigned>(n));
            const unsigned b = (a + 1 + static_cast<unsigned>(random() % static_cast<unsigned>(n - 1))) % n;
            points += "spring " + number() + " between P" + std::to_string(a + 1) + " and P" + std::to_string(b + 1) +
                      " rest " + number() + "\n";
        }
        const std::string text = "parameters g\n" + coordinates + "\n" + points + "gravity g along (" + number() +
                                 ", -" + number() + ", " + number() + ")\nvalues g = 9.81\n";
        INFO(text);
        check_recursion(text, true);
    }
}

TEST_CASE("compiled_motion: the guard on the recursion tells a wrong q̈ from a right one", "[compiled_motion]")
{
    // The pendulum m l² q̈ = −m g l sin q (m = 2, l = 0.5, g = 9.81) against recursions that
    // give q̈ = −(g/l) sin q, and twice that.
    GiNaC::realsymbol q("q"), v("v"), t("t");
    const std::vector<GiNaC::ex> symbols{q, v, t};
    const GiNaC::ex g = GiNaC::numeric(981, 100), l = GiNaC::numeric(1, 2), m = 2;
    const lagrange::expression_program mass_and_force({m * l * l, -m * g * l * GiNaC::sin(q)}, symbols);
    GiNaC::realsymbol step("$0");
    const std::vector<lagrange::program_definition> definitions{{step, -g / l * GiNaC::sin(q)}};
    const lagrange::expression_program right(definitions, std::vector<GiNaC::ex>{v, step}, symbols);
    const lagrange::expression_program wrong({v, -2 * g / l * GiNaC::sin(q)}, symbols);
    CHECK(lagrange::recursion_agrees(right, mass_and_force, 1));
    CHECK_FALSE(lagrange::recursion_agrees(wrong, mass_and_force, 1));
}
