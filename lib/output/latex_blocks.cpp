// SPDX-License-Identifier: GPL-2.0-or-later
/** @file latex_blocks.cpp
 *  The LaTeX building blocks of the documents and the report (see latex_blocks.h). */
#include "output/latex_blocks.h"

#include "core/number_text.h"

#include <algorithm>
#include <cctype>
#include <functional>
#include <utility>

namespace lagrange {

/// LaTeX special characters in free text (titles, notes); the few non-ASCII
/// characters that messages use become math, any other one a `?`. `name` becomes
/// \texttt{name}, and "--" keeps its two hyphens.
std::string latex_text(const std::string& text)
{
    static const std::vector<std::pair<std::string, std::string>> unicode = {
        {"∂", "$\\partial$"}, {"²", "$^2$"}, {"≤", "$\\le$"}, {"→", "$\\to$"}, {"·", "$\\cdot$"},
        {"−", "$-$"},          {"ω", "$\\omega$"}, {"θ", "$\\theta$"}, {"φ", "$\\phi$"}, {"ρ", "$\\rho$"},
        // more of what scenes' comments and the report's prose use (the homework's bodies, beats)
        {"π", "$\\pi$"}, {"δ", "$\\delta$"}, {"ψ", "$\\psi$"}, {"λ", "$\\lambda$"}, {"α", "$\\alpha$"},
        {"β", "$\\beta$"}, {"γ", "$\\gamma$"}, {"ε", "$\\varepsilon$"}, {"μ", "$\\mu$"}, {"σ", "$\\sigma$"},
        {"τ", "$\\tau$"}, {"ν", "$\\nu$"}, {"ξ", "$\\xi$"}, {"ζ", "$\\zeta$"}, {"η", "$\\eta$"},
        {"κ", "$\\kappa$"}, {"χ", "$\\chi$"}, {"Ω", "$\\Omega$"}, {"Δ", "$\\Delta$"}, {"Θ", "$\\Theta$"},
        {"Φ", "$\\Phi$"}, {"Ψ", "$\\Psi$"}, {"Λ", "$\\Lambda$"}, {"Σ", "$\\Sigma$"}, {"Γ", "$\\Gamma$"},
        {"¹", "$^1$"}, {"³", "$^3$"}, {"⁴", "$^4$"}, {"₀", "$_0$"}, {"₁", "$_1$"}, {"₂", "$_2$"}, {"₃", "$_3$"},
        {"₊", "$_+$"}, {"₋", "$_-$"}, {"ᵀ", "$^T$"}, {"½", "$\\frac12$"}, {"¼", "$\\frac14$"},
        {"–", "--"}, {"—", "---"}, {"±", "$\\pm$"}, {"∓", "$\\mp$"}, {"×", "$\\times$"}, {"≈", "$\\approx$"},
        {"≥", "$\\ge$"}, {"∝", "$\\propto$"}, {"∫", "$\\int$"}, {"√", "$\\surd$"}, {"…", "\\ldots{}"}, {"§", "\\S{}"}};
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        char c = text[i];
        // A number with an exponent ("1e+03", "1.13e-13", not the "e2" of a name x1e2) as
        // 10^{3} and 1.13 \times 10^{-13}.
        if (std::isdigit(static_cast<unsigned char>(c)) &&
            (i == 0 || !(std::isalnum(static_cast<unsigned char>(text[i - 1])) || text[i - 1] == '_' || text[i - 1] == '.'))) {
            std::size_t j = i;
            while (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j])))
                ++j;
            if (j + 1 < text.size() && text[j] == '.' && std::isdigit(static_cast<unsigned char>(text[j + 1])))
                for (++j; j < text.size() && std::isdigit(static_cast<unsigned char>(text[j]));)
                    ++j;
            std::size_t k = j;
            if (k < text.size() && (text[k] == 'e' || text[k] == 'E')) {
                ++k;
                if (k < text.size() && (text[k] == '+' || text[k] == '-'))
                    ++k;
                const std::size_t digits = k;
                while (k < text.size() && std::isdigit(static_cast<unsigned char>(text[k])))
                    ++k;
                if (k > digits && (k == text.size() || !(std::isalnum(static_cast<unsigned char>(text[k])) || text[k] == '_'))) {
                    out += "$" + latex_exponent(text.substr(i, k - i)) + "$";
                    i = k - 1;
                    continue;
                }
            }
        }
        if (static_cast<unsigned char>(c) >= 0x80) {
            bool known = false;
            for (const auto& [from, to] : unicode)
                if (text.compare(i, from.size(), from) == 0) {
                    out += to;
                    i += from.size() - 1;
                    known = true;
                    break;
                }
            if (!known) {
                out += '?';
                while (i + 1 < text.size() && (static_cast<unsigned char>(text[i + 1]) & 0xC0) == 0x80)
                    ++i;
            }
            continue;
        }
        switch (c) {
        case '\\': out += "\\textbackslash{}"; break;
        case '{': case '}': case '$': case '&': case '#': case '_': case '%':
            out += '\\';
            out += c;
            break;
        case '^': out += "\\^{}"; break;
        case '~': out += "\\~{}"; break;
        case '<': case '>': case '|': // not in the OT1 text fonts
            out += std::string("$") + c + "$";
            break;
        case '-': // "--" is an en dash in TeX: --max-seconds stays two hyphens
            out += i + 1 < text.size() && text[i + 1] == '-' ? "-{}" : "-";
            break;
        case '`': { // `name` as code, as the messages write it; a lone backquote as itself
            const std::size_t close = text.find('`', i + 1);
            if (close != std::string::npos && close > i + 1) {
                out += "\\texttt{" + latex_text(text.substr(i + 1, close - i - 1)) + "}";
                i = close;
            } else {
                out += "\\`{}";
            }
            break;
        }
        default: out += c;
        }
    }
    return out;
}

namespace {

/// A rough width of LaTeX math in characters: a command counts as one, braces,
/// sub/superscript marks and sizing commands as none.
std::size_t raw_width(const std::string& latex)
{
    std::size_t width = 0;
    for (std::size_t i = 0; i < latex.size(); ++i) {
        char c = latex[i];
        if (c == '\\') {
            std::size_t j = i + 1;
            while (j < latex.size() && std::isalpha(static_cast<unsigned char>(latex[j])))
                ++j;
            std::string command = latex.substr(i + 1, j - i - 1);
            if (command != "left" && command != "right" && command != "frac")
                ++width;
            i = j > i + 1 ? j - 1 : j;
        } else if (c != '{' && c != '}' && c != '^' && c != '_' && c != ' ') {
            ++width;
        }
    }
    return width;
}

constexpr std::size_t line_width = 62;

/// raw_width, with a matrix as wide as its widest row rather than all its rows.
std::size_t display_width(const std::string& latex)
{
    const std::string open = "\\begin{pmatrix}", close = "\\end{pmatrix}";
    std::size_t width = 0, from = 0;
    for (;;) {
        const std::size_t begin = latex.find(open, from);
        const std::size_t end = begin == std::string::npos ? std::string::npos : latex.find(close, begin);
        if (end == std::string::npos)
            return width + raw_width(latex.substr(from));
        width += raw_width(latex.substr(from, begin - from)) + 2; // the parentheses
        const std::string body = latex.substr(begin + open.size(), end - begin - open.size());
        std::size_t widest = 0;
        for (std::size_t row = 0; row <= body.size();) {
            std::size_t next = body.find("\\\\", row);
            if (next == std::string::npos)
                next = body.size();
            const std::string cells = body.substr(row, next - row);
            // a column gap is about two characters wide
            widest = std::max(widest, raw_width(cells) + static_cast<std::size_t>(std::count(cells.begin(), cells.end(), '&')));
            row = next + 2;
        }
        width += widest;
        from = end + close.size();
    }
}

} // namespace

std::size_t latex_math_width(const std::string& latex) { return display_width(latex); }

namespace {

/// A piece of a printed term between two places where a line may break: the term's
/// start, or a sign of a sum inside the term's \left( … \right) groups. `depth` is the
/// number of \left groups open where the piece starts.
struct term_piece {
    std::string text;
    int depth = 0;
};

bool is_letter_at(const std::string& s, std::size_t i) { return i < s.size() && std::isalpha(static_cast<unsigned char>(s[i])); }

/// A place where a term may break: a sign of a sum inside `depth` \left groups, the
/// innermost of which spans `width` characters.
struct term_cut {
    std::size_t at;
    int depth;
    std::size_t width = 0;
};

/// Every sign (" + ", " - ") of a sum inside the term's \left( … \right) groups, never inside
/// braces (a fraction, an exponent, a square root) or an environment (a matrix).
std::vector<term_cut> term_cuts(const std::string& term)
{
    std::vector<term_cut> cuts;
    int braces = 0, lefts = 0, environments = 0;
    std::vector<std::pair<std::size_t, std::size_t>> open; // per open group: its start, its first cut
    for (std::size_t i = 0; i < term.size(); ++i) {
        const char c = term[i];
        if (c == '\\') {
            if (term.compare(i, 6, "\\begin") == 0 && !is_letter_at(term, i + 6))
                ++environments;
            else if (term.compare(i, 4, "\\end") == 0 && !is_letter_at(term, i + 4))
                --environments;
            else if (term.compare(i, 5, "\\left") == 0 && !is_letter_at(term, i + 5)) {
                ++lefts;
                open.emplace_back(i, cuts.size());
            } else if (term.compare(i, 6, "\\right") == 0 && !is_letter_at(term, i + 6)) {
                --lefts;
                if (!open.empty()) { // the group's width, for the cuts directly inside it
                    const std::size_t width = display_width(term.substr(open.back().first, i - open.back().first));
                    for (std::size_t k = open.back().second; k < cuts.size(); ++k)
                        if (cuts[k].depth == lefts + 1)
                            cuts[k].width = width;
                    open.pop_back();
                }
            }
            if (!is_letter_at(term, i + 1))
                ++i; // \{, \}, \,, \\: not a brace of the structure
            continue;
        }
        if (c == '{')
            ++braces;
        else if (c == '}')
            --braces;
        else if (c == ' ' && braces == 0 && environments == 0 && lefts > 0 && i > 0 && i + 2 < term.size() &&
                 (term[i + 1] == '+' || term[i + 1] == '-') && term[i + 2] == ' ')
            cuts.push_back({i, lefts, std::string::npos});
    }
    return cuts;
}

/// A term cut at the signs of its outermost sums (the coefficient of ω⁴, not the argument
/// of a cosine in it); a piece still wider than `width` is cut again at the next sums
/// inside it, and so on. Each piece is well formed once the groups open at its ends are
/// closed with \right. and opened again with \left.
std::vector<term_piece> term_pieces(const std::string& term, std::size_t width = std::string::npos)
{
    const std::vector<term_cut> cuts = term_cuts(term);
    std::vector<bool> used(cuts.size(), false);
    // Cut [from, to) of the term (cut indices first..last) at its shallowest depth, then
    // recurse into the pieces that are still too wide.
    std::function<void(std::size_t, std::size_t, std::size_t, std::size_t)> refine =
        [&](std::size_t from, std::size_t to, std::size_t first, std::size_t last) {
            int shallowest = 0;
            for (std::size_t k = first; k < last; ++k)
                shallowest = shallowest == 0 ? cuts[k].depth : std::min(shallowest, cuts[k].depth);
            if (shallowest == 0)
                return;
            // A short group, (2a - x), is not cut when a wider one at its depth can be.
            constexpr std::size_t short_group = 24;
            bool any_wide = false;
            for (std::size_t k = first; k < last; ++k)
                any_wide = any_wide || (cuts[k].depth == shallowest && cuts[k].width > short_group);
            auto cuts_here = [&](std::size_t k) {
                return cuts[k].depth == shallowest && (!any_wide || cuts[k].width > short_group);
            };
            std::size_t start = from, start_cut = first;
            for (std::size_t k = first; k <= last; ++k) {
                if (k < last && !cuts_here(k))
                    continue;
                const std::size_t end = k < last ? cuts[k].at : to;
                if (width != std::string::npos && start_cut < k && display_width(term.substr(start, end - start)) > width)
                    refine(start, end, start_cut, k);
                if (k < last)
                    used[k] = true;
                start = end + 1;
                start_cut = k + 1;
            }
        };
    refine(0, term.size(), 0, cuts.size());
    std::vector<term_piece> pieces;
    std::size_t start = 0;
    int depth = 0;
    for (std::size_t k = 0; k < cuts.size(); ++k) {
        if (!used[k])
            continue;
        pieces.push_back({term.substr(start, cuts[k].at - start), depth});
        start = cuts[k].at + 1; // the next piece starts with its sign
        depth = cuts[k].depth;
    }
    pieces.push_back({term.substr(start), depth});
    return pieces;
}

/// The end of the brace group that opens at `open` (just past its `}`), or npos.
std::size_t group_end(const std::string& latex, std::size_t open)
{
    int depth = 0;
    for (std::size_t i = open; i < latex.size(); ++i) {
        if (latex[i] == '\\') {
            ++i; // \{ and \} are not braces of the structure
            continue;
        }
        if (latex[i] == '{')
            ++depth;
        else if (latex[i] == '}' && --depth == 0)
            return i + 1;
    }
    return std::string::npos;
}

/// Whether `latex` has a sign of a sum outside every group (depth 1 once put in parentheses).
bool is_sum(const std::string& latex)
{
    for (const term_cut& c : term_cuts("\\left(" + latex + "\\right)"))
        if (c.depth == 1)
            return true;
    return false;
}

/// Whether `latex` has a sign of a sum anywhere a line could break, once in parentheses.
bool breakable(const std::string& latex) { return !term_cuts("\\left(" + latex + "\\right)").empty(); }

std::string parenthesized(const std::string& latex) { return is_sum(latex) ? "\\left(" + latex + "\\right)" : latex; }

/// A term wider than a line with its long fractions and square roots, which TeX cannot
/// break, written with parentheses that can: \frac{a + b}{c} as \frac{1}{c} (a + b),
/// \frac{x}{a + b} as x (a + b)^{-1}, \sqrt{a + b} as (a + b)^{1/2}, inside out. Short
/// ones (a numerator of a few symbols) stay as they are.
std::string open_term(const std::string& term)
{
    constexpr std::size_t short_part = 30;
    std::string out;
    int braces = 0, environments = 0;
    for (std::size_t i = 0; i < term.size(); ++i) {
        const char c = term[i];
        if (c == '\\') {
            const bool frac = term.compare(i, 6, "\\frac{") == 0, root = term.compare(i, 6, "\\sqrt{") == 0;
            if (braces == 0 && environments == 0 && (frac || root)) {
                const std::size_t first_end = group_end(term, i + 5);
                const std::size_t second_end = frac && first_end != std::string::npos && first_end < term.size() &&
                                                       term[first_end] == '{'
                                                   ? group_end(term, first_end)
                                                   : std::string::npos;
                if (root && first_end != std::string::npos) {
                    const std::string radicand = open_term(term.substr(i + 6, first_end - i - 7));
                    if (display_width(radicand) > short_part && breakable(radicand)) {
                        out += "\\left(" + radicand + "\\right)^{1/2}";
                        i = first_end - 1;
                        continue;
                    }
                } else if (frac && second_end != std::string::npos) {
                    const std::string numerator = open_term(term.substr(i + 6, first_end - i - 7));
                    const std::string denominator = open_term(term.substr(first_end + 1, second_end - first_end - 2));
                    const bool long_numerator = display_width(numerator) > short_part && breakable(numerator);
                    const bool long_denominator = display_width(denominator) > short_part && breakable(denominator);
                    if (long_numerator || long_denominator) {
                        if (!long_denominator)
                            out += "\\frac{1}{" + denominator + "} " + parenthesized(numerator);
                        else
                            out += (numerator == "1" ? "" : parenthesized(numerator) + " ") + "\\left(" + denominator +
                                   "\\right)^{-1}";
                        i = second_end - 1;
                        continue;
                    }
                }
            }
            if (term.compare(i, 6, "\\begin") == 0 && !is_letter_at(term, i + 6))
                ++environments;
            else if (term.compare(i, 4, "\\end") == 0 && !is_letter_at(term, i + 4))
                --environments;
            out += c;
            if (!is_letter_at(term, i + 1) && i + 1 < term.size())
                out += term[++i]; // \{, \}, \,: not a brace of the structure
            continue;
        }
        if (c == '{')
            ++braces;
        else if (c == '}')
            --braces;
        out += c;
    }
    return out;
}

std::string repeated(const std::string& s, int times)
{
    std::string out;
    for (int k = 0; k < times; ++k)
        out += s;
    return out;
}

/// Rows of an align* environment: `lhs &= terms rhs`, broken before a term when the
/// line would grow wider than the page holds, and inside a term wider than a line by
/// itself at a sign of the sum in its parentheses (\right. at the end of the line,
/// \left. at the start of the next).
std::string latex_rows(const std::string& lhs, const std::vector<std::string>& terms, const std::string& rhs,
                       const std::string& relation)
{
    // Whole terms where they fit on a line, else the pieces of the term.
    std::vector<term_piece> items;
    for (const std::string& term : terms) {
        if (4 + display_width(term) <= line_width) {
            items.push_back({term, 0});
            continue;
        }
        for (term_piece& piece : term_pieces(open_term(term), line_width - 4))
            items.push_back(std::move(piece));
    }
    std::string out = lhs + (lhs.empty() ? "&" : " &" + relation + " ");
    std::size_t width = display_width(lhs);
    for (std::size_t k = 0; k < items.size(); ++k) {
        // The last item carries what follows it (" = 0").
        const std::size_t w = display_width(items[k].text) + (k + 1 == items.size() ? display_width(rhs) : 0);
        if (k > 0 && width + w > line_width) {
            // "{}" before a leading sign keeps it binary, spaced as inside the line.
            const bool sign = !items[k].text.empty() && (items[k].text[0] == '+' || items[k].text[0] == '-');
            out += repeated("\\right.", items[k].depth) + "\\\\\n&\\quad" + repeated("\\left.", items[k].depth) +
                   (sign ? "{}" : "");
            width = 4;
        }
        out += (k > 0 ? " " : "") + items[k].text;
        width += w + 1;
    }
    return out + rhs;
}

const std::string align_open = "\\begin{align*}\n", align_close = "\n\\end{align*}\n";

} // namespace

namespace {

/// The terms of a printed sum: `latex` cut at its signs outside every group.
std::vector<std::string> top_level_terms(const std::string& latex)
{
    std::vector<std::string> terms;
    std::size_t start = 0;
    const std::size_t shift = std::string("\\left(").size();
    for (const term_cut& c : term_cuts("\\left(" + latex + "\\right)"))
        if (c.depth == 1) {
            terms.push_back(latex.substr(start, c.at - shift - start));
            start = c.at - shift + 1;
        }
    terms.push_back(latex.substr(start));
    return terms;
}

/// The entries of `\begin{pmatrix} … \end{pmatrix}` (or vmatrix), row by row, or nothing
/// when `term` is not one matrix.
std::vector<std::vector<std::string>> matrix_entries(const std::string& term, std::string& kind)
{
    std::vector<std::vector<std::string>> rows;
    for (const char* k : {"pmatrix", "vmatrix"}) {
        const std::string open = std::string("\\begin{") + k + "}", close = std::string("\\end{") + k + "}";
        if (term.rfind(open, 0) != 0 || term.size() < open.size() + close.size() ||
            term.compare(term.size() - close.size(), close.size(), close) != 0)
            continue;
        kind = k;
        const std::string body = term.substr(open.size(), term.size() - open.size() - close.size());
        if (body.find("\\begin") != std::string::npos)
            return {}; // a matrix of matrices: left as it is
        rows.emplace_back(1);
        int braces = 0;
        for (std::size_t i = 0; i < body.size(); ++i) {
            const char c = body[i];
            if (c == '\\' && i + 1 < body.size() && body[i + 1] == '\\' && braces == 0) {
                rows.emplace_back(1);
                ++i;
                continue;
            }
            if (c == '&' && braces == 0) {
                rows.back().emplace_back();
                continue;
            }
            if (c == '\\' && i + 1 < body.size() && !is_letter_at(body, i + 1)) {
                rows.back().back() += body.substr(i, 2);
                ++i;
                continue;
            }
            braces += c == '{' ? 1 : c == '}' ? -1 : 0;
            rows.back().back() += c;
        }
        for (auto& row : rows)
            for (std::string& entry : row) {
                entry.erase(0, entry.find_first_not_of(' '));
                entry.erase(entry.find_last_not_of(' ') + 1);
            }
        return rows;
    }
    return {};
}

/// The name of entry (i, j) of the matrix `lhs` (a column's entry i): \mathbf{T}_{12}, a_{1,2}.
std::string entry_name(const std::string& lhs, std::size_t i, std::size_t j, bool column)
{
    const std::string index = column ? std::to_string(i + 1) : std::to_string(i + 1) + std::to_string(j + 1);
    if (lhs.size() > 3 && lhs.back() == ')' && lhs.find('(') != std::string::npos) // \mathcal{M}(q): \mathcal{M}_{12}
        return lhs.substr(0, lhs.find('(')) + "_{" + index + "}";
    if (lhs.size() > 3 && lhs.back() == '}') {
        const std::size_t sub = lhs.rfind("_{");
        if (sub != std::string::npos && group_end(lhs, sub + 1) == lhs.size())
            return lhs.substr(0, lhs.size() - 1) + "," + index + "}";
    }
    return (lhs.empty() ? std::string("D") : lhs) + "_{" + index + "}";
}

/// A matrix too wide for the page, `lhs = matrix rhs`, as the matrix of the names of its
/// long entries and then one row per entry, each broken at its signs: entries a few
/// symbols wide stay in place, and of a symmetric matrix only the upper triangle is listed.
std::string matrix_rows(const std::string& lhs, const std::vector<std::vector<std::string>>& entries,
                        const std::string& kind, const std::string& rhs, const std::string& relation)
{
    constexpr std::size_t short_entry = 10;
    const bool column = std::all_of(entries.begin(), entries.end(), [](const auto& r) { return r.size() == 1; });
    bool symmetric = !column;
    for (std::size_t i = 0; i < entries.size() && symmetric; ++i)
        for (std::size_t j = 0; j < entries[i].size() && symmetric; ++j)
            symmetric = j < entries.size() && i < entries[j].size() && entries[i][j] == entries[j][i];
    std::string skeleton = "\\begin{" + kind + "}";
    std::vector<std::pair<std::string, std::string>> named;
    for (std::size_t i = 0; i < entries.size(); ++i) {
        for (std::size_t j = 0; j < entries[i].size(); ++j) {
            const std::string& e = entries[i][j];
            std::string shown = e;
            if (display_width(e) > short_entry) {
                const std::size_t a = symmetric ? std::min(i, j) : i, b = symmetric ? std::max(i, j) : j;
                shown = entry_name(lhs, a, b, column);
                if (!symmetric || i <= j)
                    named.emplace_back(shown, e);
            }
            skeleton += (j ? " & " : "") + shown;
        }
        skeleton += i + 1 < entries.size() ? " \\\\ " : "";
    }
    skeleton += "\\end{" + kind + "}";
    std::string out = latex_rows(lhs, {skeleton}, rhs, relation);
    for (const auto& [name, entry] : named)
        out += "\\\\[4pt]\n" + latex_rows(name, top_level_terms(entry), "", "=");
    return out;
}

} // namespace

std::string latex_equation(const std::string& lhs, const std::vector<std::string>& terms, const std::string& rhs,
                           const std::string& relation)
{
    // A matrix named by the lhs (\mathbf{T}, a_{1}) and clearly wider than a line (the
    // estimate is rough) lists its entries; one without a name (a determinant) is left
    // to its writer.
    std::string kind;
    const bool named = !lhs.empty() && lhs.rfind("\\det", 0) != 0;
    if (named && terms.size() == 1 && display_width(lhs) + display_width(terms[0]) + display_width(rhs) > line_width + 8) {
        const std::vector<std::vector<std::string>> entries = matrix_entries(terms[0], kind);
        if (!entries.empty())
            return align_open + matrix_rows(lhs, entries, kind, rhs, relation) + align_close;
    }
    // No display is ever scaled: what no line can hold runs into the margin, where the
    // report's test (no overfull box above 1 pt) finds it.
    return align_open + latex_rows(lhs, terms, rhs, relation) + align_close;
}

std::string latex_equations(const std::vector<latex_row>& rows, const std::string& before)
{
    // All the rows share one align*.
    std::string block;
    for (const latex_row& r : rows) {
        const std::string display = latex_equation(r.lhs, r.terms, r.rhs, r.relation);
        block += (block.empty() ? "" : "\\\\[4pt]\n") +
                 display.substr(align_open.size(), display.size() - align_open.size() - align_close.size());
    }
    return block.empty() ? "" : before + align_open + block + align_close;
}

std::string latex_matrix(const GiNaC::matrix& m)
{
    std::string out = "\\begin{pmatrix}";
    for (unsigned i = 0; i < m.rows(); ++i) {
        for (unsigned j = 0; j < m.cols(); ++j)
            out += (j ? " & " : "") + print(m(i, j), syntax::latex);
        out += i + 1 < m.rows() ? " \\\\ " : "";
    }
    return out + "\\end{pmatrix}";
}

term_order velocity_order(const model& scene)
{
    term_order order;
    order.groups.emplace_back();
    for (const coordinate& c : scene.coordinates)
        order.groups.back().push_back(c.velocity);
    return order;
}

term_order equation_order(const model& scene)
{
    term_order order;
    order.groups.emplace_back();
    for (const coordinate& c : scene.coordinates)
        order.groups.back().push_back(c.acceleration);
    order.groups.push_back(velocity_order(scene).groups[0]);
    return order;
}

term_order omega_order(const analysis& result)
{
    term_order order;
    if (result.characteristic)
        order.groups.push_back({result.characteristic->omega});
    return order;
}

} // namespace lagrange
