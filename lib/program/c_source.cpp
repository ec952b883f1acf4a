// SPDX-License-Identifier: GPL-2.0-or-later
/** @file c_source.cpp
 *  An expression program as C source (expression_program::c_source), for native_code:
 *  straight-line code with exact constants, its sines and cosines optionally four at a
 *  time through SLEEF. */
#include "program/expression_program.h"

#include "core/number_text.h"

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace lagrange {

namespace {

bool sine_or_cosine(const instruction& i)
{
    return i.op == instruction::code::sine || i.op == instruction::code::cosine;
}

/// SLEEF's AVX2 sincos of 3.5-ulp accuracy, not its 1-ulp one. An integrator's evaluations
/// form a chain (each stage's arguments come from the last stage's result), so what counts is
/// how soon the sines are back, and the 3.5-ulp function returns them sooner. An error of a
/// few units in the last place of a sine is of the size of the roundings an evaluation makes
/// anyway.
constexpr const char* sleef_sincos_function = "Sleef_sincosd4_u35avx2";

} // namespace

bool expression_program::trigonometric() const { return std::any_of(code_.begin(), code_.end(), sine_or_cosine); }

const char* expression_program::sleef_declarations()
{
    static const std::string declarations = std::string("typedef double lagrange_v4 __attribute__((vector_size(32)));\n"
                                                        "typedef struct { lagrange_v4 x, y; } lagrange_sincos4;\n"
                                                        "lagrange_sincos4 ") +
                                            sleef_sincos_function + "(lagrange_v4);\n";
    return declarations.c_str();
}

namespace {

/// One statement of the C function: an instruction's slot, or (SLEEF) one sincos call of up to
/// four arguments with the sines and cosines taken from it.
struct statement {
    std::size_t slot = 0;              ///< the instruction (when not a call)
    bool call = false;
    int depth = 0;                     ///< a call's nesting depth and number within it
    std::size_t number = 0;
    std::vector<int> arguments;        ///< a call's argument slots
    std::vector<std::size_t> lanes;    ///< the sine or cosine slots a call defines
    std::size_t lines() const { return call ? 1 + lanes.size() : 1; }
};

} // namespace

std::string expression_program::c_source(const std::string& name, bool sleef_sincos, std::size_t part_statements) const
{
    return c_units(name, sleef_sincos, part_statements, 1).front();
}

std::vector<std::string> expression_program::c_units(const std::string& name, bool sleef_sincos,
                                                     std::size_t part_statements, std::size_t units) const
{
    using op = instruction::code;
    // The statements in order. With SLEEF, depth by depth: the depth of a slot is the most
    // sines and cosines nested on any path to it, so the slots of depth D − 1 are all known
    // before any sine or cosine of depth D is needed; the sines and cosines of depth D come
    // from one sincos per distinct argument, four per call.
    std::vector<statement> order;
    // lane_of[k]: for a sine or cosine slot, its call's statement and lane.
    std::vector<std::pair<std::size_t, std::size_t>> lane_of(code_.size());
    if (!sleef_sincos) {
        for (std::size_t k = 0; k < code_.size(); ++k)
            order.push_back({k});
    } else {
        std::vector<int> depth(code_.size(), 0);
        int deepest = 0;
        for (std::size_t k = 0; k < code_.size(); ++k) {
            const instruction& i = code_[k];
            int d = 0;
            if (reads_first_slot(i.op))
                d = depth[static_cast<std::size_t>(i.first)];
            if (reads_second_slot(i.op))
                d = std::max(d, depth[static_cast<std::size_t>(i.second)]);
            depth[k] = d + (sine_or_cosine(i) ? 1 : 0);
            deepest = std::max(deepest, depth[k]);
        }
        for (int d = 0; d <= deepest; ++d) {
            std::vector<int> arguments;
            for (std::size_t k = 0; k < code_.size(); ++k)
                if (depth[k] == d && sine_or_cosine(code_[k]) &&
                    std::find(arguments.begin(), arguments.end(), code_[k].first) == arguments.end())
                    arguments.push_back(code_[k].first);
            const std::size_t first_call = order.size();
            for (std::size_t call = 0; 4 * call < arguments.size(); ++call) {
                statement s;
                s.call = true;
                s.depth = d;
                s.number = call;
                s.arguments.assign(arguments.begin() + static_cast<std::ptrdiff_t>(4 * call),
                                   arguments.begin() + static_cast<std::ptrdiff_t>(std::min(arguments.size(), 4 * call + 4)));
                order.push_back(s);
            }
            for (std::size_t k = 0; k < code_.size(); ++k) {
                if (depth[k] != d)
                    continue;
                if (!sine_or_cosine(code_[k])) {
                    order.push_back({k});
                    continue;
                }
                const std::size_t j = static_cast<std::size_t>(
                    std::find(arguments.begin(), arguments.end(), code_[k].first) - arguments.begin());
                order[first_call + j / 4].lanes.push_back(k);
                lane_of[k] = {first_call + j / 4, j % 4};
            }
        }
    }

    // Parts: a program of more than 3 × part_statements statements goes into functions of at
    // most part_statements (GCC's optimizer takes time superlinear in the size of a function),
    // as many as a multiple of `units`, of even size, so that the units take about as long to
    // compile. Smaller programs stay one function, which evaluates faster than its parts
    // (docs/benchmarks.md, "Large systems").
    // A slot one part makes and a later part reads passes through the array r, except
    // constants, symbols and their negations, which each part makes again.
    std::size_t total = 0;
    for (const statement& s : order)
        total += s.lines();
    units = std::max<std::size_t>(units, 1);
    const bool split = part_statements > 0 && total > 3 * part_statements;
    std::vector<std::size_t> part_of_statement(order.size(), 0);
    std::size_t parts = 1;
    if (split) {
        parts = (total + part_statements - 1) / part_statements;
        parts = (parts + units - 1) / units * units;
        const std::size_t size = (total + parts - 1) / parts;
        std::size_t part = 0, in_part = 0;
        for (std::size_t k = 0; k < order.size(); ++k) {
            if (in_part >= size && part + 1 < parts) {
                ++part;
                in_part = 0;
            }
            part_of_statement[k] = part;
            in_part += order[k].lines();
        }
        parts = part + 1;
    }
    std::vector<std::size_t> part_of(code_.size(), 0);
    std::vector<bool> cheap(code_.size(), false);
    for (std::size_t k = 0; k < order.size(); ++k) {
        if (order[k].call)
            for (std::size_t slot : order[k].lanes)
                part_of[slot] = part_of_statement[k];
        else
            part_of[order[k].slot] = part_of_statement[k];
    }
    for (std::size_t k = 0; k < code_.size(); ++k) {
        const instruction& i = code_[k];
        cheap[k] = i.op == op::constant || i.op == op::symbol ||
                   (i.op == op::neg && cheap[static_cast<std::size_t>(i.first)]);
    }
    // shared[k]: slot k's place in r, or −1.
    std::vector<long> shared(code_.size(), -1);
    std::size_t shared_count = 0;
    auto share = [&](int slot, std::size_t part) {
        const std::size_t k = static_cast<std::size_t>(slot);
        if (part_of[k] != part && !cheap[k] && shared[k] < 0)
            shared[k] = static_cast<long>(shared_count++);
    };
    auto operands = [&](std::size_t k, auto&& visit) {
        const instruction& i = code_[k];
        if (reads_first_slot(i.op))
            visit(i.first);
        if (reads_second_slot(i.op))
            visit(i.second);
    };
    if (split)
        for (std::size_t k = 0; k < order.size(); ++k) {
            const std::size_t part = part_of_statement[k];
            if (order[k].call)
                for (int a : order[k].arguments)
                    share(a, part);
            else
                operands(order[k].slot, [&](int a) { share(a, part); });
        }

    std::ostringstream c;
    auto name_of = [&](int slot, std::size_t part) {
        const std::size_t k = static_cast<std::size_t>(slot);
        return split && part_of[k] != part && !cheap[k] ? "r[" + std::to_string(shared[k]) + "]"
                                                         : "v" + std::to_string(slot);
    };
    auto emit = [&](std::size_t k, std::size_t part) {
        const instruction& i = code_[k];
        c << "    const double v" << k << " = ";
        const std::string a = name_of(i.first, part), b = reads_second_slot(i.op) ? name_of(i.second, part) : "";
        switch (i.op) {
        case op::constant:
            c << hexadecimal(i.value);
            break;
        case op::symbol: c << "s[" << i.first << "]"; break;
        case op::add: c << a << " + " << b; break;
        case op::mul: c << a << " * " << b; break;
        case op::neg: c << "-" << a; break;
        case op::recip: c << "1.0 / " << a; break;
        case op::square_root: c << "sqrt(" << a << ")"; break;
        case op::integer_power: c << "__builtin_powi(" << a << ", " << i.second << ")"; break;
        case op::real_power:
            c << "pow(" << a << ", " << hexadecimal(i.value) << ")";
            break;
        case op::sine: c << "sin(" << a << ")"; break;
        case op::cosine: c << "cos(" << a << ")"; break;
        case op::exponential: c << "exp(" << a << ")"; break;
        case op::logarithm: c << "log(" << a << ")"; break;
        // libm's (<math.h>, C99); SLEEF stays for sines and cosines only
        case op::hyperbolic_sine: c << "sinh(" << a << ")"; break;
        case op::hyperbolic_cosine: c << "cosh(" << a << ")"; break;
        case op::hyperbolic_tangent: c << "tanh(" << a << ")"; break;
        case op::arcsine: c << "asin(" << a << ")"; break;
        case op::arccosine: c << "acos(" << a << ")"; break;
        case op::arctangent: c << "atan(" << a << ")"; break;
        case op::absolute: c << "fabs(" << a << ")"; break;
        }
        c << ";\n";
        if (shared[k] >= 0)
            c << "    r[" << shared[k] << "] = v" << k << ";\n";
    };
    auto batch = [](const statement& s) { return "t" + std::to_string(s.depth) + "_" + std::to_string(s.number); };
    auto emit_call = [&](const statement& s, std::size_t part) {
        c << "    const lagrange_sincos4 " << batch(s) << " = " << sleef_sincos_function << "((lagrange_v4){";
        for (std::size_t lane = 0; lane < 4; ++lane)
            c << (lane ? ", " : "") << (lane < s.arguments.size() ? name_of(s.arguments[lane], part) : "0.0");
        c << "});\n";
    };
    auto emit_lane = [&](std::size_t k) {
        const auto [call, lane] = lane_of[k];
        c << "    const double v" << k << " = " << batch(order[call]) << (code_[k].op == op::sine ? ".x[" : ".y[")
          << lane << "];\n";
        if (shared[k] >= 0)
            c << "    r[" << shared[k] << "] = v" << k << ";\n";
    };
    auto emit_outputs = [&](std::size_t part) {
        for (std::size_t k = 0; k < outputs_.size(); ++k)
            if (!split || part_of[static_cast<std::size_t>(outputs_[k])] == part)
                c << "    out[" << k << "] = v" << outputs_[k] << ";\n";
    };
    if (!split) {
        c << "static void " << name << "(const double* s, double* out)\n{\n";
        for (const statement& s : order) {
            if (!s.call) {
                emit(s.slot, 0);
                continue;
            }
            emit_call(s, 0);
            for (std::size_t k : s.lanes)
                emit_lane(k);
        }
        emit_outputs(0);
        c << "}\n";
        return {c.str()};
    }
    // Parts in units: the first unit holds the first parts and the function that calls them all,
    // the others later parts, hidden (not exported from the library) but not static.
    units = std::min(units, parts);
    std::vector<std::string> text(units);
    auto unit_of = [&](std::size_t part) { return part * units / parts; };
    const std::string signature = "(const double* restrict s, double* restrict r, double* restrict out)";
    for (std::size_t part = 0; part < parts; ++part) {
        // noinline: inlined back into one function, the parts would take as long to compile.
        c << "__attribute__((noinline" << (unit_of(part) ? ", visibility(\"hidden\"))) void " : ")) static void ")
          << name << "_" << part << signature << "\n{\n";
        // The constants, symbols and negations this part reads from others, made again (their
        // operands have lower slots, so slot order puts each after what it reads).
        std::vector<bool> needed(code_.size(), false);
        for (std::size_t k = 0; k < order.size(); ++k) {
            if (part_of_statement[k] != part)
                continue;
            auto need = [&](int a) {
                if (part_of[static_cast<std::size_t>(a)] != part && cheap[static_cast<std::size_t>(a)])
                    needed[static_cast<std::size_t>(a)] = true;
            };
            if (order[k].call)
                for (int a : order[k].arguments)
                    need(a);
            else
                operands(order[k].slot, need);
        }
        for (std::size_t k = code_.size(); k-- > 0;) {
            const std::size_t operand = static_cast<std::size_t>(code_[k].first);
            if (needed[k] && code_[k].op == op::neg && part_of[operand] != part)
                needed[operand] = true;
        }
        for (std::size_t k = 0; k < code_.size(); ++k)
            if (needed[k])
                emit(k, part);
        for (std::size_t k = 0; k < order.size(); ++k) {
            if (part_of_statement[k] != part)
                continue;
            const statement& s = order[k];
            if (!s.call) {
                emit(s.slot, part);
                continue;
            }
            emit_call(s, part);
            for (std::size_t slot : s.lanes)
                emit_lane(slot);
        }
        emit_outputs(part);
        c << "}\n";
        text[unit_of(part)] += c.str();
        c.str("");
    }
    for (std::size_t part = 0; part < parts; ++part)
        if (unit_of(part))
            c << "__attribute__((visibility(\"hidden\"))) void " << name << "_" << part << signature << ";\n";
    c << "static void " << name << "(const double* s, double* out)\n{\n    double r[" << std::max<std::size_t>(shared_count, 1)
      << "];\n";
    for (std::size_t part = 0; part < parts; ++part)
        c << "    " << name << "_" << part << "(s, r, out);\n";
    c << "}\n";
    text.front() += c.str();
    return text;
}

} // namespace lagrange
