// SPDX-License-Identifier: GPL-2.0-or-later
/** @file lower_expression.cpp
 *  Lowering of expressions: declared names only, `q'` only for coordinates, reserved
 *  names, exact integers and rationals, and no arithmetic that could hang or exhaust
 *  memory (the limits below). Also rules files (expressions with wildcards), the
 *  embedded rules and a scene's simplifier. GiNaC only ever sees expressions built
 *  here, never text. */
#include "scene/lower_expression.h"

#include "scene/lexer.h"
#include "scene/lower.h"
#include "scene/parser.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace lagrange {

namespace {

// ---- limits that keep exact arithmetic from hanging --------------------------
constexpr long max_integer_exponent = 1000;     ///< |n| in x^n
constexpr long max_exponent_denominator = 1000; ///< q in x^(p/q)
constexpr long max_number_bits = 100000;        ///< about 30,000 decimal digits

bool ends_with(const std::string& s, const std::string& suffix)
{
    return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

[[noreturn]] void fail(const expr_node& node, const std::string& message)
{
    throw scene_error(node.where, message);
}

long bits_of(const GiNaC::numeric& n)
{
    if (!n.is_rational())
        return 0;
    return GiNaC::numer(n).int_length() + GiNaC::denom(n).int_length();
}

/// Every exact number stays below max_number_bits; complex numbers are refused.
GiNaC::ex checked(const GiNaC::ex& value, const expr_node& node)
{
    if (GiNaC::is_a<GiNaC::numeric>(value)) {
        const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(value);
        if (!n.is_real())
            fail(node, "this is not a real number (the square root or power of a negative number?)");
        if (bits_of(n) > max_number_bits)
            fail(node, "number too large (more than 30,000 digits)");
    }
    return value;
}

/// The labels of the wildcards in `e`.
std::set<unsigned> wildcards_in(const GiNaC::ex& e)
{
    std::set<unsigned> labels;
    for (GiNaC::const_preorder_iterator i = e.preorder_begin(); i != e.preorder_end(); ++i)
        if (GiNaC::is_a<GiNaC::wildcard>(*i))
            labels.insert(GiNaC::ex_to<GiNaC::wildcard>(*i).get_label());
    return labels;
}

} // namespace

const std::set<std::string>& reserved_names()
{
    static const std::set<std::string> names = {
        "scene", "parameters", "coordinates", "let", "point", "gravity", "spring", "body",
        "omega", "torque", "equilibrium", "ratio", "limit", "values", "initial", "simulate",
        "use", "want", "mass", "at", "along", "between", "and", "rest", "region", "density",
        "inertia", "axis", "orientation", "until", "step", "method", "tolerance", "t", "Pi",
        "pi", "oo", "dot", "dissipation", "damper", "force", "input", "on"};
    return names;
}

void expression_lowering::adopt_names(const model& scene)
{
    for (const parameter& p : scene.parameters)
        names_[p.name] = {name_entry::kind::parameter, p.symbol, 0, {}};
    for (std::size_t i = 0; i < scene.coordinates.size(); ++i)
        names_[scene.coordinates[i].name] = {name_entry::kind::coordinate,
                                             scene.coordinates[i].position, i, {}};
    for (const input_signal& u : scene.inputs)
        names_[u.name] = {name_entry::kind::input, u.symbol, 0, u.where};
    for (const rigid_body& b : scene.bodies)
        if (b.omega)
            for (const GiNaC::realsymbol& w : *b.omega)
                names_[w.get_name()] = {name_entry::kind::angular, w, 0, {}};
    coordinates_ = scene.coordinates;
    scene_.time = scene.time;
}

void expression_lowering::declare_name(const name_ref& n, const char* what)
{
    if (reserved_names().count(n.name) || function_names().count(n.name))
        throw scene_error(n.where, quote(n.name) + " is reserved and cannot name a " + what);
    if (ends_with(n.name, "_dot") || ends_with(n.name, "_ddot"))
        throw scene_error(n.where, "names ending in `_dot` or `_ddot` are reserved for velocities "
                                   "and accelerations; write " + quote(n.name.substr(0, n.name.rfind('_')) + "'") +
                                       " for a velocity");
    auto found = names_.find(n.name);
    if (found != names_.end())
        throw scene_error(n.where, quote(n.name) + " is already declared at line " +
                                       std::to_string(found->second.declared.line));
}

std::vector<GiNaC::ex> expression_lowering::lower_vector(const vector_expr& v, const expr_context& context)
{
    std::vector<GiNaC::ex> components;
    for (const expr_ptr& c : v.components)
        components.push_back(lower(*c, context));
    while (components.size() < 3)
        components.push_back(0);
    return components;
}

GiNaC::ex expression_lowering::lower(const expr_node& node, const expr_context& context)
{
    using kind = expr_node::kind;
    switch (node.node_kind) {
    case kind::integer:
        return GiNaC::numeric(node.text.c_str());
    case kind::decimal: {
        errno = 0;
        double value = std::strtod(node.text.c_str(), nullptr);
        if (errno == ERANGE || !std::isfinite(value))
            fail(node, "the number " + node.text + " is out of the range of floating point");
        return GiNaC::numeric(value);
    }
    case kind::wildcard:
        if (!context.wildcards)
            fail(node, "wildcards (`$0`) belong in rule files");
        return GiNaC::wild(static_cast<unsigned>(std::stoul(node.text)));
    case kind::name:
        return lower_name(node, context);
    case kind::velocity:
        return lower_velocity(node, node.text, context);
    case kind::negate:
        return checked(-lower(*node.operands[0], context), node);
    case kind::sum: {
        GiNaC::exvector terms;
        for (std::size_t i = 0; i < node.operands.size(); ++i) {
            GiNaC::ex term = lower(*node.operands[i], context);
            terms.push_back(node.ops[i] == '-' ? -term : term);
        }
        return checked(GiNaC::add(terms), node);
    }
    case kind::product: {
        GiNaC::ex result = 1;
        for (std::size_t i = 0; i < node.operands.size(); ++i) {
            GiNaC::ex factor = lower(*node.operands[i], context);
            if (node.ops[i] == '/') {
                if (factor.is_zero())
                    fail(*node.operands[i], "division by zero");
                result = checked(result / factor, node);
            } else {
                result = checked(result * factor, node);
            }
        }
        return result;
    }
    case kind::power:
        return lower_power(node, context);
    case kind::call:
        return lower_call(node, context);
    }
    fail(node, "unexpected expression");
}

GiNaC::ex expression_lowering::lower_name(const expr_node& node, const expr_context& context)
{
    const std::string& name = node.text;
    if (name == "Pi" || name == "pi")
        return GiNaC::Pi;
    if (name == "t") {
        if (!context.time)
            fail(node, std::string("time `t` cannot appear in ") + context.what);
        return scene_.time;
    }
    if (function_names().count(name) || name == "dot")
        fail(node, quote(name) + " is a function: write `" + name + "(...)`");
    auto found = names_.find(name);
    if (found == names_.end()) {
        if (ends_with(name, "_dot") || ends_with(name, "_ddot"))
            fail(node, "unknown name " + quote(name) + "; the velocity of `q` is written `q'`");
        fail(node, "unknown name " + quote(name) + ": declare it with `parameters`, `coordinates` or `let`");
    }
    const name_entry& entry = found->second;
    switch (entry.name_kind) {
    case name_entry::kind::parameter:
        if (!context.parameters)
            fail(node, "parameter `" + name + "` cannot appear in " + context.what + ": give a number");
        return entry.value;
    case name_entry::kind::coordinate:
        if (!context.coordinates)
            fail(node, "coordinate `" + name + "` cannot appear in " + context.what);
        return entry.value;
    case name_entry::kind::shorthand:
        if ((!context.coordinates && has_position(entry.value)) ||
            (!context.velocities && has_velocity(entry.value)))
            fail(node, "shorthand `" + name + "` depends on the motion and cannot appear in " + context.what);
        return entry.value;
    case name_entry::kind::ratio:
        fail(node, quote(name) + " is a ratio: it names results, and cannot appear in expressions");
    case name_entry::kind::angular:
        if (!context.angular)
            fail(node, "angular velocity " + quote(name) + " cannot appear in " + context.what +
                           " (only in a `torque`)");
        return entry.value;
    case name_entry::kind::input:
        if (!context.inputs)
            fail(node, "input " + quote(name) + " cannot appear in " + context.what +
                           " (only in a `force`)");
        return entry.value;
    }
    fail(node, "unexpected name");
}

bool expression_lowering::has_position(const GiNaC::ex& e) const
{
    for (const coordinate& c : coordinates_)
        if (e.has(c.position))
            return true;
    return false;
}

bool expression_lowering::has_velocity(const GiNaC::ex& e) const
{
    for (const coordinate& c : coordinates_)
        if (e.has(c.velocity))
            return true;
    return false;
}

GiNaC::ex expression_lowering::lower_velocity(const expr_node& node, const std::string& name, const expr_context& context)
{
    auto found = names_.find(name);
    if (found == names_.end() || found->second.name_kind != name_entry::kind::coordinate)
        fail(node, quote(name + "'") + ": only coordinates have velocities, and " + quote(name) + " is not a coordinate");
    if (!context.velocities)
        fail(node, std::string("velocities cannot appear in ") + context.what);
    return coordinates_[found->second.index].velocity;
}

GiNaC::ex expression_lowering::lower_power(const expr_node& node, const expr_context& context)
{
    GiNaC::ex base = lower(*node.operands[0], context);
    GiNaC::ex exponent = lower(*node.operands[1], context);
    if (GiNaC::is_a<GiNaC::numeric>(exponent)) {
        const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(exponent);
        if (n.is_rational()) {
            if (GiNaC::abs(GiNaC::numer(n)) > max_integer_exponent ||
                GiNaC::denom(n) > max_exponent_denominator)
                fail(*node.operands[1], "exponent too large: powers go up to " +
                                            std::to_string(max_integer_exponent) +
                                            " (and roots up to the " +
                                            std::to_string(max_exponent_denominator) + "th)");
            if (GiNaC::is_a<GiNaC::numeric>(base)) {
                const GiNaC::numeric& b = GiNaC::ex_to<GiNaC::numeric>(base);
                if (b.is_zero() && n.is_negative())
                    fail(node, "division by zero (zero to a negative power)");
                if (bits_of(b) * GiNaC::abs(GiNaC::numer(n)).to_long() > max_number_bits)
                    fail(node, "number too large (more than 30,000 digits)");
            }
        }
    }
    return checked(GiNaC::pow(base, exponent), node);
}

GiNaC::ex expression_lowering::lower_call(const expr_node& node, const expr_context& context)
{
    const std::string& f = node.text;
    if (f == "dot") {
        if (node.operands.size() != 1 || node.operands[0]->node_kind != expr_node::kind::name)
            fail(node, "`dot(q)` takes the name of one coordinate");
        return lower_velocity(*node.operands[0], node.operands[0]->text, context);
    }
    if (!function_names().count(f)) {
        if (names_.count(f))
            fail(node, quote(f) + " is not a function: write `" + f + "*(...)` to multiply");
        fail(node, "unknown function " + quote(f) + "; the functions are sin cos tan exp log sqrt "
                                            "sinh cosh tanh asin acos atan abs");
    }
    if (node.operands.size() != 1)
        fail(node, quote(f) + " takes one argument");
    GiNaC::ex x = lower(*node.operands[0], context);
    try {
        GiNaC::ex value;
        if (f == "sin") value = GiNaC::sin(x);
        else if (f == "cos") value = GiNaC::cos(x);
        else if (f == "tan") value = GiNaC::tan(x);
        else if (f == "exp") value = GiNaC::exp(x);
        else if (f == "log") value = GiNaC::log(x);
        else if (f == "sqrt") value = GiNaC::sqrt(x);
        else if (f == "sinh") value = GiNaC::sinh(x);
        else if (f == "cosh") value = GiNaC::cosh(x);
        else if (f == "tanh") value = GiNaC::tanh(x);
        else if (f == "asin") value = GiNaC::asin(x);
        else if (f == "acos") value = GiNaC::acos(x);
        else if (f == "atan") value = GiNaC::atan(x);
        else value = GiNaC::abs(x);
        return checked(value, node);
    } catch (const scene_error&) {
        throw;
    } catch (const std::exception&) {
        fail(node, quote(f) + " has no value here (a pole or a point outside its domain)");
    }
}

std::vector<rewrite_rule> load_rules(const source_text& source, const model* scene)
{
    return with_source(source, [&] {
        lexer_options options;
        options.allow_wildcards = true;
        std::vector<parsed_rule> parsed = parse_rules(tokenize(source, options));
        expression_lowering lower;
        if (scene)
            lower.adopt_names(*scene);
        expr_context context{"a rule"};
        context.velocities = true;
        context.wildcards = true;
        std::vector<rewrite_rule> rules;
        for (const parsed_rule& r : parsed) {
            GiNaC::ex pattern = lower.lower(*r.pattern, context);
            GiNaC::ex replacement = lower.lower(*r.replacement, context);
            if (GiNaC::is_a<GiNaC::numeric>(pattern))
                throw scene_error(r.where, "a rule's pattern cannot be a number");
            std::set<unsigned> pattern_wilds = wildcards_in(pattern);
            for (unsigned label : wildcards_in(replacement))
                if (!pattern_wilds.count(label))
                    throw scene_error(r.where, "wildcard `$" + std::to_string(label) +
                                                   "` of the replacement does not appear in the pattern");
            rules.push_back({pattern, replacement,
                             source.file() + ":" + std::to_string(r.where.line)});
        }
        return rules;
    });
}

const std::vector<rewrite_rule>& embedded_rules()
{
    static const std::vector<rewrite_rule> rules = [] {
        std::vector<rewrite_rule> all;
        for (const embedded_rule_file& file : embedded_rule_files()) {
            std::vector<rewrite_rule> some = load_rules(source_text(std::string("rules/") + file.name, file.text), nullptr);
            all.insert(all.end(), some.begin(), some.end());
        }
        return all;
    }();
    return rules;
}

simplifier make_simplifier(const model& scene)
{
    simplifier s;
    s.angles = scene.positions();
    for (const GiNaC::ex& a : scene.accelerations())
        s.variables.append(a);
    for (const GiNaC::ex& v : scene.velocities())
        s.variables.append(v);
    s.rules = embedded_rules();
    s.rules.insert(s.rules.end(), scene.rules.begin(), scene.rules.end());
    return s;
}

} // namespace lagrange
