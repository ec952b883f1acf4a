// SPDX-License-Identifier: GPL-2.0-or-later
/** @file pictures.cpp
 *  The stages behind `animate` and `poincare` (see pictures.h). */
#include "engine/pictures.h"

#include "engine/analysis.h"
#include "numeric/free_body_motion.h"

namespace lagrange {

animation_frames animate_scene(const model& scene, const animation_settings& settings, const budget_limits& limits)
{
    if (has_free_body(scene)) {
        const analysis result = analyze(scene, {product::euler}, limits);
        for (const euler_result& body : *result.euler)
            if (body.torque_free && body.poinsot)
                return compute_body_animation(scene, body, settings);
        throw computation_error("the free body cannot be animated: Poinsot's construction needs a torque-free body "
                                "with numbers for its moments (`values`) and a nonzero initial ω (`initial`)");
    }
    const analysis result = analyze(scene, {product::equations}, limits);
    return compute_animation(scene, *result.equations, settings);
}

std::optional<phase_portrait> report_phase_portrait(const model& scene, const analysis& result)
{
    if (scene.coordinates.size() != 1 || !result.equations)
        return std::nullopt;
    try {
        return compute_phase_portrait(scene, *result.equations, result.equilibria ? &*result.equilibria : nullptr,
                                      phase_settings{});
    } catch (const computation_error&) { // no conserved energy, or a parameter without a value: no picture
        return std::nullopt;
    }
}

poincare_result poincare_scene(const model& scene, const poincare_section& section, const poincare_settings& settings,
                               const budget_limits& limits)
{
    analysis result;
    try {
        result = analyze(scene, {product::equations, product::equilibrium}, limits);
    } catch (const computation_error&) {
        result = analyze(scene, {product::equations}, limits);
    }
    return compute_poincare(scene, *result.equations, result.equilibria ? &*result.equilibria : nullptr, section,
                            settings);
}

} // namespace lagrange
