// SPDX-License-Identifier: GPL-2.0-or-later
/** @file tools.cpp
 *  Whether a test's external tool is installed. */
#include "helpers/tools.h"

#include "system/external.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <stdexcept>

#include <unistd.h>

namespace lagrange_test {

std::string configured_compiler()
{
    const char* chosen = std::getenv("LAGRANGE_CC");
    return chosen && *chosen ? chosen : "cc";
}

bool tool_available(const std::string& tool)
{
    if (std::find(std::begin(known_tools), std::end(known_tools), tool) == std::end(known_tools))
        throw std::invalid_argument("unknown tool `" + tool + "`");
    if (tool == "root")
        return geteuid() == 0;
    if (tool == "octave")
        return lagrange::program_available("octave-cli");
    if (tool == "scipy") // Debian's python3-scipy, for the interpreter the Python tests use
        return access("/usr/bin/python3", X_OK) == 0 &&
               std::system("/usr/bin/python3 -c 'import scipy.integrate' >/dev/null 2>&1") == 0;
    if (tool == "python_sympy") // Debian's python3-sympy, as the scipy tests use it
        return access("/usr/bin/python3", X_OK) == 0 &&
               std::system("/usr/bin/python3 -c 'import sympy.physics.mechanics' >/dev/null 2>&1") == 0;
    const std::string program = tool == "cc" ? configured_compiler() : tool;
    if (program.find('/') != std::string::npos)
        return access(program.c_str(), X_OK) == 0;
    return lagrange::program_available(program);
}

compiler_override::compiler_override(const std::string& compiler)
{
    if (const char* old = std::getenv("LAGRANGE_CC"))
        old_ = old;
    setenv("LAGRANGE_CC", compiler.c_str(), 1);
}

compiler_override::~compiler_override()
{
    if (old_)
        setenv("LAGRANGE_CC", old_->c_str(), 1);
    else
        unsetenv("LAGRANGE_CC");
}

std::string run_shell(const std::string& command)
{
    std::string out;
    FILE* pipe = popen(command.c_str(), "r");
    REQUIRE(pipe);
    char buffer[4096];
    for (std::size_t n; (n = fread(buffer, 1, sizeof buffer, pipe)) > 0;)
        out.append(buffer, n);
    CHECK(pclose(pipe) == 0);
    return out;
}

bool cpu_has_avx2_and_fma()
{
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#else
    return false;
#endif
}

} // namespace lagrange_test
