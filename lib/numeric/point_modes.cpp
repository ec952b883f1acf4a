// SPDX-License-Identifier: GPL-2.0-or-later
/** @file point_modes.cpp
 *  The numeric small oscillations at a parameter point, by one path (see point_modes.h). */
#include "numeric/point_modes.h"

#include "core/errors.h"
#include "numeric/damped_modes.h"
#include "numeric/gyroscopic_modes.h"

#include <cmath>
#include <stdexcept>

namespace lagrange {

namespace {

bool is_zero(const GiNaC::matrix& m)
{
    for (unsigned i = 0; i < m.rows(); ++i)
        for (unsigned j = 0; j < m.cols(); ++j)
            if (!m(i, j).is_zero())
                return false;
    return true;
}

/// `message` located at `where`: its "at these values" made precise, or `where` appended.
computation_error located(const std::string& message, const std::string& where)
{
    const std::string vague = "at these values";
    std::string text = message;
    const std::size_t at = text.find(vague);
    if (at != std::string::npos)
        text.replace(at, vague.size(), "at " + where);
    else
        text += " at " + where;
    return computation_error(text);
}

} // namespace

point_modes::point_modes(const model& scene, const linearization_result& linear, const GiNaC::matrix* damping)
    : scene_(&scene), linear_(&linear), size_(linear.kinetic.rows()),
      gyroscopic_(linear.has_gyroscopic() || linear.circulatory()),
      damped_(damping && !is_zero(*damping)), damping_(damped_ ? *damping : GiNaC::matrix(size_, size_))
{
    std::vector<GiNaC::ex> symbols;
    for (const parameter& p : scene.parameters)
        symbols.push_back(p.symbol);
    std::vector<const GiNaC::matrix*> matrices{&linear.kinetic, &linear.potential, &linear.gyroscopic, &damping_};
    for (const parameter& p : scene.parameters) {
        bool used = false;
        for (const GiNaC::matrix* m : matrices)
            used = used || m->has(p.symbol);
        used_.push_back(used);
    }
    if (!gyroscopic_)
        conservative_.emplace(scene.parameters, linear, compiled_modes_options{}, coordinate_names(scene));
    if (!gyroscopic_ && !damped_)
        return;
    std::vector<GiNaC::ex> outputs;
    for (const GiNaC::matrix* m : matrices)
        for (unsigned i = 0; i < size_; ++i)
            for (unsigned j = 0; j < size_; ++j) {
                GiNaC::ex rest = (*m)(i, j);
                for (const GiNaC::ex& s : symbols)
                    rest = rest.subs(s == 1);
                if (!GiNaC::is_a<GiNaC::numeric>(rest.evalf()))
                    throw computation_error("the linearization holds a symbol that is not a parameter");
                outputs.push_back((*m)(i, j));
            }
    matrices_.emplace(outputs, symbols);
    entries_.resize(outputs.size());
}

void point_modes::diagnose(const double* values, const std::string& where) const
{
    GiNaC::exmap at;
    for (std::size_t k = 0; k < scene_->parameters.size(); ++k)
        if (!std::isnan(values[k]))
            at[scene_->parameters[k].symbol] = GiNaC::numeric(values[k]);
    struct named {
        const GiNaC::matrix* m;
        const char *letter, *name;
    };
    for (const named& m : {named{&linear_->kinetic, "T", "kinetic"}, named{&linear_->potential, "V", "potential"},
                           named{&linear_->gyroscopic, "G", "gyroscopic"}, named{&damping_, "C", "damping"}})
        for (unsigned i = 0; i < m.m->rows(); ++i)
            for (unsigned j = 0; j < m.m->cols(); ++j) {
                const std::string entry = std::string(m.letter) + "(" + std::to_string(i + 1) + "," +
                                          std::to_string(j + 1) + ") of the " + m.name + " matrix";
                GiNaC::ex value;
                try {
                    value = (*m.m)(i, j).subs(at).evalf();
                } catch (const std::exception&) {
                    throw computation_error("the entry " + entry + " cannot be evaluated at " + where +
                                            " (a singularity: a division by zero, or log of zero)");
                }
                if (!GiNaC::is_a<GiNaC::numeric>(value))
                    continue; // a parameter without a value: reported elsewhere
                const GiNaC::numeric number = GiNaC::ex_to<GiNaC::numeric>(value);
                if (!number.is_real())
                    throw computation_error("the entry " + entry + " is not real at " + where +
                                            ": a value outside the domain of sqrt, log or an inverse function");
                if (!std::isfinite(number.to_double()))
                    throw computation_error("the entry " + entry + " overflows double precision at " + where +
                                            " (its magnitude is beyond 1.8e308)");
            }
}

void point_modes::evaluate(const double* values, numeric_modes& out, const std::function<std::string()>& where)
{
    const std::size_t n = size_;
    std::size_t given = 0; // the names stay from call to call: a sweep allocates nothing per point
    for (std::size_t k = 0; k < scene_->parameters.size(); ++k)
        if (used_[k]) {
            if (given < out.values.size() && out.values[given].first == scene_->parameters[k].name)
                out.values[given].second = values[k];
            else {
                out.values.resize(given);
                out.values.emplace_back(scene_->parameters[k].name, values[k]);
            }
            ++given;
        }
    out.values.resize(given);
    out.damped = false;
    out.eigenvalue_error.clear();
    out.damping_ratio.clear();
    out.damped_mode_backward_error.clear();
    out.proportional_damping = false;
    if (conservative_) {
        out.omega_squared.resize(n);
        out.omega.resize(n);
        out.error.resize(n);
        out.modes.resize(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
        try {
            out.method = to_string(conservative_->evaluate(values, out.omega_squared.data(), out.omega.data(),
                                                           out.error.data(), out.modes.data()));
        } catch (const computation_error& error) {
            const std::string at = where();
            diagnose(values, at);
            throw located(error.what(), at);
        } catch (const std::exception&) { // GiNaC's pole_error and kin from exact arithmetic
            const std::string at = where();
            diagnose(values, at);
            throw computation_error("the numeric modes cannot be evaluated at " + at);
        }
        for (std::size_t k = 0; k < n; ++k)
            if (!std::isfinite(out.omega[k]) || !std::isfinite(out.error[k])) {
                const std::string at = where();
                diagnose(values, at);
                throw computation_error("the frequencies are not finite at " + at +
                                        ": an entry of T or V overflows or leaves the domain of a function there");
            }
        out.growth_rate.resize(n);
        for (std::size_t k = 0; k < n; ++k)
            out.growth_rate[k] = out.omega[k] < 0 ? -out.omega[k] : 0.0;
        out.eigenvalues.clear();
        out.complex_modes.resize(0, 0);
        out.stability.clear();
    }
    if (!matrices_)
        return;
    matrices_->run(values, scratch_, entries_.data());
    const Eigen::Index size = static_cast<Eigen::Index>(n);
    Eigen::MatrixXd* targets[] = {&kinetic_, &potential_, &gyroscopic_matrix_, &damping_matrix_};
    std::size_t next = 0;
    for (Eigen::MatrixXd* m : targets) {
        m->resize(size, size);
        for (Eigen::Index i = 0; i < size; ++i)
            for (Eigen::Index j = 0; j < size; ++j)
                (*m)(i, j) = entries_[next++];
        if (!m->allFinite()) {
            const std::string at = where();
            diagnose(values, at);
            throw computation_error("the linearization is not finite at " + at);
        }
    }
    try {
        if (gyroscopic_) {
            numeric_modes modes = gyroscopic_modes_at(kinetic_, potential_, gyroscopic_matrix_);
            out.method = std::move(modes.method);
            out.omega = std::move(modes.omega);
            out.omega_squared = std::move(modes.omega_squared);
            out.error = std::move(modes.error);
            out.growth_rate = std::move(modes.growth_rate);
            out.modes.resize(0, 0);
            out.eigenvalues = std::move(modes.eigenvalues);
            out.complex_modes = std::move(modes.complex_modes);
            out.stability = std::move(modes.stability);
        }
        if (damped_)
            add_damped_eigenvalues(out, kinetic_, potential_, damping_matrix_, gyroscopic_matrix_);
    } catch (const computation_error& error) {
        throw located(error.what(), where());
    }
}

std::vector<numeric_modes> numeric_normal_modes(const model& scene, const linearization_result& linear,
                                                const GiNaC::matrix* damping)
{
    point_modes path(scene, linear, damping);
    std::vector<numeric_modes> results;
    for (const value_point& point : scene.values) {
        const auto where = [&] { return "the values on line " + std::to_string(point.where.line); };
        std::vector<double> values(scene.parameters.size(), std::nan(""));
        std::vector<bool> given(scene.parameters.size(), false);
        read_value_point(scene, point, values, given);
        for (std::size_t k = 0; k < scene.parameters.size(); ++k)
            if (path.uses(k) && !given[k])
                throw computation_error("no value for parameter `" + scene.parameters[k].name + "` at " + where());
        numeric_modes modes;
        path.evaluate(values.data(), modes, where);
        // echo every value the user gave, also those the modes do not need, in declared order
        modes.values.clear();
        for (std::size_t k = 0; k < scene.parameters.size(); ++k)
            if (given[k])
                modes.values.emplace_back(scene.parameters[k].name, values[k]);
        results.push_back(std::move(modes));
    }
    return results;
}

std::string stability_of(const numeric_modes& modes)
{
    if (!modes.stability.empty())
        return modes.stability;
    bool unstable = false, marginal = false;
    for (std::size_t k = 0; k < modes.omega.size(); ++k) {
        const double bound = modes.omega[k] == 0 ? modes.error[k] : modes.error[k] * std::abs(modes.omega[k]);
        unstable = unstable || modes.omega[k] < -bound;
        marginal = marginal || std::abs(modes.omega[k]) <= bound;
    }
    return unstable ? "unstable" : marginal ? "marginal" : "stable";
}

} // namespace lagrange
