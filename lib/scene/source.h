// SPDX-License-Identifier: GPL-2.0-or-later
/** @file source.h
 *  Scene text, kept to quote the offending line of an error. */
#pragma once

#include "core/errors.h"
#include "core/model.h"

#include <string>
#include <vector>

namespace lagrange {

/// The text of one scene file, kept to quote lines in error messages.
class source_text {
public:
    source_text(std::string file, std::string text);
    const std::string& file() const { return file_; }
    const std::string& text() const { return text_; }
    /// Physical line `line` (1-based) without its line ending; empty if out of range.
    std::string line(int line) const;

private:
    std::string file_;
    std::string text_;
    std::vector<std::size_t> line_starts_;
};

/// Attaches the offending line of `source` to `error` if it has none and comes from that file.
void attach_line(scene_error& error, const source_text& source);

/// `FILE:LINE:COL: error: MESSAGE`, then the offending line (shortened around the
/// column when it is long, control bytes shown as spaces) and a caret under the column.
std::string format_error(const scene_error& error);

/// `FILE:LINE:COL: warning: MESSAGE`, then the line and a caret, as format_error.
std::string format_warning(const scene_warning& warning);

} // namespace lagrange
