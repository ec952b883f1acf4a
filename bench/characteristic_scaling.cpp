// SPDX-License-Identifier: GPL-2.0-or-later
/** @file characteristic_scaling.cpp
 *  Benchmark: the characteristic polynomial det(V − W T) of the planar N-link pendulum
 *  (every mass and length a distinct symbol, hanging at rest), N = 2..max_N. For each N
 *  it prints the median wall time of the determinant alone (minor expansion, expanded),
 *  of the whole `characteristic` stage's work (the determinant made primitive, every
 *  coefficient factored), and the number of terms of the expanded determinant. T and V
 *  come from the engine's linearization, outside the timing; no budget is open. Last, the
 *  closed-form roots ω² of the 3-link chain's cubic (symbolic_modes without mode vectors).
 *  Usage: characteristic_scaling [max_N] [reps] */
#include "helpers/chain_scene.h"
#include "algebra/exact_matrix.h"
#include "engine/analysis.h"
#include "mechanics/modes.h"
#include "scene/lower.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

namespace {

double median_seconds(int reps, const std::function<void()>& work)
{
    std::vector<double> times;
    for (int r = 0; r < reps; ++r) {
        auto start = std::chrono::steady_clock::now();
        work();
        times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
}

} // namespace

int main(int argc, char** argv)
{
    const int max_links = argc > 1 ? std::atoi(argv[1]) : 7;
    const int reps = argc > 2 ? std::atoi(argv[2]) : 3;
    std::printf("%4s %12s %14s %10s\n", "N", "det_s", "charpoly_s", "det_terms");
    for (int links = 2; links <= max_links; ++links) {
        std::string text = lagrange_test::chain_scene(links) + "equilibrium ";
        for (int i = 1; i <= links; ++i)
            text += (i > 1 ? ", q" : "q") + std::to_string(i) + " = 0";
        lagrange::model scene = lagrange::load_model(lagrange::source_text("chain.lag", text + "\n"));
        lagrange::analysis a = lagrange::analyze(scene, {lagrange::product::linearization});
        const GiNaC::matrix& kinetic = a.linearization->kinetic;
        const GiNaC::matrix& potential = a.linearization->potential;
        GiNaC::symbol w("W");
        GiNaC::matrix pencil(links, links);
        for (int i = 0; i < links; ++i)
            for (int j = 0; j < links; ++j)
                pencil(i, j) = potential(i, j) - w * kinetic(i, j);
        std::size_t terms = 0;
        const double det = median_seconds(reps, [&] {
            GiNaC::ex d = lagrange::expansion_determinant(pencil);
            terms = GiNaC::is_a<GiNaC::add>(d) ? d.nops() : 1;
        });
        const double charpoly = median_seconds(reps, [&] {
            lagrange::characteristic_result c = lagrange::characteristic_polynomial(scene, *a.linearization);
            if (!c.factored)
                std::abort();
        });
        std::printf("%4d %12.4f %14.4f %10zu\n", links, det, charpoly, terms);
        std::fflush(stdout);
    }
    // the closed-form ω² of the 3-link chain: the roots of its cubic, without mode vectors
    std::string text = lagrange_test::chain_scene(3) + "equilibrium q1 = 0, q2 = 0, q3 = 0\n";
    lagrange::model scene = lagrange::load_model(lagrange::source_text("chain.lag", text));
    lagrange::analysis a = lagrange::analyze(scene, {lagrange::product::characteristic});
    const double cubic = median_seconds(reps, [&] {
        lagrange::modes_result m = lagrange::symbolic_modes(scene, *a.linearization, *a.characteristic, false);
        if (!m.closed_form)
            std::abort();
    });
    std::printf("closed-form frequencies of the 3-link chain (a cubic in W): %.4f s\n", cubic);
}
