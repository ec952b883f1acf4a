/** @file equilibrium.cpp
 *  The equilibria of V: ∂V/∂q = 0 solved in closed form (one coordinate: a
 *  polynomial or a trigonometric polynomial; several: angles at 0 or π and a
 *  linear system for the rest), and the stability of each from its Hessian. */
#include "mechanics/equilibrium.h"

#include "algebra/budget.h"
#include "algebra/calculus.h"
#include "algebra/exact_matrix.h"
#include "algebra/expression.h"
#include "algebra/factor.h"
#include "algebra/message_text.h"
#include "algebra/sign.h"
#include "core/errors.h"

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <optional>

namespace lagrange {

std::string to_string(stability s)
{
    switch (s) {
    case stability::stable: return "stable";
    case stability::unstable: return "unstable";
    case stability::marginal: return "marginal";
    case stability::unknown: return "unknown";
    }
    return "unknown";
}

namespace {

using GiNaC::ex;
using GiNaC::ex_to;
using GiNaC::exvector;
using GiNaC::is_a;

/// The most angle coordinates whose combinations of 0 and π are tried as equilibria.
constexpr std::size_t max_enumerated_angles = 10;

/// sin and cos of integer combinations of the coordinates (plus a constant) written
/// through sin q and cos q of each coordinate: cos(n q + c) = Re((cos q + i sin q)ⁿ e^{ic}).
/// Then a value such as q = acos(x) substitutes to exact roots (sin(2 acos x) would not).
ex expand_multiple_angles(const ex& e, const model& scene)
{
    if (e.nops() == 0)
        return e;
    map_each recurse([&](const ex& x) { return expand_multiple_angles(x, scene); });
    ex mapped = e.map(recurse);
    bool is_sin = GiNaC::is_the_function<GiNaC::sin_SERIAL>(mapped),
         is_cos = GiNaC::is_the_function<GiNaC::cos_SERIAL>(mapped);
    if (!is_sin && !is_cos)
        return mapped;
    ex argument = mapped.op(0).expand();
    GiNaC::symbol i("i");
    ex z = 1, rest = argument;
    for (const coordinate& c : scene.coordinates) {
        ex n = argument.coeff(c.position, 1);
        if (argument.degree(c.position) > 1 || !n.info(GiNaC::info_flags::integer))
            return mapped;
        long k = ex_to<GiNaC::numeric>(n).to_long();
        if (k == 0)
            continue;
        if (std::labs(k) > 20)
            return mapped;
        z *= GiNaC::pow(GiNaC::cos(c.position) + (k > 0 ? 1 : -1) * i * GiNaC::sin(c.position), std::labs(k));
        rest -= n * c.position;
    }
    if (z.is_equal(1))
        return mapped;
    z = (z * (GiNaC::cos(rest) + i * GiNaC::sin(rest))).expand();
    ex real = 0, imaginary = 0;
    for (int k = 0; k <= z.degree(i); ++k) {
        ex term = z.coeff(i, k) * (k % 4 < 2 ? 1 : -1);
        (k % 2 == 0 ? real : imaginary) += term;
    }
    return is_cos ? real : imaginary;
}

/// The real roots of ∂V/∂q = 0 in one coordinate, where they can be found in closed form.
std::vector<ex> solve_one(const ex& gradient, const GiNaC::symbol& q)
{
    std::vector<ex> roots;
    ex g = gradient.expand();
    if (g.is_zero())
        return {ex(0)};
    bool trigonometric = false;
    for (GiNaC::const_preorder_iterator i = g.preorder_begin(); i != g.preorder_end(); ++i)
        if (is_a<GiNaC::function>(*i) && i->has(q))
            trigonometric = true;
    auto add_root = [&](const ex& value) {
        for (const ex& known : roots)
            if (vanishes(known - value))
                return;
        roots.push_back(value);
    };
    if (!trigonometric) {
        if (!g.info(GiNaC::info_flags::polynomial))
            return {};
        ex factored = factor_if_quick(g);
        exvector factors = is_a<GiNaC::mul>(factored) ? exvector(factored.begin(), factored.end()) : exvector{factored};
        for (ex factor : factors) {
            if (is_a<GiNaC::power>(factor))
                factor = factor.op(0);
            if (factor.degree(q) == 1)
                add_root(tidy(-factor.coeff(q, 0) / factor.coeff(q, 1)));
        }
        return roots;
    }
    // Write the gradient as a polynomial in s = sin q, c = cos q, then as A(c) + s B(c).
    GiNaC::realsymbol s("s"), c("c");
    bool representable = true;
    std::function<ex(const ex&)> to_polynomial = [&](const ex& e) -> ex {
        if (is_a<GiNaC::function>(e) && e.has(q)) {
            std::string name = ex_to<GiNaC::function>(e).get_name();
            ex argument = e.op(0).expand();
            ex k = argument.coeff(q, 1);
            ex rest = (argument - k * q).expand();
            if ((name != "sin" && name != "cos") || rest.has(q) || !k.info(GiNaC::info_flags::integer)) {
                representable = false;
                return e;
            }
            long n = ex_to<GiNaC::numeric>(k).to_long();
            ex multiple = GiNaC::pow(c + GiNaC::I * s, n < 0 ? -n : n).expand();
            ex cos_n = multiple.real_part().expand();
            ex sin_n = ((n < 0 ? -1 : 1) * multiple.imag_part()).expand();
            // sin(nq + b) = sin nq cos b + cos nq sin b, cos(nq + b) = cos nq cos b − sin nq sin b
            if (name == "sin")
                return sin_n * GiNaC::cos(rest) + cos_n * GiNaC::sin(rest);
            return cos_n * GiNaC::cos(rest) - sin_n * GiNaC::sin(rest);
        }
        if (e.nops() == 0)
            return e;
        map_each recurse(to_polynomial);
        return e.map(recurse);
    };
    ex p = to_polynomial(g).expand();
    if (!representable || p.has(q))
        return {};
    ex a = 0, b = 0;
    for (int k = 0; k <= p.degree(s); ++k) {
        ex part = p.coeff(s, k) * GiNaC::pow(1 - c * c, k / 2);
        (k % 2 == 0 ? a : b) += part;
    }
    a = a.expand();
    b = b.expand();
    auto roots_in_cos = [&](const ex& polynomial) {
        ex factored = factor_if_quick(polynomial);
        exvector factors = is_a<GiNaC::mul>(factored) ? exvector(factored.begin(), factored.end()) : exvector{factored};
        for (ex factor : factors) {
            if (is_a<GiNaC::power>(factor))
                factor = factor.op(0);
            if (factor.degree(c) != 1)
                continue;
            ex value = tidy(-factor.coeff(c, 0) / factor.coeff(c, 1));
            if (vanishes(value - 1))
                add_root(0);
            else if (vanishes(value + 1))
                add_root(GiNaC::Pi);
            else if (is_a<GiNaC::numeric>(value) && GiNaC::abs(ex_to<GiNaC::numeric>(value)) > 1)
                continue;
            else
                add_root(GiNaC::acos(value));
        }
    };
    if (a.is_zero()) {
        add_root(0);
        add_root(GiNaC::Pi);
        if (!b.is_zero())
            roots_in_cos(b);
    } else if (b.is_zero()) {
        roots_in_cos(a);
    } else {
        for (const ex& candidate : {ex(0), ex(GiNaC::Pi)})
            if (vanishes(gradient.subs(q == candidate)))
                add_root(candidate);
    }
    return roots;
}

/// True if e contains a sine, cosine or tangent of an argument containing q.
bool inside_trigonometric(const ex& e, const ex& q)
{
    for (GiNaC::const_preorder_iterator i = e.preorder_begin(); i != e.preorder_end(); ++i)
        if (is_a<GiNaC::function>(*i) && i->has(q))
            return true;
    return false;
}

/// The solutions of ∂V/∂q = 0 for several coordinates: each angle coordinate at
/// 0 or π, the others from a linear system (free directions set to 0).
std::vector<std::vector<ex>> solve_several(const model& scene, const std::vector<ex>& gradient)
{
    std::size_t n = scene.coordinates.size();
    std::vector<std::size_t> angles, others;
    for (std::size_t i = 0; i < n; ++i) {
        bool angle = false;
        for (const ex& g : gradient)
            angle = angle || inside_trigonometric(g, scene.coordinates[i].position);
        (angle ? angles : others).push_back(i);
    }
    if (angles.size() > max_enumerated_angles)
        angles.resize(max_enumerated_angles); // the rest stay as unknowns and fail below
    std::vector<std::vector<ex>> points;
    for (unsigned long choice = 0; choice < (1UL << angles.size()); ++choice) {
        GiNaC::exmap fixed;
        for (std::size_t a = 0; a < angles.size(); ++a)
            fixed[scene.coordinates[angles[a]].position] = (choice >> a & 1) ? ex(GiNaC::Pi) : ex(0);
        GiNaC::lst equations, unknowns;
        for (std::size_t i : others)
            unknowns.append(scene.coordinates[i].position);
        bool linear = true;
        for (const ex& g : gradient) {
            ex reduced = g.subs(fixed).expand();
            if (reduced.is_zero())
                continue;
            for (const ex& u : unknowns)
                linear = linear && reduced.degree(u) <= 1 && !inside_trigonometric(reduced, u);
            equations.append(reduced == 0);
        }
        std::vector<ex> point(n, 0);
        for (const auto& [coordinate, value] : fixed)
            for (std::size_t i = 0; i < n; ++i)
                if (ex(scene.coordinates[i].position).is_equal(coordinate))
                    point[i] = value;
        if (equations.nops() > 0) {
            if (unknowns.nops() == 0 || !linear)
                continue;
            ex solution;
            try {
                solution = GiNaC::lsolve(equations, unknowns);
            } catch (const budget_exceeded&) {
                throw; // out of budget: the stage stops, no fallback
            } catch (const std::exception&) {
                continue;
            }
            if (solution.nops() == 0)
                continue;
            GiNaC::exmap free_to_zero;
            for (const ex& u : unknowns)
                free_to_zero[u] = 0;
            for (const ex& equation : solution)
                for (std::size_t i : others)
                    if (equation.lhs().is_equal(scene.coordinates[i].position))
                        point[i] = tidy(equation.rhs().subs(free_to_zero));
        }
        bool solves = true;
        for (const ex& g : gradient)
            solves = solves && vanishes(evaluate_at(g, scene, point));
        if (solves)
            points.push_back(point);
    }
    return points;
}

/// Stability from the Hessian H of V: the roots of det(λ − H) are real, and by
/// Descartes' rule they are all ≥ 0 iff the coefficients alternate in sign.
stability classify(const GiNaC::matrix& hessian)
{
    std::size_t n = hessian.rows();
    // A diagonal Hessian (a chain about its rest position): the eigenvalues are the
    // diagonal entries, no determinant needed.
    bool diagonal = true;
    for (std::size_t i = 0; i < n && diagonal; ++i)
        for (std::size_t j = 0; j < n && diagonal; ++j)
            if (i != j && !vanishes(hessian(i, j)))
                diagonal = false;
    if (diagonal) {
        bool zero = false, unknown = false;
        for (std::size_t i = 0; i < n; ++i) {
            std::optional<int> sign = sign_of(hessian(i, i));
            if (!sign)
                unknown = true;
            else if (*sign < 0)
                return stability::unstable;
            else if (*sign == 0)
                zero = true;
        }
        return unknown ? stability::unknown : zero ? stability::marginal : stability::stable;
    }
    GiNaC::symbol lambda("lambda");
    GiNaC::matrix shifted(n, n);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j)
            shifted(i, j) = (i == j ? lambda : ex(0)) - hessian(i, j);
    ex polynomial;
    try {
        polynomial = fraction_free_determinant(shifted).expand();
    } catch (const budget_exceeded&) {
        return stability::unknown; // too large to decide symbolically: the equilibrium is still usable
    }
    bool zero_root = false, all_decided = true, negative_root = false;
    bool lowest_found = false;
    for (std::size_t k = 0; k <= n; ++k) {
        ex coefficient = polynomial.coeff(lambda, static_cast<int>(k));
        std::optional<int> sign = sign_of(coefficient);
        int expected = ((n - k) % 2 == 0) ? 1 : -1;
        if (!lowest_found) {
            if (sign && *sign == 0) {
                zero_root = true;
                continue;
            }
            if (!sign) {
                all_decided = false;
                lowest_found = true;
                continue;
            }
            lowest_found = true;
        }
        if (!sign) {
            all_decided = false;
            continue;
        }
        if (*sign != 0 && *sign != expected)
            negative_root = true;
        if (*sign == 0)
            all_decided = false; // a zero coefficient above the lowest: the signs do not decide
    }
    if (negative_root)
        return stability::unstable;
    if (!all_decided)
        return stability::unknown;
    return zero_root ? stability::marginal : stability::stable;
}

} // namespace

ex evaluate_at(const ex& e, const model& scene, const std::vector<ex>& at)
{
    bool special = false; // a value other than a rational multiple of π
    for (const ex& value : at)
        special = special || !(value / GiNaC::Pi).info(GiNaC::info_flags::rational);
    if (special) {
        GiNaC::exmap values;
        for (std::size_t i = 0; i < scene.coordinates.size(); ++i) {
            values[scene.coordinates[i].position] = at[i];
            values[scene.coordinates[i].velocity] = 0;
        }
        return expand_multiple_angles(e, scene).subs(values);
    }
    GiNaC::exmap values;
    for (std::size_t i = 0; i < scene.coordinates.size(); ++i) {
        values[scene.coordinates[i].position] = at[i];
        values[scene.coordinates[i].velocity] = 0;
    }
    return e.subs(values);
}

GiNaC::matrix potential_hessian(const model& scene, const ex& potential, const std::vector<ex>& at)
{
    std::size_t n = scene.coordinates.size();
    GiNaC::matrix hessian(n, n);
    for (std::size_t i = 0; i < n; ++i) {
        ex first = differentiate(potential, scene.coordinates[i].position);
        for (std::size_t j = i; j < n; ++j) {
            ex entry = tidy(evaluate_at(differentiate(first, scene.coordinates[j].position), scene, at));
            hessian(i, j) = entry;
            hessian(j, i) = entry;
        }
    }
    return hessian;
}

equilibria_result find_equilibria(const model& scene, const lagrangian_result& lagrangian, const simplifier& simplify)
{
    std::size_t n = scene.coordinates.size();
    ex potential = simplify.canonical(lagrangian.potential);
    std::vector<ex> gradient;
    for (const coordinate& c : scene.coordinates)
        gradient.push_back(differentiate(potential, c.position));
    equilibria_result result;
    if (scene.equilibrium) {
        const std::vector<ex>& at = *scene.equilibrium;
        for (std::size_t i = 0; i < n; ++i) {
            ex slope = evaluate_at(gradient[i], scene, at);
            if (!vanishes(simplify.canonical(slope)))
                throw computation_error("the equilibrium given is not one: ∂V/∂" + scene.coordinates[i].name + " = " +
                                        message_text(slope.expand()) + " there, not 0");
        }
        result.given = true;
        result.points.push_back({at, stability::unknown});
    } else {
        std::vector<std::vector<ex>> points;
        if (n == 1) {
            for (const ex& root : solve_one(gradient[0], scene.coordinates[0].position))
                points.push_back({root});
        } else {
            points = solve_several(scene, gradient);
        }
        if (points.empty())
            throw computation_error("no equilibrium found: ∂V/∂q = 0 could not be solved in closed form; "
                                    "give one with an `equilibrium` line");
        for (const std::vector<ex>& point : points)
            result.points.push_back({point, stability::unknown});
    }
    for (equilibrium_point& point : result.points)
        point.kind = classify(potential_hessian(scene, potential, point.position));
    result.chosen = 0;
    for (stability preferred : {stability::stable, stability::marginal, stability::unknown}) {
        auto found = std::find_if(result.points.begin(), result.points.end(),
                                  [&](const equilibrium_point& p) { return p.kind == preferred; });
        if (found != result.points.end()) {
            result.chosen = static_cast<std::size_t>(found - result.points.begin());
            break;
        }
    }
    return result;
}

} // namespace lagrange
