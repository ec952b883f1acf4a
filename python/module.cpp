// SPDX-License-Identifier: GPL-2.0-or-later
/** @file module.cpp
 *  The compiled part of the Python module, `lagrange._lagrange`: loads a scene and runs the
 *  engine in process, returning each document (JSON, text, LaTeX) as a string. The
 *  package's Python code (python/lagrange/) turns the JSON into SymPy expressions and numpy
 *  arrays; the JSON writer is the library's stable representation of every result. */
#include "core/errors.h"
#include "core/model.h"
#include "engine/analysis.h"
#include "output/document.h"
#include "scene/lower.h"
#include "scene/source.h"
#include "system/files.h"

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <lagrange/version.h>

#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

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
};

/// GiNaC is not thread-safe: one load or analysis at a time, whichever Python thread asks.
std::mutex engine;

std::string run(const lagrange::model& loaded, const run_request& request, const std::string& format, bool timings)
{
    lagrange::require_document_format(format); // ValueError (pybind11), before the analysis
    std::lock_guard<std::mutex> hold(engine);
    lagrange::model scene = loaded;
    // Values given from Python replace the scene's `values` lines (the command line's add to them).
    if (!request.values.empty())
        scene.values.clear();
    for (const std::string& v : request.values)
        lagrange::add_values(scene, v, "values=");
    for (const std::string& v : request.initial)
        lagrange::add_initial(scene, v, "initial=");
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
               bool estimate_error, bool native, std::size_t max_terms, double max_seconds, bool timings) {
                run_request request{want,      values,         initial, until,     method,
                                    tolerance, estimate_error, native,  max_terms, max_seconds};
                py::gil_scoped_release unlocked;
                return run(scene, request, format, timings);
            },
            py::arg("format"), py::arg("want") = std::vector<std::string>{},
            py::arg("values") = std::vector<std::string>{}, py::arg("initial") = std::vector<std::string>{},
            py::arg("until") = py::none(),
            py::arg("method") = py::none(), py::arg("tolerance") = py::none(), py::arg("estimate_error") = true,
            py::arg("native") = true, py::arg("max_terms") = lagrange::budget_limits{}.max_terms,
            py::arg("max_seconds") = lagrange::budget_limits{}.max_seconds, py::arg("timings") = false,
            "Runs the engine and returns the document (json, text or latex) as a string.");

    m.def(
        "load",
        [](const std::string& file, const std::string& text) {
            py::gil_scoped_release unlocked;
            std::lock_guard<std::mutex> hold(engine);
            return lagrange::load_model(lagrange::source_text(file, text));
        },
        py::arg("file"), py::arg("text"),
        "Parses and checks a scene; `use` files are read relative to the folder of `file`.");

    m.def("products", [] {
        std::vector<std::string> names;
        for (const auto& entry : lagrange::product_names())
            names.push_back(entry.second);
        return names;
    }, "The `want` items this version computes, in the spec's order.");
}
