// SPDX-License-Identifier: GPL-2.0-or-later
/** @file module.cpp
 *  The compiled part of the Python module, `lagrange._lagrange`: loads a scene and runs the
 *  engine in process, returning each document (JSON, text, LaTeX) as a string. The
 *  package's Python code (python/lagrange/) turns the JSON into SymPy expressions and numpy
 *  arrays; the JSON writer is the library's stable representation of every result. */
#include "core/errors.h"
#include "core/model.h"
#include "engine/analysis.h"
#include "engine/pictures.h"
#include "output/document.h"
#include "output/animation_output.h"
#include "output/export_code.h"
#include "output/poincare_output.h"
#include "scene/lower.h"
#include "scene/source.h"
#include "system/files.h"
#include "system/signals.h"

#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <lagrange/version.h>

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <functional>
#include <mutex>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

namespace py = pybind11;

namespace {

/// What one run of the engine is asked for: the Python keyword arguments, passed on as is.
struct run_request {
    std::vector<std::string> want;   ///< product names; empty: the scene's `want` line or all it supports
    std::vector<std::string> values;  ///< `values` points, each "a=1,b=2"
    std::vector<std::string> initial; ///< initial values, each "theta=0.1, phi'=0"
    std::optional<double> until;
    std::optional<std::string> method;
    std::optional<double> tolerance;
    bool estimate_error = true;
    bool native = true;
    std::size_t max_terms = lagrange::budget_limits{}.max_terms;
    double max_seconds = lagrange::budget_limits{}.max_seconds;
    bool project_initial = false; ///< start from an initial state off the constraints projected onto them
};

/// GiNaC is not thread-safe: one load at a time, whichever Python thread asks. A fork
/// (ours, or the user's multiprocessing) waits for it, so that the child's copy of the
/// engine is whole and its mutex free (pthread_atfork in the module's init).
std::mutex engine;

/// `loaded` with the `values` points and initial values given from Python. Values replace the
/// scene's `values` lines (the command line's add to them).
lagrange::model with_values(const lagrange::model& loaded, const std::vector<std::string>& values,
                            const std::vector<std::string>& initial = {})
{
    lagrange::model scene = loaded;
    if (!values.empty())
        scene.values.clear();
    for (const std::string& v : values)
        lagrange::add_values(scene, v, "values=");
    for (const std::string& v : initial)
        lagrange::add_initial(scene, v, "initial=");
    return scene;
}

/// One run of the engine (in the child process of run_in_child).
std::string run(const lagrange::model& loaded, const run_request& request, const std::string& format, bool timings)
{
    lagrange::model scene = with_values(loaded, request.values, request.initial);
    std::set<lagrange::product> wanted;
    for (const std::string& name : request.want) {
        std::set<lagrange::product> one = lagrange::parse_want_list(name);
        wanted.insert(one.begin(), one.end());
    }
    lagrange::budget_limits limits;
    limits.max_terms = request.max_terms;
    limits.max_seconds = request.max_seconds;
    lagrange::simulation_settings settings;
    settings.until = request.until;
    settings.method = request.method;
    settings.tolerance = request.tolerance;
    settings.estimate_error = request.estimate_error;
    settings.project_initial = request.project_initial;
    settings.native = request.native;
    lagrange::analysis result = lagrange::analyze(scene, wanted, limits, settings);
    lagrange::document_options options;
    options.timings = timings;
    return lagrange::document_text(result, format, options);
}

/// Raises the package's own exception class `name` (lagrange/errors.py) built from `args`.
void raise(const char* name, const py::tuple& args)
{
    py::object type = py::module_::import("lagrange.errors").attr(name);
    py::object error = type(*args);
    PyErr_SetObject(type.ptr(), error.ptr());
}

// ---- one run in a child process --------------------------------------------------------
// Each document is computed in a forked child, as the command line computes it: the
// budget watchdog may end the child (as it ends the command line) when one GiNaC call
// overruns --max-seconds, and Ctrl-C in Python ends the child within a poll interval,
// where a step inside GiNaC could not be interrupted in this process.

/// The exit code of a child that the budget watchdog ended.
constexpr int watchdog_exit = 3;

/// The command line's option names in a message, as Python's argument names.
std::string python_names(std::string message)
{
    for (auto [option, argument] : {std::pair{"--max-seconds", "max_seconds"}, std::pair{"--max-terms", "max_terms"}}) {
        for (std::size_t at = message.find(option); at != std::string::npos; at = message.find(option, at))
            message.replace(at, std::strlen(option), argument);
    }
    return message;
}

/// What the child sends back: a kind ("document" or an exception class of the package)
/// and its fields, each as an 8-byte length and the bytes (documents may hold any byte).
void put_field(std::string& out, const std::string& field)
{
    std::uint64_t size = field.size();
    out.append(reinterpret_cast<const char*>(&size), sizeof size);
    out += field;
}

std::vector<std::string> fields_of(const std::string& in)
{
    std::vector<std::string> fields;
    std::size_t at = 0;
    while (at + sizeof(std::uint64_t) <= in.size()) {
        std::uint64_t size = 0;
        std::memcpy(&size, in.data() + at, sizeof size);
        at += sizeof size;
        if (size > in.size() - at)
            break;
        fields.push_back(in.substr(at, size));
        at += size;
    }
    return fields;
}

/// The child's message: what `work` returned, or the library error it met, as fields.
std::string outcome_of(const std::function<std::string()>& work)
{
    std::string out;
    try {
        std::string document = work();
        put_field(out, "document");
        put_field(out, document);
    } catch (const lagrange::scene_error& error) {
        const lagrange::source_location& where = error.where();
        for (const std::string& f : {std::string("SceneError"), where.file, std::to_string(where.line),
                                     std::to_string(where.column), std::string(error.what()),
                                     lagrange::format_error(error)})
            put_field(out, f);
    } catch (const lagrange::budget_exceeded& error) {
        for (const std::string& f : {std::string("BudgetExceeded"), std::string(error.what()), error.stage()})
            put_field(out, f);
    } catch (const lagrange::computation_error& error) {
        put_field(out, "ComputationError");
        put_field(out, error.what());
    } catch (const std::invalid_argument& error) {
        put_field(out, "ValueError"); // a request that cannot be met (a Poincaré energy below the minimum)
        put_field(out, error.what());
    } catch (const std::exception& error) {
        put_field(out, "OSError"); // lagrange::file_error, and what else a run may meet
        put_field(out, error.what());
    }
    return out;
}

void write_all(int fd, const std::string& bytes)
{
    for (std::size_t done = 0; done < bytes.size();) {
        ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return;
        done += static_cast<std::size_t>(n);
    }
}

/// Ends the child: SIGTERM first (its handlers remove temporary files and end its own
/// children, the compiler or gnuplot), SIGKILL if it is still there after a second.
void end_child(pid_t child)
{
    ::kill(child, SIGTERM);
    for (int k = 0; k < 100; ++k) {
        if (::waitpid(child, nullptr, WNOHANG) == child)
            return;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    ::kill(child, SIGKILL);
    ::waitpid(child, nullptr, 0);
}

/// Runs `work` (the engine) in a child process and returns what it returned; raises the
/// package's exception for a library error, KeyboardInterrupt (or what a signal handler
/// raises) when Python has a signal pending. Called with the GIL held.
std::string run_in_child(const std::function<std::string()>& work)
{
    int result_pipe[2];
    int error_pipe[2];
    if (::pipe2(result_pipe, O_CLOEXEC) != 0)
        throw lagrange::computation_error(std::string("cannot start the engine's process: ") + std::strerror(errno));
    if (::pipe2(error_pipe, O_CLOEXEC) != 0) {
        ::close(result_pipe[0]);
        ::close(result_pipe[1]);
        throw lagrange::computation_error(std::string("cannot start the engine's process: ") + std::strerror(errno));
    }
    const pid_t child = ::fork();
    if (child == 0) {
        // The child: no Python from here on, and _exit, so that nothing of Python's runs twice.
        ::dup2(error_pipe[1], STDERR_FILENO);
        lagrange::install_signal_cleanup();
        lagrange::start_budget_watchdog("", watchdog_exit, lagrange::clean_up_registered);
        write_all(result_pipe[1], outcome_of(work));
        ::_exit(0);
    }
    ::close(result_pipe[1]);
    ::close(error_pipe[1]);
    if (child < 0) {
        ::close(result_pipe[0]);
        ::close(error_pipe[0]);
        throw lagrange::computation_error(std::string("cannot start the engine's process: ") + std::strerror(errno));
    }
    std::string result, errors;
    bool interrupted = false;
    {
        py::gil_scoped_release unlocked;
        pollfd fds[2] = {{result_pipe[0], POLLIN, 0}, {error_pipe[0], POLLIN, 0}};
        std::string* sinks[2] = {&result, &errors};
        int open = 2;
        char buffer[65536];
        while (open > 0) {
            if (::poll(fds, 2, 50) > 0) {
                for (int k = 0; k < 2; ++k) {
                    if (fds[k].fd < 0 || !(fds[k].revents & (POLLIN | POLLHUP | POLLERR)))
                        continue;
                    ssize_t n = ::read(fds[k].fd, buffer, sizeof buffer);
                    if (n > 0) {
                        sinks[k]->append(buffer, static_cast<std::size_t>(n));
                    } else if (n == 0 || errno != EINTR) {
                        ::close(fds[k].fd);
                        fds[k].fd = -1;
                        --open;
                    }
                }
            }
            py::gil_scoped_acquire held;
            if (PyErr_CheckSignals() != 0) {
                interrupted = true;
                break;
            }
        }
        for (const pollfd& f : fds)
            if (f.fd >= 0)
                ::close(f.fd);
    }
    if (interrupted) {
        end_child(child);
        throw py::error_already_set(); // KeyboardInterrupt, as the signal handler raised it
    }
    int status = 0;
    while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
    std::vector<std::string> fields = fields_of(result);
    if (WIFEXITED(status) && WEXITSTATUS(status) == watchdog_exit) {
        std::string message = python_names(errors);
        while (!message.empty() && message.back() == '\n')
            message.pop_back();
        const std::size_t open_quote = message.find("the `");
        const std::size_t close_quote = message.find("` stage", open_quote == std::string::npos ? 0 : open_quote);
        std::string stage = open_quote != std::string::npos && close_quote != std::string::npos
                                ? message.substr(open_quote + 5, close_quote - open_quote - 5)
                                : "";
        raise("BudgetExceeded", py::make_tuple(message, stage));
        throw py::error_already_set();
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || fields.empty()) {
        std::string how = WIFSIGNALED(status) ? "was ended by signal " + std::to_string(WTERMSIG(status))
                                              : "stopped with exit code " + std::to_string(WEXITSTATUS(status));
        throw lagrange::computation_error("the engine's process " + how + (errors.empty() ? "" : ": " + errors));
    }
    if (!errors.empty()) // what the engine wrote to standard error (a compiler's complaint, say)
        py::module_::import("sys").attr("stderr").attr("write")(py::bytes(errors).attr("decode")("utf-8", "replace"));
    const std::string& kind = fields[0];
    if (kind == "document" && fields.size() == 2)
        return fields[1];
    if (kind == "SceneError" && fields.size() == 6)
        raise("SceneError", py::make_tuple(fields[1], std::stoi(fields[2]), std::stoi(fields[3]), fields[4], fields[5]));
    else if (kind == "BudgetExceeded" && fields.size() == 3)
        raise("BudgetExceeded", py::make_tuple(python_names(fields[1]), fields[2]));
    else if (kind == "ComputationError" && fields.size() == 2)
        raise("ComputationError", py::make_tuple(fields[1]));
    else if (kind == "OSError" && fields.size() == 2)
        PyErr_SetString(PyExc_OSError, fields[1].c_str());
    else if (kind == "ValueError" && fields.size() == 2)
        PyErr_SetString(PyExc_ValueError, fields[1].c_str());
    else
        throw lagrange::computation_error("the engine's process sent an unreadable result");
    throw py::error_already_set();
}

} // namespace

PYBIND11_MODULE(_lagrange, m)
{
    m.doc() = "The lagrange engine in process (the compiled part of the `lagrange` package).";
    m.attr("__version__") = LAGRANGE_VERSION_STRING;

    // Library errors become the package's exceptions: SceneError carries the file, line and
    // column; BudgetExceeded (a ComputationError) the stage.
    py::register_exception_translator([](std::exception_ptr pointer) {
        try {
            if (pointer)
                std::rethrow_exception(pointer);
        } catch (const lagrange::scene_error& error) {
            const lagrange::source_location& where = error.where();
            raise("SceneError", py::make_tuple(where.file, where.line, where.column, std::string(error.what()),
                                               lagrange::format_error(error)));
        } catch (const lagrange::budget_exceeded& error) {
            raise("BudgetExceeded", py::make_tuple(std::string(error.what()), error.stage()));
        } catch (const lagrange::computation_error& error) {
            raise("ComputationError", py::make_tuple(std::string(error.what())));
        } catch (const lagrange::file_error& error) {
            PyErr_SetString(PyExc_OSError, error.what());
        }
    });

    py::class_<lagrange::model>(m, "Model", "A loaded scene (lagrange::model).")
        .def_property_readonly("file", [](const lagrange::model& s) { return s.file; })
        .def_property_readonly("title", [](const lagrange::model& s) { return s.title; })
        .def_property_readonly("coordinates", [](const lagrange::model& s) { return lagrange::coordinate_names(s); })
        .def_property_readonly("parameters", [](const lagrange::model& s) { return lagrange::parameter_names(s); })
        .def(
            "export_code",
            [](const lagrange::model& scene, const std::string& target, const std::string& folder,
               const std::string& name, const std::vector<std::string>& values) {
                const std::optional<lagrange::export_target> chosen = lagrange::export_target_named(target);
                if (!chosen)
                    throw py::value_error("target must be \"c\", \"python\" or \"octave\", not \"" + target + "\"");
                if (!lagrange::valid_export_name(name))
                    throw py::value_error("name must be an identifier that is no keyword of C, Python or Octave, "
                                          "not \"" + name + "\"");
                return run_in_child([&] {
                    const lagrange::model copy = with_values(scene, values);
                    std::vector<std::pair<std::string, std::string>> files;
                    std::string written;
                    for (const lagrange::exported_file& file :
                         lagrange::export_scene(copy, *chosen, name, LAGRANGE_VERSION_STRING)) {
                        files.emplace_back(file.name, file.text);
                        written += file.name + "\n";
                    }
                    lagrange::write_files(folder, files);
                    return written;
                });
            },
            py::arg("target"), py::arg("folder"), py::arg("name"), py::arg("values") = std::vector<std::string>{},
            "Writes the equations of motion as C, Python or Octave code into `folder`; returns the file names.")
        .def_property_readonly("warnings",
                               [](const lagrange::model& s) {
                                   std::vector<std::string> texts;
                                   for (const lagrange::scene_warning& w : s.warnings)
                                       texts.push_back(lagrange::format_warning(w));
                                   return texts;
                               })
        .def(
            "document",
            [](const lagrange::model& scene, const std::string& format, const std::vector<std::string>& want,
               const std::vector<std::string>& values, const std::vector<std::string>& initial,
               std::optional<double> until, std::optional<std::string> method, std::optional<double> tolerance,
               bool estimate_error, bool native, std::size_t max_terms, double max_seconds, bool timings,
               bool project_initial) {
                run_request request{want,      values,         initial, until,     method,     tolerance,
                                    estimate_error, native,  max_terms, max_seconds, project_initial};
                lagrange::require_document_format(format); // ValueError (pybind11), before the fork
                return run_in_child([&] { return run(scene, request, format, timings); });
            },
            py::arg("format"), py::arg("want") = std::vector<std::string>{},
            py::arg("values") = std::vector<std::string>{}, py::arg("initial") = std::vector<std::string>{},
            py::arg("until") = py::none(),
            py::arg("method") = py::none(), py::arg("tolerance") = py::none(), py::arg("estimate_error") = true,
            py::arg("native") = true, py::arg("max_terms") = lagrange::budget_limits{}.max_terms,
            py::arg("max_seconds") = lagrange::budget_limits{}.max_seconds, py::arg("timings") = false,
            py::arg("project_initial") = false,
            "Runs the engine and returns the document (json, text or latex) as a string.");

    m.def(
        "poincare",
        [](const lagrange::model& loaded, const std::string& section_text, const std::vector<std::string>& values,
           const lagrange::poincare_settings& settings, std::size_t max_terms, double max_seconds) {
            return run_in_child([&] {
                const lagrange::model scene = with_values(loaded, values);
                lagrange::budget_limits limits;
                limits.max_terms = max_terms;
                limits.max_seconds = max_seconds;
                const lagrange::poincare_section section = lagrange::parse_poincare_section(section_text, scene);
                const lagrange::poincare_result result = lagrange::poincare_scene(scene, section, settings, limits);
                // The command line's CSV (shortest round-trip numbers) and its summary.
                std::ostringstream csv;
                lagrange::write_poincare_csv(csv, result);
                nlohmann::json out{{"csv", csv.str()},
                                   {"coordinates", result.coordinates},
                                   {"no_crossings", result.no_crossings},
                                   {"summary", lagrange::poincare_summary_text(result)}};
                return out.dump();
            });
        },
        py::arg("model"), py::arg("section"), py::arg("values"), py::arg("settings"),
        py::arg("max_terms") = lagrange::budget_limits{}.max_terms,
        py::arg("max_seconds") = lagrange::budget_limits{}.max_seconds,
        "The Poincaré section of `lagrange poincare` as JSON: its CSV, coordinates, summary, and why "
        "there are no crossings (or \"\").");

    m.def(
        "animate",
        [](const lagrange::model& loaded, const std::vector<std::string>& values, const std::vector<std::string>& initial,
           std::optional<double> until, double fps, double tolerance, bool native, double speed, double trail,
           const std::string& view, bool project_initial) {
            if (!lagrange::known_animation_view(view))
                throw py::value_error("view must be \"xy\", \"xz\" or \"3d\", not \"" + view + "\"");
            return run_in_child([&] {
                const lagrange::model scene = with_values(loaded, values, initial);
                lagrange::animation_settings settings;
                settings.fps = fps;
                settings.until = until;
                settings.tolerance = tolerance;
                settings.native = native;
                settings.project_initial = project_initial;
                const lagrange::animation_frames frames = lagrange::animate_scene(scene, settings, {});
                return lagrange::animation_html(frames, {speed, trail, view}, scene.title.empty() ? scene.file : scene.title);
            });
        },
        py::arg("model"), py::arg("values"), py::arg("initial"), py::arg("until"), py::arg("fps"), py::arg("tolerance"),
        py::arg("native"), py::arg("speed"), py::arg("trail"), py::arg("view"), py::arg("project_initial") = false,
        "The self-contained HTML player of `lagrange animate`, as a string.");

    py::class_<lagrange::poincare_settings>(m, "PoincareSettings", "lagrange::poincare_settings")
        .def(py::init<>())
        .def_readwrite("energy", &lagrange::poincare_settings::energy)
        .def_readwrite("orbits", &lagrange::poincare_settings::orbits)
        .def_readwrite("crossings", &lagrange::poincare_settings::crossings)
        .def_readwrite("until", &lagrange::poincare_settings::until)
        .def_readwrite("tolerance", &lagrange::poincare_settings::tolerance)
        .def_readwrite("seed", &lagrange::poincare_settings::seed)
        .def_readwrite("threads", &lagrange::poincare_settings::threads)
        .def_readwrite("native", &lagrange::poincare_settings::native);

    m.def(
        "load",
        [](const std::string& file, const std::string& text) {
            if (text.size() > lagrange::max_scene_bytes)
                throw lagrange::scene_error({file, 1, 1}, "the scene is larger than " +
                                                              std::to_string(lagrange::max_scene_bytes >> 20) + " MiB");
            py::gil_scoped_release unlocked;
            std::lock_guard<std::mutex> hold(engine);
            return lagrange::load_model(lagrange::source_text(file, text));
        },
        py::arg("file"), py::arg("text"),
        "Parses and checks a scene; `use` files are read relative to the folder of `file`.");

    m.def(
        "read_scene",
        [](const std::string& path, double wait_seconds) {
            py::gil_scoped_release unlocked;
            return lagrange::read_bounded(path, lagrange::max_scene_bytes, wait_seconds);
        },
        py::arg("path"), py::arg("wait_seconds"),
        "A scene file's text, as the command line reads it: at most 64 MiB, and a pipe or device "
        "that gives no data for `wait_seconds` is refused (OSError).");

    // A fork waits for a load in progress and leaves the child's mutex free (see `engine`).
    static bool at_fork = [] {
        return pthread_atfork([] { engine.lock(); }, [] { engine.unlock(); }, [] { engine.unlock(); }) == 0;
    }();
    (void)at_fork;

    m.def("default_export_name", &lagrange::default_export_name, py::arg("scene_file"),
          "The default name of exported code: the scene file's stem made an identifier.");

    m.def("products", [] {
        std::vector<std::string> names;
        for (const auto& entry : lagrange::product_names())
            names.push_back(entry.second);
        return names;
    }, "The `want` items this version computes, in the spec's order.");
}
