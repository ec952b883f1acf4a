// SPDX-License-Identifier: GPL-2.0-or-later
/** @file export_code.cpp
 *  The exported source code of each target (see export_code.h): the programs of
 *  exported_system written line by line in C, NumPy or Octave, and the few functions around
 *  them (the solve for q̈, the Jacobians). The small Cholesky solve in the C file is written
 *  out here because the C target promises no dependency beyond <math.h>. */
#include "output/export_code.h"

#include "engine/analysis.h"

#include "core/number_text.h"

#include <algorithm>
#include <cctype>
#include <set>
#include <sstream>

namespace lagrange {

namespace {

enum class dialect { c, python, octave };

const std::set<std::string>& keywords(dialect d)
{
    static const std::set<std::string> c = {
        "auto", "break", "case", "char", "const", "continue", "default", "do", "double", "else", "enum", "extern",
        "float", "for", "goto", "if", "inline", "int", "long", "register", "restrict", "return", "short",
        "signed", "sizeof", "static", "struct", "switch", "typedef", "union", "unsigned", "void", "volatile",
        "while", "_Bool", "_Complex", "_Imaginary", "sin", "cos", "sqrt", "exp", "log", "pow", "NAN", "INFINITY",
        "HUGE_VAL", "main"};
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

/// Argument and result names of the generated functions: a scene name equal to one is renamed.
const std::set<std::string> argument_names = {"t", "x", "u", "p", "shape", "dxdt", "M", "F", "D", "dfdx", "dfdu",
                                              "h", "i", "j", "k", "qdd", "column"};

/// The names of one target: each program symbol's (q, q̇, t, p, u), with `_` appended to a
/// name the target reserves (a keyword, or an argument of the generated functions), and the
/// prefix of temporaries, chosen to differ from every name.
struct naming {
    std::vector<std::string> symbols;
    std::vector<std::pair<std::string, std::string>> renamed;
    std::string temporary = "v";
};

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

/// Where exported function arguments hold program symbol k: the array (`x`, `p` or `u`; `t`
/// for time) and the 0-based index in it.
struct argument_place {
    char array;
    int index;
};

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

/// One program as straight-line code: `lines` gets an assignment per instruction that is
/// neither a symbol nor a constant (those are written where they are used); returns the text
/// of each output. `used` gets the index of every symbol the program reads.
std::vector<std::string> write_program(const expression_program& program, dialect d, const naming& names,
                                       const std::string& indent, std::ostringstream& lines, std::set<int>& used)
{
    using op = instruction::code;
    const std::vector<instruction>& code = program.code();
    std::vector<std::string> slot(code.size());
    const char* end = d == dialect::python ? "\n" : ";\n";
    const char* declare = d == dialect::c ? "const double " : "";
    for (std::size_t k = 0; k < code.size(); ++k) {
        const instruction& i = code[k];
        const std::string a = i.op == op::constant || i.op == op::symbol ? "" : slot[static_cast<std::size_t>(i.first)];
        const std::string b = i.op == op::add || i.op == op::mul ? slot[static_cast<std::size_t>(i.second)] : "";
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
        }
        slot[k] = names.temporary + std::to_string(k);
        lines << indent << declare << slot[k] << " = " << value << end;
    }
    std::vector<std::string> outputs;
    for (int s : program.output_slots())
        outputs.push_back(slot[static_cast<std::size_t>(s)]);
    return outputs;
}

/// What the header comment of every file says: where the code came from, the orders, the units
/// and the renamed names.
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
        << comment << "State x (" << 2 * system.coordinates << "): " << list(system.state_names) << ".\n"
        << comment << "Parameters p (" << system.parameter_names.size() << "): " << list(system.parameter_names)
        << ".\n"
        << comment << "Inputs u (" << system.input_names.size() << "): " << list(system.input_names) << ".\n"
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

// ---- C ---------------------------------------------------------------------------------

/// The body of a C function that evaluates `program` into out[]: the symbols' aliases, the
/// program, the stores; arguments it does not read are cast to void.
std::string c_body(const expression_program& program, const naming& names, const exported_system& system,
                   const std::string& out)
{
    std::ostringstream lines;
    std::set<int> used;
    std::vector<std::string> outputs = write_program(program, dialect::c, names, "    ", lines, used);
    std::ostringstream body;
    std::set<char> read;
    for (int k : used) {
        const argument_place at = place_of(k, system);
        read.insert(at.array);
        if (at.array != 't')
            body << "    const double " << names.symbols[static_cast<std::size_t>(k)] << " = " << at.array << "["
                 << at.index << "];\n";
    }
    for (char array : {'t', 'x', 'p', 'u'})
        if (!read.count(array))
            body << "    (void)" << array << ";\n";
    body << lines.str();
    for (std::size_t k = 0; k < outputs.size(); ++k)
        body << "    " << out << "[" << k << "] = " << outputs[k] << ";\n";
    return body.str();
}

std::vector<exported_file> export_c(const model& scene, const exported_system& system, const std::string& name,
                                    const std::string& version)
{
    const naming names = name_symbols(system, dialect::c);
    const std::size_t n = system.coordinates, inputs = system.input_names.size();
    const std::string args = "(double t, const double *x, const double *u, const double *p";
    std::ostringstream h;
    h << "/* " << name << ".h: the equations of motion as C99 functions.\n"
      << provenance(scene, system, names, version, " * ")
      << " * Every function is re-entrant and allocates nothing; u may be NULL when " << name << "_NU is 0.\n"
      << " * Arrays are row-major. Build: cc -std=c99 -c " << name << ".c (link with -lm). */\n"
      << "#ifndef " << name << "_H_INCLUDED\n#define " << name << "_H_INCLUDED\n\n"
      << "#define " << name << "_NQ " << n << " /* coordinates */\n"
      << "#define " << name << "_NX " << 2 * n << " /* states: the coordinates, then their velocities */\n"
      << "#define " << name << "_NU " << inputs << " /* inputs */\n"
      << "#define " << name << "_NP " << system.parameter_names.size() << " /* parameters */\n\n"
      << "/* The scene's `values` (the first line), NaN where it gives none. */\n"
      << "extern const double " << name << "_default_p[" << name << "_NP > 0 ? " << name << "_NP : 1];\n"
      << "extern const char *const " << name << "_state_names[" << name << "_NX];\n"
      << "extern const char *const " << name << "_parameter_names[" << name << "_NP > 0 ? " << name << "_NP : 1];\n\n"
      << "/* dxdt = f(t, x, u, p). Returns 0, or 1 where the mass matrix is not positive definite. */\n"
      << "int " << name << "_rhs" << args << ", double *dxdt);\n"
      << "/* dfdx = df/dx (NX x NX) and dfdu = df/du (NX x NU; may be NULL). Returns as " << name << "_rhs. */\n"
      << "int " << name << "_jacobian" << args << ", double *dfdx, double *dfdu);\n"
      << "/* The mass matrix M (NQ x NQ) and the forcing F (NQ) of M q'' = F. */\n"
      << "void " << name << "_mass_matrix" << args << ", double *M);\n"
      << "void " << name << "_forcing" << args << ", double *F);\n"
      << "/* The energy function h = sum q' dL/dq' - L (conserved when nothing drives or damps the motion). */\n"
      << "double " << name << "_energy" << args << ");\n";
    if (system.linear)
        h << "/* At the equilibrium the small oscillations are about, functions of p only: the state there\n"
          << "   (NX), and T and V (NQ x NQ each) of T q'' + V q = 0. The linearized x' = A x + B u there\n"
          << "   has A = df/dx and B = df/du of " << name << "_jacobian at that state with u = 0. */\n"
          << "void " << name << "_equilibrium(const double *p, double *x);\n"
          << "void " << name << "_linear(const double *p, double *T, double *V);\n";
    h << "\n#endif\n";

    std::ostringstream c;
    const std::string nq = name + "_NQ";
    c << "/* " << name << ".c: see " << name << ".h.\n" << provenance(scene, system, names, version, " * ") << " */\n"
      << "#include \"" << name << ".h\"\n\n#include <math.h>\n#include <stddef.h>\n\n"
      << "const double " << name << "_default_p[" << name << "_NP > 0 ? " << name << "_NP : 1] = {"
      << (system.defaults.empty() ? "0.0" : number_list(system.defaults, "NAN")) << "};\n"
      << "const char *const " << name << "_state_names[" << name << "_NX] = {";
    for (std::size_t k = 0; k < system.state_names.size(); ++k)
        c << (k ? ", " : "") << '"' << system.state_names[k] << '"';
    c << "};\nconst char *const " << name << "_parameter_names[" << name << "_NP > 0 ? " << name << "_NP : 1] = {";
    for (std::size_t k = 0; k < system.parameter_names.size(); ++k)
        c << (k ? ", " : "") << '"' << system.parameter_names[k] << '"';
    c << (system.parameter_names.empty() ? "\"\"" : "") << "};\n\n";
    bool powers = false;
    for (const expression_program* program : {&system.mass, &system.forcing, &system.mass_and_forcing,
                                              &system.derivatives, &system.energy})
        for (const instruction& i : program->code())
            powers = powers || i.op == instruction::code::integer_power;
    if (system.linear)
        for (const instruction& i : system.linear->code())
            powers = powers || i.op == instruction::code::integer_power;
    if (powers) // only when used: an unused static function is a warning
        c << "static double lagrange_ipow(double a, int n)\n{\n    double r = 1.0;\n    int k = n < 0 ? -n : n;\n"
          << "    for (; k > 0; --k)\n        r *= a;\n    return n < 0 ? 1.0 / r : r;\n}\n\n";
    // LDLᵀ without square roots, as the engine's own solve (numeric/mass_matrix.h).
    c << "/* The LDL^T factor of a (row-major, in place: L below the diagonal, D on it): 1 if a is not\n"
      << "   positive definite. */\n"
      << "static int lagrange_factor(double *a)\n{\n    int i, j, k;\n    for (j = 0; j < " << nq << "; ++j) {\n"
      << "        double d = a[j * " << nq << " + j];\n        for (k = 0; k < j; ++k)\n"
      << "            d -= a[j * " << nq << " + k] * a[j * " << nq << " + k] * a[k * " << nq << " + k];\n"
      << "        if (!(d > 0.0))\n            return 1;\n        a[j * " << nq << " + j] = d;\n"
      << "        for (i = j + 1; i < " << nq << "; ++i) {\n            double s = a[i * " << nq << " + j];\n"
      << "            for (k = 0; k < j; ++k)\n"
      << "                s -= a[i * " << nq << " + k] * a[j * " << nq << " + k] * a[k * " << nq << " + k];\n"
      << "            a[i * " << nq << " + j] = s / d;\n        }\n    }\n    return 0;\n}\n\n"
      << "/* Solves L D L^T y = b in place, b of NQ entries. */\n"
      << "static void lagrange_solve(const double *l, double *b)\n{\n    int i, k;\n"
      << "    for (i = 0; i < " << nq << "; ++i)\n        for (k = 0; k < i; ++k)\n"
      << "            b[i] -= l[i * " << nq << " + k] * b[k];\n"
      << "    for (i = 0; i < " << nq << "; ++i)\n        b[i] /= l[i * " << nq << " + i];\n"
      << "    for (i = " << nq << " - 1; i >= 0; --i)\n        for (k = i + 1; k < " << nq << "; ++k)\n"
      << "            b[i] -= l[k * " << nq << " + i] * b[k];\n}\n\n";
    c << "void " << name << "_mass_matrix" << args << ", double *M)\n{\n"
      << c_body(system.mass, names, system, "M") << "}\n\n";
    c << "void " << name << "_forcing" << args << ", double *F)\n{\n"
      << c_body(system.forcing, names, system, "F") << "}\n\n";
    c << "static void lagrange_mass_and_forcing" << args << ", double *out)\n{\n"
      << c_body(system.mass_and_forcing, names, system, "out") << "}\n\n";
    c << "static void lagrange_derivatives" << args << ", double *out)\n{\n"
      << c_body(system.derivatives, names, system, "out") << "}\n\n";
    c << "double " << name << "_energy" << args << ")\n{\n    double h[1];\n"
      << c_body(system.energy, names, system, "h") << "    return h[0];\n}\n\n";
    c << "int " << name << "_rhs" << args << ", double *dxdt)\n{\n"
      << "    double m[" << nq << " * " << nq << " + " << nq << "];\n    int i;\n"
      << "    lagrange_mass_and_forcing(t, x, u, p, m);\n";
    if (n == 2) // Cramer's rule, as the engine solves two coordinates
        c << "    {\n        const double det = m[0] * m[3] - m[1] * m[1];\n"
          << "        if (!(m[0] > 0.0 && det > 0.0))\n            return 1;\n"
          << "        dxdt[2] = (m[3] * m[4] - m[1] * m[5]) / det;\n"
          << "        dxdt[3] = (m[0] * m[5] - m[1] * m[4]) / det;\n    }\n"
          << "    dxdt[0] = x[2];\n    dxdt[1] = x[3];\n    (void)i;\n    return 0;\n}\n\n";
    else
        c << "    if (lagrange_factor(m))\n        return 1;\n"
          << "    lagrange_solve(m, m + " << nq << " * " << nq << ");\n"
          << "    for (i = 0; i < " << nq << "; ++i) {\n        dxdt[i] = x[" << nq << " + i];\n"
          << "        dxdt[" << nq << " + i] = m[" << nq << " * " << nq << " + i];\n    }\n    return 0;\n}\n\n";
    const std::string nx = name + "_NX", nu = name + "_NU";
    c << "int " << name << "_jacobian" << args << ", double *dfdx, double *dfdu)\n{\n"
      << "    /* d(q'')/dy = M^-1 (dF/dy - (dM/dy) q''), y each coordinate, velocity and input. */\n"
      << "    double m[" << nq << " * " << nq << " + " << nq << "], column[" << nq << "];\n"
      << "    double d[" << nq << " * " << nq << " * " << nq << " + 2 * " << nq << " * " << nq << " + " << nq << " * "
      << nu << " + 1];\n"
      << "    const double *qdd = m + " << nq << " * " << nq << ";\n    int i, j, k;\n"
      << "    lagrange_mass_and_forcing(t, x, u, p, m);\n    lagrange_derivatives(t, x, u, p, d);\n"
      << "    if (lagrange_factor(m))\n        return 1;\n    lagrange_solve(m, m + " << nq << " * " << nq << ");\n"
      << "    for (i = 0; i < " << nx << " * " << nx << "; ++i)\n        dfdx[i] = 0.0;\n"
      << "    for (i = 0; i < " << nq << "; ++i)\n        dfdx[i * " << nx << " + " << nq << " + i] = 1.0;\n"
      << "    for (k = 0; k < 2 * " << nq << "; ++k) {\n        for (i = 0; i < " << nq << "; ++i) {\n"
      << "            column[i] = d[" << nq << " * " << nq << " * " << nq << " + (k < " << nq << " ? 0 : " << nq
      << " * " << nq << ") + i * " << nq << " + k % " << nq << "];\n"
      << "            if (k < " << nq << ")\n                for (j = 0; j < " << nq << "; ++j)\n"
      << "                    column[i] -= d[(k * " << nq << " + i) * " << nq << " + j] * qdd[j];\n        }\n"
      << "        lagrange_solve(m, column);\n        for (i = 0; i < " << nq << "; ++i)\n"
      << "            dfdx[(" << nq << " + i) * " << nx << " + k] = column[i];\n    }\n";
    if (inputs == 0) {
        c << "    (void)dfdu;\n";
    } else {
        c << "    if (dfdu) {\n        for (k = 0; k < " << nu << "; ++k) {\n"
          << "            for (i = 0; i < " << nq << "; ++i) {\n"
          << "                column[i] = d[" << nq << " * " << nq << " * " << nq << " + 2 * " << nq << " * " << nq
          << " + i * " << nu << " + k];\n                dfdu[i * " << nu << " + k] = 0.0;\n            }\n"
          << "            lagrange_solve(m, column);\n            for (i = 0; i < " << nq << "; ++i)\n"
          << "                dfdu[(" << nq << " + i) * " << nu << " + k] = column[i];\n        }\n    }\n";
    }
    c << "    return 0;\n}\n";
    if (system.linear) {
        const std::string parts = "2 * " + nq + " + 2 * " + nq + " * " + nq;
        c << "\nstatic void lagrange_linear" << args << ", double *out)\n{\n"
          << c_body(*system.linear, names, system, "out") << "}\n\n"
          << "void " << name << "_equilibrium(const double *p, double *x)\n{\n    double out[" << parts
          << "];\n    int i;\n    lagrange_linear(0.0, NULL, NULL, p, out);\n"
          << "    for (i = 0; i < " << nx << "; ++i)\n        x[i] = out[i];\n}\n\n"
          << "void " << name << "_linear(const double *p, double *T, double *V)\n{\n    double out[" << parts
          << "];\n    int i;\n    lagrange_linear(0.0, NULL, NULL, p, out);\n"
          << "    for (i = 0; i < " << nq << " * " << nq << "; ++i) {\n        T[i] = out[" << nx << " + i];\n"
          << "        V[i] = out[" << nx << " + " << nq << " * " << nq << " + i];\n    }\n}\n";
    }
    return {{name + ".h", h.str()}, {name + ".c", c.str()}};
}

// ---- Python ----------------------------------------------------------------------------

std::string python_function(const std::string& function, const std::string& doc, const expression_program& program,
                            const naming& names, const exported_system& system, const std::string& result)
{
    std::ostringstream lines;
    std::set<int> used;
    std::vector<std::string> outputs = write_program(program, dialect::python, names, "    ", lines, used);
    std::ostringstream out;
    out << "def " << function << "(t, x, p=None, u=None):\n    \"\"\"" << doc << "\"\"\"\n"
        << "    t, x, p, u, shape = _arguments(t, x, p, u)\n";
    for (int k : used) {
        const argument_place at = place_of(k, system);
        if (at.array != 't')
            out << "    " << names.symbols[static_cast<std::size_t>(k)] << " = " << at.array << "[..., " << at.index
                << "]\n";
    }
    out << lines.str() << "    return " << result << "(shape, ";
    for (std::size_t k = 0; k < outputs.size(); ++k)
        out << (k ? ", " : "") << outputs[k];
    out << ")\n\n\n";
    return out.str();
}

std::vector<exported_file> export_python(const model& scene, const exported_system& system, const std::string& name,
                                         const std::string& version)
{
    const naming names = name_symbols(system, dialect::python);
    const std::size_t n = system.coordinates;
    auto quoted_list = [](const std::vector<std::string>& words) {
        std::string out;
        for (const std::string& w : words)
            out += (out.empty() ? "\"" : ", \"") + w + "\"";
        return "[" + out + "]";
    };
    std::ostringstream py;
    py << "\"\"\"" << name << ": the equations of motion as functions on NumPy arrays.\n\n"
       << provenance(scene, system, names, version, "")
       << "Every function takes (t, x, p=DEFAULTS, u=None) and works on a leading batch axis: x of shape\n"
       << "(..., NX), p of shape (..., NP), u of shape (..., NU). rhs works with scipy.integrate.solve_ivp:\n"
       << "solve_ivp(rhs, (0, 10), x0, args=(DEFAULTS,)).\n\"\"\"\nimport numpy as np\n\n"
       << "NQ = " << n << "\nNX = " << 2 * n << "\nNU = " << system.input_names.size() << "\nNP = "
       << system.parameter_names.size() << "\n"
       << "STATE = " << quoted_list(system.state_names) << "\n"
       << "PARAMETERS = " << quoted_list(system.parameter_names) << "\n"
       << "INPUTS = " << quoted_list(system.input_names) << "\n"
       << "DEFAULTS = np.array([" << number_list(system.defaults, "np.nan") << "], dtype=float)\n\n\n"
       << "def _arguments(t, x, p, u):\n"
       << "    x = np.asarray(x, dtype=float)\n"
       << "    p = DEFAULTS if p is None else np.asarray(p, dtype=float)\n"
       << "    u = np.zeros(NU) if u is None else np.asarray(u, dtype=float)\n"
       << "    if x.shape[-1:] != (NX,) or p.shape[-1:] != (NP,) or u.shape[-1:] != (NU,):\n"
       << "        raise ValueError(f\"x, p and u end in {NX}, {NP} and {NU} entries, not {x.shape}, {p.shape}, "
          "{u.shape}\")\n"
       << "    t = np.asarray(t, dtype=float)\n"
       << "    return t, x, p, u, np.broadcast_shapes(t.shape, x.shape[:-1], p.shape[:-1], u.shape[:-1])\n\n\n"
       << "def _vector(shape, *values):\n"
       << "    return np.stack([np.broadcast_to(np.asarray(v, dtype=float), shape) for v in values], axis=-1)\n\n\n"
       << "def _square(shape, *values):\n    return _vector(shape, *values).reshape(shape + (NQ, NQ))\n\n\n"
       << "def _scalar(shape, value):\n    return np.broadcast_to(np.asarray(value, dtype=float), shape).copy()\n\n\n";
    py << python_function("mass_matrix", "The mass matrix M of M q'' = F, shape (..., NQ, NQ).", system.mass, names,
                          system, "_square");
    py << python_function("forcing", "The forcing F of M q'' = F, shape (..., NQ).", system.forcing, names, system,
                          "_vector");
    py << python_function("_mass_and_forcing", "M (flattened) then F, their common parts computed once.",
                          system.mass_and_forcing, names, system, "_vector");
    py << python_function("_derivatives", "dM/dq_k (k slowest), dF/dq, dF/dq', dF/du, flattened.",
                          system.derivatives, names, system, "_vector");
    py << python_function("energy", "The energy function h = sum q' dL/dq' - L.", system.energy, names, system,
                          "_scalar");
    py << "def rhs(t, x, p=None, u=None):\n"
       << "    \"\"\"dx/dt = f(t, x, u, p), shape (..., NX); numpy.linalg.LinAlgError where M is singular.\"\"\"\n"
       << "    t, x, p, u, shape = _arguments(t, x, p, u)\n"
       << "    both = _mass_and_forcing(t, x, p, u)\n"
       << "    mass, force = both[..., :NQ * NQ].reshape(shape + (NQ, NQ)), both[..., NQ * NQ:]\n"
       << "    qdd = np.linalg.solve(mass, force[..., None])[..., 0]\n"
       << "    return np.concatenate([np.broadcast_to(x[..., NQ:], shape + (NQ,)), qdd], axis=-1)\n\n\n"
       << "def jacobian(t, x, p=None, u=None):\n"
       << "    \"\"\"(df/dx of shape (..., NX, NX), df/du of shape (..., NX, NU)).\"\"\"\n"
       << "    t, x, p, u, shape = _arguments(t, x, p, u)\n"
       << "    both = _mass_and_forcing(t, x, p, u)\n"
       << "    mass, force = both[..., :NQ * NQ].reshape(shape + (NQ, NQ)), both[..., NQ * NQ:]\n"
       << "    d = _derivatives(t, x, p, u)\n"
       << "    dmass = d[..., :NQ ** 3].reshape(shape + (NQ, NQ, NQ))\n"
       << "    dfq = d[..., NQ ** 3:NQ ** 3 + NQ * NQ].reshape(shape + (NQ, NQ))\n"
       << "    dfv = d[..., NQ ** 3 + NQ * NQ:NQ ** 3 + 2 * NQ * NQ].reshape(shape + (NQ, NQ))\n"
       << "    dfu = d[..., NQ ** 3 + 2 * NQ * NQ:].reshape(shape + (NQ, NU))\n"
       << "    qdd = np.linalg.solve(mass, force[..., None])[..., 0]\n"
       << "    # d(q'')/dy = M^-1 (dF/dy - (dM/dy) q''): dM/dq_k q'' as column k\n"
       << "    dq = np.linalg.solve(mass, dfq - np.einsum(\"...kij,...j->...ik\", dmass, qdd))\n"
       << "    dv = np.linalg.solve(mass, dfv)\n"
       << "    dfdx = np.zeros(shape + (NX, NX))\n"
       << "    dfdx[..., :NQ, NQ:] = np.eye(NQ)\n    dfdx[..., NQ:, :NQ] = dq\n    dfdx[..., NQ:, NQ:] = dv\n"
       << "    dfdu = np.zeros(shape + (NX, NU))\n"
       << "    if NU:\n        dfdu[..., NQ:, :] = np.linalg.solve(mass, dfu)\n"
       << "    return dfdx, dfdu\n";
    if (system.linear)
        py << "\n\n"
           << python_function("_linear", "The equilibrium's state, then T and V, flattened.", *system.linear, names,
                              system, "_vector")
           << "def equilibrium(p=None):\n"
           << "    \"\"\"The state the small oscillations are about, shape (..., NX).\"\"\"\n"
           << "    return _linear(0.0, np.zeros(NX), p)[..., :NX]\n\n\n"
           << "def linear(p=None):\n"
           << "    \"\"\"(T, V) of T q'' + V q = 0 at the equilibrium, each of shape (..., NQ, NQ).\"\"\"\n"
           << "    both = _linear(0.0, np.zeros(NX), p)\n    shape = both.shape[:-1]\n"
           << "    return (both[..., NX:NX + NQ * NQ].reshape(shape + (NQ, NQ)),\n"
           << "            both[..., NX + NQ * NQ:].reshape(shape + (NQ, NQ)))\n";
    return {{name + ".py", py.str()}};
}

// ---- Octave / MATLAB ---------------------------------------------------------------------

/// The arguments an Octave function may be called without: p from NAME_defaults(), u zero.
std::string octave_defaults(const std::string& name, std::size_t inputs)
{
    return "  if nargin < 3 || isempty(p)\n    p = " + name + "_defaults();\n  end\n  if nargin < 4\n    u = zeros(" +
           std::to_string(inputs) + ", 1);\n  end\n";
}

std::string octave_function(const std::string& name, const std::string& function, const std::string& doc,
                            const expression_program& program, const naming& names, const exported_system& system,
                            const std::string& result, std::size_t rows, std::size_t columns,
                            const std::string& header)
{
    std::ostringstream lines;
    std::set<int> used;
    std::vector<std::string> outputs = write_program(program, dialect::octave, names, "  ", lines, used);
    std::ostringstream out;
    out << "function " << result << " = " << name << "_" << function << "(t, x, p, u)\n"
        << "  % " << doc << "\n" << header
        << octave_defaults(name, system.input_names.size());
    for (int k : used) {
        const argument_place at = place_of(k, system);
        if (at.array != 't')
            out << "  " << names.symbols[static_cast<std::size_t>(k)] << " = " << at.array << "(" << at.index + 1
                << ");\n";
    }
    out << lines.str() << "  " << result << " = [";
    for (std::size_t r = 0; r < rows; ++r) {
        for (std::size_t c = 0; c < columns; ++c)
            out << (c ? ", " : "") << outputs[r * columns + c];
        out << (r + 1 < rows ? "; " : "");
    }
    out << "];\nend\n";
    return out.str();
}

std::vector<exported_file> export_octave(const model& scene, const exported_system& system, const std::string& name,
                                         const std::string& version)
{
    const naming names = name_symbols(system, dialect::octave);
    const std::size_t n = system.coordinates, inputs = system.input_names.size();
    const std::string header = provenance(scene, system, names, version, "  % ");
    const std::size_t derivatives = system.derivatives.output_count();
    std::vector<exported_file> files;
    files.push_back({name + "_mass_matrix.m",
                     octave_function(name, "mass_matrix", "The mass matrix M of M q'' = F (NQ x NQ).", system.mass,
                                     names, system, "M", n, n, header)});
    files.push_back({name + "_forcing.m", octave_function(name, "forcing", "The forcing F of M q'' = F (a column).",
                                                          system.forcing, names, system, "F", n, 1, header)});
    files.push_back({name + "_energy.m",
                     octave_function(name, "energy", "The energy function h = sum q' dL/dq' - L.", system.energy,
                                     names, system, "h", 1, 1, header)});
    files.push_back({name + "_derivatives.m",
                     octave_function(name, "derivatives", "dM/dq_k (k slowest), dF/dq, dF/dq', dF/du, as a column.",
                                     system.derivatives, names, system, "d", derivatives, 1, header)});
    std::ostringstream defaults;
    defaults << "function p = " << name << "_defaults()\n  % The scene's `values` (the first line), NaN where it "
             << "gives none, in the order of the parameters.\n" << header << "  p = ["
             << number_list(system.defaults, "NaN") << "]';\n  if isempty(p)\n    p = zeros(0, 1);\n  end\nend\n";
    files.push_back({name + "_defaults.m", defaults.str()});
    std::ostringstream rhs;
    rhs << "function dxdt = " << name << "_rhs(t, x, p, u)\n"
        << "  % dx/dt = f(t, x, u, p) as a column; for ode45 and ode15s: ode45(@(t, x) " << name
        << "_rhs(t, x, p), tspan, x0).\n" << header
        << octave_defaults(name, inputs)
        << "  M = " << name << "_mass_matrix(t, x, p, u);\n  F = " << name << "_forcing(t, x, p, u);\n"
        << "  dxdt = [x(" << n + 1 << ":" << 2 * n << "); M \\ F];\nend\n";
    files.push_back({name + "_rhs.m", rhs.str()});
    std::ostringstream jac;
    jac << "function [dfdx, dfdu] = " << name << "_jacobian(t, x, p, u)\n"
        << "  % df/dx (NX x NX) and df/du (NX x NU): d(q'')/dy = M \\ (dF/dy - (dM/dy) q'').\n" << header
        << octave_defaults(name, inputs)
        << "  n = " << n << ";\n  m = " << inputs << ";\n"
        << "  M = " << name << "_mass_matrix(t, x, p, u);\n  F = " << name << "_forcing(t, x, p, u);\n"
        << "  d = " << name << "_derivatives(t, x, p, u);\n  qdd = M \\ F;\n"
        << "  dq = reshape(d(n^3 + 1:n^3 + n^2), n, n)';\n"
        << "  for k = 1:n\n    dq(:, k) = dq(:, k) - reshape(d((k - 1) * n^2 + 1:k * n^2), n, n)' * qdd;\n  end\n"
        << "  dv = reshape(d(n^3 + n^2 + 1:n^3 + 2 * n^2), n, n)';\n"
        << "  dfdx = [zeros(n), eye(n); M \\ dq, M \\ dv];\n"
        << "  dfdu = [zeros(n, m); M \\ reshape(d(n^3 + 2 * n^2 + 1:end), m, n)'];\nend\n";
    files.push_back({name + "_jacobian.m", jac.str()});
    if (system.linear) {
        files.push_back({name + "_linear_parts.m",
                         octave_function(name, "linear_parts", "The equilibrium's state, then T and V, as a column.",
                                         *system.linear, names, system, "d", system.linear->output_count(), 1,
                                         header)});
        const std::string call = "  if nargin < 1 || isempty(p)\n    p = " + name + "_defaults();\n  end\n  d = " +
                                 name + "_linear_parts(0, zeros(" + std::to_string(2 * n) + ", 1), p);\n";
        files.push_back({name + "_equilibrium.m",
                         "function x = " + name + "_equilibrium(p)\n  % The state the small oscillations are about "
                         "(a column).\n" + header + call + "  x = d(1:" + std::to_string(2 * n) + ");\nend\n"});
        files.push_back({name + "_linear.m",
                         "function [T, V] = " + name + "_linear(p)\n  % T and V of T q'' + V q = 0 at the "
                         "equilibrium.\n" + header + call + "  n = " + std::to_string(n) + ";\n"
                         "  T = reshape(d(2 * n + 1:2 * n + n^2), n, n)';\n"
                         "  V = reshape(d(2 * n + n^2 + 1:2 * n + 2 * n^2), n, n)';\nend\n"});
    }
    return files;
}

} // namespace

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
        export_system(scene, *result.equations, result.linearization ? &*result.linearization : nullptr);
    return export_code(scene, system, target, name, version);
}

} // namespace lagrange
