// SPDX-License-Identifier: GPL-2.0-or-later
/** @file settings.cpp
 *  An ensemble's settings (see settings.h). */
#include "ensemble/settings.h"

#include "numeric/values.h"

#include <cmath>

namespace lagrange {

ensemble_settings ensemble_settings_for(const model& scene, const ensemble_measure& measure,
                                        const ensemble_request& request)
{
    if (request.seed != 1 && request.random == 0)
        throw ensemble_request_error("--seed goes with --random N");
    ensemble_settings settings;
    if (request.until)
        settings.until = *request.until;
    else if (measure.what == ensemble_measure::kind::floquet_stable)
        settings.until = 1; // each run lasts one period of the drive
    else if (scene.simulation)
        settings.until = real_value(scene.simulation->until, "the scene's `simulate until`");
    else
        throw ensemble_request_error("give the end time of every run with --until T (the scene has no `simulate until`)");
    if (!(settings.until > 0) || !std::isfinite(settings.until))
        throw ensemble_request_error("the end time must be a positive number");
    if (request.tolerance)
        settings.tolerance = *request.tolerance;
    settings.random = request.random;
    settings.seed = request.seed;
    settings.native = request.native;
    return settings;
}

std::set<product> ensemble_products(const ensemble_measure& measure)
{
    std::set<product> wanted{product::equations};
    if (measure.what == ensemble_measure::kind::floquet_stable)
        wanted.insert(product::floquet);
    return wanted;
}

} // namespace lagrange
