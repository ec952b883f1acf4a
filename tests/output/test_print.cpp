// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_print.cpp
 *  Tests of the deterministic printers: exact strings in the three syntaxes,
 *  independence from GiNaC's internal order, and plain output that GiNaC's
 *  parser reads back to the same expression. */
#include "output/print.h"

#include <catch2/catch.hpp>

#include <map>
#include <random>
#include <string>
#include <vector>

using GiNaC::ex;
using lagrange::print;
using lagrange::print_name;
using lagrange::syntax;
using lagrange::term_order;

namespace {

/// Symbols by name, created in the order given: a different creation order
/// gives GiNaC a different internal order of terms and factors.
struct symbol_table {
    std::map<std::string, ex> by_name;

    explicit symbol_table(const std::vector<std::string>& names)
    {
        for (const auto& name : names)
            by_name.emplace(name, GiNaC::realsymbol(name));
    }
    const ex& operator[](const std::string& name) const { return by_name.at(name); }
};

const std::vector<std::string> all_names = {"M", "m", "l", "g", "omega", "theta", "phi", "theta_dot",
                                            "phi_dot", "theta_ddot", "phi_ddot", "a", "b", "c", "d", "x", "y"};

symbol_table forward_symbols() { return symbol_table(all_names); }

symbol_table reverse_symbols()
{
    return symbol_table(std::vector<std::string>(all_names.rbegin(), all_names.rend()));
}

ex characteristic(const symbol_table& s)
{
    const ex &M = s["M"], &m = s["m"], &l = s["l"], &g = s["g"], &omega = s["omega"];
    return M * pow(l, 2) * pow(omega, 4) - 2 * (M + m) * g * l * pow(omega, 2) + (M + m) * pow(g, 2);
}

ex double_pendulum(const symbol_table& s)
{
    const ex &M = s["M"], &m = s["m"], &l = s["l"], &g = s["g"];
    const ex &theta = s["theta"], &phi = s["phi"];
    return (M + m) * pow(l, 2) * s["theta_ddot"] + m * pow(l, 2) * cos(theta - phi) * s["phi_ddot"] +
           m * pow(l, 2) * sin(theta - phi) * pow(s["phi_dot"], 2) + (M + m) * g * l * sin(theta);
}

term_order velocity_order(const symbol_table& s)
{
    return term_order{{{s["theta_ddot"], s["phi_ddot"]}, {s["theta_dot"], s["phi_dot"]}}};
}

/// Reads plain output back with GiNaC's parser, knowing the table's symbols.
ex reparse(const std::string& text, const symbol_table& s)
{
    GiNaC::symtab table;
    for (const auto& [name, symbol] : s.by_name)
        table[name] = symbol;
    GiNaC::parser reader(table, true);
    return reader(text);
}

bool same_meaning(const ex& a, const ex& b) { return (a - b).expand().is_zero(); }

/// A random expression of sums, products, powers and functions, the same for
/// the same seed whatever the symbols' creation order.
ex random_expression(std::mt19937& random, const symbol_table& s, int depth)
{
    static const char* const names[] = {"a", "b", "c", "x", "theta", "phi_dot"};
    auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(random); };
    if (depth == 0 || pick(4) == 0) {
        switch (pick(3)) {
        case 0: return GiNaC::numeric(pick(7) - 3, pick(3) + 1);
        default: return s[names[pick(6)]];
        }
    }
    const ex left = random_expression(random, s, depth - 1);
    const ex right = random_expression(random, s, depth - 1);
    switch (pick(9)) {
    case 0: return left + right;
    case 1: return left - right;
    case 2:
    case 3: return left * right;
    case 4: {
        const ex divisor = right + s["b"];
        return divisor.is_zero() ? left : left / divisor;
    }
    case 5: {
        const ex base = left - right;
        const int exponent = pick(7) - 3;
        return base.is_zero() ? left : pow(base, exponent);
    }
    case 6: return pow(s["c"] + left, s["x"]);
    case 7: return sin(left - right) + cos(right);
    default: return sqrt(s["a"] + pow(left, 2)) * exp(right);
    }
}

} // namespace

TEST_CASE("print: characteristic polynomial of the double pendulum", "[print]")
{
    const symbol_table s = forward_symbols();
    const ex e = characteristic(s);
    const term_order by_omega{{{s["omega"]}}};
    CHECK(print(e, syntax::plain, by_omega) == "M*l^2*omega^4-2*(M+m)*g*l*omega^2+(M+m)*g^2");
    CHECK(print(e, syntax::text, by_omega) == "M·l²·ω⁴ - 2·(M + m)·g·l·ω² + (M + m)·g²");
    CHECK(print(e, syntax::latex, by_omega) ==
          "M l^{2} \\omega^{4} - 2 \\left(M + m\\right) g l \\omega^{2} + \\left(M + m\\right) g^{2}");
}

TEST_CASE("print: double pendulum equation, accelerations then velocities", "[print]")
{
    const symbol_table s = forward_symbols();
    const ex e = double_pendulum(s);
    const term_order order = velocity_order(s);
    CHECK(print(e, syntax::plain, order) ==
          "(M+m)*l^2*theta_ddot+l^2*m*cos(theta-phi)*phi_ddot+l^2*m*sin(theta-phi)*phi_dot^2+(M+m)*g*l*sin(theta)");
    CHECK(print(e, syntax::text, order) ==
          "(M + m)·l²·θ\u0308 + l²·m·cos(θ - φ)·φ\u0308 + l²·m·sin(θ - φ)·φ\u0307² + (M + m)·g·l·sin(θ)");
    CHECK(print(e, syntax::latex, order) ==
          "\\left(M + m\\right) l^{2} \\ddot{\\theta} + l^{2} m \\cos\\left(\\theta - \\phi\\right) \\ddot{\\phi}"
          " + l^{2} m \\sin\\left(\\theta - \\phi\\right) \\dot{\\phi}^{2}"
          " + \\left(M + m\\right) g l \\sin\\theta");
}

TEST_CASE("print: term order groups by total degree, then exponents", "[print]")
{
    const symbol_table s = forward_symbols();
    const ex &x = s["x"], &y = s["y"], &a = s["a"];
    const term_order order{{{x, y}}};
    // degree 2 (x^2 before x*y before y^2), then degree 1, then the rest
    const ex e = a + y + x + pow(y, 2) + x * y + pow(x, 2) + 3;
    CHECK(print(e, syntax::plain, order) == "x^2+x*y+y^2+x+y+a+3");
    // without groups: positive terms first, then by printed form, numbers last
    CHECK(print(x - y + a - 2, syntax::plain) == "a+x-y-2");
    CHECK(print(s["theta"] - s["phi"], syntax::plain) == "theta-phi");
    CHECK(print(-x - y, syntax::plain) == "-x-y");
    CHECK(print(1 - x, syntax::plain) == "1-x");
}

TEST_CASE("print: a sum factor gets its sign from the printer, not from GiNaC", "[print]")
{
    // GiNaC writes (c-d)^3 as -(d-c)^3 for some symbol creation orders
    const symbol_table s = forward_symbols();
    const ex &a = s["a"], &c = s["c"], &d = s["d"], &x = s["x"], &omega = s["omega"];
    CHECK(print(pow(c - d, 3), syntax::plain) == "(c-d)^3");
    CHECK(print(pow(d - c, 3), syntax::plain) == "-(c-d)^3");
    CHECK(print(pow(d - c, 2) * x, syntax::plain) == "(c-d)^2*x");
    CHECK(print(x / (d - c), syntax::plain) == "-x/(c-d)");
    CHECK(print(x * (1 - a), syntax::plain) == "-(a-1)*x");
    // the leading term by the term order is positive
    const term_order by_omega{{{omega}}};
    CHECK(print(x * (a - pow(omega, 2)), syntax::plain, by_omega) == "-(omega^2-a)*x");
}

TEST_CASE("print: output does not depend on GiNaC's internal order", "[print]")
{
    std::vector<std::string> outputs[2];
    for (int pass = 0; pass < 2; ++pass) {
        const symbol_table s = pass == 0 ? forward_symbols() : reverse_symbols();
        const ex &a = s["a"], &b = s["b"], &c = s["c"], &d = s["d"], &x = s["x"], &y = s["y"];
        const std::vector<ex> cases = {
            characteristic(s),
            double_pendulum(s),
            a * b / (c * d) + x / y - GiNaC::numeric(1, 2) * a * pow(b, 2),
            sin(x - y) * cos(y - x) + pow(a + b, 2) * pow(c - d, -3),
            sqrt(x + y) + exp(-a * b) + log(c * d),
            (a + b + c) * (x - y) * d,
        };
        for (const ex& e : cases)
            for (syntax syn : {syntax::plain, syntax::text, syntax::latex}) {
                outputs[pass].push_back(print(e, syn));
                outputs[pass].push_back(print(e, syn, velocity_order(s)));
            }
    }
    REQUIRE(outputs[0].size() == outputs[1].size());
    for (std::size_t i = 0; i < outputs[0].size(); ++i)
        CHECK(outputs[0][i] == outputs[1][i]);
}

TEST_CASE("print: random expressions do not depend on GiNaC's internal order", "[print]")
{
    const symbol_table forward = forward_symbols();
    const symbol_table reverse = reverse_symbols();
    for (unsigned seed = 1; seed <= 200; ++seed) {
        std::mt19937 random_forward(seed);
        std::mt19937 random_reverse(seed);
        const ex e_forward = random_expression(random_forward, forward, 4);
        const ex e_reverse = random_expression(random_reverse, reverse, 4);
        for (syntax syn : {syntax::plain, syntax::text, syntax::latex}) {
            const std::string printed = print(e_forward, syn, velocity_order(forward));
            INFO("seed " << seed << ": " << printed);
            CHECK(printed == print(e_reverse, syn, velocity_order(reverse)));
        }
        const std::string plain = print(e_forward, syntax::plain);
        INFO("seed " << seed << ": " << plain);
        CHECK(same_meaning(reparse(plain, forward), e_forward));
    }
}

TEST_CASE("print: coefficients, fractions and powers", "[print]")
{
    const symbol_table s = forward_symbols();
    const ex &m = s["m"], &l = s["l"], &g = s["g"], &a = s["a"], &b = s["b"], &c = s["c"], &d = s["d"];
    const ex &x = s["x"], &theta_dot = s["theta_dot"];
    const ex half = GiNaC::numeric(1, 2);

    struct expected {
        ex e;
        const char* plain;
        const char* text;
        const char* latex;
    };
    const std::vector<expected> table = {
        {half * m * pow(l, 2) * pow(theta_dot, 2), "1/2*l^2*m*theta_dot^2", "(1/2)·l²·m·θ\u0307²",
         "\\frac{1}{2} l^{2} m \\dot{\\theta}^{2}"},
        {-x, "-x", "-x", "-x"},
        {-1 * x * a, "-a*x", "-a·x", "-a x"},
        {g / l, "g/l", "g/l", "\\frac{g}{l}"},
        {a * b / (c * d), "a*b/(c*d)", "a·b/(c·d)", "\\frac{a b}{c d}"},
        {-3 * a / (2 * pow(b, 2)), "-3*a/(2*b^2)", "-3·a/(2·b²)", "-\\frac{3 a}{2 b^{2}}"},
        {1 / x, "1/x", "1/x", "\\frac{1}{x}"},
        {1 / (a + b), "1/(a+b)", "1/(a + b)", "\\frac{1}{a + b}"},
        {sqrt(x), "sqrt(x)", "√x", "\\sqrt{x}"},
        {1 / sqrt(a + b), "1/sqrt(a+b)", "1/√(a + b)", "\\frac{1}{\\sqrt{a + b}}"},
        {pow(x, GiNaC::numeric(3, 2)), "x^(3/2)", "x^(3/2)", "x^{3/2}"},
        {pow(a + b, c), "(a+b)^c", "(a + b)^c", "\\left(a + b\\right)^{c}"},
        {pow(pow(a, b), c), "(a^b)^c", "(a^b)^c", "\\left(a^{b}\\right)^{c}"},
        {pow(a, b + c), "a^(b+c)", "a^(b + c)", "a^{b + c}"},
        {pow(a, -b), "a^(-b)", "a^(-b)", "a^{-b}"},
        {pow(-a, b), "(-a)^b", "(-a)^b", "\\left(-a\\right)^{b}"},
        {pow(a / b, c), "(a/b)^c", "(a/b)^c", "\\left(\\frac{a}{b}\\right)^{c}"},
        {2 * pow(3, x), "2*3^x", "2·3^x", "2 \\cdot 3^{x}"},
        {GiNaC::numeric(-5, 3), "-5/3", "-5/3", "-\\frac{5}{3}"},
        {x * GiNaC::Pi, "Pi*x", "π·x", "\\pi x"},
        {2 * GiNaC::Pi * sqrt(l / g), "2*Pi*sqrt(l/g)", "2·π·√(l/g)", "2 \\pi \\sqrt{\\frac{l}{g}}"},
    };
    for (const auto& row : table) {
        INFO(row.plain);
        CHECK(print(row.e, syntax::plain) == row.plain);
        CHECK(print(row.e, syntax::text) == row.text);
        CHECK(print(row.e, syntax::latex) == row.latex);
    }
}

TEST_CASE("print: functions", "[print]")
{
    const symbol_table s = forward_symbols();
    const ex &theta = s["theta"], &phi = s["phi"], &x = s["x"], &a = s["a"];

    CHECK(print(sin(theta), syntax::latex) == "\\sin\\theta");
    CHECK(print(cos(x), syntax::latex) == "\\cos x");
    CHECK(print(sin(theta - phi), syntax::latex) == "\\sin\\left(\\theta - \\phi\\right)");
    CHECK(print(pow(sin(theta), 2), syntax::latex) == "\\sin^{2}\\theta");
    CHECK(print(pow(cos(theta - phi), 2), syntax::latex) == "\\cos^{2}\\left(\\theta - \\phi\\right)");
    // a bare argument is closed by parentheses when more factors follow
    CHECK(print(a * sin(theta) * x, syntax::latex) == "a x \\sin\\theta");
    CHECK(print(exp(x), syntax::latex) == "e^{x}");
    CHECK(print(log(x), syntax::latex) == "\\ln x");
    CHECK(print(abs(x), syntax::latex) == "\\left|x\\right|");
    CHECK(print(atan(x), syntax::latex) == "\\arctan x");

    CHECK(print(sin(theta), syntax::text) == "sin(θ)");
    CHECK(print(pow(sin(theta), 2), syntax::text) == "sin(θ)²");
    CHECK(print(log(x), syntax::text) == "ln(x)");
    CHECK(print(abs(x), syntax::text) == "|x|");

    CHECK(print(pow(sin(theta), 2), syntax::plain) == "sin(theta)^2");
    CHECK(print(exp(-x), syntax::plain) == "exp(-x)");
    CHECK(print(abs(x) + tanh(x), syntax::plain) == "abs(x)+tanh(x)");
}

TEST_CASE("print: floats", "[print]")
{
    const symbol_table s = forward_symbols();
    const ex& x = s["x"];
    auto f = [](const char* decimal) { return ex(GiNaC::numeric(decimal)); };

    CHECK(print(f("9.81"), syntax::plain) == "9.81");
    CHECK(print(f("0.01"), syntax::plain) == "0.01");
    CHECK(print(f("2.0"), syntax::plain) == "2.0");
    CHECK(print(f("1e-14"), syntax::plain) == "1e-14");
    CHECK(print(f("1.5e20"), syntax::plain) == "1.5e20");
    CHECK(print(f("-0.25"), syntax::plain) == "-0.25");
    CHECK(print(f("123456.0"), syntax::plain) == "123456.0");
    CHECK(print(f("0.1") * x, syntax::plain) == "0.1*x");
    CHECK(print(x - f("0.5"), syntax::plain) == "x-0.5");

    CHECK(print(f("1.5e-20"), syntax::latex) == "1.5\\times10^{-20}");
    CHECK(print(f("1e6"), syntax::latex) == "10^{6}");
    CHECK(print(f("9.81"), syntax::latex) == "9.81");
    CHECK(print(f("-2.5e-7") * x, syntax::latex) == "-2.5\\times10^{-7} x");

    CHECK(print(f("1.5e-20"), syntax::text) == "1.5×10⁻²⁰");
    CHECK(print(f("0.5"), syntax::text) == "0.5");
}

TEST_CASE("print: relations and complex numbers", "[print]")
{
    const symbol_table s = forward_symbols();
    const ex &x = s["x"], &theta = s["theta"];
    const ex relation = (x + 1 == pow(theta, 2));
    CHECK(print(relation, syntax::plain) == "x+1==theta^2");
    CHECK(print(relation, syntax::text) == "x + 1 = θ²");
    CHECK(print(relation, syntax::latex) == "x + 1 = \\theta^{2}");

    CHECK(print(GiNaC::I, syntax::plain) == "I");
    CHECK(print(2 * GiNaC::I * x, syntax::plain) == "2*I*x");
    CHECK(print(x + 1 - 2 * GiNaC::I, syntax::plain) == "x+(1-2*I)");
    CHECK(print(GiNaC::I * x, syntax::latex) == "i x");
}

TEST_CASE("print_name: Greek letters, dots and subscripts", "[print]")
{
    struct expected {
        const char* name;
        const char* text;
        const char* latex;
    };
    const std::vector<expected> table = {
        {"theta", "θ", "\\theta"},
        {"Omega", "Ω", "\\Omega"},
        {"M", "M", "M"},
        {"omega", "ω", "\\omega"},
        {"theta_dot", "θ\u0307", "\\dot{\\theta}"},
        {"theta_ddot", "θ\u0308", "\\ddot{\\theta}"},
        {"theta1", "θ1", "\\theta_{1}"},
        {"theta1_dot", "θ\u0307" "1", "\\dot{\\theta}_{1}"},
        {"x_ddot", "x\u0308", "\\ddot{x}"},
        {"l_2", "l_2", "l_{2}"},
        {"m12", "m12", "m_{12}"},
        {"omega_0", "ω_0", "\\omega_{0}"},
        {"x_cm", "x_cm", "x_{\\mathrm{cm}}"},
        {"a_b_c", "a_b_c", "a_{b_{c}}"},
        {"k_theta", "k_θ", "k_{\\theta}"},
        {"mass", "mass", "\\mathrm{mass}"},
        {"xy_dot", "xy'", "\\dot{\\mathrm{xy}}"},
        {"xy_ddot", "xy''", "\\ddot{\\mathrm{xy}}"},
        {"w1_dot", "w\u0307" "1", "\\dot{w}_{1}"},
        {"beta2_x", "β2_x", "\\beta_{2_{x}}"},
        {"a_", "a_", "\\mathrm{a\\_}"},
    };
    for (const auto& row : table) {
        INFO(row.name);
        CHECK(print_name(row.name, syntax::plain) == row.name);
        CHECK(print_name(row.name, syntax::text) == row.text);
        CHECK(print_name(row.name, syntax::latex) == row.latex);
    }

    const symbol_table s = forward_symbols();
    CHECK(print(pow(s["theta_dot"], 2) * s["m"], syntax::latex) == "m \\dot{\\theta}^{2}");
    CHECK(print(s["phi_ddot"], syntax::plain) == "phi_ddot");
}

TEST_CASE("print: plain output reads back to the same expression", "[print]")
{
    const symbol_table s = forward_symbols();
    const ex &a = s["a"], &b = s["b"], &c = s["c"], &d = s["d"], &x = s["x"], &y = s["y"];
    const ex &theta = s["theta"], &phi = s["phi"], &l = s["l"], &g = s["g"];
    const ex half = GiNaC::numeric(1, 2);

    const std::vector<ex> cases = {
        characteristic(s),
        double_pendulum(s),
        half * s["m"] * pow(l, 2) * pow(s["theta_dot"], 2),
        -x,
        a - b - c,
        -a * b / (c * d),
        GiNaC::numeric(-7, 3) * x / (y * pow(a + b, 2)),
        pow(a + b, c),
        pow(pow(a, b), c),
        pow(-a, b),
        pow(a, -b),
        pow(a / b, c),
        pow(a, GiNaC::numeric(-3, 2)),
        pow(a, GiNaC::numeric(2, 3)) * b,
        sqrt(a + b) / sqrt(c),
        2 * GiNaC::Pi * sqrt(l / g),
        pow(2, x) * 3,
        pow(GiNaC::numeric(1, 2), x),
        pow(x, y + 1) - pow(y, -x),
        sin(theta - phi) * cos(theta) + pow(tan(phi), 2),
        exp(-a * b) + log(c) - abs(d),
        asin(x) + acos(y) + atan(a / b) + sinh(x) - cosh(y) * tanh(a),
        (a + b) * (c - d) * (x + y + 1),
        1 / (a + b) - 1 / (a - b),
        GiNaC::numeric(3) * x - 1,
    };
    for (const ex& e : cases) {
        const std::string text = print(e, syntax::plain);
        INFO(text);
        CHECK(same_meaning(reparse(text, s), e));
    }

    // floats read back to the same double
    const std::vector<const char*> decimals = {"9.81", "0.01", "1e-14", "1.5e20", "2.0", "0.1", "-3.25e-5"};
    for (const char* decimal : decimals) {
        const ex f = GiNaC::numeric(decimal);
        const std::string text = print(f * x, syntax::plain);
        INFO(text);
        const ex back = reparse(text, s).coeff(x, 1);
        REQUIRE(GiNaC::is_a<GiNaC::numeric>(back));
        CHECK_FALSE(GiNaC::ex_to<GiNaC::numeric>(back).is_rational());
        CHECK(GiNaC::ex_to<GiNaC::numeric>(back).to_double() == GiNaC::ex_to<GiNaC::numeric>(f).to_double());
    }
}
