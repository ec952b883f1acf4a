// SPDX-License-Identifier: GPL-2.0-or-later
/** @file document.h
 *  Printers of a whole analysis: text for people, a LaTeX document, JSON.
 *  They take results and never compute mechanics. */
#pragma once

#include "engine/analysis.h"

#include <ostream>
#include <string>

namespace lagrange {

struct document_options {
    bool timings = false;    ///< include each stage's time (`--timings`)
    bool latex_body = false; ///< LaTeX: only the body (headings, prose, align* blocks) to paste into a paper
};

void write_text(std::ostream& out, const analysis& result, const document_options& options = {});

/// A complete LaTeX document (amsmath) that pdflatex compiles; with `latex_body`, only what
/// goes between \begin{document} and \end{document} (it needs amsmath).
void write_latex(std::ostream& out, const analysis& result, const document_options& options = {});

/// One JSON object with the keys of the spec (§4).
void write_json(std::ostream& out, const analysis& result, const document_options& options = {});

/// Throws std::invalid_argument unless `format` is one of document_text's: "text",
/// "latex" or "json" (a caller checks before the analysis that it will print).
void require_document_format(const std::string& format);

/// The document in `format` (see require_document_format).
std::string document_text(const analysis& result, const std::string& format, const document_options& options = {});

} // namespace lagrange
