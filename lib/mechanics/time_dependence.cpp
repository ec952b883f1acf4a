// SPDX-License-Identifier: GPL-2.0-or-later
/** @file time_dependence.cpp
 *  Explicit time in L: the decision whether L depends on t, the points that solve the
 *  equations at every t, the proof that none does, and the linearization about such a
 *  point. */
#include "mechanics/time_dependence.h"

#include "algebra/budget.h"
#include "algebra/calculus.h"
#include "algebra/expression.h"
#include "algebra/sorted_terms.h"
#include "algebra/sign.h"
#include "algebra/trig_canonical.h"
#include "core/errors.h"
#include "mechanics/equilibrium.h"
#include "mechanics/equilibrium_candidates.h"

#include <functional>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>

namespace lagrange {

namespace {

using GiNaC::ex;
using GiNaC::exvector;

/// The most angle coordinates whose combinations of 0 and π are tried.
constexpr std::size_t max_tried_angles = 8;

/// +1 or −1: the sign of the numeric factor of the term of the sum `a` whose other
/// factors print first. a and −a get opposite signs, so sin(−ωt) is written −sin(ωt).
int orientation(const ex& a)
{
    std::string first;
    int sign = 1;
    for (const ex& term : terms_of(a.expand())) {
        GiNaC::numeric coefficient = 1;
        exvector rest;
        for (const ex& factor : factors_of(term)) {
            if (ex_kind_of(factor) == ex_kind::number)
                coefficient *= GiNaC::ex_to<GiNaC::numeric>(factor);
            else
                rest.push_back(factor);
        }
        std::ostringstream text;
        text << product_of(rest);
        if (first.empty() || text.str() < first) {
            first = text.str();
            sign = coefficient.is_negative() ? -1 : 1;
        }
    }
    return sign;
}

/// e with every sine and cosine whose argument mixes t with other terms split by the
/// addition formulas, cos(a(t) + b) = cos a cos b − sin a sin b, so that each
/// argument either contains t only through its t-part or not at all.
ex separate_time_arguments(const ex& e, const ex& time)
{
    if (e.nops() == 0 || !e.has(time))
        return e;
    map_each recurse([&](const ex& x) { return separate_time_arguments(x, time); });
    const ex mapped = e.map(recurse);
    if (!is_sin_or_cos(mapped))
        return mapped;
    exvector timed, other;
    for (const ex& term : terms_of(mapped.op(0).expand()))
        (term.has(time) ? timed : other).push_back(term);
    if (timed.empty())
        return mapped;
    // cos(a + b), sin(a + b) with a = sign·ω(t), written in sin ω, cos ω.
    const int sign = orientation(sum_of(timed));
    const ex omega = (sign * sum_of(timed)).expand(), b = sum_of(other);
    const ex cos_a = GiNaC::cos(omega), sin_a = sign * GiNaC::sin(omega);
    if (GiNaC::is_the_function<GiNaC::cos_SERIAL>(mapped))
        return cos_a * GiNaC::cos(b) - sin_a * GiNaC::sin(b);
    return sin_a * GiNaC::cos(b) + cos_a * GiNaC::sin(b);
}

/// True if `part` (a product of factors that contain t) is t^k times at most one sine or
/// cosine of ω·t with ω free of t: such functions of t are linearly independent.
bool is_basis_function(const ex& part, const ex& time)
{
    int waves = 0;
    for (const ex& factor : factors_of(part)) {
        if (factor.is_equal(time) || ex_kind_of(factor) == ex_kind::number)
            continue;
        if (ex_kind_of(factor) == ex_kind::power && factor.op(0).is_equal(time) &&
            factor.op(1).info(GiNaC::info_flags::posint))
            continue;
        if (!is_sin_or_cos(factor) || ++waves > 1)
            return false;
        const ex argument = factor.op(0).expand();
        if (argument.degree(time) != 1 || argument.ldegree(time) != 1 || argument.coeff(time, 1).has(time) ||
            orientation(argument) < 0)
            return false;
    }
    return true;
}

/// The equations at rest split by their dependence on t: F(q, t) = Σ_k c_k(q) φ_k(t),
/// so F vanishes at every t where every c_k does.
struct time_parts {
    std::vector<ex> coefficients; ///< the nonzero c_k, in canonical form
    bool independent = true;      ///< the φ_k are linearly independent: F ≡ 0 only if every c_k = 0
};

time_parts split_by_time(const std::vector<ex>& equations, const ex& time, const simplifier& simplify)
{
    time_parts parts;
    for (const ex& equation : equations) {
        std::map<ex, exvector, GiNaC::ex_is_less> by_function;
        const ex separated = separate_time_arguments(simplify.canonical(equation), time).expand();
        for (const ex& term : terms_of(separated)) {
            exvector timed, other;
            for (const ex& factor : factors_of(term))
                (factor.has(time) ? timed : other).push_back(factor);
            by_function[product_of(timed)].push_back(product_of(other));
        }
        for (const auto& [function, terms] : by_function) {
            const ex coefficient = simplify.canonical(sum_of(terms));
            if (vanishes(coefficient))
                continue;
            parts.independent = parts.independent && is_basis_function(function, time);
            parts.coefficients.push_back(coefficient);
        }
    }
    return parts;
}

bool solves_all(const model& scene, const std::vector<ex>& coefficients, const std::vector<ex>& point,
                const simplifier& simplify)
{
    for (const ex& c : coefficients)
        if (!vanishes(simplify.canonical(evaluate_at(c, scene, point))))
            return false;
    return true;
}

/// Candidate points (equilibrium_candidates.h) that solve every coefficient equation.
std::vector<std::vector<ex>> find_points(const model& scene, const std::vector<ex>& coefficients,
                                         const simplifier& simplify)
{
    const angle_split split = split_angles(scene, coefficients);
    if (split.angles.size() > max_tried_angles)
        return {};
    return points_at_angle_choices(scene, coefficients, split, [&](const std::vector<ex>& point) {
        return solves_all(scene, coefficients, point, simplify);
    });
}

/// True if it is proven that the equations `coefficients` (each depending on the one
/// coordinate q) have no common real root: for an angle, the resultants with
/// sin² q + cos² q − 1 have no common factor in cos q; otherwise the numerators have
/// no common factor in q. Parameters are taken generic (positive, independent).
bool no_common_root(const std::vector<ex>& coefficients, const ex& q)
{
    try {
        GiNaC::exmap atoms;
        const GiNaC::realsymbol s("s"), c("c");
        std::optional<ex> common;
        bool angle = false;
        for (const ex& e : coefficients)
            angle = angle || inside_trigonometric(e, q);
        for (const ex& e : coefficients) {
            ex polynomial;
            ex variable = q;
            if (angle) {
                std::optional<ex> p = trigonometric_polynomial(e, q, s, c);
                if (!p)
                    return false;
                const ex numerator = p->normal().numer().to_polynomial(atoms);
                polynomial = GiNaC::resultant(numerator, s * s + c * c - 1, s).expand();
                variable = c;
            } else {
                polynomial = e.normal().numer().to_polynomial(atoms);
                if (!polynomial.is_polynomial(q))
                    return false;
            }
            if (polynomial.is_zero())
                return false;
            common = common ? GiNaC::gcd(*common, polynomial) : polynomial;
            if (common->degree(variable) == 0)
                return true;
        }
    } catch (const budget_exceeded&) {
        throw;
    } catch (const std::exception&) {
    }
    return false;
}

/// True if some coordinate's own equations (those that depend on it alone) have no
/// common root: then no point solves them all.
bool proven_unsolvable(const model& scene, const std::vector<ex>& coefficients)
{
    for (const coordinate& q : scene.coordinates) {
        std::vector<ex> own;
        for (const ex& c : coefficients) {
            bool only_q = true;
            for (const coordinate& other : scene.coordinates)
                only_q = only_q && (other.name == q.name || !c.has(other.position));
            if (only_q)
                own.push_back(c);
        }
        for (const ex& c : own)
            if (!c.has(q.position))
                return true; // a nonzero constant equation
        if (!own.empty() && no_common_root(own, q.position))
            return true;
    }
    return false;
}

bool mentions(const ex& e, const ex& time) { return e.has(time); }

bool mentions(const std::vector<ex>& v, const ex& time)
{
    for (const ex& e : v)
        if (e.has(time))
            return true;
    return false;
}

void collect_frequencies(const ex& e, const GiNaC::symbol& time, std::vector<ex>& found)
{
    if (!e.has(time))
        return;
    if (e.is_equal(time))
        throw computation_error("L is not periodic in t: t appears outside the argument of a sine or cosine");
    if (is_sin_or_cos(e)) {
        const ex argument = e.op(0).expand();
        const ex omega = argument.coeff(time, 1);
        if (argument.degree(time) != 1 || argument.ldegree(time) > 1 || omega.has(time) ||
            (argument - omega * time).expand().has(time))
            throw computation_error("L is not periodic in t: the argument " + message_text(argument) +
                                    " of a sine or cosine is not linear in t");
        for (const ex& known : found)
            if (vanishes(known - omega) || vanishes(known + omega))
                return;
        found.push_back(omega);
        return;
    }
    if (ex_kind_of(e) == ex_kind::function && !is_sin_or_cos(e))
        throw computation_error("L is not periodic in t: t appears in " + message_text(e));
    for (std::size_t i = 0; i < e.nops(); ++i)
        collect_frequencies(e.op(i), time, found);
}

} // namespace

bool mentions_time(const model& scene)
{
    const ex& t = scene.time;
    if (mentions(scene.kinetic_terms, t) || mentions(scene.potential_terms, t) ||
        (scene.lagrangian_terms && mentions(*scene.lagrangian_terms, t)))
        return true;
    for (const point_mass& p : scene.points)
        if (mentions(p.position, t) || mentions(p.mass, t))
            return true;
    for (const spring& s : scene.springs)
        if (mentions(s.end_a, t) || mentions(s.end_b, t) || mentions(s.stiffness, t) || mentions(s.rest_length, t))
            return true;
    for (const rigid_body& b : scene.bodies)
        if ((b.position && mentions(*b.position, t)) || (b.orientation && mentions(*b.orientation, t)))
            return true;
    return false;
}

time_dependence_result analyze_time_dependence(const model& scene, const lagrangian_result& lagrangian,
                                               const equations_of_motion& equations, const simplifier& simplify)
{
    time_dependence_result result;
    result.depends_on_time = lagrangian.lagrangian_canonical.has(scene.time);
    if (!result.depends_on_time)
        return result;
    GiNaC::exmap at_rest;
    for (const coordinate& c : scene.coordinates)
        at_rest[c.velocity] = 0;
    std::vector<ex> rest_equations;
    for (const ex& f : equations.forcing)
        rest_equations.push_back(f.subs(at_rest));
    const time_parts parts = split_by_time(rest_equations, scene.time, simplify);
    if (scene.equilibrium) {
        const std::vector<ex>& at = *scene.equilibrium;
        for (std::size_t i = 0; i < rest_equations.size(); ++i) {
            const ex residual = simplify.canonical(evaluate_at(rest_equations[i], scene, at));
            if (!vanishes(residual))
                throw computation_error("the equilibrium given does not solve the equations at every t: the "
                                        "equation of " + scene.coordinates[i].name + " leaves " +
                                        message_text(residual) + " there, not 0");
        }
        result.given = true;
        result.points.push_back(at);
        return result;
    }
    result.points = find_points(scene, parts.coefficients, simplify);
    if (!result.points.empty())
        return result;
    if (parts.independent && proven_unsolvable(scene, parts.coefficients))
        throw computation_error("no equilibrium: L depends on t and no point solves the equations at all t");
    throw computation_error("L depends on t and no point that solves the equations at every t was found; "
                            "give one with an `equilibrium` line");
}

periodic_linearization linearize_about(const model& scene, const equations_of_motion& equations,
                                       const std::vector<ex>& point)
{
    const auto n = static_cast<unsigned>(scene.coordinates.size());
    periodic_linearization result{GiNaC::matrix(n, n), GiNaC::matrix(n, n), GiNaC::matrix(n, n)};
    for (unsigned i = 0; i < n; ++i) {
        for (unsigned j = 0; j < n; ++j) {
            const coordinate& c = scene.coordinates[j];
            result.mass(i, j) = evaluate_at(equations.mass(i, j), scene, point);
            result.stiffness(i, j) = evaluate_at(differentiate(equations.forcing[i], c.position), scene, point);
            result.velocity(i, j) = evaluate_at(differentiate(equations.forcing[i], c.velocity), scene, point);
        }
    }
    return result;
}

std::vector<ex> time_frequencies(const ex& e, const GiNaC::symbol& time)
{
    std::vector<ex> found;
    collect_frequencies(e, time, found);
    return found;
}

} // namespace lagrange
