// SPDX-License-Identifier: GPL-2.0-or-later
/** @file gnuplot.cpp
 *  Drawing with gnuplot (see gnuplot.h). */
#include "system/gnuplot.h"

#include "core/errors.h"
#include "system/external.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <stdexcept>
#include <cstddef>

namespace lagrange {

bool gnuplot_available() { return program_available("gnuplot"); }

gnuplot_run run_gnuplot(const std::string& script, const std::string& plot_name,
                        const std::vector<std::pair<std::string, std::string>>& files,
                        const std::vector<std::string>& environment)
{
    private_directory folder;
    for (const auto& [name, bytes] : files)
        folder.write(name, bytes);
    folder.write("plot.gp", script);
    const program_result run = run_program({"gnuplot", "plot.gp"}, folder.path(), "gnuplot.log", environment);
    gnuplot_run result;
    result.timed_out = run.timed_out;
    result.drawn = run.exit_code == 0;
    if (result.drawn) {
        result.plot = folder.read(plot_name);
    } else {
        try {
            result.log = folder.read("gnuplot.log");
        } catch (const computation_error&) {
        }
    }
    return result;
}

std::string gnuplot_string(const std::string& text)
{
    std::string out = "'";
    for (char c : text)
        if (c == '\'')
            out += "''";
        else if (static_cast<unsigned char>(c) >= 0x20 && c != 0x7f)
            out += c;
    return out + "'";
}

std::string strip_pdf_dates(std::string pdf)
{
    for (const char* key : {"/CreationDate", "/ModDate"}) {
        std::size_t at = 0;
        while ((at = pdf.find(key, at)) != std::string::npos) {
            std::size_t open = pdf.find('(', at);
            std::size_t close = open == std::string::npos ? open : pdf.find(')', open);
            if (close == std::string::npos || close - at > 64)
                break;
            std::fill(pdf.begin() + static_cast<std::ptrdiff_t>(at), pdf.begin() + static_cast<std::ptrdiff_t>(close) + 1,
                      ' ');
            at = close;
        }
    }
    return pdf;
}

plot_format plot_format_of(const std::string& path)
{
    const std::size_t dot = path.rfind('.');
    std::string extension = dot == std::string::npos || path.find('/', dot) != std::string::npos ? "" : path.substr(dot + 1);
    for (char& c : extension)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (extension == "svg")
        return plot_format::svg;
    if (extension == "png")
        return plot_format::png;
    if (extension == "pdf")
        return plot_format::pdf;
    throw std::invalid_argument("a plot is written as .svg, .png or .pdf, chosen by the file's extension, not `" +
                                path + "`");
}

std::string gnuplot_terminal(plot_format format, int width, int height, const std::string& text_mode,
                             const std::string& plot_name)
{
    const std::string mode = text_mode.empty() ? "" : " " + text_mode;
    std::string terminal;
    switch (format) {
    case plot_format::svg:
        terminal = "set terminal svg size " + std::to_string(width) + "," + std::to_string(height) + " dynamic" + mode +
                   " font 'sans,12'";
        break;
    case plot_format::png:
        terminal = "set terminal pngcairo size " + std::to_string(width) + "," + std::to_string(height) + mode +
                   " font 'sans,10'";
        break;
    case plot_format::pdf: {
        char size[64];
        std::snprintf(size, sizeof size, "%.4gin,%.4gin", width / 96.0, height / 96.0);
        terminal = std::string("set terminal pdfcairo size ") + size + mode + " color font 'sans,9'";
        break;
    }
    }
    return terminal + "\nset output " + gnuplot_string(plot_name) + "\n";
}

} // namespace lagrange
