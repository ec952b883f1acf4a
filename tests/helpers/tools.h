// SPDX-License-Identifier: GPL-2.0-or-later
/** @file tools.h
 *  The external tools some tests need (a C compiler, gnuplot, pdflatex, ffmpeg, Chromium). A
 *  test case that needs one is tagged with the tool's name ([cc], [gnuplot], [pdflatex],
 *  [ffmpeg], [chromium]); ctest runs those cases as a test of their own, `tests_FOLDER
 *  --requires TOOL "[TOOL]"`, which the runner (main.cpp) reports as skipped (exit 77) when
 *  the tool is absent. A tool that is present
 *  but fails makes its tests fail, with the tool's message. */
#pragma once

#include <optional>
#include <string>

namespace lagrange_test {

/// The tools a test can require, by tag name.
inline constexpr const char* known_tools[] = {"cc",     "gnuplot", "pdflatex", "root",    "octave",
                                              "scipy",  "ffmpeg",  "chromium", "python_sympy"};

/// Whether `tool` is installed: for "cc" the compiler the engine uses ($LAGRANGE_CC, else
/// `cc`), for "root" whether the tests run as root (owners and device nodes), for "octave"
/// octave-cli, for "scipy" whether /usr/bin/python3 imports scipy.integrate, for "python_sympy"
/// whether it imports sympy.physics.mechanics, for the others
/// the program of that name on $PATH. Throws std::invalid_argument
/// for a name that is not in known_tools.
bool tool_available(const std::string& tool);

/// The C compiler the engine uses: $LAGRANGE_CC, else `cc`.
std::string configured_compiler();

/// Sets $LAGRANGE_CC for its lifetime (a compiler wrapped by a test), then restores it, so
/// that later tests use the compiler the run was given.
class compiler_override {
public:
    explicit compiler_override(const std::string& compiler);
    ~compiler_override();
    compiler_override(const compiler_override&) = delete;
    compiler_override& operator=(const compiler_override&) = delete;

private:
    std::optional<std::string> old_;
};

/// The standard output of `command`, run by the shell; the test fails when it exits non-zero.
std::string run_shell(const std::string& command);

/// Whether this CPU has AVX2 and FMA (then the engine's native code uses SLEEF).
bool cpu_has_avx2_and_fma();

} // namespace lagrange_test
