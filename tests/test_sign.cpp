// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_sign.cpp
 *  Signs of expressions at parameter points. */
#include "algebra/sign.h"

#include <catch2/catch.hpp>

#include <vector>

using namespace GiNaC;

TEST_CASE("sign_at: a square root that factor() puts on the wrong branch keeps its sign", "[sign]")
{
    // The principal moments of a box of density M (x + a)² (1 + y z): the stability of
    // rotation about each axis is the sign of (I_i − I_j)(I_i − I_k). GiNaC's factor()
    // rewrote √X as ±i √(−X) with the sign following the term order, so that in about
    // one process in ten an intermediate axis was called stable. Fresh symbols in each
    // round give other term orders.
    for (int round = 0; round < 20; ++round) {
        possymbol M("M"), a("a"), b("b"), c("c");
        const ex root = sqrt(1297149700055040000 * pow(a, 6) * pow(M, 2) * pow(b, 6) * pow(c, 2) +
                             1297149700055040000 * pow(a, 6) * pow(M, 2) * pow(b, 2) * pow(c, 6) +
                             36031936112640000 * pow(a, 6) * pow(M, 2) * pow(b, 6) * pow(c, 6) -
                             2594299400110080000 * pow(a, 6) * pow(M, 2) * pow(b, 4) * pow(c, 4));
        const ex base = numeric(13, 288) * pow(a, 3) * M * b * pow(c, 3) + numeric(73, 1040) * pow(a, 5) * M * b * c +
                        numeric(13, 288) * pow(a, 3) * M * pow(b, 3) * c;
        const std::vector<ex> moments = {numeric(13, 144) * pow(a, 3) * M * b * pow(c, 3) +
                                             numeric(13, 144) * pow(a, 3) * M * pow(b, 3) * c,
                                         base + root / 25231564800, base - root / 25231564800};
        const exmap values{{M, 2}, {a, 1}, {b, numeric(3, 2)}, {c, 2}};
        for (std::size_t i = 0; i < 3; ++i) {
            const ex product = (moments[i] - moments[(i + 1) % 3]) * (moments[i] - moments[(i + 2) % 3]);
            const double value = *lagrange::number_at(product, values);
            INFO("round " << round << ", axis " << i + 1 << ": " << value);
            CHECK(lagrange::sign_at(product, values) == std::optional<int>(value > 0 ? 1 : -1));
        }
    }
}
