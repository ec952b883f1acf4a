// SPDX-License-Identifier: GPL-2.0-or-later
// Symbolic work that scales (issue 23): the determinant by minor expansion, the content
// and factors of large sparse polynomials, and the primitive characteristic polynomial
// of chains with every mass and length distinct.
#include "algebra/budget.h"
#include "algebra/exact_matrix.h"
#include "algebra/factor.h"
#include "algebra/integer_polynomial.h"
#include "engine/analysis.h"
#include "helpers/cli_runner.h"
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>
#include <Eigen/Dense>

#include <cmath>
#include <map>
#include <random>
#include <string>
#include <vector>

using namespace lagrange;
using namespace lagrange_test;

namespace {

/// The factors of a product (a number, powers of bases) as base -> exponent, each base
/// with the sign that makes its expanded form's GiNaC::factor() leading unit positive.
std::vector<std::pair<GiNaC::ex, int>> factors_of(const GiNaC::ex& product)
{
    GiNaC::exvector parts = GiNaC::is_a<GiNaC::mul>(product) ? GiNaC::exvector(product.begin(), product.end())
                                                               : GiNaC::exvector{product};
    std::vector<std::pair<GiNaC::ex, int>> factors;
    for (const GiNaC::ex& part : parts) {
        if (GiNaC::is_a<GiNaC::numeric>(part))
            continue;
        if (GiNaC::is_a<GiNaC::power>(part))
            factors.push_back({part.op(0).expand(), GiNaC::ex_to<GiNaC::numeric>(part.op(1)).to_int()});
        else
            factors.push_back({part.expand(), 1});
    }
    return factors;
}

/// Whether two factorizations have the same factors with the same exponents, each
/// factor up to its sign.
bool same_factors(const GiNaC::ex& a, const GiNaC::ex& b)
{
    std::vector<std::pair<GiNaC::ex, int>> fa = factors_of(a), fb = factors_of(b);
    if (fa.size() != fb.size())
        return false;
    for (const auto& [base, exponent] : fa) {
        bool found = false;
        for (const auto& [other, other_exponent] : fb)
            found = found || (exponent == other_exponent &&
                              ((base - other).expand().is_zero() || (base + other).expand().is_zero()));
        if (!found)
            return false;
    }
    return true;
}

GiNaC::numeric random_rational(std::mt19937& random)
{
    std::uniform_int_distribution<int> numerator(1, 40), denominator(1, 9);
    return GiNaC::numeric(numerator(random), denominator(random));
}

} // namespace

TEST_CASE("scaling: the minor expansion gives GiNaC's determinant", "[scaling]")
{
    GiNaC::symbol a("a"), b("b"), c("c"), w("w");
    GiNaC::matrix m{{a + w, b, 0, c}, {b, 2 * a - w * c, 1, 0}, {0, 1, c * w, a * b}, {c, 0, a * b, b - w}};
    CHECK((expansion_determinant(m) - m.determinant(GiNaC::determinant_algo::laplace)).expand().is_zero());
    CHECK((expansion_determinant(GiNaC::matrix{{a}}) - a).is_zero());
    CHECK(expansion_determinant(GiNaC::matrix(0, 0)).is_equal(1));
    // rational coefficients and a function of a parameter: the expression path
    GiNaC::matrix rational{{a / 2 + w, GiNaC::cos(b), 0}, {GiNaC::cos(b), c - w / 3, 1}, {0, 1, a * c}};
    CHECK((expansion_determinant(rational) - rational.determinant(GiNaC::determinant_algo::laplace)).expand().is_zero());
    // large integer coefficients, far past 64 bits
    GiNaC::matrix large{{GiNaC::numeric("1000000000000") * a, b}, {b, GiNaC::numeric("3000000000000") * c + w}};
    CHECK((expansion_determinant(large) - large.determinant(GiNaC::determinant_algo::laplace)).expand().is_zero());
    // a singular matrix: two equal rows
    GiNaC::matrix singular{{a, b, c}, {a, b, c}, {w, 1, a}};
    CHECK(expansion_determinant(singular).is_zero());
}

TEST_CASE("scaling: large polynomials factor as GiNaC's factor() does", "[scaling]")
{
    GiNaC::symbol g("g"), m1("m1"), m2("m2"), m3("m3"), l1("l1"), l2("l2"), l3("l3");
    // irreducible factors linear in some symbol, one of them squared, and a monomial and number
    const GiNaC::ex sum = m1 + m2 + m3;
    const GiNaC::ex mixed = l1 * m1 * m2 + l2 * m2 * m3 + l3 * m1 * m3 + l1 * l2 * l3;
    const GiNaC::ex quadratic = g * g * l1 - m2 * m3 * l3 + 3 * l2 * m1; // linear in l1 and in m1
    const GiNaC::ex product = -6 * GiNaC::pow(sum, 2) * mixed * quadratic * l1 * l1 * g;
    const GiNaC::ex expanded = product.expand();
    REQUIRE(GiNaC::is_a<GiNaC::add>(expanded));
    REQUIRE(expanded.nops() > 24);
    const GiNaC::ex ours = factor_if_quick(expanded);
    CHECK((ours - expanded).expand().is_zero());
    // the reference: GiNaC's own factor()
    CHECK(same_factors(ours, GiNaC::factor(expanded)));
    CHECK(same_factors(ours, product));
    // no symbol of degree 1 anywhere: GiNaC's factor() does it
    const GiNaC::ex squares = (GiNaC::pow(m1, 2) + GiNaC::pow(l1, 2) + GiNaC::pow(g, 2)) *
                              (GiNaC::pow(m2, 2) * GiNaC::pow(l2, 2) - GiNaC::pow(l3, 2) * GiNaC::pow(m3, 2) + 1);
    const GiNaC::ex squares_ours = factor_if_quick(squares.expand());
    CHECK((squares_ours - squares).expand().is_zero());
    CHECK(same_factors(squares_ours, GiNaC::factor(squares.expand())));
}

TEST_CASE("scaling: coprimality and the content of several polynomials, exactly", "[scaling]")
{
    GiNaC::symbol x("x"), y("y"), z("z"), u("u");
    const GiNaC::ex f = x * y + z * u + 1, g = x + y * y * z + u, h = x * z - y * u + 2;
    CHECK(polynomials_coprime((f * g).expand(), h.expand()) == true);
    CHECK(polynomials_coprime(f, g) == true);
    CHECK(polynomials_coprime((f * g).expand(), (f * h).expand()) == false);
    CHECK(polynomials_coprime((g * g).expand(), (g * h).expand()) == false);
    CHECK(polynomials_coprime(3, f) == true);
    CHECK_FALSE(polynomials_coprime(GiNaC::sin(x), f).has_value());
    // the content of several polynomials against GiNaC's gcd
    const std::vector<GiNaC::ex> polynomials{(6 * x * x * y * f * g).expand(), (4 * x * y * y * f * h).expand(),
                                             (10 * x * y * f * g * h).expand()};
    const GiNaC::ex reference = GiNaC::gcd(GiNaC::gcd(polynomials[0], polynomials[1]), polynomials[2]);
    const GiNaC::ex content = polynomial_content(polynomials);
    CHECK(((content - reference).expand().is_zero() || (content + reference).expand().is_zero()));
    CHECK((content - 2 * x * y * f).expand().is_zero());
    CHECK((polynomial_content({0, (3 * x * y).expand(), 0}) - 3 * x * y).expand().is_zero());
    CHECK(polynomial_content({0, 0}).is_zero());
}

TEST_CASE("scaling: FLINT's factors and gcd of rational polynomials, signs fixed by name", "[scaling]")
{
    GiNaC::symbol a("a"), b("b"), c("c");
    // (b/2 − a/3)² (a c − 1): the leading term in the order of names is a's, so the
    // factors are 2a − 3b (a leads, positive) squared and a c − 1, over 36
    const GiNaC::ex p = GiNaC::pow(b / 2 - a / 3, 2) * (a * c - 1) * (-5);
    const std::optional<GiNaC::ex> factored = polynomial_factor(p.expand());
    REQUIRE(factored);
    CHECK((*factored - p).expand().is_zero());
    CHECK(same_factors(*factored, GiNaC::factor(p.expand())));
    CHECK(factored->has(GiNaC::pow(2 * a - 3 * b, 2)));
    CHECK(factored->has(a * c - 1));
    CHECK(factored->has(GiNaC::numeric(-5, 36)));
    // the gcd keeps the rational content's gcd: gcd(6 a²b, 9/2 a b c) = 3/2 a b
    const std::optional<GiNaC::ex> gcd = polynomial_gcd({6 * a * a * b, GiNaC::numeric(9, 2) * a * b * c});
    REQUIRE(gcd);
    CHECK((*gcd - GiNaC::numeric(3, 2) * a * b).expand().is_zero());
    CHECK_FALSE(polynomial_factor(GiNaC::cos(a) + b).has_value());
    // a determinant whose coefficients pass 2^64
    GiNaC::matrix huge{{GiNaC::numeric("100000000000000000000") * a, b}, {c, GiNaC::numeric("300000000000000000000") * b}};
    CHECK((expansion_determinant(huge) - huge.determinant(GiNaC::determinant_algo::laplace)).expand().is_zero());
}

// The chain with every mass and length distinct (issue 23's scaling case), N = 5. The
// references: a numeric determinant of V − W T at random rational points (the polynomial
// is a multiple of it that does not depend on W), the closed form of its constant term,
// det V / (l1 ⋯ lN mN) = g^N M1 ⋯ M(N−1) with Mk = mk + … + mN, and a leading coefficient
// that is a monomial l1 ⋯ lN m1 ⋯ m(N−1) (the kinetic determinant over the content).
TEST_CASE("scaling: the 5-link chain's characteristic polynomial, primitive and factored", "[scaling]")
{
    const int n = 5;
    std::string equilibrium = "equilibrium ";
    for (int i = 1; i <= n; ++i)
        equilibrium += (i > 1 ? ", q" : "q") + std::to_string(i) + " = 0";
    model scene = load(chain_scene(n) + equilibrium + "\n");
    analysis a = analyze(scene, {product::characteristic});
    REQUIRE(a.characteristic);
    const GiNaC::ex omega = a.characteristic->omega;
    const GiNaC::ex p = a.characteristic->polynomial.expand();
    REQUIRE(p.degree(omega) == 2 * n);
    std::mt19937 random(23);
    for (int trial = 0; trial < 3; ++trial) {
        GiNaC::exmap at;
        for (const parameter& parameter : scene.parameters)
            at[parameter.symbol] = random_rational(random);
        GiNaC::ex ratio;
        for (int k = 0; k < 3; ++k) {
            const GiNaC::numeric w = random_rational(random);
            GiNaC::matrix pencil(n, n);
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j)
                    pencil(i, j) = (a.linearization->potential(i, j) - w * a.linearization->kinetic(i, j)).subs(at);
            GiNaC::ex value = 0;
            for (int power = 0; power <= n; ++power)
                value += p.coeff(omega, 2 * power).subs(at) * GiNaC::pow(w, power);
            const GiNaC::ex here = value / pencil.determinant();
            if (k == 0)
                ratio = here;
            else
                CHECK((here - ratio).is_zero());
        }
        CHECK(!ratio.is_zero());
    }
    // the coefficients: constant term and leading term in closed form
    const GiNaC::ex g = symbol_of(scene, "g");
    GiNaC::ex constant = GiNaC::pow(g, n), leading = 1;
    for (int k = 1; k <= n; ++k) {
        leading *= symbol_of(scene, "l" + std::to_string(k));
        if (k < n)
            leading *= symbol_of(scene, "m" + std::to_string(k));
        GiNaC::ex sum = 0;
        for (int i = k; i <= n; ++i)
            sum += symbol_of(scene, "m" + std::to_string(i));
        if (k < n)
            constant *= sum;
    }
    const GiNaC::ex c0 = a.characteristic->polynomial.coeff(omega, 0);
    CHECK(a.characteristic->factored);
    // det(V − W T) → det V at W = 0 and (−1)^N det T W^N: the leading coefficient is made positive
    CHECK((p.coeff(omega, 0) + constant).expand().is_zero());
    CHECK(((p.coeff(omega, 2 * n) - leading).expand().is_zero() || (p.coeff(omega, 2 * n) + leading).expand().is_zero()));
    // factored: the constant term as g^5 and its four sums
    CHECK(same_factors(c0, constant));
}

TEST_CASE("scaling: the 4-link chain's coefficients have no common factor (GiNaC's gcd)", "[scaling]")
{
    std::string text = chain_scene(4) + "equilibrium q1 = 0, q2 = 0, q3 = 0, q4 = 0\n";
    model scene = load(text);
    analysis a = analyze(scene, {product::characteristic});
    REQUIRE(a.characteristic);
    const GiNaC::ex p = a.characteristic->polynomial.expand();
    GiNaC::ex content = 0;
    for (int k = 0; k <= p.degree(a.characteristic->omega); k += 2)
        content = GiNaC::gcd(content, p.coeff(a.characteristic->omega, k));
    CHECK((content - 1).is_zero());
    // leading coefficient positive for positive parameters
    GiNaC::ex leading = p.coeff(a.characteristic->omega, 8);
    GiNaC::exmap ones;
    for (const parameter& parameter : scene.parameters)
        ones[parameter.symbol] = 1;
    CHECK(GiNaC::ex_to<GiNaC::numeric>(leading.subs(ones)).is_positive());
}

namespace {

/// The planar chain with every mass and length distinct, at rest, with one `values` point.
std::string chain_with_values(int n)
{
    std::string equilibrium = "equilibrium ", values = "values g = 9.81";
    for (int i = 1; i <= n; ++i) {
        const std::string k = std::to_string(i);
        equilibrium += (i > 1 ? ", q" : "q") + k + " = 0";
        values += ", m" + k + " = " + std::to_string(1 + i / 10.0) + ", l" + k + " = " + std::to_string(1 + i / 20.0);
    }
    return chain_scene(n) + equilibrium + "\n" + values + "\n";
}

} // namespace

// The closed-form ω² of the 3-link chain with every mass and length distinct: the roots
// of an irreducible cubic in trigonometric form. Asked for alone they come without the
// mode vectors; the reference is the generalized eigenvalues of (V, T) at random points.
TEST_CASE("scaling: the 3-link chain's closed-form frequencies, without mode vectors", "[scaling]")
{
    model scene = load(chain_scene(3) + "equilibrium q1 = 0, q2 = 0, q3 = 0\n");
    analysis a = analyze(scene, {product::frequencies});
    REQUIRE(a.modes);
    REQUIRE(a.modes->closed_form);
    REQUIRE(a.modes->frequencies.size() == 3);
    CHECK(a.modes->modes.empty());
    CHECK(a.modes->normal_coordinates.empty());
    std::mt19937 random(3);
    for (int trial = 0; trial < 3; ++trial) {
        GiNaC::exmap at;
        for (const parameter& parameter : scene.parameters)
            at[parameter.symbol] = random_rational(random);
        Eigen::Matrix3d t, v;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                t(i, j) = GiNaC::ex_to<GiNaC::numeric>(a.linearization->kinetic(i, j).subs(at).evalf()).to_double();
                v(i, j) = GiNaC::ex_to<GiNaC::numeric>(a.linearization->potential(i, j).subs(at).evalf()).to_double();
            }
        Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix3d> pencil(v, t);
        for (int k = 0; k < 3; ++k) {
            const double w2 = GiNaC::ex_to<GiNaC::numeric>(a.modes->frequencies[k].subs(at).evalf()).to_double();
            CHECK_THAT(w2, Catch::Matchers::WithinRel(pencil.eigenvalues()(k), 1e-10));
        }
    }
}

TEST_CASE("scaling: the 3-link chain's mode vectors are left to the numeric modes, with a note", "[scaling]")
{
    // A default run wants the mode vectors; for the roots of a cubic in seven parameters
    // each entry would be pages long.
    model bare = load(chain_scene(3) + "equilibrium q1 = 0, q2 = 0, q3 = 0\n");
    analysis a = analyze(bare, {});
    REQUIRE(a.modes);
    CHECK(a.modes->closed_form);
    CHECK(a.modes->vectors_left_out);
    CHECK(a.modes->frequencies.size() == 3);
    CHECK(a.modes->modes.empty());
    CHECK(a.modes->normal_coordinates.empty());
    CHECK_FALSE(a.numeric);
    REQUIRE(a.notes.size() == 1);
    CHECK_THAT(a.notes[0], Catch::Matchers::Contains("irreducible cubic") &&
                               Catch::Matchers::Contains("give `values` to have them numerically"));
    // With values the numeric modes give them, and their ω² are the closed form's at the point.
    model scene = load(chain_with_values(3));
    analysis with_values = analyze(scene, {product::modes});
    REQUIRE(with_values.modes);
    REQUIRE(with_values.numeric);
    REQUIRE(with_values.numeric->size() == 1);
    const numeric_modes& point = with_values.numeric->at(0);
    CHECK(point.modes.cols() == 3);
    GiNaC::exmap at;
    for (const auto& [name, value] : point.values)
        for (const parameter& p : scene.parameters)
            if (p.name == name)
                at[p.symbol] = value;
    for (int k = 0; k < 3; ++k) {
        const double w2 = GiNaC::ex_to<GiNaC::numeric>(with_values.modes->frequencies[k].subs(at).evalf()).to_double();
        CHECK_THAT(point.omega_squared[k], Catch::Matchers::WithinRel(w2, 1e-10));
    }
    REQUIRE(with_values.notes.size() == 1);
    CHECK_THAT(with_values.notes[0], Catch::Matchers::Contains("given numerically at the `values` points"));
    // `asymptotic` needs the vectors: it says so.
    model limited = load(chain_scene(3) + "equilibrium q1 = 0, q2 = 0, q3 = 0\nratio rho = m3/m2\nlimit rho -> 0\n");
    CHECK_THROWS_WITH(analyze(limited, {product::asymptotic}),
                      Catch::Matchers::Contains("not computed in closed form for the roots of an irreducible cubic"));
}

TEST_CASE("modes: roots of different factors come out ascending, compared through their surds", "[scaling]")
{
    // Three equal masses on springs k, 2k, 3k: m³W³ − 11km²W² + 26k²mW − 6k³ = (mW − 3k)(m²W² − 8kmW + 2k²)
    // (expanded by hand), so ω² = (4 − √14)k/m < 3k/m < (4 + √14)k/m: a linear factor's root
    // between a quadratic's two.
    model scene = load("parameters m k\ncoordinates x1 x2 x3\npoint A mass m at (x1, 0)\n"
                       "point B mass m at (x2, 0)\npoint C mass m at (x3, 0)\n"
                       "V = 1/2*k*x1^2 + k*(x2 - x1)^2 + 3/2*k*(x3 - x2)^2\n");
    analysis a = analyze(scene, {product::frequencies});
    REQUIRE(a.modes);
    REQUIRE(a.modes->frequencies.size() == 3);
    GiNaC::exmap at;
    for (const parameter& p : scene.parameters)
        at[p.symbol] = 1;
    const std::vector<double> expected{4 - std::sqrt(14.0), 3, 4 + std::sqrt(14.0)};
    for (int k = 0; k < 3; ++k) {
        const double w2 = GiNaC::ex_to<GiNaC::numeric>(a.modes->frequencies[k].subs(at).evalf()).to_double();
        CHECK_THAT(w2, Catch::Matchers::WithinRel(expected[k], 1e-12));
    }
}

TEST_CASE("scaling: a share of the budget ends before the stage's own deadline", "[scaling][budget]")
{
    CHECK_NOTHROW(budget_share(0.5)); // no budget open: nothing
    budget_limits limits;
    limits.max_seconds = 1000;
    budget_scope scope("characteristic", limits);
    {
        budget_share none(0.0);
        CHECK_THROWS_AS(budget_check(), budget_exceeded);
        CHECK(budget_stage() == "characteristic");
    }
    CHECK_NOTHROW(budget_check());
    {
        budget_share half(0.5);
        CHECK_NOTHROW(budget_check());
    }
}

// Past the budget the run degrades: the frequencies come numerically at the `values`
// points with a note, instead of nothing. The size budget trips deterministically.
TEST_CASE("degrade: frequencies over the budget are given numerically at the values", "[scaling][budget]")
{
    model scene = load(chain_with_values(4));
    budget_limits limits;
    limits.max_terms = 50;
    analysis a = analyze(scene, {product::frequencies}, limits);
    CHECK_FALSE(a.characteristic);
    CHECK_FALSE(a.modes);
    REQUIRE(a.numeric);
    REQUIRE(a.numeric->size() == 1);
    CHECK(a.wanted.count(product::numeric));
    REQUIRE(a.notes.size() == 1);
    CHECK_THAT(a.notes[0], Catch::Matchers::Contains("exceeded its size budget") &&
                               Catch::Matchers::Contains("given numerically at the `values` points"));
    // the same frequencies as the numeric modes asked for directly (an LU-free reference:
    // the sum of ω² is the trace of T⁻¹V, checked for the chain in test_reliability)
    analysis direct = analyze(scene, {product::numeric}, limits);
    REQUIRE(direct.numeric);
    CHECK(direct.numeric->at(0).omega_squared == a.numeric->at(0).omega_squared);
    // with no values there is nothing to give: the budget error, as before
    model bare = load(chain_scene(4) + "equilibrium q1 = 0, q2 = 0, q3 = 0, q4 = 0\n");
    CHECK_THROWS_AS(analyze(bare, {product::frequencies}, limits), budget_exceeded);
}

TEST_CASE("degrade: frequencies without a closed form are given numerically at the values", "[scaling]")
{
    model scene = load(chain_with_values(5)); // a quintic in ω² that does not factor
    analysis a = analyze(scene, {product::frequencies});
    REQUIRE(a.modes);
    CHECK_FALSE(a.modes->closed_form);
    REQUIRE(a.numeric);
    CHECK(a.numeric->at(0).omega_squared.size() == 5);
    REQUIRE(a.notes.size() == 1);
    CHECK_THAT(a.notes[0], Catch::Matchers::Contains("no closed form"));
    // the numeric ω² are roots of the characteristic polynomial at the values point
    GiNaC::exmap at = value_map(scene, scene.values.front());
    const GiNaC::ex omega = a.characteristic->omega;
    const GiNaC::ex p = a.characteristic->polynomial.expand().subs(at);
    for (double w2 : a.numeric->at(0).omega_squared) {
        GiNaC::ex value = 0, scale = 0;
        for (int k = 0; k <= 5; ++k) {
            const double c = GiNaC::ex_to<GiNaC::numeric>(p.coeff(omega, 2 * k).evalf()).to_double();
            value += c * std::pow(w2, k);
            scale += std::abs(c) * std::pow(w2, k);
        }
        CHECK(std::abs(GiNaC::ex_to<GiNaC::numeric>(value).to_double()) <=
              1e-9 * GiNaC::ex_to<GiNaC::numeric>(scale).to_double());
    }
}

TEST_CASE("degrade: the command line prints what it computed and exits 0", "[scaling][budget][cli]")
{
    const std::string scene = temporary_file("chain4v.lag", chain_with_values(4));
    cli_result r = run_cli(scene + " --want frequencies --max-terms 50");
    CHECK(r.exit_code == 0);
    CHECK(r.out.find("Numeric modes") != std::string::npos);
    CHECK(r.out.find("given numerically at the `values` points") != std::string::npos);
    cli_result json = run_cli(scene + " --want frequencies --max-terms 50 --format json");
    CHECK(json.exit_code == 0);
    CHECK(json.out.find("\"numeric\"") != std::string::npos);
    CHECK(json.out.find("\"notes\"") != std::string::npos);
    // nothing to fall back on without values: exit 1 with the budget's message
    const std::string bare = temporary_file("chain4.lag", chain_scene(4) + "equilibrium q1 = 0, q2 = 0, q3 = 0, q4 = 0\n");
    cli_result none = run_cli(bare + " --want frequencies --max-terms 50");
    CHECK(none.exit_code == 1);
    CHECK(none.err.find("exceeded its size budget") != std::string::npos);
}
