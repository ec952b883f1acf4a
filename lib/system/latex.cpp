// SPDX-License-Identifier: GPL-2.0-or-later
/** @file latex.cpp
 *  Compiling LaTeX with pdflatex (see latex.h). */
#include "system/latex.h"

#include "core/errors.h"
#include "system/external.h"

namespace lagrange {

std::string compile_latex(const std::string& latex, const std::vector<std::pair<std::string, std::string>>& files,
                          std::string* log)
{
    if (!program_available("pdflatex"))
        throw computation_error("pdflatex is not installed, so the report cannot be written as PDF "
                                "(install texlive-latex-base, or write FILE.tex)");
    private_directory folder;
    folder.write("report.tex", latex);
    for (const auto& [name, bytes] : files)
        folder.write(name, bytes);
    for (int pass = 0; pass < 2; ++pass) {
        program_result run = run_program({"pdflatex", "-interaction=nonstopmode", "-halt-on-error", "report.tex"},
                                         folder.path(), "pdflatex.out",
                                         {"SOURCE_DATE_EPOCH=0", "FORCE_SOURCE_DATE=1"});
        if (run.exit_code != 0) {
            std::string text;
            try {
                text = folder.read("report.log");
            } catch (const computation_error&) {
            }
            throw computation_error("pdflatex could not compile the report" +
                                    (run.timed_out ? std::string(" (timed out)") : "") + ": " + first_latex_error(text));
        }
    }
    if (log)
        *log = folder.read("report.log");
    return folder.read("report.pdf");
}

std::string first_latex_error(const std::string& log)
{
    std::size_t at = log.find("\n!");
    if (at == std::string::npos)
        return "see its log";
    std::size_t end = at + 1;
    for (int lines = 0; lines < 3 && end != std::string::npos; ++lines)
        end = log.find('\n', end + 1);
    return log.substr(at + 1, end == std::string::npos ? std::string::npos : end - at - 1);
}

} // namespace lagrange
