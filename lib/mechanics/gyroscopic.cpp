// SPDX-License-Identifier: GPL-2.0-or-later
/** @file gyroscopic.cpp
 *  The gyroscopic matrix from L1, Kelvin–Tait–Chetaev stability decided by a Sturm
 *  sequence of the characteristic polynomial in w = ω² (symbolically under positive
 *  parameters, else at the `values` points in exact rationals), and the frequencies ω in
 *  closed form. */
#include "mechanics/gyroscopic.h"

#include "algebra/calculus.h"
#include "algebra/exact_matrix.h"
#include "algebra/factor.h"
#include "algebra/sorted_terms.h"
#include "algebra/sign.h"
#include "algebra/surd.h"

#include <cln/cln.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

namespace lagrange {

namespace {

using GiNaC::ex;

/// A polynomial in one variable as its coefficients, lowest degree first.
using polynomial = std::vector<ex>;
/// The sign of a coefficient, if it can be decided.
using sign_oracle = std::function<std::optional<int>(const ex&)>;

void trim(polynomial& p)
{
    while (!p.empty() && vanishes(p.back()))
        p.pop_back();
}

/// The remainder of a divided by b (b trimmed, not empty).
polynomial remainder(polynomial a, const polynomial& b)
{
    trim(a);
    while (!a.empty() && a.size() >= b.size()) {
        ex factor = (a.back() / b.back()).normal();
        std::size_t shift = a.size() - b.size();
        for (std::size_t k = 0; k + 1 < b.size(); ++k)
            a[k + shift] = (a[k + shift] - factor * b[k]).normal();
        a.pop_back();
        trim(a);
    }
    return a;
}

/// Sign changes in a sequence of signs (zeros skipped).
int sign_changes(const std::vector<int>& signs)
{
    int changes = 0, last = 0;
    for (int s : signs) {
        if (s == 0)
            continue;
        if (last != 0 && s != last)
            ++changes;
        last = s;
    }
    return changes;
}

/// Stability from the characteristic polynomial q(w), w = ω² (coefficients lowest first,
/// leading one positive): stable when its roots are all real, positive and simple; marginal
/// when w = 0 is a root and the rest are so; unstable when q is squarefree and some root is
/// not real and positive. Nothing when a sign cannot be decided or a positive root repeats.
std::optional<stability> decide_by_roots(polynomial q, const sign_oracle& sign)
{
    trim(q);
    std::size_t zero_roots = 0;
    while (!q.empty() && vanishes(q.front())) {
        q.erase(q.begin());
        ++zero_roots;
    }
    if (q.size() <= 1)
        return zero_roots ? stability::marginal : stability::stable;
    std::vector<polynomial> sturm{q};
    polynomial derivative;
    for (std::size_t k = 1; k < q.size(); ++k)
        derivative.push_back((static_cast<int>(k) * q[k]).expand());
    trim(derivative);
    sturm.push_back(derivative);
    while (true) {
        polynomial next = remainder(sturm[sturm.size() - 2], sturm.back());
        if (next.empty())
            break;
        for (ex& c : next)
            c = (-c).normal();
        sturm.push_back(next);
    }
    std::vector<int> at_zero, at_infinity;
    for (const polynomial& p : sturm) {
        std::optional<int> low, high = sign(p.back());
        for (const ex& c : p)
            if (!vanishes(c)) {
                low = sign(c);
                break;
            }
        if (!low || !high)
            return std::nullopt;
        at_zero.push_back(*low);
        at_infinity.push_back(*high);
    }
    if (sturm.back().size() > 1)
        return std::nullopt; // q and q' share a root: a repeated root
    int positive_roots = sign_changes(at_zero) - sign_changes(at_infinity);
    if (positive_roots < static_cast<int>(q.size()) - 1)
        return stability::unstable;
    return zero_roots ? stability::marginal : stability::stable;
}

/// An exact rational for a value: rationals stay, anything else goes through its double.
ex exact_value(const ex& value)
{
    if (GiNaC::is_a<GiNaC::numeric>(value) && GiNaC::ex_to<GiNaC::numeric>(value).is_rational())
        return value;
    ex number = value.evalf();
    if (!GiNaC::is_a<GiNaC::numeric>(number) || !GiNaC::ex_to<GiNaC::numeric>(number).is_real())
        return value;
    double x = GiNaC::ex_to<GiNaC::numeric>(number).to_double();
    return GiNaC::numeric(cln::cl_N(cln::rational(cln::cl_DF(x))));
}

/// The sign of a coefficient at a parameter point given in exact rationals.
std::optional<int> sign_at_point(const ex& e, const GiNaC::exmap& point)
{
    ex value = exact_value(e.subs(point).normal());
    if (!GiNaC::is_a<GiNaC::numeric>(value) || !GiNaC::ex_to<GiNaC::numeric>(value).is_real())
        return std::nullopt;
    return GiNaC::ex_to<GiNaC::numeric>(value).csgn();
}

/// Whether every leading minor of V is positive, by `sign`.
std::optional<bool> positive_definite(const GiNaC::matrix& potential, const sign_oracle& sign)
{
    std::vector<ex> minors = leading_minors(potential);
    if (minors.size() < potential.rows())
        return false;
    for (const ex& m : minors) {
        std::optional<int> s = sign(m);
        if (!s)
            return std::nullopt;
        if (*s <= 0)
            return false;
    }
    return true;
}

/// p with p² = e when e, factored, is a square of a polynomial (of unknown sign).
std::optional<ex> polynomial_square_root(const ex& e)
{
    ex factored = factor_if_quick(e);
    GiNaC::exvector factors =
        GiNaC::is_a<GiNaC::mul>(factored) ? GiNaC::exvector(factored.begin(), factored.end()) : GiNaC::exvector{factored};
    ex root = 1;
    for (const ex& f : factors) {
        if (GiNaC::is_a<GiNaC::numeric>(f)) {
            ex r = GiNaC::sqrt(f);
            if (!GiNaC::is_a<GiNaC::numeric>(r) || !GiNaC::ex_to<GiNaC::numeric>(r).is_rational())
                return std::nullopt;
            root *= r;
        } else if (GiNaC::is_a<GiNaC::power>(f) && f.op(1).info(GiNaC::info_flags::even)) {
            root *= GiNaC::pow(f.op(0), f.op(1) / 2);
        } else {
            return std::nullopt;
        }
    }
    return root;
}

/// √w for a root w = c0 + c1·√radicand of the characteristic polynomial, denested as
/// √x ± √y when c0² − c1²·radicand = c² is a square (x, y = (c0 ± c)/2): with c ≥ 0 and
/// c0 + c ≥ 0 known; or, c's sign unknown, where c0 ≥ 0 and radicand > 0 make x, y > 0
/// and the smaller root |√x − √y|.
ex omega_of(const ex& c0, const ex& c1, const ex& radicand)
{
    if (vanishes(c1) || radicand.is_equal(1))
        return square_root(tidy(c0 + c1 * radicand));
    const ex discriminant = tidy(c0 * c0 - c1 * c1 * radicand);
    auto [outside, inside] = square_root_parts(discriminant);
    std::optional<int> c1_sign = sign_of(c1);
    if (inside.is_equal(1) && c1_sign) {
        ex c = outside;
        std::optional<int> c_sign = sign_of(c), sum = sign_of(tidy(c0 + c));
        if (c_sign && *c_sign >= 0 && sum && *sum >= 0)
            return square_root(tidy((c0 + c) / 2)) + *c1_sign * square_root(tidy((c0 - c) / 2));
    }
    std::optional<int> c0_sign = sign_of(c0), radicand_sign = sign_of(radicand);
    if (c1_sign && c0_sign && *c0_sign >= 0 && radicand_sign && *radicand_sign > 0)
        if (std::optional<ex> c = polynomial_square_root(discriminant)) {
            ex x = square_root(tidy((c0 + *c) / 2)), y = square_root(tidy((c0 - *c) / 2));
            return *c1_sign > 0 ? x + y : GiNaC::abs(x - y);
        }
    return GiNaC::sqrt(c0 + c1 * GiNaC::sqrt(radicand));
}

/// The roots ω of one factor of degree ≤ 2 in w, ascending when its leading coefficient is
/// positive; nothing for a higher degree.
std::optional<std::vector<ex>> omegas_of_factor(const ex& factor, const GiNaC::symbol& w)
{
    ex p = factor.expand();
    int degree = p.degree(w);
    std::vector<ex> c;
    for (int k = 0; k <= degree; ++k)
        c.push_back(p.coeff(w, k));
    if (degree == 1)
        return std::vector<ex>{square_root(tidy(-c[0] / c[1]))};
    if (degree != 2)
        return std::nullopt;
    auto [outside, inside] = square_root_parts(tidy(c[1] * c[1] - 4 * c[2] * c[0]));
    ex center = tidy(-c[1] / (2 * c[2])), half_width = tidy(outside / (2 * c[2]));
    std::vector<ex> roots{omega_of(center, -half_width, inside), omega_of(center, half_width, inside)};
    std::optional<int> order = sign_of(c[2]);
    if (order && *order < 0)
        std::swap(roots[0], roots[1]);
    return roots;
}

} // namespace

GiNaC::matrix gyroscopic_matrix(const model& scene, const ex& velocity_linear, const std::vector<ex>& at)
{
    std::size_t n = scene.coordinates.size();
    std::vector<ex> a;
    for (const coordinate& c : scene.coordinates)
        a.push_back(differentiate(velocity_linear, c.velocity));
    GiNaC::matrix g(n, n);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j) {
            ex entry = tidy(evaluate_at(differentiate(a[j], scene.coordinates[i].position) -
                                            differentiate(a[i], scene.coordinates[j].position),
                                        scene, at));
            g(i, j) = entry;
            g(j, i) = -entry;
        }
    return g;
}

stability gyroscopic_stability(const model& scene, const GiNaC::matrix& kinetic, const GiNaC::matrix& potential,
                               const GiNaC::matrix& gyroscopic, stability potential_verdict)
{
    if (potential_verdict == stability::stable)
        return stability::stable; // Kelvin–Tait–Chetaev I: gyroscopic forces keep a minimum stable
    std::optional<int> det_sign = sign_of(fraction_free_determinant(potential));
    if (det_sign && *det_sign < 0)
        return stability::unstable; // II: an odd number of negative stiffnesses cannot be stabilized
    GiNaC::possymbol w("W");
    const polynomial q = characteristic_coefficients(kinetic, potential, gyroscopic, w);
    if (std::optional<stability> verdict = decide_by_roots(q, [](const ex& e) { return sign_of(e); }))
        return *verdict;
    // Decided at each `values` point, in exact rationals; a verdict only if all agree.
    std::optional<stability> agreed;
    for (const value_point& point : scene.values) {
        GiNaC::exmap exact;
        for (const auto& [symbol, value] : value_map(scene, point))
            exact[symbol] = exact_value(value);
        sign_oracle at_point = [&](const ex& e) { return sign_at_point(e, exact); };
        std::optional<stability> verdict;
        std::optional<bool> minimum = positive_definite(potential, at_point);
        if (minimum && *minimum) {
            verdict = stability::stable;
        } else {
            polynomial q_at;
            for (const ex& c : q)
                q_at.push_back(exact_value(c.subs(exact).normal()));
            verdict = decide_by_roots(q_at, at_point);
        }
        if (!verdict || (agreed && *agreed != *verdict))
            return stability::unknown;
        agreed = verdict;
    }
    if (agreed)
        return *agreed;
    return potential_verdict == stability::marginal ? stability::marginal : stability::unknown;
}

stability gyroscopic_stability_at(const model& scene, const lagrangian_result& lagrangian, const std::vector<ex>& at,
                                  stability potential_verdict, const simplifier& simplify)
{
    std::size_t n = scene.coordinates.size();
    GiNaC::matrix mass = kinetic_matrix(scene, simplify.canonical(lagrangian.kinetic), at);
    GiNaC::matrix stiffness = potential_hessian(scene, simplify.canonical(lagrangian.potential), at);
    GiNaC::matrix g = gyroscopic_matrix(scene, simplify.canonical(lagrangian.gyroscopic), at);
    bool any = false;
    for (std::size_t i = 0; i < n && !any; ++i)
        for (std::size_t j = 0; j < n && !any; ++j)
            any = !vanishes(g(i, j));
    if (!any)
        return potential_verdict;
    return gyroscopic_stability(scene, mass, stiffness, g, potential_verdict);
}

modes_result gyroscopic_modes(const model& scene, const linearization_result& linear,
                              const characteristic_result& characteristic)
{
    modes_result result;
    result.gyroscopic = true;
    GiNaC::possymbol w("W");
    std::size_t n = linear.kinetic.rows();
    ex polynomial_in_w = 0;
    ex expanded = characteristic.polynomial.expand();
    for (std::size_t k = 0; k <= n; ++k)
        polynomial_in_w += expanded.coeff(characteristic.omega, static_cast<int>(2 * k)) * GiNaC::pow(w, static_cast<int>(k));
    ex factored = factor_if_quick(polynomial_in_w.expand());
    GiNaC::exvector factors =
        GiNaC::is_a<GiNaC::mul>(factored) ? GiNaC::exvector(factored.begin(), factored.end()) : GiNaC::exvector{factored};
    std::vector<ex> omegas;
    for (const ex& f : factors) {
        ex base = f;
        long multiplicity = 1;
        if (GiNaC::is_a<GiNaC::power>(f) && f.op(1).info(GiNaC::info_flags::posint)) {
            base = f.op(0);
            multiplicity = GiNaC::ex_to<GiNaC::numeric>(f.op(1)).to_long();
        }
        if (!base.has(w))
            continue;
        std::optional<std::vector<ex>> found = omegas_of_factor(base, w);
        if (!found)
            return result;
        for (long m = 0; m < multiplicity; ++m)
            omegas.insert(omegas.end(), found->begin(), found->end());
    }
    // A start that does not depend on GiNaC's factor order (hash order): ascending at the
    // first `values` point (else every parameter 1), ties by text. The proven order below wins.
    GiNaC::exmap at;
    for (const parameter& p : scene.parameters)
        at[p.symbol] = 1;
    if (!scene.values.empty())
        for (const auto& [symbol, value] : value_map(scene, scene.values.front()))
            at[symbol] = value;
    std::vector<std::pair<double, std::string>> keys;
    for (const ex& omega : omegas) {
        std::optional<double> value = number_at(omega, at);
        keys.push_back({value ? *value : HUGE_VAL, message_text(omega)});
    }
    std::vector<std::size_t> order(omegas.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return keys[a] < keys[b]; });
    std::vector<ex> sorted;
    for (std::size_t i : order)
        sorted.push_back(omegas[i]);
    omegas = sorted;
    // Insertion sort, moving a root only past those it is known to be below.
    for (std::size_t i = 1; i < omegas.size(); ++i)
        for (std::size_t j = i; j > 0; --j) {
            std::optional<int> s = sign_of(omegas[j - 1] - omegas[j]);
            if (!s || *s <= 0)
                break;
            std::swap(omegas[j - 1], omegas[j]);
        }
    result.closed_form = true;
    result.frequencies = omegas;
    return result;
}

} // namespace lagrange
