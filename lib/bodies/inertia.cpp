// SPDX-License-Identifier: GPL-2.0-or-later
/** @file inertia.cpp
 *  Inertia by exact integration over the body, principal moments and axes. */
#include "bodies/inertia.h"

#include "algebra/budget.h"
#include "algebra/calculus.h"
#include "algebra/factor.h"
#include "algebra/sign.h"
#include "algebra/sorted_terms.h"

#include <array>
#include <optional>
#include <stdexcept>
#include <utility>

namespace lagrange {

namespace {

// ---- exact integration -------------------------------------------------------------

bool is_function_of(const GiNaC::ex& e, const char* name, const GiNaC::ex& variable)
{
    return GiNaC::is_a<GiNaC::function>(e) && GiNaC::ex_to<GiNaC::function>(e).get_name() == name &&
           e.op(0).is_equal(variable);
}

/// Γ(x) for x a positive integer or half-integer, exactly: (n − 1)! or (2n)! √π / (4ⁿ n!).
GiNaC::ex gamma_of_half_integer(const GiNaC::numeric& x)
{
    if (x.is_integer())
        return GiNaC::factorial(x - 1);
    const GiNaC::numeric n = x - GiNaC::numeric(1, 2);
    return GiNaC::factorial(2 * n) / (GiNaC::pow(GiNaC::numeric(4), n) * GiNaC::factorial(n)) * GiNaC::sqrt(GiNaC::Pi);
}

/// B(p, q) = Γ(p) Γ(q) / Γ(p + q) at halves of integers, exactly.
GiNaC::ex beta_function(const GiNaC::numeric& p, const GiNaC::numeric& q)
{
    return gamma_of_half_integer(p) * gamma_of_half_integer(q) / gamma_of_half_integer(p + q);
}

/// One term c · v^n · sin(v)^a · cos(v)^b, integrated.
GiNaC::ex integrate_term(const GiNaC::ex& term, const GiNaC::realsymbol& v, const GiNaC::ex& lower,
                         const GiNaC::ex& upper)
{
    GiNaC::ex coefficient = 1;
    long n = 0, a = 0, b = 0;
    GiNaC::exvector factors;
    if (GiNaC::is_a<GiNaC::mul>(term))
        factors.assign(term.begin(), term.end());
    else
        factors.push_back(term);
    auto fail = [] {
        throw computation_error("the density cannot be integrated exactly over this region (this version integrates "
                                "polynomials in x, y, z and even powers of r)");
    };
    for (const GiNaC::ex& f : factors) {
        if (!f.has(v)) {
            coefficient *= f;
            continue;
        }
        GiNaC::ex base = f;
        long exponent = 1;
        if (GiNaC::is_a<GiNaC::power>(f)) {
            if (!f.op(1).info(GiNaC::info_flags::integer))
                fail();
            base = f.op(0);
            exponent = GiNaC::ex_to<GiNaC::numeric>(f.op(1)).to_long();
        }
        if (base.is_equal(v))
            n += exponent;
        else if (is_function_of(base, "sin", v) && exponent > 0)
            a += exponent;
        else if (is_function_of(base, "cos", v) && exponent > 0)
            b += exponent;
        else
            fail();
    }
    if (a == 0 && b == 0) {
        if (n == -1)
            fail();
        return coefficient * (GiNaC::pow(upper, n + 1) - GiNaC::pow(lower, n + 1)) / (n + 1);
    }
    if (n != 0 || !lower.is_zero())
        fail();
    // Closed-form moments of sin^a cos^b: over a full period both powers must be even,
    // over [0, π] the power of cos must be even; the values are Beta functions.
    const GiNaC::numeric pa(a + 1, 2), pb(b + 1, 2);
    if ((upper - 2 * GiNaC::Pi).is_zero())
        return (a % 2 || b % 2) ? GiNaC::ex(0) : coefficient * 2 * beta_function(pa, pb);
    if ((upper - GiNaC::Pi).is_zero())
        return b % 2 ? GiNaC::ex(0) : coefficient * beta_function(pa, pb);
    fail();
    return 0;
}

/// The measure and placement of a region, in the coordinates that suit it.
struct region_map {
    std::string coordinates;
    std::vector<integration_limit> limits; ///< innermost first
    GiNaC::ex jacobian;
    std::array<GiNaC::ex, 3> natural;      ///< x, y, z of the point (symmetry axis z)
    GiNaC::ex radius;                      ///< r = |x| in the region's coordinates
    std::vector<GiNaC::ex> natural_deltas; ///< thin bodies, in the natural x, y, z below
    std::array<GiNaC::realsymbol, 3> delta_symbols{GiNaC::realsymbol("x"), GiNaC::realsymbol("y"), GiNaC::realsymbol("z")};
};

region_map region_of(const std::string& shape, const std::vector<GiNaC::ex>& d)
{
    using GiNaC::cos;
    using GiNaC::sin;
    GiNaC::realsymbol rho("rho"), phi("phi"), theta("theta"), r("r"), s("s"), x("x"), y("y"), z("z");
    const GiNaC::ex half = GiNaC::numeric(1, 2);
    region_map m;
    const GiNaC::realsymbol xn = m.delta_symbols[0], yn = m.delta_symbols[1], zn = m.delta_symbols[2];
    if (shape == "stick" || shape == "segment") {
        m.coordinates = "cartesian";
        m.limits = {{s, -half * d[0], half * d[0]}};
        m.jacobian = 1;
        m.natural = {0, 0, s};
        m.radius = GiNaC::sqrt(s * s);
        m.natural_deltas = {xn, yn};
    } else if (shape == "ring" || shape == "circle") {
        m.coordinates = "cylindrical";
        m.limits = {{phi, 0, 2 * GiNaC::Pi}};
        m.jacobian = d[0];
        m.natural = {d[0] * cos(phi), d[0] * sin(phi), 0};
        m.radius = d[0];
        m.natural_deltas = {GiNaC::sqrt(xn * xn + yn * yn) - d[0], zn};
    } else if (shape == "disk") {
        m.coordinates = "cylindrical";
        m.limits = {{rho, 0, d[0]}, {phi, 0, 2 * GiNaC::Pi}};
        m.jacobian = rho;
        m.natural = {rho * cos(phi), rho * sin(phi), 0};
        m.radius = rho;
        m.natural_deltas = {zn};
    } else if (shape == "sphere" || shape == "shell") {
        m.coordinates = "spherical";
        m.limits = {{theta, 0, GiNaC::Pi}, {phi, 0, 2 * GiNaC::Pi}};
        m.jacobian = d[0] * d[0] * sin(theta);
        m.natural = {d[0] * sin(theta) * cos(phi), d[0] * sin(theta) * sin(phi), d[0] * cos(theta)};
        m.radius = d[0];
        m.natural_deltas = {GiNaC::sqrt(xn * xn + yn * yn + zn * zn) - d[0]};
    } else if (shape == "ball") {
        m.coordinates = "spherical";
        m.limits = {{r, 0, d[0]}, {theta, 0, GiNaC::Pi}, {phi, 0, 2 * GiNaC::Pi}};
        m.jacobian = r * r * sin(theta);
        m.natural = {r * sin(theta) * cos(phi), r * sin(theta) * sin(phi), r * cos(theta)};
        m.radius = r;
    } else if (shape == "ellipsoid") {
        // x = a r sinθ cosφ, y = b r sinθ sinφ, z = c r cosθ, r in [0, 1]: Jacobian a b c r² sinθ.
        m.coordinates = "ellipsoidal";
        m.limits = {{r, 0, 1}, {theta, 0, GiNaC::Pi}, {phi, 0, 2 * GiNaC::Pi}};
        m.jacobian = d[0] * d[1] * d[2] * r * r * sin(theta);
        m.natural = {d[0] * r * sin(theta) * cos(phi), d[1] * r * sin(theta) * sin(phi), d[2] * r * cos(theta)};
        m.radius = GiNaC::sqrt(m.natural[0] * m.natural[0] + m.natural[1] * m.natural[1] +
                               m.natural[2] * m.natural[2]);
    } else if (shape == "box") {
        m.coordinates = "cartesian";
        m.limits = {{x, -half * d[0], half * d[0]}, {y, -half * d[1], half * d[1]}, {z, -half * d[2], half * d[2]}};
        m.jacobian = 1;
        m.natural = {x, y, z};
        m.radius = GiNaC::sqrt(x * x + y * y + z * z);
    } else if (shape == "cylinder") {
        m.coordinates = "cylindrical";
        m.limits = {{rho, 0, d[0]}, {phi, 0, 2 * GiNaC::Pi}, {z, -half * d[1], half * d[1]}};
        m.jacobian = rho;
        m.natural = {rho * cos(phi), rho * sin(phi), z};
        m.radius = GiNaC::sqrt(rho * rho + z * z);
    } else if (shape == "cone") {
        // Base on z = 0, apex at z = h; the centre of mass is found by integration.
        m.coordinates = "cylindrical";
        m.limits = {{rho, 0, d[0] * (1 - z / d[1])}, {phi, 0, 2 * GiNaC::Pi}, {z, 0, d[1]}};
        m.jacobian = rho;
        m.natural = {rho * cos(phi), rho * sin(phi), z};
        m.radius = GiNaC::sqrt(rho * rho + z * z);
    } else {
        throw std::invalid_argument("unknown shape `" + shape + "`");
    }
    return m;
}

/// Body axes from the natural ones: the symmetry axis (natural z) becomes `axis`, cyclically.
std::array<GiNaC::ex, 3> permuted(const std::array<GiNaC::ex, 3>& n, char axis)
{
    if (axis == 'x')
        return {n[2], n[0], n[1]};
    if (axis == 'y')
        return {n[1], n[2], n[0]};
    return n;
}


GiNaC::ex integrate_over(GiNaC::ex f, const std::vector<integration_limit>& limits)
{
    for (const integration_limit& l : limits)
        f = integrate_exactly(f.expand(), l.variable, l.lower, l.upper);
    return normal_with_pi(f.expand());
}

bool is_constant(const GiNaC::ex& e)
{
    for (GiNaC::const_preorder_iterator i = e.preorder_begin(); i != e.preorder_end(); ++i)
        if (GiNaC::is_a<GiNaC::symbol>(*i) && !GiNaC::is_a<GiNaC::possymbol>(*i))
            return false;
    return true;
}

/// Roots of the characteristic polynomial of a symmetric 3×3 tensor when it factors
/// into linear and quadratic factors (the real roots of a symmetric matrix).
std::vector<GiNaC::ex> principal_moments(const GiNaC::matrix& tensor)
{
    GiNaC::realsymbol lambda("lambda");
    GiNaC::ex p = factor_with_pi(tensor.charpoly(lambda).expand());
    std::vector<GiNaC::ex> roots;
    for (const GiNaC::ex& f : sorted_factors(p)) { // a canonical order, not GiNaC's hash order
        GiNaC::ex base = f;
        int multiplicity = 1;
        if (GiNaC::is_a<GiNaC::power>(f) && f.op(1).info(GiNaC::info_flags::posint)) {
            base = f.op(0);
            multiplicity = GiNaC::ex_to<GiNaC::numeric>(f.op(1)).to_int();
        }
        if (!base.has(lambda))
            continue;
        int degree = base.degree(lambda);
        std::vector<GiNaC::ex> found;
        if (degree == 1) {
            found.push_back(normal_with_pi(-base.coeff(lambda, 0) / base.coeff(lambda, 1)));
        } else if (degree == 2) {
            GiNaC::ex a = base.coeff(lambda, 2), b = base.coeff(lambda, 1), c = base.coeff(lambda, 0);
            GiNaC::ex root = GiNaC::sqrt((b * b - 4 * a * c).expand());
            found.push_back(normal_with_pi((-b - root) / (2 * a)));
            found.push_back(normal_with_pi((-b + root) / (2 * a)));
            if (std::optional<int> sign = sign_of(a); sign && *sign < 0)
                std::swap(found[0], found[1]); // ascending
        } else {
            return {};
        }
        for (int k = 0; k < multiplicity; ++k)
            roots.insert(roots.end(), found.begin(), found.end());
    }
    return roots.size() == 3 ? roots : std::vector<GiNaC::ex>{};
}

/// The principal axes as columns (directions, not normalized) for distinct principal
/// moments: each is the cross product of two independent rows of I − λ·1.
std::optional<GiNaC::matrix> principal_directions(const GiNaC::matrix& tensor, const std::vector<GiNaC::ex>& moments)
{
    if (moments.size() != 3)
        return std::nullopt;
    GiNaC::matrix axes(3, 3);
    for (unsigned k = 0; k < 3; ++k) {
        for (unsigned other = 0; other < 3; ++other)
            if (other != k && normal_with_pi(moments[k] - moments[other]).is_zero())
                return std::nullopt; // a repeated moment: any axis of its plane is principal
        GiNaC::matrix shifted = tensor.sub(GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(3)).mul_scalar(moments[k]));
        bool found = false;
        const unsigned pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
        for (const auto& pair : pairs) {
            const unsigned a = pair[0], b = pair[1];
            std::array<GiNaC::ex, 3> v = {
                shifted(a, 1) * shifted(b, 2) - shifted(a, 2) * shifted(b, 1),
                shifted(a, 2) * shifted(b, 0) - shifted(a, 0) * shifted(b, 2),
                shifted(a, 0) * shifted(b, 1) - shifted(a, 1) * shifted(b, 0)};
            for (GiNaC::ex& c : v)
                c = normal_with_pi(c.expand());
            if (v[0].is_zero() && v[1].is_zero() && v[2].is_zero())
                continue;
            // Scaled so that the last nonzero component is 1, as the mode vectors are.
            GiNaC::ex scale = !v[2].is_zero() ? v[2] : !v[1].is_zero() ? v[1] : v[0];
            for (unsigned i = 0; i < 3; ++i)
                axes(i, k) = normal_with_pi(v[i] / scale);
            found = true;
            break;
        }
        if (!found)
            return std::nullopt;
    }
    return axes;
}

} // namespace

GiNaC::matrix diagonal_tensor(const std::vector<GiNaC::ex>& moments)
{
    GiNaC::matrix m(3, 3);
    for (unsigned i = 0; i < 3; ++i)
        m(i, i) = moments[i];
    return m;
}

GiNaC::ex integrate_exactly(const GiNaC::ex& f, const GiNaC::realsymbol& variable, const GiNaC::ex& lower,
                            const GiNaC::ex& upper)
{
    GiNaC::ex e = f.expand();
    if (GiNaC::is_a<GiNaC::add>(e)) {
        GiNaC::exvector terms;
        for (const GiNaC::ex& term : e)
            terms.push_back(integrate_term(term, variable, lower, upper));
        return GiNaC::add(terms);
    }
    return integrate_term(e, variable, lower, upper);
}

GiNaC::matrix shifted_tensor(const GiNaC::matrix& tensor, const GiNaC::ex& mass, const std::vector<GiNaC::ex>& a)
{
    GiNaC::matrix result(3, 3);
    GiNaC::ex a2 = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
    for (unsigned i = 0; i < 3; ++i)
        for (unsigned j = 0; j < 3; ++j)
            result(i, j) = normal_with_pi((tensor(i, j) + mass * ((i == j ? a2 : GiNaC::ex(0)) - a[i] * a[j])).expand());
    return result;
}

GiNaC::matrix rotated_tensor(const GiNaC::matrix& tensor, const GiNaC::matrix& rotation)
{
    GiNaC::matrix product = rotation.mul(tensor).mul(rotation.transpose());
    for (unsigned i = 0; i < 3; ++i)
        for (unsigned j = 0; j < 3; ++j)
            product(i, j) = product(i, j).expand();
    return product;
}

GiNaC::matrix euler_rotation(const GiNaC::ex& phi, const GiNaC::ex& theta, const GiNaC::ex& psi)
{
    auto about_z = [](const GiNaC::ex& a) {
        return GiNaC::matrix{{GiNaC::cos(a), -GiNaC::sin(a), 0}, {GiNaC::sin(a), GiNaC::cos(a), 0}, {0, 0, 1}};
    };
    GiNaC::matrix about_x{{1, 0, 0}, {0, GiNaC::cos(theta), -GiNaC::sin(theta)}, {0, GiNaC::sin(theta), GiNaC::cos(theta)}};
    return about_z(phi).mul(about_x).mul(about_z(psi));
}

std::vector<GiNaC::ex> body_angular_velocity(const GiNaC::matrix& rotation, const model& scene)
{
    // The body-frame angular velocity is the axial vector of Rᵀ Ṙ (skew-symmetric).
    GiNaC::matrix rate(3, 3);
    for (unsigned i = 0; i < 3; ++i)
        for (unsigned j = 0; j < 3; ++j)
            rate(i, j) = time_derivative(rotation(i, j), scene);
    GiNaC::matrix skew = rotation.transpose().mul(rate);
    return {skew(2, 1), skew(0, 2), skew(1, 0)};
}

inertia_result derive_inertia(const rigid_body& body)
{
    inertia_result result;
    result.body = body.name;
    result.centre_of_mass = {0, 0, 0};
    if (body.body_kind == rigid_body::kind::inertia) {
        result.coordinates = "given";
        result.mass = body.mass;
        result.density = 0;
        if (body.tensor.size() == 9) {
            for (unsigned i = 0; i < 3; ++i)
                for (unsigned j = 0; j < 3; ++j)
                    result.tensor(i, j) = body.tensor[3 * i + j];
        } else {
            result.tensor = diagonal_tensor(body.moments);
        }
        // Given about a body point a from the centre of mass: I_cm = I_a − M (|a|² 1 − a aᵀ).
        if (body.about) {
            const std::vector<GiNaC::ex>& a = *body.about;
            for (unsigned i = 0; i < 3; ++i)
                for (unsigned j = 0; j < 3; ++j)
                    budget_check_terms(result.tensor(i, j) - body.mass * ((a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) -
                                                                          a[i] * a[j]),
                                       "the tensor moved to the centre of mass");
            result.tensor = shifted_tensor(result.tensor, -body.mass, a);
        }
    } else {
        region_map region = region_of(body.shape, body.dimensions);
        result.coordinates = region.coordinates;
        std::array<GiNaC::ex, 3> placed = permuted(region.natural, body.axis);
        // Deltas: natural x, y, z written as the body coordinates they become.
        const std::array<GiNaC::ex, 3> natural_as_body =
            body.axis == 'x'   ? std::array<GiNaC::ex, 3>{body.y, body.z, body.x}
            : body.axis == 'y' ? std::array<GiNaC::ex, 3>{body.z, body.x, body.y}
                               : std::array<GiNaC::ex, 3>{body.x, body.y, body.z};
        GiNaC::exmap natural_to_body;
        for (std::size_t k = 0; k < 3; ++k)
            natural_to_body[region.delta_symbols[k]] = natural_as_body[k];
        std::vector<GiNaC::ex> deltas;
        for (const GiNaC::ex& d : region.natural_deltas)
            deltas.push_back(d.subs(natural_to_body));

        GiNaC::exmap at_point = {{body.x, placed[0]}, {body.y, placed[1]}, {body.z, placed[2]}, {body.r, region.radius}};
        auto integral = [&](const std::string& quantity, const GiNaC::ex& density, const GiNaC::ex& weight,
                            const GiNaC::exmap& weight_at) {
            body_integral i;
            i.quantity = quantity;
            i.density = density;
            i.deltas = deltas;
            i.weight = weight;
            i.integrand = (density.subs(at_point) * weight.subs(weight_at) * region.jacobian).expand();
            i.limits = region.limits;
            i.value = integrate_over(i.integrand, region.limits);
            result.integrals.push_back(i);
            return i.value;
        };
        GiNaC::ex density;
        if (body.body_kind == rigid_body::kind::shape) {
            GiNaC::ex measure = integral("measure", 1, 1, at_point);
            result.mass = body.mass;
            density = normal_with_pi(body.mass / measure);
        } else {
            density = body.density;
            result.mass = integral("mass", density, 1, at_point);
            if (sign_at(result.mass, {}) == std::optional<int>(0))
                throw computation_error("body `" + body.name + "` has zero mass");
        }
        result.density = density;
        // The centre of mass from the first moments, then the second moments about it.
        const std::array<GiNaC::ex, 3> body_xyz = {body.x, body.y, body.z};
        const char* names[] = {"x", "y", "z"};
        for (std::size_t k = 0; k < 3; ++k)
            result.centre_of_mass[k] = normal_with_pi(integral(names[k], density, body_xyz[k], at_point) / result.mass);
        GiNaC::exmap about_centre = at_point;
        for (std::size_t k = 0; k < 3; ++k)
            about_centre[body_xyz[k]] = placed[k] - result.centre_of_mass[k];
        const GiNaC::ex r2 = body.x * body.x + body.y * body.y + body.z * body.z;
        for (unsigned i = 0; i < 3; ++i)
            for (unsigned j = i; j < 3; ++j) {
                GiNaC::ex weight = (i == j ? r2 : GiNaC::ex(0)) - body_xyz[i] * body_xyz[j];
                GiNaC::ex value = integral(std::string(names[i]) + names[j], density, weight, about_centre);
                result.tensor(i, j) = result.tensor(j, i) = value;
            }
    }
    for (unsigned i = 0; i < 3; ++i)
        for (unsigned j = 0; j < 3; ++j)
            if (i != j && !result.tensor(i, j).is_zero())
                result.diagonal = false;
    if (result.diagonal) {
        result.principal = {result.tensor(0, 0), result.tensor(1, 1), result.tensor(2, 2)};
        result.principal_axes = GiNaC::matrix{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    } else {
        result.principal = principal_moments(result.tensor);
        if (std::optional<GiNaC::matrix> axes = principal_directions(result.tensor, result.principal))
            result.principal_axes = axes;
    }
    if (body.position) {
        bool constant = true;
        for (const GiNaC::ex& c : *body.position)
            constant = constant && is_constant(c);
        if (constant)
            result.about_origin = shifted_tensor(result.tensor, result.mass, *body.position);
    }
    if (body.omega)
        result.omega.assign(body.omega->begin(), body.omega->end());
    else
        result.omega = {GiNaC::realsymbol("omega1"), GiNaC::realsymbol("omega2"), GiNaC::realsymbol("omega3")};
    GiNaC::matrix w{{result.omega[0]}, {result.omega[1]}, {result.omega[2]}};
    GiNaC::matrix l = result.tensor.mul(w);
    result.angular_momentum = {l(0, 0).expand(), l(1, 0).expand(), l(2, 0).expand()};
    result.kinetic_energy = (GiNaC::numeric(1, 2) * w.transpose().mul(l)(0, 0)).expand();
    return result;
}

} // namespace lagrange
