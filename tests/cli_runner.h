/** @file cli_runner.h
 *  Runs the `lagrange` program built alongside the tests and captures what it prints. */
#pragma once

#include <string>

namespace lagrange_test {

struct cli_result {
    int exit_code = -1;   ///< 124 if the run hit the time limit
    std::string out;
    std::string err;
    double seconds = 0;
};

/// Runs `lagrange ARGS` (ARGS is passed through the shell) with `input` on standard
/// input, stopped after `limit_seconds`.
cli_result run_cli(const std::string& args, const std::string& input = "", int limit_seconds = 10);

/// Writes `content` to a fresh file in the test's temporary folder and returns its path.
std::string temporary_file(const std::string& name, const std::string& content);

std::string read_file(const std::string& path);

} // namespace lagrange_test
