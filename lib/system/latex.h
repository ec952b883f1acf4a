// SPDX-License-Identifier: GPL-2.0-or-later
/** @file latex.h
 *  Compiling a LaTeX document to PDF with pdflatex, in a private folder
 *  (system/external.h: an argument vector, no shell). */
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace lagrange {

/// Compiles `latex` with pdflatex (twice, so that references settle; dates from
/// SOURCE_DATE_EPOCH) beside `files` (name, bytes) and returns the PDF. With `log`, the
/// last run's log is stored there. Throws computation_error if pdflatex is missing or
/// fails (with the first LaTeX error).
std::string compile_latex(const std::string& latex, const std::vector<std::pair<std::string, std::string>>& files = {},
                          std::string* log = nullptr);

/// The first LaTeX error of a pdflatex log (the line starting with `!` and the next two),
/// or "see its log".
std::string first_latex_error(const std::string& log);

} // namespace lagrange
