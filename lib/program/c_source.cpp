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

std::string expression_program::c_source(const std::string& name, bool sleef_sincos) const
{
    using op = instruction::code;
    std::ostringstream c;
    auto emit = [&](std::size_t k) {
        const instruction& i = code_[k];
        c << "    const double v" << k << " = ";
        std::string a = "v" + std::to_string(i.first), b = "v" + std::to_string(i.second);
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
        }
        c << ";\n";
    };
    c << "static void " << name << "(const double* s, double* out)\n{\n";
    if (!sleef_sincos) {
        for (std::size_t k = 0; k < code_.size(); ++k)
            emit(k);
    } else {
        // Depth of a slot: the most sines and cosines nested on any path to it. The slots of
        // depth D − 1 are all known before any sine or cosine of depth D is needed.
        std::vector<int> depth(code_.size(), 0);
        int deepest = 0;
        for (std::size_t k = 0; k < code_.size(); ++k) {
            const instruction& i = code_[k];
            int d = 0;
            switch (i.op) {
            case op::constant:
            case op::symbol: break;
            case op::add:
            case op::mul: d = std::max(depth[static_cast<std::size_t>(i.first)], depth[static_cast<std::size_t>(i.second)]); break;
            default: d = depth[static_cast<std::size_t>(i.first)]; break; // unary (integer_power: second is its exponent)
            }
            depth[k] = d + (sine_or_cosine(i) ? 1 : 0);
            deepest = std::max(deepest, depth[k]);
        }
        for (int d = 0; d <= deepest; ++d) {
            // The sines and cosines of depth d: one sincos per distinct argument, four per call.
            std::vector<int> arguments;
            for (std::size_t k = 0; k < code_.size(); ++k)
                if (depth[k] == d && sine_or_cosine(code_[k]) &&
                    std::find(arguments.begin(), arguments.end(), code_[k].first) == arguments.end())
                    arguments.push_back(code_[k].first);
            for (std::size_t call = 0; 4 * call < arguments.size(); ++call) {
                std::string batch = "t" + std::to_string(d) + "_" + std::to_string(call);
                c << "    const lagrange_sincos4 " << batch << " = " << sleef_sincos_function << "((lagrange_v4){";
                for (std::size_t lane = 0; lane < 4; ++lane) {
                    std::size_t j = 4 * call + lane;
                    c << (lane ? ", " : "") << (j < arguments.size() ? "v" + std::to_string(arguments[j]) : "0.0");
                }
                c << "});\n";
            }
            for (std::size_t k = 0; k < code_.size(); ++k) {
                if (depth[k] != d)
                    continue;
                if (!sine_or_cosine(code_[k])) {
                    emit(k);
                    continue;
                }
                std::size_t j = static_cast<std::size_t>(
                    std::find(arguments.begin(), arguments.end(), code_[k].first) - arguments.begin());
                c << "    const double v" << k << " = t" << d << "_" << j / 4 << (code_[k].op == op::sine ? ".x[" : ".y[")
                  << j % 4 << "];\n";
            }
        }
    }
    for (std::size_t k = 0; k < outputs_.size(); ++k)
        c << "    out[" << k << "] = v" << outputs_[k] << ";\n";
    c << "}\n";
    return c.str();
}

} // namespace lagrange
