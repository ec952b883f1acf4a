// SPDX-License-Identifier: GPL-2.0-or-later
/** @file main.cpp
 *  The Catch2 test runner of every test folder. Before Catch2's own options it takes
 *  `--requires TOOL` (repeatable): when a tool is absent the run prints why and exits 77,
 *  which ctest reports as skipped (see tools.h). */
#define CATCH_CONFIG_RUNNER
#include "helpers/tools.h"

#include <catch2/catch.hpp>

#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

int main(int argc, char* argv[])
{
    std::vector<char*> rest{argv[0]};
    for (int k = 1; k < argc; ++k) {
        if (std::string(argv[k]) != "--requires") {
            rest.push_back(argv[k]);
            continue;
        }
        if (k + 1 >= argc) {
            std::cerr << "--requires needs a tool's name\n";
            return 2;
        }
        const std::string tool = argv[++k];
        try {
            if (!lagrange_test::tool_available(tool)) {
                std::cout << "skipped: " << (tool == "root" ? "not running as root" : "`" + tool + "` is not installed")
                          << "\n";
                return 77;
            }
        } catch (const std::invalid_argument& e) {
            std::cerr << e.what() << "\n";
            return 2;
        }
    }
    return Catch::Session().run(static_cast<int>(rest.size()), rest.data());
}
