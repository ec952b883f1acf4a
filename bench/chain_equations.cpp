// SPDX-License-Identifier: GPL-2.0-or-later
/** @file chain_equations.cpp
 *  Benchmark: the Euler–Lagrange equations of the planar N-link pendulum (point
 *  masses m1..mN on rods l1..lN, all distinct symbols, absolute angles q1..qN),
 *  derived from point positions and simplified to canonical trig form, N = 2..12.
 *  Prints N, the median wall time of the whole derivation (scene text to simplified
 *  equations), and the size of the result. Usage: chain_equations [max_N] [reps] */
#include "helpers/chain_scene.h"
#include "engine/analysis.h"
#include "scene/lower.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

std::size_t term_count(const GiNaC::ex& e)
{
    GiNaC::ex expanded = e.expand();
    return GiNaC::is_a<GiNaC::add>(expanded) ? expanded.nops() : 1;
}

} // namespace

int main(int argc, char** argv)
{
    int max_links = argc > 1 ? std::atoi(argv[1]) : 12;
    int reps = argc > 2 ? std::atoi(argv[2]) : 7;
    std::printf("%4s %12s %12s %10s\n", "N", "median_ms", "min_ms", "terms");
    for (int links = 2; links <= max_links; ++links) {
        std::string text = lagrange_test::chain_scene(links) + "want equations\n";
        std::vector<double> times;
        std::size_t terms = 0;
        for (int r = 0; r < reps; ++r) {
            auto start = std::chrono::steady_clock::now();
            lagrange::model scene = lagrange::load_model(lagrange::source_text("chain.lag", text));
            lagrange::analysis result = lagrange::analyze(scene);
            std::chrono::duration<double, std::milli> elapsed = std::chrono::steady_clock::now() - start;
            times.push_back(elapsed.count());
            terms = 0;
            for (const GiNaC::ex& e : *result.equations->residuals)
                terms += term_count(e);
        }
        std::sort(times.begin(), times.end());
        std::printf("%4d %12.3f %12.3f %10zu\n", links, times[times.size() / 2], times.front(), terms);
        std::fflush(stdout);
    }
}
