// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_cli_usability.cpp
 *  The command line's small things a user notices: --help lists the products, --plot
 *  draws a panel per coordinate, unwritable outputs fail alike, and progress shows on a
 *  terminal and never in piped output. */
#include "helpers/chain_scene.h"
#include "helpers/cli_runner.h"

#include "core/model.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cerrno>
#include <cstdlib>
#include <fcntl.h>
#include <pty.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <iterator>
#include <string>

using namespace lagrange_test;

namespace {

const std::string examples = std::string(LAGRANGE_SOURCE_DIR) + "/examples/";

std::size_t count(const std::string& text, const std::string& piece)
{
    std::size_t n = 0;
    for (std::size_t at = text.find(piece); at != std::string::npos; at = text.find(piece, at + piece.size()))
        ++n;
    return n;
}

struct terminal_run {
    int exit_code = -1;
    std::string terminal; ///< what the program wrote to its standard error, a terminal
};

/// Runs `lagrange ARGS` with standard error on a pseudo-terminal (standard output to
/// /dev/null) and the progress line's delay at 0.
terminal_run run_on_terminal(const std::string& args, int limit_seconds = 60)
{
    terminal_run result;
    int master = -1;
    const pid_t child = forkpty(&master, nullptr, nullptr, nullptr);
    REQUIRE(child >= 0);
    if (child == 0) {
        const int null = open("/dev/null", O_WRONLY);
        dup2(null, STDOUT_FILENO);
        setenv("LAGRANGE_PROGRESS_DELAY", "0", 1);
        const std::string command = "exec timeout --foreground -s KILL " + std::to_string(limit_seconds) + " " +
                                    LAGRANGE_BINARY + " " + args;
        execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    char buffer[4096];
    for (;;) {
        const ssize_t got = read(master, buffer, sizeof buffer);
        if (got > 0)
            result.terminal.append(buffer, static_cast<std::size_t>(got));
        else if (got < 0 && errno == EINTR)
            continue;
        else
            break; // EIO: the child closed the terminal
    }
    int status = 0;
    waitpid(child, &status, 0);
    close(master);
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

/// The terminal's last line as it stands at the end (each \r goes back to its start).
std::string last_line_shown(const std::string& terminal)
{
    std::string line;
    std::size_t column = 0;
    for (char c : terminal) {
        if (c == '\n') {
            line.clear();
            column = 0;
        } else if (c == '\r') {
            column = 0;
        } else {
            if (column < line.size())
                line[column] = c;
            else
                line += c;
            ++column;
        }
    }
    return line;
}

} // namespace

TEST_CASE("cli: --help lists every product and shows an example", "[cli][help]")
{
    for (const std::string& command : {std::string("--help"), std::string("report --help")}) {
        cli_result help = run_cli(command);
        REQUIRE(help.exit_code == 0);
        for (const auto& [product, name] : lagrange::product_names())
            CHECK(help.out.find(" " + name) != std::string::npos);
        CHECK(help.out.find("Example:\n  lagrange examples/double_pendulum.lag --want") != std::string::npos);
    }
    // The example runs as shown.
    cli_result example = run_cli(examples + "double_pendulum.lag --want equations,frequencies");
    CHECK(example.exit_code == 0);
    CHECK(example.out.find("Normal modes\n  ω² = ") != std::string::npos);
}

TEST_CASE("cli: --plot draws one panel per coordinate", "[cli][plot][gnuplot]")
{
    const std::string svg = temporary_file("panels.svg", "");
    cli_result r = run_cli("simulate " + examples + "double_pendulum.lag --until 5 --plot " + svg, "", 60);
    REQUIRE(r.exit_code == 0);
    const std::string plot = read_file(svg);
    REQUIRE(plot.find("<svg") != std::string::npos);
    // Two panels (gnuplot names a multiplot's panels 1a, 1b, …), each one line with the
    // coordinate as its y label (θ, φ) and no key, and t below the last.
    CHECK(count(plot, "<g id=\"gnuplot_plot_") == 2);
    CHECK(count(plot, "<g id=\"gnuplot_plot_1a\"") == 1);
    CHECK(count(plot, "<g id=\"gnuplot_plot_1b\"") == 1);
    CHECK(count(plot, "<text>θ</text>") == 1);
    CHECK(count(plot, "<text>φ</text>") == 1);
    CHECK(plot.find("<text>φ</text>") < plot.find("<text>t</text>"));
}

TEST_CASE("cli: --plot draws SVG, PNG or PDF as the extension says, and refuses another", "[cli][plot][gnuplot]")
{
    const std::string scene = examples + "double_pendulum.lag";
    const std::string response = examples + "damped_driven_oscillator.lag --input u --output x";
    struct expected_format {
        const char* extension;
        std::string magic; // the file's first bytes
    };
    for (const expected_format& f : {expected_format{"svg", "<?xml"}, expected_format{"png", "\x89PNG\r\n\x1a\n"},
                                     expected_format{"PNG", "\x89PNG\r\n\x1a\n"}, expected_format{"pdf", "%PDF-"}}) {
        for (const std::string& command : {"simulate " + scene + " --until 2", "workprecision " + scene + " --until 0.5",
                                           "response " + response}) {
            const std::string path = temporary_file(std::string("formats.") + f.extension, "");
            INFO(command << " --plot " << path);
            cli_result r = run_cli(command + " --plot " + path, "", 60);
            INFO(r.err);
            REQUIRE(r.exit_code == 0);
            CHECK(read_file(path).compare(0, f.magic.size(), f.magic) == 0);
        }
    }
    // A PDF is the same bytes from run to run (no creation date).
    const std::string first = temporary_file("first.pdf", ""), second = temporary_file("second.pdf", "");
    REQUIRE(run_cli("simulate " + scene + " --until 2 --plot " + first, "", 60).exit_code == 0);
    REQUIRE(run_cli("simulate " + scene + " --until 2 --plot " + second, "", 60).exit_code == 0);
    CHECK(read_file(first) == read_file(second));
    // Another extension: exit 2 before any work, with the formats named, and nothing written.
    for (const std::string& command : {"simulate " + scene + " --until 2", "response " + response}) {
        const std::string path = temporary_file("refused.txt", "old\n");
        cli_result r = run_cli(command + " --plot " + path, "", 60);
        CHECK(r.exit_code == 2);
        CHECK(r.err.find(".svg, .png or .pdf") != std::string::npos);
        CHECK(r.out.empty());
        CHECK(read_file(path) == "old\n");
    }
}

TEST_CASE("cli: a plot's title keeps the scene's quotes and backslashes", "[cli][plot][gnuplot]")
{
    std::string scene = read_file(examples + "damped_driven_oscillator.lag");
    const std::string old_title = "scene \"Damped driven oscillator\"";
    REQUIRE(scene.find(old_title) != std::string::npos);
    scene.replace(scene.find(old_title), old_title.size(), "scene \"Kepler's \\ oscillator\"");
    const std::string svg = temporary_file("quoted.svg", "");
    cli_result r = run_cli("response - --input u --output x --plot " + svg, scene, 60);
    REQUIRE(r.exit_code == 0);
    const std::string plot = read_file(svg);
    INFO(r.err);
    REQUIRE(plot.find("<svg") != std::string::npos);
    CHECK(plot.find("<text>Kepler's \\ oscillator: Bode diagram of u → x</text>") != std::string::npos);
}

TEST_CASE("cli: an unwritable -o, --plot or --csv exits alike, with 2 and the path", "[cli][io]")
{
    const std::string scene = examples + "beats.lag";
    const std::string response = examples + "damped_driven_oscillator.lag --input u --output x";
    for (const std::string& folder : {std::string("/no/such/folder"), std::string("/proc")}) {
        const std::string path = folder + "/out.svg"; // an extension --plot takes
        for (const std::string& args :
             {"simulate " + scene + " --until 1 -o " + path, "simulate " + scene + " --until 1 --plot " + path,
              "simulate " + scene + " --until 1 --csv " + path, "workprecision " + scene + " --until 0.5 --plot " + path,
              "response " + response + " -o " + path, "response " + response + " --plot " + path,
              scene + " --want equations -o " + path, "report " + scene + " --want equations -o " + path + ".tex"}) {
            INFO(args);
            cli_result r = run_cli(args, "", 60);
            CHECK(r.exit_code == 2);
            CHECK(r.err.rfind("lagrange: error: cannot write `" + path, 0) == 0);
        }
    }
}

TEST_CASE("cli: progress shows on a terminal during the runs and stages, and never in a pipe", "[cli][progress]")
{
    SECTION("simulate: the run and the error estimate's reference run")
    {
        terminal_run r = run_on_terminal("simulate " + examples + "double_pendulum.lag --until 20");
        CHECK(r.exit_code == 0);
        CHECK(r.terminal.find("\rlagrange: simulating with dop853 [") != std::string::npos);
        CHECK(r.terminal.find("\rlagrange: error estimate: dop853 at tolerance ") != std::string::npos);
        CHECK(last_line_shown(r.terminal).find_first_not_of(' ') == std::string::npos); // cleared
    }
    SECTION("workprecision: each method at each tolerance")
    {
        terminal_run r = run_on_terminal("workprecision " + examples + "double_pendulum.lag --until 2");
        CHECK(r.exit_code == 0);
        CHECK(r.terminal.find("\rlagrange: workprecision: dopri5 at tolerance 0.001 [") != std::string::npos);
        CHECK(r.terminal.find("\rlagrange: workprecision: dop853 at tolerance ") != std::string::npos);
        CHECK(last_line_shown(r.terminal).find_first_not_of(' ') == std::string::npos);
    }
    SECTION("a symbolic stage, with its seconds")
    {
        // A modes stage of about 60 ms in Release: the watchdog, which polls every 20 ms, sees it.
        terminal_run r = run_on_terminal(std::string(LAGRANGE_SOURCE_DIR) +
                                         "/tests/fuzz_regressions/slow_modes_factor_after_factor.lag --want modes");
        CHECK(r.exit_code == 0);
        CHECK(r.terminal.find("\rlagrange: the `") != std::string::npos);
        CHECK(r.terminal.find("` stage, 0 s") != std::string::npos);
        CHECK(last_line_shown(r.terminal).find_first_not_of(' ') == std::string::npos);
    }
    SECTION("piped: nothing but the output")
    {
        setenv("LAGRANGE_PROGRESS_DELAY", "0", 1);
        for (const std::string& args :
             {"simulate " + examples + "double_pendulum.lag --until 20",
              "workprecision " + examples + "double_pendulum.lag --until 2", examples + "double_pendulum.lag --want modes"}) {
            cli_result r = run_cli(args, "", 60);
            CHECK(r.exit_code == 0);
            CHECK(r.err.empty());
            CHECK(r.out.find('\r') == std::string::npos);
        }
        unsetenv("LAGRANGE_PROGRESS_DELAY");
    }
}

TEST_CASE("cli: --initial sets the initial values as an initial line does, errors located", "[cli][initial]")
{
    const std::string scene = examples + "double_pendulum.lag"; // initial theta = 0, phi = 0.05
    cli_result r = run_cli("simulate " + scene + " --until 0.5 --initial \"theta=0.1, theta'=-0.2\" --format json", "", 60);
    REQUIRE(r.exit_code == 0);
    nlohmann::json doc = nlohmann::json::parse(r.out);
    CHECK(doc["simulation"]["states"]["theta"][0].get<double>() == 0.1);
    CHECK(doc["simulation"]["states"]["phi"][0].get<double>() == 0.05); // the scene's, kept
    // The same start as a scene that says it in its `initial` line.
    std::string text = read_file(scene);
    const std::string line = "initial theta = 0, phi = 0.05, theta' = 0, phi' = 0";
    REQUIRE(text.find(line) != std::string::npos);
    text.replace(text.find(line), line.size(), "initial theta = 0.1, phi = 0.05, theta' = -0.2");
    cli_result same = run_cli("simulate - --until 0.5 --format json", text, 60);
    REQUIRE(same.exit_code == 0);
    CHECK(nlohmann::json::parse(same.out)["simulation"]["states"] == doc["simulation"]["states"]);
    // Bad input: exit 2, located in `--initial`.
    cli_result unknown = run_cli("simulate " + scene + " --until 0.5 --initial \"thetx=0.1\"");
    CHECK(unknown.exit_code == 2);
    CHECK(unknown.err == "--initial:1:1: error: `thetx` is not a coordinate\nthetx=0.1\n^\n");
    cli_result twice = run_cli("simulate " + scene + " --until 0.5 --initial \"phi=1, phi=2\"");
    CHECK(twice.exit_code == 2);
    CHECK(twice.err.rfind("--initial:1:8: error:", 0) == 0);
    cli_result not_values = run_cli("simulate " + scene + " --until 0.5 --initial \"theta=0.1 simulate until 3\"");
    CHECK(not_values.exit_code == 2);
    CHECK(not_values.err.rfind("--initial:1:", 0) == 0);
}

TEST_CASE("cli: an initial state off the constraints exits with 2, projected only when asked", "[cli][initial]")
{
    // examples/ladder.lag starts on its constraints; x = y = 0 with θ = 0.3 is far off them.
    // The error points at the value the projection moves most: y, from 0 to cos 0.3.
    const std::string ladder = examples + "ladder.lag";
    cli_result option = run_cli("simulate " + ladder + " --initial \"x=0, y=0, theta=0.3\"", "", 60);
    CHECK(option.exit_code == 2);
    CHECK(option.err.rfind("--initial:1:8: error: the initial state is off the constraints", 0) == 0);
    CHECK(option.err.find("\nx=0, y=0, theta=0.3\n       ^\n") != std::string::npos);
    CHECK(option.out.empty());
    std::string text = read_file(ladder);
    const std::string line = "initial x = sin(0.2), y = cos(0.2), theta = 0.2";
    REQUIRE(text.find(line) != std::string::npos);
    text.replace(text.find(line), line.size(), "initial theta = 0.3");
    const std::string scene = temporary_file("ladder_off.lag", text);
    for (const std::string& command : {"simulate " + scene, scene, scene + " --want simulation --format json"}) {
        cli_result r = run_cli(command, "", 60);
        CHECK(r.exit_code == 2);
        CHECK(r.err.find("ladder_off.lag:16:17: error: the initial state is off the constraints") != std::string::npos);
        CHECK(r.err.find("initial theta = 0.3\n                ^\n") != std::string::npos);
    }
    // --project-initial starts from the projected state, printed at the top of the output.
    cli_result projected = run_cli("simulate " + scene + " --project-initial", "", 60);
    REQUIRE(projected.exit_code == 0);
    const std::size_t top = projected.out.find("initial state projected onto the constraints");
    CHECK(top != std::string::npos);
    CHECK(top < projected.out.find("Lagrangian"));
    cli_result json = run_cli("simulate " + scene + " --project-initial --format json", "", 60);
    REQUIRE(json.exit_code == 0);
    nlohmann::json doc = nlohmann::json::parse(json.out)["simulation"];
    CHECK(doc["initial_residual"].get<double>() == Approx(0.955336).epsilon(1e-5));
    CHECK(doc["projected_initial"]["theta"].get<double>() == doc["states"]["theta"][0].get<double>());
    CHECK(doc["projected_initial"]["y"].get<double>() == Approx(std::cos(0.3)).epsilon(1e-12));
}

TEST_CASE("cli: every command takes and honours --max-terms and --max-seconds", "[cli][budget]")
{
    // The 10-link chain's characteristic polynomial takes far more than a second.
    // Past the budget, a stage stops at its next check (a note in the output, exit 0 when
    // other products remain, as in a report) or, inside one GiNaC call, by the watchdog
    // (exit 1): which comes first depends on where the time runs out. Either way the run
    // ends near the budget and says why.
    const std::string chain = temporary_file("chain10.lag", chain_scene(10));
    const std::string tex = temporary_file("chain.tex", "");
    for (const bool report : {true, false}) {
        const std::string command = report ? "report " + chain + " -o " + tex : chain + " --want characteristic";
        cli_result r = run_cli(command + " --max-terms 1000000000 --max-seconds 1", "", 30);
        CHECK(r.seconds < 8 * time_scale());
        std::ifstream written(tex);
        std::string said = r.out + r.err + (report ? std::string(std::istreambuf_iterator<char>(written), {}) : "");
        CHECK((r.exit_code == 0 || r.exit_code == 1));
        CHECK(said.find("exceeded its time budget of 1 s") != std::string::npos);
    }
    const std::string oscillator = std::string(LAGRANGE_SOURCE_DIR) + "/examples/damped_driven_oscillator.lag";
    for (const std::string& command : {"simulate " + oscillator + " --until 1",
                                       "workprecision " + oscillator + " --until 1",
                                       "response " + oscillator + " --input u --output x",
                                       "ensemble " + oscillator + " --grid \"x=0..1:2\" --until 1"})
        CHECK(run_cli(command + " --max-terms 100000 --max-seconds 20", "", 60).exit_code == 0);
}
