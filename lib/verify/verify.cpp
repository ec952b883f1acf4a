// SPDX-License-Identifier: GPL-2.0-or-later
/** @file verify.cpp
 *  Numeric checks of the symbolic results against the Lagrangian as built. */
#include "verify/verify.h"
#include "verify/check_bodies.h"
#include "verify/check_constraints.h"
#include "verify/points.h"

#include "program/double_double.h"
#include "program/expression_program.h"
#include "verify/check_symmetries.h"
#include "numeric/values.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <optional>
#include <set>
#include <stdexcept>

namespace lagrange {

namespace {

using GiNaC::ex;
using namespace verification_points;

double value_of(double_double x) { return x.hi + x.lo; }

/// The finite-difference step: a power of two, so that the points stay exact. Every
/// reference is also taken at twice the step: for fourth-order differences the error at
/// `step` is about 1/15 of the change between the two (Richardson), so that change, taken
/// whole, bounds the truncation error the comparison allows for.
constexpr double step = 0x1p-12;

/// The symbols of a state, in the order the programs read them.
struct state_layout {
    std::vector<ex> symbols; ///< q…, q'…, q''…, t, parameters…, inputs…
    std::size_t n = 0;
    std::size_t parameters = 0;
    std::size_t time() const { return 3 * n; }
    std::size_t parameter(std::size_t k) const { return 3 * n + 1 + k; }
    std::size_t input(std::size_t k) const { return 3 * n + 1 + parameters + k; }
};

state_layout layout_of(const model& scene)
{
    state_layout layout;
    layout.n = scene.coordinates.size();
    for (const coordinate& c : scene.coordinates)
        layout.symbols.push_back(c.position);
    for (const coordinate& c : scene.coordinates)
        layout.symbols.push_back(c.velocity);
    for (const coordinate& c : scene.coordinates)
        layout.symbols.push_back(c.acceleration);
    layout.symbols.push_back(scene.time);
    for (const parameter& p : scene.parameters)
        layout.symbols.push_back(p.symbol);
    layout.parameters = scene.parameters.size();
    for (const input_signal& u : scene.inputs)
        layout.symbols.push_back(u.symbol);
    return layout;
}

/// Compiled expressions run in double-double on a state.
class probe {
public:
    probe(const std::vector<ex>& outputs, const state_layout& layout) : program_(outputs, layout.symbols) {}
    std::vector<double_double> operator()(const std::vector<double>& state) const
    {
        std::vector<double_double> out(program_.output_count());
        program_.run(state.data(), scratch_, out.data());
        return out;
    }

private:
    expression_program program_;
    mutable std::vector<double_double> scratch_;
};

/// Σ weights·values / divisor in double-double (a finite-difference stencil).
double_double stencil(const double* weights, const double_double* values, std::size_t count, double divisor)
{
    double_double sum;
    for (std::size_t k = 0; k < count; ++k)
        sum = dd::add(sum, dd::mul(values[k], double_double{weights[k], 0}));
    return dd::div(sum, double_double{divisor, 0});
}

/// Fourth-order central differences: offsets −2h … 2h.
constexpr double offsets[4] = {-2, -1, 1, 2};
constexpr double first_weights[4] = {1, -8, 8, -1}; // / 12h
constexpr double second_offsets[5] = {-2, -1, 0, 1, 2};
constexpr double second_weights[5] = {-1, 16, -30, 16, -1}; // / 12h²

/// d/dx of f(x) at 0 by fourth-order differences with step h.
template <class F> double_double first_derivative(F&& f, double h = step)
{
    double_double values[4];
    for (int k = 0; k < 4; ++k)
        values[k] = f(offsets[k] * h);
    return stencil(first_weights, values, 4, 12 * h);
}

template <class F> double_double second_derivative(F&& f, double h = step)
{
    double_double values[5];
    for (int k = 0; k < 5; ++k)
        values[k] = f(second_offsets[k] * h);
    return stencil(second_weights, values, 5, 12 * h * h);
}

/// A derivative at `step` and its truncation error estimated against twice the step.
struct estimate {
    double value = 0, error = 0;
};

template <class F> estimate estimated_first_derivative(F&& f)
{
    const double fine = value_of(first_derivative(f)), coarse = value_of(first_derivative(f, 2 * step));
    return {fine, std::abs(fine - coarse)};
}

template <class F> estimate estimated_second_derivative(F&& f)
{
    const double fine = value_of(second_derivative(f)), coarse = value_of(second_derivative(f, 2 * step));
    return {fine, std::abs(fine - coarse)};
}

std::string state_text(const model& scene, const std::vector<double>& state, bool accelerations)
{
    std::string text;
    const std::size_t n = scene.coordinates.size();
    for (std::size_t i = 0; i < n; ++i) {
        const std::string& name = scene.coordinates[i].name;
        text += (i ? ", " : "") + name + " = " + message_number(state[i]) + ", " + name +
                "' = " + message_number(state[n + i]);
        if (accelerations)
            text += ", " + name + "'' = " + message_number(state[2 * n + i]);
    }
    return text;
}

/// The compiled sines and cosines are correct to double precision only, so L carries a
/// rounding error of about 2⁻⁵² of the size of its terms; a second difference divides it
/// by h². This is that error, bounded generously (the stencil weights sum to 64), in the
/// units of `scale` in close(): the allowance it adds to a comparison.
double rounding_allowance(double energy_size) { return 64 * 0x1p-52 * energy_size / (step * step) / tolerance; }

/// The Lagrangian as built, before any simplification: the reference of every check.
ex built_lagrangian(const model& scene, const lagrangian_result& lagrangian)
{
    ex l = lagrangian.kinetic_reference - lagrangian.potential_built;
    if (scene.lagrangian_terms)
        l += *scene.lagrangian_terms;
    return l;
}

/// The generalized forces as the scene gave them, for the reference: the `dissipation`
/// lines, each damper's coefficient and length |r_A − r_B| (a square root, differentiated
/// numerically), each `force q` value, and each `force on P` with P's position.
std::vector<ex> force_terms(const model& scene)
{
    std::vector<ex> terms{scene.dissipation};
    for (const damper& d : scene.dampers) {
        ex length2 = 0;
        for (std::size_t k = 0; k < 3; ++k)
            length2 += GiNaC::pow(d.end_a[k] - d.end_b[k], 2);
        terms.push_back(d.coefficient);
        terms.push_back(GiNaC::sqrt(length2));
    }
    for (const generalized_force& f : scene.forces)
        terms.push_back(f.value);
    for (const point_force& f : scene.point_forces)
        for (std::size_t k = 0; k < 3; ++k) {
            terms.push_back(f.force[k]);
            terms.push_back(f.position[k]);
        }
    return terms;
}

/// The terms of the sums among `parts` (a part that is no sum counts as one term).
std::vector<ex> top_level_terms(const std::vector<ex>& parts)
{
    std::vector<ex> terms;
    for (const ex& part : parts) {
        if (GiNaC::is_a<GiNaC::add>(part))
            for (const ex& term : part)
                terms.push_back(term);
        else
            terms.push_back(part);
    }
    return terms;
}

/// What the checks share: the layout, the compiled reference L, the parameter points.
struct checker {
    const model& scene;
    state_layout layout;
    std::optional<probe> lagrangian;
    std::optional<probe> forces; ///< force_terms, when the scene has generalized forces
    std::optional<probe> energies; ///< the terms of T, V and the `L` lines as built, for the size of L's terms
    std::string why_not; ///< why L could not be compiled
    std::vector<parameter_point> points;
    sampler random;

    checker(const model& s, const lagrangian_result& l) : scene(s), layout(layout_of(s)), points(parameter_points(s))
    {
        try {
            lagrangian.emplace(std::vector<ex>{built_lagrangian(s, l)}, layout);
            energies.emplace(top_level_terms({l.kinetic_built, l.potential_built,
                                              s.lagrangian_terms ? *s.lagrangian_terms : ex(0)}),
                             layout);
            if (s.has_generalized_forces())
                forces.emplace(force_terms(s), layout);
        } catch (const std::invalid_argument& error) {
            lagrangian.reset();
            why_not = std::string("L or the forces cannot be evaluated numerically (") + error.what() + ")";
        }
    }
    double_double l_at(const std::vector<double>& state) const { return (*lagrangian)(state)[0]; }
    /// Σ |term| over the terms of T, V and the `L` lines at a state: the size of L's terms, of
    /// which L (or V alone, at an equilibrium where its terms balance) may be a small difference.
    double energy_size(const std::vector<double>& state) const
    {
        double size = 0;
        for (const double_double& e : (*energies)(state))
            size += std::abs(value_of(e));
        return std::isfinite(size) ? size : 0;
    }

    /// A state at the parameter point: coordinates, velocities and accelerations in [−1, 1],
    /// t in [0, 1].
    std::vector<double> random_state(const parameter_point& p)
    {
        std::vector<double> state(layout.symbols.size());
        for (std::size_t i = 0; i < 3 * layout.n; ++i)
            state[i] = random.uniform(-1, 1);
        state[layout.time()] = random.uniform(0, 1);
        for (std::size_t k = 0; k < p.values.size(); ++k)
            state[layout.parameter(k)] = p.values[k];
        for (std::size_t k = 0; k < scene.inputs.size(); ++k)
            state[layout.input(k)] = random.uniform(-1, 1);
        return state;
    }
};

/// The generalized forces Q at a state from the scene's statements by finite differences:
/// −∂F/∂q̇ of the Rayleigh function (a damper's ½ b (d/dt |r_A − r_B|)² with the rate of the
/// length differenced along the motion), `force q` values, and F · ∂r_P/∂q by differences
/// of P's position. Zeros without forces.
std::vector<double> generalized_force_reference(const checker& c, const std::vector<double>& state)
{
    const std::size_t n = c.layout.n;
    std::vector<double> q(n, 0.0);
    if (!c.forces)
        return q;
    const model& scene = c.scene;
    auto terms = [&](const std::vector<double>& s) { return (*c.forces)(s); };
    // The Rayleigh function at a state: the rate of a damper's length along q + q̇τ, t + τ.
    auto rayleigh = [&](const std::vector<double>& s) {
        std::vector<double_double> at = terms(s);
        double_double f = at[0];
        for (std::size_t d = 0; d < scene.dampers.size(); ++d) {
            double_double rate = first_derivative([&](double tau) {
                std::vector<double> moved = s;
                for (std::size_t j = 0; j < n; ++j)
                    moved[j] = s[j] + s[n + j] * tau;
                moved[c.layout.time()] = s[c.layout.time()] + tau;
                return terms(moved)[2 + 2 * d];
            });
            f = dd::add(f, dd::mul(double_double{0.5, 0}, dd::mul(at[1 + 2 * d], dd::mul(rate, rate))));
        }
        return f;
    };
    std::vector<double_double> here = terms(state);
    const std::size_t first_force = 1 + 2 * scene.dampers.size();
    for (std::size_t k = 0; k < scene.forces.size(); ++k)
        q[scene.forces[k].coordinate] += value_of(here[first_force + k]);
    const std::size_t first_point = first_force + scene.forces.size();
    for (std::size_t i = 0; i < n; ++i) {
        q[i] -= value_of(first_derivative([&](double h) {
            std::vector<double> moved = state;
            moved[n + i] += h;
            return rayleigh(moved);
        }));
        for (std::size_t p = 0; p < scene.point_forces.size(); ++p)
            for (std::size_t k = 0; k < 3; ++k) {
                const std::size_t entry = first_point + 6 * p + 2 * k;
                double_double slope = first_derivative([&](double h) {
                    std::vector<double> moved = state;
                    moved[i] += h;
                    return terms(moved)[entry + 1];
                });
                q[i] += value_of(here[entry]) * value_of(slope);
            }
    }
    return q;
}

// ---- the equations of motion ----

/// The Euler–Lagrange operator d/dt ∂L/∂q̇ − ∂L/∂q of the built L at a state, by nested
/// differences along the path q + q̇τ + q̈τ²/2: each term, and their scale.
struct euler_lagrange_values {
    std::vector<double> residual, scale;
    std::vector<double> momenta; ///< ∂L/∂q̇
    double lagrangian = 0;
};

euler_lagrange_values euler_lagrange(const checker& c, const std::vector<double>& state, double h = step)
{
    const std::size_t n = c.layout.n;
    euler_lagrange_values result;
    result.lagrangian = value_of(c.l_at(state));
    auto along_path = [&](double tau) {
        std::vector<double> s = state;
        for (std::size_t j = 0; j < n; ++j) {
            s[j] = state[j] + state[n + j] * tau + state[2 * n + j] * tau * tau / 2;
            s[n + j] = state[n + j] + state[2 * n + j] * tau;
        }
        s[c.layout.time()] = state[c.layout.time()] + tau;
        return s;
    };
    for (std::size_t i = 0; i < n; ++i) {
        auto momentum_at = [&](const std::vector<double>& s) {
            return first_derivative(
                [&](double dx) {
                    std::vector<double> moved = s;
                    moved[n + i] += dx;
                    return c.l_at(moved);
                },
                h);
        };
        double_double rate = first_derivative([&](double tau) { return momentum_at(along_path(tau)); }, h);
        double_double force = first_derivative(
            [&](double dx) {
                std::vector<double> moved = state;
                moved[i] += dx;
                return c.l_at(moved);
            },
            h);
        result.residual.push_back(value_of(dd::sub(rate, force)));
        result.scale.push_back(std::abs(value_of(rate)) + std::abs(value_of(force)));
        result.momenta.push_back(value_of(momentum_at(state)));
    }
    return result;
}

verification_entry check_equations(checker& c, const equations_of_motion& equations)
{
    const std::string how = "the Euler–Lagrange operator of L as built, by finite differences in double-double";
    const std::size_t n = c.layout.n;
    std::vector<ex> outputs;
    if (equations.residuals)
        outputs = *equations.residuals;
    // The multipliers' terms Σ a_ki λ_k are checked with the multipliers (verify_multipliers).
    GiNaC::exmap no_multipliers;
    for (const constraint& k : c.scene.constraints)
        no_multipliers[k.multiplier] = 0;
    for (ex& e : outputs)
        e = e.subs(no_multipliers);
    for (std::size_t i = 0; i < n; ++i) {
        ex ma = 0;
        for (std::size_t j = 0; j < n; ++j)
            ma += equations.mass(static_cast<unsigned>(i), static_cast<unsigned>(j)) *
                  c.scene.coordinates[j].acceleration;
        outputs.push_back(ma - equations.forcing[i]);
    }
    outputs.push_back(equations.energy);
    std::optional<probe> symbolic;
    try {
        symbolic.emplace(outputs, c.layout);
    } catch (const std::invalid_argument& error) {
        return {"equations", std::string("not checked: the equations cannot be evaluated numerically (") +
                                 error.what() + ")", false};
    }
    int used = 0;
    for (const parameter_point& p : c.points) {
        std::vector<double> state = c.random_state(p);
        euler_lagrange_values reference = euler_lagrange(c, state);
        const euler_lagrange_values coarse = euler_lagrange(c, state, 2 * step);
        // The equations are d/dt ∂L/∂q̇ − ∂L/∂q − Q = 0.
        const std::vector<double> forces = generalized_force_reference(c, state);
        for (std::size_t i = 0; i < n; ++i) {
            reference.residual[i] -= forces[i];
            reference.scale[i] += std::abs(forces[i]);
        }
        std::vector<double_double> here = (*symbolic)(state);
        bool finite = std::isfinite(reference.lagrangian);
        for (const double_double& x : here)
            finite = finite && std::isfinite(value_of(x));
        for (double x : reference.residual)
            finite = finite && std::isfinite(x);
        if (!finite)
            continue;
        const std::string where = state_text(c.scene, state, true) + (p.text.empty() ? "" : " and " + p.text);
        double largest = 0;
        for (double s : reference.scale)
            largest = std::max(largest, s);
        const std::size_t forms = equations.residuals ? 2 : 1;
        for (std::size_t form = 0; form < forms; ++form)
            for (std::size_t i = 0; i < n; ++i) {
                double value = value_of(here[form * n + i]);
                const double truncation = std::abs(reference.residual[i] - coarse.residual[i]) / tolerance;
                double scale = reference.scale[i] + 1e-6 * largest + rounding_allowance(c.energy_size(state)) +
                               truncation + 1e-300;
                if (!close(value, reference.residual[i], scale))
                    fail("the equations of motion",
                         std::string(forms == 2 && form == 0 ? "the equation" : "M q'' − f in the row") + " of " +
                             c.scene.coordinates[i].name,
                         where, value, reference.residual[i]);
            }
        double energy = -reference.lagrangian, energy_scale = std::abs(reference.lagrangian);
        for (std::size_t i = 0; i < n; ++i) {
            energy += state[n + i] * reference.momenta[i];
            energy_scale += std::abs(state[n + i] * reference.momenta[i]) +
                            std::abs(state[n + i] * (reference.momenta[i] - coarse.momenta[i])) / tolerance;
        }
        double energy_here = value_of(here.back());
        if (!close(energy_here, energy, energy_scale + 1e-300))
            fail("the energy function", "h", where, energy_here, energy);
        if (++used == points_wanted)
            break;
    }
    if (used == 0)
        return {"equations", "not checked: L is not a finite real number at any point tried", false};
    return {"equations", how + (c.forces ? ", less the generalized forces of the statements by finite differences"
                                         : "") +
                             " at " + std::to_string(used) + " seeded random states",
            true};
}

// ---- the equilibrium and the linearization ----

/// The equilibrium at a parameter point, rounded to doubles; nothing if not real.
std::optional<std::vector<double>> equilibrium_at(const std::vector<ex>& at, const parameter_point& p)
{
    std::vector<double> q;
    for (const ex& x : at) {
        std::optional<double> v = real_at(x, p.map);
        if (!v)
            return std::nullopt;
        q.push_back(*v);
    }
    return q;
}

std::vector<double> resting_state(const checker& c, const std::vector<double>& q, const parameter_point& p)
{
    std::vector<double> state(c.layout.symbols.size(), 0.0);
    for (std::size_t i = 0; i < q.size(); ++i)
        state[i] = q[i];
    for (std::size_t k = 0; k < p.values.size(); ++k)
        state[c.layout.parameter(k)] = p.values[k];
    return state;
}

double quadratic_form(const Eigen::MatrixXd& m, const Eigen::VectorXd& v) { return v.dot(m * v); }

/// The linearization at the parameter points: ∂U/∂q = 0 along every coordinate, and the
/// quadratic forms of T and V along random directions against second differences of
/// L(q₀, εv) and −L(q₀ + εv, 0).
void check_linearization(checker& c, const linearization_result& linear, bool check_point,
                         std::vector<verification_entry>& entries)
{
    const std::size_t n = c.layout.n;
    int used = 0;
    for (const parameter_point& p : c.points) {
        std::optional<std::vector<double>> q = equilibrium_at(linear.at, p);
        std::optional<Eigen::MatrixXd> kinetic = matrix_at(linear.kinetic, p.map);
        // V less the applied forces' stiffness (linearization.h): the Hessian of U alone
        std::optional<Eigen::MatrixXd> potential = matrix_at(
            linear.has_force_stiffness() ? linear.potential.sub(linear.force_stiffness) : linear.potential, p.map);
        if (!q || !kinetic || !potential)
            continue;
        const std::vector<double> rest = resting_state(c, *q, p);
        if (!std::isfinite(value_of(c.l_at(rest))))
            continue;
        std::string where = "the equilibrium";
        for (std::size_t i = 0; i < n; ++i)
            where += (i ? ", " : " ") + c.scene.coordinates[i].name + " = " + message_number((*q)[i]);
        if (!p.text.empty())
            where += " with " + p.text;
        auto potential_along = [&](const Eigen::VectorXd& v, double eps) {
            std::vector<double> s = rest;
            for (std::size_t i = 0; i < n; ++i)
                s[i] += eps * v[static_cast<Eigen::Index>(i)];
            return dd::neg(c.l_at(s));
        };
        auto kinetic_along = [&](const Eigen::VectorXd& v, double eps) {
            std::vector<double> s = rest;
            for (std::size_t i = 0; i < n; ++i)
                s[n + i] = eps * v[static_cast<Eigen::Index>(i)];
            return c.l_at(s);
        };
        const double size = kinetic->cwiseAbs().sum() + potential->cwiseAbs().sum() + 1e-300;
        const double noise = rounding_allowance(c.energy_size(rest));
        if (check_point) {
            for (std::size_t i = 0; i < n; ++i) {
                Eigen::VectorXd e = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n));
                e[static_cast<Eigen::Index>(i)] = 1;
                const estimate slope = estimated_first_derivative([&](double h) { return potential_along(e, h); });
                if (!close(slope.value, 0,
                           potential->cwiseAbs().sum() + noise * step + slope.error / tolerance + 1e-300))
                    fail("the equilibrium", "∂U/∂" + c.scene.coordinates[i].name, where, slope.value, 0);
            }
        }
        std::optional<Eigen::MatrixXd> gyroscopic;
        if (linear.has_gyroscopic())
            gyroscopic = matrix_at(linear.gyroscopic, p.map);
        if (gyroscopic) {
            // uᵀGv = ∂²L/∂(q along u)∂(q̇ along v) − the same with u and v exchanged; each mixed
            // derivative by polarization: ½(f''(t, t) − f''(t, 0) − f''(0, t)).
            auto along = [&](const Eigen::VectorXd& u, const Eigen::VectorXd& v, double a, double b) {
                std::vector<double> s = rest;
                for (std::size_t i = 0; i < n; ++i) {
                    s[i] += a * u[static_cast<Eigen::Index>(i)];
                    s[n + i] = b * v[static_cast<Eigen::Index>(i)];
                }
                return c.l_at(s);
            };
            double truncation = 0;
            auto mixed = [&](const Eigen::VectorXd& u, const Eigen::VectorXd& v) {
                const estimate both = estimated_second_derivative([&](double t) { return along(u, v, t, t); });
                const estimate positions = estimated_second_derivative([&](double t) { return along(u, v, t, 0); });
                const estimate velocities = estimated_second_derivative([&](double t) { return along(u, v, 0, t); });
                truncation += (both.error + positions.error + velocities.error) / 2;
                return (both.value - positions.value - velocities.value) / 2;
            };
            Eigen::VectorXd u(static_cast<Eigen::Index>(n)), v(static_cast<Eigen::Index>(n));
            for (std::size_t i = 0; i < n; ++i) {
                u[static_cast<Eigen::Index>(i)] = c.random.uniform(-1, 1);
                v[static_cast<Eigen::Index>(i)] = c.random.uniform(-1, 1);
            }
            const double reference = mixed(u, v) - mixed(v, u), form = u.dot(*gyroscopic * v);
            if (!close(form, reference,
                       (size + gyroscopic->cwiseAbs().sum()) * u.norm() * v.norm() + 3 * noise + truncation / tolerance))
                fail("the linearization", "uᵀGv along random u, v", where, form, reference);
        }
        for (int direction = 0; direction < 2; ++direction) {
            Eigen::VectorXd v(static_cast<Eigen::Index>(n));
            for (std::size_t i = 0; i < n; ++i)
                v[static_cast<Eigen::Index>(i)] = c.random.uniform(-1, 1);
            const estimate t_form = estimated_second_derivative([&](double eps) { return kinetic_along(v, eps); });
            const estimate v_form = estimated_second_derivative([&](double eps) { return potential_along(v, eps); });
            const double scale = size * v.squaredNorm() + noise;
            if (!close(quadratic_form(*kinetic, v), t_form.value, scale + t_form.error / tolerance))
                fail("the linearization", "vᵀTv along a random v", where, quadratic_form(*kinetic, v), t_form.value);
            if (!close(quadratic_form(*potential, v), v_form.value, scale + v_form.error / tolerance))
                fail("the linearization", "vᵀVv along a random v", where, quadratic_form(*potential, v),
                     v_form.value);
        }
        if (++used == points_wanted)
            break;
    }
    const std::string points = " at " + std::to_string(used) + " parameter points";
    if (used == 0) {
        const std::string why = "not checked: the equilibrium is not real at any parameter point tried";
        if (check_point)
            entries.push_back({"equilibrium", why, false});
        entries.push_back({"linearization", why, false});
        return;
    }
    if (check_point)
        entries.push_back({"equilibrium", "∂U/∂q = 0 by finite differences of L as built" + points, true});
    entries.push_back({"linearization",
                       std::string("quadratic forms of T and V") + (linear.has_gyroscopic() ? " and the form of G" : "") +
                           " along random directions against second differences of L as built" + points,
                       true});
}

} // namespace

verification_result verify_results(const model& scene, const verification_input& input,
                                   const std::set<product>& shown)
{
    verification_result result;
    result.entries = verify_bodies(scene, input.inertia, input.euler);
    if (!input.lagrangian || scene.coordinates.empty())
        return result;
    checker c(scene, *input.lagrangian);
    auto not_checked = [&](const std::string& item) { result.entries.push_back({item, "not checked: " + c.why_not, false}); };
    if (input.equations) {
        if (c.lagrangian)
            result.entries.push_back(check_equations(c, *input.equations));
        else
            not_checked("equations");
    }
    if (input.multipliers && input.equations)
        result.entries.push_back(check_multipliers(scene, *input.equations, *input.multipliers));
    if (input.linearization) {
        const bool point = input.equilibria != nullptr;
        if (input.constrained) {
            check_constrained_linearization(scene, *input.lagrangian, *input.constrained, point, result.entries);
        } else if (c.lagrangian) {
            check_linearization(c, *input.linearization, point, result.entries);
        } else {
            if (point)
                not_checked("equilibrium");
            not_checked("linearization");
        }
        check_oscillations(scene, c.points, {*input.linearization, input.characteristic, input.modes}, shown,
                           result.entries);
        if (input.asymptotic && !input.constrained)
            result.entries.push_back(verify_asymptotic(scene, *input.linearization, *input.asymptotic));
        if (input.damping)
            for (verification_entry& entry : verify_damping(scene, *input.linearization, *input.damping))
                result.entries.push_back(std::move(entry));
        if (input.state_space)
            for (verification_entry& entry :
                 verify_linear_system(scene, *input.linearization, *input.state_space, input.transfer))
                result.entries.push_back(std::move(entry));
    }
    if (input.floquet && input.equations)
        result.entries.push_back(verify_floquet(scene, *input.equations, *input.floquet));
    check_symmetries(scene, *input.lagrangian,
                     symmetry_input{input.conserved, input.hamiltonian, input.reduced, input.steady}, result.entries);
    return result;
}

} // namespace lagrange
