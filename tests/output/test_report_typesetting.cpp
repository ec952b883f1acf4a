// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_report_typesetting.cpp
 *  Every example's report typeset like a textbook (issue 38): no formula and no figure label
 *  below 8 pt, and no line overfull by more than 1 pt. The sizes are measured, not read off
 *  the LaTeX source: a hook added before \begin{document} logs every box graphicx scales
 *  (\resizebox, \scalebox and \includegraphics all go through \Gscale@box) with the font
 *  size in force, and for an included figure the text sizes of its PDF (the Tm matrices of
 *  its content streams, inflated with zlib) times the scale it is shown at. TeX's own
 *  script sizes (8 pt for an exponent, 6 pt for an exponent's exponent in an 11 pt
 *  document) are a property of every textbook's mathematics and are not counted. */
#include "helpers/cli_runner.h"

#include <catch2/catch.hpp>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <regex>
#include <string>

using namespace lagrange_test;

namespace {

/// Logs each scaled box (`scaled X Y at SIZE`) and each included PDF (`graphic FILE`, just
/// before the scaled box that shows it).
const std::string size_hook = R"(\makeatletter
\let\lgcheckscale\Gscale@box
\long\def\Gscale@box#1[#2]#3{\typeout{lagrange-check: scaled #1 #2 at \f@size}\lgcheckscale{#1}[#2]{#3}}
\let\lgcheckinclude\Ginclude@pdftex
\def\Ginclude@pdftex#1{\typeout{lagrange-check: graphic #1}\lgcheckinclude{#1}}
\let\Ginclude@pdf\Ginclude@pdftex
\makeatother
)";

/// The stream `data` inflated, or empty if it is not a zlib stream.
std::string inflated(const std::string& data)
{
    z_stream z{};
    if (inflateInit(&z) != Z_OK)
        return "";
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
    z.avail_in = static_cast<uInt>(data.size());
    std::string out;
    char buffer[16384];
    int status = Z_OK;
    while (status == Z_OK) {
        z.next_out = reinterpret_cast<Bytef*>(buffer);
        z.avail_out = sizeof buffer;
        status = inflate(&z, Z_NO_FLUSH);
        out.append(buffer, sizeof buffer - z.avail_out);
    }
    inflateEnd(&z);
    return status == Z_STREAM_END ? out : "";
}

/// The smallest text size in a PDF's content streams, in pt: per text object the scale of
/// its Tm matrix times its Tf size (cairo writes `9 0 0 -9 x y Tm` and `/f 1 Tf`). Infinity
/// if it has no text.
double smallest_pdf_text(const std::string& pdf)
{
    static const std::regex tm(R"((-?[0-9.]+) (-?[0-9.]+) (-?[0-9.]+) (-?[0-9.]+) -?[0-9.]+ -?[0-9.]+ Tm)");
    static const std::regex tf(R"(/[^ ]+ (-?[0-9.]+) Tf)");
    double smallest = std::numeric_limits<double>::infinity();
    for (std::size_t at = pdf.find("stream"); at != std::string::npos; at = pdf.find("stream", at + 1)) {
        const std::size_t start = pdf.find('\n', at);
        const std::size_t end = pdf.find("endstream", at);
        if (start == std::string::npos || end == std::string::npos || (at >= 3 && pdf.compare(at - 3, 3, "end") == 0))
            continue;
        const std::string content = inflated(pdf.substr(start + 1, end - start - 1));
        for (std::size_t bt = content.find("BT"); bt != std::string::npos; bt = content.find("BT", bt + 2)) {
            const std::size_t et = content.find("ET", bt);
            const std::string text = content.substr(bt, et == std::string::npos ? std::string::npos : et - bt);
            std::smatch m, f;
            if (!std::regex_search(text, m, tm))
                continue;
            const double a = std::stod(m[1]), b = std::stod(m[2]), c = std::stod(m[3]), d = std::stod(m[4]);
            double size = std::sqrt(std::abs(a * d - b * c));
            if (std::regex_search(text, f, tf))
                size *= std::abs(std::stod(f[1]));
            smallest = std::min(smallest, size);
        }
        at = end;
    }
    return smallest;
}

struct typesetting {
    double smallest_formula = std::numeric_limits<double>::infinity(); ///< pt, scaled boxes only
    double smallest_label = std::numeric_limits<double>::infinity();   ///< pt, figure text as shown
    double widest_overfull = 0;                                        ///< pt
    int figures = 0;
    bool errors = false;
};

/// Compiles `tex` (its figures beside it) with the size hook and measures it.
typesetting measure(const std::string& tex)
{
    std::string source = read_file(tex);
    const std::size_t begin = source.find("\\begin{document}");
    REQUIRE(begin != std::string::npos);
    source.insert(begin, size_hook);
    const std::string folder = tex.substr(0, tex.rfind('/') + 1);
    const std::string hooked = temporary_file(tex.substr(tex.rfind('/') + 1, tex.size() - tex.rfind('/') - 5) + "-hooked.tex", source);
    int status = 0;
    const std::string log = compile_latex(hooked, status);
    typesetting t;
    t.errors = status != 0 || log.find("\n! ") != std::string::npos;
    static const std::regex line(R"(lagrange-check: (?:graphic (\S+\.pdf)|scaled (-?[0-9.]+) (-?[0-9.]+) at ([0-9.]+)))");
    std::string graphic;
    for (auto it = std::sregex_iterator(log.begin(), log.end(), line); it != std::sregex_iterator(); ++it) {
        const std::smatch& m = *it;
        if (m[1].matched) {
            graphic = m[1];
            continue;
        }
        const double scale = std::min(std::abs(std::stod(m[2])), std::abs(std::stod(m[3])));
        if (!graphic.empty()) {
            ++t.figures;
            t.smallest_label = std::min(t.smallest_label, smallest_pdf_text(read_file(folder + graphic)) * scale);
            graphic.clear();
        } else {
            t.smallest_formula = std::min(t.smallest_formula, scale * std::stod(m[4]));
        }
    }
    static const std::regex overfull(R"(Overfull \\hbox \(([0-9.]+)pt too wide\))");
    for (auto it = std::sregex_iterator(log.begin(), log.end(), overfull); it != std::sregex_iterator(); ++it)
        t.widest_overfull = std::max(t.widest_overfull, std::stod((*it)[1].str()));
    return t;
}

} // namespace

TEST_CASE("report typesetting: the size check finds a shrunk formula and an overfull line", "[report][latex][gnuplot][pdflatex]")
{
    // The check itself can fail: half of 10.95 pt is found, and a line 100 pt too wide.
    const std::string tex = temporary_file("shrunk.tex", "\\documentclass[11pt]{article}\n\\usepackage{graphicx}\n"
                                                         "\\begin{document}\n\\scalebox{0.5}{$x + y$}\n\n"
                                                         "\\noindent\\hbox to \\dimexpr\\linewidth+100pt\\relax{x\\hfil}\n"
                                                         "\\end{document}\n");
    const typesetting t = measure(tex);
    CHECK(!t.errors);
    CHECK(t.smallest_formula == Approx(5.475).margin(0.01));
    CHECK(t.widest_overfull == Approx(100).margin(0.5));
}

TEST_CASE("report typesetting: every example's report at 8 pt or more, no line overfull by 1 pt",
          "[report][latex][gnuplot][pdflatex]")
{
    int figures = 0;
    for (const std::string& scene : example_scenes()) {
        INFO(scene);
        std::string stem = scene.substr(scene.rfind('/') + 1);
        stem = stem.substr(0, stem.size() - 4);
        const std::string tex = temporary_file("typeset_" + stem + ".tex", "");
        const cli_result r = run_cli("report " + scene + " -o " + tex, "", 60);
        INFO(r.err);
        REQUIRE(r.exit_code == 0);
        const typesetting t = measure(tex);
        CHECK(!t.errors);
        CHECK(t.smallest_formula >= 8.0);
        CHECK(t.smallest_label >= 8.0);
        CHECK(t.widest_overfull <= 1.0);
        figures += t.figures;
    }
    // The figures were found and measured (a missing hook would measure nothing).
    CHECK(figures >= 10);
}
