// SPDX-License-Identifier: GPL-2.0-or-later
/** @file check_operating_point.cpp
 *  A, B and the residual about an operating point against central differences. */
#include "verify/check_operating_point.h"

#include "core/errors.h"
#include "program/expression_program.h"
#include "verify/points.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

namespace lagrange {

namespace {

using namespace verification_points;

/// The constrained dynamics at numbers: ẋ = (q̇_I, q̈_J) of the independent state.
class constrained_dynamics {
public:
    constrained_dynamics(const model& scene, const equations_of_motion& equations, const operating_linearization& point)
        : scene_(scene), point_(point), n_(scene.coordinates.size()), m_(scene.constraints.size()),
          p_(scene.inputs.size())
    {
        std::vector<GiNaC::ex> outputs, symbols;
        for (unsigned i = 0; i < n_; ++i)
            for (unsigned j = 0; j < n_; ++j)
                outputs.push_back(equations.mass(i, j));
        for (const GiNaC::ex& f : equations.forcing)
            outputs.push_back(f);
        for (unsigned k = 0; k < m_; ++k) {
            for (unsigned j = 0; j < n_; ++j)
                outputs.push_back(equations.constraints->matrix(k, j));
            outputs.push_back(equations.constraints->bias[k]);
            outputs.push_back(scene.constraints[k].rest);
            outputs.push_back(scene.constraints[k].constraint_kind == constraint::kind::holonomic
                                  ? scene.constraints[k].function
                                  : GiNaC::ex(0));
        }
        for (const coordinate& c : scene.coordinates)
            symbols.push_back(c.position);
        for (const coordinate& c : scene.coordinates)
            symbols.push_back(c.velocity);
        for (const input_signal& u : scene.inputs)
            symbols.push_back(u.symbol);
        for (const parameter& q : scene.parameters)
            symbols.push_back(q.symbol);
        program_ = expression_program(outputs, symbols);
    }

    /// ẋ at the independent state `x` and inputs `u`, the rest of the point at `base`
    /// (positions, velocities, inputs, parameters); nothing where Newton's method fails.
    std::optional<Eigen::VectorXd> rate(const std::vector<double>& base, const Eigen::VectorXd& x,
                                        const Eigen::VectorXd& u)
    {
        std::vector<double> symbols = base;
        const std::size_t free_coordinates = point_.coordinates.size();
        for (std::size_t r = 0; r < free_coordinates; ++r)
            symbols[point_.coordinates[r]] = x(static_cast<Eigen::Index>(r));
        for (std::size_t r = 0; r < point_.speeds.size(); ++r)
            symbols[n_ + point_.speeds[r]] = x(static_cast<Eigen::Index>(free_coordinates + r));
        for (std::size_t k = 0; k < p_; ++k)
            symbols[2 * n_ + k] = u(static_cast<Eigen::Index>(k));
        // The dependent coordinates: Newton on the holonomic constraints.
        std::vector<std::size_t> holonomic, dependent = complement(point_.coordinates);
        for (std::size_t k = 0; k < m_; ++k)
            if (scene_.constraints[k].constraint_kind == constraint::kind::holonomic)
                holonomic.push_back(k);
        for (int iteration = 0; iteration < 50 && !holonomic.empty(); ++iteration) {
            evaluate(symbols);
            Eigen::MatrixXd jacobian(holonomic.size(), dependent.size());
            Eigen::VectorXd residual(holonomic.size());
            for (std::size_t r = 0; r < holonomic.size(); ++r) {
                residual(static_cast<Eigen::Index>(r)) = function(holonomic[r]);
                for (std::size_t d = 0; d < dependent.size(); ++d)
                    jacobian(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(d)) =
                        constraint_row(holonomic[r], dependent[d]);
            }
            const Eigen::VectorXd step = jacobian.fullPivLu().solve(residual);
            for (std::size_t d = 0; d < dependent.size(); ++d)
                symbols[dependent[d]] -= step(static_cast<Eigen::Index>(d));
            if (step.norm() < 1e-15 * (1 + residual.norm()))
                break;
        }
        evaluate(symbols);
        for (std::size_t k : holonomic)
            if (!(std::abs(function(k)) < 1e-11))
                return std::nullopt;
        // The dependent speeds from A q̇ + b = 0.
        const std::vector<std::size_t> dependent_speeds = complement(point_.speeds);
        if (m_ > 0) {
            Eigen::MatrixXd block(m_, dependent_speeds.size());
            Eigen::VectorXd known(m_);
            for (std::size_t k = 0; k < m_; ++k) {
                known(static_cast<Eigen::Index>(k)) = rest(k);
                for (std::size_t j : point_.speeds)
                    known(static_cast<Eigen::Index>(k)) += constraint_row(k, j) * symbols[n_ + j];
                for (std::size_t d = 0; d < dependent_speeds.size(); ++d)
                    block(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(d)) =
                        constraint_row(k, dependent_speeds[d]);
            }
            const Eigen::VectorXd solved = block.fullPivLu().solve(-known);
            for (std::size_t d = 0; d < dependent_speeds.size(); ++d)
                symbols[n_ + dependent_speeds[d]] = solved(static_cast<Eigen::Index>(d));
            evaluate(symbols);
        }
        // q̈ from the augmented system.
        const Eigen::Index size = static_cast<Eigen::Index>(n_ + m_);
        Eigen::MatrixXd system = Eigen::MatrixXd::Zero(size, size);
        Eigen::VectorXd right(size);
        for (std::size_t i = 0; i < n_; ++i) {
            for (std::size_t j = 0; j < n_; ++j)
                system(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = out_[i * n_ + j];
            right(static_cast<Eigen::Index>(i)) = out_[n_ * n_ + i];
        }
        for (std::size_t k = 0; k < m_; ++k) {
            for (std::size_t j = 0; j < n_; ++j) {
                system(static_cast<Eigen::Index>(n_ + k), static_cast<Eigen::Index>(j)) = constraint_row(k, j);
                system(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(n_ + k)) = -constraint_row(k, j);
            }
            right(static_cast<Eigen::Index>(n_ + k)) = -bias(k);
        }
        const Eigen::VectorXd solution = system.fullPivLu().solve(right);
        Eigen::VectorXd result(static_cast<Eigen::Index>(free_coordinates + point_.speeds.size()));
        for (std::size_t r = 0; r < free_coordinates; ++r)
            result(static_cast<Eigen::Index>(r)) = symbols[n_ + point_.coordinates[r]];
        for (std::size_t r = 0; r < point_.speeds.size(); ++r)
            result(static_cast<Eigen::Index>(free_coordinates + r)) = solution(static_cast<Eigen::Index>(point_.speeds[r]));
        return result;
    }

private:
    const model& scene_;
    const operating_linearization& point_;
    std::size_t n_, m_, p_;
    expression_program program_;
    std::vector<double> scratch_, out_;

    void evaluate(const std::vector<double>& symbols)
    {
        out_.resize(program_.output_count());
        program_.run(symbols.data(), scratch_, out_.data());
    }
    std::size_t constraint_base(std::size_t k) const { return n_ * n_ + n_ + k * (n_ + 3); }
    double constraint_row(std::size_t k, std::size_t j) const { return out_[constraint_base(k) + j]; }
    double bias(std::size_t k) const { return out_[constraint_base(k) + n_]; }
    double rest(std::size_t k) const { return out_[constraint_base(k) + n_ + 1]; }
    double function(std::size_t k) const { return out_[constraint_base(k) + n_ + 2]; }
    std::vector<std::size_t> complement(const std::vector<std::size_t>& taken) const
    {
        std::vector<std::size_t> rest;
        for (std::size_t j = 0; j < n_; ++j)
            if (std::find(taken.begin(), taken.end(), j) == taken.end())
                rest.push_back(j);
        return rest;
    }
};

std::optional<double> number(const GiNaC::ex& e, const GiNaC::exmap& at)
{
    const GiNaC::ex v = e.subs(at).evalf();
    if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real())
        return std::nullopt;
    return GiNaC::ex_to<GiNaC::numeric>(v).to_double();
}

} // namespace

verification_entry verify_operating_point(const model& scene, const equations_of_motion& equations,
                                          const operating_linearization& point)
{
    const std::size_t n = scene.coordinates.size(), p = scene.inputs.size();
    std::optional<constrained_dynamics> dynamics;
    try {
        dynamics.emplace(scene, equations, point);
    } catch (const std::invalid_argument&) {
        return {"state_space", "not checked: the equations use a function the compiled programs do not take", false};
    }
    sampler seeds;
    int checked = 0;
    std::string where;
    for (const parameter_point& parameters : parameter_points(scene)) {
        if (checked == points_wanted)
            break;
        GiNaC::exmap at = parameters.map;
        for (std::size_t i = 0; i < n; ++i)
            if (point.position[i].is_equal(scene.coordinates[i].position))
                at[scene.coordinates[i].position] = seeds.uniform(0.25, 1.25);
        std::vector<double> base(2 * n + p + scene.parameters.size());
        bool usable = true;
        auto set = [&](std::size_t slot, const GiNaC::ex& e) {
            const std::optional<double> v = number(e, at);
            usable = usable && v.has_value();
            base[slot] = v.value_or(0);
        };
        for (std::size_t i = 0; i < n; ++i) {
            set(i, point.position[i]);
            set(n + i, point.velocity[i]);
        }
        for (std::size_t k = 0; k < p; ++k)
            set(2 * n + k, point.inputs[k]);
        for (std::size_t k = 0; k < scene.parameters.size(); ++k)
            base[2 * n + p + k] = parameters.values[k];
        const std::optional<Eigen::MatrixXd> a = matrix_at(point.a, at);
        const std::optional<Eigen::MatrixXd> b = matrix_at(point.b, at);
        if (!usable || !a || !b)
            continue;
        const Eigen::Index states = a->rows();
        Eigen::VectorXd x(states), u(static_cast<Eigen::Index>(p)), residual(states);
        const std::size_t free_coordinates = point.coordinates.size();
        for (Eigen::Index r = 0; r < states; ++r) {
            const std::size_t k = static_cast<std::size_t>(r);
            const std::optional<double> f = number(point.residual[k], at);
            usable = usable && f;
            x(r) = k < free_coordinates ? base[point.coordinates[k]] : base[n + point.speeds[k - free_coordinates]];
            residual(r) = f.value_or(0);
        }
        for (std::size_t k = 0; k < p; ++k)
            u(static_cast<Eigen::Index>(k)) = base[2 * n + k];
        const std::optional<Eigen::VectorXd> rate = dynamics->rate(base, x, u);
        if (!usable || !rate)
            continue;
        const double scale = 1 + (a->size() ? a->cwiseAbs().maxCoeff() : 0.0) + (b->size() ? b->cwiseAbs().maxCoeff() : 0.0) +
                             (rate->size() ? rate->cwiseAbs().maxCoeff() : 0.0);
        const std::string here = at_point(parameters);
        for (Eigen::Index r = 0; r < states; ++r)
            if (!close((*rate)(r), residual(r), scale))
                fail("state_space", "residual entry " + std::to_string(r + 1), here, residual(r), (*rate)(r));
        // Central differences, step 2⁻²⁰ relative: about 1e-10 of truncation and rounding each.
        auto column = [&](Eigen::VectorXd dx, Eigen::VectorXd du, double h) -> std::optional<Eigen::VectorXd> {
            const std::optional<Eigen::VectorXd> up = dynamics->rate(base, x + dx, u + du);
            const std::optional<Eigen::VectorXd> down = dynamics->rate(base, x - dx, u - du);
            if (!up || !down)
                return std::nullopt;
            return (*up - *down) / (2 * h);
        };
        for (Eigen::Index j = 0; j < states + static_cast<Eigen::Index>(p); ++j) {
            const bool state = j < states;
            const double h = std::ldexp(1.0 + std::abs(state ? x(j) : u(j - states)), -20);
            Eigen::VectorXd dx = Eigen::VectorXd::Zero(states), du = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(p));
            (state ? dx(j) : du(j - states)) = h;
            const std::optional<Eigen::VectorXd> reference = column(dx, du, h);
            if (!reference) {
                usable = false;
                break;
            }
            for (Eigen::Index r = 0; r < states; ++r) {
                const double here_value = state ? (*a)(r, j) : (*b)(r, j - states);
                // Differences reach about 1e-9 of the scale; the tolerance is that, not 1e-7's 100×.
                if (std::abs(here_value - (*reference)(r)) > 1e-6 * scale)
                    fail("state_space", std::string(state ? "A" : "B") + "(" + std::to_string(r + 1) + ", " +
                                            std::to_string((state ? j : j - states) + 1) + ")",
                         here, here_value, (*reference)(r));
            }
        }
        if (!usable)
            continue;
        ++checked;
        where += (where.empty() ? "" : "; ") + here;
    }
    if (checked == 0)
        return {"state_space", "not checked: no parameter point where the constrained dynamics could be evaluated",
                false};
    return {"state_space",
            "A, B and the residual against central differences of the full constrained dynamics (dependent "
            "coordinates by Newton's method, speeds and accelerations from the constraints and [M −Aᵀ; A 0]) at " +
                where,
            true};
}

} // namespace lagrange
