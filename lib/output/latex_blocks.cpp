/** @file latex_blocks.cpp
 *  The LaTeX building blocks of the documents and the report (see latex_blocks.h). */
#include "output/latex_blocks.h"

#include <algorithm>
#include <cctype>
#include <utility>

namespace lagrange {

/// LaTeX special characters in free text (titles, notes); the few non-ASCII
/// characters that messages use become math, any other one a `?`.
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
        default: out += c;
        }
    }
    return out;
}

/// A rough width of LaTeX math in characters: a command counts as one, braces,
/// sub/superscript marks and sizing commands as none.
std::size_t latex_math_width(const std::string& latex)
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

namespace {

/// Rows of an align* environment: `lhs &= terms rhs`, broken before a term
/// when the line would grow wider than the page holds.
std::string latex_rows(const std::string& lhs, const std::vector<std::string>& terms, const std::string& rhs,
                       const std::string& relation = "=")
{
    constexpr std::size_t line_width = 62;
    std::string out = lhs + (lhs.empty() ? "&" : " &" + relation + " ");
    std::size_t width = latex_math_width(lhs);
    bool first = true;
    for (const std::string& term : terms) {
        std::size_t w = latex_math_width(term);
        if (!first && width + w > line_width) {
            out += "\\\\\n&\\quad";
            width = 4;
        }
        out += (first ? "" : " ") + term;
        width += w + 1;
        first = false;
    }
    return out + rhs;
}

} // namespace

std::string latex_equation(const std::string& lhs, const std::vector<std::string>& terms, const std::string& rhs,
                           const std::string& relation)
{
    constexpr std::size_t line_width = 62;
    std::size_t widest = 0;
    for (const std::string& term : terms)
        widest = std::max(widest, latex_math_width(term) + (terms.size() == 1 ? latex_math_width(lhs) : 0));
    if (widest <= line_width)
        return "\\begin{align*}\n" + latex_rows(lhs, terms, rhs, relation) + "\n\\end{align*}\n";
    std::string joined;
    for (const std::string& term : terms)
        joined += (joined.empty() ? "" : " ") + term;
    return "\\[\\resizebox{\\linewidth}{!}{$\\displaystyle " + (lhs.empty() ? "" : lhs + " " + relation + " ") + joined + rhs +
           "$}\\]\n";
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
