// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_verification_error.cpp
 *  The self-verification allows for its own error and no more: correct results whose
 *  finite differences lose accuracy (a fast drive in t, a potential whose terms cancel at
 *  the equilibrium) pass, and the same results made slightly wrong are still refused. */
#include "engine/analysis.h"
#include "verify/verify.h"
#include "helpers/cli_runner.h"
#include "helpers/expressions.h"
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace lagrange;

namespace {

const std::string scenes = std::string(LAGRANGE_SOURCE_DIR) + "/tests/scenes/";

model load_scene(const std::string& name) { return lagrange_test::load(lagrange_test::read_file(scenes + name)); }

void require_caught(const model& scene, const verification_input& input, const std::string& product)
{
    try {
        verify_results(scene, input, {product::equations});
        FAIL("the wrong " << product << " passed verification");
    } catch (const computation_error& e) {
        INFO(e.what());
        CHECK(std::string(e.what()).find("verification failed: " + product) != std::string::npos);
    }
}

} // namespace

TEST_CASE("verification allows for the truncation error of differences in a fast drive", "[verification]")
{
    model scene = load_scene("kapitza_fast_drive.lag");
    analysis a = analyze(scene, {product::equations});
    REQUIRE(a.equations);
    const verification_input right = verification_input_of(a);
    CHECK_NOTHROW(verify_results(scene, right, {product::equations}));

    // A wrong drive amplitude of one part in 10⁴ in the forcing is still caught.
    equations_of_motion wrong = *a.equations;
    const GiNaC::ex a_symbol = lagrange_test::symbol_of(scene, "a");
    wrong.forcing[0] = wrong.forcing[0].subs(a_symbol == a_symbol * GiNaC::numeric(10001, 10000));
    verification_input input = right;
    input.equations = &wrong;
    require_caught(scene, input, "the equations of motion");
}

TEST_CASE("verification sizes L by its terms where V's terms cancel at the equilibrium", "[verification]")
{
    model scene = load_scene("yukawa_orbit.lag");
    analysis a = analyze(scene, {product::linearization});
    REQUIRE(a.linearization);
    // V'' = k e^-1 at r = 1 (3J²/m − 5k e^-1 with J² = 2 k m e^-1): the exact result,
    // which the check once refused.
    const GiNaC::exmap at{{lagrange_test::symbol_of(scene, "m"), 2}, {lagrange_test::symbol_of(scene, "k"), 3}};
    CHECK(lagrange_test::value_at(a.linearization->potential(0, 0), at) == Approx(3 * std::exp(-1.0)).epsilon(1e-12));
    const verification_input right = verification_input_of(a);
    CHECK_NOTHROW(verify_results(scene, right, {product::linearization}));

    linearization_result wrong = *a.linearization;
    wrong.potential(0, 0) = wrong.potential(0, 0) * GiNaC::numeric(10001, 10000);
    verification_input input = right;
    input.linearization = &wrong;
    require_caught(scene, input, "the linearization");
}
