// SPDX-License-Identifier: GPL-2.0-or-later
/** @file errors.h
 *  The two failures every layer reports: bad input at a position in a scene
 *  (exit code 2) and a computation that cannot be done (exit code 1). */
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

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

} // namespace lagrange
