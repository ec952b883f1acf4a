/** @file scene_helpers.h
 *  Helpers shared by the tests: load a scene from text, expect an error at a position,
 *  a chain of pendulums, find a scene's symbol by name. */
#pragma once

#include "scene/lower.h"

#include <catch2/catch.hpp>

#include <string>

namespace lagrange_test {

inline lagrange::model load(const std::string& text)
{
    return lagrange::load_model(lagrange::source_text("test.lag", text));
}

/// Loads `text`, expecting a scene_error at line:column whose message contains `fragment`.
inline void require_error(const std::string& text, int line, int column, const std::string& fragment)
{
    INFO("scene:\n" << text);
    try {
        load(text);
        FAIL("no error");
    } catch (const lagrange::scene_error& e) {
        INFO("message: " << e.what());
        CHECK(e.where().file == "test.lag");
        CHECK(e.where().line == line);
        CHECK(e.where().column == column);
        CHECK(std::string(e.what()).find(fragment) != std::string::npos);
        CHECK(e.has_line_text());
    }
}

const std::string header = "parameters m g l\ncoordinates q\n";

/// A planar chain of `links` point masses on rods under gravity: parameters g, m1 l1 … (no values).
inline std::string chain_scene(int links)
{
    std::string parameters = "parameters g", coordinates = "coordinates", points, x, y;
    for (int k = 1; k <= links; ++k) {
        const std::string i = std::to_string(k);
        parameters += " m" + i + " l" + i;
        coordinates += " q" + i;
        x += (k > 1 ? " + " : "") + ("l" + i + "*sin(q" + i + ")");
        y += " - l" + i + "*cos(q" + i + ")";
        points += "point P" + i + " mass m" + i + " at (" + x + "," + y + ")\n";
    }
    return parameters + "\n" + coordinates + "\n" + points + "gravity g along (0, -1)\n";
}

/// The symbol of a parameter, coordinate (`q`, `q_dot`, `q_ddot`), the ratio or time `t`.
inline GiNaC::ex symbol_of(const lagrange::model& scene, const std::string& name)
{
    for (const lagrange::parameter& p : scene.parameters)
        if (p.name == name)
            return p.symbol;
    for (const lagrange::coordinate& c : scene.coordinates) {
        if (c.name == name)
            return c.position;
        if (c.name + "_dot" == name)
            return c.velocity;
        if (c.name + "_ddot" == name)
            return c.acceleration;
    }
    if (scene.ratio && scene.ratio->name == name)
        return scene.ratio->symbol;
    if (name == "t")
        return scene.time;
    FAIL("no symbol " << name);
    return 0;
}

} // namespace lagrange_test
