/** @file analysis.h
 *  The stage planner: walks back from the wanted products, runs each needed
 *  stage once, in order, and records its time. Stages that are not needed do not run. */
#pragma once

#include "mechanics/lagrangian.h"
#include "scene/model.h"

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace lagrange {

struct stage_time {
    std::string stage;
    double seconds;
};

/// Everything the stages computed for one scene.
struct analysis {
    const model* scene = nullptr;
    std::set<product> wanted;            ///< what was asked for (resolved)
    std::vector<stage_time> stages;      ///< the stages that ran, in order, with their times
    std::optional<lagrangian_result> lagrangian;
    std::optional<std::vector<GiNaC::ex>> equations;
};

/// The products this version computes.
const std::set<product>& available_products();

/// Runs the stages that `wanted` needs (if empty: the scene's `want` line, or every
/// available product the scene supports). Throws computation_error for a product
/// this version does not compute, or when a stage cannot be done.
analysis analyze(const model& scene, const std::set<product>& wanted = {});

} // namespace lagrange
