/** @file oscillations.cpp
 *  Small oscillations about an equilibrium: the equilibria of V and their
 *  stability, the kinetic and potential matrices there, the characteristic
 *  polynomial det(V − ω²T), and the frequencies, mode vectors, normal
 *  coordinates and asymptotic limits in closed form where one exists. */
#include "mechanics/oscillations.h"

#include "algebra/budget.h"
#include "algebra/exact_matrix.h"
#include "algebra/expression.h"
#include "algebra/factor.h"
#include "algebra/message_text.h"
#include "algebra/sign.h"
#include "algebra/surd.h"
#include "core/errors.h"

#include <algorithm>
#include <functional>
#include <map>

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

/// e with the coordinates at `at` and the velocities at zero.
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

/// ∂²V/∂qi∂qj at a point.
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

/// The primitive polynomial in W = ω² from det(V − W T): its coefficients, lowest
/// degree first, with every common factor removed and the leading one positive.
std::vector<ex> characteristic_coefficients(const GiNaC::matrix& kinetic, const GiNaC::matrix& potential,
                                            const GiNaC::symbol& w)
{
    std::size_t n = kinetic.rows();
    GiNaC::matrix pencil(n, n);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j)
            pencil(i, j) = potential(i, j) - w * kinetic(i, j);
    ex det = fraction_free_determinant(pencil).normal();
    ex fraction = det.numer_denom();
    ex numerator = fraction.op(0).expand();
    std::optional<int> denominator_sign = sign_of(fraction.op(1));
    std::vector<ex> coefficients;
    for (int k = 0; k <= numerator.degree(w); ++k)
        coefficients.push_back(numerator.coeff(w, k).expand());
    ex content = 0;
    for (const ex& c : coefficients)
        if (!c.is_zero())
            content = content.is_zero() ? c : GiNaC::gcd(content, c);
    if (content.is_zero())
        return coefficients;
    int flip = (denominator_sign && *denominator_sign < 0) ? -1 : 1;
    std::optional<int> leading = sign_of(coefficients.back() / content);
    if (leading && *leading < 0)
        flip = -flip;
    for (ex& c : coefficients) {
        ex quotient;
        if (!GiNaC::divide(c, content, quotient))
            quotient = (c / content).normal();
        c = factor_if_quick(flip * quotient);
    }
    return coefficients;
}

/// One closed-form root W of the characteristic polynomial, with the surd it contains.
struct closed_root {
    ex value;
    surd root;
};

/// The roots of a factor of degree ≤ 3 in w, ascending where that is known.
std::optional<std::vector<closed_root>> roots_of_factor(const ex& factor, const GiNaC::symbol& w)
{
    ex p = factor.expand();
    int degree = p.degree(w);
    std::vector<ex> c;
    for (int k = 0; k <= degree; ++k)
        c.push_back(p.coeff(w, k));
    if (degree == 1)
        return std::vector<closed_root>{{tidy(-c[0] / c[1]), surd{}}};
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
        return roots;
    }
    if (degree == 3) {
        // Three real roots (T is positive definite): the trigonometric form.
        ex shift = -c[2] / (3 * c[3]);
        ex p_depressed = tidy((3 * c[3] * c[1] - c[2] * c[2]) / (3 * c[3] * c[3]));
        ex q_depressed = tidy((2 * GiNaC::pow(c[2], 3) - 9 * c[3] * c[2] * c[1] + 27 * c[3] * c[3] * c[0]) /
                              (27 * GiNaC::pow(c[3], 3)));
        if (vanishes(p_depressed))
            return std::vector<closed_root>(3, closed_root{tidy(shift), surd{}});
        ex amplitude = 2 * square_root(-p_depressed / 3);
        ex angle = GiNaC::acos(tidy(3 * q_depressed / (2 * p_depressed)) * square_root(-3 / p_depressed)) / 3;
        std::vector<closed_root> roots;
        for (int k = 2; k >= 0; --k)
            roots.push_back({tidy(shift) + amplitude * GiNaC::cos(angle - 2 * GiNaC::Pi * k / 3), surd{}});
        return roots;
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
    exvector factors = is_a<GiNaC::mul>(factored) ? exvector(factored.begin(), factored.end()) : exvector{factored};
    std::vector<closed_root> roots;
    for (const ex& f : factors) {
        ex base = f;
        long multiplicity = 1;
        if (is_a<GiNaC::power>(f) && f.op(1).info(GiNaC::info_flags::posint)) {
            base = f.op(0);
            multiplicity = ex_to<GiNaC::numeric>(f.op(1)).to_long();
        }
        if (!base.has(w))
            continue;
        std::optional<std::vector<closed_root>> found = roots_of_factor(base, w);
        if (!found)
            return std::nullopt;
        for (long m = 0; m < multiplicity; ++m)
            roots.insert(roots.end(), found->begin(), found->end());
    }
    // Insertion sort, moving a root only past those it is known to be below.
    for (std::size_t i = 1; i < roots.size(); ++i)
        for (std::size_t j = i; j > 0; --j) {
            std::optional<int> s = sign_of(roots[j - 1].value - roots[j].value);
            if (!s || *s <= 0)
                break;
            std::swap(roots[j - 1], roots[j]);
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
std::optional<ex> clean_normal_coordinate(const model& scene, const std::vector<ex>& weights,
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
            combination += fold_surd(simplify_with(weights[j] / weights[pivot], r), r) * scene.coordinates[j].position;
        if (!sign || *sign == 0)
            return std::nullopt; // (w_p/√norm² written out is longer than the plain sum)
        ex scale_squared = simplify_with(weights[pivot] * weights[pivot] / norm_squared, r);
        // the squares come out of the root; the numeric denominator stays in it
        ex fraction = tidy(scale_squared).numer_denom();
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
/// characteristic coefficients.
struct closed_modes {
    bool closed_form = false;
    std::vector<ex> frequencies;
    std::vector<std::vector<ex>> modes;
    std::vector<ex> normal_coordinates;
};

closed_modes solve_modes(const model& scene, const GiNaC::matrix& kinetic, const GiNaC::matrix& potential,
                         const std::vector<ex>& coefficients, const GiNaC::symbol& w)
{
    closed_modes result;
    std::optional<std::vector<closed_root>> roots = closed_form_roots(coefficients, w);
    if (!roots)
        return result;
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
                return result;
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
            coordinate_sum += weights.back() * scene.coordinates[j].position;
        }
        if (std::optional<ex> clean = clean_normal_coordinate(scene, weights, norm_squared, surds[k])) {
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

/// A symbol named `base` (or base_, base__, …) that no parameter or coordinate uses.
std::string free_name(const model& scene, std::string base)
{
    auto taken = [&](const std::string& name) {
        for (const parameter& p : scene.parameters)
            if (p.name == name)
                return true;
        for (const coordinate& c : scene.coordinates)
            if (c.name == name)
                return true;
        return scene.ratio && scene.ratio->name == name;
    };
    while (taken(base))
        base += "_";
    return base;
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

/// Terms of the Laurent series of e in eps at 0, lowest order first (at most `count`).
std::vector<std::pair<int, ex>> series_terms(const ex& e, const GiNaC::symbol& eps, int count)
{
    std::vector<std::pair<int, ex>> terms;
    for (int order = count; order <= 4 * count && static_cast<int>(terms.size()) < count; order += count) {
        terms.clear();
        ex polynomial = GiNaC::series_to_poly(e.series(eps == 0, order));
        polynomial = polynomial.expand();
        for (int k = polynomial.ldegree(eps); k <= polynomial.degree(eps); ++k) {
            ex c = polynomial.coeff(eps, k);
            if (!vanishes(c))
                terms.emplace_back(k, tidy(c));
        }
    }
    if (static_cast<int>(terms.size()) > count)
        terms.resize(count);
    return terms;
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

linearization_result linearize(const model& scene, const lagrangian_result& lagrangian, const std::vector<ex>& at,
                               const simplifier& simplify)
{
    if (!lagrangian.split)
        throw computation_error("the Lagrangian is not quadratic in the velocities: no small-oscillation analysis");
    std::size_t n = scene.coordinates.size();
    if (at.size() != n)
        throw std::invalid_argument("linearize: the equilibrium has " + std::to_string(at.size()) +
                                    " values for " + std::to_string(n) + " coordinates");
    linearization_result result{at, GiNaC::matrix(n, n), GiNaC::matrix(n, n)};
    ex kinetic = simplify.canonical(lagrangian.kinetic);
    ex potential = simplify.canonical(lagrangian.potential);
    for (std::size_t i = 0; i < n; ++i) {
        ex kinetic_row = differentiate(kinetic, scene.coordinates[i].velocity);
        for (std::size_t j = i; j < n; ++j) {
            ex entry = tidy(evaluate_at(differentiate(kinetic_row, scene.coordinates[j].velocity), scene, at));
            result.kinetic(i, j) = entry;
            result.kinetic(j, i) = entry;
        }
    }
    result.potential = potential_hessian(scene, potential, at);
    for (std::size_t i = 0; i < n; ++i)
        if (vanishes(result.kinetic(i, i)))
            throw computation_error("coordinate `" + scene.coordinates[i].name +
                                    "` has no kinetic energy at the equilibrium");
    std::vector<ex> minors = leading_minors(result.kinetic);
    for (std::size_t k = 0; k < minors.size(); ++k) {
        std::optional<int> sign = sign_of(minors[k]);
        if (sign && *sign <= 0)
            throw computation_error("the kinetic matrix is not positive definite at the equilibrium: the kinetic energy "
                                    "of " + scene.coordinates[0].name + " … " + scene.coordinates[k].name +
                                    " can vanish (leading minor " + message_text(minors[k].expand()) + ")");
    }
    return result;
}

characteristic_result characteristic_polynomial(const model& scene, const linearization_result& linear)
{
    characteristic_result result{GiNaC::possymbol(free_name(scene, "omega")), 0};
    GiNaC::possymbol w("W");
    std::vector<ex> coefficients = characteristic_coefficients(linear.kinetic, linear.potential, w);
    ex polynomial = 0;
    for (std::size_t k = 0; k < coefficients.size(); ++k)
        polynomial += coefficients[k] * GiNaC::pow(result.omega, static_cast<int>(2 * k));
    result.polynomial = polynomial;
    return result;
}

modes_result symbolic_modes(const model& scene, const linearization_result& linear,
                            const characteristic_result& characteristic)
{
    modes_result result;
    GiNaC::possymbol w("W");
    std::size_t n = linear.kinetic.rows();
    std::vector<ex> coefficients;
    ex polynomial = characteristic.polynomial.expand();
    for (std::size_t k = 0; k <= n; ++k)
        coefficients.push_back(polynomial.coeff(characteristic.omega, static_cast<int>(2 * k)));
    closed_modes plain = solve_modes(scene, linear.kinetic, linear.potential, coefficients, w);
    result.closed_form = plain.closed_form;
    result.frequencies = plain.frequencies;
    result.modes = plain.modes;
    result.normal_coordinates = plain.normal_coordinates;
    if (!plain.closed_form)
        return result;
    if (std::optional<GiNaC::exmap> in_ratio = ratio_substitution(scene)) {
        GiNaC::matrix kinetic = ex_to<GiNaC::matrix>(linear.kinetic.subs(*in_ratio));
        GiNaC::matrix potential = ex_to<GiNaC::matrix>(linear.potential.subs(*in_ratio));
        closed_modes ratio = solve_modes(scene, kinetic, potential,
                                         characteristic_coefficients(kinetic, potential, w), w);
        if (ratio.closed_form) {
            result.frequencies_in_ratio = ratio.frequencies;
            result.modes_in_ratio = ratio.modes;
            result.normal_coordinates_in_ratio = ratio.normal_coordinates;
        }
    }
    return result;
}

asymptotic_result asymptotic_limit(const model& scene, const modes_result& modes)
{
    asymptotic_result result;
    if (!scene.limit)
        return result;
    const limit_request& limit = *scene.limit;
    result.label = limit.variable + (limit.to_infinity ? " -> oo" : " -> 0");
    ex variable;
    const std::vector<ex>* frequencies = nullptr;
    const std::vector<std::vector<ex>>* mode_vectors = nullptr;
    const std::vector<ex>* normal_coordinates = nullptr;
    if (scene.ratio && scene.ratio->name == limit.variable && !modes.frequencies_in_ratio.empty()) {
        variable = scene.ratio->symbol;
        frequencies = &modes.frequencies_in_ratio;
        mode_vectors = &modes.modes_in_ratio;
        normal_coordinates = &modes.normal_coordinates_in_ratio;
    } else {
        for (const parameter& p : scene.parameters)
            if (p.name == limit.variable)
                variable = p.symbol;
        frequencies = &modes.frequencies;
        mode_vectors = &modes.modes;
        normal_coordinates = &modes.normal_coordinates;
    }
    if (variable.is_zero() || frequencies->empty())
        return result;
    // x = ε² (x -> 0) or x = 1/ε² (x -> ∞): the square roots of x become powers of ε.
    GiNaC::possymbol eps("epsilon");
    ex replacement = limit.to_infinity ? 1 / (eps * eps) : eps * eps;
    ex back = limit.to_infinity ? 1 / GiNaC::sqrt(variable) : GiNaC::sqrt(variable);
    auto in_eps = [&](const ex& e) { return simplify_square_roots(e.subs(variable == replacement)); };
    auto sum_of = [&](const std::vector<std::pair<int, ex>>& terms, std::size_t count) {
        ex sum = 0;
        for (std::size_t t = 0; t < count && t < terms.size(); ++t)
            sum += terms[t].second * GiNaC::pow(back, terms[t].first);
        return sum;
    };
    // The leading term c εᵏ of a product or power is the product or power of the
    // leading terms: this keeps the series away from √ of a sum that vanishes at ε = 0.
    std::function<ex(const ex&)> leading_in_eps = [&](const ex& e) -> ex {
        try {
            std::vector<std::pair<int, ex>> terms = series_terms(e, eps, 1);
            if (terms.empty())
                return 0;
            return terms[0].second * GiNaC::pow(eps, terms[0].first);
        } catch (const budget_exceeded&) {
            throw; // out of budget: the stage stops, no fallback
        } catch (const std::exception&) {
        }
        if (is_a<GiNaC::mul>(e)) {
            ex product = 1;
            for (const ex& factor : e)
                product *= leading_in_eps(factor);
            return product;
        }
        if (is_a<GiNaC::power>(e) && is_a<GiNaC::numeric>(e.op(1)))
            return simplify_square_roots(GiNaC::pow(leading_in_eps(e.op(0)), e.op(1)));
        throw computation_error("no series");
    };
    auto leading = [&](const ex& e) -> ex {
        try {
            return tidy(leading_in_eps(in_eps(e)).subs(eps == back));
        } catch (const budget_exceeded&) {
            throw; // out of budget: the stage stops, no fallback
        } catch (const std::exception&) {
            return e;
        }
    };
    // Frequencies: the leading term of each, and further terms until they differ.
    std::vector<std::vector<std::pair<int, ex>>> terms;
    bool expanded = true;
    for (const ex& f : *frequencies) {
        try {
            terms.push_back(series_terms(in_eps(f), eps, 4));
        } catch (const budget_exceeded&) {
            throw; // out of budget: the stage stops, no fallback
        } catch (const std::exception&) {
            expanded = false;
            break;
        }
    }
    if (expanded) {
        std::vector<std::size_t> kept(terms.size(), 1);
        for (int round = 0; round < 3; ++round) {
            bool changed = false;
            for (std::size_t i = 0; i < terms.size(); ++i)
                for (std::size_t j = i + 1; j < terms.size(); ++j)
                    if (vanishes(sum_of(terms[i], kept[i]) - sum_of(terms[j], kept[j]))) {
                        kept[i] = std::min(kept[i] + 1, terms[i].size());
                        kept[j] = std::min(kept[j] + 1, terms[j].size());
                        changed = true;
                    }
            if (!changed)
                break;
        }
        for (std::size_t i = 0; i < terms.size(); ++i) {
            // c0·εᵏ⁰ (1 + (c1/c0) εᵏ¹⁻ᵏ⁰ + …): the leading term outside, corrections in order
            ex correction = 1;
            for (std::size_t t = 1; t < kept[i] && t < terms[i].size(); ++t)
                correction += tidy(terms[i][t].second / terms[i][0].second) *
                              GiNaC::pow(back, terms[i][t].first - terms[i][0].first);
            result.frequencies.push_back(terms[i][0].second * GiNaC::pow(back, terms[i][0].first) * correction);
            std::vector<ex> series{terms[i][0].second * GiNaC::pow(back, terms[i][0].first), 1};
            for (std::size_t t = 1; t < kept[i] && t < terms[i].size(); ++t)
                series.push_back(tidy(terms[i][t].second / terms[i][0].second) *
                                 GiNaC::pow(back, terms[i][t].first - terms[i][0].first));
            result.frequency_series.push_back(series);
        }
        // Frequencies equal to leading order beat: ω_j − ω_i and the period 2π/(ω_j − ω_i).
        for (std::size_t i = 0; i < terms.size(); ++i)
            for (std::size_t j = i + 1; j < terms.size(); ++j) {
                if (terms[i].empty() || terms[j].empty() || terms[i][0].first != terms[j][0].first ||
                    !vanishes(terms[i][0].second - terms[j][0].second))
                    continue;
                try {
                    ex difference = leading_in_eps(in_eps(GiNaC::sqrt((*frequencies)[j]) -
                                                          GiNaC::sqrt((*frequencies)[i])));
                    if (difference.is_zero())
                        continue;
                    difference = tidy(difference.subs(eps == back));
                    result.beats.push_back({i, j, difference, tidy(2 * GiNaC::Pi / difference)});
                } catch (const budget_exceeded&) {
                    throw; // out of budget: the stage stops, no fallback
                } catch (const std::exception&) {
                }
            }
    } else {
        result.frequencies = *frequencies;
    }
    for (const std::vector<ex>& mode : *mode_vectors) {
        std::vector<ex> limit_mode;
        for (const ex& component : mode)
            limit_mode.push_back(leading(component));
        result.modes.push_back(limit_mode);
    }
    for (const ex& zeta : *normal_coordinates) {
        // ζ = (Σ w_j q_j) · scale: the leading terms of each w_j times that of the scale
        ex combination = 0, scale = 1;
        for (const ex& factor : is_a<GiNaC::mul>(zeta) ? exvector(zeta.begin(), zeta.end()) : exvector{zeta}) {
            bool has_coordinate = false;
            for (const coordinate& c : scene.coordinates)
                has_coordinate = has_coordinate || factor.has(c.position);
            (has_coordinate ? combination : scale) = has_coordinate ? combination + factor : scale * factor;
        }
        // written as prefactor·(q_p + Σ r_j q_j) with p the first coordinate present
        ex leading_scale = leading(scale);
        std::vector<ex> coefficients;
        for (const coordinate& c : scene.coordinates)
            coefficients.push_back(leading(combination.expand().coeff(c.position, 1)));
        std::size_t pivot = 0;
        while (pivot + 1 < coefficients.size() && vanishes(coefficients[pivot]))
            ++pivot;
        ex sum = 0;
        for (std::size_t j = 0; j < coefficients.size(); ++j)
            sum += tidy(coefficients[j] / coefficients[pivot]) * scene.coordinates[j].position;
        result.normal_coordinates.push_back(tidy(coefficients[pivot] * leading_scale) * sum);
    }
    return result;
}

} // namespace lagrange
