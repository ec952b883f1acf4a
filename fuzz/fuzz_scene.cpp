// SPDX-License-Identifier: GPL-2.0-or-later
/** @file fuzz_scene.cpp
 *  libFuzzer target over the whole path: scene text -> parse -> check -> derive ->
 *  linearize -> characteristic polynomial -> symbolic and numeric modes -> the three
 *  printers, with small budgets (fuzz/run.sh builds and runs it); and `--sweep`: a
 *  comment line `#sweep SPEC` (SPEC as after --sweep, `;` between axes) sweeps the
 *  numeric modes over at most 64 points through the sweep printers. The file paths of the
 *  command line run too, in a private folder of odd files: `use` of a rules file, a folder,
 *  a named pipe with no writer, a link, /dev/zero; -o and --csv onto a new file, an
 *  existing private file, a link and a folder.
 *
 *  Allowed outcomes: scene_error (bad input, exit 2) or computation_error (exit 1,
 *  budget_exceeded included). Anything else that escapes — a GiNaC or CLN internal
 *  exception that would reach the user, a crash, a sanitizer report, a leak, a hang
 *  past libFuzzer's -timeout — is a bug, but for one kind of overrun: a symbolic stage stuck
 *  in one GiNaC call, which the program's watchdog ends at --max-seconds. With
 *  LAGRANGE_FUZZ_WATCHDOG set, this target starts that watchdog too (exit 3), and fuzz/run.sh
 *  runs each input that went over -timeout again with it on. */
#include "algebra/budget.h"
#include "engine/analysis.h"
#include "output/document.h"
#include "output/sweep_output.h"
#include "output/simulation.h"
#include "scene/lower.h"
#include "system/files.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sys/stat.h>
#include <unistd.h>
#include <sstream>
#include <string>
#include <typeinfo>
#include <vector>

namespace {

/// The `#sweep SPEC` line's axes (as `lagrange --sweep` parses them), swept and printed
/// as text and JSON when the grid has at most 64 points (larger grids are the same loop).
void sweep(const std::string& text, const lagrange::model& scene, const lagrange::analysis& result,
           std::ostream& out)
{
    std::size_t at = text.find("#sweep ");
    if (at == std::string::npos || !result.linearization)
        return;
    std::size_t begin = at + 7, end = text.find('\n', begin);
    std::string line = text.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
    std::vector<lagrange::sweep_axis> axes;
    for (std::size_t start = 0; start <= line.size() && axes.size() < 3;) {
        std::size_t stop = std::min(line.find(';', start), line.size());
        axes.push_back(lagrange::parse_sweep_axis(line.substr(start, stop - start), scene));
        start = stop + 1;
    }
    if (lagrange::sweep_size(axes) > 64)
        return;
    lagrange::point_modes path = lagrange::numeric_modes_path(result);
    lagrange::write_sweep(out, scene, path, axes, "text");
    lagrange::write_sweep(out, scene, path, axes, "json");
}

/// A private folder of odd files, made once: what `use` and -o meet on a user's disc.
const std::string& odd_files()
{
    static const std::string folder = [] {
        char pattern[] = "/tmp/lagrange-fuzz-XXXXXX";
        std::string made = mkdtemp(pattern) ? pattern : "/tmp";
        std::ofstream(made + "/good.rules") << "sin($1)^2 -> 1 - cos($1)^2\n";
        std::ofstream(made + "/private.txt") << "old\n";
        chmod((made + "/private.txt").c_str(), 0600);
        std::filesystem::create_directory(made + "/folder");
        mkfifo((made + "/pipe").c_str(), 0600);
        symlink((made + "/good.rules").c_str(), (made + "/link.rules").c_str());
        symlink((made + "/private.txt").c_str(), (made + "/link.txt").c_str());
        return made;
    }();
    return folder;
}

/// `use "NAME"` reads one of the odd files, chosen by NAME, as the command line reads them.
std::string read_odd_file(const std::string& name, const lagrange::source_location& where)
{
    static const char* const files[] = {"good.rules", "link.rules", "folder", "pipe", "missing", "/dev/zero"};
    const std::string file = files[std::hash<std::string>{}(name) % std::size(files)];
    try {
        return lagrange::read_bounded(file[0] == '/' ? file : odd_files() + "/" + file, 1u << 20, 0.01);
    } catch (const lagrange::file_error& error) {
        throw lagrange::scene_error(where, error.what());
    }
}

/// The output written as -o would write it, onto one of the odd targets chosen by `key`.
void write_odd_output(std::size_t key, const std::string& bytes)
{
    static const char* const targets[] = {"new.txt", "private.txt", "link.txt", "folder"};
    const std::string target = odd_files() + "/" + targets[key % std::size(targets)];
    try {
        lagrange::write_output(target, bytes);
    } catch (const lagrange::file_error&) {
    }
    std::remove((odd_files() + "/new.txt").c_str());
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
    if (std::getenv("LAGRANGE_FUZZ_WATCHDOG"))
        lagrange::start_budget_watchdog("fuzz: ", 3);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    if (size > 4096)
        return -1; // keep scenes small: expression swell is the budgets' business, not the fuzzer's
    const std::string text(reinterpret_cast<const char*>(data), size);
    lagrange::source_text source("fuzz.lag", text);
    try {
        lagrange::model scene = lagrange::load_model(source, read_odd_file);
        lagrange::budget_limits limits;
        limits.max_terms = 2000;
        limits.max_seconds = 0.3; // per stage: all of them well inside the 20 s -timeout under ASan
        // The motion stages run too, but briefly, interpreted (no compiler per input) and
        // without the second run that estimates the error.
        lagrange::simulation_settings motion;
        motion.until = 0.05;
        motion.estimate_error = false;
        motion.native = false;
        motion.max_seconds = 1;
        lagrange::analysis result = lagrange::analyze(scene, {}, limits, motion);
        std::ostringstream out;
        lagrange::write_text(out, result);
        lagrange::write_json(out, result);
        lagrange::write_latex(out, result);
        sweep(text, scene, result, out);
        write_odd_output(size, out.str());
        if (result.simulation) {
            std::ostringstream csv;
            lagrange::write_trajectory_csv(csv, *result.simulation);
            write_odd_output(size / 4, csv.str());
        }
    } catch (const lagrange::scene_error& error) {
        (void)lagrange::format_error(error);
    } catch (const lagrange::computation_error&) {
    } catch (const std::exception& error) {
        std::fprintf(stderr, "fuzz: unexpected %s escaped: %s\n", typeid(error).name(), error.what());
        std::abort();
    }
    return 0;
}
