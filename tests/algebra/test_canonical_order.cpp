// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_canonical_order.cpp
 *  Results that do not depend on GiNaC's hash order. GiNaC orders terms by hashes
 *  seeded from addresses (which change between processes) and symbol serials (which
 *  change with the symbols made before): here the same expressions are built from two
 *  sets of symbols with the same names made in opposite orders, so their hash orders,
 *  and the signs GiNaC gives factor sums, differ within one process. The canonical keys,
 *  the compiled programs and the order of factors must not. */
#include "algebra/canonical_order.h"
#include "algebra/sorted_terms.h"
#include "program/expression_program.h"
#include "numeric/values.h"

#include <catch2/catch.hpp>

#include <cln/cln.h>

#include <string>
#include <vector>

using namespace lagrange;
using GiNaC::ex;

namespace {

struct symbols {
    GiNaC::symbol a, b, c, x, y;
};

/// Symbols named a, b, c, x, y, made in the given order (so with other serials).
symbols make_symbols(bool reversed)
{
    if (!reversed) {
        GiNaC::symbol a("a"), b("b"), c("c"), x("x"), y("y");
        return {a, b, c, x, y};
    }
    GiNaC::symbol y("y"), x("x"), c("c"), b("b"), a("a");
    return {a, b, c, x, y};
}

/// Sums as factors, integer powers of sums, quotients, functions of sums and many terms.
std::vector<ex> sample(const symbols& s)
{
    const ex a = s.a, b = s.b, c = s.c, x = s.x, y = s.y;
    return {
        (a - b) * c * x + (b - c) * (a - x) * y,
        GiNaC::numeric(3, 7) * (c - a) * (b - a) / (x - y),
        GiNaC::pow(a - b, 3) * x - GiNaC::pow(b - x, 2) * y + 1 / GiNaC::pow(c - a, 2),
        GiNaC::sin(a - b) * (x - y) + GiNaC::cos(c * x - a * y) * (y - a) * (b - c),
        a * x + b * y + c * x * y - a * b - b * c + x * x * y - y * y * a + 5 * c - 1,
    };
}

std::vector<ex> as_list(const symbols& s) { return {s.a, s.b, s.c, s.x, s.y}; }

} // namespace

TEST_CASE("canonical keys: equal for one value in either hash order and with either sign of a factor",
          "[determinism][canonical_order]")
{
    const symbols first = make_symbols(false), second = make_symbols(true);
    const std::vector<ex> one = sample(first), other = sample(second);
    for (std::size_t k = 0; k < one.size(); ++k) {
        INFO(one[k] << "  and  " << other[k]);
        CHECK(canonical_key(one[k]) == canonical_key(other[k]));
    }
    const ex a = first.a, b = first.b, c = first.c;
    CHECK(canonical_key((a - b) * c) == canonical_key(-(b - a) * c));
    CHECK(canonical_key((a - b) * c) != canonical_key((b - a) * c));
    canonical_keys keys;
    CHECK(keys.sum(a - b).negative != keys.sum(b - a).negative);
    CHECK(keys.sum(a - b).key == keys.sum(b - a).key);
    CHECK(canonical_key(GiNaC::pow(a - b, 3) * c) == canonical_key(-GiNaC::pow(b - a, 3) * c));
    CHECK(canonical_key(GiNaC::pow(a - b, 2) * c) == canonical_key(GiNaC::pow(b - a, 2) * c));
    CHECK(canonical_key(c / (a - b)) == canonical_key(-c / (b - a)));
}

TEST_CASE("compiled programs: the same operations in the same order in either hash order",
          "[determinism][expression_program]")
{
    const symbols first = make_symbols(false), second = make_symbols(true);
    const expression_program one(sample(first), as_list(first)), other(sample(second), as_list(second));
    CHECK(one.c_source("f") == other.c_source("f"));
    // And the same program for an expression written with the other sign of its factors.
    const ex a = first.a, b = first.b, c = first.c, x = first.x;
    const expression_program p({(a - b) * (c - x) * x}, as_list(first)), q({(b - a) * (x - c) * x}, as_list(first));
    CHECK(p.c_source("f") == q.c_source("f"));
    // The values are right.
    const std::vector<double> at{0.3, -1.7, 2.5, 0.9, -0.4};
    std::vector<double> scratch, out(one.output_count());
    one.run(at.data(), scratch, out.data());
    const double A = at[0], B = at[1], C = at[2], X = at[3], Y = at[4];
    CHECK(out[0] == Approx((A - B) * C * X + (B - C) * (A - X) * Y));
    CHECK(out[1] == Approx(3.0 / 7 * (C - A) * (B - A) / (X - Y)));
    CHECK(out[2] == Approx(std::pow(A - B, 3) * X - std::pow(B - X, 2) * Y + 1 / std::pow(C - A, 2)));
    CHECK(out[3] == Approx(std::sin(A - B) * (X - Y) + std::cos(C * X - A * Y) * (Y - A) * (B - C)));
    CHECK(out[4] == Approx(A * X + B * Y + C * X * Y - A * B - B * C + X * X * Y - Y * Y * A + 5 * C - 1));
}

TEST_CASE("sorted factors: one order whatever sign factor() gave each factor", "[determinism][canonical_order]")
{
    const symbols first = make_symbols(false);
    const ex a = first.a, b = first.b, c = first.c;
    const GiNaC::exvector one = sorted_factors((a - b) * (c - a) * (b + c));
    const GiNaC::exvector other = sorted_factors((b - a) * (a - c) * (b + c));
    REQUIRE(one.size() == other.size());
    for (std::size_t k = 0; k < one.size(); ++k) {
        INFO(one[k] << "  and  " << other[k]);
        CHECK((one[k] - other[k]).expand().is_zero() ^ (one[k] + other[k]).expand().is_zero());
    }
}

TEST_CASE("exact numbers: a double becomes the rational it stands for", "[determinism][values]")
{
    const GiNaC::symbol x("x");
    const ex e = exact_numbers(GiNaC::numeric(0.1) * x + GiNaC::numeric(2.5));
    CHECK(e.is_equal(ex(GiNaC::numeric(cln::rational(cln::cl_DF(0.1)))) * x + GiNaC::numeric(5, 2)));
    CHECK(GiNaC::ex_to<GiNaC::numeric>(e.coeff(x, 1)).is_rational());
    CHECK(GiNaC::ex_to<GiNaC::numeric>(e.coeff(x, 1)).to_double() == 0.1);
}
