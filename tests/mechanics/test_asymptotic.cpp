// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_asymptotic.cpp
 *  The asymptotic limit with zero modes (a free translation): the pendulum on a freely
 *  sliding cart and the free linear three-atom molecule, against their closed forms. */
#include "helpers/cli_runner.h"
#include "mechanics/asymptotic.h"
#include "mechanics/equilibrium.h"
#include "mechanics/lagrangian.h"
#include "mechanics/linearization.h"
#include "mechanics/modes.h"
#include "scene/lower.h"
#include "helpers/scene_helpers.h"
#include "helpers/expressions.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <string>

using namespace lagrange;
using lagrange_test::load;
using lagrange_test::symbol_of;

using lagrange_test::same;
using lagrange_test::value_at;

namespace {

struct limited {
    model scene;
    modes_result modes;
    asymptotic_result asymptotic;
};

limited analyse(const std::string& text)
{
    limited a{load(text), {}, {}};
    simplifier simplify = make_simplifier(a.scene);
    lagrangian_result lagrangian = derive_lagrangian(a.scene, simplify);
    equilibria_result equilibria = find_equilibria(a.scene, lagrangian, simplify);
    linearization_result linear = linearize(a.scene, lagrangian, equilibria.points.at(equilibria.chosen).position,
                                            simplify);
    a.modes = symbolic_modes(a.scene, linear, characteristic_polynomial(a.scene, linear));
    a.asymptotic = asymptotic_limit(a.scene, a.modes);
    return a;
}

const std::string cart_pendulum = R"(scene "Pendulum on a freely sliding cart"
parameters M m l g
coordinates x theta
point cart mass M at (x, 0)
point bob mass m at (x + l*sin(theta), -l*cos(theta))
gravity g along (0, -1)
ratio rho = m/M
limit rho -> 0
values M = 2, m = 1, l = 1, g = 9.81
)";

const std::string free_molecule = R"(scene "Free linear three-atom molecule"
parameters m M k
coordinates x1 x2 x3
T = 1/2*m*x1'^2 + 1/2*M*x2'^2 + 1/2*m*x3'^2
V = 1/2*k*(x2 - x1)^2 + 1/2*k*(x3 - x2)^2
ratio mu = M/m
limit mu -> oo
values m = 16, M = 12, k = 1
)";

} // namespace

TEST_CASE("asymptotic: pendulum on a sliding cart, rho = m/M -> 0 with a zero mode", "[asymptotic]")
{
    limited a = analyse(cart_pendulum);
    GiNaC::ex M = symbol_of(a.scene, "M"), m = symbol_of(a.scene, "m"), l = symbol_of(a.scene, "l"),
              g = symbol_of(a.scene, "g"), rho = symbol_of(a.scene, "rho");
    // closed form: ω² = 0 (the cart and bob translate) and (M + m) g/(M l) = (1 + rho) g/l
    REQUIRE(a.modes.frequencies.size() == 2);
    CHECK(same(a.modes.frequencies[0], 0));
    CHECK(same(a.modes.frequencies[1], (M + m) * g / (M * l)));
    REQUIRE(a.modes.frequencies_in_ratio.size() == 2);
    CHECK(same(a.modes.frequencies_in_ratio[1], (1 + rho) * g / l));
    CHECK(a.asymptotic.label == "rho -> 0");
    REQUIRE(a.asymptotic.frequencies.size() == 2);
    CHECK(same(a.asymptotic.frequencies[0], 0));
    CHECK(same(a.asymptotic.frequencies[1], g / l));
    CHECK(a.asymptotic.modes.size() == 2);
    CHECK(a.asymptotic.normal_coordinates.size() == 2);
}

TEST_CASE("asymptotic: free linear molecule, mu = M/m -> oo with a zero mode and beats", "[asymptotic]")
{
    limited a = analyse(free_molecule);
    GiNaC::ex m = symbol_of(a.scene, "m"), M = symbol_of(a.scene, "M"), k = symbol_of(a.scene, "k"),
              mu = symbol_of(a.scene, "mu");
    // closed form: 0, k/m, k (1/m + 2/M)
    REQUIRE(a.modes.frequencies.size() == 3);
    CHECK(same(a.modes.frequencies[0], 0));
    CHECK(same(a.modes.frequencies[1], k / m));
    CHECK(same(a.modes.frequencies[2], k * (1 / m + 2 / M)));
    CHECK(a.asymptotic.label == "mu -> oo");
    REQUIRE(a.asymptotic.frequencies.size() == 3);
    CHECK(same(a.asymptotic.frequencies[0], 0));
    CHECK(same(a.asymptotic.frequencies[1], k / m));
    // k/m and k/m (1 + 2/mu) agree to leading order: the correction is kept, and they beat
    // with ω3 − ω2 = √(k/m) (√(1 + 2/mu) − 1) → √(k/m)/mu
    CHECK(same(a.asymptotic.frequencies[2], k / m * (1 + 2 / mu)));
    REQUIRE(a.asymptotic.beats.size() == 1);
    CHECK(a.asymptotic.beats[0].lower == 1);
    CHECK(a.asymptotic.beats[0].upper == 2);
    CHECK(same(GiNaC::pow(a.asymptotic.beats[0].difference, 2), k / (m * mu * mu)));
}

TEST_CASE("asymptotic: the zero-mode scenes run in every format", "[asymptotic][cli]")
{
    for (const std::string& scene : {cart_pendulum, free_molecule}) {
        for (const char* format : {"text", "latex", "json"}) {
            lagrange_test::cli_result r = lagrange_test::run_cli(std::string("- --format ") + format, scene, 60);
            INFO(scene << format << r.err);
            CHECK(r.exit_code == 0);
        }
        lagrange_test::cli_result r = lagrange_test::run_cli("- --format json", scene, 60);
        nlohmann::json doc = nlohmann::json::parse(r.out);
        CHECK(doc.contains("asymptotic"));
        CHECK(doc["frequencies"].size() == doc["coordinates"].size());
    }
}
