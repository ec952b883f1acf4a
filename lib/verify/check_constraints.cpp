// SPDX-License-Identifier: GPL-2.0-or-later
/** @file check_constraints.cpp
 *  Numeric checks of the multipliers, constraint forces and reduced linearization. */
#include "verify/check_constraints.h"

#include "core/number_text.h"

#include "numeric/values.h"

#include <Eigen/Dense>

#include <cmath>
#include <functional>
#include <random>
#include <sstream>

namespace lagrange {

namespace {

constexpr int points_wanted = 3;

/// `e` at `at` as a double (NaN where it is not a finite real number).
double value_at(const GiNaC::ex& e, const GiNaC::exmap& at)
{
    try {
        GiNaC::ex v = e.subs(at).evalf();
        if (GiNaC::is_a<GiNaC::numeric>(v) && GiNaC::ex_to<GiNaC::numeric>(v).is_real()) {
            double d = GiNaC::ex_to<GiNaC::numeric>(v).to_double();
            if (std::isfinite(d))
                return d;
        }
    } catch (const std::exception&) {
    }
    return std::nan("");
}

/// A state: parameters, coordinates, velocities and t as numbers.
struct state {
    GiNaC::exmap parameters;
    std::vector<double> q, v;
    double t = 0;
    GiNaC::exmap map(const model& scene) const
    {
        GiNaC::exmap at = parameters;
        for (std::size_t j = 0; j < scene.coordinates.size(); ++j) {
            at[scene.coordinates[j].position] = q[j];
            at[scene.coordinates[j].velocity] = v[j];
        }
        at[scene.time] = t;
        return at;
    }
};

/// f'(0) by the central difference of step h.
double derivative(const std::function<double(double)>& f, double h) { return (f(h) - f(-h)) / (2 * h); }
double second_derivative(const std::function<double(double)>& f, double h)
{
    return (f(h) - 2 * f(0) + f(-h)) / (h * h);
}

[[noreturn]] void fail(const std::string& what, double got, double expected)
{
    throw computation_error("verification failed: " + what + ": " + significant(got, 10) + " against " +
                            significant(expected, 10) + " by the numeric check");
}

bool close(double a, double b, double scale, double tolerance) { return std::abs(a - b) <= tolerance * scale; }

} // namespace

verification_entry check_multipliers(const model& scene, const equations_of_motion& equations,
                                     const multipliers_result& multipliers)
{
    const std::size_t n = scene.coordinates.size(), m = scene.constraints.size();
    std::mt19937 random(515);
    std::uniform_real_distribution<double> centred(-1, 1), positive(0.5, 2.0);
    int used = 0;
    for (int attempt = 0; attempt < 20 && used < points_wanted; ++attempt) {
        state s;
        for (const parameter& p : scene.parameters)
            s.parameters[p.symbol] = positive(random);
        for (const input_signal& u : scene.inputs)
            s.parameters[u.symbol] = centred(random);
        for (std::size_t j = 0; j < n; ++j) {
            s.q.push_back(centred(random));
            s.v.push_back(centred(random));
        }
        s.t = 0.5 + 0.5 * centred(random);
        // The constraint rows and c from the constraints as written, by differences.
        Eigen::MatrixXd a(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(n));
        Eigen::VectorXd bias(static_cast<Eigen::Index>(m));
        bool finite = true;
        for (std::size_t k = 0; k < m; ++k) {
            const constraint& c = scene.constraints[k];
            const bool holonomic = c.constraint_kind == constraint::kind::holonomic;
            auto moved = [&](std::size_t j, bool velocity, double h) {
                state t = s;
                (velocity ? t.v : t.q)[j] += h;
                return value_at(c.function, t.map(scene));
            };
            for (std::size_t j = 0; j < n; ++j)
                a(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(j)) =
                    derivative([&](double h) { return moved(j, !holonomic, h); }, 1e-5);
            // Along the path q + q̇τ (q̈ = 0), t + τ: c is the second derivative of a holonomic f and
            // the first of a Pfaffian one.
            auto along = [&](double tau) {
                state t = s;
                for (std::size_t j = 0; j < n; ++j)
                    t.q[j] += s.v[j] * tau;
                t.t += tau;
                return value_at(c.function, t.map(scene));
            };
            bias[static_cast<Eigen::Index>(k)] = holonomic ? second_derivative(along, 1e-4) : derivative(along, 1e-5);
        }
        const GiNaC::exmap at = s.map(scene);
        Eigen::MatrixXd system = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(n + m), static_cast<Eigen::Index>(n + m));
        Eigen::VectorXd right(static_cast<Eigen::Index>(n + m));
        for (std::size_t i = 0; i < n; ++i) {
            for (std::size_t j = 0; j < n; ++j)
                system(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
                    value_at(equations.mass(static_cast<unsigned>(i), static_cast<unsigned>(j)), at);
            right[static_cast<Eigen::Index>(i)] = value_at(equations.forcing[i], at);
            for (std::size_t k = 0; k < m; ++k) {
                system(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(n + k)) =
                    -a(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(i));
                system(static_cast<Eigen::Index>(n + k), static_cast<Eigen::Index>(i)) =
                    a(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(i));
            }
        }
        for (std::size_t k = 0; k < m; ++k)
            right[static_cast<Eigen::Index>(n + k)] = -bias[static_cast<Eigen::Index>(k)];
        finite = system.allFinite() && right.allFinite();
        Eigen::FullPivLU<Eigen::MatrixXd> lu(system);
        if (!finite || !lu.isInvertible() || lu.rcond() < 1e-8)
            continue;
        Eigen::VectorXd solution = lu.solve(right);
        const double scale = 1 + solution.cwiseAbs().maxCoeff();
        for (std::size_t k = 0; k < m; ++k) {
            const double expected = solution[static_cast<Eigen::Index>(n + k)];
            const double got = value_at(multipliers.constraints[k].multiplier, at);
            if (!close(got, expected, scale, 1e-5))
                fail("the multiplier of `" + scene.constraints[k].name + "`", got, expected);
            // A force's virtual work along its point's coordinates is λ a_kj.
            for (const constraint_point_force& f : multipliers.constraints[k].forces)
                for (const point_mass& p : scene.points) {
                    if (p.name != f.point)
                        continue;
                    std::vector<double> force;
                    for (const GiNaC::ex& x : f.force)
                        force.push_back(value_at(x, at));
                    for (std::size_t j = 0; j < n; ++j) {
                        if (!f.force.empty() && ![&] {
                                for (const GiNaC::ex& x : p.position)
                                    if (x.has(scene.coordinates[j].position))
                                        return true;
                                return false;
                            }())
                            continue;
                        double work = 0;
                        for (std::size_t r = 0; r < force.size(); ++r)
                            work += force[r] * derivative(
                                                   [&](double h) {
                                                       state t = s;
                                                       t.q[j] += h;
                                                       return value_at(p.position[r], t.map(scene));
                                                   },
                                                   1e-5);
                        const double generalized = expected * a(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(j));
                        if (!close(work, generalized, scale * (1 + a.cwiseAbs().maxCoeff()), 1e-5))
                            fail("the virtual work of the force of `" + scene.constraints[k].name + "` on `" +
                                     p.name + "` along " + scene.coordinates[j].name,
                                 work, generalized);
                    }
                }
        }
        ++used;
    }
    if (used == 0)
        return {"multipliers", "not checked: the constrained system is singular or not finite at every state tried",
                false};
    return {"multipliers",
            "[M −Aᵀ; A 0] solved numerically with A and its derivative by finite differences of the constraints as "
            "written, and each constraint force's virtual work, at " + std::to_string(used) + " seeded random states",
            true};
}

void check_constrained_linearization(const model& scene, const lagrangian_result& lagrangian,
                                     const constrained_linearization& constrained, bool point,
                                     std::vector<verification_entry>& entries)
{
    const std::size_t n = scene.coordinates.size(), m = scene.constraints.size();
    const std::size_t r = constrained.independent.size();
    std::vector<std::size_t> dependent;
    for (std::size_t j = 0; j < n; ++j)
        if (std::find(constrained.independent.begin(), constrained.independent.end(), j) ==
            constrained.independent.end())
            dependent.push_back(j);
    const std::vector<GiNaC::ex>& equilibrium = constrained.equilibria.points.at(0).position;
    std::mt19937 random(919);
    std::uniform_real_distribution<double> positive(0.5, 2.0);
    int used = 0;
    for (int attempt = 0; attempt < 10 && used < points_wanted; ++attempt) {
        GiNaC::exmap parameters;
        for (const parameter& p : scene.parameters)
            parameters[p.symbol] = positive(random);
        std::vector<double> q0;
        for (const GiNaC::ex& e : equilibrium)
            q0.push_back(value_at(e, parameters));
        bool finite = true;
        for (double x : q0)
            finite = finite && std::isfinite(x);
        if (!finite)
            continue;
        auto map_at = [&](const std::vector<double>& q, const std::vector<double>& v) {
            GiNaC::exmap at = parameters;
            for (std::size_t j = 0; j < n; ++j) {
                at[scene.coordinates[j].position] = q[j];
                at[scene.coordinates[j].velocity] = v[j];
            }
            at[scene.time] = 0;
            return at;
        };
        const std::vector<double> rest(n, 0.0);
        // The point on the constraints with the independent coordinates moved by δ.
        auto on_manifold = [&](const std::vector<double>& delta) {
            std::vector<double> q = q0;
            for (std::size_t i = 0; i < r; ++i)
                q[constrained.independent[i]] += delta[i];
            for (int iteration = 0; iteration < 30; ++iteration) {
                Eigen::VectorXd g(static_cast<Eigen::Index>(m));
                Eigen::MatrixXd jacobian(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(m));
                for (std::size_t k = 0; k < m; ++k) {
                    g[static_cast<Eigen::Index>(k)] = value_at(scene.constraints[k].function, map_at(q, rest));
                    for (std::size_t d = 0; d < m; ++d)
                        jacobian(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(d)) = derivative(
                            [&](double h) {
                                std::vector<double> moved = q;
                                moved[dependent[d]] += h;
                                return value_at(scene.constraints[k].function, map_at(moved, rest));
                            },
                            1e-6);
                }
                if (g.cwiseAbs().maxCoeff() < 1e-14)
                    break;
                Eigen::VectorXd step = jacobian.fullPivLu().solve(g);
                for (std::size_t d = 0; d < m; ++d)
                    q[dependent[d]] -= step[static_cast<Eigen::Index>(d)];
            }
            return q;
        };
        auto potential = [&](const std::vector<double>& delta) {
            return value_at(lagrangian.potential_built, map_at(on_manifold(delta), rest));
        };
        const double h = 1e-3;
        Eigen::MatrixXd v_reference(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(r));
        Eigen::MatrixXd tangent(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(r));
        double gradient_size = 0, v_scale = std::abs(potential(std::vector<double>(r, 0.0)));
        for (std::size_t i = 0; i < r; ++i) {
            auto along_i = [&](double x) {
                std::vector<double> d(r, 0.0);
                d[i] = x;
                return potential(d);
            };
            gradient_size = std::max(gradient_size, std::abs(derivative(along_i, h)));
            for (std::size_t j = 0; j < r; ++j) {
                auto both = [&](double x, double y) {
                    std::vector<double> d(r, 0.0);
                    d[i] += x;
                    d[j] += y;
                    return potential(d);
                };
                v_reference(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
                    (both(h, h) - both(h, -h) - both(-h, h) + both(-h, -h)) / (4 * h * h);
            }
            for (std::size_t k = 0; k < n; ++k)
                tangent(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(i)) = derivative(
                    [&](double x) {
                        std::vector<double> d(r, 0.0);
                        d[i] = x;
                        return on_manifold(d)[k];
                    },
                    1e-5);
        }
        // T along the tangent vectors: K(a + b) − K(a) − K(b) = aᵀ T b.
        auto kinetic = [&](const Eigen::VectorXd& velocity) {
            std::vector<double> v(velocity.data(), velocity.data() + n);
            return value_at(lagrangian.kinetic_built, map_at(q0, v));
        };
        Eigen::MatrixXd t_reference(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(r));
        for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(r); ++i)
            for (Eigen::Index j = 0; j < static_cast<Eigen::Index>(r); ++j)
                t_reference(i, j) = i == j ? 2 * kinetic(tangent.col(i))
                                           : kinetic(tangent.col(i) + tangent.col(j)) - kinetic(tangent.col(i)) -
                                                 kinetic(tangent.col(j));
        if (!v_reference.allFinite() || !t_reference.allFinite())
            continue;
        const double v_size = 1 + v_reference.cwiseAbs().maxCoeff() + v_scale;
        if (point && gradient_size > 1e-5 * v_size)
            fail("the equilibrium: the slope of V along the constraints", gradient_size, 0);
        const double t_size = 1 + t_reference.cwiseAbs().maxCoeff();
        for (unsigned i = 0; i < r; ++i)
            for (unsigned j = 0; j < r; ++j) {
                const double v_got = value_at(constrained.linear.potential(i, j), parameters);
                const double t_got = value_at(constrained.linear.kinetic(i, j), parameters);
                if (!close(v_got, v_reference(i, j), v_size, 1e-4))
                    fail("the reduced V entry (" + std::to_string(i + 1) + ", " + std::to_string(j + 1) + ")", v_got,
                         v_reference(i, j));
                if (!close(t_got, t_reference(i, j), t_size, 1e-6))
                    fail("the reduced T entry (" + std::to_string(i + 1) + ", " + std::to_string(j + 1) + ")", t_got,
                         t_reference(i, j));
            }
        ++used;
    }
    const std::string at = " at " + std::to_string(used) + " seeded parameter points";
    if (used == 0) {
        if (point)
            entries.push_back({"equilibrium", "not checked: not finite at any parameter point tried", false});
        entries.push_back({"linearization", "not checked: not finite at any parameter point tried", false});
        return;
    }
    if (point)
        entries.push_back({"equilibrium", "V on the constraints (dependent coordinates by Newton's method) is level "
                                          "there by finite differences" + at, true});
    entries.push_back({"linearization", "the Hessian of V on the constraints and T along their tangent vectors by "
                                        "finite differences" + at, true});
}

} // namespace lagrange
