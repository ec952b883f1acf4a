// SPDX-License-Identifier: GPL-2.0-or-later
/** @file cli_runner.h
 *  Runs the `lagrange` program built alongside the tests and captures what it prints;
 *  the files the CLI, example and report tests share. */
#pragma once

#include <string>
#include <vector>

namespace lagrange_test {

struct cli_result {
    int exit_code = -1;   ///< 124 if the run hit the time limit
    std::string out;
    std::string err;
    double seconds = 0;
};

/// Runs `lagrange ARGS` (ARGS is passed through the shell) with `input` on standard
/// input, stopped after `limit_seconds`; `shell_setup` (a command such as `ulimit -v N`)
/// runs before it in the same shell.
cli_result run_cli(const std::string& args, const std::string& input = "", int limit_seconds = 10,
                   const std::string& shell_setup = "");

/// How many times slower this build runs than a plain Release one: LAGRANGE_TEST_TIME_SCALE
/// (scripts/sanitize.sh sets it), 1 when unset. Bounds on a run's time are multiplied by it.
double time_scale();

/// Writes `content` to a fresh file in the test's temporary folder and returns its path.
std::string temporary_file(const std::string& name, const std::string& content);

std::string read_file(const std::string& path);

/// The scenes in examples/, as paths, sorted.
std::vector<std::string> example_scenes();

/// Compiles `tex` (a path) with pdflatex in its folder; returns pdflatex's log.
std::string compile_latex(const std::string& tex, int& status);

} // namespace lagrange_test
