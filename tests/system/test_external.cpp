// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_external.cpp
 *  Private temporary folders and running programs without a shell. */
#include "system/external.h"
#include "scene/source.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <sys/stat.h>

TEST_CASE("external: a private folder is mode 0700 and removed with its content", "[external]")
{
    std::string path;
    {
        lagrange::private_directory folder;
        path = folder.path();
        struct stat info {};
        REQUIRE(stat(path.c_str(), &info) == 0);
        CHECK((info.st_mode & 0777) == 0700);
        folder.write("a.txt", "hello");
        CHECK(folder.read("a.txt") == "hello");
        std::filesystem::create_directory(path + "/sub");
        folder.write("sub/b.txt", "x");
        CHECK_THROWS_AS(folder.read("missing"), lagrange::computation_error);
    }
    CHECK(!std::filesystem::exists(path));
}

TEST_CASE("external: programs run without a shell, with their exit code, output and environment", "[external]")
{
    lagrange::private_directory folder;
    CHECK(lagrange::program_available("sh"));
    CHECK(!lagrange::program_available("no-such-program-lagrange"));
    // Shell syntax in an argument is an argument, not a command.
    lagrange::program_result echo =
        lagrange::run_program({"echo", "a;b", "$(touch", "pwned)"}, folder.path(), "out.log");
    CHECK(echo.exit_code == 0);
    CHECK(folder.read("out.log") == "a;b $(touch pwned)\n");
    CHECK(!std::filesystem::exists(folder.path() + "/pwned"));
    CHECK(lagrange::run_program({"false"}, folder.path(), "f.log").exit_code == 1);
    CHECK(lagrange::run_program({"no-such-program-lagrange"}, folder.path(), "n.log").exit_code == -1);
    CHECK(lagrange::run_program({"true"}, folder.path() + "/no-such-folder", "t.log").exit_code == -1);
    lagrange::program_result env =
        lagrange::run_program({"sh", "-c", "echo $LAGRANGE_PROBE; pwd"}, folder.path(), "e.log", {"LAGRANGE_PROBE=42"});
    CHECK(env.exit_code == 0);
    CHECK(folder.read("e.log") == "42\n" + std::filesystem::canonical(folder.path()).string() + "\n");
    lagrange::program_result slow = lagrange::run_program({"sleep", "5"}, folder.path(), "s.log", {}, 1);
    CHECK(slow.timed_out);
    CHECK(slow.exit_code == -1);
}
