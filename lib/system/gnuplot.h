// SPDX-License-Identifier: GPL-2.0-or-later
/** @file gnuplot.h
 *  Drawing with gnuplot: a script run in a private folder (system/external.h: an
 *  argument vector, no shell), the plot it writes read back. The figures of the report
 *  and the plots of `--plot` both go through here. */
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace lagrange {

/// Whether gnuplot is on $PATH.
bool gnuplot_available();

/// What a run of gnuplot gave.
struct gnuplot_run {
    bool drawn = false;     ///< gnuplot ran to the end with status 0
    bool timed_out = false;
    std::string plot;       ///< the bytes of the file the script wrote (when drawn)
    std::string log;        ///< gnuplot's messages (when not drawn)
};

/// Runs `script` with gnuplot in a private folder that holds `files` (name, bytes) and
/// reads back `plot_name`, which the script writes. `environment` entries (NAME=value)
/// are added to ours. Throws computation_error if the folder cannot be made or the plot
/// cannot be read after a run that succeeded.
gnuplot_run run_gnuplot(const std::string& script, const std::string& plot_name,
                        const std::vector<std::pair<std::string, std::string>>& files = {},
                        const std::vector<std::string>& environment = {});

/// A string literal for a gnuplot script that keeps every printable character: in single
/// quotes, where a backslash is literal, with a quote doubled (gnuplot's own escape) and
/// control characters, which would end the line of the script, dropped.
std::string gnuplot_string(const std::string& text);

/// The formats a plot is drawn in, chosen by the file's extension.
enum class plot_format { svg, png, pdf };

/// The format of a plot written to `path`: .svg, .png (gnuplot's pngcairo) or .pdf
/// (pdfcairo), in any case. Throws std::invalid_argument naming the extensions otherwise.
plot_format plot_format_of(const std::string& path);

/// The gnuplot lines that choose the terminal for `format` at `width` × `height` pixels
/// (a PDF at 96 pixels to the inch), with `text_mode` ("enhanced", "noenhanced" or ""),
/// and write to `plot_name`.
std::string gnuplot_terminal(plot_format format, int width, int height, const std::string& text_mode,
                             const std::string& plot_name);

/// Blanks the creation and modification dates cairo writes into a PDF (same length, so
/// the cross-reference offsets stay valid): a figure then depends on its script only.
std::string strip_pdf_dates(std::string pdf);

} // namespace lagrange
