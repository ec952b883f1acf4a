// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_lower_body.cpp
 *  Bodies given a full inertia tensor (products of inertia, `about` a body point, zero
 *  moments) against ½ ωᵀ I ω computed here and against SymPy's parallel-axis tests
 *  (physics/mechanics/tests/test_rigidbody.py and test_particle.py); and the input
 *  errors of §5 bodies at their position. */
#include "bodies/euler.h"
#include "bodies/inertia.h"
#include "mechanics/lagrangian.h"
#include "helpers/scene_helpers.h"
#include "helpers/expressions.h"

#include <catch2/catch.hpp>

#include <random>

using namespace lagrange;
using namespace lagrange_test;

namespace {

void require_tensor(const GiNaC::matrix& actual, const GiNaC::matrix& expected)
{
    for (unsigned i = 0; i < 3; ++i)
        for (unsigned j = 0; j < 3; ++j) {
            INFO("entry (" << i << ", " << j << "): " << actual(i, j) << " against " << expected(i, j));
            CHECK(same(actual(i, j), expected(i, j)));
        }
}

const std::string sympy_header = "parameters m Ix Iy Iz a b\ncoordinates q\n";

} // namespace

TEST_CASE("given tensors: T of a body with products of inertia is ½ ωᵀ I ω", "[lower_body][inertia]")
{
    model scene = load("parameters M A B C D E F\ncoordinates phi theta\n"
                       "body B inertia ((A, -F, -E), (-F, B, -D), (-E, -D, C)) mass M "
                       "orientation rotations(z phi, x theta)\n");
    const lagrangian_result l = derive_lagrangian(scene, make_simplifier(scene));
    // R = R_z(φ) R_x(θ): in the body frame ω = R_x(θ)ᵀ e_z φ̇ + e_x θ̇ = (θ̇, φ̇ sin θ, φ̇ cos θ).
    const GiNaC::ex th = symbol_of(scene, "theta"), dph = symbol_of(scene, "phi_dot"),
                    dth = symbol_of(scene, "theta_dot");
    const std::vector<GiNaC::ex> w = {dth, dph * GiNaC::sin(th), dph * GiNaC::cos(th)};
    const GiNaC::ex A = symbol_of(scene, "A"), B = symbol_of(scene, "B"), C = symbol_of(scene, "C"),
                    D = symbol_of(scene, "D"), E = symbol_of(scene, "E"), F = symbol_of(scene, "F");
    const GiNaC::ex expected = (A * w[0] * w[0] + B * w[1] * w[1] + C * w[2] * w[2]) / 2 - F * w[0] * w[1] -
                               E * w[0] * w[2] - D * w[1] * w[2];
    std::mt19937 random(3);
    std::uniform_real_distribution<double> x(-1.2, 1.2);
    for (int k = 0; k < 8; ++k) {
        GiNaC::exmap at;
        for (const parameter& p : scene.parameters)
            at[p.symbol] = x(random);
        for (const coordinate& c : scene.coordinates) {
            at[c.position] = x(random);
            at[c.velocity] = x(random);
        }
        const double found = GiNaC::ex_to<GiNaC::numeric>(l.kinetic.subs(at).evalf()).to_double();
        const double wanted = GiNaC::ex_to<GiNaC::numeric>(expected.subs(at).evalf()).to_double();
        CHECK_THAT(found, Catch::Matchers::WithinAbs(wanted, 1e-12));
    }
    // The inertia stage keeps the tensor, off-diagonal entries and all.
    const inertia_result inertia = derive_inertia(scene.bodies[0]);
    CHECK_FALSE(inertia.diagonal);
    CHECK(same(inertia.tensor(0, 1), -F));
    CHECK(same(inertia.tensor(1, 2), -D));
}

TEST_CASE("given tensors: SymPy's test_rigidbody_inertia, a tensor given about a point", "[lower_body][inertia]")
{
    // RigidBody('R', o, N, m, (Io, p)) with Io = inertia(N, Ix, Iy, Iz) about p = o + a N.x + b N.y:
    // central_inertia == inertia(N, Ix − b²m, Iy − a²m, Iz − m(a² + b²), m a b).
    auto central = [](const model& scene) {
        const GiNaC::ex m = symbol_of(scene, "m"), Ix = symbol_of(scene, "Ix"), Iy = symbol_of(scene, "Iy"),
                        Iz = symbol_of(scene, "Iz"), a = symbol_of(scene, "a"), b = symbol_of(scene, "b");
        return GiNaC::matrix{{Ix - b * b * m, m * a * b, 0}, {m * a * b, Iy - a * a * m, 0}, {0, 0, Iz - m * (a * a + b * b)}};
    };
    model scene = load(sympy_header + "body R inertia ((Ix, 0, 0), (0, Iy, 0), (0, 0, Iz)) mass m about (a, b, 0)\n");
    require_tensor(derive_inertia(scene.bodies[0]).tensor, central(scene));
    // The principal moments form, given about the same point, gives the same tensor.
    model moments = load(sympy_header + "body R inertia (Ix, Iy, Iz) mass m about (a, b, 0)\n");
    require_tensor(derive_inertia(moments.bodies[0]).tensor, central(moments));
}

TEST_CASE("given tensors: SymPy's test_parallel_axis for a rigid body and for a particle", "[lower_body][inertia]")
{
    // R.parallel_axis(p) with central Io = inertia(N, Ix, Iy, Iz), p = o + a N.x + b N.y:
    // inertia(N, Ix + m b², Iy + m a², Iz + m (a² + b²), ixy = −m a b). Our tensor about
    // the origin of a body whose centre is at (a, b, 0) is the same shift.
    model scene = load(sympy_header + "body R inertia ((Ix, 0, 0), (0, Iy, 0), (0, 0, Iz)) mass m at (a, b, 0)\n");
    const inertia_result inertia = derive_inertia(scene.bodies[0]);
    REQUIRE(inertia.about_origin);
    const GiNaC::ex m = symbol_of(scene, "m"), Ix = symbol_of(scene, "Ix"), Iy = symbol_of(scene, "Iy"),
                    Iz = symbol_of(scene, "Iz"), a = symbol_of(scene, "a"), b = symbol_of(scene, "b");
    require_tensor(*inertia.about_origin, GiNaC::matrix{{Ix + m * b * b, -m * a * b, 0},
                                                        {-m * a * b, Iy + m * a * a, 0},
                                                        {0, 0, Iz + m * (a * a + b * b)}});
    // Particle('P', o, m).parallel_axis(p): inertia(N, m b², m a², m (a² + b²), ixy = −m a b).
    // A body with all moments zero is a particle.
    model particle = load(sympy_header + "body P inertia ((0, 0, 0), (0, 0, 0), (0, 0, 0)) mass m at (a, b, 0)\n");
    const inertia_result point = derive_inertia(particle.bodies[0]);
    REQUIRE(point.about_origin);
    const GiNaC::ex pm = symbol_of(particle, "m"), pa = symbol_of(particle, "a"), pb = symbol_of(particle, "b");
    require_tensor(*point.about_origin, GiNaC::matrix{{pm * pb * pb, -pm * pa * pb, 0},
                                                      {-pm * pa * pb, pm * pa * pa, 0},
                                                      {0, 0, pm * (pa * pa + pb * pb)}});
    // And back: that tensor given about the point (a, b, 0) leaves nothing about the centre.
    model back = load(sympy_header + "body P inertia ((m*b^2, -m*a*b, 0), (-m*a*b, m*a^2, 0), "
                                     "(0, 0, m*(a^2 + b^2))) mass m about (a, b, 0)\n");
    require_tensor(derive_inertia(back.bodies[0]).tensor, GiNaC::matrix(3, 3));
}

TEST_CASE("given tensors: zero moments of a thin rod and numbers about a point", "[lower_body][inertia]")
{
    // A thin rod along x has no moment about x: diag(0, I, I).
    model rod = load("parameters m\ncoordinates q\nbody S inertia (0, 1, 1) mass m orientation rotations(z q)\n");
    CHECK(derive_inertia(rod.bodies[0]).tensor(0, 0).is_zero());
    // SymPy's test_rigidbody3 uses I = outer(B.x, B.x), diag(1, 0, 0), which no body has.
    require_error("parameters m\ncoordinates q\nbody S inertia (1, 0, 0) mass m\n", 3, 16, "triangle inequality");
    // diag(5, 6, 7) of mass 1 about a point 3 along x from the centre: the centre has
    // diag(5, 6 − 9, 7 − 9), which no body has: an error at `about`.
    require_error("parameters m\ncoordinates q\nbody S inertia (5, 6, 7) mass 1 about (3, 0, 0)\n", 3, 39,
                  "impossible about the centre of mass");
    // A uniform rod of length 2 and mass 3 given about its end (1, 0, 0): diag(0, 4, 4)
    // there, diag(0, 1, 1) = (1/12)·3·2² about the centre.
    model end = load("coordinates q\nbody S inertia (0, 4, 4) mass 3 about (1, 0, 0)\n");
    require_tensor(derive_inertia(end.bodies[0]).tensor, GiNaC::matrix{{0, 0, 0}, {0, 1, 0}, {0, 0, 1}});
}

TEST_CASE("given tensors: a free thin body has no Euler equations (exit 1)", "[lower_body][euler]")
{
    for (const char* body : {"body B inertia (0, 1, 1) mass m\n", "body B stick(l) mass m\n",
                             "body B inertia ((1, 1, 0), (1, 1, 0), (0, 0, 2)) mass m\n"}) {
        model scene = load(std::string("parameters m l\n") + body + "omega B (w1, w2, w3)\n");
        const inertia_result inertia = derive_inertia(scene.bodies[0]);
        REQUIRE_THROWS_AS(derive_euler(scene.bodies[0], inertia, scene.initial, {}), computation_error);
    }
}

TEST_CASE("bodies of §5: input errors at their position", "[lower_body][lower]")
{
    const std::string h = "parameters m l I1\ncoordinates q p\n";
    // attached to
    require_error(h + "body B disk(l) mass m attached to X\n", 3, 35, "unknown body `X`");
    require_error(h + "body B disk(l) mass m attached to B\n", 3, 35, "attached to itself");
    require_error(h + "body A disk(l) mass m attached to B\nbody B disk(l) mass m attached to A\n", 4, 35,
                  "the attachments make a cycle");
    require_error(h + "body A disk(l) mass m attached to B\nbody B disk(l) mass m attached to C\n"
                      "body C disk(l) mass m attached to A\n",
                  5, 35, "cycle");
    require_error(h + "body A disk(l) mass m\nomega A (w1, w2, w3)\nbody B disk(l) mass m attached to A\n", 5, 35,
                  "is free");
    require_error(h + "body A disk(l) mass m orientation rotations(z q)\nbody B disk(l) mass m attached to A\n"
                      "omega B (w1, w2, w3)\n",
                  5, 1, "attached to `A`");
    // rotations
    require_error(h + "body B disk(l) mass m orientation rotations(z q, w p)\n", 3, 50, "`x`, `y` or `z`, not `w`");
    require_error(h + "body B disk(l) mass m orientation rotations(q)\n", 3, 46, "expected");
    require_error(h + "body B disk(l) mass m orientation xyz(q, 0, 0)\n", 3, 35, "rotations(z q1, x q2, ...)");
    // tensors
    require_error(h + "body B inertia ((1, 2, 0), (3, 1, 0), (0, 0, 1)) mass m\n", 3, 29, "symmetric");
    // Entries too large to expand are compared at random values of their parameters.
    CHECK_NOTHROW(load(h + "body B inertia ((1, (m+l)^400*(m-l), 0), ((m^2-l^2)*(m+l)^399, 1, 0), (0, 0, 1)) mass m\n"));
    require_error(h + "body B inertia ((1, (m+l)^400*(m-l), 0), ((m^2-l^2)*(m+l)^398, 1, 0), (0, 0, 1)) mass m\n", 3,
                  43, "symmetric");
    require_error(h + "body B inertia ((-1, 0, 0), (0, 1, 0), (0, 0, 1)) mass m\n", 3, 18, "cannot be negative");
    require_error(h + "body B inertia (1, 1, 3) mass m\n", 3, 16, "triangle inequality");
    require_error(h + "body B inertia ((1, 0, 0), (0, 1, 0)) mass m\n", 3, 16, "three rows");
    require_error(h + "body B inertia ((1, 0, 0), (0, 1), (0, 0, 1)) mass m\n", 3, 28, "three entries");
    // products of inertia too large for the moments: diag(1, 1, 1) with I_xy = 0.9 has
    // principal moments 0.1, 1, 1.9, which break the triangle inequality.
    require_error(h + "body B inertia ((1, 0.9, 0), (0.9, 1, 0), (0, 0, 1)) mass m\n", 3, 16, "triangle");
    require_error(h + "body B inertia (I1, 1, 3) mass m\nvalues I1 = 1, m = 1, l = 1\n", 4, 13,
                  "the moments of inertia of body `B` break the triangle inequality");
    require_error(h + "body B disk(l) mass m about (0, 0, 1)\n", 3, 29, "`about` names the point");
    require_error(h + "body B inertia (1, 1, 1) mass m about (0, q, 1)\n", 3, 43, "coordinate `q` cannot appear");
}
