// SPDX-License-Identifier: GPL-2.0-or-later
/** @file scene_helpers.h
 *  Helpers shared by the tests: load a scene from text, expect an error at a position (in a
 *  scene or in a command-line option),
 *  a chain of pendulums, find a scene's symbol by name. */
#pragma once

#include "helpers/chain_scene.h"
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

/// Runs parse(), the parsing of `text` given to a command-line option, expecting a scene_error
/// located in the pseudo-file `option` at `column` whose message contains `fragment`.
template <class Parse>
void require_option_error(const std::string& option, const std::string& text, Parse&& parse, int column,
                          const std::string& fragment)
{
    INFO(option << " " << text);
    try {
        parse();
        FAIL("no error");
    } catch (const lagrange::scene_error& e) {
        INFO(e.what());
        CHECK(e.where().file == option);
        CHECK(e.where().column == column);
        CHECK(std::string(e.what()).find(fragment) != std::string::npos);
    }
}

const std::string header = "parameters m g l\ncoordinates q\n";

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
