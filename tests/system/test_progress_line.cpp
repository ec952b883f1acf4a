// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_progress_line.cpp
 *  The progress line (system/progress_line.h): what it writes, when, and how it clears. */
#include "system/progress_line.h"

#include <catch2/catch.hpp>

#include <sstream>

TEST_CASE("progress line: a bar with its percentage, rewritten in place and cleared", "[progress]")
{
    std::ostringstream out;
    lagrange::progress_line line(out, true, 0);
    line.show("simulating with dop853", 0.5);
    const std::string shown = "lagrange: simulating with dop853 [##########          ] 50%";
    CHECK(out.str() == "\r" + shown);
    line.show("simulating with dop853", 0.6); // within a tenth of a second: not redrawn
    CHECK(out.str() == "\r" + shown);
    line.clear();
    CHECK(out.str() == "\r" + shown + "\r" + std::string(shown.size(), ' ') + "\r");
    line.clear(); // nothing shown: nothing written
    CHECK(out.str() == "\r" + shown + "\r" + std::string(shown.size(), ' ') + "\r");
}

TEST_CASE("progress line: a shorter line blanks the rest of a longer one", "[progress]")
{
    std::ostringstream out;
    lagrange::progress_line line(out, true, 0);
    line.show("the `characteristic` stage", -1);
    const std::string first = "lagrange: the `characteristic` stage, 0 s";
    CHECK(out.str() == "\r" + first);
    line.show("x", -1); // another step: drawn at once, over the first
    const std::string second = "lagrange: x, 0 s";
    CHECK(out.str() == "\r" + first + "\r" + second + std::string(first.size() - second.size(), ' '));
    line.show("", 0); // an empty step clears
    CHECK(out.str().substr(out.str().size() - first.size() - 2) == "\r" + std::string(first.size(), ' ') + "\r");
}

TEST_CASE("progress line: at most 79 columns, cut between code points", "[progress]")
{
    std::ostringstream out;
    lagrange::progress_line line(out, true, 0);
    std::string long_step;
    for (int k = 0; k < 40; ++k)
        long_step += "θ";
    line.show(long_step + long_step, 0.25);
    const std::string text = out.str().substr(1);
    std::size_t code_points = 0;
    for (unsigned char c : text)
        code_points += (c & 0xC0) != 0x80 ? 1 : 0;
    CHECK(code_points == 79);
    CHECK(text.rfind("lagrange: θθ", 0) == 0);
    CHECK((static_cast<unsigned char>(text.back()) & 0xC0) == 0x80); // ends on a whole θ
    CHECK(text.substr(text.size() - 2) == "θ");
}

TEST_CASE("progress line: nothing when not enabled or before its delay", "[progress]")
{
    std::ostringstream off;
    lagrange::progress_line disabled(off, false, 0);
    disabled.show("simulating", 0.5);
    disabled.clear();
    CHECK(off.str().empty());
    CHECK(!disabled.callback());

    std::ostringstream later;
    lagrange::progress_line delayed(later, true, 3600);
    delayed.callback()("simulating", 0.5);
    delayed.clear();
    CHECK(later.str().empty());
}
