// SPDX-License-Identifier: GPL-2.0-or-later
/** @file readiness.cpp
 *  What the numeric commands need (see readiness.h). */
#include "engine/readiness.h"

#include <set>

namespace lagrange {

namespace {

/// The parameters that `point` gives no value of, as "`m`, `k`".
std::string missing_parameters(const model& scene, const value_point* point)
{
    std::set<std::string> given;
    if (point)
        for (const auto& entry : point->values)
            given.insert(entry.first);
    std::string listed;
    for (const parameter& p : scene.parameters)
        if (!given.count(p.name))
            listed += (listed.empty() ? "`" : ", `") + p.name + "`";
    return listed;
}

} // namespace

std::vector<std::string> unmet_needs(const model& scene)
{
    std::vector<std::string> needs;
    const std::string numeric_commands = "simulate, workprecision and the numeric modes";
    if (scene.values.empty()) {
        const std::string missing = missing_parameters(scene, nullptr);
        if (!missing.empty())
            needs.push_back(numeric_commands + ": values of " + missing + " (a `values` line or --values)");
    } else {
        for (const value_point& point : scene.values) {
            const std::string missing = missing_parameters(scene, &point);
            if (!missing.empty())
                needs.push_back(numeric_commands + ": the `values` line at line " + std::to_string(point.where.line) +
                                " gives no value of " + missing);
        }
    }
    if (!scene.simulation)
        needs.push_back("simulate, workprecision and ensemble: an end time (a `simulate until T` line or --until)");
    return needs;
}

} // namespace lagrange
