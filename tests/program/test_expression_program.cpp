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
#include <cstdlib>
#include <filesystem>
#include <random>

namespace {

using lagrange::a_priori_bound;
using lagrange::double_double;
using lagrange::expression_program;
using status = expression_program::a_priori_status;

const cln::float_format_t digits60 = cln::float_format(60);

cln::cl_F exact(double x) { return cln::cl_float(cln::rational(cln::cl_DF(x)), digits60); }
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
