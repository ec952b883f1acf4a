// SPDX-License-Identifier: GPL-2.0-or-later
/** @file gnuplot.cpp
 *  Drawing with gnuplot (see gnuplot.h). */
#include "system/gnuplot.h"

#include "core/errors.h"
#include "system/external.h"

#include <algorithm>
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

} // namespace lagrange
