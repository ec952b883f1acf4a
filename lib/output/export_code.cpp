// SPDX-License-Identifier: GPL-2.0-or-later
/** @file export_code.cpp
 *  Exported code (see export_code.h): the names, the programs of exported_system written line
 *  by line in C, NumPy or Octave (export_program.h), and the choice of target; each target's
 *  files are written in export_c.cpp, export_python.cpp and export_octave.cpp. */
#include "output/export_code.h"
#include "output/export_program.h"

#include "engine/analysis.h"

#include "core/number_text.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>
#include <sstream>

namespace lagrange {

namespace export_detail {

const std::set<std::string>& keywords(dialect d)
{
    static const std::set<std::string> c = {
        "auto", "break", "case", "char", "const", "continue", "default", "do", "double", "else", "enum", "extern",
        "float", "for", "goto", "if", "inline", "int", "long", "register", "restrict", "return", "short",
        "signed", "sizeof", "static", "struct", "switch", "typedef", "union", "unsigned", "void", "volatile",
        "while", "_Bool", "_Complex", "_Imaginary", "sin", "cos", "sqrt", "exp", "log", "pow", "fabs", "sinh", "cosh",
        "tanh", "asin", "acos", "atan", "NAN",
        "INFINITY", "HUGE_VAL", "isfinite", "main", "uint64_t", "lagrange_augmented", "lagrange_augmented_system",
        "lagrange_constraint_derivatives", "lagrange_constraint_parts", "lagrange_derivatives",
        "lagrange_factor", "lagrange_ipow", "lagrange_linear", "lagrange_lu_solve", "lagrange_mass_and_forcing",
        "lagrange_sincos", "lagrange_sincos2", "lagrange_solve"};
    static const std::set<std::string> python = {
        "False", "None", "True", "and", "as", "assert", "async", "await", "break", "class", "continue", "def",
        "del", "elif", "else", "except", "finally", "for", "from", "global", "if", "import", "in", "is", "lambda",
        "nonlocal", "not", "or", "pass", "raise", "return", "try", "while", "with", "yield", "match", "case",
        "type", "np"};
    static const std::set<std::string> octave = {
        "break", "case", "catch", "classdef", "continue", "do", "else", "elseif", "end", "end_try_catch",
        "end_unwind_protect", "endclassdef", "endenumeration", "endevents", "endfor", "endfunction", "endif",
        "endmethods", "endparfor", "endproperties", "endswitch", "endwhile", "enumeration", "events", "for",
        "function", "global", "if", "methods", "otherwise", "parfor", "persistent", "properties", "return",
        "switch", "try", "until", "unwind_protect", "unwind_protect_cleanup", "while", "nargin", "nargout"};
    return d == dialect::c ? c : d == dialect::python ? python : octave;
}

namespace {

/// Argument and result names of the generated functions: a scene name equal to one is renamed.
const std::set<std::string> argument_names = {"t", "x", "u", "p", "shape", "dxdt", "M", "F", "D", "dfdx", "dfdu",
                                              "h", "i", "j", "k", "qdd", "column",
                                              "conserved"};

} // namespace

naming name_symbols(const exported_system& system, dialect d)
{
    std::vector<std::string> given = system.state_names;
    given.push_back("t");
    given.insert(given.end(), system.parameter_names.begin(), system.parameter_names.end());
    given.insert(given.end(), system.input_names.begin(), system.input_names.end());
    naming out;
    std::set<std::string> taken(given.begin(), given.end());
    for (std::size_t k = 0; k < given.size(); ++k) {
        std::string name = given[k];
        if (name != "t") // time is the argument t itself
            while (keywords(d).count(name) || argument_names.count(name) || (name != given[k] && taken.count(name)))
                name += '_';
        if (name != given[k]) {
            out.renamed.emplace_back(given[k], name);
            taken.insert(name);
        }
        out.symbols.push_back(name);
    }
    auto collides = [&](const std::string& prefix) {
        for (const std::string& name : out.symbols)
            if (name.size() > prefix.size() && name.compare(0, prefix.size(), prefix) == 0 &&
                std::all_of(name.begin() + static_cast<std::ptrdiff_t>(prefix.size()), name.end(),
                            [](unsigned char c) { return std::isdigit(c); }))
                return true;
        return false;
    };
    while (collides(out.temporary))
        out.temporary += '_';
    return out;
}

argument_place place_of(int k, const exported_system& system)
{
    const int n = static_cast<int>(system.coordinates);
    const int parameters = static_cast<int>(system.parameter_names.size());
    if (k < 2 * n)
        return {'x', k};
    if (k == 2 * n)
        return {'t', 0};
    if (k <= 2 * n + parameters)
        return {'p', k - 2 * n - 1};
    return {'u', k - 2 * n - 1 - parameters};
}

namespace {

using op = instruction::code;

/// Which instructions an output reads: a program's definitions (the steps of a recursion)
/// are compiled whether read or not, and an unread one would be an unused variable in C.
std::vector<bool> live_instructions(const expression_program& program)
{
    const std::vector<instruction>& code = program.code();
    std::vector<bool> live(code.size(), false);
    for (int s : program.output_slots())
        live[static_cast<std::size_t>(s)] = true;
    for (std::size_t k = code.size(); k-- > 0;) {
        if (!live[k] || !reads_first_slot(code[k].op))
            continue;
        live[static_cast<std::size_t>(code[k].first)] = true;
        if (reads_second_slot(code[k].op))
            live[static_cast<std::size_t>(code[k].second)] = true;
    }
    return live;
}

/// Each argument slot whose sine or cosine is taken: the indices of its (first) sine and
/// cosine, or past the program's end for one not taken.
std::map<int, std::pair<std::size_t, std::size_t>> sincos_pairs(const expression_program& program,
                                                                 const std::vector<bool>& live)
{
    const std::vector<instruction>& code = program.code();
    std::map<int, std::pair<std::size_t, std::size_t>> pairs;
    for (std::size_t k = 0; k < code.size(); ++k)
        if (live[k] && (code[k].op == op::sine || code[k].op == op::cosine)) {
            auto [at, fresh] = pairs.try_emplace(code[k].first, code.size() + k, code.size() + k);
            std::size_t& first = code[k].op == op::sine ? at->second.first : at->second.second;
            first = std::min(first, k); // a repeated one reads the first's value
        }
    return pairs;
}

/// The arguments that lagrange_sincos2 takes two at a time in C: those that are symbols
/// (known from the start), in the order of their first sine or cosine, an even count.
std::vector<int> paired_arguments(const expression_program& program,
                                  const std::map<int, std::pair<std::size_t, std::size_t>>& pairs)
{
    std::vector<std::pair<std::size_t, int>> first; // (first use, argument slot)
    for (const auto& [argument, uses] : pairs)
        if (program.code()[static_cast<std::size_t>(argument)].op == op::symbol)
            first.emplace_back(std::min(uses.first, uses.second), argument);
    std::sort(first.begin(), first.end());
    std::vector<int> out;
    for (std::size_t k = 0; k + 1 < first.size(); k += 2)
        out.insert(out.end(), {first[k].second, first[k + 1].second});
    return out;
}

} // namespace

bool takes_sincos_pairs(const expression_program& program)
{
    const std::vector<bool> live = live_instructions(program);
    return !paired_arguments(program, sincos_pairs(program, live)).empty();
}

std::vector<std::string> write_program(const expression_program& program, dialect d, const naming& names,
                                       const std::string& indent, std::ostringstream& lines, std::set<int>& used)
{
    const std::vector<instruction>& code = program.code();
    std::vector<std::string> slot(code.size());
    const char* end = d == dialect::python ? "\n" : ";\n";
    const char* declare = d == dialect::c ? "const double " : "";
    const std::vector<bool> live = live_instructions(program);
    // In C an argument's sine and cosine come from one lagrange_sincos call, at the first of
    // the two; the arguments that are symbols two at a time from lagrange_sincos2, first
    // (its two lanes are taken at once where the compiler vectorizes straight-line code).
    std::map<int, std::pair<std::size_t, std::size_t>> pairs;
    std::set<int> paired;
    if (d == dialect::c) {
        pairs = sincos_pairs(program, live);
        const std::vector<int> arguments = paired_arguments(program, pairs);
        paired.insert(arguments.begin(), arguments.end());
        for (std::size_t k = 0; k < arguments.size(); k += 2) {
            std::string declared, pointers, values;
            for (int argument : {arguments[k], arguments[k + 1]}) {
                const int symbol = code[static_cast<std::size_t>(argument)].first;
                used.insert(symbol);
                values += names.symbols[static_cast<std::size_t>(symbol)] + ", ";
                for (std::size_t at : {pairs.at(argument).first, pairs.at(argument).second}) {
                    declared += (declared.empty() ? "" : ", ") + names.temporary + std::to_string(at);
                    pointers += ", &" + names.temporary + std::to_string(at);
                }
            }
            lines << indent << "double " << declared << ";\n"
                  << indent << "lagrange_sincos2(" << values.substr(0, values.size() - 2) << pointers << ");\n";
        }
    }
    for (std::size_t k = 0; k < code.size(); ++k) {
        const instruction& i = code[k];
        if (!live[k])
            continue;
        if (d == dialect::c && (i.op == op::sine || i.op == op::cosine)) {
            const auto [sine, cosine] = pairs.at(i.first);
            slot[k] = names.temporary + std::to_string(i.op == op::sine ? sine : cosine);
            if (k == std::min(sine, cosine) && !paired.count(i.first))
                lines << indent << "double " << names.temporary << sine << ", " << names.temporary << cosine << ";\n"
                      << indent << "lagrange_sincos(" << slot[static_cast<std::size_t>(i.first)] << ", &"
                      << names.temporary << sine << ", &" << names.temporary << cosine << ");\n";
            continue;
        }
        const std::string a = i.op == op::constant || i.op == op::symbol ? "" : slot[static_cast<std::size_t>(i.first)];
        const std::string b = reads_second_slot(i.op) ? slot[static_cast<std::size_t>(i.second)] : "";
        std::string value;
        switch (i.op) {
        case op::constant: slot[k] = i.value < 0 ? "(" + float_decimal(i.value) + ")" : float_decimal(i.value); continue;
        case op::symbol:
            slot[k] = names.symbols[static_cast<std::size_t>(i.first)];
            used.insert(i.first);
            continue;
        case op::add: value = a + " + " + b; break;
        case op::mul: value = a + " * " + b; break;
        case op::neg: value = "-" + a; break;
        case op::recip: value = "1.0 / " + a; break;
        case op::square_root: value = (d == dialect::python ? "np.sqrt(" : "sqrt(") + a + ")"; break;
        case op::integer_power:
            value = d == dialect::c ? "lagrange_ipow(" + a + ", " + std::to_string(i.second) + ")"
                                    : a + (d == dialect::python ? " ** " : " ^ ") + "(" + std::to_string(i.second) + ")";
            break;
        case op::real_power:
            value = d == dialect::c ? "pow(" + a + ", " + float_decimal(i.value) + ")"
                                    : a + (d == dialect::python ? " ** " : " ^ ") + "(" + float_decimal(i.value) + ")";
            break;
        case op::sine: value = (d == dialect::python ? "np.sin(" : "sin(") + a + ")"; break;
        case op::cosine: value = (d == dialect::python ? "np.cos(" : "cos(") + a + ")"; break;
        case op::exponential: value = (d == dialect::python ? "np.exp(" : "exp(") + a + ")"; break;
        case op::logarithm: value = (d == dialect::python ? "np.log(" : "log(") + a + ")"; break;
        // C99's <math.h>, NumPy's (elementwise along the batch axes) and Octave's (elementwise)
        case op::hyperbolic_sine: value = (d == dialect::python ? "np.sinh(" : "sinh(") + a + ")"; break;
        case op::hyperbolic_cosine: value = (d == dialect::python ? "np.cosh(" : "cosh(") + a + ")"; break;
        case op::hyperbolic_tangent: value = (d == dialect::python ? "np.tanh(" : "tanh(") + a + ")"; break;
        case op::arcsine: value = (d == dialect::python ? "np.arcsin(" : "asin(") + a + ")"; break;
        case op::arccosine: value = (d == dialect::python ? "np.arccos(" : "acos(") + a + ")"; break;
        case op::arctangent: value = (d == dialect::python ? "np.arctan(" : "atan(") + a + ")"; break;
        case op::absolute:
            value = (d == dialect::python ? "np.abs(" : d == dialect::c ? "fabs(" : "abs(") + a + ")";
            break;
        }
        slot[k] = names.temporary + std::to_string(k);
        lines << indent << declare << slot[k] << " = " << value << end;
    }
    std::vector<std::string> outputs;
    for (int s : program.output_slots())
        outputs.push_back(slot[static_cast<std::size_t>(s)]);
    return outputs;
}

std::string provenance(const model& scene, const exported_system& system, const naming& names,
                       const std::string& version, const std::string& comment)
{
    auto list = [](const std::vector<std::string>& names) {
        std::string out;
        for (const std::string& n : names)
            out += (out.empty() ? "" : ", ") + n;
        return out.empty() ? std::string("(none)") : out;
    };
    std::ostringstream out;
    out << comment << "Generated by lagrange " << version << " (`lagrange export`) from the scene "
        << (scene.file.empty() ? "<stdin>" : scene.file) << (scene.title.empty() ? "" : ", \"" + scene.title + "\"")
        << ".\n"
        << comment << "The equations of motion M(t, q, q', u, p) q'' = F(t, q, q', u, p), as x' = f(t, x, u, p).\n"
        << (system.recursion ? comment + "rhs takes q'' from the articulated-body recursion of the scene's tree of "
                                         "points and bodies, in O(n)\n" +
                                   comment + "steps without M; mass_matrix, forcing and jacobian are of M and F.\n"
            : system.constraint_parts ? std::string()
                                      : comment + "rhs solves M q'' = F for q''.\n")
        << comment << "State x (" << 2 * system.coordinates << "): " << list(system.state_names) << ".\n"
        << comment << "Parameters p (" << system.parameter_names.size() << "): " << list(system.parameter_names)
        << ".\n"
        << comment << "Inputs u (" << system.input_names.size() << "): " << list(system.input_names) << ".\n"
        << (system.constraint_parts
                ? comment + "Constraints (" + std::to_string(system.constraint_names.size()) + "): " +
                      list(system.constraint_names) + "; M q'' = F + A^T lambda with A q'' = -c.\n"
                : std::string())
        << comment << "Units: none are assumed; the numbers are in whatever units the scene's values use.\n"
        << comment
        << (system.linear ? "Linearized: `equilibrium` gives the state the small oscillations are about and `linear`\n" +
                                comment + "T and V there, functions of p; A and B are the Jacobian there with u = 0.\n"
                          : "No equilibrium was found to linearize about, so there is no `equilibrium` or `linear`.\n");
    if (!names.renamed.empty()) {
        out << comment << "Renamed (a keyword or an argument name gets `_` appended):";
        for (const auto& [from, to] : names.renamed)
            out << ' ' << from << " -> " << to << (&to == &names.renamed.back().second ? "." : ",");
        out << '\n';
    }
    return out.str();
}

std::string number_list(const std::vector<double>& values, const char* nan)
{
    std::string out;
    for (double v : values)
        out += (out.empty() ? "" : ", ") + (v == v ? float_decimal(v) : std::string(nan));
    return out;
}

} // namespace export_detail

using namespace export_detail;

std::optional<export_target> export_target_named(const std::string& word)
{
    if (word == "c")
        return export_target::c;
    if (word == "python")
        return export_target::python;
    if (word == "octave")
        return export_target::octave;
    return std::nullopt;
}

std::string default_export_name(const std::string& scene_file)
{
    std::string stem = scene_file;
    const std::size_t slash = stem.rfind('/');
    if (slash != std::string::npos)
        stem = stem.substr(slash + 1);
    const std::size_t dot = stem.rfind('.');
    if (dot != std::string::npos && dot > 0)
        stem = stem.substr(0, dot);
    for (char& ch : stem)
        if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '_')
            ch = '_';
    if (stem.empty() || stem == "-" || stem == "_stdin_" || stem == "_stdin")
        return "scene";
    if (std::isdigit(static_cast<unsigned char>(stem[0])))
        stem = "scene_" + stem;
    return valid_export_name(stem) ? stem : stem + "_";
}

bool valid_export_name(const std::string& name)
{
    if (name.empty() || name.size() > 64 || std::isdigit(static_cast<unsigned char>(name[0])))
        return false;
    for (char ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '_')
            return false;
    for (dialect d : {dialect::c, dialect::python, dialect::octave})
        if (keywords(d).count(name))
            return false;
    return true;
}

std::vector<exported_file> export_code(const model& scene, const exported_system& system, export_target target,
                                       const std::string& name, const std::string& version)
{
    switch (target) {
    case export_target::c: return export_c(scene, system, name, version);
    case export_target::python: return export_python(scene, system, name, version);
    case export_target::octave: return export_octave(scene, system, name, version);
    }
    return {};
}

std::vector<exported_file> export_scene(const model& scene, export_target target, const std::string& name,
                                        const std::string& version, const budget_limits& limits)
{
    const analysis result = analyze_for_export(scene, limits);
    const exported_system system =
        export_system(scene, *result.equations, result.linearization ? &*result.linearization : nullptr,
                      result.conserved ? &*result.conserved : nullptr);
    return export_code(scene, system, target, name, version);
}

} // namespace lagrange
