// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_verification.cpp
 *  The self-verification layer: correct results pass, and a result made wrong on
 *  purpose (one term's sign flipped, one entry changed) is caught, naming the product.
 *  Each "caught" test calls the checks directly, so it fails if they check nothing. */
#include "engine/analysis.h"
#include "verify/verify.h"
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>

#include <string>

using namespace lagrange;
using lagrange_test::load;

namespace {

const std::string double_pendulum = R"(
parameters M m l g
coordinates theta phi
point upper mass M at (l*sin(theta), -l*cos(theta))
point lower mass m at (l*sin(theta) + l*sin(phi), -l*cos(theta) - l*cos(phi))
gravity g along (0, -1)
equilibrium theta = 0, phi = 0
)";

/// Flips the sign of the first term of a sum (or of the whole expression).
GiNaC::ex flip_one_term(const GiNaC::ex& e)
{
    GiNaC::ex x = e.expand();
    if (GiNaC::is_a<GiNaC::add>(x))
        return x - 2 * x.op(0);
    return -x;
}

void require_caught(const model& scene, const verification_input& input, const std::string& product)
{
    try {
        verify_results(scene, input, {product::equations, product::frequencies, product::modes,
                                      product::normal_coordinates});
        FAIL("the wrong " << product << " passed verification");
    } catch (const computation_error& e) {
        INFO(e.what());
        CHECK(std::string(e.what()).find("verification failed: " + product) != std::string::npos);
    }
}

} // namespace

TEST_CASE("verification passes the double pendulum and says how", "[verification]")
{
    model scene = load(double_pendulum);
    analysis a = analyze(scene);
    REQUIRE(a.verification);
    std::vector<std::string> items;
    for (const verification_entry& e : a.verification->entries) {
        INFO(e.item << ": " << e.how);
        CHECK(e.checked);
        items.push_back(e.item);
    }
    CHECK(items == std::vector<std::string>{"equations", "equilibrium", "linearization", "characteristic",
                                            "frequencies", "modes", "normal_coordinates"});
}

TEST_CASE("verification catches a wrong term in the equations of motion", "[verification]")
{
    model scene = load(double_pendulum);
    analysis a = analyze(scene, {product::equations});
    REQUIRE(a.equations);
    REQUIRE(a.equations->residuals);
    equations_of_motion wrong = *a.equations;
    (*wrong.residuals)[1] = flip_one_term((*wrong.residuals)[1]);
    verification_input input = verification_input_of(a);
    input.equations = &wrong;
    require_caught(scene, input, "the equations of motion");

    // The form M q̈ = f that the integrators solve is checked too.
    equations_of_motion wrong_force = *a.equations;
    wrong_force.forcing[0] = flip_one_term(wrong_force.forcing[0]);
    input.equations = &wrong_force;
    require_caught(scene, input, "the equations of motion");

    equations_of_motion wrong_energy = *a.equations;
    wrong_energy.energy = flip_one_term(wrong_energy.energy);
    input.equations = &wrong_energy;
    require_caught(scene, input, "the energy function");
}

TEST_CASE("verification catches a wrong linearization, polynomial, frequency, mode", "[verification]")
{
    model scene = load(double_pendulum);
    analysis a = analyze(scene, {product::frequencies, product::modes, product::normal_coordinates});
    REQUIRE(a.linearization);
    REQUIRE(a.modes);
    REQUIRE(a.modes->closed_form);
    const verification_input right = verification_input_of(a);
    CHECK_NOTHROW(verify_results(scene, right, {product::frequencies}));

    linearization_result wrong_linear = *a.linearization;
    wrong_linear.potential(0, 1) = wrong_linear.potential(0, 1) + 1;
    wrong_linear.potential(1, 0) = wrong_linear.potential(0, 1);
    verification_input input = right;
    input.linearization = &wrong_linear;
    input.characteristic = nullptr;
    input.modes = nullptr;
    require_caught(scene, input, "the linearization");

    linearization_result moved = *a.linearization;
    moved.at[0] = GiNaC::numeric(1, 10);
    input.linearization = &moved;
    require_caught(scene, input, "the equilibrium");

    characteristic_result wrong_polynomial = *a.characteristic;
    wrong_polynomial.polynomial = flip_one_term(wrong_polynomial.polynomial);
    input = right;
    input.characteristic = &wrong_polynomial;
    require_caught(scene, input, "the characteristic polynomial");

    modes_result wrong_frequency = *a.modes;
    wrong_frequency.frequencies[0] = wrong_frequency.frequencies[0] * GiNaC::numeric(101, 100);
    input = right;
    input.modes = &wrong_frequency;
    require_caught(scene, input, "the frequencies");

    modes_result wrong_mode = *a.modes;
    std::swap(wrong_mode.modes[0], wrong_mode.modes[1]);
    input.modes = &wrong_mode;
    require_caught(scene, input, "the modes");

    modes_result wrong_normal = *a.modes;
    wrong_normal.normal_coordinates[0] = 2 * wrong_normal.normal_coordinates[0];
    input.modes = &wrong_normal;
    require_caught(scene, input, "the normal coordinates");
}

TEST_CASE("verification checks an L line with velocity-linear terms and explicit parameters", "[verification]")
{
    // A charge in a magnetic field written as L: the equations are checked against the
    // Euler–Lagrange operator of the L as written.
    model scene = load(R"(
parameters m q B k
coordinates x y
L = m/2*(x'^2 + y'^2) + q*B/2*(x*y' - y*x') - k/2*(x^2 + y^2)
)");
    analysis a = analyze(scene, {product::equations});
    REQUIRE(a.verification);
    REQUIRE(a.verification->entries.size() == 1);
    CHECK(a.verification->entries[0].checked);
    equations_of_motion wrong = *a.equations;
    (*wrong.residuals)[0] = flip_one_term((*wrong.residuals)[0]);
    verification_input input = verification_input_of(a);
    input.equations = &wrong;
    require_caught(scene, input, "the equations of motion");
}

TEST_CASE("verification checks the asymptotic frequencies near the limit, and catches a wrong one",
          "[verification][asymptotic]")
{
    for (const char* limit : {"limit rho -> 0", "limit rho -> oo"}) {
        INFO(limit);
        model scene = load(double_pendulum + "ratio rho = m/M\n" + limit + "\nvalues M = 1, m = 0.5, l = 1, g = 9.81\n");
        analysis a = analyze(scene, {product::asymptotic});
        REQUIRE(a.asymptotic);
        REQUIRE(a.verification);
        bool found = false;
        for (const verification_entry& e : a.verification->entries)
            if (e.item == "asymptotic") {
                INFO(e.how);
                CHECK(e.checked);
                found = true;
            }
        CHECK(found);

        // The leading term off by 1 %, and a frequency swapped for the other's: both caught.
        verification_input input = verification_input_of(a);
        asymptotic_result off = *a.asymptotic;
        off.frequencies[0] = off.frequencies[0] * GiNaC::numeric(101, 100);
        input.asymptotic = &off;
        require_caught(scene, input, "asymptotic");
        asymptotic_result swapped = *a.asymptotic;
        swapped.frequencies[1] = swapped.frequencies[0] * 3;
        input.asymptotic = &swapped;
        require_caught(scene, input, "asymptotic");
    }
}
