// SPDX-License-Identifier: GPL-2.0-or-later
/** @file expression_program.h
 *  Straight-line numeric code compiled once from GiNaC expressions in a fixed list
 *  of symbols: a postfix instruction list with common subexpressions shared, run
 *  many times in double, in double with a running error bound, or in double-double. */
#pragma once

#include "program/double_double.h"

#include <ginac/ginac.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace lagrange {

/// One step of a program; operands are earlier slots.
struct instruction {
    enum class code { constant, symbol, add, mul, neg, recip, square_root, integer_power, real_power,
                      sine, cosine, exponential, logarithm, hyperbolic_sine, hyperbolic_cosine,
                      hyperbolic_tangent, arcsine, arccosine, arctangent, absolute };
    code op = code::constant;
    int first = 0;          ///< operand slot (or symbol index)
    int second = 0;         ///< second operand slot, or the exponent of integer_power
    double value = 0;       ///< constant (rounded) or real exponent
    double value_low = 0;   ///< constant: the next 53 bits (value + value_low is the double-double)
    double value_error = 0; ///< constant: |exact − value|
};

/// Whether an instruction's `first` (and `second`) are slots, rather than a symbol's index,
/// an exponent (integer_power's second) or nothing: what every reader of a program follows.
inline bool reads_first_slot(instruction::code op)
{
    return op != instruction::code::constant && op != instruction::code::symbol;
}
inline bool reads_second_slot(instruction::code op)
{
    return op == instruction::code::add || op == instruction::code::mul;
}

/// What is known of a slot before it runs, where every symbol it reads is positive: its
/// sign, and a bound on the relative error of its double-double value. Both are known for
/// slots built from symbols and constants by +, ×, ÷, √, integer powers and abs (exact)
/// without adding terms of opposite sign (subtraction-free: no cancellation, so every step
/// only adds its own rounding). Each double-double step is taken to round within 2^-99 relative, eight
/// times the published bounds of these algorithms (at most 16u², Joldes–Muller–Popescu,
/// ACM TOMS 44(2), 2017), and as long as no value under- or overflows (run_batch_a_priori
/// checks that on every point).
struct a_priori_bound {
    bool known = false;
    int sign = 0;         ///< −1, 0 or +1, where known
    double relative = 0;  ///< |computed − exact| ≤ relative·|exact|, where known
};

/// One rounding of a double-double step in a priori bounds (see a_priori_bound).
constexpr double double_double_step = 0x1p-99;
/// Below this a double-double's low part loses bits to underflow; above it Dekker's
/// splitting or a product overflows. A priori bounds need every value in between.
constexpr double a_priori_smallest = 0x1p-968;
constexpr double a_priori_largest = 0x1p995;
/// Whether a magnitude lies in that range (false for NaN). Without branches, for vectorized loops.
LAGRANGE_ALWAYS_INLINE inline bool in_a_priori_range(double magnitude)
{
    return (magnitude >= a_priori_smallest) & (magnitude <= a_priori_largest);
}

/// Compiled from `outputs`, a list of expressions in `symbols`; throws
/// std::invalid_argument naming any other symbol or unsupported function. The functions:
/// sin cos tan exp log sinh cosh tanh asin acos atan abs, and the conjugate of an argument
/// GiNaC knows to be real (the derivative of abs at a complex symbol has one). `invariant`
/// names symbols that keep their value from one evaluation to the next (parameters given
/// as arguments): a product's part in them alone is computed as one value, shared by every
/// product with the same part, before the rest is multiplied on.
/// `definitions`: intermediate quantities, each a symbol defined by an expression in the
/// symbols and the symbols defined before it, computed once in that order (the steps of a
/// recursion, numeric/point_tree.h); the outputs may read them too. A definition is
/// compiled whether an output reads it or not.
struct program_definition {
    GiNaC::ex symbol, value;
};
class expression_program {
public:
    expression_program() = default;
    expression_program(const std::vector<GiNaC::ex>& outputs, const std::vector<GiNaC::ex>& symbols,
                       const std::vector<GiNaC::ex>& invariant = {})
        : expression_program({}, outputs, symbols, invariant)
    {
    }
    expression_program(const std::vector<program_definition>& definitions, const std::vector<GiNaC::ex>& outputs,
                       const std::vector<GiNaC::ex>& symbols, const std::vector<GiNaC::ex>& invariant = {});

    std::size_t output_count() const { return outputs_.size(); }
    /// The instructions, in order (slot k is instruction k), and the slot of each output:
    /// for writers of the program in another language (output/export_code.h).
    const std::vector<instruction>& code() const { return code_; }
    const std::vector<int>& output_slots() const { return outputs_; }
    std::size_t instruction_count() const { return code_.size(); }
    /// Only + − × ÷, integer powers, square roots and absolute values: double-double
    /// evaluation keeps its ~32 digits and the bound scales with the unit roundoff.
    bool algebraic() const { return algebraic_; }

    /// Whether the program takes any sine or cosine.
    bool trigonometric() const;

    /// The program as a C function `static void NAME(const double* symbols, double* out)`
    /// (straight-line code, constants exact as hexadecimal floats), for native compilation.
    /// `sleef_sincos`: its sines and cosines four arguments at a time by SLEEF's AVX2
    /// sincos (its 3.5-ulp one; the source then needs sleef_declarations, AVX2 and
    /// -lsleef): arguments that need no sine or cosine are evaluated first, so each batch
    /// holds all the arguments of its nesting depth. Without it, libm's sin and cos.
    /// A program of more than 3 × `part_statements` statements is written as functions of at
    /// most `part_statements` statements each, which GCC compiles in much less time than one (its
    /// optimizer is superlinear in a function's size); the values one part passes to a later
    /// one go through a local array. The same operations in the same order either way, so
    /// the results are the same. 0: always one function.
    static constexpr std::size_t default_part_statements = 2500;
    std::string c_source(const std::string& name, bool sleef_sincos = false,
                         std::size_t part_statements = default_part_statements) const;
    /// c_source's parts in up to `units` C translation units, to be compiled side by side and
    /// linked together: the first holds the function `NAME` and the first parts, the others
    /// the later parts (hidden functions NAME_k). One unit when the program is not split.
    std::vector<std::string> c_units(const std::string& name, bool sleef_sincos, std::size_t part_statements,
                                     std::size_t units) const;
    /// The C declarations that code from c_source(…, true) needs: SLEEF's function with its
    /// types spelled as GCC vectors (the same ABI as <sleef.h>'s __m256d), so that no
    /// compilation has to parse <immintrin.h>, a large header.
    static const char* sleef_declarations();

    /// Runs the program on the symbol values; `scratch` is resized as needed.
    void run(const double* symbols, std::vector<double>& scratch, double* out) const;
    void run(const double* symbols, std::vector<bounded_double>& scratch, bounded_double* out) const;
    void run(const double* symbols, std::vector<double_double>& scratch, double_double* out) const;

    /// Runs the program on `count` points at once (at most batch_size), in double-double
    /// and with running error bounds together, structure of arrays: point j's symbols start
    /// at symbols + j·stride; output k of point j goes to out[k·4·batch_size + j] (hi),
    /// [.. + batch_size + j] (lo), [.. + 2·batch_size + j] (value of the bounded run) and
    /// [.. + 3·batch_size + j] (its error bound). One dispatch per instruction for the
    /// whole batch instead of one per point; the loops over points vectorize (with FMA
    /// products where the CPU has them, see fma_kernels()).
    static constexpr std::size_t batch_size = 32;
    void run_batch(const double* symbols, std::size_t stride, std::size_t count, std::vector<double>& scratch,
                   double* out) const;

    /// A priori bound of output k (see a_priori_bound).
    const a_priori_bound& output_bound(std::size_t k) const { return output_bounds_[k]; }
    /// What a point's run says of the a priori bounds.
    enum class a_priori_status : unsigned char {
        holds,        ///< every symbol positive, every slot of known sign in range
        not_positive, ///< a symbol the program reads is not positive (or not a number): no a priori bounds
        out_of_range, ///< a slot of known sign left [2^-968, 2^995]: under- or overflow, no bounds at all
    };
    /// As run_batch, in double-double only: no running bound is computed (the a priori
    /// bound of output k is output_bound(k).relative·|value|). outputs[k] is set to output
    /// k's lanes in `scratch`: hi at outputs[k][j], lo at outputs[k][batch_size + j].
    /// status[j] says whether point j's bounds hold.
    void run_batch_a_priori(const double* symbols, std::size_t stride, std::size_t count,
                            std::vector<double>& scratch, const double** outputs, a_priori_status* status) const;
    /// The status of a point from the slots a double-double run() left in `scratch`.
    a_priori_status check_a_priori(const std::vector<double_double>& scratch) const;

private:
    std::vector<instruction> code_;
    std::vector<int> outputs_; ///< slot of each output
    bool algebraic_ = true;
    std::vector<a_priori_bound> bounds_;        ///< of each slot
    std::vector<a_priori_bound> output_bounds_; ///< of each output
    std::vector<std::size_t> symbol_slots_;     ///< the slots that read a symbol
    /// The slots the range check covers: of known, nonzero sign and not constant.
    std::vector<std::size_t> checked_slots_;
    /// Symbols all in this range: no slot of known sign can leave its range (a fast check).
    std::pair<double, double> safe_symbols_{HUGE_VAL, 0};
    /// status of each point from every slot of known sign (the full check)
    void check_block(const double* slots, std::size_t count, a_priori_status* status) const;
};

} // namespace lagrange
