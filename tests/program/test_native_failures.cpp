// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_native_failures.cpp
 *  Why native code was not compiled, told apart (program/native_code.h): no compiler (named,
 *  LAGRANGE_CC included), a compile error with the compiler's first lines, a load error with
 *  dlerror's text, a missing, full or unsafe TMPDIR; and the interpreter runs on. Every test
 *  restores the environment it changes. */
#include "helpers/cli_runner.h"
#include "program/expression_program.h"
#include "program/native_code.h"
#include "system/external.h"
#include "helpers/tools.h"

#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace {

/// Saves the named environment variables and puts them back (set or unset) when it goes.
class environment_guard {
public:
    environment_guard(std::initializer_list<const char*> names)
    {
        for (const char* name : names) {
            const char* value = std::getenv(name);
            saved_.emplace_back(name, value ? std::optional<std::string>(value) : std::nullopt);
        }
    }
    ~environment_guard()
    {
        for (const auto& [name, value] : saved_) {
            if (value)
                setenv(name.c_str(), value->c_str(), 1);
            else
                unsetenv(name.c_str());
        }
    }
    environment_guard(const environment_guard&) = delete;
    environment_guard& operator=(const environment_guard&) = delete;

private:
    std::vector<std::pair<std::string, std::optional<std::string>>> saved_;
};

/// Why compiling a small program with LAGRANGE_CC = `compiler` fails ("" if it does not),
/// with the cache off, so that every attempt runs the compiler.
std::string failure_with(const std::string& compiler)
{
    environment_guard guard({"LAGRANGE_CC", "LAGRANGE_CACHE"});
    setenv("LAGRANGE_CC", compiler.c_str(), 1);
    setenv("LAGRANGE_CACHE", "0", 1);
    GiNaC::symbol x("x"), y("y");
    lagrange::expression_program program({GiNaC::sin(x) * y, x * x - y}, {x, y});
    std::string why;
    std::shared_ptr<lagrange::native_module> module = lagrange::native_module::compile({&program}, {}, &why);
    return module ? "" : why;
}

/// An executable script `name` with `body` in `folder`; its path.
std::string script(const lagrange::private_directory& folder, const std::string& name, const std::string& body)
{
    folder.write(name, "#!/bin/sh\n" + body);
    std::filesystem::permissions(folder.path() + "/" + name, std::filesystem::perms::owner_all);
    return folder.path() + "/" + name;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

/// The shell lines that find the output file (after -o) among a compiler's arguments.
const std::string find_output = "out=\nwhile [ $# -gt 0 ]; do [ \"$1\" = -o ] && out=$2; shift; done\n";

} // namespace

TEST_CASE("native failures: a compiler that cannot be started is named, LAGRANGE_CC included", "[native][native_failures]")
{
    setenv("LAGRANGE_CC", "outer value", 1);
    {
        std::string why = failure_with("/nonexistent/lagrange-cc");
        INFO(why);
        CHECK(contains(why, "no C compiler"));
        CHECK(contains(why, "`/nonexistent/lagrange-cc` (LAGRANGE_CC)"));
        CHECK(contains(why, "No such file or directory"));
        why = failure_with("lagrange-no-such-compiler"); // looked up in PATH
        INFO(why);
        CHECK(contains(why, "no C compiler"));
        CHECK(contains(why, "`lagrange-no-such-compiler`"));
    }
    // The environment is as it was.
    REQUIRE(std::getenv("LAGRANGE_CC"));
    CHECK(std::string(std::getenv("LAGRANGE_CC")) == "outer value");
    CHECK(!std::getenv("LAGRANGE_CACHE"));
    unsetenv("LAGRANGE_CC");
}

TEST_CASE("native failures: a compile error says so, with the compiler's first lines", "[native][native_failures]")
{
    lagrange::private_directory folder("lagrange-test");
    const std::string silent = failure_with("false");
    INFO(silent);
    CHECK(contains(silent, "compile error: `false` (LAGRANGE_CC) exited with status 1"));
    CHECK(!contains(silent, "no C compiler"));

    const std::string cc = script(folder, "cc", "echo 'programs.c:3:7: error: pretend failure' >&2\n"
                                                "echo 'second line'\necho 'third line'\necho 'fourth line'\nexit 1\n");
    const std::string why = failure_with(cc);
    INFO(why);
    CHECK(contains(why, "compile error"));
    CHECK(contains(why, "exited with status 1"));
    CHECK(contains(why, "programs.c:3:7: error: pretend failure; second line; third line"));
    CHECK(!contains(why, "fourth line")); // the first few lines only
    CHECK(!contains(why, "no C compiler"));
    CHECK(!contains(why, "\n"));          // one line, for `evaluation:`

    // A compiler that runs out of room in the temporary folder: said so.
    const std::string full = script(folder, "full-cc", "echo 'programs.c: fatal error: No space left on device'\nexit 1\n");
    const std::string no_room = failure_with(full);
    INFO(no_room);
    CHECK(contains(no_room, "is full"));
    CHECK(contains(no_room, "No space left on device"));
}

TEST_CASE("native failures: a library that does not load gives dlerror's text", "[native][native_failures][cc]")
{
    lagrange::private_directory folder("lagrange-test");
    const std::string garbage = script(folder, "garbage-cc", find_output + "echo 'not a library' > \"$out\"\n");
    std::string why = failure_with(garbage);
    INFO(why);
    CHECK(contains(why, "the compiled equations could not be loaded: "));
    CHECK(contains(why, "programs")); // dlerror names the file
    CHECK(!contains(why, "no C compiler"));
    // A real library, but without the programs.
    folder.write("empty.c", "int lagrange_nothing;\n");
    const std::string empty =
        script(folder, "empty-cc", find_output + "exec " + lagrange_test::configured_compiler() +
                                       " -shared -fPIC -o \"$out\" '" + folder.path() + "/empty.c'\n");
    why = failure_with(empty);
    INFO(why);
    CHECK(contains(why, "could not be loaded"));
    CHECK(contains(why, "lagrange_programs"));
}

TEST_CASE("native failures: a missing or unsafe TMPDIR is told, not a missing compiler",
          "[native][native_failures][cc]")
{
    environment_guard guard({"TMPDIR"});
    lagrange::private_directory folder("lagrange-test");
    setenv("TMPDIR", (folder.path() + "/missing").c_str(), 1);
    std::string why = failure_with("cc");
    INFO(why);
    CHECK(contains(why, "the temporary folder " + folder.path() + "/missing (TMPDIR) does not exist"));

    folder.write("file", "");
    setenv("TMPDIR", (folder.path() + "/file").c_str(), 1);
    why = failure_with("cc");
    INFO(why);
    CHECK(contains(why, "(TMPDIR) is not a folder"));

    // Writable by others without the sticky bit: another user could swap the private folder.
    const std::string open = folder.path() + "/open";
    REQUIRE(mkdir(open.c_str(), 0700) == 0);
    REQUIRE(chmod(open.c_str(), 0777) == 0);
    setenv("TMPDIR", open.c_str(), 1);
    why = failure_with("cc");
    INFO(why);
    CHECK(contains(why, "(TMPDIR) is not safe for compiled code: " + open + " is writable by others"));
    CHECK(!contains(why, "no C compiler"));
    CHECK(std::filesystem::is_empty(open)); // the private folder made there went again

    // With the sticky bit (as /tmp) it is used.
    REQUIRE(chmod(open.c_str(), 01777) == 0);
    why = failure_with(lagrange_test::configured_compiler());
    CHECK(why.empty());
}

TEST_CASE("native failures: the simulation runs on in the interpreter and says why", "[native][native_failures][cli]")
{
    environment_guard guard({"LAGRANGE_CC", "LAGRANGE_CACHE"});
    setenv("LAGRANGE_CC", "false", 1);
    setenv("LAGRANGE_CACHE", "0", 1);
    const std::string scene = std::string(LAGRANGE_SOURCE_DIR) + "/examples/double_pendulum.lag";
    lagrange_test::cli_result r = lagrange_test::run_cli("simulate " + scene + " --until 0.5", "", 60);
    CHECK(r.exit_code == 0);
    CHECK(contains(r.out, "evaluation: interpreted: compile error: `false` (LAGRANGE_CC) exited with status 1"));
}
