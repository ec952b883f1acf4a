// SPDX-License-Identifier: GPL-2.0-or-later
/** @file check_damping.cpp
 *  Numeric checks of the damped small oscillations by a route that shares nothing with
 *  the symbolic derivation: C against the Rayleigh function and the forces as the scene
 *  wrote them (polarization of the quadratic F in the velocities, damper rates from
 *  central differences of the end positions, velocity derivatives of the applied forces
 *  by central differences), and det(K + sC + s²M) against the printed polynomial at
 *  complex s (LU). */
#include "verify/verify.h"

#include "core/errors.h"
#include "numeric/values.h"
#include "verify/points.h"

#include <Eigen/Dense>

#include <cmath>
#include <complex>
#include <cstdint>
#include <optional>

namespace lagrange {

namespace {

using GiNaC::ex;
using complex = std::complex<double>;
using verification_points::matrix_at;

constexpr double tolerance = 1e-6;
constexpr double step = 0x1p-12;   ///< central differences of positions and forces
constexpr double offset = 0x1p-20; ///< distance from the equilibrium (a damper's length may vanish there)
constexpr int points_wanted = 2;

/// Deterministic parameter points: each `values` line's, then seeded ones in [1/2, 2].
std::vector<GiNaC::exmap> parameter_points(const model& scene)
{
    std::vector<GiNaC::exmap> points;
    std::uint64_t state = 0x64616d70696e67ULL; // "damping"
    auto uniform = [&] {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return 0.5 + 1.5 * static_cast<double>((state >> 33) % 65) / 64;
    };
    for (int attempt = 0; attempt < 6; ++attempt) {
        GiNaC::exmap given;
        if (attempt < static_cast<int>(scene.values.size()))
            given = value_map(scene, scene.values[static_cast<std::size_t>(attempt)]);
        GiNaC::exmap point;
        for (const parameter& p : scene.parameters) {
            double x = uniform();
            auto found = given.find(p.symbol);
            if (found != given.end()) {
                ex v = found->second.evalf();
                if (GiNaC::is_a<GiNaC::numeric>(v) && GiNaC::ex_to<GiNaC::numeric>(v).is_real())
                    x = GiNaC::ex_to<GiNaC::numeric>(v).to_double();
            }
            point[p.symbol] = GiNaC::numeric(x);
        }
        points.push_back(point);
    }
    return points;
}

std::string point_text(const model& scene, const GiNaC::exmap& point)
{
    std::string text;
    for (const parameter& p : scene.parameters)
        text += (text.empty() ? "" : ", ") + p.name + " = " +
                message_number(GiNaC::ex_to<GiNaC::numeric>(point.at(p.symbol)).to_double());
    return text.empty() ? "the check" : text;
}

/// A state of the scene: coordinates, velocities, inputs 0, t = 0, at a parameter point.
struct state_point {
    const model& scene;
    const GiNaC::exmap& parameters;
    std::vector<double> q, v;
    std::vector<double> inputs = {}; ///< empty: every input 0

    GiNaC::exmap map() const
    {
        GiNaC::exmap at = parameters;
        for (std::size_t i = 0; i < q.size(); ++i) {
            at[scene.coordinates[i].position] = GiNaC::numeric(q[i]);
            at[scene.coordinates[i].velocity] = GiNaC::numeric(v[i]);
        }
        for (std::size_t k = 0; k < scene.inputs.size(); ++k)
            at[scene.inputs[k].symbol] = k < inputs.size() ? GiNaC::ex(GiNaC::numeric(inputs[k])) : GiNaC::ex(0);
        at[scene.time] = 0;
        return at;
    }
    std::optional<double> operator()(const ex& e) const { return real_at(e, map()); }
};

/// d/dt of a point's position along the velocities: Σ_k ∂r/∂q_k q̇_k by central differences.
std::optional<std::vector<double>> rate_of(const std::vector<ex>& position, const state_point& at)
{
    std::vector<double> rate(position.size(), 0.0);
    for (std::size_t k = 0; k < at.q.size(); ++k) {
        if (at.v[k] == 0)
            continue;
        state_point plus = at, minus = at;
        plus.q[k] += step;
        minus.q[k] -= step;
        for (std::size_t c = 0; c < position.size(); ++c) {
            std::optional<double> up = plus(position[c]), down = minus(position[c]);
            if (!up || !down)
                return std::nullopt;
            rate[c] += (*up - *down) / (2 * step) * at.v[k];
        }
    }
    return rate;
}

/// The whole Rayleigh function at a state, as the scene wrote it: the `dissipation` lines
/// and ½ b ((d·ḋ)/|d|)² of every damper with d = r_A − r_B.
std::optional<double> rayleigh_at(const state_point& at)
{
    std::optional<double> total = at(at.scene.dissipation);
    if (!total)
        return std::nullopt;
    for (const damper& d : at.scene.dampers) {
        std::vector<ex> difference;
        for (std::size_t c = 0; c < 3; ++c)
            difference.push_back(d.end_a[c] - d.end_b[c]);
        std::optional<std::vector<double>> rate = rate_of(difference, at);
        std::optional<double> b = at(d.coefficient);
        if (!rate || !b)
            return std::nullopt;
        double dot = 0, length2 = 0;
        for (std::size_t c = 0; c < 3; ++c) {
            std::optional<double> x = at(difference[c]);
            if (!x)
                return std::nullopt;
            dot += *x * (*rate)[c];
            length2 += *x * *x;
        }
        if (length2 == 0)
            return std::nullopt;
        *total += 0.5 * *b * dot * dot / length2;
    }
    return total;
}

/// The applied generalized forces at a state: `force q` values and F·∂r_P/∂q_i (central
/// differences of P's position).
std::optional<std::vector<double>> applied_at(const state_point& at)
{
    const std::size_t n = at.q.size();
    std::vector<double> q(n, 0.0);
    for (const generalized_force& f : at.scene.forces) {
        std::optional<double> value = at(f.value);
        if (!value)
            return std::nullopt;
        q[f.coordinate] += *value;
    }
    for (const point_force& f : at.scene.point_forces)
        for (std::size_t i = 0; i < n; ++i) {
            state_point plus = at, minus = at;
            plus.q[i] += step;
            minus.q[i] -= step;
            for (std::size_t c = 0; c < 3; ++c) {
                std::optional<double> force = at(f.force[c]), up = plus(f.position[c]), down = minus(f.position[c]);
                if (!force || !up || !down)
                    return std::nullopt;
                q[i] += *force * (*up - *down) / (2 * step);
            }
        }
    return q;
}

/// C at the positions `q` from the statements: the Hessian of F in the velocities by
/// polarization (F is quadratic in them, so exactly), minus ∂(applied)/∂q̇ by differences.
std::optional<Eigen::MatrixXd> damping_reference(const model& scene, const GiNaC::exmap& parameters,
                                                 const std::vector<double>& q)
{
    const std::size_t n = q.size();
    Eigen::MatrixXd c(n, n);
    auto rayleigh = [&](std::size_t i, std::size_t j, double sign) {
        state_point at{scene, parameters, q, std::vector<double>(n, 0.0)};
        at.v[i] += 1;
        at.v[j] += sign;
        return rayleigh_at(at);
    };
    auto applied = [&](std::size_t j, double h) {
        state_point at{scene, parameters, q, std::vector<double>(n, 0.0)};
        at.v[j] = h;
        return applied_at(at);
    };
    for (std::size_t j = 0; j < n; ++j) {
        std::optional<std::vector<double>> up = applied(j, step), down = applied(j, -step);
        if (!up || !down)
            return std::nullopt;
        for (std::size_t i = 0; i < n; ++i) {
            std::optional<double> hessian;
            if (i == j) {
                std::optional<double> f = rayleigh(i, i, 0);
                if (f)
                    hessian = 2 * *f;
            } else {
                std::optional<double> plus = rayleigh(i, j, 1), minus = rayleigh(i, j, -1);
                if (plus && minus)
                    hessian = (*plus - *minus) / 2;
            }
            if (!hessian)
                return std::nullopt;
            c(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = *hessian - ((*up)[i] - (*down)[i]) / (2 * step);
        }
    }
    return c;
}

/// The linearization's equilibrium at `parameters`: the entries that are real numbers there
/// (fewer than n where one is not).
std::vector<double> equilibrium_at(const linearization_result& linear, const GiNaC::exmap& parameters)
{
    std::vector<double> q0;
    for (const ex& x : linear.at)
        if (std::optional<double> v = real_at(x, parameters))
            q0.push_back(*v);
    return q0;
}

/// C from the statements beside the equilibrium q0 (both sides averaged), to O(offset²): a damper's length may vanish at q0 itself.
std::optional<Eigen::MatrixXd> damping_beside(const model& scene, const GiNaC::exmap& parameters,
                                              const std::vector<double>& q0)
{
    std::vector<double> plus = q0, minus = q0;
    for (std::size_t i = 0; i < q0.size(); ++i) {
        const double direction = 1 + 0.375 * static_cast<double>(i % 3);
        plus[i] += offset * direction;
        minus[i] -= offset * direction;
    }
    std::optional<Eigen::MatrixXd> up = damping_reference(scene, parameters, plus);
    std::optional<Eigen::MatrixXd> down = damping_reference(scene, parameters, minus);
    if (!up || !down)
        return std::nullopt;
    return Eigen::MatrixXd((*up + *down) / 2);
}

[[noreturn]] void fail(const std::string& product, const std::string& what, const std::string& where, double here,
                       double reference)
{
    throw computation_error("verification failed: " + product + ": " + what + " at " + where + " is " +
                            message_number(here, 10) + ", but " + message_number(reference, 10) +
                            " by the independent check; the result is not printed");
}

} // namespace

std::vector<verification_entry> verify_damping(const model& scene, const linearization_result& linear,
                                               const damping_result& damping)
{
    const std::size_t n = scene.coordinates.size();
    int used = 0;
    for (const GiNaC::exmap& parameters : parameter_points(scene)) {
        const std::vector<double> q0 = equilibrium_at(linear, parameters);
        std::optional<Eigen::MatrixXd> symbolic = matrix_at(damping.damping, parameters);
        std::optional<Eigen::MatrixXd> mass = matrix_at(linear.kinetic, parameters);
        std::optional<Eigen::MatrixXd> stiffness = matrix_at(linear.potential, parameters);
        std::optional<Eigen::MatrixXd> gyroscopic = matrix_at(linear.gyroscopic, parameters);
        if (q0.size() != n || !symbolic || !mass || !stiffness || !gyroscopic)
            continue;
        std::optional<Eigen::MatrixXd> beside = damping_beside(scene, parameters, q0);
        if (!beside)
            continue;
        const Eigen::MatrixXd& reference = *beside;
        const std::string where = point_text(scene, parameters);
        const double size = reference.cwiseAbs().sum() + symbolic->cwiseAbs().sum() + 1e-300;
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < n; ++j) {
                const double here = (*symbolic)(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
                const double there = reference(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
                if (std::abs(here - there) > tolerance * size)
                    fail("the damping matrix",
                         "C(" + scene.coordinates[i].name + ", " + scene.coordinates[j].name + ")", where, here,
                         there);
            }
        // p(s)/det(K + s(C − G) + s²M) is the same at every s (the factor removed to make p
        // primitive); C from the differences beside the equilibrium, G as linearized.
        std::optional<complex> ratio;
        int compared = 0;
        for (int k = 0; compared < static_cast<int>(2 * n) + 2 && k < 8 * static_cast<int>(n) + 8; ++k) {
            const complex s(-0.3 + 0.125 * k, 0.375 + 0.25 * k);
            const Eigen::MatrixXcd pencil = stiffness->cast<complex>() + s * (reference - *gyroscopic).cast<complex>() +
                                            (s * s) * mass->cast<complex>();
            const complex det = pencil.partialPivLu().determinant();
            const double scale = std::pow(stiffness->norm() + std::abs(s) * reference.norm() +
                                              std::norm(s) * mass->norm(),
                                          static_cast<double>(n));
            if (std::abs(det) < 1e-6 * scale)
                continue; // too near a root for the ratio to be well conditioned
            GiNaC::exmap at = parameters;
            at[damping.s] = GiNaC::numeric(s.real()) + GiNaC::I * GiNaC::numeric(s.imag());
            ex value = damping.polynomial.subs(at).evalf();
            if (!GiNaC::is_a<GiNaC::numeric>(value))
                break;
            const GiNaC::numeric& number = GiNaC::ex_to<GiNaC::numeric>(value);
            const complex r = complex(GiNaC::real(number).to_double(), GiNaC::imag(number).to_double()) / det;
            if (!ratio) {
                ratio = r;
                if (std::abs(r) == 0 || !std::isfinite(std::abs(r)))
                    break;
            } else if (std::abs(r - *ratio) > tolerance * std::abs(*ratio)) {
                fail("the damped characteristic polynomial",
                     "|p(s)/det(K + s(C − G) + s²M)| at s = " + message_number(s.real()) + " + " +
                         message_number(s.imag()) + "i",
                     where, std::abs(r), std::abs(*ratio));
            }
            ++compared;
        }
        if (++used == points_wanted)
            break;
    }
    if (used == 0) {
        const std::string why = "not checked: C is not real beside the equilibrium at any parameter point tried";
        return {{"damping", why, false}, {"damped_characteristic", why, false}};
    }
    const std::string points = " at " + std::to_string(used) + " parameter points";
    return {{"damping",
             "against second differences of the Rayleigh function and differences of the forces as written, "
             "beside the equilibrium" +
                 points,
             true},
            {"damped_characteristic", std::string("against det(K + ") + (damping.gyroscopic ? "s(C − G)" : "sC") +
                                          " + s²M) (LU) at " + std::to_string(2 * n + 2) +
                                          " complex s" + points,
             true}};
}

namespace {

/// B_q = ∂Q/∂u at rest at q0 by central differences of the applied forces in each input.
std::optional<Eigen::MatrixXd> input_reference(const model& scene, const GiNaC::exmap& parameters,
                                               const std::vector<double>& q0)
{
    const std::size_t n = q0.size(), m = scene.inputs.size();
    Eigen::MatrixXd b(n, m);
    for (std::size_t j = 0; j < m; ++j) {
        state_point up{scene, parameters, q0, std::vector<double>(n, 0.0), std::vector<double>(m, 0.0)};
        state_point down = up;
        up.inputs[j] = step;
        down.inputs[j] = -step;
        std::optional<std::vector<double>> qu = applied_at(up), qd = applied_at(down);
        if (!qu || !qd)
            return std::nullopt;
        for (std::size_t i = 0; i < n; ++i)
            b(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = ((*qu)[i] - (*qd)[i]) / (2 * step);
    }
    return b;
}

void compare_matrices(const std::string& product, const std::string& name, const Eigen::MatrixXd& here,
                      const Eigen::MatrixXd& reference, const std::string& where)
{
    const double size = here.cwiseAbs().sum() + reference.cwiseAbs().sum() + 1e-300;
    for (Eigen::Index i = 0; i < here.rows(); ++i)
        for (Eigen::Index j = 0; j < here.cols(); ++j)
            if (std::abs(here(i, j) - reference(i, j)) > tolerance * size)
                fail(product, name + "(" + std::to_string(i + 1) + ", " + std::to_string(j + 1) + ")", where,
                     here(i, j), reference(i, j));
}

} // namespace

std::vector<verification_entry> verify_linear_system(const model& scene, const linearization_result& linear,
                                                     const state_space_result& system, const transfer_result* transfer)
{
    const std::size_t n = scene.coordinates.size();
    int used = 0;
    for (const GiNaC::exmap& parameters : parameter_points(scene)) {
        const std::vector<double> q0 = equilibrium_at(linear, parameters);
        std::optional<Eigen::MatrixXd> a = matrix_at(system.a, parameters), b = matrix_at(system.b, parameters);
        std::optional<Eigen::MatrixXd> mass = matrix_at(linear.kinetic, parameters);
        std::optional<Eigen::MatrixXd> stiffness = matrix_at(linear.potential, parameters);
        std::optional<Eigen::MatrixXd> gyroscopic = matrix_at(linear.gyroscopic, parameters);
        if (q0.size() != n || !a || !b || !mass || !stiffness || !gyroscopic)
            continue;
        std::optional<Eigen::MatrixXd> damping = damping_beside(scene, parameters, q0);
        std::optional<Eigen::MatrixXd> forcing = input_reference(scene, parameters, q0);
        if (!damping || !forcing)
            continue;
        const Eigen::MatrixXd inverse_mass = mass->inverse();
        const Eigen::Index size = static_cast<Eigen::Index>(n);
        Eigen::MatrixXd a_reference = Eigen::MatrixXd::Zero(2 * size, 2 * size);
        a_reference.block(0, size, size, size) = Eigen::MatrixXd::Identity(size, size);
        a_reference.block(size, 0, size, size) = -inverse_mass * *stiffness;
        a_reference.block(size, size, size, size) = inverse_mass * (*gyroscopic - *damping);
        Eigen::MatrixXd b_reference = Eigen::MatrixXd::Zero(2 * size, forcing->cols());
        if (forcing->cols() > 0) // no inputs: B has no columns (and no data to take a block of)
            b_reference.block(size, 0, size, forcing->cols()) = inverse_mass * *forcing;
        const std::string where = point_text(scene, parameters);
        compare_matrices("the state space", "A", *a, a_reference, where);
        compare_matrices("the state space", "B", *b, b_reference, where);
        if (transfer) {
            for (const complex s : {complex(0.25, 0.75), complex(-0.5, 1.5), complex(1.25, 0.125)}) {
                const Eigen::MatrixXcd pencil = (s * s) * mass->cast<complex>() +
                                                s * (*damping - *gyroscopic).cast<complex>() +
                                                stiffness->cast<complex>();
                Eigen::PartialPivLU<Eigen::MatrixXcd> lu(pencil);
                const Eigen::MatrixXcd reference = lu.solve(forcing->cast<complex>());
                const double scale = reference.cwiseAbs().sum() + 1e-300;
                for (const transfer_function& h : transfer->entries) {
                    GiNaC::exmap at = parameters;
                    at[transfer->s] = GiNaC::numeric(s.real()) + GiNaC::I * GiNaC::numeric(s.imag());
                    ex value = h.function().subs(at).evalf();
                    if (!GiNaC::is_a<GiNaC::numeric>(value))
                        continue;
                    const GiNaC::numeric& number = GiNaC::ex_to<GiNaC::numeric>(value);
                    const complex here(GiNaC::real(number).to_double(), GiNaC::imag(number).to_double());
                    const complex there = reference(static_cast<Eigen::Index>(h.coordinate),
                                                    static_cast<Eigen::Index>(h.input));
                    if (std::abs(here - there) > tolerance * scale)
                        fail("the transfer function",
                             "|H(s)| of " + scene.inputs[h.input].name + " -> " +
                                 scene.coordinates[h.coordinate].name + " at s = " + message_number(s.real()) +
                                 " + " + message_number(s.imag()) + "i",
                             where, std::abs(here), std::abs(there));
                }
            }
        }
        if (++used == points_wanted)
            break;
    }
    std::vector<verification_entry> entries;
    if (used == 0) {
        const std::string why = "not checked: the matrices are not real at any parameter point tried";
        entries.push_back({"state_space", why, false});
        if (transfer)
            entries.push_back({"transfer", why, false});
        return entries;
    }
    const std::string points = " at " + std::to_string(used) + " parameter points";
    entries.push_back({"state_space",
                       "A and B against M⁻¹ of the verified T, V, G with C and ∂Q/∂u from the statements by "
                       "differences" +
                           points,
                       true});
    if (transfer)
        entries.push_back({"transfer", "against (s²M + s(C − G) + K)⁻¹ ∂Q/∂u (LU) at 3 complex s" + points, true});
    return entries;
}

} // namespace lagrange
