// SPDX-License-Identifier: GPL-2.0-or-later
/** @file lexer.h
 *  Splits scene text into tokens that carry their file, line and column. */
#pragma once

#include "scene/source.h"

#include <string>
#include <vector>

namespace lagrange {

enum class token_kind {
    name,       ///< [A-Za-z][A-Za-z0-9_]*
    integer,    ///< 123
    decimal,    ///< 1.5, 1e-14, 2.5E3
    string,     ///< "text" (the quotes are not part of `text`)
    wildcard,   ///< $0 (rule files only)
    left_paren, ///< (
    right_paren,///< )
    comma,      ///< ,
    equals,     ///< =
    plus,       ///< +
    minus,      ///< -
    star,       ///< *
    slash,      ///< /
    caret,      ///< ^
    prime,      ///< '
    arrow,      ///< ->
    colon,      ///< : (after a constraint's name)
    newline,    ///< end of a statement
    end,        ///< end of the text
};

/// A short description of a token kind for messages ("a name", "`(`").
std::string describe(token_kind kind);

/// `text` in backquotes for a message, shortened to its first 40 characters.
std::string quote(const std::string& text);

struct token {
    token_kind kind;
    std::string text;
    source_location where;
};

struct lexer_options {
    bool allow_wildcards = false;      ///< `$0`: rule files
    std::size_t max_number_digits = 1000;
};

/// Tokenizes a whole scene. Handles a UTF-8 byte-order mark, CRLF line endings,
/// `#` comments, `\` line continuation; rejects invalid UTF-8, NUL and other
/// control bytes, and characters outside the language, with their position.
std::vector<token> tokenize(const source_text& source, const lexer_options& options = {});

} // namespace lagrange
