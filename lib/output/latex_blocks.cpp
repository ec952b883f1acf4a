// SPDX-License-Identifier: GPL-2.0-or-later
/** @file latex_blocks.cpp
 *  The LaTeX building blocks of the documents and the report (see latex_blocks.h). */
#include "output/latex_blocks.h"

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
        {"≥", "$\\ge$"}, {"∫", "$\\int$"}, {"√", "$\\surd$"}, {"…", "\\ldots{}"}, {"§", "\\S{}"}};
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        char c = text[i];
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

/// A term cut at the signs (" + ", " - ") of the outermost sums inside its parentheses
/// (the coefficient of ω⁴, not the argument of a cosine in it), never inside braces (a
/// fraction, an exponent, a square root): each piece is well formed once the groups
/// open at its ends are closed with \right. and opened again with \left.
std::vector<term_piece> term_pieces(const std::string& term)
{
    struct cut {
        std::size_t at;
        int depth;
    };
    std::vector<cut> cuts;
    int braces = 0, lefts = 0, environments = 0;
    for (std::size_t i = 0; i < term.size(); ++i) {
        const char c = term[i];
        if (c == '\\') {
            if (term.compare(i, 6, "\\begin") == 0 && !is_letter_at(term, i + 6))
                ++environments;
            else if (term.compare(i, 4, "\\end") == 0 && !is_letter_at(term, i + 4))
                --environments;
            else if (term.compare(i, 5, "\\left") == 0 && !is_letter_at(term, i + 5))
                ++lefts;
            else if (term.compare(i, 6, "\\right") == 0 && !is_letter_at(term, i + 6))
                --lefts;
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
            cuts.push_back({i, lefts});
    }
    int shallowest = 0;
    for (const cut& c : cuts)
        shallowest = shallowest == 0 ? c.depth : std::min(shallowest, c.depth);
    std::vector<term_piece> pieces;
    std::size_t start = 0;
    int depth = 0;
    for (const cut& c : cuts) {
        if (c.depth != shallowest)
            continue;
        pieces.push_back({term.substr(start, c.at - start), depth});
        start = c.at + 1; // the next piece starts with its sign
        depth = c.depth;
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

/// A term that is a fraction whose numerator is a sum, "\frac{a + b}{c} x", as
/// "\frac{1}{c} \left(a + b\right) x": the sum can then break across lines. Any other
/// term as it is.
std::string opened_fraction(const std::string& term)
{
    std::size_t start = 0;
    for (const char* sign : {"- ", "+ ", "-"})
        if (term.rfind(sign, 0) == 0) {
            start = std::string(sign).size();
            break;
        }
    if (term.compare(start, 6, "\\frac{") != 0)
        return term;
    const std::size_t numerator_end = group_end(term, start + 5);
    if (numerator_end == std::string::npos || numerator_end >= term.size() || term[numerator_end] != '{')
        return term;
    const std::size_t denominator_end = group_end(term, numerator_end);
    if (denominator_end == std::string::npos)
        return term;
    const std::string numerator = term.substr(start + 6, numerator_end - 1 - (start + 6));
    if (term_pieces("\\left(" + numerator + "\\right)").size() < 2)
        return term; // not a sum
    return term.substr(0, start) + "\\frac{1}{" + term.substr(numerator_end + 1, denominator_end - numerator_end - 2) +
           "} \\left(" + numerator + "\\right)" + term.substr(denominator_end);
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
        for (term_piece& piece : term_pieces(opened_fraction(term)))
            items.push_back(std::move(piece));
    }
    std::string out = lhs + (lhs.empty() ? "&" : " &" + relation + " ");
    std::size_t width = display_width(lhs);
    for (std::size_t k = 0; k < items.size(); ++k) {
        // The last item carries what follows it (" = 0").
        const std::size_t w = display_width(items[k].text) + (k + 1 == items.size() ? display_width(rhs) : 0);
        if (k > 0 && width + w > line_width) {
            out += repeated("\\right.", items[k].depth) + "\\\\\n&\\quad" + repeated("\\left.", items[k].depth);
            width = 4;
        }
        out += (k > 0 ? " " : "") + items[k].text;
        width += w + 1;
    }
    return out + rhs;
}

const std::string align_open = "\\begin{align*}\n", align_close = "\n\\end{align*}\n";

} // namespace

std::string latex_equation(const std::string& lhs, const std::vector<std::string>& terms, const std::string& rhs,
                           const std::string& relation)
{
    std::size_t widest = 0; // the widest piece a line cannot break
    std::size_t count = 0;
    for (const std::string& term : terms)
        for (const term_piece& piece : term_pieces(4 + display_width(term) <= line_width ? term : opened_fraction(term))) {
            widest = std::max(widest, display_width(piece.text));
            ++count;
        }
    if (count == 1)
        widest += display_width(lhs);
    if (widest <= line_width)
        return align_open + latex_rows(lhs, terms, rhs, relation) + align_close;
    std::string joined;
    for (const std::string& term : terms)
        joined += (joined.empty() ? "" : " ") + term;
    return "\\[\\resizebox{\\linewidth}{!}{$\\displaystyle " + (lhs.empty() ? "" : lhs + " " + relation + " ") + joined +
           rhs + "$}\\]\n";
}

std::string latex_equations(const std::vector<latex_row>& rows, const std::function<std::string(const std::string&)>& scaled,
                            const std::string& before)
{
    // Consecutive aligned rows share one align*; a scaled row stands alone between them.
    std::string out, block;
    auto flush = [&] {
        if (!block.empty())
            out += before + align_open + block + align_close;
        block.clear();
    };
    for (const latex_row& r : rows) {
        const std::string display = latex_equation(r.lhs, r.terms, r.rhs, r.relation);
        if (display.compare(0, align_open.size(), align_open) == 0) {
            block += (block.empty() ? "" : "\\\\[4pt]\n") +
                     display.substr(align_open.size(), display.size() - align_open.size() - align_close.size());
        } else {
            flush();
            out += before + (scaled ? scaled(display) : display);
        }
    }
    flush();
    return out;
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
