// SPDX-License-Identifier: GPL-2.0-or-later
/** @file print_names.cpp
 *  How symbol names print (see print_name in print.h): Greek letters, dots over
 *  velocities, trailing digits and underscores as subscripts. */
#include "output/print.h"

#include <algorithm>
#include <map>
#include <utility>

namespace lagrange {

namespace {

struct greek_letter {
    const char* text;
    const char* latex;
};

const std::map<std::string, greek_letter>& greek_letters()
{
    static const std::map<std::string, greek_letter> letters = {
        {"alpha", {"α", "\\alpha"}},     {"beta", {"β", "\\beta"}},
        {"gamma", {"γ", "\\gamma"}},     {"delta", {"δ", "\\delta"}},
        {"epsilon", {"ε", "\\epsilon"}}, {"varepsilon", {"ϵ", "\\varepsilon"}},
        {"zeta", {"ζ", "\\zeta"}},       {"eta", {"η", "\\eta"}},
        {"theta", {"θ", "\\theta"}},     {"vartheta", {"ϑ", "\\vartheta"}},
        {"iota", {"ι", "\\iota"}},       {"kappa", {"κ", "\\kappa"}},
        {"lambda", {"λ", "\\lambda"}},   {"mu", {"μ", "\\mu"}},
        {"nu", {"ν", "\\nu"}},           {"xi", {"ξ", "\\xi"}},
        {"omicron", {"ο", "o"}},         {"pi", {"π", "\\pi"}},
        {"varpi", {"ϖ", "\\varpi"}},     {"rho", {"ρ", "\\rho"}},
        {"varrho", {"ϱ", "\\varrho"}},   {"sigma", {"σ", "\\sigma"}},
        {"varsigma", {"ς", "\\varsigma"}}, {"tau", {"τ", "\\tau"}},
        {"upsilon", {"υ", "\\upsilon"}}, {"phi", {"φ", "\\phi"}},
        {"varphi", {"ϕ", "\\varphi"}},   {"chi", {"χ", "\\chi"}},
        {"psi", {"ψ", "\\psi"}},         {"omega", {"ω", "\\omega"}},
        {"Gamma", {"Γ", "\\Gamma"}},     {"Delta", {"Δ", "\\Delta"}},
        {"Theta", {"Θ", "\\Theta"}},     {"Lambda", {"Λ", "\\Lambda"}},
        {"Xi", {"Ξ", "\\Xi"}},           {"Pi", {"Π", "\\Pi"}},
        {"Sigma", {"Σ", "\\Sigma"}},     {"Upsilon", {"Υ", "\\Upsilon"}},
        {"Phi", {"Φ", "\\Phi"}},         {"Psi", {"Ψ", "\\Psi"}},
        {"Omega", {"Ω", "\\Omega"}},
    };
    return letters;
}

bool ends_with(const std::string& s, const std::string& suffix)
{
    return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }

/// A name part split into its letters and its trailing digit run: "theta12" -> ("theta", "12").
std::pair<std::string, std::string> split_trailing_digits(const std::string& part)
{
    std::size_t end = part.size();
    while (end > 0 && is_digit(part[end - 1]))
        --end;
    if (end == 0)
        return {part, ""}; // all digits: a number, not a letter with a subscript
    return {part.substr(0, end), part.substr(end)};
}

/// A word as a LaTeX symbol: Greek letter, single letter, or upright multi-letter name.
std::string latex_word(const std::string& word)
{
    auto greek = greek_letters().find(word);
    if (greek != greek_letters().end())
        return greek->second.latex;
    if (word.size() == 1 || std::all_of(word.begin(), word.end(), is_digit))
        return word;
    return "\\mathrm{" + word + "}";
}

/// A word as text: Greek letters in Unicode, anything else unchanged.
std::string text_word(const std::string& word)
{
    auto greek = greek_letters().find(word);
    return greek != greek_letters().end() ? greek->second.text : word;
}

/// A subscript part in LaTeX: its own trailing digits become a further subscript.
std::string latex_part(const std::string& part)
{
    auto [letters, digits] = split_trailing_digits(part);
    std::string out = latex_word(letters);
    if (!digits.empty())
        out += "_{" + digits + "}";
    return out;
}

/// A name with underscores that do not separate subscripts ("a__b", "a_"), in LaTeX.
std::string latex_literal(const std::string& name)
{
    std::string out = "\\mathrm{";
    for (char c : name) {
        if (c == '_')
            out += "\\_";
        else
            out += c;
    }
    return out + "}";
}

} // namespace

std::string print_name(const std::string& name, syntax s)
{
    if (s == syntax::plain)
        return name;

    int dots = 0;
    std::string base = name;
    if (ends_with(name, "_ddot") && name.size() > 5) {
        dots = 2;
        base = name.substr(0, name.size() - 5);
    } else if (ends_with(name, "_dot") && name.size() > 4) {
        dots = 1;
        base = name.substr(0, name.size() - 4);
    }

    std::vector<std::string> parts;
    for (std::size_t start = 0;;) {
        std::size_t end = base.find('_', start);
        parts.push_back(base.substr(start, end == std::string::npos ? std::string::npos : end - start));
        if (end == std::string::npos)
            break;
        start = end + 1;
    }
    const bool regular = std::none_of(parts.begin(), parts.end(), [](const std::string& p) { return p.empty(); });
    auto [letters, digits] = regular ? split_trailing_digits(parts[0]) : std::make_pair(base, std::string());

    if (s == syntax::latex) {
        std::string head = regular ? latex_word(letters) : latex_literal(base);
        if (dots > 0)
            head = (dots == 2 ? "\\ddot{" : "\\dot{") + head + "}";
        std::vector<std::string> subscripts;
        if (!digits.empty())
            subscripts.push_back(digits);
        for (std::size_t i = 1; regular && i < parts.size(); ++i)
            subscripts.push_back(latex_part(parts[i]));
        std::string nested;
        for (auto it = subscripts.rbegin(); it != subscripts.rend(); ++it)
            nested = nested.empty() ? *it : *it + "_{" + nested + "}";
        return nested.empty() ? head : head + "_{" + nested + "}";
    }

    // text
    std::string head = regular ? text_word(letters) : base;
    const bool one_letter = (regular && greek_letters().count(letters) > 0) || (letters.size() == 1 && is_letter(letters[0]));
    if (dots > 0)
        head += one_letter ? (dots == 2 ? "\u0308" : "\u0307") : (dots == 2 ? "''" : "'");
    std::string out = head + digits;
    for (std::size_t i = 1; regular && i < parts.size(); ++i) {
        auto [sub_letters, sub_digits] = split_trailing_digits(parts[i]);
        out += "_" + text_word(sub_letters) + sub_digits;
    }
    return out;
}

} // namespace lagrange
