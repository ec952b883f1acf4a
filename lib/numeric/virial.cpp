// SPDX-License-Identifier: GPL-2.0-or-later
/** @file virial.cpp
 *  Time averages of T and V along a simulated trajectory. */
#include "numeric/virial.h"

#include "core/errors.h"
#include "numeric/compiled_motion.h"
#include "program/expression_program.h"
#include "numeric/values.h"

#include <algorithm>
#include <cmath>

namespace lagrange {

namespace {

/// ∫ f dt over the samples by the trapezoid rule, with every `stride`-th sample.
double trapezoid(const std::vector<double>& t, const std::vector<double>& f, std::size_t stride)
{
    double sum = 0;
    std::size_t last = 0;
    for (std::size_t k = stride; k < t.size(); k += stride) {
        sum += 0.5 * (f[k] + f[last]) * (t[k] - t[last]);
        last = k;
    }
    return sum;
}

} // namespace

virial_result time_averages(const model& scene, const lagrangian_result& lagrangian, const simulation_result& motion)
{
    const trajectory& run = motion.run;
    const std::size_t n = scene.coordinates.size();
    if (motion.first_order || run.times.size() < 3 || run.states.size() != run.times.size())
        throw computation_error("`virial` needs a simulated trajectory of the coordinates with at least 3 output "
                                "times");
    virial_result result;
    result.from = run.times.front();
    result.to = run.times.back();
    const double span = result.to - result.from;
    if (!(span > 0))
        throw computation_error("`virial` needs a simulated span longer than zero");

    const expression_program energies({at_values(lagrangian.kinetic_built, scene, motion.values),
                                       at_values(lagrangian.potential_built, scene, motion.values)},
                                      state_symbols(scene));

    std::vector<double> kinetic(run.times.size()), potential(run.times.size()), in(2 * n + 1), out(2), scratch;
    for (std::size_t k = 0; k < run.times.size(); ++k) {
        if (run.states[k].size() < 2 * n)
            throw computation_error("`virial` needs the coordinates and velocities along the trajectory");
        std::copy(run.states[k].begin(), run.states[k].begin() + 2 * n, in.begin());
        in[2 * n] = run.times[k];
        energies.run(in.data(), scratch, out.data());
        kinetic[k] = out[0];
        potential[k] = out[1];
    }
    result.kinetic = trapezoid(run.times, kinetic, 1) / span;
    result.potential = trapezoid(run.times, potential, 1) / span;
    if (!std::isfinite(result.kinetic) || !std::isfinite(result.potential))
        throw computation_error("`virial`: T or V is not finite along the trajectory");
    // Richardson: the trapezoid rule errs by O(h²), so the full-step sum is off by about a
    // third of its difference from the half-sampled sum (when that covers the same span).
    if ((run.times.size() - 1) % 2 == 0)
        result.quadrature_error =
            std::max(std::abs(result.kinetic - trapezoid(run.times, kinetic, 2) / span),
                     std::abs(result.potential - trapezoid(run.times, potential, 2) / span)) / 3;
    else
        result.quadrature_error = NAN;
    return result;
}

} // namespace lagrange
