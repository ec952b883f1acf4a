// SPDX-License-Identifier: GPL-2.0-or-later
/** @file cli_runner.cpp
 *  Runs the `lagrange` program for the command-line tests. */
#include "helpers/cli_runner.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace lagrange_test {

namespace {

std::string temporary_folder()
{
    static const std::string folder = [] {
        char pattern[] = "/tmp/lagrange-test-XXXXXX";
        const char* made = mkdtemp(pattern);
        return std::string(made ? made : "/tmp");
    }();
    return folder;
}

} // namespace

std::string read_file(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::vector<std::string> example_scenes()
{
    std::vector<std::string> scenes;
    for (const auto& entry : std::filesystem::directory_iterator(std::string(LAGRANGE_SOURCE_DIR) + "/examples"))
        if (entry.path().extension() == ".lag")
            scenes.push_back(entry.path().string());
    std::sort(scenes.begin(), scenes.end());
    return scenes;
}

std::string compile_latex(const std::string& tex, int& status)
{
    std::string directory = tex.substr(0, tex.rfind('/'));
    std::string name = tex.substr(tex.rfind('/') + 1);
    std::string command = "cd " + directory + " && pdflatex -interaction=nonstopmode -halt-on-error " + name +
                          " >/dev/null 2>&1";
    status = std::system(command.c_str());
    return read_file(tex.substr(0, tex.size() - 4) + ".log");
}

std::string temporary_file(const std::string& name, const std::string& content)
{
    std::string path = temporary_folder() + "/" + name;
    std::ofstream out(path, std::ios::binary);
    out << content;
    return path;
}

double time_scale()
{
    const char* scale = std::getenv("LAGRANGE_TEST_TIME_SCALE");
    return scale ? std::max(1, std::atoi(scale)) : 1;
}

cli_result run_cli(const std::string& args, const std::string& input, int limit_seconds, const std::string& shell_setup)
{
    static int counter = 0;
    std::string stem = temporary_folder() + "/run" + std::to_string(++counter);
    std::string in = temporary_file("run" + std::to_string(counter) + ".in", input);
    // Sanitizer builds run several times slower: scripts/sanitize.sh sets LAGRANGE_TEST_TIME_SCALE.
    limit_seconds *= static_cast<int>(time_scale());
    std::string command = (shell_setup.empty() ? "" : shell_setup + "; ") + "timeout -s KILL " +
                          std::to_string(limit_seconds) + " " + LAGRANGE_BINARY + " " + args + " <" + in + " >" +
                          stem + ".out 2>" + stem + ".err";
    auto start = std::chrono::steady_clock::now();
    int status = std::system(command.c_str());
    std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    cli_result result;
    result.seconds = elapsed.count();
    if (WIFEXITED(status))
        result.exit_code = WEXITSTATUS(status);
    else
        result.exit_code = 128 + WTERMSIG(status);
    result.out = read_file(stem + ".out");
    result.err = read_file(stem + ".err");
    return result;
}

} // namespace lagrange_test
