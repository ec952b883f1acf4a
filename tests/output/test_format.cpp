// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_format.cpp
 *  printable: what a terminal would act on becomes `?`; everything else, UTF-8 included, stays. */
#include "output/format.h"

#include <catch2/catch.hpp>

#include <string>

using namespace lagrange;

TEST_CASE("printable: C0, DEL and C1 controls become ?, text and UTF-8 stay", "[format]")
{
    CHECK(printable("plain `text`, θ and ω\nnext\tline") == "plain `text`, θ and ω\nnext\tline");
    CHECK(printable("\x1b[31mred\x7f") == "?[31mred?");
    CHECK(printable("csi \xC2\x9B" "2J, nel \xC2\x85, nbsp \xC2\xA0") == "csi ?2J, nel ?, nbsp \xC2\xA0");
    CHECK(printable(std::string("nul\0end", 7)) == "nul?end");
}
