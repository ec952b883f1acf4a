// SPDX-License-Identifier: GPL-2.0-or-later
/** @file source.cpp
 *  Scene text and error formatting with a caret under the offending column. */
#include "scene/source.h"

#include <algorithm>
#include <sstream>

namespace lagrange {

source_text::source_text(std::string file, std::string text)
    : file_(std::move(file)), text_(std::move(text))
{
    line_starts_.push_back(0);
    for (std::size_t i = 0; i < text_.size(); ++i)
        if (text_[i] == '\n')
            line_starts_.push_back(i + 1);
}

std::string source_text::line(int line) const
{
    if (line < 1 || static_cast<std::size_t>(line) > line_starts_.size())
        return {};
    std::size_t begin = line_starts_[line - 1];
    std::size_t end = text_.find('\n', begin);
    if (end == std::string::npos)
        end = text_.size();
    if (end > begin && text_[end - 1] == '\r')
        --end;
    return text_.substr(begin, end - begin);
}

namespace {

bool is_continuation_byte(unsigned char c) { return (c & 0xC0) == 0x80; }

/// Splits a line into displayable code points; bytes that are not valid
/// printable UTF-8 become a single '?' each, control characters a space.
std::vector<std::string> display_cells(const std::string& line)
{
    std::vector<std::string> cells;
    for (std::size_t i = 0; i < line.size();) {
        unsigned char c = static_cast<unsigned char>(line[i]);
        if (c < 0x80) {
            cells.emplace_back(1, (c < 0x20 || c == 0x7F) ? ' ' : static_cast<char>(c));
            ++i;
            continue;
        }
        int length = (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
        bool valid = length > 0 && i + length <= line.size();
        for (int k = 1; valid && k < length; ++k)
            valid = is_continuation_byte(static_cast<unsigned char>(line[i + k]));
        const bool c1_control = valid && c == 0xC2 && static_cast<unsigned char>(line[i + 1]) <= 0x9F;
        if (c1_control) { // U+0080 … U+009F: a terminal would act on it
            cells.emplace_back(" ");
            i += length;
        } else if (valid) {
            cells.push_back(line.substr(i, length));
            i += length;
        } else {
            cells.emplace_back("?");
            ++i;
        }
    }
    return cells;
}

} // namespace

void attach_line(scene_error& error, const source_text& source)
{
    if (!error.has_line_text() && error.where().file == source.file())
        error.attach_line_text(source.line(error.where().line));
}

namespace {

/// `FILE:LINE:COL: KIND: MESSAGE`, then `line_text` (when there is one) with a caret.
std::string format_diagnostic(const source_location& at, const char* kind, const std::string& message,
                              const std::string* line_text)
{
    std::ostringstream out;
    out << at.file << ':' << at.line << ':' << at.column << ": " << kind << ": " << message << '\n';
    if (!line_text)
        return out.str();
    std::vector<std::string> cells = display_cells(*line_text);
    // Show at most a window of 100 code points around the column.
    constexpr int window = 100;
    int column = at.column;
    int first = 1;
    if (static_cast<int>(cells.size()) > window && column > window / 2)
        first = std::min(column - window / 2, static_cast<int>(cells.size()) - window + 1);
    int last = std::min(static_cast<int>(cells.size()), first + window - 1);
    std::string shown = first > 1 ? "..." : "";
    std::string caret = first > 1 ? "   " : "";
    for (int k = first; k <= last; ++k) {
        shown += cells[k - 1];
        if (k < column)
            caret += ' ';
    }
    if (last < static_cast<int>(cells.size()))
        shown += "...";
    for (int k = std::max(last + 1, first); k < column; ++k)
        caret += ' ';
    out << shown << '\n' << caret << "^\n";
    return out.str();
}

} // namespace

std::string format_error(const scene_error& error)
{
    return format_diagnostic(error.where(), "error", error.what(),
                             error.has_line_text() ? &error.line_text() : nullptr);
}

std::string format_warning(const scene_warning& warning)
{
    return format_diagnostic(warning.where, "warning", warning.message,
                             warning.line_text.empty() ? nullptr : &warning.line_text);
}

} // namespace lagrange
