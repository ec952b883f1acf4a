// SPDX-License-Identifier: GPL-2.0-or-later
/** @file chain_equilibrium.cpp
 *  Benchmark: the stable equilibrium of the planar N-link pendulum (absolute angles,
 *  distinct masses and lengths), found without listing the 2^N combinations of 0 and
 *  π. Prints N, the number of points reported, the chosen point's stability and the
 *  median CPU time of find_equilibria alone (the Lagrangian is derived beforehand).
 *  Usage: chain_equilibrium [max_N] [reps] */
#include "helpers/chain_scene.h"
#include "mechanics/equilibrium.h"
#include "mechanics/lagrangian.h"
#include "scene/lower.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <vector>

int main(int argc, char** argv)
{
    int max_links = argc > 1 ? std::atoi(argv[1]) : 12;
    int repetitions = argc > 2 ? std::atoi(argv[2]) : 5;
    std::printf("%6s %8s %10s %12s\n", "links", "points", "stability", "cpu seconds");
    for (int links = 2; links <= max_links; ++links) {
        lagrange::model scene =
            lagrange::load_model(lagrange::source_text("chain.lag", lagrange_test::chain_scene(links)));
        lagrange::simplifier simplify = lagrange::make_simplifier(scene);
        lagrange::lagrangian_result lagrangian = lagrange::derive_lagrangian(scene, simplify);
        std::vector<double> seconds;
        lagrange::equilibria_result result;
        for (int r = 0; r < repetitions; ++r) {
            std::clock_t start = std::clock();
            result = lagrange::find_equilibria(scene, lagrangian, simplify);
            seconds.push_back(static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC);
        }
        std::sort(seconds.begin(), seconds.end());
        std::printf("%6d %8zu %10s %12.4f\n", links, result.points.size(),
                    lagrange::to_string(result.points[result.chosen].kind).c_str(), seconds[seconds.size() / 2]);
    }
}
