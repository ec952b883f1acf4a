// SPDX-License-Identifier: GPL-2.0-or-later
/** @file inertia_cubature.cpp
 *  A body's mass, centre of mass and inertia tensor at numbers, by cubature over the
 *  region as described here (see check_bodies.h), the references of the inertia checks. */
#include "verify/check_bodies.h"

#include "program/expression_program.h"
#include "numeric/values.h"

#include <Eigen/Dense>
#include <boost/math/quadrature/gauss.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace lagrange {

using GiNaC::ex;

namespace {

// ---- cubature ----

/// One node of a rule: a point of the region (natural axes, symmetry axis z) and its
/// weight, the Jacobian included.
struct node {
    std::array<double, 3> point;
    double weight;
};

using rule_1d = std::vector<std::pair<double, double>>; ///< (abscissa, weight)

/// Gauss–Legendre on [a, b] from Boost's table of 10 points: exact for polynomials of
/// degree up to 19. The integrands below are polynomials in each variable of degree at
/// most 8 (the density) + 2 (the weight) + 2 (the Jacobian), so the rules are exact up
/// to rounding.
rule_1d legendre(double a, double b)
{
    using rule = boost::math::quadrature::gauss<double, 10>;
    const double middle = (a + b) / 2, half = (b - a) / 2;
    rule_1d nodes;
    for (std::size_t i = 0; i < rule::abscissa().size(); ++i) {
        const double x = rule::abscissa()[i], w = rule::weights()[i];
        nodes.push_back({middle + half * x, half * w});
        if (x != 0)
            nodes.push_back({middle - half * x, half * w});
    }
    return nodes;
}

/// A full turn: the trapezoidal rule with 16 points is exact for trigonometric
/// polynomials of degree below 16 (the integrands have degree at most 10 in φ).
const rule_1d& turn()
{
    static const rule_1d nodes = [] {
        constexpr int count = 16;
        rule_1d n;
        for (int k = 0; k < count; ++k)
            n.push_back({2 * M_PI * k / count, 2 * M_PI / count});
        return n;
    }();
    return nodes;
}

/// The region of a shape with dimensions d, as nodes. This describes each shape anew
/// (lib/bodies/inertia.cpp has its own description, in θ) so that the two share nothing.
/// The polar direction is u = cos θ in [−1, 1] with sin θ = √(1 − u²) (dV = r² dr du dφ):
/// after the turn in φ only even powers of sin θ remain, so the integrands are
/// polynomials in u and Gauss–Legendre is exact in u as well.
std::optional<std::vector<node>> region_nodes(const std::string& shape, const std::vector<double>& d)
{
    std::vector<node> nodes;
    auto add = [&](double x, double y, double z, double w) { nodes.push_back({{x, y, z}, w}); };
    const rule_1d polar = legendre(-1, 1), unit = legendre(0, 1);
    if (shape == "stick" || shape == "segment") {
        for (auto [s, w] : legendre(-d[0] / 2, d[0] / 2))
            add(0, 0, s, w);
    } else if (shape == "ring" || shape == "circle") {
        for (auto [phi, w] : turn())
            add(d[0] * std::cos(phi), d[0] * std::sin(phi), 0, d[0] * w);
    } else if (shape == "disk") {
        for (auto [rho, wr] : legendre(0, d[0]))
            for (auto [phi, wp] : turn())
                add(rho * std::cos(phi), rho * std::sin(phi), 0, rho * wr * wp);
    } else if (shape == "sphere" || shape == "shell") {
        for (auto [u, wu] : polar)
            for (auto [phi, wp] : turn()) {
                const double s = std::sqrt(1 - u * u);
                add(d[0] * s * std::cos(phi), d[0] * s * std::sin(phi), d[0] * u, d[0] * d[0] * wu * wp);
            }
    } else if (shape == "ball" || shape == "ellipsoid") {
        // An ellipsoid is the unit ball stretched by its semi-axes: Jacobian a b c r².
        const bool ball = shape == "ball";
        const double a = d[0], b = ball ? d[0] : d[1], c = ball ? d[0] : d[2];
        for (auto [r, wr] : unit)
            for (auto [u, wu] : polar)
                for (auto [phi, wp] : turn()) {
                    const double s = r * std::sqrt(1 - u * u);
                    add(a * s * std::cos(phi), b * s * std::sin(phi), c * r * u, a * b * c * r * r * wr * wu * wp);
                }
    } else if (shape == "box") {
        for (auto [x, wx] : legendre(-d[0] / 2, d[0] / 2))
            for (auto [y, wy] : legendre(-d[1] / 2, d[1] / 2))
                for (auto [z, wz] : legendre(-d[2] / 2, d[2] / 2))
                    add(x, y, z, wx * wy * wz);
    } else if (shape == "cylinder") {
        for (auto [rho, wr] : legendre(0, d[0]))
            for (auto [phi, wp] : turn())
                for (auto [z, wz] : legendre(-d[1] / 2, d[1] / 2))
                    add(rho * std::cos(phi), rho * std::sin(phi), z, rho * wr * wp * wz);
    } else if (shape == "cone") {
        // Base of radius R on z = 0, apex at z = h: the disk at height z has radius R (1 − z/h).
        for (auto [z, wz] : legendre(0, d[1]))
            for (auto [rho, wr] : legendre(0, d[0] * (1 - z / d[1])))
                for (auto [phi, wp] : turn())
                    add(rho * std::cos(phi), rho * std::sin(phi), z, rho * wr * wp * wz);
    } else {
        return std::nullopt;
    }
    return nodes;
}

/// Natural axes (symmetry axis z) to body axes: the symmetry axis becomes `axis`, and the
/// other two follow cyclically.
std::array<double, 3> to_body(const std::array<double, 3>& n, char axis)
{
    const int a = axis == 'x' ? 0 : axis == 'y' ? 1 : 2;
    std::array<double, 3> b{};
    b[static_cast<std::size_t>(a)] = n[2];
    b[static_cast<std::size_t>((a + 1) % 3)] = n[0];
    b[static_cast<std::size_t>((a + 2) % 3)] = n[1];
    return b;
}

Eigen::Vector3d vector_of(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }



std::optional<numeric_body> given_inertia(const rigid_body& body, const GiNaC::exmap& at)
{
    numeric_body result;
    std::optional<double> mass = real_at(body.mass, at);
    std::optional<std::vector<double>> entries = numbers_at(body.tensor.empty() ? body.moments : body.tensor, at);
    if (!mass || !entries)
        return std::nullopt;
    result.mass = *mass;
    for (unsigned i = 0; i < 3; ++i)
        for (unsigned j = 0; j < 3; ++j)
            result.tensor(i, j) = body.tensor.empty() ? (i == j ? (*entries)[i] : 0.0) : (*entries)[3 * i + j];
    if (body.about) {
        std::optional<std::vector<double>> a = numbers_at(*body.about, at);
        if (!a)
            return std::nullopt;
        const Eigen::Vector3d offset((*a)[0], (*a)[1], (*a)[2]);
        result.tensor -= parallel_axis(result.mass, offset);
        result.extent = offset.norm();
    }
    return result;
}

} // namespace

/// M (|a|² 1 − a aᵀ): the parallel-axis term.
Eigen::Matrix3d parallel_axis(double mass, const Eigen::Vector3d& a)
{
    return mass * (a.squaredNorm() * Eigen::Matrix3d::Identity() - a * a.transpose());
}

std::optional<std::vector<double>> numbers_at(const std::vector<ex>& list, const GiNaC::exmap& at)
{
    std::vector<double> out;
    for (const ex& e : list) {
        std::optional<double> x = real_at(e, at);
        if (!x)
            return std::nullopt;
        out.push_back(*x);
    }
    return out;
}

std::optional<numeric_body> numeric_inertia(const rigid_body& body, const GiNaC::exmap& at)
{
    if (body.body_kind == rigid_body::kind::inertia)
        return given_inertia(body, at);
    std::optional<std::vector<double>> dimensions = numbers_at(body.dimensions, at);
    if (!dimensions)
        return std::nullopt;
    for (double d : *dimensions)
        if (!(d > 0))
            return std::nullopt;
    std::optional<std::vector<node>> nodes = region_nodes(body.shape, *dimensions);
    if (!nodes)
        return std::nullopt;
    std::vector<std::array<double, 3>> points;
    for (const node& n : *nodes)
        points.push_back(to_body(n.point, body.axis));

    // The density at every node: M / measure for a uniform shape, else the scene's ρ(x, y, z, r).
    numeric_body result;
    for (const node& n : *nodes)
        result.measure += n.weight;
    std::vector<double> density(nodes->size());
    if (body.body_kind == rigid_body::kind::shape) {
        std::optional<double> mass = real_at(body.mass, at);
        if (!mass || result.measure == 0)
            return std::nullopt;
        std::fill(density.begin(), density.end(), *mass / result.measure);
    } else {
        std::optional<expression_program> program;
        try {
            program.emplace(std::vector<ex>{body.density.subs(at)}, std::vector<ex>{body.x, body.y, body.z, body.r});
        } catch (const std::invalid_argument&) {
            return std::nullopt;
        }
        std::vector<double> scratch;
        for (std::size_t k = 0; k < points.size(); ++k) {
            const std::array<double, 3>& p = points[k];
            const double symbols[4] = {p[0], p[1], p[2], std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2])};
            program->run(symbols, scratch, &density[k]);
            if (!std::isfinite(density[k]))
                return std::nullopt;
        }
    }
    // The mass and first moments, then the second moments about the centre of mass.
    for (std::size_t k = 0; k < points.size(); ++k) {
        const double dm = density[k] * (*nodes)[k].weight;
        result.mass += dm;
        for (std::size_t i = 0; i < 3; ++i)
            result.first_moments[i] += dm * points[k][i];
        result.extent = std::max(result.extent, std::sqrt(points[k][0] * points[k][0] + points[k][1] * points[k][1] +
                                                          points[k][2] * points[k][2]));
    }
    if (!(std::abs(result.mass) > 0))
        return std::nullopt;
    for (std::size_t i = 0; i < 3; ++i)
        result.centre_of_mass[i] = result.first_moments[i] / result.mass;
    for (std::size_t k = 0; k < points.size(); ++k) {
        const double dm = density[k] * (*nodes)[k].weight;
        const Eigen::Vector3d x = vector_of(points[k]) - vector_of(result.centre_of_mass);
        result.tensor += dm * (x.squaredNorm() * Eigen::Matrix3d::Identity() - x * x.transpose());
    }
    return result;
}

} // namespace lagrange
