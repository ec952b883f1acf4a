// SPDX-License-Identifier: GPL-2.0-or-later
/** @file lower_constraint.cpp
 *  Classifying constraints, and finding redundant or inconsistent ones by their
 *  velocity forms at random points. */
#include "scene/lower_constraint.h"

#include "scene/lexer.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <string>

namespace lagrange {

namespace {

/// Every coordinate, parameter and t at random values (parameters positive).
struct sample_point {
    GiNaC::exmap at;
    std::vector<double> positions;
};

sample_point random_point(const model& scene, std::mt19937& random)
{
    std::uniform_real_distribution<double> centred(-1.0, 1.0), positive(0.5, 2.0), time(0.1, 1.0);
    sample_point p;
    for (const parameter& q : scene.parameters)
        p.at[q.symbol] = positive(random);
    for (const input_signal& u : scene.inputs)
        p.at[u.symbol] = centred(random);
    for (const coordinate& c : scene.coordinates) {
        p.positions.push_back(centred(random));
        p.at[c.position] = p.positions.back();
    }
    p.at[scene.time] = time(random);
    return p;
}

/// The value of `e` at `at`, or nothing where it is not a finite real number.
std::optional<double> value_at(const GiNaC::ex& e, const GiNaC::exmap& at)
{
    try {
        GiNaC::ex v = e.subs(at).evalf();
        if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real())
            return std::nullopt;
        double d = GiNaC::ex_to<GiNaC::numeric>(v).to_double();
        return std::isfinite(d) ? std::optional<double>(d) : std::nullopt;
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

/// A constraint's velocity form (a, b) at a point.
struct velocity_form {
    Eigen::VectorXd a;
    double b = 0;
};

std::optional<velocity_form> form_at(const constraint& c, const GiNaC::exmap& at)
{
    velocity_form form{Eigen::VectorXd(static_cast<Eigen::Index>(c.coefficients.size())), 0};
    for (std::size_t j = 0; j < c.coefficients.size(); ++j) {
        std::optional<double> v = value_at(c.coefficients[j], at);
        if (!v)
            return std::nullopt;
        form.a[static_cast<Eigen::Index>(j)] = *v;
    }
    std::optional<double> b = value_at(c.rest, at);
    if (!b)
        return std::nullopt;
    form.b = *b;
    return form;
}

/// "constraint `a`", "constraints `a` and `b`", "constraints `a`, `b` and `c`".
std::string constraint_list(const model& scene, const std::vector<std::size_t>& which)
{
    std::string text = which.size() == 1 ? "constraint " : "constraints ";
    for (std::size_t k = 0; k < which.size(); ++k) {
        if (k > 0)
            text += k + 1 == which.size() ? " and " : ", ";
        text += "`" + scene.constraints[which[k]].name + "`";
    }
    return text;
}

/// Newton's method with minimum-norm steps for the holonomic constraints `which` = 0, from the
/// positions of `p` with its parameters and t: a point on their common manifold, if it converges.
std::optional<GiNaC::exmap> point_on_manifold(const model& scene, const std::vector<std::size_t>& which,
                                              const sample_point& p)
{
    const auto n = static_cast<Eigen::Index>(scene.coordinates.size());
    const auto m = static_cast<Eigen::Index>(which.size());
    GiNaC::exmap at = p.at;
    Eigen::VectorXd q = Eigen::Map<const Eigen::VectorXd>(p.positions.data(), n);
    for (int iteration = 0; iteration < 60; ++iteration) {
        for (Eigen::Index j = 0; j < n; ++j)
            at[scene.coordinates[static_cast<std::size_t>(j)].position] = q[j];
        Eigen::VectorXd g(m);
        Eigen::MatrixXd jacobian(m, n);
        for (Eigen::Index i = 0; i < m; ++i) {
            const constraint& c = scene.constraints[which[static_cast<std::size_t>(i)]];
            std::optional<double> value = value_at(c.function, at);
            std::optional<velocity_form> form = form_at(c, at);
            if (!value || !form)
                return std::nullopt;
            g[i] = *value;
            jacobian.row(i) = form->a.transpose();
        }
        if (g.norm() < 1e-13)
            return at;
        q -= jacobian.completeOrthogonalDecomposition().solve(g);
        if (!q.allFinite())
            return std::nullopt;
    }
    return std::nullopt;
}

constexpr int sample_points = 3;

} // namespace

constraint classify_constraint(const name_ref& name, const GiNaC::ex& f, const source_location& where,
                               const model& scene)
{
    constraint c;
    c.name = name.name;
    c.where = name.where;
    c.function = f;
    c.multiplier = GiNaC::realsymbol("lambda_" + name.name);
    bool has_velocity = false;
    for (const coordinate& q : scene.coordinates)
        has_velocity = has_velocity || f.has(q.velocity);
    if (!has_velocity) {
        c.constraint_kind = constraint::kind::holonomic;
        for (const coordinate& q : scene.coordinates)
            c.coefficients.push_back(f.diff(q.position));
        c.rest = f.diff(scene.time);
        return c;
    }
    c.constraint_kind = constraint::kind::pfaffian;
    GiNaC::exmap at_rest;
    for (const coordinate& q : scene.coordinates)
        at_rest[q.velocity] = 0;
    GiNaC::ex linear_part = 0;
    for (const coordinate& q : scene.coordinates) {
        GiNaC::ex a = f.diff(q.velocity);
        for (const coordinate& other : scene.coordinates)
            if (a.has(other.velocity))
                throw scene_error(where, "a constraint is holonomic (no velocities) or linear in the velocities "
                                         "(Pfaffian, as rolling `x' = R*phi'`); this one is neither: it is not "
                                         "linear in `" + q.name + "'`");
        c.coefficients.push_back(a);
        linear_part += a * q.velocity;
    }
    c.rest = f.subs(at_rest);
    if (!(f - linear_part - c.rest).normal().is_zero())
        throw scene_error(where, "a constraint is holonomic (no velocities) or linear in the velocities (Pfaffian, "
                                 "as rolling `x' = R*phi'`); this one is neither");
    return c;
}

void check_constraints(const model& scene)
{
    if (scene.constraints.empty())
        return;
    std::mt19937 random(20261124);
    std::vector<sample_point> points;
    std::vector<std::vector<velocity_form>> forms; // [point][constraint]
    for (int attempt = 0; attempt < 20 * sample_points && points.size() < sample_points; ++attempt) {
        sample_point p = random_point(scene, random);
        std::vector<velocity_form> at_p;
        for (const constraint& c : scene.constraints)
            if (std::optional<velocity_form> form = form_at(c, p.at))
                at_p.push_back(*form);
        if (at_p.size() != scene.constraints.size())
            continue;
        points.push_back(p);
        forms.push_back(at_p);
    }
    if (points.empty())
        return; // nowhere defined at random points: the computation says why

    std::vector<std::size_t> independent;
    for (std::size_t k = 0; k < scene.constraints.size(); ++k) {
        const constraint& c = scene.constraints[k];
        // Is row k a combination of the independent rows before it, at every point?
        bool dependent = true;
        std::vector<Eigen::VectorXd> combinations;
        for (std::size_t p = 0; p < points.size() && dependent; ++p) {
            const Eigen::VectorXd& row = forms[p][k].a;
            Eigen::MatrixXd basis(row.size(), static_cast<Eigen::Index>(independent.size()));
            for (std::size_t i = 0; i < independent.size(); ++i)
                basis.col(static_cast<Eigen::Index>(i)) = forms[p][independent[i]].a;
            double scale = 1 + row.lpNorm<Eigen::Infinity>();
            for (std::size_t i = 0; i < independent.size(); ++i)
                scale = std::max(scale, basis.col(static_cast<Eigen::Index>(i)).lpNorm<Eigen::Infinity>());
            Eigen::VectorXd combination = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(independent.size()));
            if (!independent.empty())
                combination = basis.completeOrthogonalDecomposition().solve(row);
            Eigen::VectorXd residual = row - basis * combination;
            dependent = residual.lpNorm<Eigen::Infinity>() <= 1e-9 * scale;
            combinations.push_back(combination);
        }
        if (!dependent) {
            independent.push_back(k);
            if (independent.size() >= scene.coordinates.size())
                throw scene_error(c.where, "with constraint `" + c.name + "` the " +
                                               std::to_string(independent.size()) + " constraints leave no degree "
                                               "of freedom among the " + std::to_string(scene.coordinates.size()) +
                                               " coordinates");
            continue;
        }
        std::vector<std::size_t> sources;
        for (std::size_t i = 0; i < independent.size(); ++i)
            if (std::abs(combinations[0][static_cast<Eigen::Index>(i)]) > 1e-9)
                sources.push_back(independent[i]);
        bool all_holonomic = c.constraint_kind == constraint::kind::holonomic;
        for (std::size_t i : sources)
            all_holonomic = all_holonomic && scene.constraints[i].constraint_kind == constraint::kind::holonomic;
        if (sources.empty()) {
            // It does not involve the coordinates' motion at all.
            bool holds = true;
            for (const sample_point& p : points) {
                std::optional<double> v =
                    value_at(all_holonomic ? c.function : c.rest, p.at);
                holds = holds && v && std::abs(*v) <= 1e-9;
            }
            throw scene_error(c.where, "constraint `" + c.name + "` " +
                                           (holds ? "is redundant: it holds identically"
                                                  : "is inconsistent: it involves no coordinate's motion and does "
                                                    "not hold"));
        }
        std::optional<bool> holds;
        if (all_holonomic) {
            // On the manifold of the sources, a function of them is constant: zero or not.
            for (const sample_point& p : points) {
                std::optional<GiNaC::exmap> on = point_on_manifold(scene, sources, p);
                if (!on)
                    continue;
                std::optional<double> v = value_at(c.function, *on);
                if (v) {
                    holds = std::abs(*v) <= 1e-8 * (1 + std::abs(value_at(c.function, p.at).value_or(0)));
                    break;
                }
            }
        } else {
            // Velocity forms: a_k = Σ c_i a_i, so they agree when b_k = Σ c_i b_i too.
            holds = true;
            for (std::size_t p = 0; p < points.size(); ++p) {
                double combined = 0, scale = 1 + std::abs(forms[p][k].b);
                for (std::size_t i = 0; i < independent.size(); ++i) {
                    combined += combinations[p][static_cast<Eigen::Index>(i)] * forms[p][independent[i]].b;
                    scale = std::max(scale, std::abs(forms[p][independent[i]].b));
                }
                holds = *holds && std::abs(forms[p][k].b - combined) <= 1e-9 * scale;
            }
        }
        const std::string others = constraint_list(scene, sources);
        if (!holds)
            throw scene_error(c.where, "constraint `" + c.name + "` is redundant or inconsistent: it depends on " +
                                           others);
        throw scene_error(c.where, "constraint `" + c.name + "` " +
                                       (*holds ? "is redundant: it follows from " + others
                                               : "is inconsistent with " + others + ": no motion satisfies both"));
    }
}

independent_request lower_independent(const statement& s, const model& scene, const std::string& line_text)
{
    independent_request request;
    request.where = s.where;
    request.line_text = line_text;
    for (const assignment& a : s.assignments) {
        const std::string& name = a.target.name;
        auto found = std::find_if(scene.coordinates.begin(), scene.coordinates.end(),
                                  [&](const coordinate& c) { return c.name == name; });
        if (found == scene.coordinates.end())
            throw scene_error(a.target.where, "`" + name + "` is not a coordinate");
        const std::size_t i = static_cast<std::size_t>(found - scene.coordinates.begin());
        std::vector<std::size_t>& list = a.velocity ? request.speeds : request.coordinates;
        if (std::find(list.begin(), list.end(), i) != list.end())
            throw scene_error(a.target.where, "`" + name + (a.velocity ? "'" : "") + "` is given twice");
        list.push_back(i);
    }
    return request;
}

} // namespace lagrange
