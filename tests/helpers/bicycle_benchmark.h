// SPDX-License-Identifier: GPL-2.0-or-later
/** @file bicycle_benchmark.h
 *  The published reference of the Whipple bicycle benchmark (Meijaard, Papadopoulos, Ruina
 *  and Schwab, Proc. R. Soc. A 463 (2007) 1955–1982), shared by the tests of the reduced
 *  bicycle (tests/numeric/test_critical.cpp) and of the whole one
 *  (tests/mechanics/test_bicycle.cpp). */
#pragma once

#include "numeric/critical.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
#include <map>
#include <vector>

namespace lagrange_test {

/// Table 2 of Meijaard et al. (2007): at each speed v = 0, 1, …, 10 m/s, the weave pair
/// (one of the conjugates listed), the capsize and the castor eigenvalues; at v = 0 the four
/// real ones (as transcribed in D. L. Peterson's whipple test, and for v = 0, 4, 5, 10 in
/// the `pathfinder` package's test_whipple.py).
inline const std::map<int, std::vector<std::complex<double>>>& bicycle_table_2()
{
    static const std::map<int, std::vector<std::complex<double>>> table = {
        {0, {3.13164324790656, -3.13164324790656, 5.53094371765393, -5.53094371765393}},
        {1, {{3.52696170990070, 0.80774027519930}, -3.13423125066578, -7.11008014637442}},
        {2, {{2.68234517512745, 1.68066296590675}, -3.07158645641514, -8.67387984831735}},
        {3, {{1.70675605663975, 2.31582447384325}, -2.63366137253667, -10.35101467245920}},
        {4, {{0.41325331521125, 3.07910818603206}, -1.42944427361326, -12.15861426576447}},
        {5, {{-0.77534188219585, 4.46486771378823}, -0.32286642900409, -14.07838969279822}},
        {6, {{-1.52644486584142, 5.87673060598709}, -0.00406690076970, -16.08537123098030}},
        {7, {{-2.13875644258362, 7.19525913329805}, 0.10268170574766, -18.15788466125262}},
        {8, {{-2.69348683581097, 8.46037971396931}, 0.14327879765713, -20.27940894394569}},
        {9, {{-3.21675402252485, 9.69377351531791}, 0.15790184030917, -22.43788559040858}},
        {10, {{-3.72016840437287, 10.90681139476287}, 0.16105338653172, -24.62459635017404}},
    };
    return table;
}

/// The computed eigenvalue nearest `reference`, relative to |reference|.
inline double relative_distance(const std::vector<std::complex<double>>& computed, std::complex<double> reference)
{
    double best = 1e300;
    for (const std::complex<double>& s : computed)
        best = std::min(best, std::abs(s - reference) / std::abs(reference));
    return best;
}

/// The eigenvalues of a `critical v from 0 to 10` run against Table 2: its table rows are
/// v = 0, 1, …, 10 exactly, each with the four lean and steer eigenvalues, every reference
/// (and its conjugate) matched to 1e-10 relative.
inline void check_table_2(const lagrange::critical_result& r)
{
    REQUIRE(r.parameter == "v");
    std::size_t rows = 0;
    for (std::size_t i = 0; i < r.grid.size(); i += r.table_every, ++rows) {
        const int v = static_cast<int>(rows);
        INFO("v = " << v);
        REQUIRE(r.grid[i] == static_cast<double>(v));
        REQUIRE(r.locus[i].size() == 4);
        for (const std::complex<double>& reference : bicycle_table_2().at(v)) {
            INFO("reference " << reference);
            CHECK(relative_distance(r.locus[i], reference) <= 1e-10);
            CHECK(relative_distance(r.locus[i], std::conj(reference)) <= 1e-10);
        }
    }
    CHECK(rows == 11);
}

} // namespace lagrange_test
