// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_expression_program.cpp
 *  The compiled programs' arithmetic against 60-digit references: each double-double
 *  operation within its published error bound, the a priori bounds of subtraction-free
 *  programs bounding the actual error, and the checks that say where they do not apply. */
#include "program/double_double.h"
#include "program/expression_program.h"
#include "program/native_code.h"
#include "system/external.h"
#include "helpers/tools.h"

#include <catch2/catch.hpp>

#include <cln/cln.h>

#include <cmath>
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <random>

namespace {

using lagrange::a_priori_bound;
using lagrange::double_double;
using lagrange::expression_program;
using status = expression_program::a_priori_status;

const cln::float_format_t digits60 = cln::float_format(60);

cln::cl_F exact(double x)
{
    if (x != 0 && std::abs(x) < 0x1p-1000) // CLN's doubles have no subnormals: scaled up and back
        return cln::scale_float(exact(std::ldexp(x, 200)), -200);
    return cln::cl_float(cln::rational(cln::cl_DF(x)), digits60);
}
cln::cl_F exact(double_double x) { return exact(x.hi) + exact(x.lo); }

/// |x − reference| / |reference|, in units of u² = 2^-106.
double error_in_u2(double_double x, const cln::cl_F& reference)
{
    cln::cl_F e = cln::abs((exact(x) - reference) / reference);
    return cln::double_approx(e) * 0x1p106;
}

/// The value of `e` at `values` (exact rationals of the doubles), to 60 digits, by GiNaC.
cln::cl_F reference(const GiNaC::ex& e, const std::vector<GiNaC::ex>& symbols, const std::vector<double>& values)
{
    GiNaC::exmap at;
    for (std::size_t k = 0; k < symbols.size(); ++k)
        at[symbols[k]] = GiNaC::numeric(cln::rational(cln::cl_DF(values[k])));
    int saved = GiNaC::Digits;
    GiNaC::Digits = 60;
    GiNaC::ex value = e.subs(at).evalf();
    GiNaC::Digits = saved;
    return cln::cl_float(cln::realpart(GiNaC::ex_to<GiNaC::numeric>(value).to_cl_N()), digits60);
}

/// A random double-double: hi over 2^-60…2^60 of either sign, lo a random half-ulp fraction.
double_double random_double_double(std::mt19937& random, bool positive = false)
{
    std::uniform_real_distribution<double> mantissa(1, 2), fraction(-0.5, 0.5);
    std::uniform_int_distribution<int> exponent(-60, 60), sign(0, 1);
    double hi = std::ldexp(mantissa(random), exponent(random)) * (positive || sign(random) ? 1 : -1);
    double lo = fraction(random) * (std::nextafter(std::abs(hi), HUGE_VAL) - std::abs(hi));
    return lagrange::dd::quick_two_sum(hi, lo);
}

} // namespace

TEST_CASE("double-double arithmetic: each operation within its published bound", "[expression_program]")
{
    // Published bounds (Joldes, Muller, Popescu 2017; Lefèvre et al. 2023): accurate sum 3u²,
    // product 5u², DWDivDW2 15u² + 56u³, SQRTDWtoDW 25/8 u². The a priori bounds assume
    // 2^-99 = 128u² per step. The FMA and Dekker products give the same bits.
    std::mt19937 random(2017);
    double worst_add = 0, worst_mul = 0, worst_div = 0, worst_sqrt = 0;
    for (int k = 0; k < 20000; ++k) {
        double_double a = random_double_double(random), b = random_double_double(random);
        cln::cl_F A = exact(a), Bx = exact(b);
        double_double sum = lagrange::dd::add(a, b);
        if (!cln::zerop(A + Bx))
            worst_add = std::max(worst_add, error_in_u2(sum, A + Bx));
        double_double product = lagrange::dd::mul<false>(a, b), fused_product = lagrange::dd::mul<true>(a, b);
        REQUIRE(product.hi == fused_product.hi);
        REQUIRE(product.lo == fused_product.lo);
        worst_mul = std::max(worst_mul, error_in_u2(product, A * Bx));
        double_double quotient = lagrange::dd::div<false>(a, b), fused_quotient = lagrange::dd::div<true>(a, b);
        REQUIRE(quotient.hi == fused_quotient.hi);
        REQUIRE(quotient.lo == fused_quotient.lo);
        worst_div = std::max(worst_div, error_in_u2(quotient, A / Bx));
        double_double positive = random_double_double(random, true);
        double_double root = lagrange::dd::sqrt<false>(positive), fused_root = lagrange::dd::sqrt<true>(positive);
        REQUIRE(root.hi == fused_root.hi);
        REQUIRE(root.lo == fused_root.lo);
        worst_sqrt = std::max(worst_sqrt, error_in_u2(root, cln::sqrt(exact(positive))));
    }
    INFO("worst relative errors in u²: add " << worst_add << ", mul " << worst_mul << ", div " << worst_div
                                              << ", sqrt " << worst_sqrt);
    CHECK(worst_add <= 3);
    CHECK(worst_mul <= 5);
    CHECK(worst_div <= 15.01);
    CHECK(worst_sqrt <= 25.0 / 8);
    // and √ of zero and of negative numbers as documented
    CHECK(lagrange::dd::sqrt(double_double{0, 0}).hi == 0);
    CHECK(std::isnan(lagrange::dd::sqrt(double_double{-4, 0}).hi));
}

TEST_CASE("a priori bounds: known for subtraction-free programs only", "[expression_program]")
{
    GiNaC::possymbol x("x"), y("y"), z("z");
    std::vector<GiNaC::ex> symbols{x, y, z};
    expression_program p({pow(x + y, 3) * sqrt(z) / (x + 2 * z), x - y, -x * y, pow(x - y, 2), GiNaC::ex(0),
                          GiNaC::Pi * x, sin(x), 1 / (x + 1 / (y + GiNaC::numeric(1, 3)))},
                         symbols);
    const a_priori_bound &positive = p.output_bound(0), &difference = p.output_bound(1),
                         &negative = p.output_bound(2), &square = p.output_bound(3), &zero = p.output_bound(4),
                         &constant = p.output_bound(5), &sine = p.output_bound(6), &fraction = p.output_bound(7);
    CHECK(positive.known);
    CHECK(positive.sign == 1);
    CHECK(positive.relative > 0);
    CHECK(positive.relative < 1e-28); // a dozen steps of 2^-99
    CHECK_FALSE(difference.known);
    CHECK(negative.known);
    CHECK(negative.sign == -1);
    CHECK_FALSE(square.known); // (x − y)² may cancel inside: no bound even though it is ≥ 0
    CHECK(zero.known);
    CHECK(zero.sign == 0);
    CHECK(zero.relative == 0);
    CHECK(constant.known);
    CHECK(constant.relative >= lagrange::double_double_step); // π is rounded, and so is the product
    CHECK_FALSE(sine.known);
    CHECK(fraction.known);
    CHECK(fraction.sign == 1);
}

TEST_CASE("a priori bounds: constants, symbols and powers read no slot", "[expression_program]")
{
    // Found by the fuzzer (the molecule example under UBSan): the analysis took a constant's
    // and a symbol's `first` (a symbol index) and a power's `second` (its exponent) for
    // slots. A program that starts with a constant, reads the sixth of six symbols and
    // raises to a power beyond its length must analyse without touching them.
    GiNaC::possymbol a("a"), b("b"), c("c"), d("d"), e("e"), x("x");
    std::vector<GiNaC::ex> symbols{a, b, c, d, e, x};
    expression_program constant({GiNaC::numeric(3, 7)}, symbols);
    CHECK(constant.output_bound(0).known);
    CHECK(constant.output_bound(0).sign == 1);
    expression_program power({pow(x, 9)}, symbols);
    CHECK(power.instruction_count() == 2);
    CHECK(power.output_bound(0).known);
    CHECK(power.output_bound(0).relative > 0);
    expression_program half({GiNaC::numeric(1, 2) * pow(x, 2) * e}, symbols);
    CHECK(half.output_bound(0).known);
    std::vector<double> values{1, 1, 1, 1, 3, 2};
    std::vector<double_double> dd_scratch, out(1);
    half.run(values.data(), dd_scratch, out.data());
    CHECK(out[0].hi == 6);
    CHECK(half.check_a_priori(dd_scratch) == status::holds);
}

TEST_CASE("a priori bounds bound the error of subtraction-free programs", "[expression_program]")
{
    // Deep, badly scaled, subtraction-free expressions at random positive points over 2^-40…2^40:
    // each point's double-double value within its a priori bound of the 60-digit value, in one
    // point's run and in a batch, and the bounds tight enough to mean something.
    GiNaC::possymbol a("a"), b("b"), c("c");
    std::vector<GiNaC::ex> symbols{a, b, c};
    std::vector<GiNaC::ex> outputs{pow(a + b, 7) * pow(c, -3) + sqrt(a * b + c / 7),
                                   1 / (a + 1 / (b + 1 / (c + GiNaC::numeric(1, 3)))),
                                   pow(a * b * c + GiNaC::Pi, GiNaC::numeric(5, 2)),
                                   4 * pow(a, 6) * (b + c) * pow(c, 2) * pow(b, 3),
                                   -(a + b) / sqrt(c * c + GiNaC::numeric(2, 3) * a)};
    expression_program p(outputs, symbols);
    constexpr std::size_t B = expression_program::batch_size;
    std::mt19937 random(99);
    std::uniform_real_distribution<double> exponent(-40, 40);
    std::vector<double> points(3 * B);
    std::vector<double> scratch;
    std::vector<const double*> rows(outputs.size());
    std::vector<double_double> dd_scratch(0), dd_out(outputs.size());
    std::vector<status> statuses(B);
    double worst = 0; // error / bound
    for (int round = 0; round < 8; ++round) {
        for (double& x : points)
            x = std::exp2(exponent(random));
        p.run_batch_a_priori(points.data(), 3, B, scratch, rows.data(), statuses.data());
        for (std::size_t j = 0; j < B; ++j) {
            REQUIRE(statuses[j] == status::holds);
            std::vector<double> values(points.begin() + 3 * j, points.begin() + 3 * j + 3);
            p.run(values.data(), dd_scratch, dd_out.data());
            CHECK(p.check_a_priori(dd_scratch) == status::holds);
            for (std::size_t k = 0; k < outputs.size(); ++k) {
                const a_priori_bound& bound = p.output_bound(k);
                REQUIRE(bound.known);
                double_double batch{rows[k][j], rows[k][B + j]};
                REQUIRE(batch.hi == dd_out[k].hi); // one point and a batch: the same bits
                REQUIRE(batch.lo == dd_out[k].lo);
                double error = error_in_u2(batch, reference(outputs[k], symbols, values)) * 0x1p-106;
                INFO("output " << k << " at " << values[0] << ", " << values[1] << ", " << values[2]);
                CHECK(error <= bound.relative);
                worst = std::max(worst, error / bound.relative);
            }
        }
    }
    for (std::size_t k = 0; k < outputs.size(); ++k)
        CHECK(p.output_bound(k).relative < 1e-27);
    INFO("largest error / bound " << worst);
    CHECK(worst > 0); // the outputs do round
}

TEST_CASE("a priori bounds: where they do not apply", "[expression_program]")
{
    GiNaC::possymbol x("x"), y("y");
    std::vector<GiNaC::ex> symbols{x, y};
    expression_program p({pow(x, 4) * y, x + y}, symbols);
    constexpr std::size_t B = expression_program::batch_size;
    std::vector<double> points(2 * B, 1.5), scratch;
    const double* rows[2];
    std::vector<status> statuses(B);
    points[2 * 1] = -1.0;          // a negative symbol: the signs are not known
    points[2 * 2 + 1] = 0.0;       // zero is not positive either
    points[2 * 3] = std::nan("");  // nor is NaN
    points[2 * 4] = 1e-100;        // x⁴ = 1e-400 underflows
    points[2 * 5] = 1e200;         // x⁴ overflows
    points[2 * 6] = 1e-60;         // x⁴ y = 1.5e-240: fine, although outside the fast check's range
    points[2 * 7 + 1] = 1e300;     // y alone is fine, x⁴ y = 5e300 too, x + y too
    p.run_batch_a_priori(points.data(), 2, B, scratch, rows, statuses.data());
    CHECK(statuses[0] == status::holds);
    CHECK(statuses[1] == status::not_positive);
    CHECK(statuses[2] == status::not_positive);
    CHECK(statuses[3] == status::not_positive);
    CHECK(statuses[4] == status::out_of_range);
    CHECK(statuses[5] == status::out_of_range);
    CHECK(statuses[6] == status::holds);
    CHECK(statuses[7] == status::out_of_range); // 1e300 > 2^995: too close to overflow for Dekker
    // one point at a time says the same
    std::vector<double_double> dd_scratch, dd_out(2);
    for (std::size_t j = 0; j < 8; ++j) {
        p.run(&points[2 * j], dd_scratch, dd_out.data());
        INFO("point " << j);
        CHECK(p.check_a_priori(dd_scratch) == statuses[j]);
    }
    // a difference has no bound, but the other outputs keep theirs, and the points their status
    expression_program q({x - y, x * y}, symbols);
    std::fill(points.begin(), points.end(), 2.0);
    q.run_batch_a_priori(points.data(), 2, B, scratch, rows, statuses.data());
    CHECK_FALSE(q.output_bound(0).known);
    CHECK(q.output_bound(1).known);
    CHECK(rows[0][0] == 0);
    CHECK(rows[1][0] == 4);
    CHECK(statuses[0] == status::holds);
}

TEST_CASE("native code: sines and cosines, by SLEEF four at a time or by libm, within a few ulps of 60 digits",
          "[expression_program][native][cc]")
{
    // Five arguments of depth 1 (two SLEEF calls), three of depth 2 and one of depth 3 (nested
    // sines and cosines: each batch needs the one before), sin and cos of the same argument (one
    // sincos), and a slot between the levels.
    GiNaC::symbol x("x"), y("y"), z("z"), w("w"), v("v");
    std::vector<GiNaC::ex> symbols = {x, y, z, w, v};
    std::vector<GiNaC::ex> outputs = {GiNaC::sin(x),
                                      GiNaC::cos(x),
                                      GiNaC::sin(y) * GiNaC::cos(y),
                                      GiNaC::sin(GiNaC::cos(x)),
                                      GiNaC::cos(GiNaC::sin(y)),
                                      GiNaC::sin(GiNaC::sin(GiNaC::sin(x))),
                                      GiNaC::cos(z) * w,
                                      GiNaC::sin(w) + GiNaC::pow(v, 2),
                                      GiNaC::cos(v * GiNaC::sin(z))};
    expression_program program(outputs, symbols);
    REQUIRE(program.trigonometric());
    const std::string source = program.c_source("p", true);
    CHECK(source.find("Sleef_sincosd4_u35avx2") != std::string::npos);
    CHECK(program.c_source("p", false).find("Sleef") == std::string::npos);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> value(-10, 10);
    for (const char* setting : {"1", "0"}) {
        INFO("LAGRANGE_SLEEF=" << setting);
        setenv("LAGRANGE_SLEEF", setting, 1);
        std::string why;
        std::shared_ptr<lagrange::native_module> module = lagrange::native_module::compile({&program}, {}, &why);
        unsetenv("LAGRANGE_SLEEF");
        INFO(why);
        REQUIRE(module);
        // SLEEF where the CPU has AVX2 and FMA (the test command installs libsleef-dev).
        CHECK(module->sleef() == (std::string(setting) == "1" && lagrange_test::cpu_has_avx2_and_fma()));
        for (int point = 0; point < 200; ++point) {
            std::vector<double> at(5);
            for (double& a : at)
                a = value(random);
            std::vector<double> out(outputs.size());
            module->get(0)(at.data(), out.data());
            for (std::size_t k = 0; k < outputs.size(); ++k) {
                double expected = cln::double_approx(reference(outputs[k], symbols, at));
                INFO("output " << k << " at " << at[0] << ", " << at[1] << ", " << at[2] << ", " << at[3] << ", "
                               << at[4] << ": " << out[k] << " against " << expected);
                // SLEEF's sin and cos are within 3.5 ulp, libm's within 1; nesting, products and sums add
                // a few roundings of quantities up to 10 in size (v·sin z with |v| ≤ 10), so the
                // bound is absolute where the value is small (cos(v·sin z) near a zero).
                CHECK(std::abs(out[k] - expected) <= 32 * 0x1p-53 * std::max(std::abs(expected), 1.0));
                if (k < 2) { // sin x and cos x themselves: SLEEF's documented 3.5 ulp of the exact
                             // value, and half an ulp for rounding the reference to a double
                    double unit = std::nextafter(std::abs(expected), HUGE_VAL) - std::abs(expected);
                    CHECK(std::abs(out[k] - expected) <= 4 * unit);
                }
            }
        }
    }
}

TEST_CASE("native code: without SLEEF to link, libm's sines, and the same values", "[expression_program][native][cc]")
{
    // A compiler that refuses -lsleef, as on a machine without libsleef-dev: the module is
    // compiled again without SLEEF (and later ones in this process skip it), never refused.
    lagrange::private_directory folder("lagrange-test");
    folder.write("cc", "#!/bin/sh\nfor a in \"$@\"; do [ \"$a\" = -lsleef ] && exit 1; done\nexec " + lagrange_test::configured_compiler() +
                           " \"$@\"\n");
    std::filesystem::permissions(folder.path() + "/cc", std::filesystem::perms::owner_all);
    GiNaC::symbol x("x"), y("y");
    expression_program program({GiNaC::sin(x) * GiNaC::cos(y), GiNaC::cos(GiNaC::sin(x) + y)}, {x, y});
    std::string why;
    std::shared_ptr<lagrange::native_module> refused, later;
    {
        lagrange_test::compiler_override wrapped(folder.path() + "/cc");
        refused = lagrange::native_module::compile({&program}, {}, &why);
        later = lagrange::native_module::compile({&program});
    }
    INFO(why);
    REQUIRE(refused);
    REQUIRE(later);
    CHECK(!refused->sleef());
    CHECK(!later->sleef());
    std::vector<double> at = {0.7, -2.3}, out(2), interpreted(2), scratch;
    refused->get(0)(at.data(), out.data());
    program.run(at.data(), scratch, interpreted.data());
    CHECK(out == interpreted); // libm's sin and cos, and no contraction: the interpreter's numbers
}

TEST_CASE("native code in parts: the same numbers as one function, with and without SLEEF",
          "[expression_program][native][cc]")
{
    // Parts of 3 statements: values cross parts through the array (products, sums, sines and
    // their nested arguments), constants, symbols and negations are made again in each part,
    // and an output may come from any part.
    GiNaC::symbol x("x"), y("y"), z("z");
    std::vector<GiNaC::ex> symbols = {x, y, z};
    const GiNaC::ex shared = x * y + GiNaC::numeric(3, 7) * z;
    std::vector<GiNaC::ex> outputs = {GiNaC::sin(shared) * x - y,
                                      GiNaC::cos(shared * z) + GiNaC::pow(shared, 3),
                                      -z,
                                      GiNaC::numeric(5, 3),
                                      GiNaC::sin(GiNaC::cos(x) * shared) / (1 + y * y),
                                      shared * GiNaC::sqrt(2 + x * x) - GiNaC::cos(z - x) * y};
    expression_program program(outputs, symbols);
    for (bool sleef : {true, false}) {
        INFO("SLEEF " << sleef);
        const std::string parts = program.c_source("p", sleef, 3), whole = program.c_source("p", sleef, 0);
        CHECK(parts.find("p_2(s, r, out);") != std::string::npos);
        CHECK(whole.find("p_0") == std::string::npos);
    }
    lagrange::native_limits in_parts, whole;
    in_parts.part_statements = 3;
    whole.part_statements = 0;
    for (const char* setting : {"1", "0"}) {
        INFO("LAGRANGE_SLEEF=" << setting);
        setenv("LAGRANGE_SLEEF", setting, 1);
        std::string why;
        std::shared_ptr<lagrange::native_module> a = lagrange::native_module::compile({&program}, in_parts, &why);
        std::shared_ptr<lagrange::native_module> b = lagrange::native_module::compile({&program}, whole, &why);
        unsetenv("LAGRANGE_SLEEF");
        INFO(why);
        REQUIRE(a);
        REQUIRE(b);
        CHECK(a->sleef() == b->sleef());
        std::mt19937 random(11);
        std::uniform_real_distribution<double> value(-3, 3);
        for (int point = 0; point < 100; ++point) {
            std::vector<double> at = {value(random), value(random), value(random)}, first(outputs.size()),
                                second(outputs.size()), interpreted(outputs.size()), scratch;
            a->get(0)(at.data(), first.data());
            b->get(0)(at.data(), second.data());
            CHECK(first == second); // the same operations in the same order
            program.run(at.data(), scratch, interpreted.data());
            for (std::size_t k = 0; k < outputs.size(); ++k)
                CHECK(std::abs(first[k] - interpreted[k]) <= 1e-12 * std::max(1.0, std::abs(interpreted[k])));
        }
    }
}

namespace {

/// One of the functions beyond sin, cos, tan, exp and log: how to apply it, its hard spots
/// (each also taken negative) and the largest magnitude of its random arguments.
struct function_case {
    const char* name;
    GiNaC::ex (*apply)(const GiNaC::ex&);
    std::vector<double> spots;
    double largest;
    bool near_one = false; ///< asin, acos: also random arguments 1 − 2^-k
};

std::vector<function_case> function_cases()
{
    const std::vector<double> hyperbolic = {0, 1e-300, 1e-10, 0.5, 1, 3, 19, 20, 40, 100, 700};
    const std::vector<double> inverse = {0,   1e-300, 1e-10, 0.5, 0.9, 1 - 1e-6, 1 - 0x1p-26, 1 - 0x1p-40,
                                         1 - 0x1p-52, 1 - 0x1p-53, 1};
    return {{"sinh", [](const GiNaC::ex& a) -> GiNaC::ex { return GiNaC::sinh(a); }, hyperbolic, 700},
            {"cosh", [](const GiNaC::ex& a) -> GiNaC::ex { return GiNaC::cosh(a); }, hyperbolic, 700},
            {"tanh", [](const GiNaC::ex& a) -> GiNaC::ex { return GiNaC::tanh(a); }, hyperbolic, 700},
            {"asin", [](const GiNaC::ex& a) -> GiNaC::ex { return GiNaC::asin(a); }, inverse, 1, true},
            {"acos", [](const GiNaC::ex& a) -> GiNaC::ex { return GiNaC::acos(a); }, inverse, 1, true},
            {"atan", [](const GiNaC::ex& a) -> GiNaC::ex { return GiNaC::atan(a); },
             {0, 1e-300, 1e-10, 1, 1e8, 1e20, 1e300}, 1e300},
            {"abs", [](const GiNaC::ex& a) -> GiNaC::ex { return GiNaC::abs(a); }, {0, 1e-300, 1.5, 1e300}, 1e300}};
}

/// Whether a running bound holds: |value − exact| ≤ error, nothing claimed by an infinite
/// error, and a value that is not a number only with an infinite error.
bool holds(lagrange::bounded_double b, const cln::cl_F& reference)
{
    if (b.error == HUGE_VAL)
        return true;
    if (!std::isfinite(b.value) || !std::isfinite(b.error))
        return false;
    return cln::abs(exact(b.value) - reference) <= exact(b.error);
}

bool same(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

} // namespace

TEST_CASE("hyperbolic, inverse trigonometric functions and abs: each arithmetic against 60 digits",
          "[expression_program]")
{
    // f(x) at an exact argument, f(z·y) at a rounded one (y = 0.1, z = t/y: the product carries
    // an error into f), and GiNaC's f′(x) and f″(x), which must compile too (x/|x| for abs),
    // at hard spots (asin and acos at and next to ±1, tanh and atan far out, abs at ±0) and
    // at random arguments. The double run and the bounded run's value are the same bits; the
    // running bound contains the 60-digit value (or is infinite, as asin's and acos's must be
    // where the argument's interval reaches ±1); double-double is within 8u relative of it
    // for f itself, however ill-conditioned f is there (asin near 1), its argument being nearly exact;
    // a batch gives the bits of one point's runs.
    GiNaC::realsymbol x("x"), z("z"), y("y");
    const std::vector<GiNaC::ex> symbols{x, z, y};
    constexpr double y0 = 0.1, u = lagrange::unit_roundoff;
    constexpr std::size_t B = expression_program::batch_size;
    for (const function_case& f : function_cases()) {
        INFO(f.name);
        const GiNaC::ex fx = f.apply(x);
        const std::vector<GiNaC::ex> outputs{fx, f.apply(z * y), fx.diff(x), fx.diff(x, 2)};
        const expression_program p(outputs, symbols);
        CHECK(p.algebraic() == (std::string(f.name) == "abs"));
        std::vector<double> arguments;
        for (double s : f.spots)
            arguments.insert(arguments.end(), {s, -s});
        std::mt19937 random(1234);
        std::uniform_real_distribution<double> decade(-8, std::log10(f.largest)), bits(1, 53);
        for (int k = 0; k < 300; ++k) {
            const double magnitude = f.near_one && k % 2 ? 1 - std::exp2(-bits(random)) : std::pow(10.0, decade(random));
            arguments.push_back(k % 3 ? magnitude : -magnitude);
        }
        std::vector<double> points;
        for (double t : arguments)
            points.insert(points.end(), {t, t / y0, y0});
        double worst_ratio = 0; // error / bound
        int infinite = 0;
        std::vector<double> scratch, batch(outputs.size() * 4 * B), plain(outputs.size());
        std::vector<lagrange::bounded_double> bounded_scratch, bounded(outputs.size());
        std::vector<double_double> dd_scratch, dd(outputs.size());
        for (std::size_t first = 0; first < arguments.size(); first += B) {
            const std::size_t count = std::min(B, arguments.size() - first);
            p.run_batch(&points[3 * first], 3, count, scratch, batch.data());
            for (std::size_t j = 0; j < count; ++j) {
                const double* at = &points[3 * (first + j)];
                p.run(at, bounded_scratch, bounded.data());
                p.run(at, dd_scratch, dd.data());
                std::vector<double> plain_scratch;
                p.run(at, plain_scratch, plain.data());
                const cln::cl_RA product = cln::rational(cln::cl_DF(at[1])) * cln::rational(cln::cl_DF(at[2]));
                // the double-double product z·y is exact short of under- and overflow (Dekker's
                // splitting overflows, the FMA and Dekker low parts underflow differently)
                const bool exact_product = at[0] == 0 || (std::abs(at[0]) > 1e-270 && std::abs(at[0]) < 1e290);
                for (std::size_t k = 0; k < outputs.size(); ++k) {
                    INFO("output " << k << " at x = " << at[0] << ", z·y = " << at[1] << "·" << at[2]);
                    const bool dd_meant = (k != 1 || exact_product) && (k < 2 || std::abs(at[0]) < 1e30);
                    const double* lane = &batch[k * 4 * B + j];
                    if (dd_meant) {
                        CHECK(same(lane[0], dd[k].hi));
                        CHECK(same(lane[B], dd[k].lo));
                    }
                    CHECK(same(lane[2 * B], bounded[k].value));
                    CHECK(same(lane[3 * B], bounded[k].error));
                    CHECK(same(plain[k], bounded[k].value));
                    if (k == 1 && f.near_one && cln::abs(product) > 1)
                        continue; // the exact argument is outside the domain
                    if (k >= 2 && ((f.near_one && std::abs(at[0]) == 1) || (std::string(f.name) == "abs" && at[0] == 0) ||
                                   std::abs(at[0]) > 1e30))
                        continue; // no derivative there (or running::recip squares past overflow)
                    if (k >= 2 && std::isnan(bounded[k].error))
                        continue; // 0·∞ in a product of the derivative's arithmetic: no bound claimed
                    const cln::cl_F value = reference(outputs[k], symbols, {at[0], at[1], at[2]});
                    INFO("double " << bounded[k].value << " ± " << bounded[k].error << ", exact "
                                   << cln::double_approx(value));
                    CHECK(holds(bounded[k], value));
                    if (bounded[k].error == HUGE_VAL) {
                        ++infinite;
                        CHECK(f.near_one); // only where the derivative is unbounded
                        CHECK(std::abs(at[0]) > 0.9); // z·y is about x
                    } else if (holds(bounded[k], value) && bounded[k].error > 0) {
                        const double error = cln::double_approx(cln::abs(exact(bounded[k].value) - value));
                        worst_ratio = std::max(worst_ratio, error / bounded[k].error);
                    }
                    if (k == 0 && std::isfinite(bounded[k].value)) // f at an exact argument: only libm's rounding
                        CHECK(bounded[k].error <= 8 * u * std::abs(bounded[k].value));
                    if (k < 2 && dd_meant) { // double-double: double accuracy, whatever the conditioning
                        const double relative =
                            cln::zerop(value) ? std::abs(dd[k].hi) + std::abs(dd[k].lo)
                                              : cln::double_approx(cln::abs((exact(dd[k]) - value) / value));
                        CHECK(relative <= 8 * u);
                    }
                }
            }
        }
        INFO("largest error / bound " << worst_ratio << ", infinite bounds " << infinite);
        CHECK(worst_ratio > 0.01); // the bounds say something
        if (f.near_one)
            CHECK(infinite > 0); // f(z·y) with z·y rounded next to ±1
    }
}

TEST_CASE("asin and acos at ±1 in double-double: the low part's square root, and no more than the domain",
          "[expression_program]")
{
    // x + y with x = ±1 and y a low part toward 0: the first-order correction would be infinite;
    // the value is about √(2|y|) off asin(±1). A low part away from 0 is taken as ±1.
    GiNaC::realsymbol x("x"), y("y");
    const std::vector<GiNaC::ex> symbols{x, y};
    const std::vector<GiNaC::ex> outputs{GiNaC::asin(x + y), GiNaC::acos(x + y)};
    const expression_program p(outputs, symbols);
    std::vector<double_double> scratch, out(2);
    std::vector<lagrange::bounded_double> bounded_scratch, bounded(2);
    for (double one : {1.0, -1.0})
        for (double low : {0x1p-54, 0x1p-60, 0x1p-80, 0x1p-100}) {
            const std::vector<double> at{one, -one * low};
            INFO("x = " << one << ", y = " << at[1]);
            p.run(at.data(), scratch, out.data());
            for (std::size_t k = 0; k < 2; ++k) {
                const cln::cl_F value = reference(outputs[k], symbols, at);
                const double relative = cln::double_approx(cln::abs((exact(out[k]) - value) / value));
                CHECK(relative <= 4 * lagrange::unit_roundoff);
            }
            // the double x + y rounds to ±1: its interval reaches ±1, so no finite bound
            p.run(at.data(), bounded_scratch, bounded.data());
            CHECK(bounded[0].error == HUGE_VAL);
            CHECK(bounded[1].error == HUGE_VAL);
            const std::vector<double> beyond{one, one * low};
            p.run(beyond.data(), scratch, out.data());
            const std::vector<double> at_one{one, 0};
            for (std::size_t k = 0; k < 2; ++k) {
                const cln::cl_F value = reference(outputs[k], symbols, at_one);
                if (cln::zerop(value)) {
                    CHECK(out[k].hi == 0);
                    CHECK(out[k].lo == 0);
                } else {
                    CHECK(cln::double_approx(cln::abs((exact(out[k]) - value) / value)) <= 4 * lagrange::unit_roundoff);
                }
            }
        }
}

TEST_CASE("conjugate compiles where its argument is real, and csgn and complex conjugates do not",
          "[expression_program]")
{
    GiNaC::realsymbol x("x");
    GiNaC::symbol w("w"); // not known to be real
    // d|w|/dw = (w + conj w)/(2|w|) for a complex symbol: refused, as before, with the function named
    const GiNaC::ex complex_derivative = GiNaC::abs(w).diff(w);
    REQUIRE(complex_derivative.has(GiNaC::conjugate_function(w)));
    try {
        expression_program({complex_derivative}, {w});
        FAIL("compiled");
    } catch (const std::invalid_argument& e) {
        CHECK(std::string(e.what()).find("cannot evaluate conjugate(w) numerically") != std::string::npos);
    }
    CHECK_THROWS_AS(expression_program({GiNaC::csgn(x)}, {x}), std::invalid_argument);
    // conj of a real expression held unevaluated is the expression
    const GiNaC::ex held = GiNaC::conjugate_function(GiNaC::sin(x) + 1).hold();
    REQUIRE(GiNaC::is_a<GiNaC::function>(held));
    const expression_program p({held, GiNaC::abs(x).diff(x)}, {x});
    std::vector<double> scratch, out(2);
    const double at = -0.75;
    p.run(&at, scratch, out.data());
    CHECK(out[0] == std::sin(-0.75) + 1);
    CHECK(out[1] == -1); // x/|x|
}

TEST_CASE("a priori bounds: abs keeps the bound of its argument, the other new functions have none",
          "[expression_program]")
{
    // real symbols, so that GiNaC keeps |−ab − 1| (it drops abs of what it knows to be positive);
    // the a priori analysis takes every symbol positive
    GiNaC::realsymbol a("a"), b("b");
    const std::vector<GiNaC::ex> symbols{a, b};
    const std::vector<GiNaC::ex> outputs{GiNaC::abs(-a * b - 1) * (a + b), GiNaC::abs(a - b), GiNaC::sinh(a),
                                         GiNaC::cosh(a), GiNaC::tanh(a), GiNaC::asin(1 / (a + 1)),
                                         GiNaC::acos(1 / (a + 1)), GiNaC::atan(a)};
    const expression_program p(outputs, symbols);
    REQUIRE(std::any_of(p.code().begin(), p.code().end(),
                        [](const lagrange::instruction& i) { return i.op == lagrange::instruction::code::absolute; }));
    const a_priori_bound& absolute = p.output_bound(0);
    REQUIRE(absolute.known);
    CHECK(absolute.sign == 1);
    CHECK(absolute.relative > 0);
    CHECK(absolute.relative < 1e-28);
    CHECK_FALSE(p.output_bound(1).known); // a difference inside
    for (std::size_t k = 2; k < outputs.size(); ++k)
        CHECK_FALSE(p.output_bound(k).known);
    // and the bound holds, in a batch over 2^-30…2^30
    const expression_program q({outputs[0]}, symbols);
    constexpr std::size_t B = expression_program::batch_size;
    std::mt19937 random(5);
    std::uniform_real_distribution<double> exponent(-30, 30);
    std::vector<double> points(2 * B), scratch;
    for (double& v : points)
        v = std::exp2(exponent(random));
    const double* rows[1];
    std::vector<status> statuses(B);
    q.run_batch_a_priori(points.data(), 2, B, scratch, rows, statuses.data());
    for (std::size_t j = 0; j < B; ++j) {
        REQUIRE(statuses[j] == status::holds);
        const double_double value{rows[0][j], rows[0][B + j]};
        const double error =
            error_in_u2(value, reference(outputs[0], symbols, {points[2 * j], points[2 * j + 1]})) * 0x1p-106;
        CHECK(error <= q.output_bound(0).relative);
    }
}

TEST_CASE("native code: the hyperbolic and inverse trigonometric functions and abs are libm's, as interpreted",
          "[expression_program][native][cc]")
{
    GiNaC::realsymbol x("x"), y("y");
    const std::vector<GiNaC::ex> symbols{x, y};
    std::vector<GiNaC::ex> outputs;
    for (const function_case& f : function_cases()) {
        const GiNaC::ex argument = f.near_one ? x * y / 16 : x * y; // no sine: no SLEEF
        outputs.push_back(f.apply(argument));
        outputs.push_back(f.apply(argument).diff(x));
    }
    const expression_program program(outputs, symbols);
    const std::string source = program.c_source("p");
    for (const char* call : {"sinh(", "cosh(", "tanh(", "asin(", "acos(", "atan(", "fabs("})
        CHECK(source.find(call) != std::string::npos);
    std::string why;
    std::shared_ptr<lagrange::native_module> module = lagrange::native_module::compile({&program}, {}, &why);
    INFO(why);
    REQUIRE(module);
    std::mt19937 random(3);
    std::uniform_real_distribution<double> value(-4, 4);
    std::vector<double> out(outputs.size()), interpreted(outputs.size()), scratch;
    for (int point = 0; point < 500; ++point) {
        const std::vector<double> at{value(random), point % 7 == 0 ? 0.0 : value(random)};
        module->get(0)(at.data(), out.data());
        program.run(at.data(), scratch, interpreted.data());
        for (std::size_t k = 0; k < outputs.size(); ++k) {
            INFO("output " << k << " at " << at[0] << ", " << at[1]);
            CHECK(same(out[k], interpreted[k])); // the same calls, no contraction: the same bits
        }
    }
}
