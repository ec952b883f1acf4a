// SPDX-License-Identifier: GPL-2.0-or-later
/** @file slips.cpp
 *  Likely slips in a valid scene (see slips.h). */
#include "scene/slips.h"

#include "scene/lexer.h"

#include <string>
#include <vector>

namespace lagrange {

std::optional<scene_warning> kinetic_energy_slip(const model& scene, const source_location& kinetic_line)
{
    if (scene.coordinates.empty())
        return std::nullopt;
    std::vector<std::string> missing;
    std::string listed;
    for (const coordinate& c : scene.coordinates)
        if (!scene.kinetic_terms.has(c.velocity)) {
            listed += (missing.empty() ? "" : ", ") + quote(c.name);
            missing.push_back(c.name);
        }
    const coordinate& first = scene.coordinates.front();
    if (missing.size() == scene.coordinates.size())
        return scene_warning{kinetic_line,
                             "`T` has no velocities, so it is no kinetic energy: the velocity of " + quote(first.name) +
                                 " is written " + quote(first.name + "'"),
                             ""};
    if (!missing.empty() && scene.points.empty() && scene.bodies.empty())
        return scene_warning{kinetic_line,
                             "`T` has no velocity of " + listed +
                                 ", which then has no kinetic energy (a velocity is written with a prime, as " +
                                 quote(missing.front() + "'") + ")",
                             ""};
    return std::nullopt;
}

} // namespace lagrange
