/** @file source.h
 *  Scene text, positions in it, and the error type that carries a position. */
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace lagrange {

/// A position in a scene file: 1-based line and column (column counts code points).
struct source_location {
    std::string file;
    int line = 1;
    int column = 1;
};

/// Bad input: a message written for the user, at a position in the scene.
class scene_error : public std::runtime_error {
public:
    scene_error(source_location where, const std::string& message)
        : std::runtime_error(message), where_(std::move(where)) {}
    const source_location& where() const { return where_; }

    /// The text of the offending line, attached by whoever holds the source.
    const std::string& line_text() const { return line_text_; }
    bool has_line_text() const { return has_line_text_; }
    void attach_line_text(std::string text)
    {
        line_text_ = std::move(text);
        has_line_text_ = true;
    }

private:
    source_location where_;
    std::string line_text_;
    bool has_line_text_ = false;
};

/// The computation could not be done (no equilibrium, singular kinetic matrix, ...):
/// exit code 1 at the command line.
class computation_error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

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

} // namespace lagrange
