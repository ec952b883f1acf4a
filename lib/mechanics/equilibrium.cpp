// SPDX-License-Identifier: GPL-2.0-or-later
/** @file equilibrium.cpp
 *  The equilibria of V: ∂V/∂q = 0 solved in closed form (one coordinate: a
 *  polynomial or a trigonometric polynomial; several: angles at 0 or π and a
 *  linear system for the rest), and the stability of each from its Hessian. */
#include "mechanics/equilibrium.h"

#include "mechanics/equilibrium_candidates.h"
#include "mechanics/gyroscopic.h"

#include "algebra/budget.h"
#include "algebra/calculus.h"
#include "algebra/exact_matrix.h"
#include "algebra/expression.h"
#include "algebra/factor.h"
#include "algebra/sorted_terms.h"
#include "algebra/sign.h"
#include "core/errors.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <map>
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

/// Above this many angle coordinates the combinations of 0 and π are not listed:
/// the stable equilibrium is looked for directly (2^N points help nobody).
constexpr std::size_t max_listed_angles = 4;

/// e with tangents written as sin/cos and, for every argument u of a sine or cosine,
/// sin² u = 1 − cos² u in numerator and denominator, common factors cancelled. Sines
/// and cosines of different arguments are taken as independent, so the result equals e
/// (and is 0 only where e is 0 identically). e itself where there is nothing to reduce.
/// sin(k·a) and cos(k·a), k an integer (the canonical form writes multiple angles), through
/// sin a and cos a by the binomial expansion of (cos a + i sin a)^k.
struct multiple_angles : GiNaC::map_function {
    ex operator()(const ex& e) override
    {
        const bool is_sin = GiNaC::is_the_function<GiNaC::sin_SERIAL>(e),
                   is_cos = GiNaC::is_the_function<GiNaC::cos_SERIAL>(e);
        if ((!is_sin && !is_cos) || !GiNaC::is_a<GiNaC::mul>(e.op(0)))
            return e.map(*this);
        const ex argument = e.op(0);
        const ex k = argument.op(argument.nops() - 1); // a mul's numeric coefficient is last
        if (!k.info(GiNaC::info_flags::integer) || GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(k)) > 12)
            return e.map(*this);
        const ex a = argument / k;
        const long n = std::labs(GiNaC::ex_to<GiNaC::numeric>(k).to_long());
        const ex c = GiNaC::cos(a), s = GiNaC::sin(a);
        ex sum = 0;
        for (long j = is_sin ? 1 : 0; j <= n; j += 2)
            sum += (((j / 2) % 2) ? -1 : 1) * GiNaC::binomial(n, j) * GiNaC::pow(c, n - j) * GiNaC::pow(s, j);
        return is_sin && k.info(GiNaC::info_flags::negative) ? -sum : sum;
    }
};

} // namespace

ex reduce_trigonometric(const ex& e)
{
    multiple_angles expand_angles;
    ex x = expand_angles(
        e.subs(GiNaC::tan(GiNaC::wild(0)) == GiNaC::sin(GiNaC::wild(0)) / GiNaC::cos(GiNaC::wild(0))));
    // one (sine, cosine) pair of symbols per distinct argument, in order of appearance
    std::vector<std::pair<ex, std::pair<GiNaC::realsymbol, GiNaC::realsymbol>>> arguments;
    GiNaC::exmap to_symbols, back;
    for (GiNaC::const_preorder_iterator i = x.preorder_begin(); i != x.preorder_end(); ++i) {
        bool is_sin = GiNaC::is_the_function<GiNaC::sin_SERIAL>(*i),
             is_cos = GiNaC::is_the_function<GiNaC::cos_SERIAL>(*i);
        if (!is_sin && !is_cos)
            continue;
        ex argument = i->op(0);
        auto known = std::find_if(arguments.begin(), arguments.end(),
                                  [&](const auto& a) { return a.first.is_equal(argument); });
        if (known != arguments.end())
            continue;
        GiNaC::realsymbol sine("S"), cosine("C");
        arguments.push_back({argument, {sine, cosine}});
        to_symbols[GiNaC::sin(argument)] = sine;
        to_symbols[GiNaC::cos(argument)] = cosine;
        back[sine] = GiNaC::sin(argument);
        back[cosine] = GiNaC::cos(argument);
    }
    if (arguments.empty())
        return e;
    ex fraction = x.subs(to_symbols).normal().numer_denom();
    for (const auto& [argument, pair] : arguments)
        if (fraction.has(argument))
            return e; // the argument also outside sin and cos
    auto reduce = [&](ex polynomial) {
        polynomial = polynomial.expand();
        for (const auto& [argument, pair] : arguments) {
            const auto& [sine, cosine] = pair;
            ex reduced = 0;
            for (int k = 0; k <= polynomial.degree(sine); ++k)
                reduced += polynomial.coeff(sine, k) * GiNaC::pow(1 - cosine * cosine, k / 2) *
                           (k % 2 == 0 ? ex(1) : ex(sine));
            polynomial = reduced.expand();
        }
        return polynomial;
    };
    budget_check();
    ex reduced = (reduce(fraction.op(0)) / reduce(fraction.op(1))).normal();
    return reduced.subs(back);
}

namespace {

/// Zero as a function of the coordinates and parameters: the rational test of
/// vanishes(), then after reduce_trigonometric (so that a residual in sin(th0),
/// cos(th0) and tan(th0) of a parameter th0 is recognized as 0).
bool vanishes_identically(const ex& e)
{
    if (vanishes(e))
        return true;
    try {
        return vanishes(reduce_trigonometric(e));
    } catch (const budget_exceeded&) {
        throw; // out of budget: the stage stops, no fallback
    } catch (const std::exception&) {
        return false;
    }
}

/// ∂²V/∂qi∂qj at a point; each entry tidied if asked (for printing), else as it comes
/// (enough to classify, and much faster for a long chain).
GiNaC::matrix hessian_at(const model& scene, const ex& potential, const std::vector<ex>& at, bool tidy_entries);

/// The coordinates whose potential contains √(q²) (a spring's length, as for the
/// elastic pendulum's r), and the potential on the physical branch q > 0, where
/// √(q²) = q.
std::pair<std::vector<bool>, ex> on_positive_branch(const model& scene, const ex& potential)
{
    std::vector<bool> branch(scene.coordinates.size(), false);
    ex result = potential;
    for (std::size_t i = 0; i < scene.coordinates.size(); ++i) {
        const ex q = scene.coordinates[i].position;
        ex replaced = result.subs(GiNaC::pow(GiNaC::pow(q, 2), GiNaC::wild(0)) == GiNaC::pow(q, 2 * GiNaC::wild(0)));
        if (!replaced.is_equal(result)) {
            branch[i] = true;
            result = replaced;
        }
    }
    return {branch, result};
}

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

/// The test of a candidate equilibrium: every component of ∂V/∂q vanishes there.
point_check gradient_vanishes(const model& scene, const std::vector<ex>& gradient)
{
    return [&scene, &gradient](const std::vector<ex>& point) {
        for (const ex& g : gradient)
            if (!vanishes(evaluate_at(g, scene, point)))
                return false;
        return true;
    };
}

/// A stable equilibrium found without listing the 2^N combinations of N angles:
/// when each ∂V/∂q_i depends on q_i alone (a chain in absolute angles), each
/// coordinate at a root where ∂²V/∂q_i² > 0; otherwise every angle at 0, if that is
/// a stable equilibrium (a hanging chain in relative angles). Nothing if neither applies.
std::optional<std::vector<ex>> stable_without_listing(const model& scene, const std::vector<ex>& gradient,
                                                      const std::vector<std::size_t>& others,
                                                      const std::function<stability(const std::vector<ex>&)>& kind_at)
{
    std::size_t n = scene.coordinates.size();
    bool decoupled = true;
    for (std::size_t i = 0; i < n && decoupled; ++i)
        for (std::size_t j = 0; j < n && decoupled; ++j)
            if (i != j && gradient[i].has(scene.coordinates[j].position))
                decoupled = false;
    if (decoupled) {
        std::vector<ex> point(n, 0);
        bool found = true;
        for (std::size_t i = 0; i < n && found; ++i) {
            const GiNaC::symbol& q = scene.coordinates[i].position;
            ex curvature = differentiate(gradient[i], q);
            found = false;
            for (const ex& root : solve_one(gradient[i], q)) {
                point[i] = root;
                if (sign_of(tidy(evaluate_at(curvature, scene, point))) == std::optional<int>(1)) {
                    found = true;
                    break;
                }
            }
        }
        if (found && gradient_vanishes(scene, gradient)(point))
            return point;
        return std::nullopt;
    }
    GiNaC::exmap at_zero;
    for (std::size_t i = 0; i < n; ++i)
        if (std::find(others.begin(), others.end(), i) == others.end())
            at_zero[scene.coordinates[i].position] = 0;
    std::optional<std::vector<ex>> hanging = point_with_angles(scene, gradient, at_zero, others, gradient_vanishes(scene, gradient));
    if (hanging && kind_at(*hanging) == stability::stable)
        return hanging;
    return std::nullopt;
}

/// The solutions of ∂V/∂q = 0 for several coordinates: each angle coordinate at
/// 0 or π, the others from a linear system (free directions set to 0). With more
/// than max_listed_angles angles, only a stable equilibrium where one is found directly.
std::vector<std::vector<ex>> solve_several(const model& scene, const std::vector<ex>& gradient,
                                           const std::function<stability(const std::vector<ex>&)>& kind_at)
{
    const angle_split split = split_angles(scene, gradient);
    if (split.angles.size() > max_listed_angles)
        if (std::optional<std::vector<ex>> stable = stable_without_listing(scene, gradient, split.others, kind_at))
            return {*stable};
    if (split.angles.size() > max_enumerated_angles)
        return {};
    return points_at_angle_choices(scene, gradient, split, gradient_vanishes(scene, gradient));
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

/// Stability decided at the scene's `values` points, for a Hessian whose sign depends
/// on the parameters: the eigenvalues of the Hessian there. Unknown when there are no
/// values, when a parameter has no value, when the point itself is not real there
/// (acos(g/(R w²)) for g > R w²), when an eigenvalue is too close to zero to tell its
/// sign, or when the points disagree.
stability classify_at_values(const model& scene, const GiNaC::matrix& hessian, const std::vector<ex>& position)
{
    if (scene.values.empty())
        return stability::unknown;
    std::size_t n = hessian.rows();
    std::optional<stability> agreed;
    for (const value_point& point : scene.values) {
        const GiNaC::exmap at = value_map(scene, point);
        for (const ex& coordinate : position) {
            ex number;
            try {
                number = coordinate.subs(at).evalf();
            } catch (const std::exception&) {
                return stability::unknown;
            }
            if (!is_a<GiNaC::numeric>(number) || !ex_to<GiNaC::numeric>(number).is_real())
                return stability::unknown; // no such equilibrium at these values
        }
        Eigen::MatrixXd numeric_hessian(n, n);
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < n; ++j) {
                ex entry;
                try {
                    entry = hessian(i, j).subs(at).evalf();
                } catch (const std::exception&) {
                    return stability::unknown;
                }
                if (!is_a<GiNaC::numeric>(entry) || !ex_to<GiNaC::numeric>(entry).is_real())
                    return stability::unknown;
                numeric_hessian(i, j) = ex_to<GiNaC::numeric>(entry).to_double();
            }
        if (!numeric_hessian.allFinite())
            return stability::unknown;
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(numeric_hessian, Eigen::EigenvaluesOnly);
        if (solver.info() != Eigen::Success)
            return stability::unknown;
        const Eigen::VectorXd& eigenvalues = solver.eigenvalues();
        double scale = eigenvalues.cwiseAbs().maxCoeff();
        double tolerance = 1e-9 * scale * static_cast<double>(n);
        if (scale == 0 || eigenvalues.cwiseAbs().minCoeff() <= tolerance)
            return stability::unknown; // a zero eigenvalue cannot be told from rounding here
        stability kind = eigenvalues.minCoeff() < 0 ? stability::unstable : stability::stable;
        if (agreed && *agreed != kind)
            return stability::unknown; // stable at some values, unstable at others
        agreed = kind;
    }
    return *agreed;
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
    return hessian_at(scene, potential, at, true);
}

GiNaC::matrix kinetic_matrix(const model& scene, const ex& kinetic, const std::vector<ex>& at)
{
    const std::size_t n = scene.coordinates.size();
    GiNaC::matrix mass(n, n);
    for (std::size_t i = 0; i < n; ++i) {
        const ex row = differentiate(kinetic, scene.coordinates[i].velocity);
        for (std::size_t j = i; j < n; ++j) {
            const ex entry = tidy(evaluate_at(differentiate(row, scene.coordinates[j].velocity), scene, at));
            mass(i, j) = entry;
            mass(j, i) = entry;
        }
    }
    return mass;
}

namespace {

GiNaC::matrix hessian_at(const model& scene, const ex& potential, const std::vector<ex>& at, bool tidy_entries)
{
    std::size_t n = scene.coordinates.size();
    // near a point where q > 0, √(q²) = q: the Hessian comes out without nested roots
    ex local = potential;
    for (std::size_t i = 0; i < n && i < at.size(); ++i)
        if (sign_of(at[i]) == std::optional<int>(1)) {
            const ex q = scene.coordinates[i].position;
            local = local.subs(GiNaC::pow(GiNaC::pow(q, 2), GiNaC::wild(0)) == GiNaC::pow(q, 2 * GiNaC::wild(0)));
        }
    GiNaC::matrix hessian(n, n);
    for (std::size_t i = 0; i < n; ++i) {
        ex first = differentiate(local, scene.coordinates[i].position);
        for (std::size_t j = i; j < n; ++j) {
            ex second = differentiate(first, scene.coordinates[j].position);
            if (second.is_zero()) { // most entries of a long chain: nothing to evaluate or tidy
                hessian(i, j) = 0;
                hessian(j, i) = 0;
                continue;
            }
            ex entry = evaluate_at(second, scene, at);
            if (tidy_entries)
                entry = tidy(entry);
            if (has_trigonometric(entry)) {
                // at a point given through a parameter (θ = th0): sin² th0 = 1 − cos² th0
                try {
                    entry = reduce_trigonometric(entry);
                    if (tidy_entries)
                        entry = tidy(entry);
                } catch (const budget_exceeded&) {
                    throw; // out of budget: the stage stops, no fallback
                } catch (const std::exception&) {
                }
            }
            hessian(i, j) = entry;
            hessian(j, i) = entry;
        }
    }
    return hessian;
}

} // namespace

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
            // the canonical form may write multiple angles (sin 3θ) that reduce_trigonometric
            // does not take apart: try the slope as it comes too
            if (!vanishes_identically(simplify.canonical(slope)) && !vanishes_identically(slope))
                throw computation_error("the equilibrium given is not one: ∂V/∂" + scene.coordinates[i].name + " = " +
                                        message_text(slope.expand()) + " there, not 0");
        }
        result.given = true;
        GiNaC::matrix hessian = hessian_at(scene, potential, at, false);
        stability kind = classify(hessian);
        result.points.push_back({at, kind == stability::unknown ? classify_at_values(scene, hessian, at) : kind});
    } else {
        // A slope that no coordinate enters cannot vanish anywhere (Atwood's machine).
        for (std::size_t i = 0; i < n; ++i) {
            bool constant = true;
            for (const coordinate& c : scene.coordinates)
                constant = constant && !gradient[i].has(c.position);
            if (constant && !vanishes(gradient[i]))
                throw computation_error("no equilibrium: ∂U/∂" + scene.coordinates[i].name + " = " +
                                        message_text(gradient[i].expand()) + " ≠ 0 everywhere");
        }
        // Spring lengths √(q²): solved on the physical branch q > 0, where √(q²) = q.
        std::pair<std::vector<bool>, ex> on_branch = on_positive_branch(scene, potential);
        const std::vector<bool>& branch = on_branch.first;
        const ex& branch_potential = on_branch.second;
        std::vector<ex> branch_gradient;
        for (const coordinate& c : scene.coordinates)
            branch_gradient.push_back(differentiate(branch_potential, c.position));
        // stability from the Hessian on the branch, else at the `values` points
        auto kind_at = [&](const std::vector<ex>& at) {
            GiNaC::matrix hessian = hessian_at(scene, branch_potential, at, false);
            stability kind = classify(hessian);
            return kind == stability::unknown ? classify_at_values(scene, hessian, at) : kind;
        };
        std::vector<std::vector<ex>> points;
        if (n == 1) {
            for (const ex& root : solve_one(branch_gradient[0], scene.coordinates[0].position))
                points.push_back({root});
        } else {
            points = solve_several(scene, branch_gradient, kind_at);
        }
        if (points.empty() && n > 1) // e.g. roots of ρ² + z²: try each coordinate axis
            points = axis_equilibria(scene, branch_gradient);
        // V as written, where it is the potential: ½ f² keeps its square there
        const ex written = vanishes_identically(lagrangian.potential_built - lagrangian.potential) ? lagrangian.potential_built
                                                                                      : lagrangian.potential;
        for (const std::vector<ex>& point : points) {
            // a set of equilibria (Størmer's V = ½ f²): one point stands for the whole set
            if (result.family && on_family(scene, *result.family, point))
                continue;
            if (!result.family)
                result.family = family_through(scene, written, point);
            bool kept = true;
            for (std::size_t i = 0; i < n && kept; ++i)
                kept = !branch[i] || sign_of(point[i]) == std::optional<int>(1);
            for (std::size_t i = 0; i < n && kept; ++i)
                kept = vanishes_identically(evaluate_at(branch_gradient[i], scene, point));
            if (kept)
                result.points.push_back({point, stability::unknown});
        }
        if (result.points.empty())
            throw computation_error("no equilibrium found: ∂V/∂q = 0 could not be solved in closed form; "
                                    "give one with an `equilibrium` line");
        for (equilibrium_point& point : result.points)
            point.kind = kind_at(point.position);
    }
    if (!lagrangian.gyroscopic.is_zero()) // Kelvin–Tait–Chetaev: G can stabilize a maximum
        for (equilibrium_point& point : result.points)
            point.kind = gyroscopic_stability_at(scene, lagrangian, point.position, point.kind, simplify);
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
