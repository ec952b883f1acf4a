// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_readiness.cpp
 *  unmet_needs: what the numeric commands need that a scene does not give. */
#include "engine/readiness.h"
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>

using namespace lagrange;
using namespace lagrange_test;

TEST_CASE("readiness: values of every parameter and an end time", "[readiness]")
{
    const std::string energies = "parameters m k\ncoordinates x\nT = 1/2*m*x'^2\nV = 1/2*k*x^2\n";
    std::vector<std::string> none = unmet_needs(load(energies));
    REQUIRE(none.size() == 2);
    CHECK(none[0] == "simulate, workprecision and the numeric modes: values of `m`, `k` (a `values` line or "
                     "--values)");
    CHECK(none[1] == "simulate, workprecision and ensemble: an end time (a `simulate until T` line or --until)");

    std::vector<std::string> partial = unmet_needs(load(energies + "values m = 1, k = 2\nvalues m = 2\n"));
    REQUIRE(partial.size() == 2);
    CHECK(partial[0] == "simulate, workprecision and the numeric modes: the `values` line at line 6 gives no "
                        "value of `k`");

    CHECK(unmet_needs(load(energies + "values m = 1, k = 2\nsimulate until 3\n")).empty());
    // No parameters: nothing to give values of.
    CHECK(unmet_needs(load("coordinates x\nT = 1/2*x'^2\nV = x^2/2\nsimulate until 1\n")).empty());
}
