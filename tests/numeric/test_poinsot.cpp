// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_poinsot.cpp
 *  Poinsot's construction of a free asymmetric box: the contact point lies on the inertia
 *  ellipsoid and on the invariable plane at √(2T)/|L| (T and L written out by hand), the
 *  ellipsoid's normal there is L, L stays fixed in space, and the body's material point at
 *  the contact has zero velocity (the orientation differentiated by finite differences); a
 *  symmetric body's herpolhode is the circle its constant |ω| gives. */
#include "engine/analysis.h"
#include "numeric/poinsot.h"
#include "helpers/scene_helpers.h"
#include "helpers/free_box.h"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using lagrange_test::load;

namespace {

const std::array<double, 3>& moments = lagrange_test::free_box_moments;
const std::array<double, 3>& omega0 = lagrange_test::free_box_omega0;

using vector3 = std::array<double, 3>;

vector3 times(const std::array<double, 9>& R, const vector3& v)
{
    return {R[0] * v[0] + R[1] * v[1] + R[2] * v[2], R[3] * v[0] + R[4] * v[1] + R[5] * v[2],
            R[6] * v[0] + R[7] * v[1] + R[8] * v[2]};
}

vector3 transposed_times(const std::array<double, 9>& R, const vector3& v)
{
    return {R[0] * v[0] + R[3] * v[1] + R[6] * v[2], R[1] * v[0] + R[4] * v[1] + R[7] * v[2],
            R[2] * v[0] + R[5] * v[1] + R[8] * v[2]};
}

double norm(const vector3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

/// The space velocity of the body point `b` (body axes) at frame f: Ṙ b, with Ṙ by the
/// fourth-order central difference of the frames' orientations.
vector3 material_velocity(const lagrange::poinsot_motion& m, std::size_t f, const vector3& b, double h)
{
    vector3 v{};
    const double weights[] = {1, -8, 0, 8, -1};
    for (int k = -2; k <= 2; ++k) {
        const vector3 r = times(m.rotation[f + static_cast<std::size_t>(k + 2) - 2], b);
        for (int i = 0; i < 3; ++i)
            v[i] += weights[k + 2] * r[i] / (12 * h);
    }
    return v;
}

} // namespace

TEST_CASE("poinsot: the inertia ellipsoid of a free box rolls without slipping on the invariable plane",
          "[poinsot]")
{
    lagrange::model scene = load(lagrange_test::free_box_scene);
    lagrange::analysis a = lagrange::analyze(scene, {lagrange::product::euler});
    REQUIRE(a.euler);
    REQUIRE(a.euler->size() == 1);
    lagrange::poinsot_settings settings;
    settings.until = 20;
    settings.step = 0.01;
    const lagrange::poinsot_motion m = lagrange::compute_poinsot(a.euler->front(), settings);

    double two_t = 0;
    vector3 l0{};
    for (int i = 0; i < 3; ++i) {
        two_t += moments[i] * omega0[i] * omega0[i];
        l0[i] = moments[i] * omega0[i];
    }
    const double distance = std::sqrt(two_t) / norm(l0);
    CHECK_THAT(m.plane_distance, WithinRel(distance, 1e-14));
    for (int i = 0; i < 3; ++i)
        CHECK_THAT(m.semi_axes[i], WithinRel(1 / std::sqrt(moments[i]), 1e-14));
    REQUIRE(m.times.size() == 2001);
    REQUIRE(m.contact.size() == m.times.size());

    double worst_plane = 0, worst_ellipsoid = 0, worst_normal = 0, worst_slip = 0, smallest_other = 1e300;
    for (std::size_t f = 0; f < m.times.size(); ++f) {
        const vector3& p = m.contact[f];
        const std::array<double, 9>& R = m.rotation[f];
        // On the plane z = −√(2T)/|L| …
        worst_plane = std::max(worst_plane, std::abs(p[2] + distance));
        // … and on the ellipsoid ρᵀ I ρ = 1, in body axes …
        const vector3 b = transposed_times(R, p);
        double on = 0;
        for (int i = 0; i < 3; ++i)
            on += moments[i] * b[i] * b[i];
        worst_ellipsoid = std::max(worst_ellipsoid, std::abs(on - 1));
        // … whose normal there, I ρ turned into space, is −z: the plane is tangent, and L = R I ω stays along −z.
        const vector3 normal = times(R, {moments[0] * b[0], moments[1] * b[1], moments[2] * b[2]});
        worst_normal = std::max(worst_normal, std::hypot(normal[0], normal[1]) / norm(normal));
        CHECK(normal[2] < 0);
        const vector3 l = times(R, {moments[0] * m.omega[f][0], moments[1] * m.omega[f][1], moments[2] * m.omega[f][2]});
        worst_normal = std::max(worst_normal, std::hypot(l[0], l[1], l[2] + norm(l0)) / norm(l0));
        if (f < 2 || f + 2 >= m.times.size())
            continue;
        // Rolling without slipping: the body's point at the contact does not move.
        const double speed = norm(material_velocity(m, f, b, settings.step));
        const double scale = norm(m.omega[f]) * norm(p);
        worst_slip = std::max(worst_slip, speed / scale);
        // Another point of the ellipsoid, the end of its first semi-axis, does move.
        smallest_other = std::min(smallest_other,
                                  norm(material_velocity(m, f, {m.semi_axes[0], 0, 0}, settings.step)) / scale);
    }
    CHECK(worst_plane <= 1e-9 * distance);
    CHECK(worst_ellipsoid <= 1e-9);
    CHECK(worst_normal <= 1e-9);
    CHECK(worst_slip <= 1e-7);
    CHECK(smallest_other >= 1e-2);
    // The herpolhode leaves its start: the contact point moves on the plane.
    CHECK(std::hypot(m.contact.back()[0] - m.contact.front()[0], m.contact.back()[1] - m.contact.front()[1]) > 0.01);
    // The polhode is closed and lies on the ellipsoid.
    REQUIRE(m.polhode.size() > 2);
    CHECK(m.polhode.front() == m.polhode.back());
    for (const vector3& b : m.polhode)
        CHECK_THAT(moments[0] * b[0] * b[0] + moments[1] * b[1] * b[1] + moments[2] * b[2] * b[2], WithinAbs(1, 1e-9));
}

TEST_CASE("poinsot: a body under torque has no construction", "[poinsot]")
{
    lagrange::euler_result e;
    e.body = "X";
    e.torque_free = false;
    REQUIRE_THROWS_AS(lagrange::compute_poinsot(e, {}), lagrange::computation_error);
}

TEST_CASE("poinsot: a symmetric body's herpolhode is a circle about the foot of the centre", "[poinsot]")
{
    // I = (1, 1, 2), ω(0) = (0.3, 0, 1): |ω| is constant, so the contact point ρ = Rω/√(2T) keeps
    // its distance √(|ω|²/(2T) − d²) from the plane's point nearest the centre (d = √(2T)/|L|).
    lagrange::model scene = load("parameters M A C\nbody D inertia (A, A, C) mass M\nomega D (p, q, r)\n"
                                 "values M = 1, A = 1, C = 2\ninitial p = 0.3, q = 0, r = 1\n");
    lagrange::analysis a = lagrange::analyze(scene, {lagrange::product::euler});
    REQUIRE(a.euler);
    lagrange::poinsot_settings settings;
    settings.until = 30;
    settings.step = 0.05;
    const lagrange::poinsot_motion m = lagrange::compute_poinsot(a.euler->front(), settings);
    const double two_t = 1 * 0.09 + 2 * 1.0, l = std::sqrt(0.09 + 4.0), d = std::sqrt(two_t) / l;
    const double radius = std::sqrt((0.09 + 1.0) / two_t - d * d);
    // The polhode's period: the transverse ω turns at (C − A) r / A = 1.
    CHECK_THAT(m.period, WithinRel(2 * M_PI, 1e-12));
    double worst = 0;
    for (const vector3& c : m.contact)
        worst = std::max(worst, std::abs(std::hypot(c[0], c[1]) - radius));
    CHECK(worst <= 1e-9);
    CHECK(radius > 0.05);
}
