/** @file rigid_body.cpp
 *  Inertia by integration, Euler's equations, torque-free motion, Poinsot. */
#include "bodies/rigid_body.h"
#include "algebra/factor.h"

#include "algebra/calculus.h"

#include <Eigen/Eigenvalues>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

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

GiNaC::matrix diagonal_matrix(const std::vector<GiNaC::ex>& d)
{
    GiNaC::matrix m(3, 3);
    for (unsigned i = 0; i < 3; ++i)
        m(i, i) = d[i];
    return m;
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
    GiNaC::exvector factors;
    if (GiNaC::is_a<GiNaC::mul>(p))
        factors.assign(p.begin(), p.end());
    else
        factors.push_back(p);
    std::vector<GiNaC::ex> roots;
    for (const GiNaC::ex& f : factors) {
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

std::optional<double> number_of(const GiNaC::ex& e, const GiNaC::exmap& values)
{
    GiNaC::ex n = e.subs(values).evalf();
    if (!GiNaC::is_a<GiNaC::numeric>(n) || !GiNaC::ex_to<GiNaC::numeric>(n).is_real())
        return std::nullopt;
    return GiNaC::ex_to<GiNaC::numeric>(n).to_double();
}

/// The sign of e: +1, −1, 0, or nothing if it cannot be told (also at `values`).
std::optional<int> sign_of(const GiNaC::ex& e, const GiNaC::exmap& values)
{
    GiNaC::ex n = factor_with_pi(e);
    if (n.is_zero())
        return 0;
    if (n.info(GiNaC::info_flags::positive))
        return 1;
    if ((-n).info(GiNaC::info_flags::positive))
        return -1;
    if (std::optional<double> x = number_of(n, values)) {
        if (std::abs(*x) < 1e-14 * (1 + std::abs(*x)))
            return 0;
        return *x > 0 ? 1 : -1;
    }
    return std::nullopt;
}

} // namespace

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
        result.tensor = diagonal_matrix(body.moments);
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
            if (sign_of(result.mass, {}) == std::optional<int>(0))
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

std::array<double, 3> euler_result::elliptic_solution::evaluate(double t) const
{
    double cn = 0, dn = 0;
    double sn = boost::math::jacobi_elliptic(modulus, rate * t + phase, &cn, &dn);
    std::array<double, 3> w{};
    w[roles[0]] = amplitudes[0] * cn;
    w[roles[1]] = amplitudes[1] * sn;
    w[roles[2]] = amplitudes[2] * dn;
    return w;
}

namespace {

/// The asymmetric torque-free solution in Jacobi elliptic functions (Landau & Lifshitz §37),
/// for moments I and initial ω; nothing for a degenerate case (an axis rotation, the separatrix).
std::optional<euler_result::elliptic_solution> elliptic_motion(const std::array<double, 3>& I,
                                                               const std::array<double, 3>& w0)
{
    euler_result::elliptic_solution s;
    s.moments = I;
    s.initial = w0;
    double two_t = 0, l2 = 0;
    for (int i = 0; i < 3; ++i) {
        two_t += I[i] * w0[i] * w0[i];
        l2 += I[i] * I[i] * w0[i] * w0[i];
    }
    s.energy = two_t / 2;
    s.momentum_squared = l2;
    std::array<std::size_t, 3> order = {0, 1, 2};
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return I[a] < I[b]; });
    const std::size_t a = order[0], b = order[1], c = order[2];
    const double Ia = I[a], Ib = I[b], Ic = I[c];
    const double scale = std::max({std::abs(two_t * Ic), std::abs(l2), 1e-300});
    if (Ib - Ia <= 1e-12 * Ic || Ic - Ib <= 1e-12 * Ic)
        return std::nullopt;
    const double above = l2 - two_t * Ia, below = two_t * Ic - l2;
    if (above <= 1e-13 * scale || below <= 1e-13 * scale || std::abs(l2 - two_t * Ib) <= 1e-12 * scale)
        return std::nullopt;
    double k2 = 0;
    if (l2 > two_t * Ib) { // ω about the axis of the largest moment keeps its sign: dn there
        s.roles = {a, b, c};
        s.amplitudes = {std::sqrt(below / (Ia * (Ic - Ia))), std::sqrt(below / (Ib * (Ic - Ib))),
                        std::sqrt(above / (Ic * (Ic - Ia)))};
        s.rate = std::sqrt((Ic - Ib) * above / (Ia * Ib * Ic));
        k2 = (Ib - Ia) * below / ((Ic - Ib) * above);
    } else { // about the axis of the smallest moment
        s.roles = {c, b, a};
        s.amplitudes = {std::sqrt(above / (Ic * (Ic - Ia))), std::sqrt(above / (Ib * (Ib - Ia))),
                        std::sqrt(below / (Ia * (Ic - Ia)))};
        s.rate = std::sqrt((Ib - Ia) * below / (Ia * Ib * Ic));
        k2 = (Ic - Ib) * above / ((Ib - Ia) * below);
    }
    if (!(k2 > 0 && k2 < 1))
        return std::nullopt;
    s.modulus = std::sqrt(k2);
    // Parity: with amplitudes positive the triple solves Euler's equations when the cn
    // equation I_p ω̇_p = (I_{p+1} − I_{p+2}) ω_{p+1} ω_{p+2} holds in sign; else flip sn.
    const std::size_t p = s.roles[0];
    const double lhs = -I[p] * s.amplitudes[0] * s.rate;
    const double rhs = (I[(p + 1) % 3] - I[(p + 2) % 3]) * s.amplitudes[1] * s.amplitudes[2];
    if ((lhs > 0) != (rhs > 0))
        s.amplitudes[1] = -s.amplitudes[1];
    // Flipping two components is a symmetry of the equations: match the sign of the dn component.
    if ((w0[s.roles[2]] < 0) != (s.amplitudes[2] < 0)) {
        s.amplitudes[2] = -s.amplitudes[2];
        s.amplitudes[0] = -s.amplitudes[0];
    }
    const double amplitude_angle = std::atan2(w0[s.roles[1]] / s.amplitudes[1], w0[s.roles[0]] / s.amplitudes[0]);
    s.phase = boost::math::ellint_1(s.modulus, amplitude_angle);
    s.period = 4 * boost::math::ellint_1(s.modulus) / s.rate;
    return s;
}

} // namespace

euler_result derive_euler(const rigid_body& body, const inertia_result& inertia,
                          const std::optional<initial_state>& initial, const GiNaC::exmap& values)
{
    if (!body.omega)
        throw std::invalid_argument("body `" + body.name + "` has no `omega`");
    euler_result result;
    result.body = body.name;
    result.omega.assign(body.omega->begin(), body.omega->end());
    result.rates.assign(body.omega_rates.begin(), body.omega_rates.end());
    const std::vector<GiNaC::ex>& w = result.omega;
    const std::vector<GiNaC::ex>& dw = result.rates;
    for (const GiNaC::ex& n : body.torque)
        result.torque_free = result.torque_free && n.is_zero();

    // dL/dt|space = dL/dt|body + ω × L = N with L = I ω and I constant in the body frame.
    auto euler_equations = [&](const GiNaC::matrix& tensor) {
        GiNaC::matrix omega{{w[0]}, {w[1]}, {w[2]}}, rates{{dw[0]}, {dw[1]}, {dw[2]}};
        GiNaC::matrix l = tensor.mul(omega), l_rate = tensor.mul(rates);
        std::vector<GiNaC::ex> equations;
        for (unsigned i = 0; i < 3; ++i) {
            const unsigned j = (i + 1) % 3, k = (i + 2) % 3;
            GiNaC::ex cross = w[j] * l(k, 0) - w[k] * l(j, 0);
            equations.push_back((l_rate(i, 0) + cross - body.torque[i]).expand());
        }
        return equations;
    };
    result.equations = euler_equations(inertia.tensor);
    if (inertia.diagonal) {
        result.moments = inertia.principal;
    } else if (inertia.principal.size() == 3) {
        result.moments = inertia.principal;
        result.principal_equations = euler_equations(diagonal_matrix(inertia.principal));
    }
    if (result.moments.size() != 3)
        return result;
    const std::vector<GiNaC::ex>& I = result.moments;
    result.kinetic_energy = 0;
    result.angular_momentum_squared = 0;
    for (int i = 0; i < 3; ++i) {
        result.kinetic_energy += GiNaC::numeric(1, 2) * I[i] * w[i] * w[i];
        result.angular_momentum_squared += I[i] * I[i] * w[i] * w[i];
    }
    // Stability of steady rotation about axis i: small deviations obey
    // δω̈_j = (I_i − I_j)(I_k − I_i) ω_i² / (I_j I_k) δω_j, so rotation is stable when
    // (I_i − I_j)(I_i − I_k) > 0 (largest or smallest moment), unstable when < 0.
    for (int i = 0; i < 3; ++i) {
        std::optional<int> sign = sign_of((I[i] - I[(i + 1) % 3]) * (I[i] - I[(i + 2) % 3]), values);
        result.stability.push_back(!sign ? "unknown" : *sign > 0 ? "stable" : *sign < 0 ? "unstable" : "marginal");
    }
    if (!result.torque_free)
        return result;

    std::vector<GiNaC::ex> start;
    bool numbers = initial.has_value();
    for (const GiNaC::ex& wi : w) {
        const std::string name = GiNaC::ex_to<GiNaC::symbol>(wi).get_name();
        if (initial) {
            auto found = initial->others.find(name);
            start.push_back(found == initial->others.end() ? GiNaC::ex(0) : found->second);
        } else {
            start.push_back(GiNaC::realsymbol(name + "_0"));
        }
    }
    // Symmetric body: two equal moments.
    std::optional<std::size_t> axis;
    for (std::size_t a = 0; a < 3 && !axis; ++a)
        if (normal_with_pi(I[(a + 1) % 3] - I[(a + 2) % 3]).is_zero())
            axis = a;
    if (axis) {
        euler_result::symmetric_solution s;
        const std::size_t a = *axis, b = (a + 1) % 3, c = (a + 2) % 3;
        s.axis = a;
        const GiNaC::ex transverse = I[b];
        s.precession = normal_with_pi((I[a] - transverse) * start[a] / transverse);
        s.constants = start;
        GiNaC::realsymbol t("t");
        s.time = t;
        s.omega.resize(3);
        // ω̇_b = −Ω ω_c, ω̇_c = Ω ω_b: a rotation of (ω_b, ω_c) at the rate Ω.
        s.omega[a] = start[a];
        s.omega[b] = start[b] * GiNaC::cos(s.precession * t) - start[c] * GiNaC::sin(s.precession * t);
        s.omega[c] = start[c] * GiNaC::cos(s.precession * t) + start[b] * GiNaC::sin(s.precession * t);
        result.symmetric = s;
    }
    if (!numbers)
        return result;
    std::array<double, 3> moments{}, w0{};
    for (int i = 0; i < 3; ++i) {
        std::optional<double> m = number_of(I[i], values), v = number_of(start[i], values);
        if (!m || !v || *m <= 0)
            return result;
        moments[i] = *m;
        w0[i] = *v;
    }
    euler_result::poinsot_construction poinsot;
    double two_t = 0, l2 = 0;
    for (int i = 0; i < 3; ++i) {
        two_t += moments[i] * w0[i] * w0[i];
        l2 += moments[i] * moments[i] * w0[i] * w0[i];
    }
    if (two_t <= 0)
        return result;
    for (int i = 0; i < 3; ++i)
        poinsot.ellipsoid_axes[i] = std::sqrt(two_t / moments[i]);
    poinsot.plane_distance = two_t / std::sqrt(l2);
    constexpr int polhode_points = 64;
    if (!axis) {
        result.elliptic = elliptic_motion(moments, w0);
        if (result.elliptic)
            for (int n = 0; n < polhode_points; ++n)
                poinsot.polhode.push_back(result.elliptic->evaluate(result.elliptic->period * n / polhode_points));
    } else {
        const std::size_t a = *axis, b = (a + 1) % 3, c = (a + 2) % 3;
        const double omega_p = (moments[a] - moments[b]) * w0[a] / moments[b];
        const double period = omega_p != 0 ? 2 * M_PI / std::abs(omega_p) : 0;
        for (int n = 0; n < polhode_points && period > 0; ++n) {
            const double angle = omega_p * period * n / polhode_points;
            std::array<double, 3> p{};
            p[a] = w0[a];
            p[b] = w0[b] * std::cos(angle) - w0[c] * std::sin(angle);
            p[c] = w0[c] * std::cos(angle) + w0[b] * std::sin(angle);
            poinsot.polhode.push_back(p);
        }
    }
    result.poinsot = poinsot;
    return result;
}

} // namespace lagrange
