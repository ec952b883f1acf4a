// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_verification_bodies.cpp
 *  The self-verification of the rigid bodies' results: the cubature against textbook
 *  closed forms, every example with bodies and scenes of every shape and region passing,
 *  and a tensor entry, a principal moment, a centre of mass, an Euler equation term and
 *  the torque-free solutions made wrong on purpose and caught. The "caught" tests call
 *  verify_results directly, so they fail if the checks check nothing. */
#include "engine/analysis.h"
#include "verify/check_bodies.h"
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>
#include <string>

using namespace lagrange;
using lagrange_test::load;
using Catch::Matchers::WithinRel;
using Catch::Matchers::WithinAbs;

namespace {

model load_example(const std::string& name)
{
    const std::string path = std::string(LAGRANGE_SOURCE_DIR) + "/examples/" + name;
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return load_model(source_text(path, text.str()));
}

/// The products a body scene prints about its bodies.
std::set<product> body_products(const model& scene)
{
    std::set<product> wanted{product::inertia};
    for (const rigid_body& b : scene.bodies)
        if (b.omega)
            wanted.insert(product::euler);
    return wanted;
}

/// Analyzes the bodies of `scene` and requires the inertia (and Euler) entries, checked.
void require_verified(const model& scene)
{
    const std::set<product> wanted = body_products(scene);
    analysis a = analyze(scene, wanted);
    REQUIRE(a.verification);
    std::set<std::string> items;
    for (const verification_entry& e : a.verification->entries) {
        INFO(e.item << ": " << e.how);
        CHECK(e.checked);
        items.insert(e.item);
    }
    CHECK(items.count("inertia") == 1);
    CHECK(items.count("euler") == wanted.count(product::euler));
}

void require_caught(const model& scene, const verification_input& input, const std::string& product,
                    const std::string& entry)
{
    try {
        verify_results(scene, input, {product::inertia, product::euler});
        FAIL("the wrong " << entry << " passed verification");
    } catch (const computation_error& e) {
        INFO(e.what());
        CHECK(std::string(e.what()).find("verification failed: " + product) != std::string::npos);
        CHECK(std::string(e.what()).find(entry) != std::string::npos);
    }
}

GiNaC::ex flip_one_term(const GiNaC::ex& e)
{
    GiNaC::ex x = e.expand();
    if (GiNaC::is_a<GiNaC::add>(x))
        return x - 2 * x.op(0);
    return -x;
}

const rigid_body& only_body(const model& scene)
{
    REQUIRE(scene.bodies.size() == 1);
    return scene.bodies.front();
}

} // namespace

TEST_CASE("verification of bodies: the cubature against textbook closed forms", "[verification_bodies]")
{
    model scene = load("parameters M R h a b c\n"
                       "body K cone(R, h) mass M\nbody E ellipsoid(a, b, c) mass M\nbody X box(a, b, c) mass M axis x\n"
                       "body G ring(R) mass M axis y\nbody H sphere(R) mass M\nbody S stick(h) mass M\n"
                       "body T inertia (a, b, c) mass M about (0, 0, h)\n");
    GiNaC::exmap at;
    const double M = 1.5, R = 0.75, h = 2, a = 0.5, b = 1.25, c = 1.75;
    const double values[] = {M, R, h, a, b, c};
    for (std::size_t k = 0; k < scene.parameters.size(); ++k)
        at[scene.parameters[k].symbol] = GiNaC::numeric(values[k]);
    auto inertia_of = [&](std::size_t k) {
        std::optional<numeric_body> body = numeric_inertia(scene.bodies[k], at);
        REQUIRE(body);
        return *body;
    };
    const double eps = 1e-12;
    // Cone, base on z = 0: centre of mass at h/4, I_zz = 3/10 M R², I_xx = 3/20 M R² + 3/80 M h².
    numeric_body cone = inertia_of(0);
    CHECK_THAT(cone.mass, WithinRel(M, eps));
    CHECK_THAT(cone.measure, WithinRel(M_PI * R * R * h / 3, eps));
    CHECK_THAT(cone.centre_of_mass[2], WithinRel(h / 4, eps));
    CHECK_THAT(cone.tensor(2, 2), WithinRel(0.3 * M * R * R, eps));
    CHECK_THAT(cone.tensor(0, 0), WithinRel(M * (3 * R * R / 20 + 3 * h * h / 80), eps));
    CHECK_THAT(cone.tensor(0, 2), WithinAbs(0, eps));
    // Ellipsoid: I_xx = M (b² + c²)/5.
    numeric_body ellipsoid = inertia_of(1);
    CHECK_THAT(ellipsoid.measure, WithinRel(4 * M_PI * a * b * c / 3, eps));
    CHECK_THAT(ellipsoid.tensor(0, 0), WithinRel(M * (b * b + c * c) / 5, eps));
    CHECK_THAT(ellipsoid.tensor(2, 2), WithinRel(M * (a * a + b * b) / 5, eps));
    // Box turned by `axis x`: its edges a, b, c lie along body y, z, x.
    numeric_body box = inertia_of(2);
    CHECK_THAT(box.tensor(0, 0), WithinRel(M * (a * a + b * b) / 12, eps));
    CHECK_THAT(box.tensor(1, 1), WithinRel(M * (b * b + c * c) / 12, eps));
    CHECK_THAT(box.tensor(0, 1), WithinAbs(0, eps));
    // Ring about body y (its axis): M R²; about a diameter M R²/2.
    numeric_body ring = inertia_of(3);
    CHECK_THAT(ring.measure, WithinRel(2 * M_PI * R, eps));
    CHECK_THAT(ring.tensor(1, 1), WithinRel(M * R * R, eps));
    CHECK_THAT(ring.tensor(2, 2), WithinRel(M * R * R / 2, eps));
    CHECK_THAT(inertia_of(4).tensor(0, 0), WithinRel(2 * M * R * R / 3, eps));
    CHECK_THAT(inertia_of(5).tensor(0, 0), WithinRel(M * h * h / 12, eps));
    CHECK_THAT(inertia_of(5).tensor(2, 2), WithinAbs(0, eps));
    // Moments given about (0, 0, h): moved to the centre by I − M (|a|² 1 − a aᵀ).
    numeric_body given = inertia_of(6);
    CHECK_THAT(given.tensor(0, 0), WithinRel(a - M * h * h, eps));
    CHECK_THAT(given.tensor(2, 2), WithinRel(c, eps));
}

TEST_CASE("verification of bodies: every example with bodies passes", "[verification_bodies]")
{
    for (const char* name : {"ball.lag", "compound_double_pendulum.lag", "disk.lag", "free_asymmetric_top.lag",
                             "heavy_top.lag", "heavy_top_precession.lag", "hollow_sphere.lag", "homework_bodies.lag",
                             "physical_pendulum.lag", "rolling_coin.lag", "stick.lag"}) {
        INFO(name);
        require_verified(load_example(name));
    }
}

TEST_CASE("verification of bodies: every shape and region, turned, passes", "[verification_bodies]")
{
    const std::string header = "parameters M R h a b c rho0 l\n";
    for (const char* body : {
             "body K cone(R, h) mass M axis x", "body C cylinder(R, h) mass M axis y",
             "body E ellipsoid(a, b, c) mass M", "body X box(a, b, c) mass M", "body G ring(R) mass M axis x",
             "body B region ball(R) density rho0*(1 + z/R + x^2/R^2)",
             "body S region segment(l) density rho0*(1 + z/l) axis x",
             "body D region disk(R) density rho0*(2 + x/R) axis y",
             "body H region shell(R) density rho0*(1 + z/R)^2",
             "body Y region cylinder(R, h) density rho0*(1 + r^2/R^2 + x*z/R^2)",
             "body Q region box(a, b, c) density rho0*(1 + x/a + y*z/(b*c))",
             "body P region circle(R) density rho0*(2 + y/R)",
             "body T inertia ((5, -1, 0), (-1, 4, 0), (0, 0, 6)) mass 2 about (1/2, 0, 0) at (a, b, c)",
             "body U inertia (a, b, a + b) mass M about (0, c/10, 0)"}) {
        INFO(body);
        require_verified(load(header + body + "\n"));
    }
}

TEST_CASE("verification of bodies: free bodies, with and without torque, pass", "[verification_bodies]")
{
    for (const char* scene : {
             // Symmetric with numbers: the closed form and Poinsot's construction at the values.
             "parameters M R h\nbody C cylinder(R, h) mass M\nomega C (w1, w2, w3)\n"
             "values M = 1, R = 1, h = 3\ninitial w1 = 0.3, w3 = 2\n",
             // Symmetric about body x.
             "parameters M R\nbody D disk(R) mass M axis x\nomega D (p, q, s)\n",
             // A torque that depends on ω and t.
             "parameters M a b c k\nbody X box(a, b, c) mass M\nomega X (w1, w2, w3)\n"
             "torque X (k*w2, 0, -k*w3 + sin(t))\n",
             // Body axes that are not principal.
             "parameters rho0 a b c\nbody Q region box(a, b, c) density rho0*(1 + x*y/(a*b))\n"
             "omega Q (w1, w2, w3)\n",
             // Turning very slowly (|ω| about 1e-6, a period of 6e6): the reference integration
             // keeps its error in ω's own scale.
             "parameters M a b c\nbody X box(a, b, c) mass M\nomega X (w1, w2, w3)\n"
             "values M = 1, a = 1, b = 2, c = 3\ninitial w1 = 0.2e-6, w2 = 1e-6, w3 = 0.3e-6\n"}) {
        INFO(scene);
        require_verified(load(scene));
    }
}

TEST_CASE("verification of bodies: the JSON of a scene without coordinates lists inertia and euler",
          "[verification_bodies]")
{
    model scene = load_example("disk.lag");
    analysis a = analyze(scene);
    REQUIRE(a.verification);
    REQUIRE(a.verification->entries.size() == 2);
    CHECK(a.verification->entries[0].item == "inertia");
    CHECK(a.verification->entries[0].how.find("Gauss–Legendre") != std::string::npos);
    CHECK(a.verification->entries[1].item == "euler");
}

TEST_CASE("verification of bodies: a wrong tensor entry, principal moment, centre of mass is caught",
          "[verification_bodies]")
{
    model scene = load("parameters M R h\nbody K cone(R, h) mass M axis y\n");
    analysis a = analyze(scene, {product::inertia});
    REQUIRE(a.inertia);
    const verification_input right = verification_input_of(a);
    CHECK_NOTHROW(verify_results(scene, right, {product::inertia}));

    std::vector<inertia_result> wrong = *a.inertia;
    wrong[0].tensor(0, 0) = wrong[0].tensor(0, 0) * GiNaC::numeric(1001, 1000);
    verification_input input = right;
    input.inertia = &wrong;
    require_caught(scene, input, "the inertia", "I_xx of body K");

    wrong = *a.inertia;
    wrong[0].tensor(0, 1) = wrong[0].tensor(1, 0) = scene.parameters[0].symbol * GiNaC::pow(scene.parameters[1].symbol, 2) / 1000;
    require_caught(scene, input, "the inertia", "I_xy of body K");

    wrong = *a.inertia;
    REQUIRE(wrong[0].principal.size() == 3);
    wrong[0].principal[2] = flip_one_term(wrong[0].principal[2]);
    require_caught(scene, input, "the inertia", "principal moment");

    wrong = *a.inertia;
    wrong[0].centre_of_mass[1] = wrong[0].centre_of_mass[1] * 2;
    require_caught(scene, input, "the inertia", "centre of mass's y of body K");

    // A given tensor: the parallel-axis shift must be taken with the right sign.
    model given = load("parameters M A C d\nbody T inertia (A, A, C) mass M about (0, 0, d)\n");
    analysis b = analyze(given, {product::inertia});
    std::vector<inertia_result> unshifted = *b.inertia;
    unshifted[0].tensor = diagonal_tensor({given.parameters[1].symbol, given.parameters[1].symbol,
                                           given.parameters[2].symbol});
    input = verification_input_of(b);
    CHECK_NOTHROW(verify_results(given, input, {product::inertia}));
    input.inertia = &unshifted;
    require_caught(given, input, "the inertia", "I_xx of body T");
}

TEST_CASE("verification of bodies: a wrong Euler equation term and wrong solutions are caught",
          "[verification_bodies]")
{
    model disk = load_example("disk.lag");
    analysis a = analyze(disk, {product::inertia, product::euler});
    REQUIRE(a.euler);
    const verification_input right = verification_input_of(a);
    CHECK_NOTHROW(verify_results(disk, right, {product::euler}));

    std::vector<euler_result> wrong = *a.euler;
    wrong[0].equations[0] = flip_one_term(wrong[0].equations[0]);
    verification_input input = right;
    input.euler = &wrong;
    require_caught(disk, input, "Euler's equations", "the equation of w1_dot of body D");

    wrong = *a.euler;
    REQUIRE(wrong[0].symmetric);
    wrong[0].symmetric->omega[0] = wrong[0].symmetric->omega[0].subs(wrong[0].symmetric->time == 2 * wrong[0].symmetric->time);
    require_caught(disk, input, "Euler's equations", "w1(t)");

    wrong = *a.euler;
    wrong[0].symmetric->precession = -wrong[0].symmetric->precession;
    require_caught(disk, input, "Euler's equations", "precession rate");

    model top = load_example("free_asymmetric_top.lag");
    analysis b = analyze(top, {product::inertia, product::euler});
    REQUIRE(b.euler);
    REQUIRE(b.euler->at(0).elliptic);
    input = verification_input_of(b);
    CHECK_NOTHROW(verify_results(top, input, {product::euler}));
    std::vector<euler_result> wrong_top = *b.euler;
    wrong_top[0].elliptic->modulus *= 1.001;
    input.euler = &wrong_top;
    require_caught(top, input, "Euler's equations", "of the elliptic solution");

    wrong_top = *b.euler;
    wrong_top[0].elliptic->period *= 1.001;
    require_caught(top, input, "Euler's equations", "of the elliptic solution");

    wrong_top = *b.euler;
    wrong_top[0].poinsot->polhode[5][1] *= 1.001;
    require_caught(top, input, "Euler's equations", "polhode point 6");

    wrong_top = *b.euler;
    std::swap(wrong_top[0].stability[0], wrong_top[0].stability[1]);
    require_caught(top, input, "Euler's equations", "the rotation about axis 1");

    // Body axes that are not principal: the equations in principal axes are checked too.
    model tilted = load("parameters rho0 a b c\nbody Q region box(a, b, c) density rho0*(1 + x*y/(a*b))\n"
                        "omega Q (w1, w2, w3)\n");
    analysis c = analyze(tilted, {product::inertia, product::euler});
    REQUIRE(c.euler);
    REQUIRE(c.euler->at(0).principal_equations.size() == 3);
    input = verification_input_of(c);
    CHECK_NOTHROW(verify_results(tilted, input, {product::euler}));
    std::vector<euler_result> wrong_tilted = *c.euler;
    wrong_tilted[0].principal_equations[2] = flip_one_term(wrong_tilted[0].principal_equations[2]);
    input.euler = &wrong_tilted;
    require_caught(tilted, input, "Euler's equations", "the principal-axes equation of w3_dot of body Q");
}
