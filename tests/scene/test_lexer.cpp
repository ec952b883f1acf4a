// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_lexer.cpp
 *  The lexer: positions, byte-order mark, CRLF, continuation, and its error paths. */
#include "helpers/scene_helpers.h"
#include "scene/lexer.h"

#include <catch2/catch.hpp>

using namespace lagrange;
using namespace lagrange_test;

TEST_CASE("lexer: tokens carry line and column", "[lexer]")
{
    source_text source("a.lag", "parameters m\n  T = 1/2*m*q'^2 # comment\n");
    std::vector<token> tokens = tokenize(source);
    REQUIRE(tokens.size() >= 6);
    CHECK(tokens[0].text == "parameters");
    CHECK(tokens[0].where.line == 1);
    CHECK(tokens[0].where.column == 1);
    CHECK(tokens[2].kind == token_kind::newline);
    CHECK(tokens[3].text == "T");
    CHECK(tokens[3].where.line == 2);
    CHECK(tokens[3].where.column == 3);
    CHECK(tokens.back().kind == token_kind::end);
}

TEST_CASE("lexer: byte-order mark, CRLF and continuation", "[lexer]")
{
    model scene = load("\xEF\xBB\xBFparameters m \\\r\n  k\r\ncoordinates x\r\nT = 1/2*m*x'^2\r\nV = 1/2*k*x^2\r\n");
    REQUIRE(scene.parameters.size() == 2);
    CHECK(scene.parameters[1].name == "k");
    CHECK(scene.coordinates.size() == 1);
}

TEST_CASE("lexer: columns count code points in comments and strings", "[lexer]")
{
    require_error("scene \"θ-pendulum\" @\n", 1, 20, "unexpected character");
}

TEST_CASE("lexer: error paths", "[lexer]")
{
    require_error(header + "T = m*q'^2 @\n", 3, 12, "unexpected character `@`");
    require_error(header + "T = θ\n", 3, 5, "names are ASCII");
    require_error(header + "T = m\xFF\n", 3, 6, "invalid UTF-8");
    require_error(header + std::string("T = m\0", 6) + "\n", 3, 6, "control character");
    require_error(header + "# bad \xC3\x28 byte\n", 3, 7, "invalid UTF-8");
    // C1 controls (CSI U+009B, NEL U+0085) in a title, a comment and the code: refused as C0 ones.
    require_error("scene \"evil \xC2\x9B" "2J\"\n", 1, 13, "control character (U+009B) in a string");
    require_error(header + "# next \xC2\x85 line\n", 3, 8, "control character (U+0085) in a comment");
    require_error(header + "T = m\xC2\x9Bq\n", 3, 6, "unexpected control character (U+009B)");
    require_error("scene \"open\n", 1, 7, "unterminated string");
    require_error(header + "T = 2x\n", 3, 6, "a number cannot run into a name");
    require_error(header + "T = m \\ q\n", 3, 7, "continues a line only at its end");
    require_error(header + "T = " + std::string(2000, '1') + "\n", 3, 5, "number too long");
    require_error(header + "T = $0\n", 3, 5, "unexpected character `$`");
}
