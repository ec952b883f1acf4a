/** @file main.cpp
 *  The `lagrange` command: turns arguments into library calls, prints, and maps
 *  errors to exit codes (0 success, 1 computation not possible, 2 bad input or usage). */
#include "engine/analysis.h"
#include "output/document.h"
#include "scene/lower.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <cerrno>
#include <cstring>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace {

constexpr int exit_ok = 0;
constexpr int exit_failed = 1;
constexpr int exit_bad_input = 2;
constexpr std::size_t max_scene_bytes = 64u << 20;

/// A usage error: exit code 2, message without position.
struct usage_error : std::runtime_error {
    using std::runtime_error::runtime_error;
};

lagrange::source_text read_scene(const std::string& path)
{
    std::string text;
    if (path == "-") {
        std::ostringstream buffer;
        buffer << std::cin.rdbuf();
        text = buffer.str();
    } else {
        struct stat info {};
        if (stat(path.c_str(), &info) != 0)
            throw usage_error("cannot open `" + path + "`: no such file");
        if (S_ISDIR(info.st_mode))
            throw usage_error("`" + path + "` is a folder, not a scene file");
        std::ifstream in(path, std::ios::binary);
        if (!in)
            throw usage_error("cannot read `" + path + "`");
        std::ostringstream buffer;
        buffer << in.rdbuf();
        text = buffer.str();
    }
    if (text.size() > max_scene_bytes)
        throw usage_error("`" + path + "` is larger than 64 MB: not a scene file");
    return lagrange::source_text(path == "-" ? "<stdin>" : path, text);
}

/// Writes `text` to `path` through a temporary file in the same folder (so that the
/// rename is atomic), renamed over `path` only once it is complete: a failure never
/// truncates or half-writes an existing file, and leaves no temporary file behind.
void write_output(const std::string& path, const std::string& text)
{
    if (path.empty() || path == "-") {
        std::cout << text;
        std::cout.flush();
        return;
    }
    std::string pattern = path + ".XXXXXX";
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    int fd = mkstemp(name.data());
    if (fd < 0)
        throw usage_error("cannot write `" + path + "`: " + std::strerror(errno));
    const std::string temporary(name.data());
    // mkstemp makes the file private (0600); give it the usual mode (0666 less the umask).
    mode_t mask = umask(0);
    umask(mask);
    bool ok = fchmod(fd, 0666 & ~mask) == 0;
    const char* data = text.data();
    std::size_t left = text.size();
    while (ok && left > 0) {
        ssize_t written = ::write(fd, data, left);
        if (written < 0 && errno == EINTR)
            continue;
        if (written <= 0) {
            ok = false;
            break;
        }
        data += written;
        left -= static_cast<std::size_t>(written);
    }
    int error = ok ? 0 : errno;
    if (::close(fd) != 0 && ok) {
        ok = false;
        error = errno;
    }
    if (ok && std::rename(temporary.c_str(), path.c_str()) != 0) {
        ok = false;
        error = errno;
    }
    if (!ok) {
        std::remove(temporary.c_str());
        throw usage_error("cannot write `" + path + "`" + (error ? std::string(": ") + std::strerror(error) : ""));
    }
}

struct run_options {
    std::string scene_path;
    std::string want;
    std::vector<std::string> values;
    std::string format = "text";
    std::string output;
    bool timings = false;
    lagrange::budget_limits budget;
};

int analyze_scene(const run_options& options)
{
    lagrange::source_text source = read_scene(options.scene_path);
    lagrange::model scene = lagrange::load_model(source);
    for (const std::string& v : options.values)
        lagrange::add_values(scene, v);
    std::set<lagrange::product> wanted;
    if (!options.want.empty())
        wanted = lagrange::parse_want_list(options.want);
    lagrange::analysis result = lagrange::analyze(scene, wanted, options.budget);
    lagrange::document_options document;
    document.timings = options.timings;
    std::ostringstream out;
    if (options.format == "json")
        lagrange::write_json(out, result, document);
    else if (options.format == "latex")
        lagrange::write_latex(out, result, document);
    else
        lagrange::write_text(out, result, document);
    write_output(options.output, out.str());
    return exit_ok;
}

int check_scene(const std::string& path)
{
    lagrange::source_text source = read_scene(path);
    lagrange::model scene = lagrange::load_model(source);
    std::cout << source.file() << ": ok (" << scene.coordinates.size() << " coordinates, "
              << scene.parameters.size() << " parameters)\n";
    return exit_ok;
}

int run(int argc, char** argv)
{
    CLI::App app{"lagrange: equations of motion, equilibria, normal modes and rigid bodies from a scene file"};
    app.set_version_flag("--version", std::string("lagrange ") + LAGRANGE_VERSION);
    app.require_subcommand(0, 1);

    run_options options;
    app.add_option("SCENE", options.scene_path, "the scene file (`-` for standard input)");
    app.add_option("--want", options.want, "products to compute, comma-separated (default: the scene's `want`)");
    app.add_option("--values", options.values, "a parameter point such as a=1,b=2.5 (repeatable)");
    app.add_option("--format", options.format, "output format")->check(CLI::IsMember({"text", "latex", "json"}));
    app.add_option("-o,--output", options.output, "write the output to this file");
    app.add_flag("--timings", options.timings, "show which stages ran and how long each took");
    app.add_option("--max-terms", options.budget.max_terms,
                   "size budget: most terms in any expression of a symbolic stage")
        ->check(CLI::Range(std::size_t{1}, std::size_t{1} << 40))
        ->capture_default_str();
    app.add_option("--max-seconds", options.budget.max_seconds, "time budget of each symbolic stage, in seconds")
        ->check(CLI::Range(1e-3, 1e7))
        ->capture_default_str();

    std::string check_path;
    CLI::App* check = app.add_subcommand("check", "parse and validate a scene only");
    check->add_option("SCENE", check_path, "the scene file")->required();

    std::string later_path;
    std::vector<std::string> later_rest;
    std::vector<CLI::App*> later;
    for (const char* name : {"report", "simulate", "workprecision"}) {
        CLI::App* sub = app.add_subcommand(name, std::string("`") + name + "` (not in this version yet)");
        sub->add_option("SCENE", later_path, "the scene file");
        sub->allow_extras();
        later.push_back(sub);
    }

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        int code = app.exit(error);
        return code == 0 ? exit_ok : exit_bad_input;
    }

    if (check->parsed())
        return check_scene(check_path);
    for (CLI::App* sub : later)
        if (sub->parsed()) {
            std::cerr << "lagrange: `" << sub->get_name() << "` is not available in this version yet\n";
            return exit_failed;
        }
    if (options.scene_path.empty()) {
        std::cerr << app.help();
        return exit_bad_input;
    }
    return analyze_scene(options);
}

} // namespace

int main(int argc, char** argv)
{
    try {
        return run(argc, argv);
    } catch (const lagrange::scene_error& error) {
        std::cerr << lagrange::format_error(error);
        return exit_bad_input;
    } catch (const usage_error& error) {
        std::cerr << "lagrange: error: " << error.what() << '\n';
        return exit_bad_input;
    } catch (const lagrange::computation_error& error) {
        std::cerr << "lagrange: error: " << error.what() << '\n';
        return exit_failed;
    } catch (const std::bad_alloc&) {
        std::cerr << "lagrange: error: out of memory\n";
        return exit_failed;
    } catch (const std::exception& error) {
        std::cerr << "lagrange: error: the computation failed (" << error.what() << ")\n";
        return exit_failed;
    }
}
