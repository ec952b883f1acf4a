// SPDX-License-Identifier: GPL-2.0-or-later
/** @file main.cpp
 *  The `lagrange` command: turns arguments into library calls, prints, and maps
 *  errors to exit codes (0 success, 1 computation not possible, 2 bad input or usage). */
#include "engine/analysis.h"
#include "engine/pictures.h"
#include "engine/readiness.h"
#include "ensemble/settings.h"
#include "output/document.h"
#include "output/export_code.h"
#include "output/format.h"
#include "output/ensemble_output.h"
#include "output/animation_output.h"
#include "output/phase_output.h"
#include "output/poincare_output.h"
#include "output/report.h"
#include "output/response_output.h"
#include "output/simulation.h"
#include "output/sweep_output.h"
#include "numeric/values.h"
#include "scene/lower.h"
#include "system/files.h"
#include "system/gnuplot.h"
#include "system/progress_line.h"
#include "system/signals.h"

#include <CLI/CLI.hpp>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <chrono>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <fstream>
#include <iostream>
#include <sstream>
#include <cerrno>
#include <cstring>
#include <sys/stat.h>
#include <vector>

namespace {

constexpr int exit_ok = 0;
constexpr int exit_failed = 1;
constexpr int exit_bad_input = 2;

/// A usage error: exit code 2, message without position.
struct usage_error : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// A scene from a file or standard input, bounded in size and, for a pipe or a device,
/// in the time it may take to give its data (the time budget).
lagrange::source_text read_scene(const std::string& path, double wait_seconds = lagrange::budget_limits{}.max_seconds)
{
    std::string text = lagrange::read_bounded(path, lagrange::max_scene_bytes, wait_seconds);
    return lagrange::source_text(path == "-" ? "<stdin>" : path, text);
}

/// The scene in `source` with the --values points added.
lagrange::model load_scene(const lagrange::source_text& source, const std::vector<std::string>& values,
                           const std::vector<std::string>& initial = {})
{
    lagrange::model scene = lagrange::load_model(source);
    for (const lagrange::scene_warning& warning : scene.warnings)
        std::cerr << lagrange::format_warning(warning);
    for (const std::string& v : values)
        lagrange::add_values(scene, v);
    for (const std::string& i : initial)
        lagrange::add_initial(scene, i);
    return scene;
}

/// The scene at `path` (standard input for "-") with the --values points added and the
/// --initial values set.
lagrange::model load_scene(const std::string& path, const std::vector<std::string>& values,
                           const std::vector<std::string>& initial = {},
                           double wait_seconds = lagrange::budget_limits{}.max_seconds)
{
    return load_scene(read_scene(path, wait_seconds), values, initial);
}

/// The help of --initial, which every command that integrates takes.
const char* const initial_help = "initial values such as \"theta=0.1, phi'=0\": they replace the scene's for those "
                                 "coordinates";
/// The help of --project-initial, beside --initial.
const char* const project_initial_help = "start from the initial state moved onto the constraints by least change "
                                         "(printed first) when it is off them; without it that is an error";

/// The help of --latex-body, beside --format.
const char* const latex_body_help = "with --format latex: only the body (headings, prose and equations), without the "
                                    "preamble, to paste into a paper";

/// A plot's title: the scene's, or its file name.
std::string plot_title(const lagrange::model& scene) { return scene.title.empty() ? scene.file : scene.title; }

using lagrange::output_file;
using lagrange::write_output;
using lagrange::progress_line;

/// Clears the progress line when a command ends, before its output or error message.
struct progress_cleared_at_end {
    ~progress_cleared_at_end() { progress_line::standard_error().clear(); }
};

/// The products `--want` takes (the library's list, wrapped) and an example, for --help.
std::string products_help()
{
    std::string text = "Products (--want, or a scene's `want` line):\n ";
    std::size_t column = 1;
    for (const auto& [unused, name] : lagrange::product_names()) {
        if (column + name.size() + 2 > 78) {
            text += "\n ";
            column = 1;
        }
        text += " " + name + ",";
        column += name.size() + 2;
    }
    text.pop_back();
    return text + "\n\nExample:\n  lagrange examples/double_pendulum.lag --want equations,frequencies\n";
}

struct run_options {
    std::string scene_path;
    std::string want;
    std::vector<std::string> values;
    std::vector<std::string> initial; ///< --initial, applied in order
    bool project_initial = false;     ///< --project-initial
    std::string format = "text";
    std::string output;
    bool timings = false;
    bool latex_body = false; ///< --latex-body
    lagrange::budget_limits budget;
    std::vector<std::string> sweeps;
};

/// The analysis of the products in `want` (a --want list; empty: the scene's or the
/// default ones), with progress on the terminal.
lagrange::analysis analyze_wanted(const lagrange::model& scene, const std::string& want,
                                  const lagrange::budget_limits& budget, bool project_initial)
{
    std::set<lagrange::product> wanted;
    if (!want.empty())
        wanted = lagrange::parse_want_list(want);
    lagrange::simulation_settings settings;
    settings.project_initial = project_initial;
    settings.progress = progress_line::standard_error().callback();
    return lagrange::analyze(scene, wanted, budget, settings);
}

/// The analysis as text, LaTeX or JSON, to `path` (or standard output). Run times only
/// with `timings`: the output stays the same run to run; `latex_body`: LaTeX without its
/// preamble, to paste into a paper.
void write_document(const lagrange::analysis& result, const std::string& format, bool timings, bool latex_body,
                    const std::string& path)
{
    lagrange::document_options document;
    document.timings = timings;
    document.latex_body = latex_body;
    write_output(path, lagrange::document_text(result, format, document));
}

/// `--sweep`: the numeric modes over a grid, streamed to the output as computed.
int sweep_scene(const run_options& options)
{
    if (options.format == "latex")
        throw usage_error("--sweep writes text or json, not latex");
    if (!options.want.empty())
        throw usage_error("--sweep computes the numeric modes only; leave out --want");
    lagrange::model scene = load_scene(options.scene_path, options.values, options.initial, options.budget.max_seconds);
    std::vector<lagrange::sweep_axis> axes;
    for (const std::string& s : options.sweeps)
        axes.push_back(lagrange::parse_sweep_axis(s, scene));
    lagrange::sweep_size(axes);
    lagrange::analysis result = lagrange::analyze(scene, {lagrange::product::linearization}, options.budget);
    output_file out(options.output);
    lagrange::point_modes path = lagrange::numeric_modes_path(result);
    lagrange::write_sweep(out.stream(), scene, path, axes, options.format);
    out.commit();
    return exit_ok;
}

int analyze_scene(const run_options& options)
{
    if (!options.sweeps.empty())
        return sweep_scene(options);
    lagrange::model scene = load_scene(options.scene_path, options.values, options.initial, options.budget.max_seconds);
    lagrange::analysis result = analyze_wanted(scene, options.want, options.budget, options.project_initial);
    write_document(result, options.format, options.timings, options.latex_body, options.output);
    return exit_ok;
}

struct motion_options {
    std::string scene_path;
    std::vector<std::string> values;
    std::vector<std::string> initial; ///< --initial, applied in order
    bool project_initial = false;     ///< --project-initial
    std::optional<double> until;
    std::string method;
    std::optional<double> tolerance;
    std::string csv;
    std::string plot;
    std::string format = "text";
    std::string output;
    bool interpret = false; ///< evaluate the equations with the interpreter instead of native code
    bool timings = false;
    bool latex_body = false; ///< --latex-body
};

/// A --plot path whose extension names no format is a usage error, before any work.
void require_plot_format(const std::string& path)
{
    if (path.empty())
        return;
    try {
        lagrange::plot_format_of(path);
    } catch (const std::invalid_argument& error) {
        throw usage_error(error.what());
    }
}

int motion_command(const motion_options& options, lagrange::product wanted, const lagrange::budget_limits& budget)
{
    require_plot_format(options.plot);
    lagrange::model scene = load_scene(options.scene_path, options.values, options.initial, budget.max_seconds);
    lagrange::simulation_settings settings;
    settings.until = options.until;
    if (!options.method.empty())
        settings.method = options.method;
    settings.tolerance = options.tolerance;
    settings.project_initial = options.project_initial;
    settings.progress = progress_line::standard_error().callback();
    settings.native = !options.interpret;
    lagrange::analysis result = lagrange::analyze(scene, {wanted}, budget, settings);
    progress_line::standard_error().clear();
    const std::string title = plot_title(scene);
    if (result.simulation && !options.csv.empty()) {
        std::ostringstream csv;
        lagrange::write_trajectory_csv(csv, *result.simulation);
        write_output(options.csv, csv.str());
    }
    if (!options.plot.empty()) {
        if (result.simulation)
            lagrange::plot_trajectory(options.plot, *result.simulation, title);
        if (result.workprecision)
            lagrange::plot_workprecision(options.plot, *result.workprecision, title);
    }
    write_document(result, options.format, options.timings, options.latex_body, options.output);
    return exit_ok;
}

struct response_options {
    std::string scene_path;
    std::vector<std::string> values;
    std::string input, output;
    double from = 0, to = 0;
    std::size_t points = 400;
    bool linear = false;
    std::string format = "text";
    std::string output_path;
    std::string plot;
};

/// `lagrange response SCENE --input u --output q`: the frequency response H(iω) of the
/// linearized system, as text, CSV or JSON, and its Bode diagram.
int response_command(const response_options& options, const lagrange::budget_limits& budget)
{
    require_plot_format(options.plot);
    lagrange::model scene = load_scene(options.scene_path, options.values, {}, budget.max_seconds);
    lagrange::analysis result = lagrange::analyze(scene, {lagrange::product::state_space}, budget);
    lagrange::response_settings settings;
    settings.from = options.from;
    settings.to = options.to;
    settings.points = options.points;
    settings.logarithmic = !options.linear;
    lagrange::frequency_response response = lagrange::frequency_response_of(
        scene, *result.linearization, *result.state_space, options.input, options.output, settings);
    if (!options.plot.empty())
        lagrange::plot_response(options.plot, response, plot_title(scene));
    std::ostringstream out;
    if (options.format == "csv")
        lagrange::write_response_csv(out, response);
    else if (options.format == "json")
        lagrange::write_response_json(out, response);
    else
        lagrange::write_response_text(out, response);
    write_output(options.output_path, out.str());
    return exit_ok;
}

struct ensemble_options {
    std::string scene_path;
    std::string grid;
    std::optional<double> until;
    std::string measure = "final";
    std::string output;
    std::size_t threads = 0;
    std::optional<double> tolerance;
    std::size_t random = 0;
    std::uint64_t seed = 1;
    bool resume = false;
    bool interpret = false;
    double mpi_timeout = lagrange::ensemble_run_options{}.silence_seconds;
    std::vector<std::string> values;
    std::vector<std::string> initial; ///< --initial, applied in order
};

/// Points done, points per second and the time left, on the progress line (a terminal only).
std::function<void(std::size_t, std::size_t)> ensemble_progress()
{
    progress_line& line = progress_line::standard_error();
    if (!line.enabled())
        return nullptr;
    const auto start = std::chrono::steady_clock::now();
    auto shown = std::make_shared<double>(-1);
    return [&line, start, shown](std::size_t done, std::size_t total) {
        if (done >= total) {
            line.clear();
            return;
        }
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (elapsed - *shown < 0.25 || done == 0)
            return;
        *shown = elapsed;
        const double rate = static_cast<double>(done) / elapsed;
        const auto left = static_cast<long>(static_cast<double>(total - done) / rate);
        char text[96];
        std::snprintf(text, sizeof text, "ensemble %zu/%zu, %.0f/s, %ld:%02ld:%02ld left", done, total, rate,
                      left / 3600, left / 60 % 60, left % 60);
        line.show(text, static_cast<double>(done) / static_cast<double>(total));
    };
}

/// `lagrange ensemble SCENE --grid "..." --until T`: the measure at every point of the grid,
/// as CSV (standard output or -o FILE.csv), JSON (-o FILE.json) or a PNG map (-o FILE.png).
int ensemble_command(const ensemble_options& options, const lagrange::budget_limits& budget)
{
    auto ends_with = [&](const std::string& suffix) {
        const std::string& p = options.output;
        return p.size() > suffix.size() && p.compare(p.size() - suffix.size(), suffix.size(), suffix) == 0;
    };
    const bool png = ends_with(".png"), json = ends_with(".json");
    const bool to_file = !options.output.empty() && options.output != "-";
    if (to_file && !png && !json && !ends_with(".csv"))
        throw usage_error("`ensemble -o` takes a file ending in .csv, .json or .png, not `" + options.output + "`");
    if (options.resume && (!to_file || png || json))
        throw usage_error("--resume continues a CSV file: give it with -o FILE.csv");
    lagrange::model scene = load_scene(options.scene_path, options.values, options.initial, budget.max_seconds);
    std::vector<lagrange::ensemble_axis> axes = lagrange::parse_ensemble_grid(options.grid, scene, options.random > 0);
    lagrange::ensemble_measure measure = lagrange::parse_ensemble_measure(options.measure, scene);
    lagrange::ensemble_settings settings;
    try {
        settings = lagrange::ensemble_settings_for(
            scene, measure, {options.until, options.tolerance, options.random, options.seed, !options.interpret});
    } catch (const lagrange::ensemble_request_error& error) {
        throw usage_error(error.what());
    }
    lagrange::analysis result = lagrange::analyze(scene, lagrange::ensemble_products(measure), budget);
    lagrange::ensemble_problem problem(scene, *result.equations, axes, measure, settings,
                                       result.time ? &*result.time : nullptr);

    lagrange::ensemble_run_options run;
    run.threads = options.threads;
    run.silence_seconds = options.mpi_timeout;
    run.progress = ensemble_progress();
    std::ofstream file;                              // CSV: in place, for --resume
    std::unique_ptr<lagrange::output_file> whole_file; // JSON: replaced only when complete
    std::unique_ptr<lagrange::ensemble_map> map;
    std::ostream* out = &std::cout;
    auto last_flush = std::chrono::steady_clock::now();
    lagrange::ensemble_sink sink;
    const bool rank_zero = lagrange::ensemble_root_process();
    if (options.resume && rank_zero)
        run.first = lagrange::resume_ensemble_csv(options.output, problem);
    sink.begin = [&] {
        if (png) {
            map = std::make_unique<lagrange::ensemble_map>(problem);
            return;
        }
        if (to_file && json) {
            whole_file = std::make_unique<lagrange::output_file>(options.output);
            out = &whole_file->stream();
        } else if (to_file) {
            // CSV is written as the rows come (no temporary file), so that an interrupted run
            // leaves the rows done so far for --resume.
            file.open(options.output, run.first > 0 ? std::ios::app | std::ios::binary : std::ios::trunc | std::ios::binary);
            if (!file)
                throw lagrange::file_error("cannot write `" + options.output + "`: " + std::strerror(errno));
            out = &file;
        }
        if (json)
            lagrange::write_ensemble_json_begin(*out, problem);
        else if (run.first == 0)
            lagrange::write_ensemble_csv_header(*out, problem);
    };
    sink.row = [&](std::size_t index, const double* row) {
        if (map) {
            map->row(row);
            return;
        }
        if (json)
            lagrange::write_ensemble_json_row(*out, problem, index, row);
        else
            lagrange::write_ensemble_csv_row(*out, problem, row);
        if (index % 64 == 0 && std::chrono::steady_clock::now() - last_flush > std::chrono::milliseconds(500)) {
            // A full disc stops the run here, at the first flush that fails, not at the end.
            errno = 0;
            if (!out->flush())
                throw lagrange::computation_error("cannot write `" + (to_file ? options.output : "-") + "`: " +
                                                  (errno ? std::strerror(errno) : "the disc may be full"));
            last_flush = std::chrono::steady_clock::now();
        }
    };
    if (options.resume && !rank_zero)
        run.first = 0; // only rank 0 reads the file; it hands out the points from there
    lagrange::ensemble_summary summary = lagrange::run_ensemble(problem, run, sink);
    if (!summary.root)
        return exit_ok;
    if (json)
        lagrange::write_ensemble_json_end(*out, problem, summary);
    if (map)
        map->draw(options.output, plot_title(scene));
    if (whole_file) {
        whole_file->commit();
    } else if (file.is_open()) {
        errno = 0;
        if (!file.flush())
            throw lagrange::computation_error("cannot write `" + options.output + "`: " +
                                              (errno ? std::strerror(errno) : "the disc may be full"));
        file.close();
    } else if (!png) {
        lagrange::finish_standard_output();
    }
    std::string failure = summary.failures > 0 ? problem.failure_message(summary.first_failure) : "";
    std::cerr << lagrange::ensemble_summary_text(problem, summary, failure);
    return exit_ok;
}

struct poincare_options {
    std::string scene_path;
    std::string section;
    std::string axes;
    double energy = 0;
    std::size_t orbits = lagrange::poincare_settings{}.orbits;
    std::size_t crossings = lagrange::poincare_settings{}.crossings;
    double until = lagrange::poincare_settings{}.until;
    std::optional<double> tolerance;
    std::uint64_t seed = 1;
    std::size_t threads = 0;
    std::string output;
    bool interpret = false;
    std::vector<std::string> values;
};

/// `lagrange poincare SCENE --section "q = 0, q' > 0" --energy E`: the crossings of many
/// orbits at energy E, as CSV (standard output or -o FILE.csv) or a picture (-o FILE.svg|png|pdf).
int poincare_command(const poincare_options& options, const lagrange::budget_limits& budget)
{
    const std::string& path = options.output;
    const std::size_t dot = path.rfind('.');
    const std::string extension = dot == std::string::npos ? "" : path.substr(dot);
    const bool to_file = !path.empty() && path != "-", csv = !to_file || extension == ".csv";
    if (!csv) {
        try {
            lagrange::plot_format_of(path);
        } catch (const std::invalid_argument&) {
            throw usage_error("`poincare -o` takes a file ending in .csv, .svg, .png or .pdf, not `" + path + "`");
        }
    }
    lagrange::model scene = load_scene(options.scene_path, options.values, {}, budget.max_seconds);
    const lagrange::poincare_section section = lagrange::parse_poincare_section(options.section, scene);
    const lagrange::poincare_axes axes = options.axes.empty()
                                             ? lagrange::default_poincare_axes(scene, section)
                                             : lagrange::parse_poincare_axes(options.axes, scene, section);
    lagrange::poincare_settings settings;
    settings.energy = options.energy;
    settings.orbits = options.orbits;
    settings.crossings = options.crossings;
    settings.until = options.until;
    if (options.tolerance)
        settings.tolerance = *options.tolerance;
    settings.seed = options.seed;
    settings.threads = options.threads;
    settings.native = !options.interpret;
    lagrange::poincare_result section_result;
    try {
        section_result = lagrange::poincare_scene(scene, section, settings, budget);
    } catch (const lagrange::poincare_request_error& error) {
        throw usage_error(error.what());
    }
    section_result.axes = axes;
    if (csv) {
        std::ostringstream out;
        lagrange::write_poincare_csv(out, section_result);
        write_output(to_file ? path : "-", out.str());
    } else {
        lagrange::plot_poincare(path, section_result, plot_title(scene));
    }
    std::cerr << lagrange::poincare_summary_text(section_result);
    return exit_ok;
}

struct phase_options {
    std::string scene_path;
    std::string coordinate;
    std::size_t levels = lagrange::phase_settings{}.levels;
    std::string output;
    std::vector<std::string> values;
};

/// `lagrange phase SCENE [--coordinate q] -o FILE`: the phase portrait as a picture
/// (FILE.svg|png|pdf) or its energy grid (FILE.csv).
int phase_command(const phase_options& options, const lagrange::budget_limits& budget)
{
    const std::string& path = options.output;
    const bool csv = path.size() > 4 && path.compare(path.size() - 4, 4, ".csv") == 0;
    if (!csv) {
        try {
            lagrange::plot_format_of(path);
        } catch (const std::invalid_argument&) {
            throw usage_error("`phase -o` takes a file ending in .svg, .png, .pdf or .csv, not `" + path + "`");
        }
    }
    lagrange::model scene = load_scene(options.scene_path, options.values, {}, budget.max_seconds);
    lagrange::phase_settings settings;
    settings.levels = options.levels;
    if (!options.coordinate.empty())
        settings.coordinate = lagrange::phase_coordinate(options.coordinate, scene);
    lagrange::analysis result;
    try {
        result = lagrange::analyze(scene, {lagrange::product::equations, lagrange::product::equilibrium}, budget);
    } catch (const lagrange::computation_error&) {
        result = lagrange::analyze(scene, {lagrange::product::equations}, budget);
    }
    const lagrange::phase_portrait portrait = lagrange::compute_phase_portrait(
        scene, *result.equations, result.equilibria ? &*result.equilibria : nullptr, settings);
    if (csv) {
        std::ostringstream out;
        lagrange::write_phase_csv(out, portrait);
        write_output(path, out.str());
    } else {
        lagrange::plot_phase_portrait(path, portrait, plot_title(scene));
    }
    std::cerr << lagrange::phase_summary_text(portrait);
    return exit_ok;
}

struct animate_options {
    std::string scene_path;
    std::string output;
    double fps = 30;
    double speed = 1;
    double trail = 0;
    std::string view;
    std::optional<double> until;
    std::optional<double> tolerance;
    bool interpret = false;
    bool project_initial = false;
    std::vector<std::string> values;
    std::vector<std::string> initial;
};

/// `lagrange animate SCENE -o FILE.html|mp4|gif`: the motion as a self-contained player or a video.
int animate_command(const animate_options& options, const lagrange::budget_limits& budget)
{
    auto ends_with = [&](const std::string& suffix) {
        const std::string& p = options.output;
        return p.size() > suffix.size() && p.compare(p.size() - suffix.size(), suffix.size(), suffix) == 0;
    };
    const bool html = ends_with(".html"), video = ends_with(".mp4") || ends_with(".gif");
    if (!html && !video)
        throw usage_error("`animate -o` takes a file ending in .html, .mp4 or .gif, not `" + options.output + "`");
    if (!lagrange::known_animation_view(options.view))
        throw usage_error("--view takes xy, xz or 3d, not `" + options.view + "`");
    lagrange::model scene = load_scene(options.scene_path, options.values, options.initial, budget.max_seconds);
    lagrange::animation_settings settings;
    settings.fps = options.fps;
    settings.until = options.until;
    if (options.tolerance)
        settings.tolerance = *options.tolerance;
    else if (scene.simulation && scene.simulation->tolerance)
        settings.tolerance = lagrange::real_value(*scene.simulation->tolerance, "the scene's tolerance");
    settings.native = !options.interpret;
    settings.project_initial = options.project_initial;
    lagrange::animation_view view{options.speed, options.trail, options.view, options.fps};
    if (video) {
        lagrange::check_video_encoder(options.output); // says why before the work
        settings.fps = options.fps / options.speed;     // one frame of the run per frame of the video
    }
    const lagrange::animation_frames frames = lagrange::animate_scene(scene, settings, budget);
    if (video)
        lagrange::write_animation_video(options.output, frames, view);
    else
        write_output(options.output, lagrange::animation_html(frames, view, plot_title(scene)));
    return exit_ok;
}

struct export_options {
    std::string scene_path;
    std::string target;
    std::string folder = ".";
    std::string name;
    std::vector<std::string> values;
};

/// `lagrange export SCENE --to c|python|octave [-o DIR] [--name NAME]`: the equations of
/// motion as source code, written into DIR with nothing half-written.
int export_command(const export_options& options, const lagrange::budget_limits& budget)
{
    const std::string name = options.name.empty() ? lagrange::default_export_name(options.scene_path) : options.name;
    if (!lagrange::valid_export_name(name))
        throw usage_error("--name " + options.name + ": the exported functions' name must be an identifier (letters, "
                          "digits and `_`, not starting with a digit) and no keyword of C, Python or Octave");
    lagrange::model scene = load_scene(options.scene_path, options.values, {}, budget.max_seconds);
    std::vector<std::pair<std::string, std::string>> files;
    for (const lagrange::exported_file& file :
         lagrange::export_scene(scene, *lagrange::export_target_named(options.target), name, LAGRANGE_VERSION, budget))
        files.emplace_back(file.name, file.text);
    lagrange::write_files(options.folder, files);
    for (const auto& file : files)
        std::cout << options.folder << (options.folder.back() == '/' ? "" : "/") << file.first << '\n';
    lagrange::finish_standard_output();
    return exit_ok;
}

int check_scene(const std::string& path)
{
    lagrange::source_text source = read_scene(path);
    lagrange::model scene = load_scene(source, {});
    std::cout << source.file() << ": ok (" << scene.coordinates.size() << " coordinates, "
              << scene.parameters.size() << " parameters)\n";
    for (const std::string& need : lagrange::unmet_needs(scene))
        std::cout << "  needed by " << need << '\n';
    lagrange::finish_standard_output();
    return exit_ok;
}

/// `lagrange report SCENE -o FILE.tex|FILE.pdf`: the derivation as a LaTeX
/// document; its figures are written beside FILE.tex, or compiled into FILE.pdf.
int report_scene(const run_options& options, const lagrange::budget_limits& budget)
{
    const std::string& path = options.output;
    auto ends_with = [&](const std::string& suffix) {
        return path.size() > suffix.size() && path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0;
    };
    bool pdf = ends_with(".pdf");
    if (!path.empty() && path != "-" && !pdf && !ends_with(".tex"))
        throw usage_error("`report -o` takes a file ending in .tex or .pdf, not `" + path + "`");
    lagrange::source_text source = read_scene(options.scene_path, budget.max_seconds);
    lagrange::model scene = load_scene(source, options.values, options.initial);
    lagrange::analysis result = analyze_wanted(scene, options.want, budget, options.project_initial);
    result.phase = lagrange::report_phase_portrait(scene, result);
    lagrange::report_options report;
    // Figures go beside the .tex file, named after it (letters, digits and `-` only).
    std::size_t slash = path.rfind('/');
    std::string folder = slash == std::string::npos ? "" : path.substr(0, slash + 1);
    std::string stem = path.substr(folder.size(), path.size() - folder.size() - (pdf || ends_with(".tex") ? 4 : 0));
    for (char& c : stem)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-')
            c = '-';
    // Inside a PDF the figures' names do not depend on the output's name.
    report.figure_prefix = pdf || stem.empty() || path == "-" ? "report-" : stem + "-";
    report.plots = !path.empty() && path != "-"; // on standard output there is nowhere to put figures
    lagrange::report_document document = lagrange::build_report(result, source, report);
    if (pdf) {
        write_output(path, lagrange::compile_report(document));
        return exit_ok;
    }
    for (const lagrange::report_file& figure : document.figures)
        write_output(folder + figure.name, figure.bytes);
    write_output(path, document.latex);
    return exit_ok;
}

/// Refuses `nan` and `inf`, which pass CLI11's range checks (every comparison with nan is false).
const CLI::Validator finite_number(
    [](std::string& text) {
        char* end = nullptr;
        double value = std::strtod(text.c_str(), &end);
        return std::isfinite(value) ? std::string() : "must be a finite number, not `" + text + "`";
    },
    "FINITE");

/// A finite number above 0; CLI11's PositiveNumber prints its range up to the largest double.
const CLI::Validator positive_number(
    [](std::string& text) {
        char* end = nullptr;
        double value = std::strtod(text.c_str(), &end);
        return std::isfinite(value) && value > 0 ? std::string()
                                                  : "must be a positive, finite number, not `" + text + "`";
    },
    "POSITIVE");

int run(int argc, char** argv)
{
    // Progress is drawn on a terminal during the symbolic stages too (the budget watchdog
    // reports the open stage); the line's clock starts here.
    progress_cleared_at_end cleared;
    lagrange::show_stage_progress(progress_line::standard_error().callback()); // empty off a terminal

    CLI::App app{"lagrange: equations of motion, equilibria, normal modes and rigid bodies from a scene file"};
    app.footer(products_help());
    app.set_version_flag("--version", std::string("lagrange ") + LAGRANGE_VERSION);
    app.require_subcommand(0, 1);

    run_options options;
    app.add_option("SCENE", options.scene_path, "the scene file (`-` for standard input)");
    app.add_option("--want", options.want, "products to compute, comma-separated (default: the scene's `want`)");
    app.add_option("--values", options.values, "a parameter point such as a=1,b=2.5 (repeatable)");
    app.add_option("--initial", options.initial, initial_help);
    app.add_flag("--project-initial", options.project_initial, project_initial_help);
    app.add_option("--format", options.format, "output format")->check(CLI::IsMember({"text", "latex", "json"}));
    app.add_flag("--latex-body", options.latex_body, latex_body_help);
    app.add_option("-o,--output", options.output, "write the output to this file");
    app.add_flag("--timings", options.timings, "show which stages ran and how long each took");
    app.add_option("--sweep", options.sweeps,
                   "numeric modes over a grid, streamed: name=from..to:count[:log] (repeatable)");
    // Every command honours the budgets: the options exist on each, bound to one budget.
    auto add_budget_options = [&](CLI::App* command) {
        command
            ->add_option("--max-terms", options.budget.max_terms,
                         "size budget: most terms in any expression of a symbolic stage")
            ->check(CLI::Range(std::size_t{1}, std::size_t{1} << 40))
            ->capture_default_str();
        command
            ->add_option("--max-seconds", options.budget.max_seconds, "time budget of each symbolic stage, in seconds")
            ->check(finite_number & CLI::Range(1e-3, 1e7))
            ->capture_default_str();
    };
    add_budget_options(&app);

    std::string check_path;
    CLI::App* check = app.add_subcommand("check", "parse and validate a scene only");
    check->add_option("SCENE", check_path, "the scene file")->required();

    run_options report_options;
    CLI::App* report = app.add_subcommand("report", "the whole derivation as a LaTeX document (-o FILE.tex or FILE.pdf)");
    report->add_option("SCENE", report_options.scene_path, "the scene file (`-` for standard input)")->required();
    report->add_option("-o,--output", report_options.output, "FILE.tex (figures beside it) or FILE.pdf (needs pdflatex)");
    report->add_option("--want", report_options.want, "products to derive, comma-separated (default: the scene's `want`)");
    report->add_option("--values", report_options.values, "a parameter point such as a=1,b=2.5 (repeatable)");
    report->add_option("--initial", report_options.initial, initial_help);
    report->add_flag("--project-initial", report_options.project_initial, project_initial_help);
    report->footer(products_help());

    motion_options simulate_options, workprecision_options;
    CLI::App* simulate = app.add_subcommand("simulate", "integrate the equations of motion from the initial state");
    CLI::App* workprecision = app.add_subcommand("workprecision", "error against run time, per method and tolerance");
    for (auto [sub, o] : {std::pair{simulate, &simulate_options}, std::pair{workprecision, &workprecision_options}}) {
        sub->add_option("SCENE", o->scene_path, "the scene file (`-` for standard input)")->required();
        sub->add_option("--values", o->values, "a parameter point such as a=1,b=2.5 (repeatable; later ones win)");
        sub->add_option("--initial", o->initial, initial_help);
        sub->add_flag("--project-initial", o->project_initial, project_initial_help);
        sub->add_option("--until", o->until, "end time (default: the scene's `simulate until`)")
            ->check(positive_number);
        sub->add_option("--plot", o->plot, "draw a plot with gnuplot: .svg, .png or .pdf, by the extension");
        sub->add_option("--format", o->format, "output format")->check(CLI::IsMember({"text", "latex", "json"}));
        sub->add_flag("--latex-body", o->latex_body, latex_body_help);
        sub->add_option("-o,--output", o->output, "write the output to this file");
        sub->add_flag("--interpret", o->interpret,
                      "evaluate the equations with the interpreter (default: compiled to machine code by the "
                      "system's C compiler, when there is one)");
        sub->add_flag("--timings", o->timings, "show the run time and the stages' times");
    }
    simulate->add_option("--method", simulate_options.method,
                         "auto, dopri5, rkf78, dop853, bulirsch-stoer, bdf or implicit-midpoint")
        ->check(CLI::IsMember({"auto", "dopri5", "rkf78", "dop853", "bulirsch-stoer", "bdf", "implicit-midpoint"}));
    simulate->add_option("--tolerance", simulate_options.tolerance, "relative and absolute tolerance per step")
        ->check(finite_number & CLI::Range(1e-14, 0.5));
    simulate->add_option("--csv", simulate_options.csv, "write the trajectory as CSV");
    bool native_flag = false; // accepted for older scripts: native code is the default now
    simulate->add_flag("--native", native_flag, "compile the equations to machine code (the default)");

    response_options response_options;
    CLI::App* response =
        app.add_subcommand("response", "frequency response (Bode diagram) of one input to one coordinate");
    response->add_option("SCENE", response_options.scene_path, "the scene file (`-` for standard input)")->required();
    response->add_option("--input", response_options.input, "the input (an `input` line's name)")->required();
    response->add_option("--output", response_options.output, "the coordinate whose response is wanted")->required();
    response->add_option("--values", response_options.values,
                         "a parameter point such as a=1,b=2.5 (repeatable; later ones win)");
    response->add_option("--from", response_options.from,
                         "lowest drive frequency ω (default: a tenth of the smallest |s|)")
        ->check(positive_number);
    response->add_option("--to", response_options.to, "highest drive frequency ω (default: ten times the largest |s|)")
        ->check(positive_number);
    response->add_option("--points", response_options.points, "number of frequencies")
        ->check(CLI::Range(std::size_t{2}, std::size_t{10000000}))
        ->capture_default_str();
    response->add_flag("--linear", response_options.linear, "space the frequencies evenly (default: logarithmically)");
    response->add_option("--format", response_options.format, "output format")
        ->check(CLI::IsMember({"text", "csv", "json"}));
    response->add_option("-o,--output-file", response_options.output_path, "write the output to this file");
    response->add_option("--plot", response_options.plot,
                         "draw the Bode diagram with gnuplot: .svg, .png or .pdf, by the extension");

    export_options export_options;
    CLI::App* exporter =
        app.add_subcommand("export", "the equations of motion as C, Python or MATLAB/Octave code (docs/export.md)");
    exporter->add_option("SCENE", export_options.scene_path, "the scene file (`-` for standard input)")->required();
    exporter->add_option("--to", export_options.target, "c, python or octave")
        ->required()
        ->check(CLI::IsMember({"c", "python", "octave"}));
    exporter->add_option("-o,--output", export_options.folder, "the folder to write into (made if missing)")
        ->capture_default_str();
    exporter->add_option("--name", export_options.name, "the name of the functions and files (default: the scene "
                                                        "file's stem)");
    exporter->add_option("--values", export_options.values,
                         "a parameter point such as a=1,b=2.5: the defaults of the parameters (later ones win)");

    ensemble_options ensemble_options;
    CLI::App* ensemble = app.add_subcommand(
        "ensemble", "many runs at once over a grid of initial values and parameters, on all cores (and MPI)");
    ensemble->add_option("SCENE", ensemble_options.scene_path, "the scene file (`-` for standard input)")->required();
    ensemble->add_option("--grid", ensemble_options.grid,
                         "the grid: \"name=from..to:count[:log], ...\" over coordinates (initial values), "
                         "velocities (q') and parameters")
        ->required();
    ensemble->add_option("--until", ensemble_options.until, "end time of every run (default: the scene's `simulate until`)")
        ->check(positive_number);
    ensemble->add_option("--measure", ensemble_options.measure,
                         "final, flip_time, flip_time:COORDINATE, max_lyapunov or floquet_stable")
        ->capture_default_str();
    ensemble->add_option("-o,--output", ensemble_options.output, "FILE.csv, FILE.json or FILE.png (default: CSV on standard output)");
    ensemble->add_option("--threads", ensemble_options.threads, "threads per process (default: all cores)")
        ->check(CLI::Range(std::size_t{1}, std::size_t{4096}));
    ensemble->add_option("--tolerance", ensemble_options.tolerance,
                         "target of each run's relative error (default: the scene's, else 1e-9)")
        ->check(finite_number & CLI::Range(1e-14, 0.5));
    ensemble->add_option("--random", ensemble_options.random,
                         "N random points, uniform in the --grid ranges (name=from..to[:log]) instead of the grid")
        ->check(CLI::Range(std::size_t{1}, std::size_t{1000000000000}));
    ensemble->add_option("--seed", ensemble_options.seed, "seed of --random (default 1)");
    ensemble->add_flag("--resume", ensemble_options.resume, "continue the CSV file of an interrupted run (-o FILE.csv)");
    ensemble
        ->add_option("--mpi-timeout", ensemble_options.mpi_timeout,
                     "under MPI: seconds a process may send nothing before the run ends, naming it")
        ->check(finite_number & CLI::Range(1.0, 1e6))
        ->capture_default_str();
    ensemble->add_option("--values", ensemble_options.values, "a parameter point such as a=1,b=2.5 (repeatable; later ones win)");
    ensemble->add_option("--initial", ensemble_options.initial, initial_help);
    ensemble->add_flag("--interpret", ensemble_options.interpret,
                       "evaluate the equations with the interpreter (default: machine code by the system's C compiler)");

    poincare_options poincare_options;
    CLI::App* poincare = app.add_subcommand(
        "poincare", "a Poincaré section: the crossings of many orbits at one energy, on all cores (docs/pictures.md)");
    poincare->add_option("SCENE", poincare_options.scene_path, "the scene file (`-` for standard input)")->required();
    poincare->add_option("--section", poincare_options.section, "the section: \"q = level\" or \"q = level, q' > 0\"")
        ->required();
    poincare->add_option("--axes", poincare_options.axes,
                         "the picture's two axes: coordinates or velocities other than the section's, such as \"y, y'\" "
                         "(default: the first other coordinate and its velocity)");
    poincare->add_option("--energy", poincare_options.energy, "the energy of every orbit")
        ->required()
        ->check(finite_number);
    poincare->add_option("--orbits", poincare_options.orbits, "orbits, each started on the section")
        ->check(CLI::Range(std::size_t{1}, std::size_t{10000000}))
        ->capture_default_str();
    poincare->add_option("--crossings", poincare_options.crossings, "crossings per orbit, at most (the start counts)")
        ->check(CLI::Range(std::size_t{1}, std::size_t{100000000}))
        ->capture_default_str();
    poincare->add_option("--until", poincare_options.until, "the longest time of an orbit")
        ->check(positive_number)
        ->capture_default_str();
    poincare->add_option("--tolerance", poincare_options.tolerance, "target of each orbit's relative error (default 1e-9)")
        ->check(finite_number & CLI::Range(1e-14, 0.5));
    poincare->add_option("--seed", poincare_options.seed, "seed of the orbits' starts (default 1)");
    poincare->add_option("--threads", poincare_options.threads, "threads (default: all cores)")
        ->check(CLI::Range(std::size_t{1}, std::size_t{4096}));
    poincare->add_option("-o,--output", poincare_options.output,
                         "FILE.csv, or a picture FILE.svg, FILE.png or FILE.pdf (default: CSV on standard output)");
    poincare->add_option("--values", poincare_options.values,
                         "a parameter point such as a=1,b=2.5 (repeatable; later ones win)");
    poincare->add_flag("--interpret", poincare_options.interpret,
                       "evaluate the equations with the interpreter (default: machine code by the system's C compiler)");

    phase_options phase_options;
    CLI::App* phase = app.add_subcommand(
        "phase", "a phase portrait: q against q' over a grid of energies, with separatrices (docs/pictures.md)");
    phase->add_option("SCENE", phase_options.scene_path, "the scene file (`-` for standard input)")->required();
    phase->add_option("--coordinate", phase_options.coordinate, "the coordinate drawn (default: the first)");
    phase->add_option("--levels", phase_options.levels, "energies drawn between the minimum and the top")
        ->check(CLI::Range(std::size_t{1}, std::size_t{200}))
        ->capture_default_str();
    phase->add_option("-o,--output", phase_options.output, "FILE.svg, FILE.png or FILE.pdf, or FILE.csv (the grid)")
        ->required();
    phase->add_option("--values", phase_options.values, "a parameter point such as a=1,b=2.5 (repeatable; later ones win)");

    animate_options animate_options;
    CLI::App* animate = app.add_subcommand(
        "animate", "the motion as a self-contained HTML player or a video (docs/pictures.md)");
    animate->add_option("SCENE", animate_options.scene_path, "the scene file (`-` for standard input)")->required();
    animate->add_option("-o,--output", animate_options.output, "FILE.html (or .mp4, .gif: with ffmpeg)")->required();
    animate->add_option("--fps", animate_options.fps, "HTML: frames per unit of simulated time; videos: frames per second of video")
        ->check(positive_number & CLI::Range(0.1, 1000.0))
        ->capture_default_str();
    animate->add_option("--speed", animate_options.speed, "simulated time per second of playing")
        ->check(positive_number)
        ->capture_default_str();
    animate->add_option("--trail", animate_options.trail, "seconds of path drawn behind each point")
        ->check(finite_number & CLI::Range(0.0, 1e6))
        ->capture_default_str();
    animate->add_option("--view", animate_options.view, "xy, xz or 3d (default: xy for planar scenes, else 3d)");
    animate->add_option("--until", animate_options.until, "the length in simulated time (default: the scene's `simulate until`)")
        ->check(positive_number);
    animate->add_option("--tolerance", animate_options.tolerance, "target of the relative error (default: the scene's, or 1e-9)")
        ->check(finite_number & CLI::Range(1e-14, 0.5));
    animate->add_option("--values", animate_options.values, "a parameter point such as a=1,b=2.5 (repeatable; later ones win)");
    animate->add_option("--initial", animate_options.initial, initial_help);
    animate->add_flag("--project-initial", animate_options.project_initial, project_initial_help);
    animate->add_flag("--interpret", animate_options.interpret,
                      "evaluate the equations with the interpreter (default: machine code by the system's C compiler)");

    for (CLI::App* command : {report, simulate, workprecision, response, ensemble, exporter, poincare, phase, animate})
        add_budget_options(command);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        // CLI11 quotes the offending argument: printed through printable(), so that a control
        // sequence typed into an option does not reach the terminal.
        std::ostringstream out, err;
        int code = app.exit(error, out, err);
        std::cout << lagrange::printable(out.str());
        std::cerr << lagrange::printable(err.str());
        return code == 0 ? exit_ok : exit_bad_input;
    }

    if (check->parsed())
        return check_scene(check_path);
    if (report->parsed())
        return report_scene(report_options, options.budget);
    if (simulate->parsed())
        return motion_command(simulate_options, lagrange::product::simulation, options.budget);
    if (workprecision->parsed())
        return motion_command(workprecision_options, lagrange::product::workprecision, options.budget);
    if (response->parsed())
        return response_command(response_options, options.budget);
    if (ensemble->parsed())
        return ensemble_command(ensemble_options, options.budget);
    if (exporter->parsed())
        return export_command(export_options, options.budget);
    if (poincare->parsed())
        return poincare_command(poincare_options, options.budget);
    if (phase->parsed())
        return phase_command(phase_options, options.budget);
    if (animate->parsed())
        return animate_command(animate_options, options.budget);
    if (options.scene_path.empty()) {
        std::cerr << app.help();
        return exit_bad_input;
    }
    return analyze_scene(options);
}

} // namespace

int main(int argc, char** argv)
{
    lagrange::guard_standard_streams();
    // SIGINT and SIGTERM remove temporary files and end the compiler: exit 130 or 143.
    lagrange::install_signal_cleanup();
    // --max-seconds holds even inside a GiNaC call that cannot be interrupted.
    lagrange::start_budget_watchdog("lagrange: error: ", exit_failed, lagrange::clean_up_registered);
    try {
        return run(argc, argv);
    } catch (const lagrange::scene_error& error) {
        std::cerr << lagrange::format_error(error);
        return exit_bad_input;
    } catch (const usage_error& error) {
        std::cerr << "lagrange: error: " << lagrange::printable(error.what()) << '\n';
        return exit_bad_input;
    } catch (const lagrange::file_error& error) {
        std::cerr << "lagrange: error: " << lagrange::printable(error.what()) << '\n';
        return exit_bad_input;
    } catch (const lagrange::computation_error& error) {
        std::cerr << "lagrange: error: " << lagrange::printable(error.what()) << '\n';
        return exit_failed;
    } catch (const std::bad_alloc&) {
        std::cerr << "lagrange: error: out of memory\n";
        return exit_failed;
    } catch (const std::exception& error) {
        std::cerr << "lagrange: error: the computation failed (" << lagrange::printable(error.what()) << ")\n";
        return exit_failed;
    }
}
