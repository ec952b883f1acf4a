// SPDX-License-Identifier: GPL-2.0-or-later
/** @file report.h
 *  The derivation report: a complete LaTeX document that reads like a careful
 *  solution (the scene as written, T/V/L as built and simplified, the equations
 *  as M(q)q̈ + … = 0, equilibria, T and V, the characteristic polynomial, the
 *  modes, limits, numeric tables) with gnuplot figures. It prints results and
 *  never derives mechanics itself. */
#pragma once

#include "engine/analysis.h"
#include "scene/source.h"

#include <functional>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace lagrange {

struct report_options {
    bool plots = true;          ///< draw figures with gnuplot (left out with a sentence if it is missing)
    std::string figure_prefix;  ///< file names of the figures start with this (e.g. "double_pendulum-")
};

/// A file the document includes (a figure), written next to the .tex file.
struct report_file {
    std::string name;  ///< file name, no folder
    std::string bytes;
};

struct report_document {
    std::string latex;                ///< the complete document
    std::vector<report_file> figures; ///< the files it includes
};

class report_writer;

/// One section of the report. `applies` says whether the analysis has what it
/// prints (and the scene asked for it); `write` prints it.
struct report_section {
    std::string name;
    std::function<bool(const analysis&)> applies;
    std::function<void(report_writer&)> write;
};

/// What section writers print with: the output stream, the analysis, and the
/// building blocks (displays that break across lines, figures through gnuplot).
class report_writer {
public:
    report_writer(const analysis& result, const source_text& source, const report_options& options);

    const analysis& result() const { return result_; }
    const model& scene() const { return *result_.scene; }
    const source_text& source() const { return source_; }
    std::ostream& out() { return out_; }

    /// Prose: LaTeX's special characters escaped.
    report_writer& text(const std::string& prose);
    /// Raw LaTeX, as is.
    report_writer& latex(const std::string& code);
    /// `lhs relation e` as a display, broken across lines when long.
    void display(const std::string& lhs, const GiNaC::ex& e, const std::string& rhs = "",
                 const std::string& relation = "=");
    /// A display of already printed LaTeX terms.
    void display_terms(const std::string& lhs, const std::vector<std::string>& terms, const std::string& rhs = "",
                       const std::string& relation = "=");
    /// One row of a group of displays.
    struct row {
        std::string lhs;
        std::vector<std::string> terms;
        std::string rhs;
        std::string relation = "=";
    };
    /// Several displays in one aligned block, each broken across lines where long (never scaled).
    void display_rows(const std::vector<row>& rows);
    /// `lhs = (matrix)`; one wider than the page names its long entries and lists them below.
    void display_matrix(const std::string& lhs, const GiNaC::matrix& m);

    /// Runs `script` (gnuplot commands that draw on the pdfcairo terminal the
    /// writer sets up, `width_cm` by `height_cm`) and includes the figure with
    /// `caption`. Without gnuplot, a sentence says the figure is left out.
    /// Returns whether the figure was made.
    bool figure(const std::string& name, const std::string& script, double width_cm, double height_cm,
                const std::string& caption);

    /// LaTeX of a symbol name (θ̇ -> \dot{\theta}).
    static std::string name(const std::string& symbol_name);
    /// LaTeX of an expression (deterministic).
    static std::string math(const GiNaC::ex& e);
    /// LaTeX of a double, `1.5\times10^{-20}`, to `digits` significant digits (0: shortest exact).
    static std::string number(double x, int digits = 0);

    report_document finish();

private:
    const analysis& result_;
    const source_text& source_;
    const report_options& options_;
    std::ostringstream out_;
    std::vector<report_file> figures_;
    int gnuplot_state_ = 0; ///< 0 unknown, 1 available, -1 missing
};

/// The sections in document order. The rigid-body (inertia, Euler's equations)
/// and simulation (beats, polhode, work-precision) sections are added here as
/// further entries by their own files.
const std::vector<report_section>& report_sections();

/// Builds the whole report of `result` (the analysis of the scene in `source`).
report_document build_report(const analysis& result, const source_text& source, const report_options& options = {});

/// Compiles the report with pdflatex (twice, in a private temporary folder, with
/// the figures beside it) and returns the PDF. Throws computation_error if
/// pdflatex is missing or fails (with the first LaTeX error).
std::string compile_report(const report_document& document);

} // namespace lagrange
