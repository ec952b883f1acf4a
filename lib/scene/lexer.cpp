// SPDX-License-Identifier: GPL-2.0-or-later
/** @file lexer.cpp
 *  The scene lexer: one pass over the bytes, tracking line and column. */
#include "scene/lexer.h"

#include <cctype>

namespace lagrange {

std::string describe(token_kind kind)
{
    switch (kind) {
    case token_kind::name: return "a name";
    case token_kind::integer: return "an integer";
    case token_kind::decimal: return "a number";
    case token_kind::string: return "a string";
    case token_kind::wildcard: return "a wildcard";
    case token_kind::left_paren: return "`(`";
    case token_kind::right_paren: return "`)`";
    case token_kind::comma: return "`,`";
    case token_kind::equals: return "`=`";
    case token_kind::plus: return "`+`";
    case token_kind::minus: return "`-`";
    case token_kind::star: return "`*`";
    case token_kind::slash: return "`/`";
    case token_kind::caret: return "`^`";
    case token_kind::prime: return "`'`";
    case token_kind::arrow: return "`->`";
    case token_kind::colon: return "`:`";
    case token_kind::newline: return "the end of the line";
    case token_kind::end: return "the end of the file";
    }
    return "a token";
}

std::string quote(const std::string& text)
{
    constexpr std::size_t longest = 40;
    if (text.size() <= longest)
        return "`" + text + "`";
    std::size_t cut = longest;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80)
        --cut; // do not split a UTF-8 sequence
    return "`" + text.substr(0, cut) + "...`";
}

namespace {

class scanner {
public:
    scanner(const source_text& source, const lexer_options& options)
        : source_(source), text_(source.text()), options_(options) {}

    std::vector<token> run()
    {
        if (text_.compare(0, 3, "\xEF\xBB\xBF") == 0)
            pos_ = 3; // byte-order mark: not a column
        while (pos_ < text_.size())
            next();
        if (!tokens_.empty() && tokens_.back().kind != token_kind::newline)
            push(token_kind::newline, "", here());
        push(token_kind::end, "", here());
        return std::move(tokens_);
    }

private:
    source_location here() const { return {source_.file(), line_, column_}; }

    [[noreturn]] void fail(const source_location& at, const std::string& message) const
    {
        throw scene_error(at, message);
    }

    void push(token_kind kind, std::string text, source_location at)
    {
        tokens_.push_back({kind, std::move(text), std::move(at)});
    }

    char peek(std::size_t ahead = 0) const
    {
        return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0';
    }

    /// Advances over one ASCII byte on the current line.
    void advance(std::size_t count = 1)
    {
        pos_ += count;
        column_ += static_cast<int>(count);
    }

    void new_line()
    {
        ++pos_;
        ++line_;
        column_ = 1;
    }

    /// Length of the valid UTF-8 sequence at pos_, or 0.
    std::size_t utf8_length() const
    {
        auto byte = [&](std::size_t k) { return static_cast<unsigned char>(peek(k)); };
        unsigned char c = byte(0);
        std::size_t length = (c >= 0xC2 && c <= 0xDF) ? 2 : (c >= 0xE0 && c <= 0xEF) ? 3
                           : (c >= 0xF0 && c <= 0xF4) ? 4 : 0;
        if (length == 0 || pos_ + length > text_.size())
            return 0;
        for (std::size_t k = 1; k < length; ++k)
            if ((byte(k) & 0xC0) != 0x80)
                return 0;
        if (c == 0xE0 && byte(1) < 0xA0) return 0; // overlong
        if (c == 0xED && byte(1) > 0x9F) return 0; // surrogates
        if (c == 0xF0 && byte(1) < 0x90) return 0; // overlong
        if (c == 0xF4 && byte(1) > 0x8F) return 0; // beyond U+10FFFF
        return length;
    }

    /// A C1 control character (U+0080 … U+009F, as CSI and OSC) at pos_: a terminal acts on
    /// it, so it is refused as the C0 controls are.
    bool is_c1_control() const
    {
        return static_cast<unsigned char>(peek()) == 0xC2 && static_cast<unsigned char>(peek(1)) >= 0x80 &&
               static_cast<unsigned char>(peek(1)) <= 0x9F;
    }

    /// Steps over one code point inside a comment or string; rejects bad bytes.
    void advance_code_point(const char* where)
    {
        unsigned char c = static_cast<unsigned char>(peek());
        if (c >= 0x80) {
            std::size_t length = utf8_length();
            if (length == 0)
                fail(here(), "invalid UTF-8 byte in " + std::string(where));
            if (is_c1_control())
                fail(here(), "control character (U+00" + hex(static_cast<unsigned char>(peek(1))) + ") in " + where);
            pos_ += length;
            ++column_;
            return;
        }
        if ((c < 0x20 && c != '\t') || c == 0x7F)
            fail(here(), "control character (byte " + std::to_string(c) + ") in " + where);
        advance();
    }

    void next()
    {
        char c = peek();
        source_location at = here();
        if (c == ' ' || c == '\t') {
            advance();
        } else if (c == '\r' && peek(1) == '\n') {
            advance();
        } else if (c == '\n') {
            if (!tokens_.empty() && tokens_.back().kind != token_kind::newline)
                push(token_kind::newline, "", at);
            new_line();
        } else if (c == '#') {
            while (pos_ < text_.size() && peek() != '\n' && !(peek() == '\r' && peek(1) == '\n'))
                advance_code_point("a comment");
        } else if (c == '\\') {
            continuation();
        } else if (std::isalpha(static_cast<unsigned char>(c))) {
            std::size_t start = pos_;
            while (std::isalnum(static_cast<unsigned char>(peek())) || peek() == '_')
                advance();
            push(token_kind::name, text_.substr(start, pos_ - start), at);
        } else if (std::isdigit(static_cast<unsigned char>(c)) ||
                   (c == '.' && std::isdigit(static_cast<unsigned char>(peek(1))))) {
            number(at);
        } else if (c == '"') {
            string_literal(at);
        } else if (c == '$' && options_.allow_wildcards) {
            advance();
            std::size_t start = pos_;
            while (std::isdigit(static_cast<unsigned char>(peek())))
                advance();
            if (pos_ == start || pos_ - start > 3)
                fail(at, "a wildcard is `$` followed by a number from 0 to 999");
            push(token_kind::wildcard, text_.substr(start, pos_ - start), at);
        } else if (c == '-' && peek(1) == '>') {
            advance(2);
            push(token_kind::arrow, "->", at);
        } else {
            punctuation(c, at);
        }
    }

    void continuation()
    {
        source_location at = here();
        advance();
        while (peek() == ' ' || peek() == '\t')
            advance();
        if (peek() == '\r' && peek(1) == '\n')
            advance();
        if (peek() == '\n')
            new_line();
        else if (pos_ < text_.size())
            fail(at, "`\\` continues a line only at its end");
    }

    void number(const source_location& at)
    {
        std::size_t start = pos_;
        bool decimal = false;
        while (std::isdigit(static_cast<unsigned char>(peek())))
            advance();
        if (peek() == '.') {
            decimal = true;
            advance();
            while (std::isdigit(static_cast<unsigned char>(peek())))
                advance();
        }
        if ((peek() == 'e' || peek() == 'E') &&
            (std::isdigit(static_cast<unsigned char>(peek(1))) ||
             ((peek(1) == '+' || peek(1) == '-') && std::isdigit(static_cast<unsigned char>(peek(2)))))) {
            decimal = true;
            advance(2);
            while (std::isdigit(static_cast<unsigned char>(peek())))
                advance();
        }
        if (std::isalpha(static_cast<unsigned char>(peek())) || peek() == '_')
            fail(here(), "a number cannot run into a name: write `2*x`, not `2x`");
        if (pos_ - start > options_.max_number_digits)
            fail(at, "number too long (more than " + std::to_string(options_.max_number_digits) +
                         " characters)");
        push(decimal ? token_kind::decimal : token_kind::integer, text_.substr(start, pos_ - start), at);
    }

    void string_literal(const source_location& at)
    {
        advance();
        std::size_t start = pos_;
        while (peek() != '"') {
            if (pos_ >= text_.size() || peek() == '\n' || (peek() == '\r' && peek(1) == '\n'))
                fail(at, "unterminated string: a `\"` is missing on this line");
            advance_code_point("a string");
        }
        std::string value = text_.substr(start, pos_ - start);
        advance();
        push(token_kind::string, std::move(value), at);
    }

    void punctuation(char c, const source_location& at)
    {
        token_kind kind;
        switch (c) {
        case '(': kind = token_kind::left_paren; break;
        case ')': kind = token_kind::right_paren; break;
        case ',': kind = token_kind::comma; break;
        case '=': kind = token_kind::equals; break;
        case '+': kind = token_kind::plus; break;
        case '-': kind = token_kind::minus; break;
        case '*': kind = token_kind::star; break;
        case '/': kind = token_kind::slash; break;
        case '^': kind = token_kind::caret; break;
        case '\'': kind = token_kind::prime; break;
        case ':': kind = token_kind::colon; break;
        default: unexpected(c, at);
        }
        advance();
        push(kind, std::string(1, c), at);
    }

    [[noreturn]] void unexpected(char c, const source_location& at) const
    {
        unsigned char byte = static_cast<unsigned char>(c);
        if (byte >= 0x80) {
            std::size_t length = utf8_length();
            if (length == 0)
                fail(at, "invalid UTF-8 byte (0x" + hex(byte) + ")");
            if (is_c1_control())
                fail(at, "unexpected control character (U+00" + hex(static_cast<unsigned char>(peek(1))) + ")");
            fail(at, "unexpected character `" + text_.substr(pos_, length) +
                         "`: names are ASCII letters, digits and `_` (write `theta`, not `θ`)");
        }
        if (byte < 0x20 || byte == 0x7F)
            fail(at, "unexpected control character (byte 0x" + hex(byte) + ")");
        fail(at, std::string("unexpected character `") + c + "`");
    }

    static std::string hex(unsigned char byte)
    {
        const char* digits = "0123456789ABCDEF";
        return {digits[byte >> 4], digits[byte & 0xF]};
    }

    const source_text& source_;
    const std::string& text_;
    lexer_options options_;
    std::vector<token> tokens_;
    std::size_t pos_ = 0;
    int line_ = 1;
    int column_ = 1;
};

} // namespace

std::vector<token> tokenize(const source_text& source, const lexer_options& options)
{
    return scanner(source, options).run();
}

} // namespace lagrange
