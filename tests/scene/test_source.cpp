// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_source.cpp
 *  Error messages: location, the offending line and a caret. */
#include "helpers/scene_helpers.h"
#include "scene/source.h"

#include <catch2/catch.hpp>

using namespace lagrange;
using namespace lagrange_test;

TEST_CASE("format_error: location, line and caret", "[source]")
{
    scene_error error({"s.lag", 2, 5}, "unknown name `w`");
    error.attach_line_text("T = w");
    CHECK(format_error(error) == "s.lag:2:5: error: unknown name `w`\nT = w\n    ^\n");
}

TEST_CASE("format_error: a 1 MB line is shown as a short window", "[source]")
{
    scene_error error({"s.lag", 1, 500000}, "bad");
    error.attach_line_text(std::string(1000000, 'a'));
    std::string text = format_error(error);
    CHECK(text.size() < 400);
    std::size_t second_line = text.find('\n') + 1;
    std::size_t third_line = text.find('\n', second_line) + 1;
    std::string shown = text.substr(second_line, third_line - second_line - 1);
    std::string caret = text.substr(third_line);
    CHECK(caret.back() == '\n');
    CHECK(caret.size() - 2 < shown.size());
}

TEST_CASE("format_error: a C1 control in the quoted line is shown as a space", "[source]")
{
    scene_error error({"s.lag", 1, 3}, "bad");
    error.attach_line_text("a\xC2\x9B" "b");
    CHECK(format_error(error) == "s.lag:1:3: error: bad\na b\n  ^\n");
}
