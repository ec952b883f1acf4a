// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_orientation.cpp
 *  Bodies turned by sequences of rotations and attached to one another: the angular
 *  velocity against finite differences of R, `rotations(z, x, z)` against Goldstein's
 *  Euler-angle ω, T and V of a compound double pendulum and of a rod hanging from a
 *  turning disc against closed forms integrated by hand, and the self-verification. */
#include "algebra/rotation.h"
#include "bodies/inertia.h"
#include "bodies/orientation.h"
#include "engine/analysis.h"
#include "mechanics/lagrangian.h"
#include "verify/verify.h"
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

using namespace lagrange;
using namespace lagrange_test;
using Catch::Matchers::WithinAbs;

namespace {

double number(const GiNaC::ex& e) { return GiNaC::ex_to<GiNaC::numeric>(e.evalf()).to_double(); }

/// Random values for every coordinate, velocity and parameter of `scene`.
GiNaC::exmap random_point(const model& scene, std::mt19937& random)
{
    std::uniform_real_distribution<double> angle(-1.5, 1.5), positive(0.5, 2.0);
    GiNaC::exmap at;
    for (const coordinate& c : scene.coordinates) {
        at[c.position] = angle(random);
        at[c.velocity] = angle(random);
    }
    for (const parameter& p : scene.parameters)
        at[p.symbol] = positive(random);
    return at;
}

/// Whether a and b agree at `count` random points of `scene`.
void require_same_values(const model& scene, const GiNaC::ex& a, const GiNaC::ex& b, int count = 8)
{
    std::mt19937 random(7);
    for (int k = 0; k < count; ++k) {
        const GiNaC::exmap at = random_point(scene, random);
        const double x = number(a.subs(at)), y = number(b.subs(at));
        INFO("a = " << a << "\nb = " << b);
        CHECK_THAT(x, WithinAbs(y, 1e-10 * (1 + std::abs(y))));
    }
}

} // namespace

TEST_CASE("orientation: ω of a rotation sequence is the axial vector of RᵀṘ by finite differences",
          "[orientation]")
{
    model scene = load("coordinates a b c d\n");
    const GiNaC::ex a = scene.coordinates[0].position, b = scene.coordinates[1].position,
                    c = scene.coordinates[2].position, d = scene.coordinates[3].position;
    struct sequence {
        std::vector<char> axes;
        std::vector<GiNaC::ex> angles;
    };
    const std::vector<sequence> sequences = {
        {{'z', 'x', 'y'}, {a, b, c}},
        {{'y', 'z', 'y', 'x'}, {a, 2 * b, c - a, d}},
        {{'x'}, {a * b}},
        {{'z', 'z'}, {a, b}},
    };
    std::mt19937 random(11);
    for (const sequence& s : sequences) {
        const std::vector<GiNaC::ex> omega = sequence_angular_velocity(s.axes, s.angles, scene);
        const GiNaC::matrix rotation = rotation_sequence(s.axes, s.angles);
        for (int trial = 0; trial < 5; ++trial) {
            const GiNaC::exmap at = random_point(scene, random);
            // R(q + h q̇) and R(q − h q̇): Ṙ by central differences, then ω̂ = Rᵀ Ṙ.
            const double h = 1e-5;
            GiNaC::exmap ahead, behind, here;
            for (const coordinate& k : scene.coordinates) {
                const GiNaC::ex q = at.at(k.position), v = at.at(k.velocity);
                ahead[k.position] = q + h * v;
                behind[k.position] = q - h * v;
                here[k.position] = q;
            }
            std::array<std::array<double, 3>, 3> r{}, rate{};
            for (unsigned i = 0; i < 3; ++i)
                for (unsigned j = 0; j < 3; ++j) {
                    r[i][j] = number(rotation(i, j).subs(here));
                    rate[i][j] = (number(rotation(i, j).subs(ahead)) - number(rotation(i, j).subs(behind))) / (2 * h);
                }
            auto skew = [&](unsigned i, unsigned j) {
                double sum = 0;
                for (unsigned k = 0; k < 3; ++k)
                    sum += r[k][i] * rate[k][j];
                return sum;
            };
            const std::array<double, 3> expected = {skew(2, 1), skew(0, 2), skew(1, 0)};
            for (unsigned i = 0; i < 3; ++i)
                CHECK_THAT(number(omega[i].subs(at)), WithinAbs(expected[i], 1e-8));
        }
    }
}

TEST_CASE("orientation: rotations(z, x, z) is zxz, and both give Goldstein's ω", "[orientation]")
{
    model scene = load("coordinates phi theta psi\n");
    const std::vector<GiNaC::ex> angles = {scene.coordinates[0].position, scene.coordinates[1].position,
                                           scene.coordinates[2].position};
    const std::vector<GiNaC::ex> sequence = sequence_angular_velocity({'z', 'x', 'z'}, angles, scene);
    const std::vector<GiNaC::ex> euler =
        body_angular_velocity(euler_rotation(angles[0], angles[1], angles[2]), scene);
    for (unsigned i = 0; i < 3; ++i)
        require_same_values(scene, sequence[i], euler[i]);

    // The kinetic energy of a top at the origin written both ways, against
    // T = ½ A (φ̇² sin²θ + θ̇²) + ½ C (φ̇ cos θ + ψ̇)² (Goldstein 5.5).
    const std::string header = "parameters A C M\ncoordinates phi theta psi\n";
    model written = load(header + "body top inertia (A, A, C) mass M orientation rotations(z phi, x theta, z psi)\n");
    model euler_angles = load(header + "body top inertia (A, A, C) mass M orientation zxz(phi, theta, psi)\n");
    auto goldstein = [](const model& m) {
        const GiNaC::ex A = symbol_of(m, "A"), C = symbol_of(m, "C");
        const GiNaC::ex th = symbol_of(m, "theta"), dph = symbol_of(m, "phi_dot"), dth = symbol_of(m, "theta_dot"),
                        dps = symbol_of(m, "psi_dot");
        return A / 2 * (dph * dph * GiNaC::pow(GiNaC::sin(th), 2) + dth * dth) +
               C / 2 * GiNaC::pow(dph * GiNaC::cos(th) + dps, 2);
    };
    for (const model* m : {&written, &euler_angles})
        require_same_values(*m, derive_lagrangian(*m, make_simplifier(*m)).kinetic, goldstein(*m));
    // The stage `top` still finds the heavy top when it is written as rotations(z, x, z).
    CHECK(written.bodies[0].rotation_axes == std::vector<char>{'z', 'x', 'z'});
}

TEST_CASE("orientation: ½ tr(Ṙ J Ṙᵀ) equals ½ ωᵀ I ω for a tensor with products of inertia", "[orientation]")
{
    model scene = load("coordinates a b c\n");
    const std::vector<GiNaC::ex> angles = {scene.coordinates[0].position, scene.coordinates[1].position,
                                           scene.coordinates[2].position};
    const std::vector<char> axes = {'x', 'y', 'z'};
    const GiNaC::matrix tensor{{3, GiNaC::numeric(-1, 2), GiNaC::numeric(1, 3)},
                               {GiNaC::numeric(-1, 2), 4, GiNaC::numeric(1, 5)},
                               {GiNaC::numeric(1, 3), GiNaC::numeric(1, 5), 5}};
    const std::vector<GiNaC::ex> w = sequence_angular_velocity(axes, angles, scene);
    GiNaC::ex half_w_i_w = 0;
    for (unsigned i = 0; i < 3; ++i)
        for (unsigned j = 0; j < 3; ++j)
            half_w_i_w += w[i] * tensor(i, j) * w[j] / 2;
    require_same_values(scene, rotational_energy_from_rate(rotation_sequence(axes, angles), tensor, scene),
                        half_w_i_w);
}

namespace {

const std::string compound_double_pendulum = R"(
parameters m l g
coordinates th1 th2
body upper stick(l) mass m axis y at (l/2*sin(th1), -l/2*cos(th1), 0) orientation rotations(z th1)
body lower stick(l) mass m axis y attached to upper at (l/2*sin(th2), -l/2 - l/2*cos(th2), 0) \
    orientation rotations(z th2)
gravity g along (0, -1, 0)
equilibrium th1 = 0, th2 = 0
)";

} // namespace

TEST_CASE("attached bodies: the compound double pendulum of two equal rods", "[orientation][attached]")
{
    model scene = load(compound_double_pendulum);
    REQUIRE(scene.bodies.size() == 2);
    CHECK(scene.bodies[1].attached_to == "upper");
    CHECK(scene.bodies[1].rotation_axes == std::vector<char>{'z', 'z'});
    const lagrangian_result l = derive_lagrangian(scene, make_simplifier(scene));
    // With absolute angles φ1 = θ1, φ2 = θ1 + θ2 (Goldstein/Taylor, two uniform rods of
    // mass m and length l): T = (m l²/6)(4 φ̇1² + φ̇2² + 3 φ̇1 φ̇2 cos(φ1 − φ2)),
    // V = −(m g l/2)(3 cos φ1 + cos φ2).
    const GiNaC::ex m = symbol_of(scene, "m"), len = symbol_of(scene, "l"), g = symbol_of(scene, "g");
    const GiNaC::ex p1 = symbol_of(scene, "th1"), p2 = p1 + symbol_of(scene, "th2");
    const GiNaC::ex v1 = symbol_of(scene, "th1_dot"), v2 = v1 + symbol_of(scene, "th2_dot");
    const GiNaC::ex kinetic = m * len * len / 6 * (4 * v1 * v1 + v2 * v2 + 3 * v1 * v2 * GiNaC::cos(p1 - p2));
    const GiNaC::ex potential = -m * g * len / 2 * (3 * GiNaC::cos(p1) + GiNaC::cos(p2));
    require_same_values(scene, l.kinetic, kinetic);
    require_same_values(scene, l.potential, potential);

    // Small oscillations: ω² = (g/l)(3 ∓ 6/√7), the roots of 7λ² − 42λ + 27 with λ = ω² l/g.
    analysis a = analyze(scene, {product::frequencies});
    REQUIRE(a.modes);
    REQUIRE(a.modes->frequencies.size() == 2);
    const GiNaC::exmap values = {{m, GiNaC::numeric(13, 10)}, {len, GiNaC::numeric(7, 10)}, {g, GiNaC::numeric(981, 100)}};
    std::vector<double> found;
    for (const GiNaC::ex& w2 : a.modes->frequencies)
        found.push_back(number(w2.subs(values)));
    std::sort(found.begin(), found.end());
    const double scale = 9.81 / 0.7;
    CHECK_THAT(found[0], WithinAbs(scale * (3 - 6 / std::sqrt(7.0)), 1e-10));
    CHECK_THAT(found[1], WithinAbs(scale * (3 + 6 / std::sqrt(7.0)), 1e-10));
}

TEST_CASE("attached bodies: a rod hanging from the rim of a turning disc", "[orientation][attached]")
{
    // The disc turns about the vertical z by φ; the rod hangs from the rim point (R, 0, 0)
    // of the disc and swings about the disc's y axis by θ.
    model scene = load(R"(
parameters M m R l g
coordinates phi theta
body disc disk(R) mass M orientation rotations(z phi)
body rod stick(l) mass m attached to disc at (R - l/2*sin(theta), 0, -l/2*cos(theta)) orientation rotations(y theta)
gravity g along (0, 0, -1)
)");
    const lagrangian_result l = derive_lagrangian(scene, make_simplifier(scene));
    // By hand: a rod point at distance s from the pivot is at radius R − s sin θ and height
    // −s cos θ, so v² = s² θ̇² + (R − s sin θ)² φ̇²; (m/l)∫₀ˡ ½ v² ds gives the rod's T.
    const GiNaC::ex M = symbol_of(scene, "M"), m = symbol_of(scene, "m"), R = symbol_of(scene, "R"),
                    len = symbol_of(scene, "l"), g = symbol_of(scene, "g");
    const GiNaC::ex th = symbol_of(scene, "theta"), dph = symbol_of(scene, "phi_dot"),
                    dth = symbol_of(scene, "theta_dot");
    const GiNaC::ex s = GiNaC::sin(th);
    const GiNaC::ex rod = m / 2 * (len * len / 3 * dth * dth + (R * R - R * len * s + len * len / 3 * s * s) * dph * dph);
    const GiNaC::ex disc = M * R * R / 4 * dph * dph;
    require_same_values(scene, l.kinetic, rod + disc);
    require_same_values(scene, l.potential, -m * g * len / 2 * GiNaC::cos(th));
}

TEST_CASE("attached bodies: chains compose in any order of statements", "[orientation][attached]")
{
    // The child is declared before its parent: the attachment is resolved at the end.
    model before = load("parameters m l\ncoordinates a b\n"
                        "body C stick(l) mass m attached to P at (0, l, 0) orientation rotations(x b)\n"
                        "body P stick(l) mass m at (a, 0, 0) orientation rotations(z a)\n");
    const rigid_body& child = before.bodies[0];
    REQUIRE(child.position);
    REQUIRE(child.orientation);
    CHECK(child.rotation_axes == std::vector<char>{'z', 'x'});
    const GiNaC::ex a = symbol_of(before, "a"), len = symbol_of(before, "l");
    // r = r_P + R_z(a) (0, l, 0) = (a − l sin a, l cos a, 0).
    CHECK(((*child.position)[0] - (a - len * GiNaC::sin(a))).expand().is_zero());
    CHECK(((*child.position)[1] - len * GiNaC::cos(a)).expand().is_zero());
    CHECK((*child.position)[2].is_zero());
}

TEST_CASE("attached bodies: the self-verification checks T and V of a chain", "[orientation][verification]")
{
    model scene = load(compound_double_pendulum);
    analysis a = analyze(scene);
    REQUIRE(a.verification);
    std::vector<std::string> items;
    for (const verification_entry& e : a.verification->entries) {
        INFO(e.item << ": " << e.how);
        CHECK(e.checked);
        items.push_back(e.item);
    }
    CHECK(std::find(items.begin(), items.end(), "linearization") != items.end());
    // The reference T goes through ½ tr(Ṙ J Ṙᵀ), not through ω: it agrees with T as built.
    require_same_values(scene, a.lagrangian->kinetic_reference, a.lagrangian->kinetic_built);
    // A wrong kinetic matrix is caught against that reference.
    REQUIRE(a.linearization);
    linearization_result wrong = *a.linearization;
    wrong.kinetic(0, 0) = wrong.kinetic(0, 0) * GiNaC::numeric(11, 10);
    verification_input input = verification_input_of(a);
    input.linearization = &wrong;
    input.characteristic = nullptr;
    input.modes = nullptr;
    REQUIRE_THROWS_AS(verify_results(scene, input, {product::frequencies}), computation_error);
}
