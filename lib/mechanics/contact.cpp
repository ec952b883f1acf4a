// SPDX-License-Identifier: GPL-2.0-or-later
/** @file contact.cpp
 *  The ground's force on each rolling wheel (contact.h). */
#include "mechanics/contact.h"

#include "core/errors.h"

#include <cstddef>

namespace lagrange {

namespace {

/// The multiplier of the constraint named `name`.
const GiNaC::ex& multiplier_of(const model& scene, const multipliers_result& multipliers, const std::string& name)
{
    for (std::size_t k = 0; k < scene.constraints.size(); ++k)
        if (scene.constraints[k].name == name)
            return multipliers.constraints.at(k).multiplier;
    throw computation_error("the constraint `" + name + "` of a `rolls` line is missing");
}

} // namespace

contact_result derive_contact_forces(const model& scene, const multipliers_result& multipliers,
                                     const simplifier& simplify)
{
    if (scene.contacts.empty())
        throw computation_error("`contact` needs a wheel rolling on the ground (`rolls W on ground`)");
    contact_result result;
    for (const rolling_contact& wheel : scene.contacts) {
        if (wheel.normal_by_construction)
            throw computation_error(
                "`contact`: the height of " + wheel.body + " above the ground holds by its coordinates, so the "
                "normal force does no virtual work in them and is no multiplier; give the height a coordinate of "
                "its own (its centre `at (x, y, z)`), and `rolls` adds the constraint " + wheel.body + "_contact");
        contact_force entry;
        entry.body = wheel.body;
        for (const GiNaC::ex& p : wheel.point)
            entry.point.push_back(simplify_ratio(p, simplify).normal());
        for (unsigned i = 0; i < 3; ++i) {
            GiNaC::ex sum = 0;
            std::size_t terms = 0;
            for (std::size_t k = 0; k < wheel.constraints.size(); ++k) {
                const GiNaC::ex& along = wheel.directions[k][i];
                if (along.is_zero())
                    continue;
                sum += along * multiplier_of(scene, multipliers, wheel.constraints[k]);
                ++terms;
            }
            // one term is a multiplier as the multipliers stage simplified it, times a number
            entry.force.push_back(terms > 1 ? simplify_ratio(sum, simplify) : sum);
        }
        result.contacts.push_back(std::move(entry));
    }
    return result;
}

} // namespace lagrange
