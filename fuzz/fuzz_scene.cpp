/** @file fuzz_scene.cpp
 *  libFuzzer target over the whole path: scene text -> parse -> check -> derive ->
 *  linearize -> characteristic polynomial -> symbolic and numeric modes -> the three
 *  printers, with small budgets (fuzz/run.sh builds and runs it); and `--sweep`: a
 *  comment line `#sweep SPEC` (SPEC as after --sweep, `;` between axes) sweeps the
 *  numeric modes over at most 64 points through the sweep printers.
 *
 *  Allowed outcomes: scene_error (bad input, exit 2) or computation_error (exit 1,
 *  budget_exceeded included). Anything else that escapes — a GiNaC or CLN internal
 *  exception that would reach the user, a crash, a sanitizer report, a leak, a hang
 *  past libFuzzer's -timeout — is a bug. */
#include "engine/analysis.h"
#include "output/document.h"
#include "output/sweep_output.h"
#include "scene/lower.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
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
    lagrange::write_sweep(out, scene, *result.linearization, axes, "text");
    lagrange::write_sweep(out, scene, *result.linearization, axes, "json");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    if (size > 4096)
        return -1; // keep scenes small: expression swell is the budgets' business, not the fuzzer's
    const std::string text(reinterpret_cast<const char*>(data), size);
    lagrange::source_text source("fuzz.lag", text);
    // `use "file.rules"` must not touch the disk: every file is an empty rules file.
    lagrange::file_reader no_files = [](const std::string&, const lagrange::source_location&) {
        return std::string("# empty\n");
    };
    try {
        lagrange::model scene = lagrange::load_model(source, no_files);
        lagrange::budget_limits limits;
        limits.max_terms = 2000;
        limits.max_seconds = 0.3; // per stage: all of them well inside the 5 s -timeout under ASan
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
    } catch (const lagrange::scene_error& error) {
        (void)lagrange::format_error(error);
    } catch (const lagrange::computation_error&) {
    } catch (const std::exception& error) {
        std::fprintf(stderr, "fuzz: unexpected %s escaped: %s\n", typeid(error).name(), error.what());
        std::abort();
    }
    return 0;
}
