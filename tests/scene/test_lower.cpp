// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_lower.cpp
 *  Semantic checks and lowering: exact numbers, shorthands, rules, and every error path. */
#include "bodies/inertia.h"
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>

using namespace lagrange;
using namespace lagrange_test;

TEST_CASE("lower: numbers stay exact, decimals are floats", "[lower]")
{
    model scene = load("parameters m\ncoordinates x\nT = 1/3*m*x'^2 + 123456789012345678901234567890*m\nV = 1e-14*x^2\n");
    GiNaC::ex t = scene.kinetic_terms;
    GiNaC::symbol unused;
    GiNaC::ex coefficient = t.coeff(scene.coordinates[0].velocity, 2);
    CHECK((coefficient - GiNaC::numeric(1, 3) * scene.parameters[0].symbol).expand().is_zero());
    CHECK(t.has(GiNaC::numeric("123456789012345678901234567890")));
    GiNaC::ex v = scene.potential_terms.coeff(scene.coordinates[0].position, 2);
    REQUIRE(GiNaC::is_a<GiNaC::numeric>(v));
    CHECK_FALSE(GiNaC::ex_to<GiNaC::numeric>(v).is_rational());
    CHECK(GiNaC::ex_to<GiNaC::numeric>(v).to_double() == Approx(1e-14).epsilon(1e-15));
}

TEST_CASE("lower: let shorthands are substituted", "[lower]")
{
    model scene = load("parameters m k\ncoordinates x\nlet s = k*x^2\nV = 1/2*s\n");
    GiNaC::ex expected = GiNaC::numeric(1, 2) * scene.parameters[1].symbol * GiNaC::pow(scene.coordinates[0].position, 2);
    CHECK((scene.potential_terms - expected).expand().is_zero());
}

TEST_CASE("lower: I is a name, not the imaginary unit", "[lower]")
{
    model scene = load("parameters I\ncoordinates x\nT = 1/2*I*x'^2\n");
    CHECK_FALSE(scene.kinetic_terms.has(GiNaC::I));
}

TEST_CASE("lower: L, T and V are parameter names (spec section 1)", "[lower]")
{
    // A statement keyword is one only where a statement starts: `T = ...` is still the
    // kinetic energy, while `T` inside an expression is the parameter.
    model scene = load("parameters m L T V\ncoordinates q\nT = 1/2*m*L^2*q'^2\nV = m*V*T*q^2\n");
    REQUIRE(scene.parameters.size() == 4);
    GiNaC::ex m = symbol_of(scene, "m"), l = symbol_of(scene, "L"), period = symbol_of(scene, "T"),
              v = symbol_of(scene, "V"), q = symbol_of(scene, "q"), q_dot = symbol_of(scene, "q_dot");
    CHECK((scene.kinetic_terms - m * l * l * q_dot * q_dot / 2).expand().is_zero());
    CHECK((scene.potential_terms - m * v * period * q * q).expand().is_zero());
}

TEST_CASE("lower: the homework's stick(L)", "[lower]")
{
    model scene = load("parameters M L\nbody S stick(L) mass M axis y\n");
    REQUIRE(scene.bodies.size() == 1);
    REQUIRE(scene.bodies[0].dimensions.size() == 1);
    CHECK(scene.bodies[0].dimensions[0].is_equal(symbol_of(scene, "L")));
    // a thin rod along y: I_xx = I_zz = M L^2/12 about its centre, I_yy = 0 (textbook)
    lagrange::inertia_result inertia = lagrange::derive_inertia(scene.bodies[0]);
    GiNaC::ex mass = symbol_of(scene, "M"), length = symbol_of(scene, "L");
    CHECK((inertia.tensor(0, 0) - mass * length * length / 12).normal().is_zero());
    CHECK((inertia.tensor(2, 2) - mass * length * length / 12).normal().is_zero());
    CHECK(inertia.tensor(1, 1).normal().is_zero());
}

TEST_CASE("lower: error paths", "[lower]")
{
    require_error(header + "T = m*z'^2\n", 3, 7, "`z'`: only coordinates have velocities");
    require_error(header + "T = m*w\n", 3, 7, "unknown name `w`");
    require_error(header + "T = m*q_dot^2\n", 3, 7, "the velocity of `q` is written `q'`");
    require_error(header + "T = m*g'^2\n", 3, 7, "only coordinates have velocities");
    require_error("parameters m m\n", 1, 14, "already declared at line 1");
    require_error("parameters m\ncoordinates m\n", 2, 13, "already declared");
    require_error("parameters sin\n", 1, 12, "reserved");
    require_error("parameters t\n", 1, 12, "reserved");
    require_error("parameters x_dot\n", 1, 12, "reserved for velocities");
    require_error(header + "T = 1/2*m*q'^2\nL = 1/2*m*q'^2\n", 4, 1, "cannot be combined with the `T` line");
    require_error(header + "L = 1/2*m*q'^2\nV = m*g*q\n", 4, 1, "cannot be combined with the Lagrangian");
    require_error(header + "L = q\nL = q\n", 4, 1, "given twice");
    require_error(header + "T = m/0\n", 3, 7, "division by zero");
    require_error(header + "T = m*0^(-1)\n", 3, 8, "division by zero");
    require_error(header + "T = log(0)\n", 3, 5, "`log` has no value here");
    require_error(header + "T = tan(Pi/2)\n", 3, 5, "`tan` has no value here");
    require_error(header + "T = 2^(2^64)\n", 3, 9, "exponent too large");
    require_error(header + "T = (2^1000)^1000\n", 3, 13, "number too large");
    require_error(header + "T = factorial(10^9)\n", 3, 5, "unknown function `factorial`");
    require_error(header + "T = m(q)\n", 3, 5, "is not a function");
    require_error(header + "T = sin\n", 3, 5, "is a function");
    require_error(header + "T = sin(q, q)\n", 3, 5, "takes one argument");
    require_error(header + "T = dot(m)\n", 3, 9, "`m` is not a coordinate");
    require_error(header + "T = (-1)^(1/2)\n", 3, 9, "not a real number");
    require_error(header + "T = 1e999999\n", 3, 5, "out of the range");
    require_error(header + "point P mass m at (q', 0)\n", 3, 20, "velocities cannot appear in a position");
    require_error(header + "point P mass q at (q, 0)\n", 3, 14, "coordinate `q` cannot appear in a mass");
    require_error(header + "point P mass m at (q, 0)\npoint P mass m at (q, 0)\n", 4, 7, "already declared");
    require_error(header + "gravity g along (0, 0)\n", 3, 17, "zero vector");
    require_error(header + "gravity g along (0, -1)\ngravity g along (0, -1)\n", 4, 1, "given twice");
    require_error(header + "spring g between P and (0, 0)\n", 3, 18, "unknown point `P`");
    require_error(header + "equilibrium m = 0\n", 3, 13, "is not a coordinate");
    require_error("parameters m\ncoordinates q p\nequilibrium q = 0\n", 3, 1, "does not give coordinate `p`");
    require_error(header + "equilibrium q = 0, q = 1\n", 3, 20, "given twice");
    require_error(header + "values m = 1, m = 2\n", 3, 15, "given twice");
    require_error(header + "values q = 1\n", 3, 8, "is not a parameter");
    require_error(header + "values m = g\n", 3, 12, "give a number");
    require_error(header + "initial q = 0, q' = 1, q = 2\n", 3, 24, "given twice");
    require_error(header + "ratio r = m*g\n", 3, 11, "one parameter over another");
    require_error(header + "ratio r = m/g\nV = r*q\n", 4, 5, "is a ratio");
    require_error(header + "limit z -> 0\n", 3, 7, "is not a declared ratio");
    require_error(header + "simulate until -1\n", 3, 16, "must be positive");
    require_error(header + "want everything\n", 3, 6, "unknown product `everything`");
    require_error(header + "use \"no-such-file.rules\"\n", 3, 1, "cannot read the rules file");
    require_error(header + "scene \"a\"\nscene \"b\"\n", 4, 1, "given twice");
    require_error("parameters m\n", 1, 1, "declares no coordinates");
    require_error("", 1, 1, "declares no coordinates");
}

TEST_CASE("lower: scenes that make no sense are rejected at the offending line", "[lower]")
{
    // a limit is taken in the scene's ratio, declared before or after it
    require_error(header + "limit m -> 0\n", 3, 7, "is not a declared ratio");
    require_error(header + "ratio rho = m/g\nlimit m -> 0\n", 4, 7, "is not a declared ratio");
    CHECK(load(header + "limit rho -> oo\nratio rho = m/g\n").limit->variable == "rho");
    // gravity out of the plane of planar points
    require_error(header + "point P mass m at (q, 0)\ngravity g along (0, 0, -1)\n", 4, 17, "points are planar");
    require_error(header + "gravity g along (0, 0, -1)\npoint P mass m at (q, 0)\n", 3, 17, "points are planar");
    CHECK(load(header + "point P mass m at (q, 0, 0)\ngravity g along (0, 0, -1)\n").gravity.has_value());
    // values that make a mass, a dimension or a moment zero or negative
    require_error(header + "point P mass m at (q, 0)\nvalues m = -1, g = 1, l = 1\n", 4, 12,
                  "mass of point `P` negative");
    require_error(header + "point P mass m*l at (q, 0)\nvalues m = 2, l = 0\n", 4, 12, "mass of point `P` zero");
    require_error("parameters M L\ncoordinates q\nbody S stick(L) mass M axis y\nvalues M = 1, L = 0\n", 4, 19,
                  "a dimension of body `S` zero");
    require_error("parameters M I1 I2\ncoordinates q\nbody B inertia (I1, I2, I1) mass M\nvalues M = 1, I1 = 1, "
                  "I2 = -2\n",
                  4, 28, "a moment of inertia of body `B` negative");
    // every parameter is assumed positive, not only masses (issue 32)
    require_error(header + "point P mass m at (q, 0)\nvalues m = 2, g = -1, l = 1\n", 4, 19,
                  "parameter `g` is assumed real and positive");
    {
        model scene = load(header + "point P mass m at (q, 0)\n");
        REQUIRE_THROWS_AS(add_values(scene, "m=0"), scene_error);
    }
    // a body with orientation coordinates has its angular velocity derived, not named
    require_error("parameters M R\ncoordinates a b c\nbody B ball(R) mass M orientation zxz(a, b, c)\n"
                  "omega B (w1, w2, w3)\n",
                  4, 1, "derived from them");
}

TEST_CASE("lower: use adds rules, errors in a rules file point into it", "[lower]")
{
    auto reader = [](const std::string& path, const source_location&) -> std::string {
        if (path == "good.rules")
            return "# comment\ncos($0)^2 -> 1 - sin($0)^2\n";
        return "sin($0) -> $1\n";
    };
    model scene = load_model(source_text("test.lag", header + "use \"good.rules\"\n"), reader);
    REQUIRE(scene.rules.size() == 1);
    CHECK(scene.rules[0].origin == "good.rules:2");
    try {
        load_model(source_text("test.lag", header + "use \"bad.rules\"\n"), reader);
        FAIL("no error");
    } catch (const scene_error& e) {
        CHECK(e.where().file == "bad.rules");
        CHECK(e.where().line == 1);
        CHECK(std::string(e.what()).find("does not appear in the pattern") != std::string::npos);
        CHECK(e.line_text() == "sin($0) -> $1");
    }
}

TEST_CASE("lower: the embedded rules parse", "[lower][rules]")
{
    CHECK_NOTHROW(embedded_rules());
}

TEST_CASE("lower: --values and --want from the command line", "[lower]")
{
    model scene = load(header);
    add_values(scene, "m=1, g=9.81");
    REQUIRE(scene.values.size() == 1);
    CHECK(scene.values[0].values.size() == 2);
    try {
        add_values(scene, "m=1,z=2");
        FAIL("no error");
    } catch (const scene_error& e) {
        CHECK(e.where().file == "--values");
        CHECK(e.where().column == 5);
    }
    CHECK(parse_want_list("equations, modes") == std::set<product>{product::equations, product::modes});
    try {
        parse_want_list("equations,nonsense");
        FAIL("no error");
    } catch (const scene_error& e) {
        CHECK(e.where().column == 11);
    }
}

TEST_CASE("lower: an equilibrium with a rate is a steady motion", "[lower][symmetries]")
{
    model scene = load("parameters m l g th0 Omega\ncoordinates theta phi\nT = 1/2*m*l^2*theta'^2\n"
                       "equilibrium theta = th0, phi' = Omega\n");
    CHECK_FALSE(scene.equilibrium);
    REQUIRE(scene.steady);
    CHECK(scene.steady->positions[0]->is_equal(scene.parameters[3].symbol));
    CHECK_FALSE(scene.steady->positions[1]);
    CHECK(scene.steady->rates[1]->is_equal(scene.parameters[4].symbol));
    CHECK_FALSE(scene.steady->rates[0]);
    require_error(header + "equilibrium q = 0, q' = 1\n", 3, 20, "given twice");
}

TEST_CASE("lower: a kinetic energy without velocities is a warning at its line", "[lower][warnings]")
{
    // The prime forgotten: T = ½ m x² is valid, with no kinetic energy at all.
    model forgotten = load("parameters m k\ncoordinates x\nT = 1/2*m*x^2\nV = 1/2*k*x^2\n");
    REQUIRE(forgotten.warnings.size() == 1);
    CHECK(forgotten.warnings[0].where.line == 3);
    CHECK(forgotten.warnings[0].where.column == 1);
    CHECK(forgotten.warnings[0].message.find("`T` has no velocities") != std::string::npos);
    CHECK(forgotten.warnings[0].line_text == "T = 1/2*m*x^2");
    CHECK(format_warning(forgotten.warnings[0]) == "test.lag:3:1: warning: " + forgotten.warnings[0].message +
                                                       "\nT = 1/2*m*x^2\n^\n");

    // One coordinate of two without a velocity, and no points or bodies to give it one.
    model half = load("parameters m k\ncoordinates x y\nT = 1/2*m*x'^2 + m*y^2\nV = 1/2*k*x^2\n");
    REQUIRE(half.warnings.size() == 1);
    CHECK(half.warnings[0].message.find("no velocity of `y`") != std::string::npos);

    // Every velocity present, or the kinetic energy given by points: no warning.
    CHECK(load("parameters m k\ncoordinates x y\nT = 1/2*m*(x'^2 + y'^2)\nV = k*x^2\n").warnings.empty());
    CHECK(load("parameters m l\ncoordinates q r\npoint P mass m at (r, q)\nT = m*r'^2\n").warnings.empty());
    CHECK(load("parameters m k\ncoordinates x\nL = 1/2*m*x'^2 - k*x^2\n").warnings.empty());
}
