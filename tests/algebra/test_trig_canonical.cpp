// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_trig_canonical.cpp
 *  The canonical trigonometric form for arguments that are not coordinates: w*t, x/R,
 *  q1 - q2/2, a parameter. Every result is compared by meaning: the difference from a
 *  textbook identity vanishes, and the form agrees with the input at random points. */
#include "algebra/trig_canonical.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

namespace {

using GiNaC::ex;

bool expanded_zero(const ex& e)
{
    return e.is_zero() || e.expand().normal().is_zero();
}

/// |a − b| at `count` random points of `symbols` (uniform in [0.3, 2.3)), the largest.
double largest_difference(const ex& a, const ex& b, const GiNaC::lst& symbols, int count = 20)
{
    std::mt19937 random(1234);
    std::uniform_real_distribution<double> uniform(0.3, 2.3);
    double largest = 0;
    for (int k = 0; k < count; ++k) {
        GiNaC::exmap point;
        for (const ex& s : symbols)
            point[s] = uniform(random);
        const ex d = GiNaC::evalf((a - b).subs(point));
        largest = std::max(largest, std::abs(GiNaC::ex_to<GiNaC::numeric>(d).to_double()));
    }
    return largest;
}

} // namespace

TEST_CASE("trig_canonical: sin^2 + cos^2 of w·t is 1", "[trig_canonical]")
{
    const GiNaC::realsymbol q("q"), t("t");
    const GiNaC::possymbol w("w"), m("m");
    const GiNaC::lst angles{q};
    CHECK(lagrange::trig_canonical(GiNaC::pow(GiNaC::cos(w * t), 2) + GiNaC::pow(GiNaC::sin(w * t), 2), angles)
              .is_equal(1));
    // Scaled, and mixed with the coordinate: sin²q (cos²wt + sin²wt) = sin²q.
    const ex mixed = m * GiNaC::pow(GiNaC::sin(q), 2) *
                     (GiNaC::pow(GiNaC::cos(w * t), 2) + GiNaC::pow(GiNaC::sin(w * t), 2));
    CHECK(expanded_zero(lagrange::trig_canonical(mixed - m * GiNaC::pow(GiNaC::sin(q), 2), angles)));
    CHECK_FALSE(lagrange::trig_canonical(mixed, angles).has(t));
}

TEST_CASE("trig_canonical: arguments x/R, q1 - q2/2 and a parameter", "[trig_canonical]")
{
    const GiNaC::realsymbol x("x"), q1("q1"), q2("q2");
    const GiNaC::possymbol R("R"), a("a");
    SECTION("x/R")
    {
        const GiNaC::lst angles{x};
        CHECK(lagrange::trig_canonical(GiNaC::pow(GiNaC::cos(x / R), 2) + GiNaC::pow(GiNaC::sin(x / R), 2), angles)
                  .is_equal(1));
        // 2 sin(x/R) cos(x/R) = sin(2x/R)
        CHECK(expanded_zero(lagrange::trig_canonical(2 * GiNaC::sin(x / R) * GiNaC::cos(x / R) - GiNaC::sin(2 * x / R),
                                               angles)));
    }
    SECTION("q1 - q2/2")
    {
        const GiNaC::lst angles{q1, q2};
        const ex u = q1 - q2 / 2;
        CHECK(lagrange::trig_canonical(GiNaC::pow(GiNaC::cos(u), 2) + GiNaC::pow(GiNaC::sin(u), 2), angles)
                  .is_equal(1));
        // cos(q1 - q2/2) cos(q2/2) − sin(q1 − q2/2) sin(q2/2) = cos(q1)
        const ex sum = GiNaC::cos(u) * GiNaC::cos(q2 / 2) - GiNaC::sin(u) * GiNaC::sin(q2 / 2);
        CHECK(expanded_zero(lagrange::trig_canonical(sum - GiNaC::cos(q1), angles)));
    }
    SECTION("a parameter")
    {
        const GiNaC::lst angles{x};
        // A parameter times a coordinate is one more angle; a positive parameter alone
        // stays an offset (sin a, cos a, tan a are atoms of the coefficients).
        CHECK(lagrange::trig_canonical(GiNaC::pow(GiNaC::cos(a * x), 2) + GiNaC::pow(GiNaC::sin(a * x), 2), angles)
                  .is_equal(1));
        CHECK(expanded_zero(
            lagrange::trig_canonical(2 * GiNaC::sin(a * x) * GiNaC::cos(a * x) - GiNaC::sin(2 * a * x), angles)));
        // cos(x + a) through the addition formula
        const ex sum = GiNaC::cos(x) * GiNaC::cos(a) - GiNaC::sin(x) * GiNaC::sin(a);
        CHECK(expanded_zero(lagrange::trig_canonical(sum - GiNaC::cos(x + a), angles)));
        CHECK(lagrange::trig_equal(sum, GiNaC::cos(a + x), angles));
        CHECK_FALSE(lagrange::trig_equal(sum, GiNaC::cos(a - x), angles));
    }
}

TEST_CASE("trig_canonical: the kinetic energy of a bead on a turning hoop is free of t", "[trig_canonical]")
{
    // r = R (sin q cos wt, sin q sin wt, −cos q); T = ½ m |ṙ|² = ½ m R² (q̇² + w² sin² q).
    const GiNaC::realsymbol q("q"), q_dot("q_dot"), t("t");
    const GiNaC::possymbol m("m"), R("R"), w("w");
    const ex vx = R * (GiNaC::cos(q) * q_dot * GiNaC::cos(w * t) - GiNaC::sin(q) * w * GiNaC::sin(w * t));
    const ex vy = R * (GiNaC::cos(q) * q_dot * GiNaC::sin(w * t) + GiNaC::sin(q) * w * GiNaC::cos(w * t));
    const ex vz = R * GiNaC::sin(q) * q_dot;
    const ex kinetic = GiNaC::numeric(1, 2) * m * (vx * vx + vy * vy + vz * vz);
    const ex canonical = lagrange::trig_canonical(kinetic, GiNaC::lst{q});
    CHECK_FALSE(canonical.has(t));
    const ex reference = GiNaC::numeric(1, 2) * m * R * R * (q_dot * q_dot + w * w * GiNaC::pow(GiNaC::sin(q), 2));
    CHECK(lagrange::trig_equal(canonical, reference, GiNaC::lst{q}));
    CHECK(largest_difference(canonical, kinetic, GiNaC::lst{q, q_dot, t, m, R, w}) < 1e-12);
}

TEST_CASE("trig_canonical: products of harmonics of t and of the coordinates", "[trig_canonical]")
{
    const GiNaC::realsymbol q("q"), t("t");
    const GiNaC::possymbol w("w"), g("g");
    const GiNaC::lst angles{q};
    const ex e = GiNaC::sin(q) * GiNaC::cos(w * t) * (g + GiNaC::cos(2 * w * t)) +
                 GiNaC::pow(GiNaC::sin(w * t - q), 3);
    const ex canonical = lagrange::trig_canonical(e, angles);
    CHECK(largest_difference(canonical, e, GiNaC::lst{q, t, w, g}) < 1e-12);
    // The general path and the fast path (where it applies) give the same form.
    CHECK(canonical.is_equal(lagrange::trig_canonical_general(e, angles)));
    // Canonical: the same function written otherwise gives the same form.
    const ex rewritten = GiNaC::sin(q) * GiNaC::cos(w * t) * g +
                         GiNaC::sin(q) * (GiNaC::cos(3 * w * t) + GiNaC::cos(w * t)) / 2 -
                         GiNaC::pow(GiNaC::sin(q - w * t), 3);
    CHECK(expanded_zero(canonical - lagrange::trig_canonical(rewritten, angles)));
}
