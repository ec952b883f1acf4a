// SPDX-License-Identifier: GPL-2.0-or-later
/** @file modes.cpp
 *  The normal modes in closed form: the roots of the characteristic polynomial
 *  factor by factor (linear, quadratic with its surd, cubic in trigonometric
 *  form), mode vectors from cofactors or a T-orthogonal null space basis, and
 *  normal coordinates normalized by Aᵀ T A = I. */
#include "mechanics/modes.h"

#include "algebra/budget.h"
#include "algebra/exact_matrix.h"
#include "algebra/expression.h"
#include "algebra/factor.h"
#include "algebra/sign.h"
#include "algebra/canonical_order.h"
#include "algebra/sorted_terms.h"
#include "algebra/surd.h"

#include <algorithm>
#include <optional>
#include <utility>

namespace lagrange {

namespace {

using GiNaC::ex;
using GiNaC::ex_to;
using GiNaC::exvector;
using GiNaC::is_a;

/// One closed-form root W of the characteristic polynomial, with the surd it contains.
struct closed_root {
    ex value;
    surd root;
    /// A root of an irreducible cubic in trigonometric form whose angle depends on the
    /// parameters: its mode vector would have entries pages long.
    bool unwieldy = false;
};

/// The roots of one factor, and whether they are known to be in ascending order.
struct factor_roots {
    std::vector<closed_root> roots;
    bool ascending = false;
};

/// The roots of a factor of degree ≤ 3 in w, ascending where that is known.
std::optional<factor_roots> roots_of_factor(const ex& factor, const GiNaC::symbol& w)
{
    ex p = factor.expand();
    // factor() gives a factor either sign by GiNaC's hash order; the roots' forms follow
    // the sign, so take the canonical one (canonical_order.h).
    if (is_a<GiNaC::add>(p) && canonical_keys().sum(p).negative)
        p = (-p).expand();
    int degree = p.degree(w);
    std::vector<ex> c;
    for (int k = 0; k <= degree; ++k)
        c.push_back(p.coeff(w, k));
    if (degree == 1)
        return factor_roots{{{tidy(-c[0] / c[1]), surd{}}}, true};
    if (degree == 2) {
        auto [outside, inside] = square_root_parts(tidy(c[1] * c[1] - 4 * c[2] * c[0]));
        surd s;
        s.radicand = inside;
        ex root = inside.is_equal(1) ? outside : outside * s.symbol;
        std::vector<closed_root> roots{{simplify_with((-c[1] - root) / (2 * c[2]), s), s},
                                       {simplify_with((-c[1] + root) / (2 * c[2]), s), s}};
        std::optional<int> order = sign_of(c[2]);
        if (order && *order < 0)
            std::swap(roots[0], roots[1]);
        return factor_roots{roots, order && *order != 0};
    }
    if (degree == 3) {
        // Three real roots (T is positive definite): the trigonometric form.
        ex shift = -c[2] / (3 * c[3]);
        ex p_depressed = tidy((3 * c[3] * c[1] - c[2] * c[2]) / (3 * c[3] * c[3]));
        ex q_depressed = tidy((2 * GiNaC::pow(c[2], 3) - 9 * c[3] * c[2] * c[1] + 27 * c[3] * c[3] * c[0]) /
                              (27 * GiNaC::pow(c[3], 3)));
        ex shift_value = tidy(shift);
        if (vanishes(p_depressed))
            return factor_roots{std::vector<closed_root>(3, closed_root{shift_value, surd{}}), true};
        ex amplitude = 2 * square_root(-p_depressed / 3);
        ex cosine = merge_signed_powers(tidy(3 * q_depressed / (2 * p_depressed)) * square_root(-3 / p_depressed));
        ex angle = GiNaC::acos(cosine) / 3;
        const bool unwieldy = has_symbol(cosine);
        // With the angle in [0, π/3], cos(angle − 4π/3) ≤ cos(angle − 2π/3) ≤ cos(angle):
        // k = 2, 1, 0 is ascending, as the amplitude is positive.
        std::vector<closed_root> roots;
        for (int k = 2; k >= 0; --k)
            roots.push_back({shift_value + amplitude * GiNaC::cos(angle - 2 * GiNaC::Pi * k / 3), surd{}, unwieldy});
        return factor_roots{roots, true};
    }
    return std::nullopt;
}

/// The roots of the polynomial with these coefficients (in w), each as often as
/// its multiplicity, ascending where the order can be decided; nothing if some
/// factor has degree above 3.
std::optional<std::vector<closed_root>> closed_form_roots(const std::vector<ex>& coefficients, const GiNaC::symbol& w)
{
    ex polynomial = 0;
    for (std::size_t k = 0; k < coefficients.size(); ++k)
        polynomial += coefficients[k] * GiNaC::pow(w, static_cast<int>(k));
    ex factored = factor_if_quick(polynomial.expand());
    // Roots whose order cannot be decided keep the order of their factors: a canonical one.
    const exvector factors = sorted_factors(factored);
    std::vector<closed_root> roots;
    // Roots of one factor (one copy of it) whose order is known share a group.
    std::vector<std::size_t> group;
    std::size_t next_group = 0;
    for (const ex& f : factors) {
        ex base = f;
        long multiplicity = 1;
        if (is_a<GiNaC::power>(f) && f.op(1).info(GiNaC::info_flags::posint)) {
            base = f.op(0);
            multiplicity = ex_to<GiNaC::numeric>(f.op(1)).to_long();
        }
        if (!base.has(w))
            continue;
        std::optional<factor_roots> found = roots_of_factor(base, w);
        if (!found)
            return std::nullopt;
        for (long m = 0; m < multiplicity; ++m) {
            const std::size_t shared = next_group++;
            for (const closed_root& root : found->roots) {
                roots.push_back(root);
                group.push_back(found->ascending ? shared : next_group++);
            }
        }
    }
    // Insertion sort, moving a root only past those it is known to be below; within a
    // factor whose roots are known ascending, no comparison is needed.
    for (std::size_t i = 1; i < roots.size(); ++i)
        for (std::size_t j = i; j > 0; --j) {
            if (group[j - 1] == group[j])
                break;
            std::optional<int> s =
                sign_of(roots[j - 1].root.restore(roots[j - 1].value) - roots[j].root.restore(roots[j].value));
            if (!s || *s <= 0)
                break;
            std::swap(roots[j - 1], roots[j]);
            std::swap(group[j - 1], group[j]);
        }
    return roots;
}

/// A mode vector for a simple root: a row of cofactors of V − W T (the last row
/// first, as a = (T12 W − V12, V11 − T11 W) for two coordinates).
std::optional<std::vector<ex>> cofactor_mode(const GiNaC::matrix& pencil, const surd& root)
{
    std::size_t n = pencil.rows();
    if (n == 1)
        return std::vector<ex>{1};
    for (std::size_t r = n; r-- > 0;) {
        std::vector<ex> a(n);
        bool nonzero = false;
        for (std::size_t j = 0; j < n; ++j) {
            GiNaC::matrix minor(n - 1, n - 1);
            for (std::size_t i = 0, mi = 0; i < n; ++i) {
                if (i == r)
                    continue;
                for (std::size_t k = 0, mk = 0; k < n; ++k) {
                    if (k == j)
                        continue;
                    minor(mi, mk++) = pencil(i, k);
                }
                ++mi;
            }
            ex sign = ((r + j) % 2 == 0) ? 1 : -1;
            a[j] = simplify_with(sign * minor.determinant(), root);
            nonzero = nonzero || !vanishes(a[j]);
        }
        if (nonzero)
            return a;
    }
    return std::nullopt;
}

/// uᵀ T v.
ex kinetic_product(const GiNaC::matrix& kinetic, const std::vector<ex>& u, const std::vector<ex>& v)
{
    ex sum = 0;
    for (std::size_t i = 0; i < u.size(); ++i)
        for (std::size_t j = 0; j < v.size(); ++j)
            sum += u[i] * kinetic(i, j) * v[j];
    return sum;
}

/// Scales a mode so that its last nonzero component is 1.
std::vector<ex> scaled_mode(std::vector<ex> a, const surd& root)
{
    for (std::size_t j = a.size(); j-- > 0;) {
        if (vanishes(a[j]))
            continue;
        ex last = a[j];
        for (ex& component : a)
            component = simplify_with(component / last, root);
        break;
    }
    return a;
}

/// ζ = (Σ_j w_j q_j)/√norm² with w = T a, written as ±√(w_p²/norm²)·(q_p + Σ_j (w_j/w_p) q_j)
/// for the first coordinate p with w_p ≠ 0, each part reduced to c0 + c1·s and
/// rationalized. Nothing if the sign of w_p cannot be decided.
std::optional<ex> clean_normal_coordinate(const std::vector<ex>& displacements, const std::vector<ex>& weights,
                                          const ex& norm_squared, const surd& r)
{
    try {
        std::size_t pivot = weights.size();
        for (std::size_t j = 0; j < weights.size() && pivot == weights.size(); ++j)
            if (!vanishes(r.restore(weights[j])))
                pivot = j;
        if (pivot == weights.size())
            return std::nullopt;
        std::optional<int> sign = sign_with(weights[pivot], r);
        ex combination = 0;
        for (std::size_t j = 0; j < weights.size(); ++j)
            combination += fold_surd(simplify_with(weights[j] / weights[pivot], r), r) * displacements[j];
        if (!sign || *sign == 0)
            return std::nullopt; // (w_p/√norm² written out is longer than the plain sum)
        ex scale_squared = simplify_with(weights[pivot] * weights[pivot] / norm_squared, r);
        // the squares come out of the root; the numeric denominator stays in it
        // √m/√X, not √(−m)/√(−X): GiNaC gives the pair a sign by its hash order.
        ex fraction = canonical_numer_denom(tidy(scale_squared));
        auto [numerator_out, numerator_in] = square_root_parts_of_product(factor_if_quick(fraction.op(0)));
        auto [denominator_out, denominator_in] = square_root_parts_of_product(factor_if_quick(fraction.op(1)));
        ex scale = numerator_out / denominator_out * GiNaC::sqrt(r.restore(numerator_in)) /
                   GiNaC::sqrt(r.restore(denominator_in));
        return *sign * r.restore(scale) * combination;
    } catch (const budget_exceeded&) {
        throw; // out of budget: the stage stops, no fallback
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

/// Frequencies, modes and normal coordinates from T, V and the primitive
/// characteristic coefficients; the frequencies alone without `vectors`.
struct closed_modes {
    bool closed_form = false;
    bool vectors_left_out = false;
    std::string vectors_left_out_why;
    std::vector<ex> frequencies;
    std::vector<std::vector<ex>> modes;
    std::vector<ex> normal_coordinates;
};

closed_modes solve_modes(const std::vector<ex>& displacements, const GiNaC::matrix& kinetic,
                         const GiNaC::matrix& potential, const std::vector<ex>& coefficients, const GiNaC::symbol& w,
                         bool vectors)
{
    closed_modes result;
    std::optional<std::vector<closed_root>> roots = closed_form_roots(coefficients, w);
    if (!roots)
        return result;
    // The mode vectors of a cubic's roots in parameters are pages long per entry, and take
    // minutes: they are left to the numeric modes.
    const bool unwieldy =
        std::any_of(roots->begin(), roots->end(), [](const closed_root& root) { return root.unwieldy; });
    // The frequencies alone: they stand whether or not the mode vectors are found.
    auto frequencies_alone = [&](const std::string& why) {
        closed_modes alone;
        alone.closed_form = true;
        alone.vectors_left_out = vectors;
        alone.vectors_left_out_why = vectors ? why : "";
        for (const closed_root& root : *roots)
            alone.frequencies.push_back(root.root.restore(root.value));
        return alone;
    };
    if (!vectors || unwieldy)
        return frequencies_alone("the roots of an irreducible cubic in the parameters, whose entries would be "
                                 "pages long");
    std::size_t n = kinetic.rows();
    std::vector<std::vector<ex>> modes;
    std::vector<surd> surds;
    for (std::size_t k = 0; k < roots->size(); ++k) {
        const closed_root& root = (*roots)[k];
        GiNaC::matrix pencil(n, n);
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < n; ++j)
                pencil(i, j) = (potential(i, j) - root.value * kinetic(i, j)).expand();
        std::size_t multiplicity = 0, first = k;
        for (std::size_t j = 0; j < roots->size(); ++j)
            if (vanishes((*roots)[j].value - root.value)) {
                ++multiplicity;
                first = std::min(first, j);
            }
        std::optional<std::vector<ex>> mode;
        if (multiplicity == 1)
            mode = cofactor_mode(pencil, root.root);
        if (!mode) {
            // a repeated root: the (k − first)th vector of a T-orthogonal basis of the null space
            std::vector<std::vector<ex>> basis = null_space(pencil);
            if (k - first >= basis.size())
                return frequencies_alone("a repeated ω², whose modes (a basis of the null space of V − ω²T) "
                                         "are not found in closed form");
            std::vector<ex> v = basis[k - first];
            for (std::size_t earlier = first; earlier < k; ++earlier) {
                const std::vector<ex>& u = modes[earlier];
                ex projection = (kinetic_product(kinetic, u, v) / kinetic_product(kinetic, u, u)).normal();
                for (std::size_t i = 0; i < n; ++i)
                    v[i] = (v[i] - projection * u[i]).normal();
            }
            mode = v;
        }
        modes.push_back(scaled_mode(*mode, root.root));
        surds.push_back(root.root);
    }
    result.closed_form = true;
    for (std::size_t k = 0; k < roots->size(); ++k) {
        result.frequencies.push_back((*roots)[k].value);
        const std::vector<ex>& a = modes[k];
        ex norm_squared = simplify_with(kinetic_product(kinetic, a, a), surds[k]);
        ex coordinate_sum = 0;
        std::vector<ex> weights;
        for (std::size_t j = 0; j < n; ++j) {
            ex weight = 0;
            for (std::size_t i = 0; i < n; ++i)
                weight += a[i] * kinetic(i, j);
            weights.push_back(simplify_with(weight, surds[k]));
            coordinate_sum += weights.back() * displacements[j];
        }
        if (std::optional<ex> clean = clean_normal_coordinate(displacements, weights, norm_squared, surds[k])) {
            result.normal_coordinates.push_back(*clean);
            continue;
        }
        ex norm = norm_squared.has(surds[k].symbol) ? GiNaC::sqrt(norm_squared) : square_root(norm_squared);
        result.normal_coordinates.push_back(surds[k].restore(coordinate_sum / norm));
    }
    for (std::size_t k = 0; k < modes.size(); ++k) {
        result.frequencies[k] = surds[k].restore(result.frequencies[k]);
        for (ex& component : modes[k])
            component = surds[k].restore(component);
    }
    result.modes = modes;
    return result;
}

/// The map m -> rho*M of the scene's ratio, if it has one of that shape.
std::optional<GiNaC::exmap> ratio_substitution(const model& scene)
{
    if (!scene.ratio)
        return std::nullopt;
    ex fraction = scene.ratio->definition.numer_denom();
    if (!is_a<GiNaC::symbol>(fraction.op(0)))
        return std::nullopt;
    return GiNaC::exmap{{fraction.op(0), scene.ratio->symbol * fraction.op(1)}};
}

} // namespace

modes_result symbolic_modes(const model& scene, const linearization_result& linear,
                            const characteristic_result& characteristic, bool vectors)
{
    modes_result result;
    GiNaC::possymbol w("W");
    std::size_t n = linear.kinetic.rows();
    std::vector<ex> coefficients;
    ex polynomial = characteristic.polynomial.expand();
    for (std::size_t k = 0; k <= n; ++k)
        coefficients.push_back(polynomial.coeff(characteristic.omega, static_cast<int>(2 * k)));
    // normal coordinates in the displacements q − q₀ from the equilibrium
    for (std::size_t i = 0; i < n; ++i)
        result.displacements.push_back(i < linear.at.size() ? scene.coordinates[i].position - linear.at[i]
                                                            : ex(scene.coordinates[i].position));
    closed_modes plain = solve_modes(result.displacements, linear.kinetic, linear.potential, coefficients, w, vectors);
    result.closed_form = plain.closed_form;
    result.vectors_left_out = plain.vectors_left_out;
    result.vectors_left_out_why = plain.vectors_left_out_why;
    result.frequencies = plain.frequencies;
    result.modes = plain.modes;
    result.normal_coordinates = plain.normal_coordinates;
    if (!plain.closed_form)
        return result;
    if (std::optional<GiNaC::exmap> in_ratio = ratio_substitution(scene)) {
        GiNaC::matrix kinetic = ex_to<GiNaC::matrix>(linear.kinetic.subs(*in_ratio));
        GiNaC::matrix potential = ex_to<GiNaC::matrix>(linear.potential.subs(*in_ratio));
        std::vector<ex> displacements;
        for (const ex& d : result.displacements)
            displacements.push_back(d.subs(*in_ratio));
        closed_modes ratio = solve_modes(displacements, kinetic, potential,
                                         characteristic_coefficients(kinetic, potential, w), w, vectors);
        if (ratio.closed_form) {
            result.frequencies_in_ratio = ratio.frequencies;
            result.modes_in_ratio = ratio.modes;
            result.normal_coordinates_in_ratio = ratio.normal_coordinates;
        }
    }
    return result;
}

} // namespace lagrange
