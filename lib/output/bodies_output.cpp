// SPDX-License-Identifier: GPL-2.0-or-later
/** @file bodies_output.cpp
 *  Printers of inertia tensors (with the integrals they come from), Euler's equations,
 *  their torque-free solutions, Poinsot's construction and the stability of rotations. */
#include "output/bodies_output.h"

#include "output/latex_blocks.h"
#include "output/print.h"

#include <nlohmann/json.hpp>

#include <cctype>
#include <charconv>
#include <cmath>

namespace lagrange {

namespace {

/// A number in LaTeX math: the shortest round trip, its exponent as \times10^{k}.
std::string latex_round_trip(double x) { return latex_exponent(round_trip(x)); }

const char* const axis_names[] = {"x", "y", "z"};


std::string join(const std::vector<std::string>& parts, const std::string& separator)
{
    std::string out;
    for (std::size_t i = 0; i < parts.size(); ++i)
        out += (i ? separator : "") + parts[i];
    return out;
}

std::vector<std::string> printed(const std::vector<GiNaC::ex>& v, syntax s, const term_order& order = {})
{
    std::vector<std::string> out;
    for (const GiNaC::ex& e : v)
        out.push_back(print(e, s, order));
    return out;
}

/// The body an inertia result is of (every result names a body of its scene).
const rigid_body& body_of(const model& scene, const std::string& name)
{
    if (const rigid_body* b = body_named(scene, name))
        return *b;
    throw std::invalid_argument("unknown body `" + name + "`");
}

/// How the body was given, as the scene wrote it: `disk(R)`, `region ball(R)`, `inertia (…)`.
std::string description(const rigid_body& b, syntax s)
{
    const std::string attached =
        b.attached_to.empty() ? ""
        : s == syntax::latex  ? ", attached to $" + print_name(b.attached_to, s) + "$"
                              : ", attached to " + print_name(b.attached_to, s);
    if (b.body_kind == rigid_body::kind::inertia && b.tensor.empty() && !b.about)
        return "given by its principal moments" + attached;
    if (b.body_kind == rigid_body::kind::inertia) {
        const std::string about = b.about ? join(printed(*b.about, s), ", ") : "";
        return std::string(b.tensor.empty() ? "given by its principal moments" : "given by its inertia tensor") +
               (b.about ? (s == syntax::latex ? " about $(" + about + ")$" : " about (" + about + ")") : "") + attached;
    }
    const std::string dimensions = join(printed(b.dimensions, s), ", ");
    std::string text = (b.body_kind == rigid_body::kind::region ? "region " : "") + b.shape +
                       (s == syntax::latex ? "$(" + dimensions + ")$" : "(" + dimensions + ")");
    if (b.axis != 'z')
        text += ", axis " + std::string(1, b.axis);
    return text + attached;
}

term_order euler_order(const euler_result& e)
{
    return {{e.rates, e.omega}};
}

std::string quantity_name(const std::string& quantity, syntax s)
{
    if (quantity == "measure" || quantity == "mass")
        return quantity == "mass" ? "M" : (s == syntax::latex ? "\\mathrm{measure}" : "measure");
    if (quantity.size() == 1)
        return s == syntax::latex ? "M " + quantity + "_{\\mathrm{cm}}" : "M·" + quantity + "_cm";
    return s == syntax::latex ? "I_{" + quantity + "}" : "I_" + quantity;
}

/// ρ with its deltas: `M/(π·R²)·δ(z)`.
std::string density_text(const body_integral& i, syntax s)
{
    std::string text = print(i.density, s);
    for (const GiNaC::ex& d : i.deltas)
        text += (s == syntax::latex ? "\\,\\delta(" : "·δ(") + print(d, s) + ")";
    return text;
}

/// ∫ from lower to upper … d(variable), outermost first.
std::string integral_text(const body_integral& i, syntax s)
{
    std::string text;
    for (auto l = i.limits.rbegin(); l != i.limits.rend(); ++l) {
        if (s == syntax::latex)
            text += "\\int_{" + print(l->lower, s) + "}^{" + print(l->upper, s) + "}";
        else
            text += "∫[" + print(l->variable, s) + " = " + print(l->lower, s) + " … " + print(l->upper, s) + "] ";
    }
    if (s == syntax::latex) {
        text += "\\left(" + print(i.integrand, s) + "\\right)";
        for (const integration_limit& l : i.limits)
            text += "\\,d" + print(l.variable, s);
    } else {
        text += "(" + print(i.integrand, s) + ")";
    }
    return text;
}

std::string omega_name(const GiNaC::ex& w, syntax s) { return print(w, s); }

/// A rough width of LaTeX math in characters (as document.cpp measures it): a command
/// counts as one, braces and sub/superscript marks as none.
std::size_t latex_width(const std::string& latex)
{
    std::size_t width = 0;
    for (std::size_t i = 0; i < latex.size(); ++i) {
        const char c = latex[i];
        if (c == '\\') {
            std::size_t j = i + 1;
            while (j < latex.size() && std::isalpha(static_cast<unsigned char>(latex[j])))
                ++j;
            ++width;
            i = j > i + 1 ? j - 1 : j;
        } else if (c != '{' && c != '}' && c != '^' && c != '_' && c != ' ' && c != '&') {
            ++width;
        }
    }
    return width;
}

/// A displayed line of math; one wider than the page is scaled down to the page width.
std::string latex_line(const std::string& math)
{
    constexpr std::size_t line_width = 75;
    if (latex_width(math) <= line_width)
        return "\\[" + math + "\\]\n";
    return "\\[\\resizebox{\\linewidth}{!}{$\\displaystyle " + math + "$}\\]\n";
}

} // namespace

namespace {
void write_tops_text(std::ostream& out, const analysis& result);
} // namespace

void write_bodies_text(std::ostream& out, const analysis& result)
{
    write_tops_text(out, result);
    const model& scene = *result.scene;
    if (result.inertia) {
        out << "\nInertia (about the centre of mass, body axes)\n";
        for (const inertia_result& in : *result.inertia) {
            const rigid_body& b = body_of(scene, in.body);
            out << "  body " << in.body << ": " << description(b, syntax::text) << "\n";
            out << "    mass M = " << print(in.mass, syntax::text) << '\n';
            if (!in.integrals.empty()) {
                out << "    ρ = " << density_text(in.integrals.back(), syntax::text) << "  (" << in.coordinates
                    << " coordinates)\n";
                bool shifted = false;
                for (const GiNaC::ex& c : in.centre_of_mass)
                    shifted = shifted || !c.is_zero();
                if (shifted)
                    out << "    centre of mass (from the region's centre): (" +
                               join(printed(in.centre_of_mass, syntax::text), ", ") + ")\n";
                for (const body_integral& i : in.integrals)
                    if (i.quantity.size() != 1 || shifted)
                        out << "    " << quantity_name(i.quantity, syntax::text) << " = " << integral_text(i, syntax::text)
                            << " = " << print(i.value, syntax::text) << '\n';
            }
            out << "    I =\n";
            for (unsigned r = 0; r < 3; ++r) {
                std::vector<std::string> row;
                for (unsigned c = 0; c < 3; ++c)
                    row.push_back(print(in.tensor(r, c), syntax::text));
                out << "      [" << join(row, ", ") << "]\n";
            }
            if (!in.principal.empty())
                out << "    principal moments: " << join(printed(in.principal, syntax::text), ", ")
                    << (in.diagonal ? "  (the body axes are principal axes)" : "") << '\n';
            if (!in.diagonal && in.principal_axes)
                for (unsigned k = 0; k < 3; ++k)
                    out << "      axis of " << print(in.principal[k], syntax::text) << ": ("
                        << print((*in.principal_axes)(0, k), syntax::text) << ", "
                        << print((*in.principal_axes)(1, k), syntax::text) << ", "
                        << print((*in.principal_axes)(2, k), syntax::text) << ")\n";
            if (in.about_origin) {
                std::vector<std::string> rows;
                for (unsigned r = 0; r < 3; ++r) {
                    std::vector<std::string> row;
                    for (unsigned c = 0; c < 3; ++c)
                        row.push_back(print((*in.about_origin)(r, c), syntax::text));
                    rows.push_back("[" + join(row, ", ") + "]");
                }
                out << "    about the origin (parallel axes): " << join(rows, ", ") << '\n';
            }
            term_order order{{in.omega}};
            for (unsigned k = 0; k < 3; ++k)
                out << "    L_" << axis_names[k] << " = " << print(in.angular_momentum[k], syntax::text, order) << '\n';
            out << "    T = " << print(in.kinetic_energy, syntax::text, order) << '\n';
        }
    }
    if (result.euler) {
        out << "\nEuler's equations\n";
        for (const euler_result& e : *result.euler) {
            const term_order order = euler_order(e);
            out << "  body " << e.body << (e.principal_equations.empty() ? "" : " (general form, body axes)") << ":\n";
            for (const GiNaC::ex& eq : e.equations)
                out << "    " << print(eq, syntax::text, order) << " = 0\n";
            if (!e.principal_equations.empty()) {
                out << "  in principal axes (moments " << join(printed(e.moments, syntax::text), ", ") << "):\n";
                for (const GiNaC::ex& eq : e.principal_equations)
                    out << "    " << print(eq, syntax::text, order) << " = 0\n";
            }
            if (e.torque_free && !e.moments.empty()) {
                out << "    conserved: T = " << print(e.kinetic_energy, syntax::text, order)
                    << ",  |L|² = " << print(e.angular_momentum_squared, syntax::text, order) << '\n';
            }
            if (e.symmetric) {
                const auto& s = *e.symmetric;
                out << "  symmetric body (axis " << s.axis + 1 << "): Ω = " << print(s.precession, syntax::text) << '\n';
                for (unsigned k = 0; k < 3; ++k)
                    out << "    " << omega_name(e.omega[k], syntax::text) << "(t) = " << print(s.omega[k], syntax::text)
                        << '\n';
            }
            if (e.elliptic) {
                const auto& s = *e.elliptic;
                const char* functions[] = {"cn", "sn", "dn"};
                out << "  Jacobi elliptic solution, modulus k = " << round_trip(s.modulus) << ", period "
                    << round_trip(s.period) << ":\n";
                for (unsigned k = 0; k < 3; ++k) {
                    unsigned role = 0;
                    while (s.roles[role] != k)
                        ++role;
                    out << "    " << omega_name(e.omega[k], syntax::text) << "(t) = " << round_trip(s.amplitudes[role]) << "·"
                        << functions[role] << "(" << round_trip(s.rate) << "·t " << (s.phase < 0 ? "- " : "+ ")
                        << round_trip(std::abs(s.phase)) << ", k)\n";
                }
                out << "    T = " << round_trip(s.energy) << ", |L|² = " << round_trip(s.momentum_squared) << '\n';
            }
            if (e.poinsot) {
                const auto& p = *e.poinsot;
                out << "  Poinsot: inertia ellipsoid ωᵀIω = 2T with semi-axes " << round_trip(p.ellipsoid_axes[0]) << ", "
                    << round_trip(p.ellipsoid_axes[1]) << ", " << round_trip(p.ellipsoid_axes[2])
                    << "; invariable plane at distance 2T/|L| = " << round_trip(p.plane_distance) << "; polhode: "
                    << p.polhode.size() << " points (JSON)\n";
            }
            if (!e.stability.empty()) {
                out << "  rotation about axis 1, 2, 3: " << join(e.stability, ", ") << '\n';
            }
        }
    }
}

namespace {

void write_tops_text(std::ostream& out, const analysis& result)
{
    if (!result.tops)
        return;
    for (const top_result& top : *result.tops) {
        const term_order order{{{top.spin}}};
        out << "\nTop " << top.body << " (Routh, p_φ = p_ψ = I3·" << print(top.spin, syntax::text) << ")\n";
        out << "  I1 about the pivot = " << print(top.pivot_moment, syntax::text)
            << ", I3 = " << print(top.spin_moment, syntax::text) << '\n';
        out << "  V_eff = " << print(top.effective_potential, syntax::text, order) << '\n';
        out << "  V_eff ≈ const + (" << print(top.curvature, syntax::text, order) << ")·"
            << print(top.nutation, syntax::text) << "²\n";
        out << "  the sleeping top is stable when " << print(top.condition, syntax::text, order) << " > 0\n";
        if (!top.precession_quadratic.empty()) {
            const term_order by_rate{{{top.precession}, {top.spin}}};
            const GiNaC::ex& w = top.precession;
            const std::vector<GiNaC::ex>& a = top.precession_quadratic;
            out << "  steady precession at " << print(top.nutation, syntax::text) << ": "
                << print(a[2] * w * w + a[1] * w + a[0], syntax::text, by_rate) << " = 0\n"
                << "    slow Ω = " << print(top.slow_precession, syntax::text, order) << '\n'
                << "    fast Ω = " << print(top.fast_precession, syntax::text, order) << '\n';
            if (!top.nutation_frequency_squared.is_zero())
                out << "  nutation about it: ω² = " << print(top.nutation_frequency_squared, syntax::text, by_rate)
                    << '\n';
        }
    }
}

void write_tops_latex(std::ostream& out, const analysis& result)
{
    if (!result.tops)
        return;
    for (const top_result& top : *result.tops) {
        const term_order order{{{top.spin}}};
        out << "\\subsection*{Top $" << print_name(top.body, syntax::latex) << "$}\n"
            << "With the cyclic momenta at their sleeping values $p_\\phi = p_\\psi = I_3 "
            << print(top.spin, syntax::latex) << "$, $I_1 = " << print(top.pivot_moment, syntax::latex)
            << "$ about the pivot and $I_3 = " << print(top.spin_moment, syntax::latex) << "$:\n"
            << latex_equation("V_{\\mathrm{eff}}", print_terms(top.effective_potential, syntax::latex, order), "")
            << "about $" << print(top.nutation, syntax::latex) << " = 0$ its curvature gives the sleeping-top condition\n"
            << latex_equation("", print_terms(top.condition, syntax::latex, order), " > 0.");
        if (!top.precession_quadratic.empty()) {
            const term_order by_rate{{{top.precession}, {top.spin}}};
            const GiNaC::ex& w = top.precession;
            const std::vector<GiNaC::ex>& a = top.precession_quadratic;
            out << "Steady precession at $" << print(top.nutation, syntax::latex) << "$:\n"
                << latex_equation("", print_terms(a[2] * w * w + a[1] * w + a[0], syntax::latex, by_rate), " = 0,")
                << latex_equations({{"\\Omega_{\\mathrm{slow}}", print_terms(top.slow_precession, syntax::latex, order), ","},
                                    {"\\Omega_{\\mathrm{fast}}", print_terms(top.fast_precession, syntax::latex, order)}});
            if (!top.nutation_frequency_squared.is_zero())
                out << "Nutation about it:\n"
                    << latex_equation("\\omega^2", print_terms(top.nutation_frequency_squared, syntax::latex, by_rate), "");
        }
    }
}

} // namespace

void write_bodies_latex(std::ostream& out, const analysis& result)
{
    write_tops_latex(out, result);
    const model& scene = *result.scene;
    auto matrix = [](const GiNaC::matrix& m) {
        std::string text = "\\begin{pmatrix}";
        for (unsigned r = 0; r < 3; ++r)
            for (unsigned c = 0; c < 3; ++c)
                text += print(m(r, c), syntax::latex) + (c < 2 ? " & " : r < 2 ? " \\\\ " : "");
        return text + "\\end{pmatrix}";
    };
    auto display = [&](const std::string& math) {
        out << latex_line(math);
    };
    if (result.inertia) {
        out << "\\subsection*{Inertia}\n";
        for (const inertia_result& in : *result.inertia) {
            const rigid_body& b = body_of(scene, in.body);
            out << "Body $" << print_name(in.body, syntax::latex) << "$: " << description(b, syntax::latex)
                << ", mass $M = " << print(in.mass, syntax::latex) << "$.\n";
            if (!in.integrals.empty()) {
                out << "Density $\\rho = " << density_text(in.integrals.back(), syntax::latex) << "$ (" << in.coordinates
                    << " coordinates).\n";
                bool shifted = false;
                for (const GiNaC::ex& c : in.centre_of_mass)
                    shifted = shifted || !c.is_zero();
                for (const body_integral& i : in.integrals)
                    if (i.quantity.size() != 1 || shifted)
                        out << latex_line(quantity_name(i.quantity, syntax::latex) + " = " + integral_text(i, syntax::latex) +
                                          " = " + print(i.value, syntax::latex));
            }
            display("I = " + matrix(in.tensor));
            if (in.about_origin)
                display("I_{O} = " + matrix(*in.about_origin));
            term_order order{{in.omega}};
            display("L = I\\omega = \\begin{pmatrix}" + join(printed(in.angular_momentum, syntax::latex, order), " \\\\ ") +
                    "\\end{pmatrix},\\quad T = \\tfrac12\\omega^{T} I \\omega = " +
                    print(in.kinetic_energy, syntax::latex, order));
        }
    }
    if (result.euler) {
        out << "\\subsection*{Euler's equations}\n";
        for (const euler_result& e : *result.euler) {
            const term_order order = euler_order(e);
            out << "Body $" << print_name(e.body, syntax::latex) << "$:\n";
            auto rows = [&](const std::vector<GiNaC::ex>& equations) {
                std::vector<latex_row> r;
                for (const GiNaC::ex& equation : equations)
                    r.push_back({"", print_terms(equation, syntax::latex, order), " = 0"});
                return latex_equations(r);
            };
            out << rows(e.equations);
            if (!e.principal_equations.empty())
                out << "In principal axes:\n" << rows(e.principal_equations);
            if (e.torque_free && !e.moments.empty())
                display("T = " + print(e.kinetic_energy, syntax::latex, order) +
                        ",\\quad |L|^{2} = " + print(e.angular_momentum_squared, syntax::latex, order));
            if (e.symmetric) {
                const auto& s = *e.symmetric;
                std::vector<std::string> rows;
                for (unsigned k = 0; k < 3; ++k)
                    rows.push_back(print(e.omega[k], syntax::latex) + "(t) &= " + print(s.omega[k], syntax::latex));
                out << "Symmetric body, $\\Omega = " << print(s.precession, syntax::latex) << "$:\n\\begin{align*}\n"
                    << join(rows, " \\\\\n") << "\n\\end{align*}\n";
            }
            if (e.elliptic) {
                const auto& s = *e.elliptic;
                const char* functions[] = {"cn", "sn", "dn"};
                std::vector<std::string> rows;
                for (unsigned k = 0; k < 3; ++k) {
                    unsigned role = 0;
                    while (s.roles[role] != k)
                        ++role;
                    rows.push_back(print(e.omega[k], syntax::latex) + "(t) &= " + latex_round_trip(s.amplitudes[role]) +
                                   "\\,\\mathrm{" + functions[role] + "}(" + latex_round_trip(s.rate) + "\\,t " +
                                   (s.phase < 0 ? "- " : "+ ") + latex_round_trip(std::abs(s.phase)) + ", k)");
                }
                out << "Jacobi elliptic solution, $k = " << latex_round_trip(s.modulus) << "$, period $" << latex_round_trip(s.period)
                    << "$:\n\\begin{align*}\n" << join(rows, " \\\\\n") << "\n\\end{align*}\n";
            }
            if (e.poinsot)
                out << "Poinsot: the ellipsoid $\\omega^{T} I \\omega = 2T$ has the semi-axes\n\\[" << latex_round_trip(e.poinsot->ellipsoid_axes[0])
                    << ",\\quad " << latex_round_trip(e.poinsot->ellipsoid_axes[1]) << ",\\quad "
                    << latex_round_trip(e.poinsot->ellipsoid_axes[2]) << "\\]\nand the invariable plane is at the distance\n\\[2T/|L| = "
                    << latex_round_trip(e.poinsot->plane_distance) << "\\]\nfrom the centre.\n\n";
            if (!e.stability.empty())
                out << "Rotation about axes 1, 2, 3: " << join(e.stability, ", ") << ".\n\n";
        }
    }
}

void write_bodies_json(nlohmann::ordered_json& doc, const analysis& result)
{
    auto strings = [](const std::vector<GiNaC::ex>& v, const term_order& order = {}) {
        nlohmann::ordered_json list = nlohmann::ordered_json::array();
        for (const GiNaC::ex& e : v)
            list.push_back(print(e, syntax::plain, order));
        return list;
    };
    auto matrix = [](const GiNaC::matrix& m) {
        nlohmann::ordered_json rows = nlohmann::ordered_json::array();
        for (unsigned r = 0; r < 3; ++r) {
            nlohmann::ordered_json row = nlohmann::ordered_json::array();
            for (unsigned c = 0; c < 3; ++c)
                row.push_back(print(m(r, c), syntax::plain));
            rows.push_back(row);
        }
        return rows;
    };
    if (result.inertia) {
        nlohmann::ordered_json all = nlohmann::ordered_json::object();
        for (const inertia_result& in : *result.inertia) {
            nlohmann::ordered_json body;
            body["tensor"] = matrix(in.tensor);
            body["principal"] = strings(in.principal);
            if (in.principal_axes) {
                nlohmann::ordered_json axes = nlohmann::ordered_json::array();
                for (unsigned k = 0; k < 3; ++k)
                    axes.push_back({print((*in.principal_axes)(0, k), syntax::plain),
                                    print((*in.principal_axes)(1, k), syntax::plain),
                                    print((*in.principal_axes)(2, k), syntax::plain)});
                body["principal_axes"] = axes;
            }
            body["mass"] = print(in.mass, syntax::plain);
            body["coordinates"] = in.coordinates;
            if (!in.integrals.empty()) {
                body["density"] = print(in.density, syntax::plain);
                body["centre_of_mass"] = strings(in.centre_of_mass);
                nlohmann::ordered_json integrals = nlohmann::ordered_json::array();
                for (const body_integral& i : in.integrals) {
                    nlohmann::ordered_json limits = nlohmann::ordered_json::array();
                    for (const integration_limit& l : i.limits)
                        limits.push_back({{"variable", print(l.variable, syntax::plain)},
                                          {"lower", print(l.lower, syntax::plain)},
                                          {"upper", print(l.upper, syntax::plain)}});
                    integrals.push_back({{"quantity", i.quantity},
                                         {"density", print(i.density, syntax::plain)},
                                         {"deltas", strings(i.deltas)},
                                         {"weight", print(i.weight, syntax::plain)},
                                         {"integrand", print(i.integrand, syntax::plain)},
                                         {"limits", limits},
                                         {"value", print(i.value, syntax::plain)}});
                }
                body["integrals"] = integrals;
            }
            if (in.about_origin)
                body["about_origin"] = matrix(*in.about_origin);
            term_order order{{in.omega}};
            body["angular_momentum"] = strings(in.angular_momentum, order);
            body["kinetic_energy"] = print(in.kinetic_energy, syntax::plain, order);
            all[in.body] = body;
        }
        doc["inertia"] = all;
    }
    if (result.tops && !result.tops->empty()) {
        nlohmann::ordered_json all = nlohmann::ordered_json::object();
        for (const top_result& top : *result.tops) {
            const term_order order{{{top.spin}}};
            all[top.body] = {{"pivot_moment", print(top.pivot_moment, syntax::plain)},
                             {"spin_moment", print(top.spin_moment, syntax::plain)},
                             {"effective_potential", print(top.effective_potential, syntax::plain, order)},
                             {"curvature", print(top.curvature, syntax::plain, order)},
                             {"sleeping_condition", print(top.condition, syntax::plain, order) + " > 0"}};
            if (!top.precession_quadratic.empty()) {
                const term_order by_rate{{{top.precession}, {top.spin}}};
                const GiNaC::ex& w = top.precession;
                const std::vector<GiNaC::ex>& a = top.precession_quadratic;
                all[top.body]["precession_condition"] =
                    print(a[2] * w * w + a[1] * w + a[0], syntax::plain, by_rate) + " = 0";
                all[top.body]["slow_precession"] = print(top.slow_precession, syntax::plain, order);
                all[top.body]["fast_precession"] = print(top.fast_precession, syntax::plain, order);
                if (!top.nutation_frequency_squared.is_zero())
                    all[top.body]["nutation_frequency_squared"] =
                        print(top.nutation_frequency_squared, syntax::plain, by_rate);
            }
        }
        doc["top"] = all;
    }
    if (result.euler) {
        nlohmann::ordered_json all = nlohmann::ordered_json::object();
        for (const euler_result& e : *result.euler) {
            const term_order order = euler_order(e);
            nlohmann::ordered_json body;
            body["equations"] = strings(e.equations, order);
            if (!e.principal_equations.empty())
                body["principal_equations"] = strings(e.principal_equations, order);
            if (e.torque_free && !e.moments.empty())
                body["conserved"] = {{"kinetic_energy", print(e.kinetic_energy, syntax::plain, order)},
                                     {"angular_momentum_squared", print(e.angular_momentum_squared, syntax::plain, order)}};
            if (e.symmetric) {
                const auto& s = *e.symmetric;
                body["solution"] = {{"kind", "symmetric"},
                                    {"axis", s.axis + 1},
                                    {"precession", print(s.precession, syntax::plain)},
                                    {"omega", strings(s.omega)}};
            } else if (e.elliptic) {
                const auto& s = *e.elliptic;
                const char* functions[] = {"cn", "sn", "dn"};
                nlohmann::ordered_json omega = nlohmann::ordered_json::array();
                for (unsigned k = 0; k < 3; ++k) {
                    unsigned role = 0;
                    while (s.roles[role] != k)
                        ++role;
                    omega.push_back(round_trip(s.amplitudes[role]) + "*" + functions[role] + "(" + round_trip(s.rate) +
                                    "*t" + (s.phase < 0 ? "-" : "+") + round_trip(std::abs(s.phase)) + ", k)");
                }
                body["solution"] = {{"kind", "elliptic"},     {"omega", omega},
                                    {"modulus", s.modulus},   {"rate", s.rate},
                                    {"phase", s.phase},       {"period", s.period},
                                    {"energy", s.energy},     {"angular_momentum_squared", s.momentum_squared}};
            }
            if (e.poinsot) {
                nlohmann::ordered_json polhode = nlohmann::ordered_json::array();
                for (const auto& p : e.poinsot->polhode)
                    polhode.push_back({p[0], p[1], p[2]});
                body["poinsot"] = {{"ellipsoid_axes", e.poinsot->ellipsoid_axes},
                                   {"plane_distance", e.poinsot->plane_distance},
                                   {"polhode", polhode}};
            }
            if (!e.stability.empty())
                body["stability"] = e.stability;
            all[e.body] = body;
        }
        doc["euler"] = all;
    }
}

} // namespace lagrange
