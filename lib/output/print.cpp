// SPDX-License-Identifier: GPL-2.0-or-later
/** @file print.cpp
 *  Deterministic printers for expressions in plain, text and LaTeX syntax. The
 *  expression tree is walked here, not by GiNaC's printers, so that the order of
 *  terms and factors depends on their printed form only. */
#include "output/print.h"
#include "output/print_pieces.h"

#include "core/number_text.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <utility>

namespace lagrange {

namespace {

using GiNaC::ex;
using GiNaC::is_a;
using GiNaC::numeric;
using namespace print_pieces;

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }

// ---------------------------------------------------------------------------
// Functions

/// LaTeX command of a function printed as an operator (`\sin x`); empty if none.
std::string latex_operator(const std::string& name)
{
    static const std::map<std::string, std::string> operators = {
        {"sin", "\\sin"},     {"cos", "\\cos"},       {"tan", "\\tan"},
        {"sinh", "\\sinh"},   {"cosh", "\\cosh"},     {"tanh", "\\tanh"},
        {"asin", "\\arcsin"}, {"acos", "\\arccos"},   {"atan", "\\arctan"},
        {"log", "\\ln"},
    };
    auto found = operators.find(name);
    return found != operators.end() ? found->second : std::string();
}

/// Functions whose powers print as `\sin^{2}\theta` in LaTeX.
bool is_trigonometric(const std::string& name)
{
    static const char* const names[] = {"sin", "cos", "tan", "sinh", "cosh", "tanh"};
    return std::find_if(std::begin(names), std::end(names), [&](const char* n) { return name == n; }) !=
           std::end(names);
}

/// An argument simple enough to follow a LaTeX operator without parentheses.
bool is_bare_argument(const ex& e)
{
    if (is_a<GiNaC::symbol>(e) || is_a<GiNaC::constant>(e))
        return true;
    return is_a<numeric>(e) && GiNaC::ex_to<numeric>(e).is_pos_integer();
}

/// `\sin` followed by an argument: a space only where the argument starts with a letter or digit.
std::string apply_operator(const std::string& command, const std::string& argument)
{
    if (!argument.empty() && (is_letter(argument[0]) || is_digit(argument[0])))
        return command + " " + argument;
    return command + argument;
}

// ---------------------------------------------------------------------------
// Term order

/// A term of a sum, printed, with what orders it.
struct sum_term {
    piece body;                     ///< the term without its sign
    bool negative = false;
    bool constant = false;          ///< a number only
    bool real = true;               ///< a real coefficient: the sign is known
    std::string monomial;           ///< plain form without the numeric coefficient
    term_degrees degrees;           ///< where the term order puts it
};

/// Compares terms by their printed form, numbers last. Negative if `a` comes first.
int compare_forms(const sum_term& a, const sum_term& b)
{
    if (a.constant != b.constant)
        return a.constant ? 1 : -1;
    if (int c = a.monomial.compare(b.monomial))
        return c;
    return a.body.plain.compare(b.body.plain);
}

// ---------------------------------------------------------------------------
// The printer

class printer {
public:
    printer(syntax syn, const term_order& order) : syn_(syn), order_(order) {}

    piece render(const ex& e) const
    {
        if (is_a<numeric>(e))
            return number_piece(GiNaC::ex_to<numeric>(e), syn_);
        if (is_a<GiNaC::symbol>(e))
            return symbol_piece(e);
        if (is_a<GiNaC::add>(e))
            return sum_piece(e);
        if (is_a<GiNaC::mul>(e)) {
            term_factors parts = split_term(e);
            return product_piece(parts.coefficient, parts.factors);
        }
        if (is_a<GiNaC::power>(e))
            return power_piece(e);
        if (is_a<GiNaC::function>(e))
            return function_piece(e);
        if (is_a<GiNaC::constant>(e))
            return constant_piece(e);
        if (is_a<GiNaC::relational>(e))
            return relation_piece(e);
        return fallback_piece(e);
    }

    /// The terms of `e` (a sum, or one term), in printed order, each after the
    /// first with its sign in front ("+ x", "- y").
    std::vector<std::string> term_strings(const ex& e) const
    {
        if (!is_a<GiNaC::add>(e))
            return {render(e).out};
        std::vector<sum_term> terms = sum_terms(e);
        sort_terms(terms);
        std::vector<std::string> out;
        for (std::size_t i = 0; i < terms.size(); ++i) {
            const char* sign = terms[i].negative ? (i == 0 ? "-" : "- ") : (i == 0 ? "" : "+ ");
            out.push_back(sign + terms[i].body.out);
        }
        return out;
    }

private:
    syntax syn_;
    const term_order& order_;

    const char* times() const { return syn_ == syntax::plain ? "*" : syn_ == syntax::text ? "·" : " "; }

    piece symbol_piece(const ex& e) const
    {
        const std::string& name = GiNaC::ex_to<GiNaC::symbol>(e).get_name();
        piece p;
        p.plain = name;
        p.out = syn_ == syntax::plain ? name : print_name(name, syn_);
        return p;
    }

    piece constant_piece(const ex& e) const
    {
        piece p;
        if (e.is_equal(GiNaC::Pi)) {
            p.plain = "Pi";
            p.out = syn_ == syntax::latex ? "\\pi" : syn_ == syntax::text ? "π" : "Pi";
            return p;
        }
        if (e.is_equal(GiNaC::Euler)) {
            p.plain = "Euler";
            p.out = syn_ == syntax::latex ? "\\gamma_{E}" : syn_ == syntax::text ? "γ" : "Euler";
            return p;
        }
        return fallback_piece(e);
    }

    /// Anything without a printer here: GiNaC's own output, parenthesized where it matters.
    piece fallback_piece(const ex& e) const
    {
        std::ostringstream plain;
        plain << e;
        piece p;
        p.plain = plain.str();
        if (syn_ == syntax::latex) {
            std::ostringstream latex;
            latex << GiNaC::latex << e << GiNaC::dflt;
            p.out = latex.str();
        } else {
            p.out = p.plain;
        }
        if (!is_a<GiNaC::constant>(e)) {
            p.plain_level = sum_level;
            p.out_level = sum_level;
        }
        return p;
    }

    /// Joins printed factors, in order, with the syntax's multiplication sign.
    void join_factors(const std::vector<piece>& items, std::string& plain, std::string& out) const
    {
        for (std::size_t i = 0; i < items.size(); ++i) {
            const piece& item = items[i];
            const bool last = i + 1 == items.size();
            const std::string& item_out = !last && !item.closed.empty() ? item.closed : item.out;
            if (i > 0) {
                plain += '*';
                if (syn_ == syntax::latex && !item_out.empty() && is_digit(item_out[0]))
                    out += " \\cdot ";
                else
                    out += times();
            }
            plain += item.plain;
            out += item_out;
        }
    }

    /// A factor of a product, printed, and parenthesized as a factor.
    struct factor_item {
        piece raw;
        piece wrapped;
        int rank = 0; ///< see factor_rank
    };

    factor_item make_item(const piece& p, int rank = 0) const { return {p, wrap(p, product_level, syn_), rank}; }

    /// Where a factor stands in a product: sums first, then symbols (parameters),
    /// then functions, then the term order's variables in their given order
    /// (m*l^2*cos(theta-phi)*theta_dot*phi_dot, as textbooks write it).
    int factor_rank(const ex& base) const
    {
        if (is_a<GiNaC::add>(base))
            return 0;
        int position = 0;
        for (const auto& group : order_.groups)
            for (const ex& s : group) {
                ++position;
                if (base.is_equal(s))
                    return 2 + position;
            }
        if (is_a<GiNaC::function>(base))
            return 2;
        return 1;
    }

    /// Joins factors above or below a LaTeX fraction line, where a single factor needs no parentheses.
    void join_items(const std::vector<factor_item>& items, std::string& plain, std::string& out) const
    {
        std::vector<piece> wrapped;
        wrapped.reserve(items.size());
        for (const auto& item : items)
            wrapped.push_back(item.wrapped);
        join_factors(wrapped, plain, out);
        if (syn_ == syntax::latex && items.size() == 1)
            out = items.front().raw.out;
    }

    /// A product printed without its sign.
    struct product_result {
        piece body;
        bool negative = false;
        std::string monomial; ///< plain form without the coefficient: a term's sort key in a sum
    };

    /// coefficient * factors: factors sorted by their plain form, those with a
    /// negative exponent as a denominator, sums with an integer exponent in a
    /// sign of their own (GiNaC's choice depends on its internal order).
    product_result product_parts(numeric coefficient, const GiNaC::exvector& factors) const
    {
        std::vector<factor_item> numerator;
        std::vector<factor_item> denominator;
        for (const ex& factor : factors) {
            ex base = factor;
            numeric k = 1;
            if (is_a<GiNaC::power>(factor) && is_a<numeric>(factor.op(1)) &&
                GiNaC::ex_to<numeric>(factor.op(1)).is_real()) {
                base = factor.op(0);
                k = GiNaC::ex_to<numeric>(factor.op(1));
            } else if (is_a<GiNaC::power>(factor)) {
                numerator.push_back(make_item(render(factor), 1));
                continue;
            }
            const bool below = k < 0;
            const numeric magnitude = below ? -k : k;
            piece item;
            if (is_a<GiNaC::add>(base) && k.is_integer()) {
                auto [sum, flipped] = canonical_sum(base);
                if (flipped && k.is_odd())
                    coefficient = -coefficient;
                item = magnitude == 1 ? sum : power_of(sum, magnitude);
            } else if (below) {
                item = render(GiNaC::pow(base, magnitude));
            } else {
                item = render(factor);
            }
            (below ? denominator : numerator).push_back(make_item(item, factor_rank(base)));
        }
        auto by_plain = [](const factor_item& a, const factor_item& b) {
            return a.rank != b.rank ? a.rank < b.rank : a.wrapped.plain < b.wrapped.plain;
        };
        std::stable_sort(numerator.begin(), numerator.end(), by_plain);
        std::stable_sort(denominator.begin(), denominator.end(), by_plain);

        product_result result;
        result.negative = coefficient.is_real() && coefficient < 0;
        if (result.negative)
            coefficient = -coefficient;

        std::string ignored;
        join_items(numerator, result.monomial, ignored);
        if (!denominator.empty()) {
            std::string below_plain;
            join_items(denominator, below_plain, ignored);
            result.monomial = (numerator.empty() ? "1" : result.monomial) + "/" + below_plain;
        }

        if (factors.empty()) {
            result.body = number_piece(coefficient, syn_);
            return result;
        }

        const bool rational = coefficient.is_rational();
        piece& body = result.body;
        body.plain_level = product_level;
        body.out_level = product_level;
        if (denominator.empty()) {
            std::vector<factor_item> items;
            if (coefficient != 1) {
                factor_item c = make_item(number_piece(coefficient, syn_));
                if (rational && !coefficient.is_integer() && syn_ == syntax::text)
                    c.wrapped.out = "(" + c.wrapped.out + ")";
                items.push_back(c);
            }
            items.insert(items.end(), numerator.begin(), numerator.end());
            if (items.size() == 1) {
                body = items.front().wrapped;
                return result;
            }
            std::vector<piece> wrapped;
            for (const auto& item : items)
                wrapped.push_back(item.wrapped);
            join_factors(wrapped, body.plain, body.out);
            return result;
        }

        // A quotient: integer parts of the coefficient go above and below the line.
        std::vector<factor_item> above;
        std::vector<factor_item> below;
        if (rational) {
            if (coefficient.numer() != 1 || numerator.empty())
                above.push_back(make_item(number_piece(coefficient.numer(), syn_)));
            if (coefficient.denom() != 1)
                below.push_back(make_item(number_piece(coefficient.denom(), syn_)));
        } else {
            above.push_back(make_item(number_piece(coefficient, syn_)));
        }
        above.insert(above.end(), numerator.begin(), numerator.end());
        below.insert(below.end(), denominator.begin(), denominator.end());

        std::string above_plain, above_out, below_plain, below_out;
        join_items(above, above_plain, above_out);
        join_items(below, below_plain, below_out);
        const bool single_below = below.size() == 1;
        if (!single_below || below.front().wrapped.plain_level < power_level)
            below_plain = "(" + below_plain + ")";
        if (syn_ == syntax::latex) {
            body.out = "\\frac{" + above_out + "}{" + below_out + "}";
        } else {
            if (!single_below || below.front().wrapped.out_level < power_level)
                below_out = "(" + below_out + ")";
            body.out = above_out + "/" + below_out;
        }
        body.plain = above_plain + "/" + below_plain;
        return result;
    }

    piece product_piece(const numeric& coefficient, const GiNaC::exvector& factors) const
    {
        product_result parts = product_parts(coefficient, factors);
        return parts.negative ? negated(parts.body) : parts.body;
    }

    /// The terms of a sum, printed, with what orders them.
    std::vector<sum_term> sum_terms(const ex& e) const
    {
        std::vector<sum_term> terms;
        terms.reserve(e.nops());
        for (const ex& term : e) {
            const term_factors split = split_term(term);
            product_result parts = product_parts(split.coefficient, split.factors);
            sum_term t;
            t.negative = parts.negative;
            t.constant = split.factors.empty();
            t.real = split.coefficient.is_real();
            t.body = wrap(parts.body, product_level, syn_);
            t.monomial = std::move(parts.monomial);
            t.degrees = degrees_of(term, order_);
            terms.push_back(std::move(t));
        }
        return terms;
    }

    /// The terms ordered by the term order's groups, positive terms before
    /// negative ones, constants last, then by their plain form; then joined.
    static void sort_terms(std::vector<sum_term>& terms)
    {
        std::sort(terms.begin(), terms.end(), [](const sum_term& a, const sum_term& b) {
            if (int c = compare_degrees(a.degrees, b.degrees))
                return c < 0;
            if (a.negative != b.negative)
                return b.negative;
            if (int c = compare_forms(a, b))
                return c < 0;
            return false;
        });
    }

    piece assemble_sum(std::vector<sum_term>& terms) const
    {
        sort_terms(terms);

        piece result;
        result.plain_level = sum_level;
        result.out_level = sum_level;
        for (std::size_t i = 0; i < terms.size(); ++i) {
            const sum_term& t = terms[i];
            if (i == 0) {
                if (t.negative) {
                    result.plain += '-';
                    result.out += '-';
                }
            } else {
                result.plain += t.negative ? '-' : '+';
                if (syn_ == syntax::plain)
                    result.out += t.negative ? "-" : "+";
                else
                    result.out += t.negative ? " - " : " + ";
            }
            result.plain += t.body.plain;
            result.out += t.body.out;
        }
        return result;
    }

    piece sum_piece(const ex& e) const
    {
        std::vector<sum_term> terms = sum_terms(e);
        return assemble_sum(terms);
    }

    /// The sum or its negative, whichever has a positive leading term (by the
    /// order without signs); true if negated. For a factor whose sign can go
    /// into the coefficient: GiNaC writes (c-d)^3 or -(d-c)^3 depending on its
    /// internal order.
    std::pair<piece, bool> canonical_sum(const ex& e) const
    {
        std::vector<sum_term> terms = sum_terms(e);
        const sum_term* leading = nullptr;
        for (const auto& t : terms) {
            if (!t.real)
                return {assemble_sum(terms), false};
            if (!leading) {
                leading = &t;
                continue;
            }
            int c = compare_degrees(t.degrees, leading->degrees);
            if (c == 0)
                c = compare_forms(t, *leading);
            if (c < 0)
                leading = &t;
        }
        if (!leading || !leading->negative)
            return {assemble_sum(terms), false};
        for (auto& t : terms)
            t.negative = !t.negative;
        return {assemble_sum(terms), true};
    }

    piece power_piece(const ex& e) const
    {
        const ex& base = e.op(0);
        const ex& exponent = e.op(1);
        if (!is_a<numeric>(exponent))
            return power_of(render(base), exponent);
        const numeric& k = GiNaC::ex_to<numeric>(exponent);
        if (k.is_real() && k < 0)
            return product_piece(1, {e});
        if (k == numeric(1, 2))
            return sqrt_piece(base);
        if (syn_ == syntax::latex && k.is_pos_integer() && is_a<GiNaC::function>(base) && base.nops() == 1 &&
            is_trigonometric(GiNaC::ex_to<GiNaC::function>(base).get_name()))
            return trigonometric_power_piece(base, k);
        if (is_a<GiNaC::add>(base) && k.is_integer()) {
            auto [sum, flipped] = canonical_sum(base);
            piece p = power_of(sum, exponent);
            return flipped && k.is_odd() ? negated(p) : p;
        }
        return power_of(render(base), exponent);
    }

    /// A printed base raised to `exponent`.
    piece power_of(const piece& base, const ex& exponent) const
    {
        const piece b = wrap(base, atom_level, syn_);
        const piece x = render(exponent);
        piece p;
        p.plain_level = power_level;
        p.out_level = power_level;
        const bool plain_bare = x.plain_level == atom_level;
        p.plain = b.plain + "^" + (plain_bare ? x.plain : "(" + x.plain + ")");
        const numeric* k = is_a<numeric>(exponent) ? &GiNaC::ex_to<numeric>(exponent) : nullptr;
        switch (syn_) {
        case syntax::plain:
            p.out = p.plain;
            break;
        case syntax::text:
            if (k && k->is_nonneg_integer())
                p.out = b.out + superscript(x.out);
            else
                p.out = b.out + "^" + (x.out_level == atom_level ? x.out : "(" + x.out + ")");
            break;
        case syntax::latex:
            if (k && k->is_rational() && !k->is_integer())
                p.out = b.out + "^{" + x.plain + "}";
            else
                p.out = b.out + "^{" + x.out + "}";
            break;
        }
        return p;
    }

    piece sqrt_piece(const ex& base) const
    {
        const piece b = render(base);
        piece p;
        p.plain = "sqrt(" + b.plain + ")";
        switch (syn_) {
        case syntax::plain:
            p.out = p.plain;
            break;
        case syntax::text:
            p.out = "√" + (b.out_level == atom_level ? b.out : "(" + b.out + ")");
            p.out_level = power_level;
            break;
        case syntax::latex:
            p.out = "\\sqrt{" + b.out + "}";
            break;
        }
        return p;
    }

    /// `\sin^{2}\theta` (LaTeX only).
    piece trigonometric_power_piece(const ex& function, const numeric& k) const
    {
        const piece argument = render(function.op(0));
        const std::string command =
            latex_operator(GiNaC::ex_to<GiNaC::function>(function).get_name()) + "^{" + integer_string(k) + "}";
        piece p;
        p.plain = GiNaC::ex_to<GiNaC::function>(function).get_name() + "(" + argument.plain + ")^" + integer_string(k);
        p.plain_level = power_level;
        p.out_level = power_level;
        p.closed = command + "\\left(" + argument.out + "\\right)";
        p.out = is_bare_argument(function.op(0)) ? apply_operator(command, argument.out) : p.closed;
        return p;
    }

    piece function_piece(const ex& e) const
    {
        const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
        std::vector<piece> arguments;
        arguments.reserve(e.nops());
        for (const ex& argument : e)
            arguments.push_back(render(argument));

        piece p;
        p.plain = name + "(";
        for (std::size_t i = 0; i < arguments.size(); ++i)
            p.plain += (i > 0 ? "," : "") + arguments[i].plain;
        p.plain += ")";

        auto joined = [&](const char* separator) {
            std::string s;
            for (std::size_t i = 0; i < arguments.size(); ++i)
                s += (i > 0 ? separator : "") + arguments[i].out;
            return s;
        };
        switch (syn_) {
        case syntax::plain:
            p.out = p.plain;
            break;
        case syntax::text:
            if (name == "abs" && arguments.size() == 1)
                p.out = "|" + arguments[0].out + "|";
            else
                p.out = (name == "log" ? std::string("ln") : name) + "(" + joined(", ") + ")";
            break;
        case syntax::latex: {
            const std::string command = latex_operator(name);
            if (name == "exp" && arguments.size() == 1) {
                p.out = "e^{" + arguments[0].out + "}";
                p.out_level = power_level;
            } else if (name == "abs" && arguments.size() == 1) {
                p.out = "\\left|" + arguments[0].out + "\\right|";
            } else if (!command.empty() && arguments.size() == 1) {
                p.closed = command + "\\left(" + arguments[0].out + "\\right)";
                if (is_bare_argument(e.op(0))) {
                    p.out = apply_operator(command, arguments[0].out);
                    p.out_level = power_level;
                } else {
                    p.out = p.closed;
                    p.closed.clear();
                }
            } else {
                p.out = "\\operatorname{" + name + "}\\left(" + joined(", ") + "\\right)";
            }
            break;
        }
        }
        return p;
    }

    piece relation_piece(const ex& e) const
    {
        const piece lhs = render(e.lhs());
        const piece rhs = render(e.rhs());
        const char* plain_op = "==";
        const char* text_op = "=";
        const char* latex_op = "=";
        if (e.info(GiNaC::info_flags::relation_not_equal)) {
            plain_op = "!=", text_op = "≠", latex_op = "\\neq";
        } else if (e.info(GiNaC::info_flags::relation_less)) {
            plain_op = "<", text_op = "<", latex_op = "<";
        } else if (e.info(GiNaC::info_flags::relation_less_or_equal)) {
            plain_op = "<=", text_op = "≤", latex_op = "\\le";
        } else if (e.info(GiNaC::info_flags::relation_greater)) {
            plain_op = ">", text_op = ">", latex_op = ">";
        } else if (e.info(GiNaC::info_flags::relation_greater_or_equal)) {
            plain_op = ">=", text_op = "≥", latex_op = "\\ge";
        }
        piece p;
        p.plain = lhs.plain + plain_op + rhs.plain;
        switch (syn_) {
        case syntax::plain: p.out = p.plain; break;
        case syntax::text: p.out = lhs.out + " " + text_op + " " + rhs.out; break;
        case syntax::latex: p.out = lhs.out + " " + latex_op + " " + rhs.out; break;
        }
        p.plain_level = relation_level;
        p.out_level = relation_level;
        return p;
    }
};

} // namespace

std::string print(const GiNaC::ex& e, syntax s, const term_order& order)
{
    return printer(s, order).render(e).out;
}

std::vector<std::string> print_terms(const GiNaC::ex& e, syntax s, const term_order& order)
{
    return printer(s, order).term_strings(e);
}

} // namespace lagrange
