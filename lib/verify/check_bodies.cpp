// SPDX-License-Identifier: GPL-2.0-or-later
/** @file check_bodies.cpp
 *  Numeric checks of the inertia and Euler results: cubature of the density over each
 *  shape's own parametrization, the parallel-axis shift of given tensors, Euler's
 *  equations formed numerically, and torque-free solutions against Boost.Odeint. */
#include "verify/check_bodies.h"

#include "core/errors.h"
#include "program/expression_program.h"
#include "numeric/values.h"

#include <Eigen/Dense>
#include <boost/numeric/odeint.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

namespace lagrange {

namespace {

using GiNaC::ex;

/// Agreement asked of a symbolic result and its cubature: the rules below are exact for
/// the polynomial densities the engine integrates (up to rounding, about 1e-14).
constexpr double tolerance = 1e-9;
/// Agreement of a closed-form ω(t) with the numeric integration (tolerance 1e-12 per step).
constexpr double motion_tolerance = 1e-8;
constexpr int attempts = 6;
constexpr int points_wanted = 2;

const char* const axis_names[] = {"x", "y", "z"};

// ---- parameter points ----

/// Parameter values: each `values` line's, the others (and every one after the lines)
/// seeded multiples of 1/64 in [1/2, 2], exact rationals, so that every run and every
/// message is the same.
struct body_point {
    GiNaC::exmap map;
    std::string text; ///< "M = 1.25, R = 0.75"
};

/// A seeded sequence of multiples of 1/64 (exact in double and as rationals).
class sampler {
public:
    explicit sampler(std::uint64_t seed) : state_(seed) {}
    /// In [lo, hi], for lo and hi multiples of 1/64.
    GiNaC::numeric rational(double lo, double hi)
    {
        state_ = state_ * 6364136223846793005ULL + 1442695040888963407ULL;
        const auto steps = static_cast<std::uint64_t>((hi - lo) * 64) + 1;
        return GiNaC::numeric(static_cast<long>(lo * 64) + static_cast<long>((state_ >> 33) % steps), 64);
    }

private:
    std::uint64_t state_;
};

std::vector<body_point> parameter_points(const model& scene)
{
    std::vector<body_point> points;
    sampler random(0x626f64696573ULL); // "bodies"
    auto uniform = [&] { return random.rational(0.5, 2); };
    for (int attempt = 0; attempt < attempts; ++attempt) {
        GiNaC::exmap given;
        if (attempt < static_cast<int>(scene.values.size()))
            given = value_map(scene, scene.values[static_cast<std::size_t>(attempt)]);
        body_point p;
        for (const parameter& parameter : scene.parameters) {
            ex x = uniform();
            auto found = given.find(parameter.symbol);
            if (found != given.end() && real_at(found->second, {}))
                x = found->second;
            p.map[parameter.symbol] = x;
            p.text += (p.text.empty() ? "" : ", ") + parameter.name + " = " + message_number(*real_at(x, {}));
        }
        if (p.text.empty())
            p.text = "the numbers given";
        points.push_back(std::move(p));
    }
    return points;
}

[[noreturn]] void fail(const std::string& product, const std::string& what, const std::string& where, double here,
                       double reference)
{
    throw computation_error("verification failed: " + product + ": " + what + " at " + where + " is " +
                            message_number(here, 10) + ", but " + message_number(reference, 10) +
                            " by the independent check; the result is not printed");
}

[[noreturn]] void not_real(const std::string& product, const std::string& what, const std::string& where)
{
    throw computation_error("verification failed: " + product + ": " + what + " is not a real number at " + where +
                            "; the result is not printed");
}

/// A printed expression at a point, compared with its reference within tolerance·scale.
struct comparer {
    std::string product;
    std::string where;
    double tolerance;

    double value(const ex& e, const GiNaC::exmap& at, const std::string& what) const
    {
        std::optional<double> x = real_at(e, at);
        if (!x)
            not_real(product, what, where);
        return *x;
    }
    void expect(double here, double reference, double scale, const std::string& what) const
    {
        if (!(std::abs(here - reference) <= tolerance * scale))
            fail(product, what, where, here, reference);
    }
    void expect(const ex& e, const GiNaC::exmap& at, double reference, double scale, const std::string& what) const
    {
        expect(value(e, at, what), reference, scale, what);
    }
};

} // namespace

namespace {

// ---- the inertia ----

/// The references of one body at one point, kept for the Euler checks.
struct checked_body {
    numeric_body reference;
    std::vector<double> principal; ///< the printed principal moments at the point (verified)
};

double trace_scale(const Eigen::Matrix3d& tensor)
{
    return std::max(std::abs(tensor.trace()), 1e-300);
}

/// Checks one body at one point; throws on a disagreement.
void check_inertia(const rigid_body& body, const inertia_result& in, const numeric_body& ref, const body_point& p,
                   checked_body& out)
{
    const comparer c{"the inertia", p.text, tolerance};
    const std::string of = " of body " + in.body;
    const GiNaC::exmap& at = p.map;
    const double scale = trace_scale(ref.tensor);
    c.expect(in.mass, at, ref.mass, std::abs(ref.mass), "the mass" + of);
    if (body.body_kind == rigid_body::kind::shape)
        c.expect(in.density, at, ref.mass / ref.measure, std::abs(ref.mass / ref.measure), "the density" + of);
    if (!in.integrals.empty())
        for (std::size_t i = 0; i < 3; ++i)
            c.expect(in.centre_of_mass[i], at, ref.centre_of_mass[i], ref.extent,
                     "the centre of mass's " + std::string(axis_names[i]) + of);
    // Each printed integral: the measure, the mass, a first moment about the region's
    // centre, or a second moment (an entry of the tensor) about the centre of mass.
    for (const body_integral& integral : in.integrals) {
        const std::string what = "the integral " + integral.quantity + of;
        const std::string& q = integral.quantity;
        if (q == "measure")
            c.expect(integral.value, at, ref.measure, std::abs(ref.measure), what);
        else if (q == "mass")
            c.expect(integral.value, at, ref.mass, std::abs(ref.mass), what);
        else if (q.size() == 1)
            c.expect(integral.value, at, ref.first_moments[static_cast<std::size_t>(q[0] - 'x')],
                     std::abs(ref.mass) * ref.extent, what);
        else if (q.size() == 2)
            c.expect(integral.value, at, ref.tensor(q[0] - 'x', q[1] - 'x'), scale, what);
    }
    for (unsigned i = 0; i < 3; ++i)
        for (unsigned j = 0; j < 3; ++j)
            c.expect(in.tensor(i, j), at, ref.tensor(i, j), scale,
                     "I_" + std::string(axis_names[i]) + axis_names[j] + of);
    // Principal moments: as a multiset, against the eigenvalues of the reference tensor.
    out.principal.clear();
    if (in.principal.size() == 3) {
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(ref.tensor, Eigen::EigenvaluesOnly);
        std::vector<std::pair<double, std::size_t>> printed;
        for (std::size_t k = 0; k < 3; ++k) {
            out.principal.push_back(c.value(in.principal[k], at, "principal moment " + std::to_string(k + 1) + of));
            printed.push_back({out.principal.back(), k});
        }
        std::sort(printed.begin(), printed.end());
        for (std::size_t k = 0; k < 3; ++k)
            c.expect(printed[k].first, solver.eigenvalues()[static_cast<Eigen::Index>(k)], scale,
                     "principal moment " + std::to_string(printed[k].second + 1) + of + " (number " +
                         std::to_string(k + 1) + " in ascending order)");
        if (in.principal_axes)
            for (unsigned k = 0; k < 3; ++k) {
                const std::string what = "the principal axis of moment " + std::to_string(k + 1) + of;
                Eigen::Vector3d a;
                for (unsigned i = 0; i < 3; ++i)
                    a[i] = c.value((*in.principal_axes)(i, k), at, what);
                const double residual = ((ref.tensor - out.principal[k] * Eigen::Matrix3d::Identity()) * a).norm();
                if (!(a.norm() > 0))
                    fail("the inertia", what + " (its length)", p.text, 0, 1);
                c.expect(residual, 0, scale * a.norm(), "|(I − λ) a| for " + what);
            }
    }
    if (in.about_origin && body.position) {
        std::optional<std::vector<double>> position = numbers_at(*body.position, at);
        if (!position)
            not_real("the inertia", "the position of body " + in.body, p.text);
        const Eigen::Matrix3d shifted =
            ref.tensor + parallel_axis(ref.mass, Eigen::Vector3d((*position)[0], (*position)[1], (*position)[2]));
        for (unsigned i = 0; i < 3; ++i)
            for (unsigned j = 0; j < 3; ++j)
                c.expect((*in.about_origin)(i, j), at, shifted(i, j), trace_scale(shifted),
                         "the entry (" + std::to_string(i + 1) + ", " + std::to_string(j + 1) +
                             ") about the origin" + of);
    }
    // L = I ω and T = ½ ωᵀ I ω at a fixed ω with distinct components.
    GiNaC::exmap with_omega = at;
    const Eigen::Vector3d omega(0.75, -0.5, 1.25);
    for (unsigned k = 0; k < 3 && k < in.omega.size(); ++k)
        with_omega[in.omega[k]] = GiNaC::numeric(static_cast<long>(omega[k] * 4), 4);
    const Eigen::Vector3d momentum = ref.tensor * omega;
    const comparer at_omega{"the inertia", p.text + " and ω = (0.75, -0.5, 1.25)", tolerance};
    for (unsigned k = 0; k < 3; ++k)
        at_omega.expect(in.angular_momentum[k], with_omega, momentum[k], scale * omega.norm(),
                        "L_" + std::string(axis_names[k]) + of);
    at_omega.expect(in.kinetic_energy, with_omega, omega.dot(momentum) / 2, scale * omega.squaredNorm(),
                    "T" + of);
}

// ---- Euler's equations ----

using omega_state = std::array<double, 3>;

/// ω(t) of the torque-free Euler equations I ω̇ = −ω × I ω from ω(0), at each of `times`
/// (ascending), by Boost.Odeint's controlled Runge–Kutta–Fehlberg 7(8) at tolerance 1e-13.
std::vector<omega_state> integrate_free(const Eigen::Matrix3d& tensor, const omega_state& start,
                                        const std::vector<double>& times)
{
    namespace odeint = boost::numeric::odeint;
    const Eigen::Matrix3d inverse = tensor.inverse();
    auto rhs = [&](const omega_state& w, omega_state& dw, double) {
        const Eigen::Vector3d omega(w[0], w[1], w[2]);
        const Eigen::Vector3d rate = -inverse * omega.cross(tensor * omega);
        dw = {rate[0], rate[1], rate[2]};
    };
    // The absolute tolerance in ω's own scale: a body turning at 1e-6 rad/s would otherwise be
    // integrated to a relative 1e-7 only, and its closed form judged against that.
    const double size = std::max(std::sqrt(start[0] * start[0] + start[1] * start[1] + start[2] * start[2]), 1e-300);
    auto stepper = odeint::make_controlled(1e-13 * size, 1e-13, odeint::runge_kutta_fehlberg78<omega_state>());
    std::vector<omega_state> out;
    omega_state w = start;
    double t = 0;
    for (double next : times) {
        if (next > t)
            odeint::integrate_adaptive(stepper, rhs, w, t, next, (next - t) / 64);
        t = next;
        out.push_back(w);
    }
    return out;
}

std::string omega_text(const std::vector<ex>& names, const Eigen::Vector3d& w)
{
    std::string text;
    for (unsigned k = 0; k < 3; ++k)
        text += (k ? ", " : "") + GiNaC::ex_to<GiNaC::symbol>(names[k]).get_name() + " = " + message_number(w[k]);
    return text;
}

/// A state of a free body: ω, ω̇ in [−1, 1] and t in [0, 1], seeded, with the parameters.
struct euler_state {
    Eigen::Vector3d omega, rates;
    GiNaC::exmap map;
    std::string text;
};

euler_state random_state(const model& scene, const euler_result& e, const body_point& p, sampler& random)
{
    euler_state s{{}, {}, p.map, p.text};
    auto draw = [&](const ex& symbol, double& value) {
        const GiNaC::numeric x = random.rational(-1, 1);
        value = x.to_double();
        s.map[symbol] = x;
        s.text += ", " + GiNaC::ex_to<GiNaC::symbol>(symbol).get_name() + " = " + message_number(value);
    };
    for (unsigned k = 0; k < 3; ++k)
        draw(e.omega[k], s.omega[k]);
    for (unsigned k = 0; k < 3; ++k)
        draw(e.rates[k], s.rates[k]);
    const GiNaC::numeric t = random.rational(0, 1);
    s.map[scene.time] = t;
    s.text += ", t = " + message_number(t.to_double());
    return s;
}

/// The printed equations (each = 0) against I ω̇ + ω × I ω − N at a state.
void check_equations(const rigid_body& body, const std::vector<ex>& equations, const Eigen::Matrix3d& tensor,
                     const euler_result& e, const euler_state& state, const std::string& which)
{
    const comparer c{"Euler's equations", state.text, tolerance};
    Eigen::Vector3d torque;
    for (unsigned k = 0; k < 3; ++k)
        torque[k] = c.value(body.torque[k], state.map, "the torque of body " + e.body);
    const Eigen::Vector3d& w = state.omega;
    const Eigen::Vector3d momentum = tensor * w, rate = tensor * state.rates, cross = w.cross(momentum);
    const Eigen::Vector3d reference = rate + cross - torque;
    for (unsigned k = 0; k < 3; ++k) {
        const double scale = std::abs(rate[k]) + std::abs(cross[k]) + std::abs(torque[k]) + 1e-300;
        c.expect(equations[k], state.map, reference[k], scale,
                 which + " of " + GiNaC::ex_to<GiNaC::symbol>(e.rates[k]).get_name() + " of body " + e.body);
    }
}

/// The symmetric torque-free solution ω(t) against the numeric integration of Euler's
/// equations with `tensor` from its own ω(0), over one turn of the precession.
void check_symmetric(const euler_result& e, const Eigen::Matrix3d& tensor, const body_point& p)
{
    const euler_result::symmetric_solution& s = *e.symmetric;
    GiNaC::exmap at = p.map;
    // Symbols among the constants ω(0) take distinct values.
    const double chosen[3] = {0.5, -0.75, 1.25};
    for (unsigned k = 0; k < 3; ++k)
        if (GiNaC::is_a<GiNaC::symbol>(s.constants[k]))
            at[s.constants[k]] = GiNaC::numeric(static_cast<long>(chosen[k] * 4), 4);
    std::string where = p.text;
    omega_state start{};
    for (unsigned k = 0; k < 3; ++k) {
        const comparer c{"Euler's equations", where, motion_tolerance};
        start[k] = c.value(s.constants[k], at, "ω(0)");
    }
    const Eigen::Vector3d w0(start[0], start[1], start[2]);
    where += " and " + omega_text(e.omega, w0) + " at t = 0";
    const comparer c{"Euler's equations", where, motion_tolerance};
    // The precession rate from the numeric equations: the turning rate of the transverse
    // components, (ω_b ω̇_c − ω_c ω̇_b) / (ω_b² + ω_c²).
    const std::size_t a = s.axis, b = (a + 1) % 3, d = (a + 2) % 3;
    const Eigen::Vector3d rate = -tensor.inverse() * w0.cross(tensor * w0);
    const double transverse = w0[b] * w0[b] + w0[d] * w0[d];
    double omega_p = 0;
    if (transverse > 0) {
        omega_p = (w0[b] * rate[d] - w0[d] * rate[b]) / transverse;
        c.expect(s.precession, at, omega_p, std::abs(omega_p) + w0.norm(), "the precession rate of body " + e.body);
    }
    const double period = std::abs(omega_p) > 1e-6 ? 2 * M_PI / std::abs(omega_p) : 1;
    std::vector<double> times;
    for (int k = 0; k <= 8; ++k)
        times.push_back(period * k / 8);
    const std::vector<omega_state> numeric = integrate_free(tensor, start, times);
    for (std::size_t n = 0; n < times.size(); ++n) {
        GiNaC::exmap when = at;
        when[s.time] = GiNaC::numeric(times[n]);
        for (unsigned k = 0; k < 3; ++k)
            c.expect(s.omega[k], when, numeric[n][k], w0.norm(),
                     GiNaC::ex_to<GiNaC::symbol>(e.omega[k]).get_name() + "(t) at t = " + message_number(times[n]) +
                         " of body " + e.body);
    }
}

/// The elliptic solution (at the first `values` line) against the numeric integration
/// from its ω(0) over one period, and its energy and |L|² from ω(0).
void check_elliptic(const euler_result& e, const std::vector<double>& moments, const omega_state& initial,
                    const body_point& p)
{
    const euler_result::elliptic_solution& s = *e.elliptic;
    const Eigen::Vector3d w0(initial[0], initial[1], initial[2]);
    const comparer c{"Euler's equations", p.text + " and " + omega_text(e.omega, w0) + " at t = 0",
                     motion_tolerance};
    const std::string of = " of body " + e.body;
    for (unsigned k = 0; k < 3; ++k) {
        c.expect(s.moments[k], moments[k], std::abs(moments[k]), "the moment I" + std::to_string(k + 1) +
                                                                        " of the elliptic solution" + of);
        c.expect(s.initial[k], initial[k], w0.norm(), "ω(0) of the elliptic solution" + of);
    }
    const Eigen::Matrix3d tensor = Eigen::Vector3d(moments[0], moments[1], moments[2]).asDiagonal();
    const Eigen::Vector3d momentum = tensor * w0;
    const double energy = w0.dot(momentum) / 2, momentum_squared = momentum.squaredNorm();
    c.expect(s.energy, energy, std::abs(energy), "the energy of the elliptic solution" + of);
    c.expect(s.momentum_squared, momentum_squared, momentum_squared, "|L|² of the elliptic solution" + of);
    std::vector<double> times;
    for (int k = 0; k <= 8; ++k)
        times.push_back(s.period * k / 8);
    const std::vector<omega_state> numeric = integrate_free(tensor, initial, times);
    for (std::size_t n = 0; n < times.size(); ++n) {
        const std::array<double, 3> closed = s.evaluate(times[n]);
        for (unsigned k = 0; k < 3; ++k)
            c.expect(closed[k], numeric[n][k], w0.norm(),
                     GiNaC::ex_to<GiNaC::symbol>(e.omega[k]).get_name() + "(t) at t = " + message_number(times[n]) +
                         " of the elliptic solution" + of);
    }
    // After one period the numeric ω is back at ω(0).
    for (unsigned k = 0; k < 3; ++k)
        c.expect(numeric.back()[k], initial[k], w0.norm(),
                 "ω after the period " + message_number(s.period) + " of the elliptic solution" + of);
}

/// Poinsot's construction: the ellipsoid's semi-axes √(2T/I_i), the plane's distance
/// 2T/|L|, and every polhode point on both the energy and the momentum ellipsoid.
void check_poinsot(const euler_result& e, const std::vector<double>& moments, const omega_state& initial,
                   const body_point& p)
{
    const euler_result::poinsot_construction& poinsot = *e.poinsot;
    const comparer c{"Euler's equations", p.text, motion_tolerance};
    const std::string of = " of Poinsot's construction of body " + e.body;
    double two_t = 0, l2 = 0;
    for (unsigned k = 0; k < 3; ++k) {
        two_t += moments[k] * initial[k] * initial[k];
        l2 += moments[k] * moments[k] * initial[k] * initial[k];
    }
    for (unsigned k = 0; k < 3; ++k) {
        const double axis = std::sqrt(two_t / moments[k]);
        c.expect(poinsot.ellipsoid_axes[k], axis, axis, "semi-axis " + std::to_string(k + 1) + of);
    }
    const double distance = two_t / std::sqrt(l2);
    c.expect(poinsot.plane_distance, distance, distance, "the plane's distance" + of);
    for (std::size_t n = 0; n < poinsot.polhode.size(); ++n) {
        double energy = 0, momentum = 0;
        for (unsigned k = 0; k < 3; ++k) {
            energy += moments[k] * poinsot.polhode[n][k] * poinsot.polhode[n][k];
            momentum += moments[k] * moments[k] * poinsot.polhode[n][k] * poinsot.polhode[n][k];
        }
        c.expect(energy, two_t, two_t, "2T at polhode point " + std::to_string(n + 1) + of);
        c.expect(momentum, l2, l2, "|L|² at polhode point " + std::to_string(n + 1) + of);
    }
}

/// The stability of rotation about each principal axis from the sign of
/// (I_i − I_j)(I_i − I_k) of the verified moments.
void check_stability(const euler_result& e, const std::vector<double>& moments, const body_point& p)
{
    const double largest = *std::max_element(moments.begin(), moments.end());
    for (std::size_t i = 0; i < 3 && i < e.stability.size(); ++i) {
        const double product = (moments[i] - moments[(i + 1) % 3]) * (moments[i] - moments[(i + 2) % 3]);
        const double small = tolerance * largest * largest;
        const std::string expected = product > small ? "stable" : product < -small ? "unstable" : "marginal";
        if (e.stability[i] != "unknown" && e.stability[i] != expected)
            throw computation_error("verification failed: Euler's equations: the rotation about axis " +
                                    std::to_string(i + 1) + " of body " + e.body + " at " + p.text + " is " +
                                    e.stability[i] + ", but " + expected +
                                    " by the independent check; the result is not printed");
    }
}

void check_euler(const model& scene, const rigid_body& body, const inertia_result& in, const euler_result& e,
                 const checked_body& checked, const body_point& p, bool first_values_point, sampler& random)
{
    const Eigen::Matrix3d& tensor = checked.reference.tensor;
    const euler_state state = random_state(scene, e, p, random);
    check_equations(body, e.equations, tensor, e, state, "the equation");
    // The moments e uses are the printed principal moments (verified as a set): in body
    // order when the body axes are principal, else in the principal axes.
    std::vector<double> moments;
    if (e.moments.size() == 3) {
        const comparer c{"Euler's equations", p.text, tolerance};
        for (std::size_t k = 0; k < 3; ++k) {
            const double reference = in.diagonal ? tensor(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(k))
                                                 : checked.principal.at(k);
            moments.push_back(c.value(e.moments[k], p.map, "moment " + std::to_string(k + 1)));
            c.expect(moments.back(), reference, trace_scale(tensor),
                     "moment " + std::to_string(k + 1) + " of body " + e.body);
        }
    }
    const Eigen::Matrix3d principal =
        moments.empty() ? tensor : Eigen::Matrix3d(Eigen::Vector3d(moments[0], moments[1], moments[2]).asDiagonal());
    if (!e.principal_equations.empty())
        check_equations(body, e.principal_equations, principal, e, state, "the principal-axes equation");
    const Eigen::Matrix3d& solution_tensor = in.diagonal ? tensor : principal;
    if (!moments.empty() && e.torque_free) {
        // The conserved T and |L|² at the state, in the axes the moments are in.
        const Eigen::Vector3d& w = state.omega;
        const comparer c{"Euler's equations", state.text, tolerance};
        const Eigen::Vector3d momentum = solution_tensor * w;
        c.expect(e.kinetic_energy, state.map, w.dot(momentum) / 2, trace_scale(tensor) * w.squaredNorm(),
                 "the conserved kinetic energy of body " + e.body);
        c.expect(e.angular_momentum_squared, state.map, momentum.squaredNorm(),
                 trace_scale(tensor) * trace_scale(tensor) * w.squaredNorm(),
                 "the conserved |L|² of body " + e.body);
    }
    if (!moments.empty() && (first_values_point || scene.values.empty()))
        check_stability(e, moments, p);
    if (e.symmetric)
        check_symmetric(e, solution_tensor, p);
    if ((e.elliptic || e.poinsot) && first_values_point && !moments.empty() && scene.initial) {
        omega_state initial{};
        for (unsigned k = 0; k < 3; ++k) {
            auto found = scene.initial->others.find(GiNaC::ex_to<GiNaC::symbol>(e.omega[k]).get_name());
            if (found != scene.initial->others.end())
                initial[k] = comparer{"Euler's equations", p.text, tolerance}.value(found->second, p.map, "ω(0)");
        }
        if (e.elliptic)
            check_elliptic(e, moments, initial, p);
        if (e.poinsot)
            check_poinsot(e, moments, initial, p);
    }
}

} // namespace

std::vector<verification_entry> verify_bodies(const model& scene, const std::vector<inertia_result>* inertia,
                                              const std::vector<euler_result>* euler)
{
    std::vector<verification_entry> entries;
    if (!inertia || inertia->empty())
        return entries;
    const std::vector<body_point> points = parameter_points(scene);
    // Per body: the references at the points used.
    std::map<std::string, std::vector<std::pair<const body_point*, checked_body>>> checked;
    std::size_t used_points = 0, given = 0, integrated = 0;
    std::vector<std::string> unusable; ///< bodies with no usable point
    for (const inertia_result& in : *inertia) {
        const rigid_body* body = body_named(scene, in.body);
        if (!body)
            continue;
        (body->body_kind == rigid_body::kind::inertia ? given : integrated) += 1;
        std::size_t used = 0;
        for (std::size_t k = 0; k < points.size() && used < points_wanted; ++k) {
            std::optional<numeric_body> reference = numeric_inertia(*body, points[k].map);
            if (!reference)
                continue;
            checked_body result{*reference, {}};
            check_inertia(*body, in, *reference, points[k], result);
            checked[in.body].push_back({&points[k], result});
            ++used;
        }
        if (used == 0)
            unusable.push_back(in.body);
        used_points = std::max(used_points, used);
    }
    if (!unusable.empty()) {
        std::string names;
        for (const std::string& name : unusable)
            names += (names.empty() ? "" : ", ") + name;
        entries.push_back({"inertia",
                           "not checked: the dimensions, mass or density of body " + names +
                               " are not real numbers at any parameter point tried",
                           false});
    } else {
        std::string how = "mass, centre of mass, the integrals, the tensor, principal moments (against its "
                          "eigenvalues, Eigen) and axes, L and T against ";
        if (integrated)
            how += "tensor-product Gauss–Legendre cubature of the density over the region";
        if (integrated && given)
            how += ", or ";
        if (given)
            how += "the parallel-axis shift of the numbers given";
        how += " at " + std::to_string(used_points) + " parameter points";
        entries.push_back({"inertia", how, true});
    }
    if (!euler || euler->empty())
        return entries;
    bool solution = false, every_body = true;
    sampler random(0x65756c6572ULL); // "euler"
    for (const euler_result& e : *euler) {
        const rigid_body* body = body_named(scene, e.body);
        auto found = checked.find(e.body);
        if (!body || found == checked.end()) {
            every_body = false;
            continue;
        }
        const inertia_result* in = nullptr;
        for (const inertia_result& candidate : *inertia)
            if (candidate.body == e.body)
                in = &candidate;
        for (const auto& [point, reference] : found->second) {
            const bool first_values_point = point == &points.front() && !scene.values.empty();
            check_euler(scene, *body, *in, e, reference, *point, first_values_point, random);
        }
        solution = solution || e.symmetric || e.elliptic;
    }
    if (!every_body) {
        entries.push_back({"euler", "not checked: the inertia of a free body could not be evaluated", false});
        return entries;
    }
    entries.push_back({"euler",
                       std::string("I ω̇ + ω × I ω − N formed numerically from the checked tensor at seeded random ω, ω̇, t") +
                           (solution ? "; the torque-free solution against Euler's equations integrated numerically "
                                       "(Boost.Odeint, Runge–Kutta–Fehlberg 7(8), tolerance 1e-13) over a period"
                                     : "") +
                           " at " + std::to_string(used_points) + " parameter points",
                       true});
    return entries;
}

} // namespace lagrange
