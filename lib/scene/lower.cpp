// SPDX-License-Identifier: GPL-2.0-or-later
/** @file lower.cpp
 *  Semantic checks and lowering of a scene's statements: declared names only, no
 *  duplicates, each statement's own rules (an equilibrium that gives every
 *  coordinate, ...). Expressions are lowered by lower_expression.cpp, bodies by
 *  lower_body.cpp. */
#include "scene/lower.h"

#include "core/assumptions.h"

#include "scene/lexer.h"
#include "scene/lower_body.h"
#include "scene/lower_constraint.h"
#include "scene/lower_expression.h"
#include "scene/parser.h"
#include "scene/slips.h"
#include "system/files.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

namespace lagrange {

namespace {

constexpr std::size_t max_rules_bytes = 16u << 20;
/// A rules file that is a named pipe or a device must give its data within this time.
constexpr double rules_wait_seconds = 30;

/// Lowers the statements of a scene, in order, into the model.
class lowering : public body_lowering {
public:
    lowering(const source_text& source, file_reader read_file)
        : source_(source), read_file_(std::move(read_file)) {}

    model run(const scene_ast& ast)
    {
        scene_.file = source_.file();
        scene_.kinetic_terms = 0;
        scene_.potential_terms = 0;
        for (const statement& s : ast.statements)
            lower_statement(s);
        finish();
        return std::move(scene_);
    }

    value_point values_line(const statement& s) { return lower_values(s); }
    initial_state initial_line(const statement& s) { return initial_of(s); }

private:
    // ---- statements ---------------------------------------------------------------

    void lower_statement(const statement& s)
    {
        const std::string& k = s.keyword;
        if (k == "scene") {
            if (seen_title_)
                throw scene_error(s.where, "the scene's title is given twice");
            seen_title_ = true;
            scene_.title = s.text;
        } else if (k == "parameters") {
            for (const name_ref& n : s.names)
                declare_parameter(n);
        } else if (k == "coordinates") {
            for (const name_ref& n : s.names)
                declare_coordinate(n);
        } else if (k == "let") {
            declare_name(s.names[0], "shorthand");
            expr_context context{"a shorthand"};
            context.velocities = true;
            names_[s.names[0].name] = {name_entry::kind::shorthand, lower(*s.value, context), 0, s.names[0].where};
        } else if (k == "T" || k == "V" || k == "L") {
            lower_energy(s);
        } else if (k == "point") {
            lower_point(s);
        } else if (k == "gravity") {
            lower_gravity(s);
        } else if (k == "spring") {
            lower_spring(s);
        } else if (k == "body") {
            lower_body(s);
        } else if (k == "omega") {
            lower_omega(s);
        } else if (k == "torque") {
            lower_torque(s);
        } else if (k == "equilibrium") {
            lower_equilibrium(s);
        } else if (k == "ratio") {
            lower_ratio(s);
        } else if (k == "limit") {
            lower_limit(s);
        } else if (k == "values") {
            scene_.values.push_back(lower_values(s));
            value_statements_.push_back(&s);
        } else if (k == "initial") {
            lower_initial(s);
        } else if (k == "simulate") {
            lower_simulate(s);
        } else if (k == "use") {
            lower_use(s);
        } else if (k == "want") {
            lower_want(s);
        } else if (k == "dissipation") {
            lower_dissipation(s);
        } else if (k == "damper") {
            lower_damper(s);
        } else if (k == "force") {
            lower_force(s);
        } else if (k == "input") {
            for (const name_ref& n : s.names)
                declare_input(n);
        } else if (k == "constraint") {
            lower_constraint(s);
        } else if (k == "linearize") {
            lower_operating_point(s);
        } else if (k == "independent") {
            if (scene_.independent)
                throw scene_error(s.where, "the independent coordinates are given twice");
            scene_.independent = lower_independent(s, scene_, source_.line(s.where.line));
        } else if (k == "critical") {
            lower_critical(s);
        } else if (k == "rolls") {
            lower_rolls(s);
        }
    }

    /// `linearize about q = e, q' = w, u = u0`: values in the parameters.
    void lower_operating_point(const statement& s)
    {
        if (scene_.operating_point)
            throw scene_error(s.where, "the operating point is given twice");
        operating_point_request point;
        point.where = s.where;
        point.positions.resize(coordinates_.size());
        point.velocities.resize(coordinates_.size());
        point.position_where.assign(coordinates_.size(), s.where);
        point.velocity_where.assign(coordinates_.size(), s.where);
        point.inputs.assign(scene_.inputs.size(), 0);
        std::vector<bool> input_given(scene_.inputs.size(), false);
        for (const assignment& a : s.assignments) {
            const GiNaC::ex value =
                lower(*a.value, expr_context{"an operating point's value", false, false, true, false});
            auto found = names_.find(a.target.name);
            if (found != names_.end() && found->second.name_kind == name_entry::kind::input && !a.velocity) {
                std::size_t k = 0;
                while (scene_.inputs[k].name != a.target.name)
                    ++k;
                if (input_given[k])
                    throw scene_error(a.target.where, quote(a.target.name) + " is given twice");
                input_given[k] = true;
                point.inputs[k] = value;
                continue;
            }
            if (found == names_.end() || found->second.name_kind != name_entry::kind::coordinate)
                throw scene_error(a.target.where, quote(a.target.name) + " is not a coordinate or an input");
            const std::size_t i = found->second.index;
            std::optional<GiNaC::ex>& target = a.velocity ? point.velocities[i] : point.positions[i];
            if (target)
                throw scene_error(a.target.where,
                                  "`" + a.target.name + (a.velocity ? "'" : "") + "` is given twice");
            target = value;
            (a.velocity ? point.velocity_where : point.position_where)[i] = a.value->where;
            point.line_texts[a.value->where.line] = source_.line(a.value->where.line);
        }
        point.line_texts[s.where.line] = source_.line(s.where.line);
        scene_.operating_point = std::move(point);
    }

    void declare_parameter(const name_ref& n)
    {
        declare_name(n, "parameter");
        parameter p{n.name, GiNaC::possymbol(n.name)};
        names_[n.name] = {name_entry::kind::parameter, p.symbol, 0, n.where};
        scene_.parameters.push_back(p);
    }

    void declare_coordinate(const name_ref& n)
    {
        declare_name(n, "coordinate");
        coordinate c{n.name, GiNaC::realsymbol(n.name), GiNaC::realsymbol(n.name + "_dot"),
                     GiNaC::realsymbol(n.name + "_ddot")};
        names_[n.name] = {name_entry::kind::coordinate, c.position, scene_.coordinates.size(), n.where};
        scene_.coordinates.push_back(c);
        coordinates_.push_back(c);
    }

    void lower_energy(const statement& s)
    {
        expr_context context{"an energy"};
        context.velocities = true;
        GiNaC::ex value = lower(*s.value, context);
        if (s.keyword == "L") {
            if (scene_.lagrangian_terms)
                throw scene_error(s.where, "the Lagrangian `L` is given twice");
            if (energy_line_)
                throw scene_error(s.where, "`L` gives the whole Lagrangian: it cannot be combined with the `" +
                                               energy_keyword_ + "` line at line " +
                                               std::to_string(energy_line_->line));
            scene_.lagrangian_terms = value;
            lagrangian_line_ = s.where;
            return;
        }
        if (lagrangian_line_)
            throw scene_error(s.where, quote(s.keyword) + " cannot be combined with the Lagrangian `L` at line " +
                                           std::to_string(lagrangian_line_->line));
        if (!energy_line_) {
            energy_line_ = s.where;
            energy_keyword_ = s.keyword;
        }
        if (s.keyword == "T" && !kinetic_line_)
            kinetic_line_ = s.where;
        (s.keyword == "T" ? scene_.kinetic_terms : scene_.potential_terms) += value;
    }


    void lower_point(const statement& s)
    {
        const name_ref& n = s.names[0];
        auto found = points_.find(n.name);
        if (found != points_.end())
            throw scene_error(n.where, "point `" + n.name + "` is already declared at line " +
                                           std::to_string(found->second.line));
        points_[n.name] = n.where;
        point_mass p;
        p.name = n.name;
        p.where = n.where;
        p.mass = lower(*s.value, expr_context{"a mass", false});
        p.position = lower_vector(*s.vector, expr_context{"a position"});
        if (s.vector->components.size() == 3)
            spatial_point_ = true;
        scene_.points.push_back(std::move(p));
    }

    void lower_gravity(const statement& s)
    {
        if (scene_.gravity)
            throw scene_error(s.where, "gravity is given twice");
        gravity_field g;
        g.strength = lower(*s.value, expr_context{"the strength of gravity", false, false, true, false});
        std::vector<GiNaC::ex> d = lower_vector(*s.vector, expr_context{"a direction", false, false, true, false});
        GiNaC::ex norm2 = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).expand();
        if (norm2.is_zero())
            throw scene_error(s.vector->where, "the direction of gravity is the zero vector");
        GiNaC::ex norm = GiNaC::sqrt(norm2);
        for (GiNaC::ex& component : d)
            component = (component / norm).normal();
        g.direction = d;
        scene_.gravity = g;
        if (s.vector->components.size() == 3)
            spatial_gravity_ = s.vector->where;
    }

    std::vector<GiNaC::ex> lower_endpoint(const endpoint& e)
    {
        if (e.position)
            return lower_vector(*e.position, expr_context{"a position"});
        for (const point_mass& p : scene_.points)
            if (p.name == e.point->name)
                return p.position;
        throw scene_error(e.point->where, "unknown point " + quote(e.point->name) + ": declare it with `point` first");
    }

    void lower_spring(const statement& s)
    {
        spring sp;
        sp.stiffness = lower(*s.value, expr_context{"a stiffness", false, false, true, false});
        sp.end_a = lower_endpoint(*s.end_a);
        sp.end_b = lower_endpoint(*s.end_b);
        sp.rest_length = s.rest ? lower(*s.rest, expr_context{"a rest length", false, false, true, false})
                                : GiNaC::ex(0);
        scene_.springs.push_back(std::move(sp));
    }

    // ---- forces beyond L: dissipation, dampers, forces, inputs (§5) -----------------------

    void declare_input(const name_ref& n)
    {
        declare_name(n, "input");
        input_signal u{n.name, GiNaC::realsymbol(n.name), n.where, source_.line(n.where.line)};
        names_[n.name] = {name_entry::kind::input, u.symbol, 0, n.where};
        scene_.inputs.push_back(u);
    }

    /// A Rayleigh function is a quadratic form in the velocities: every term of degree two.
    void lower_dissipation(const statement& s)
    {
        expr_context context{"a Rayleigh function"};
        context.velocities = true;
        GiNaC::ex f = lower(*s.value, context);
        GiNaC::symbol scale("scale");
        GiNaC::exmap scaled;
        GiNaC::lst velocities;
        for (const coordinate& c : coordinates_) {
            scaled[c.velocity] = scale * c.velocity;
            velocities.append(c.velocity);
        }
        GiNaC::ex expanded = f.subs(scaled).expand();
        if (!f.is_zero() && (!f.is_polynomial(velocities) || expanded.degree(scale) != 2 ||
                             expanded.ldegree(scale) != 2))
            throw scene_error(s.value->where, "a Rayleigh function is quadratic in the velocities (every term "
                                              "has two of them, as in `1/2*b*x'^2`); this one is not");
        if (!scene_.dissipation_line)
            scene_.dissipation_line = s.where;
        scene_.dissipation += f;
    }

    void lower_damper(const statement& s)
    {
        damper d;
        d.where = s.where;
        d.coefficient = lower(*s.value, expr_context{"a damping coefficient", false, false, true, false});
        d.end_a = lower_endpoint(*s.end_a);
        d.end_b = lower_endpoint(*s.end_b);
        GiNaC::ex length2 = 0;
        for (std::size_t k = 0; k < 3; ++k)
            length2 += GiNaC::pow(d.end_a[k] - d.end_b[k], 2);
        if (length2.expand().is_zero())
            throw scene_error(s.where, "the damper's two ends are the same point");
        scene_.dampers.push_back(std::move(d));
    }

    void lower_force(const statement& s)
    {
        expr_context context{"a force"};
        context.velocities = true;
        context.inputs = true;
        const name_ref& n = s.names[0];
        if (!s.on_point) {
            auto found = names_.find(n.name);
            if (found == names_.end() || found->second.name_kind != name_entry::kind::coordinate)
                throw scene_error(n.where, "a generalized force acts on a coordinate, and " + quote(n.name) +
                                               " is not one");
            scene_.forces.push_back({found->second.index, lower(*s.value, context), s.where});
            return;
        }
        for (const point_mass& p : scene_.points)
            if (p.name == n.name) {
                scene_.point_forces.push_back({p.name, p.position, lower_vector(*s.vector, context), s.where});
                return;
            }
        throw scene_error(n.where, "unknown point " + quote(n.name) + ": declare it with `point` first (a point "
                                   "that only carries a force has `mass 0`)");
    }

    void lower_constraint(const statement& s)
    {
        const name_ref& n = s.names[0];
        for (const constraint& c : scene_.constraints)
            if (c.name == n.name)
                throw scene_error(n.where, "constraint " + quote(n.name) + " is already declared at line " +
                                               std::to_string(c.where.line));
        if (names_.count("lambda_" + n.name))
            throw scene_error(n.where, "the multiplier of constraint " + quote(n.name) + " is `lambda_" + n.name +
                                           "`, which is already declared");
        expr_context context{"a constraint"};
        context.velocities = true;
        GiNaC::ex f = lower(*s.value, context) - lower(*s.right, context);
        scene_.constraints.push_back(classify_constraint(n, f, s.value->where, scene_));
    }

    const name_entry& coordinate_named(const name_ref& n)
    {
        auto found = names_.find(n.name);
        if (found == names_.end() || found->second.name_kind != name_entry::kind::coordinate)
            throw scene_error(n.where, quote(n.name) + " is not a coordinate");
        return found->second;
    }

    void lower_equilibrium(const statement& s)
    {
        if (scene_.equilibrium || scene_.steady)
            throw scene_error(s.where, "the equilibrium is given twice");
        std::vector<std::optional<GiNaC::ex>> values(coordinates_.size()), rates(coordinates_.size());
        bool steady = false;
        for (const assignment& a : s.assignments) {
            std::size_t i = coordinate_named(a.target).index;
            if (values[i] || rates[i])
                throw scene_error(a.target.where, quote(a.target.name) + " is given twice");
            const GiNaC::ex value = lower(*a.value, expr_context{a.velocity ? "a steady rate" : "an equilibrium value",
                                                                 false, false, true, false});
            (a.velocity ? rates[i] : values[i]) = value;
            steady = steady || a.velocity;
        }
        if (steady) {
            // A steady motion: coordinates without a value are cyclic (checked by the stage).
            scene_.steady = steady_motion_request{values, rates, s.where};
            return;
        }
        std::vector<GiNaC::ex> equilibrium;
        for (std::size_t i = 0; i < values.size(); ++i) {
            if (!values[i])
                throw scene_error(s.where, "the equilibrium does not give coordinate `" +
                                               coordinates_[i].name + "`");
            equilibrium.push_back(*values[i]);
        }
        scene_.equilibrium = equilibrium;
    }

    void lower_ratio(const statement& s)
    {
        if (scene_.ratio)
            throw scene_error(s.where, "a ratio is given twice");
        declare_name(s.names[0], "ratio");
        GiNaC::ex definition = lower(*s.value, expr_context{"a ratio", false, false, true, false});
        GiNaC::ex numerator = definition.numer(), denominator = definition.denom();
        if (!GiNaC::is_a<GiNaC::possymbol>(numerator) || !GiNaC::is_a<GiNaC::possymbol>(denominator))
            throw scene_error(s.value->where, "a ratio is one parameter over another, such as `m/M`");
        ratio_request r{s.names[0].name, GiNaC::possymbol(s.names[0].name), definition};
        names_[r.name] = {name_entry::kind::ratio, r.symbol, 0, s.names[0].where};
        scene_.ratio = r;
    }

    void lower_limit(const statement& s)
    {
        if (scene_.limit)
            throw scene_error(s.where, "a limit is given twice");
        const name_ref& n = s.names[0];
        auto found = names_.find(n.name);
        if (found != names_.end() && found->second.name_kind != name_entry::kind::ratio &&
            found->second.name_kind != name_entry::kind::parameter)
            throw scene_error(n.where, quote(n.name) + " is not a ratio");
        scene_.limit = limit_request{n.name, s.limit_target->name == "oo"};
        limit_name_ = n; // checked against the `ratio` line (before or after) in finish()
    }

    GiNaC::ex constant_value(const expr_node& node, const char* what)
    {
        GiNaC::ex value = lower(node, expr_context{what, false, false, false, false});
        GiNaC::ex number = value.evalf();
        if (!GiNaC::is_a<GiNaC::numeric>(number) || !GiNaC::ex_to<GiNaC::numeric>(number).is_real())
            throw scene_error(node.where, std::string(what) + " must be a real number");
        return value;
    }

    /// An input's value: a number or an expression in t and the parameters.
    GiNaC::ex input_value(const expr_node& node)
    {
        GiNaC::ex value = lower(node, expr_context{"an input's value", false, false, true, true});
        if (!value.info(GiNaC::info_flags::real) && GiNaC::is_a<GiNaC::numeric>(value.evalf()))
            throw scene_error(node.where, "an input's value must be real");
        return value;
    }

    void lower_critical(const statement& s)
    {
        if (scene_.critical)
            throw scene_error(s.where, "a critical range is given twice");
        const name_ref& n = s.names[0];
        auto found = names_.find(n.name);
        if (found == names_.end() || found->second.name_kind != name_entry::kind::parameter)
            throw scene_error(n.where, quote(n.name) + " is not a parameter: `critical` runs a parameter over a "
                                                       "range, as `critical v from 0 to 10`");
        critical_request request;
        for (std::size_t k = 0; k < scene_.parameters.size(); ++k)
            if (scene_.parameters[k].name == n.name)
                request.parameter = k;
        request.where = s.where;
        const auto bound = [&](const expr_node& e) {
            const GiNaC::ex value = constant_value(e, "a range's end").evalf();
            const double number = GiNaC::ex_to<GiNaC::numeric>(value).to_double();
            // 0 is the edge of a parameter's domain: the linearization is evaluated there as numbers
            if (!(number >= 0) || !std::isfinite(number))
                throw scene_error(e.where, "a range's end must be a finite number ≥ 0, as the parameter " +
                                               quote(n.name) + " is assumed positive");
            return number;
        };
        request.from = bound(*s.value);
        request.to = bound(*s.right);
        if (!(request.from < request.to))
            throw scene_error(s.right->where, "the range's end must be above its start");
        scene_.critical = request;
    }

    value_point lower_values(const statement& s)
    {
        value_point point;
        point.where = s.where;
        std::set<std::string> seen;
        for (const assignment& a : s.assignments) {
            auto found = names_.find(a.target.name);
            if (found != names_.end() && found->second.name_kind == name_entry::kind::input && !a.velocity) {
                if (!seen.insert(a.target.name).second)
                    throw scene_error(a.target.where, quote(a.target.name) + " is given twice");
                point.inputs.emplace_back(a.target.name, input_value(*a.value));
                continue;
            }
            if (found == names_.end() || found->second.name_kind != name_entry::kind::parameter || a.velocity)
                throw scene_error(a.target.where, quote(a.target.name + (a.velocity ? "'" : "")) +
                                                      " is not a parameter");
            if (!seen.insert(a.target.name).second)
                throw scene_error(a.target.where, quote(a.target.name) + " is given twice");
            point.values.emplace_back(a.target.name, constant_value(*a.value, "a parameter value"));
        }
        return point;
    }

    void lower_initial(const statement& s)
    {
        if (scene_.initial)
            throw scene_error(s.where, "the initial state is given twice");
        scene_.initial = initial_of(s);
    }

    initial_state initial_of(const statement& s)
    {
        initial_state state;
        for (const assignment& a : s.assignments) {
            auto angular = names_.find(a.target.name);
            if (angular != names_.end() && angular->second.name_kind == name_entry::kind::angular) {
                if (a.velocity)
                    throw scene_error(a.target.where, "an angular velocity has no `'`: write " +
                                                          quote(a.target.name + " = ..."));
                if (state.others.count(a.target.name))
                    throw scene_error(a.target.where, quote(a.target.name) + " is given twice");
                state.others[a.target.name] = constant_value(*a.value, "an initial value");
                continue;
            }
            std::size_t i = coordinate_named(a.target).index;
            auto& target = a.velocity ? state.velocities : state.positions;
            const std::string& name = coordinates_[i].name;
            if (target.count(name))
                throw scene_error(a.target.where, "`" + name + (a.velocity ? "'" : "") + "` is given twice");
            target[name] = constant_value(*a.value, "an initial value");
            (a.velocity ? state.velocity_written : state.position_written)[name] = {a.value->where, source_.line(a.value->where.line)};
        }
        state.statement = {s.where, source_.line(s.where.line)};
        return state;
    }

    GiNaC::ex positive_constant(const expr_node& node, const char* what)
    {
        GiNaC::ex value = constant_value(node, what);
        if (!GiNaC::ex_to<GiNaC::numeric>(value.evalf()).is_positive())
            throw scene_error(node.where, std::string(what) + " must be positive");
        return value;
    }

    void lower_simulate(const statement& s)
    {
        if (scene_.simulation)
            throw scene_error(s.where, "`simulate` is given twice");
        simulation_request r;
        r.statement = {s.where, source_.line(s.where.line)};
        r.until = positive_constant(*s.value, "the end time");
        if (s.step) {
            r.step = positive_constant(*s.step, "the step");
            const double outputs = GiNaC::ex_to<GiNaC::numeric>((r.until / *r.step).evalf()).to_double();
            if (!(outputs <= 1e7))
                throw scene_error(s.step->where, "the step gives more than 10^7 output times up to the end time");
        }
        if (s.tolerance)
            r.tolerance = positive_constant(*s.tolerance, "the tolerance");
        if (s.method) {
            static const std::set<std::string> methods = {
                "auto", "dopri5", "rkf78", "dop853", "bulirsch-stoer", "bdf", "implicit-midpoint", "dp5", "rk45",
                "dormand-prince", "fehlberg", "rk78", "bs", "bulirsch_stoer", "cvode", "stiff", "midpoint",
                "implicit_midpoint", "symplectic"};
            if (!methods.count(s.method->name))
                throw scene_error(s.method->where, "unknown method `" + s.method->name +
                                                       "` (auto, dopri5, rkf78, dop853, bulirsch-stoer, bdf, implicit-midpoint)");
            r.method = s.method->name;
        }
        scene_.simulation = r;
    }

    void lower_use(const statement& s)
    {
        std::string path = s.text;
        if (path.empty())
            throw scene_error(s.where, "`use` needs a file name");
        if (path[0] != '/') {
            std::string folder = source_.file();
            std::size_t slash = folder.rfind('/');
            folder = (folder == "-" || folder == "<stdin>" || slash == std::string::npos) ? "" : folder.substr(0, slash + 1);
            path = folder + path;
        }
        std::string text = read_file_ ? read_file_(path, s.where) : read_from_disk(path, s.where);
        source_text rules_source(path, text);
        std::vector<rewrite_rule> rules;
        try {
            rules = load_rules(rules_source, &scene_);
        } catch (const scene_error& error) {
            // A file not named as a rules file may be anything (`use "/etc/passwd"`): its
            // error is told at the `use`, quoting no line of it.
            const std::string suffix = ".rules";
            if (path.size() > suffix.size() && path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0)
                throw;
            throw scene_error(s.where, quote(path) + " is not a rules file: line " +
                                           std::to_string(error.where().line) + ", column " +
                                           std::to_string(error.where().column) + ": " + error.what());
        }
        scene_.rules.insert(scene_.rules.end(), rules.begin(), rules.end());
    }

    static std::string read_from_disk(const std::string& path, const source_location& where)
    {
        try {
            return read_bounded(path, max_rules_bytes, rules_wait_seconds);
        } catch (const file_error& error) {
            throw scene_error(where, std::string("cannot read the rules file: ") + error.what());
        }
    }

    void lower_want(const statement& s)
    {
        for (const name_ref& n : s.names) {
            std::optional<product> p = product_from_name(n.name);
            if (!p) {
                std::string items;
                for (const auto& [unused, name] : product_names())
                    items += (items.empty() ? "" : ", ") + name;
                throw scene_error(n.where, "unknown product " + quote(n.name) + "; the products are: " + items);
            }
            scene_.wanted.insert(*p);
        }
    }

    void finish()
    {
        if (scene_.coordinates.empty() && scene_.bodies.empty())
            throw scene_error({source_.file(), 1, 1}, "the scene declares no coordinates (`coordinates q1 q2 ...`)");
        if (limit_name_ && (!scene_.ratio || scene_.ratio->name != limit_name_->name))
            throw scene_error(limit_name_->where, quote(limit_name_->name) + " is not a declared ratio: a limit "
                                                  "is taken in the scene's `ratio`, as `ratio rho = m/M` then "
                                                  "`limit rho -> 0`");
        // Planar points move in the plane (x, y): a third component of gravity would act on nothing.
        if (spatial_gravity_ && !scene_.points.empty() && !spatial_point_ && scene_.bodies.empty())
            throw scene_error(*spatial_gravity_, "the points are planar (x, y), so gravity has two components "
                                                 "`(dx, dy)`; give the points three components to use a third");
        for (std::size_t k = 0; k < value_statements_.size(); ++k) {
            check_physical(scene_, scene_.values[k], *value_statements_[k]);
            check_assumptions(scene_.values[k], *value_statements_[k]);
        }
        resolve_body_attachments();
        check_constraints(scene_);
        if (kinetic_line_)
            if (std::optional<scene_warning> slip = kinetic_energy_slip(scene_, *kinetic_line_))
                scene_.warnings.push_back({slip->where, slip->message, source_.line(kinetic_line_->line)});
    }

public:
    /// Rejects a parameter value of a `values` statement that contradicts what the derivation
    /// assumes of parameters (core/assumptions.h), with the caret at the value. After
    /// check_physical, whose message names the quantity (a negative mass) where there is one.
    static void check_assumptions(const value_point& point, const statement& s)
    {
        for (const auto& [name, value] : point.values)
            if (std::optional<std::string> why = parameter_value_contradiction(name, value)) {
                for (const assignment& a : s.assignments)
                    if (a.target.name == name && !a.velocity)
                        throw scene_error(a.value->where, *why);
                throw scene_error(s.where, *why);
            }
    }

    /// Rejects a `values` point that makes a mass, a body's dimension or moment zero or
    /// negative, with the caret at the value of a parameter the quantity depends on.
    static void check_physical(const model& scene, const value_point& point, const statement& s)
    {
        const GiNaC::exmap at = value_map(scene, point);
        auto check = [&](const GiNaC::ex& quantity, const std::string& what) {
            if (GiNaC::is_a<GiNaC::numeric>(quantity))
                return; // a constant: the statement itself was checked
            GiNaC::ex number;
            try {
                number = quantity.subs(at).evalf();
            } catch (const std::exception&) {
                return; // not defined at these values: the computation says so
            }
            if (!GiNaC::is_a<GiNaC::numeric>(number) || !GiNaC::ex_to<GiNaC::numeric>(number).is_real() ||
                GiNaC::ex_to<GiNaC::numeric>(number).is_positive())
                return;
            auto culprit = [&]() -> source_location {
                for (const assignment& a : s.assignments)
                    for (const parameter& p : scene.parameters)
                        if (p.name == a.target.name && quantity.has(p.symbol))
                            return a.value->where;
                return s.where;
            };
            throw scene_error(culprit(), "these values make " + what + " " +
                                         (GiNaC::ex_to<GiNaC::numeric>(number).is_zero() ? "zero" : "negative") +
                                         "; it must be positive");
        };
        for (const point_mass& p : scene.points)
            check(p.mass, "the mass of point " + quote(p.name));
        for (const rigid_body& b : scene.bodies) {
            if (b.body_kind != rigid_body::kind::region)
                check(b.mass, "the mass of body " + quote(b.name));
            for (const GiNaC::ex& d : b.dimensions)
                check(d, "a dimension of body " + quote(b.name));
            if (std::optional<inertia_problem> problem = check_inertia(b, at)) {
                // The caret goes to a value the broken quantity depends on.
                const GiNaC::matrix given = given_tensor(b);
                GiNaC::lst inputs{given};
                if (problem->at == inertia_problem::place::entry)
                    inputs = GiNaC::lst{given(static_cast<unsigned>(problem->entry),
                                              static_cast<unsigned>(problem->entry))};
                if (problem->at == inertia_problem::place::about) {
                    inputs.append(b.mass);
                    inputs.append(GiNaC::lst(b.about->begin(), b.about->end()));
                }
                for (const assignment& a : s.assignments)
                    for (const parameter& p : scene.parameters)
                        if (p.name == a.target.name && inputs.has(p.symbol))
                            throw scene_error(a.value->where,
                                              "these values make " + inertia_message(*problem, b.name, true));
                throw scene_error(s.where, "these values make " + inertia_message(*problem, b.name, true));
            }
        }
    }

private:
    const source_text& source_;
    file_reader read_file_;
    std::optional<name_ref> limit_name_;
    std::optional<source_location> spatial_gravity_;
    bool spatial_point_ = false;
    std::vector<const statement*> value_statements_;
    std::map<std::string, source_location> points_;
    bool seen_title_ = false;
    std::optional<source_location> energy_line_;
    std::optional<source_location> kinetic_line_; ///< the first `T` line
    std::string energy_keyword_;
    std::optional<source_location> lagrangian_line_;
};

} // namespace

model load_model(const source_text& source, const file_reader& read_file)
{
    return with_source(source, [&] {
        std::vector<token> tokens = tokenize(source);
        scene_ast ast = parse_scene(tokens);
        return lowering(source, read_file).run(ast);
    });
}

namespace {

/// Parses `text`, given on the command line as option `option` (--values, --initial), as
/// the one statement `keyword text` of a scene, lowered with the names of `scene`, and
/// hands it to `use`. An error is located in the option's own text.
template <typename Use>
void lower_option(const model& scene, const std::string& option, const std::string& keyword, const std::string& text,
                  const char* usage, Use use)
{
    const std::string prefix = keyword + " ";
    source_text source(option, prefix + text);
    try {
        std::vector<token> tokens = tokenize(source);
        scene_ast ast = parse_scene(tokens);
        if (ast.statements.size() != 1 || ast.statements[0].keyword != keyword)
            throw scene_error({option, 1, static_cast<int>(prefix.size()) + 1}, usage);
        lowering lower(source, {});
        lower.adopt_names(scene);
        use(lower, ast.statements[0]);
    } catch (scene_error& error) {
        source_location at = error.where();
        at.column = std::max(1, at.column - static_cast<int>(prefix.size()));
        scene_error shifted(at, error.what());
        shifted.attach_line_text(text);
        throw shifted;
    }
}

} // namespace

void add_values(model& scene, const std::string& text, const std::string& origin)
{
    lower_option(scene, origin, "values", text, "give values as `a=1,b=2`",
                 [&](lowering& lower, const statement& s) {
                     value_point point = lower.values_line(s);
                     lowering::check_physical(scene, point, s);
                     lowering::check_assumptions(point, s);
                     scene.values.push_back(point);
                 });
}

void add_initial(model& scene, const std::string& text, const std::string& origin)
{
    const std::string keyword = "initial"; // lower_option reads `initial TEXT`
    lower_option(scene, origin, keyword, text, "give initial values as `theta=0.1, phi'=0`",
                 [&](lowering& lower, const statement& s) {
                     initial_state given = lower.initial_line(s);
                     // Where the values were written, in the option's own text (without the keyword).
                     for (auto* written : {&given.position_written, &given.velocity_written})
                         for (auto& [name, at] : *written)
                             at = {{origin, at.where.line, at.where.column - static_cast<int>(keyword.size() + 1)}, text};
                     given.statement = {{origin, 1, 1}, text};
                     scene.initial = scene.initial.value_or(initial_state{});
                     scene.initial->merge(given);
                 });
}

} // namespace lagrange
