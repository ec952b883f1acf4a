// SPDX-License-Identifier: GPL-2.0-or-later
/** @file settings.cpp
 *  An ensemble's settings (see settings.h). */
#include "ensemble/settings.h"

#include "numeric/simulation.h"

#include <cmath>

namespace lagrange {

ensemble_settings ensemble_settings_for(const model& scene, const ensemble_measure& measure,
                                        const ensemble_request& request)
{
    if (request.seed != 1 && request.random == 0)
        throw ensemble_request_error("--seed goes with --random N");
    simulation_settings asked; // the span is read as `simulate` reads it: one rule for both
    asked.until = request.until;
    asked.tolerance = request.tolerance;
    if (!asked.until && definition_of(measure.what).one_period)
        asked.until = 1; // each run lasts one period of the drive
    if (!asked.until && !scene.simulation)
        throw ensemble_request_error("give the end time of every run with --until T (the scene has no `simulate until`)");
    if (asked.until && !(*asked.until > 0 && std::isfinite(*asked.until)))
        throw ensemble_request_error("the end time must be a positive number");
    simulation_span span;
    try {
        span = simulation_span_of(scene, asked);
    } catch (const computation_error& error) {
        throw ensemble_request_error(error.what());
    }
    ensemble_settings settings;
    settings.until = span.until;
    settings.tolerance = span.tolerance;
    settings.random = request.random;
    settings.seed = request.seed;
    settings.native = request.native;
    return settings;
}

std::set<product> ensemble_products(const ensemble_measure& measure)
{
    std::set<product> wanted{product::equations};
    if (definition_of(measure.what).one_period)
        wanted.insert(product::floquet);
    return wanted;
}

} // namespace lagrange
