// SPDX-License-Identifier: GPL-2.0-or-later
/** @file inertia.cpp
 *  The `inertia` family: each body's tensor with the integrals it comes from (the density with
 *  its deltas, the integral in body coordinates and in the coordinates the engine integrated
 *  in, its value), the principal axes, L = Iω and T = ½ωᵀIω, in text, LaTeX, JSON and the
 *  report (the homework's eqs. 16–35). */
#include "output/body_family.h"

#include "core/number_text.h"
#include "output/latex_blocks.h"
#include "output/print.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace lagrange {

namespace {

const char* const axis_names[] = {"x", "y", "z"};

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

/// How the body was given, as the report's prose says it.
std::string description_prose(const rigid_body& b)
{
    const std::string attached =
        b.attached_to.empty() ? "" : ", attached to $" + report_writer::name(b.attached_to) + "$";
    if (b.body_kind == rigid_body::kind::inertia) {
        std::string about;
        if (b.about)
            for (std::size_t i = 0; i < 3; ++i)
                about += (i ? ", " : "") + report_writer::math((*b.about)[i]);
        return std::string(b.tensor.empty() ? "given by its principal moments" : "given by its inertia tensor") +
               (b.about ? " about the body point $(" + about + ")$" : "") + attached;
    }
    std::string dimensions;
    for (std::size_t i = 0; i < b.dimensions.size(); ++i)
        dimensions += (i ? ", " : "") + report_writer::math(b.dimensions[i]);
    std::string text = (b.body_kind == rigid_body::kind::region ? "the region " : "a uniform ") +
                       latex_text(b.shape) + "$(" + dimensions + ")$";
    if (b.axis != 'z')
        text += std::string(" with its symmetry axis along body $") + b.axis + "$";
    return text + attached;
}

/// The density ϱ with its deltas, `\frac{M}{\pi R^2}\,\delta(z)`. (ϱ, because ρ
/// is the radius of the cylindrical coordinates.) The hollow sphere's
/// δ(√(x²+y²+z²) − R) is written δ(r − R).
std::string density_latex(const GiNaC::ex& density, const std::vector<GiNaC::ex>& deltas, const rigid_body& b)
{
    std::string text = density.is_equal(1) && !deltas.empty() ? "" : report_writer::math(density);
    const GiNaC::ex radius = GiNaC::sqrt(b.x * b.x + b.y * b.y + b.z * b.z);
    for (const GiNaC::ex& d : deltas)
        text += (text.empty() ? "" : "\\,") + std::string("\\delta(") + report_writer::math(d.subs(radius == b.r)) + ")";
    return text;
}

/// ∫_lower^upper … outermost first, and the differentials innermost first.
std::string integral_signs(const body_integral& i)
{
    std::string text;
    for (auto l = i.limits.rbegin(); l != i.limits.rend(); ++l)
        text += "\\int_{" + report_writer::math(l->lower) + "}^{" + report_writer::math(l->upper) + "}";
    return text;
}

std::string differentials(const body_integral& i)
{
    std::string text;
    for (const integration_limit& l : i.limits)
        text += "\\,d" + report_writer::math(l.variable);
    return text;
}

/// One display row `lhs = ∫_V ϱ (weight) dV = ∫∫∫ (integrand) dq… = value`, broken
/// across lines where it is long; a constant density stands in front of the
/// integral, as the homework writes it.
report_writer::row integral_row(const std::string& lhs, const body_integral& i, const rigid_body& b)
{
    std::vector<std::string> terms;
    std::string weight = i.weight.is_equal(1) ? "" : "\\left(" + report_writer::math(i.weight) + "\\right)";
    std::string density = density_latex(i.density, i.deltas, b);
    if (density == "1")
        density.clear();
    terms.push_back("\\int_{V} " + density + (density.empty() || weight.empty() ? "" : "\\,") + weight + "\\,dV");
    const bool constant = !i.density.has(b.x) && !i.density.has(b.y) && !i.density.has(b.z) && !i.density.has(b.r) &&
                          !i.density.is_zero() && !i.density.is_equal(1);
    GiNaC::ex inner = i.integrand;
    std::string factor;
    if (constant) {
        GiNaC::ex divided = (i.integrand / i.density).expand();
        if ((divided * i.density - i.integrand).expand().is_zero()) {
            inner = divided;
            factor = report_writer::math(i.density) + " ";
        }
    }
    std::vector<std::string> integrand = print_terms(inner, syntax::latex);
    const std::string open = "= " + factor + integral_signs(i);
    if (integrand.size() == 1) {
        terms.push_back(open + "\\left(" + integrand[0] + "\\right)" + differentials(i));
    } else {
        integrand.front() = open + "\\Big(" + integrand.front();
        integrand.back() += "\\Big)" + differentials(i);
        terms.insert(terms.end(), integrand.begin(), integrand.end());
    }
    terms.push_back("= " + report_writer::math(i.value));
    return {lhs, terms};
}

const body_integral* integral_of(const inertia_result& in, const std::string& quantity)
{
    for (const body_integral& i : in.integrals)
        if (i.quantity == quantity)
            return &i;
    return nullptr;
}

std::string omega_row(const std::vector<GiNaC::ex>& omega)
{
    std::string text = "(";
    for (std::size_t k = 0; k < omega.size(); ++k)
        text += (k ? ", " : "") + report_writer::math(omega[k]);
    return text + ")^{T}";
}

void write_body_inertia(report_writer& w, const inertia_result& in, const rigid_body& b)
{
    w.latex("\\subsection{Body " + body_title(in.body) + "}\n");
    w.text("The body ").latex(body_title(in.body)).text(" is ").latex(description_prose(b)).text(", of mass ")
        .latex("$" + report_writer::math(in.mass) + "$");
    if (in.integrals.empty()) {
        w.text(". Its inertia tensor about the centre of mass is given in the scene, in principal axes.\n");
    } else {
        w.text(". The engine integrates in " + in.coordinates + " coordinates ")
            .latex(in.integrals.front().limits.empty() ? "" : "(");
        for (std::size_t k = 0; k < in.integrals.front().limits.size(); ++k)
            w.latex((k ? ", " : "") + std::string("$") + report_writer::math(in.integrals.front().limits[k].variable) + "$");
        w.latex(in.integrals.front().limits.empty() ? "" : ")");
        w.text(", with the Jacobian of the coordinates in the integrand");
        if (!in.integrals.front().deltas.empty())
            w.text(" and the deltas of the thin body carried out");
        w.text(".\n\n");
        if (const body_integral* measure = integral_of(in, "measure")) {
            w.text("The body is uniform. Its measure (length, area or volume) is");
            w.display_rows({integral_row("|V|", *measure, b)});
            w.text("so its density is");
            w.display_terms("\\varrho(\\mathbf{r})", {density_latex(in.density, measure->deltas, b)});
        } else if (const body_integral* mass = integral_of(in, "mass")) {
            w.text("Its density is ")
                .latex("$\\varrho(\\mathbf{r}) = " + density_latex(in.density, mass->deltas, b) + "$")
                .text(", and its mass");
            w.display_rows({integral_row("M", *mass, b)});
        }
        bool shifted = std::any_of(in.centre_of_mass.begin(), in.centre_of_mass.end(),
                                   [](const GiNaC::ex& c) { return !c.is_zero(); });
        if (shifted) {
            w.text("The first moments place the centre of mass:");
            std::vector<report_writer::row> rows;
            for (const char* name : axis_names)
                if (const body_integral* first = integral_of(in, name))
                    rows.push_back(integral_row(std::string("M ") + name + "_{\\mathrm{cm}}", *first, b));
            w.display_rows(rows);
            std::string centre = "\\left(";
            for (std::size_t k = 0; k < in.centre_of_mass.size(); ++k)
                centre += (k ? ",\\ " : "") + report_writer::math(in.centre_of_mass[k]);
            w.text("so the centre of mass is at ").latex("$" + centre + "\\right)$").text(
                " from the origin of the region; the moments below are about it.\n");
        } else {
            w.text("The first moments ").latex("$\\int_V \\varrho\\, x_i\\, dV$").text(
                " vanish, so the centre of mass is the origin of the body axes.\n");
        }
        w.text("Each component of the inertia tensor ")
            .latex("$I_{ij} = \\int_V \\varrho(\\mathbf{r})\\,(r^{2}\\delta_{ij} - x_i x_j)\\,dV$")
            .text(" about the centre of mass, as the integral it comes from:");
        std::vector<report_writer::row> rows;
        for (unsigned i = 0; i < 3; ++i)
            for (unsigned j = i; j < 3; ++j)
                if (const body_integral* component =
                        integral_of(in, std::string(axis_names[i]) + axis_names[j]))
                    rows.push_back(integral_row(std::string("I_{") + axis_names[i] + axis_names[j] + "}", *component, b));
        w.display_rows(rows);
        w.text("The tensor is symmetric, ").latex("$I_{ji} = I_{ij}$").text(", so").latex("\n");
    }
    w.display_matrix("\\mathbf{I}", in.tensor);
    if (!in.principal.empty()) {
        std::vector<report_writer::row> rows{{"I_{1}", {}}};
        for (std::size_t k = 0; k < in.principal.size(); ++k)
            rows.front().terms.push_back((k ? ",\\quad I_{" + std::to_string(k + 1) + "} = " : "") +
                                         report_writer::math(in.principal[k]));
        if (in.diagonal) {
            w.text("The body axes are principal axes; the principal moments are");
            w.display_rows(rows);
        } else {
            w.text("The principal moments, the roots of ").latex("$\\det(\\mathbf{I} - \\lambda) = 0$").text(", are");
            w.display_rows(rows);
            if (in.principal_axes) {
                w.text("along the columns of");
                w.display_matrix("\\mathbf{E}", *in.principal_axes);
            }
        }
    }
    if (in.about_origin) {
        w.text("About the origin of the scene (parallel axes, ").latex("$\\mathbf{I} + M(|\\mathbf{a}|^{2} - \\mathbf{a}\\mathbf{a}^{T})$").text("):");
        w.display_matrix("\\mathbf{I}_{O}", *in.about_origin);
    }
    const term_order order{{in.omega}};
    w.text("With the angular velocity ")
        .latex("$\\boldsymbol{\\omega} = " + omega_row(in.omega) + "$")
        .text(" in the body axes, the angular momentum ")
        .latex("$\\mathbf{L} = \\mathbf{I}\\boldsymbol{\\omega}$")
        .text(" and the kinetic energy ")
        .latex("$T = \\frac{1}{2}\\boldsymbol{\\omega}^{T}\\mathbf{I}\\boldsymbol{\\omega}$")
        .text(" are");
    std::string column = "\\begin{pmatrix}";
    for (std::size_t k = 0; k < in.angular_momentum.size(); ++k)
        column += (k ? " \\\\ " : "") + print(in.angular_momentum[k], syntax::latex, order);
    w.display_rows({{"\\mathbf{L}", {column + "\\end{pmatrix}"}}, {"T", print_terms(in.kinetic_energy, syntax::latex, order)}});
}

} // namespace

void write_inertia_text(std::ostream& out, const analysis& result)
{
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
}

void write_inertia_latex(std::ostream& out, const analysis& result)
{
    const model& scene = *result.scene;
    auto matrix = [](const GiNaC::matrix& m) {
        std::string text = "\\begin{pmatrix}";
        for (unsigned r = 0; r < 3; ++r)
            for (unsigned c = 0; c < 3; ++c)
                text += print(m(r, c), syntax::latex) + (c < 2 ? " & " : r < 2 ? " \\\\ " : "");
        return text + "\\end{pmatrix}";
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
            out << latex_line("I = " + matrix(in.tensor));
            if (in.about_origin)
                out << latex_line("I_{O} = " + matrix(*in.about_origin));
            term_order order{{in.omega}};
            out << latex_line("L = I\\omega = \\begin{pmatrix}" + join(printed(in.angular_momentum, syntax::latex, order), " \\\\ ") +
                    "\\end{pmatrix},\\quad T = \\tfrac12\\omega^{T} I \\omega = " +
                    print(in.kinetic_energy, syntax::latex, order));
        }
    }
}

void write_inertia_json(nlohmann::ordered_json& doc, const analysis& result)
{
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
            body["principal"] = json_strings(in.principal);
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
                body["centre_of_mass"] = json_strings(in.centre_of_mass);
                nlohmann::ordered_json integrals = nlohmann::ordered_json::array();
                for (const body_integral& i : in.integrals) {
                    nlohmann::ordered_json limits = nlohmann::ordered_json::array();
                    for (const integration_limit& l : i.limits)
                        limits.push_back({{"variable", print(l.variable, syntax::plain)},
                                          {"lower", print(l.lower, syntax::plain)},
                                          {"upper", print(l.upper, syntax::plain)}});
                    integrals.push_back({{"quantity", i.quantity},
                                         {"density", print(i.density, syntax::plain)},
                                         {"deltas", json_strings(i.deltas)},
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
            body["angular_momentum"] = json_strings(in.angular_momentum, order);
            body["kinetic_energy"] = print(in.kinetic_energy, syntax::plain, order);
            all[in.body] = body;
        }
        doc["inertia"] = all;
    }
}

void write_inertia_section(report_writer& w)
{
    w.latex("\\section{Inertia tensors}\n");
    const auto& all = *w.result().inertia;
    if (std::any_of(all.begin(), all.end(), [](const inertia_result& in) { return !in.integrals.empty(); }))
        w.text("Each tensor is derived by integrating the density over the body, about its centre of mass and in "
               "body axes (x, y, z).\n");
    for (const inertia_result& in : *w.result().inertia)
        if (const rigid_body* b = body_named(w.scene(), in.body))
            write_body_inertia(w, in, *b);
}

} // namespace lagrange
