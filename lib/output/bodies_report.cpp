// SPDX-License-Identifier: GPL-2.0-or-later
/** @file bodies_report.cpp
 *  The report's rigid-body sections: each inertia component as the integral it
 *  comes from (the homework's eqs. 16–35: the density with its deltas, the
 *  integral in body coordinates, the same integral set up in the coordinates the
 *  engine integrated in, its value), the tensor, principal axes, L = Iω and
 *  T = ½ωᵀIω; Euler's equations, the torque-free solution, the conserved
 *  quantities, stability per axis and the polhode; the heavy top. Everything
 *  printed is a result of the `inertia`, `euler` and `top` stages; the only
 *  arithmetic here is presentation (a constant density taken in front of an
 *  integral, the closed-form ω(t) evaluated to draw it). */
#include "output/report_sections.h"

#include "core/number_text.h"

#include "output/latex_blocks.h"
#include "output/print.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lagrange {

namespace {

const char* const axis_names[] = {"x", "y", "z"};

std::string body_title(const std::string& name) { return "$" + report_writer::name(name) + "$"; }

/// How the body was given, as the scene wrote it.
std::string description(const rigid_body& b)
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

std::string gnuplot_number(double x) { return significant(std::abs(x) < 1e-14 ? 0.0 : x, 9); }

/// A name of ω_k for gnuplot's labels (plain text, Unicode).
std::string plain_name(const GiNaC::ex& e) { return print(e, syntax::text); }

void write_body_inertia(report_writer& w, const inertia_result& in, const rigid_body& b)
{
    w.latex("\\subsection{Body " + body_title(in.body) + "}\n");
    w.text("The body ").latex(body_title(in.body)).text(" is ").latex(description(b)).text(", of mass ")
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

void write_inertia(report_writer& w)
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

/// The polhode on the inertia ellipsoid, drawn in 3D.
void polhode_figure(report_writer& w, const euler_result& e, const std::string& tag)
{
    const auto& p = *e.poinsot;
    if (p.polhode.empty())
        return;
    std::string script = "set parametric\nset view equal xyz\nset view 64, 28, 1.2\nset ticslevel 0\nset hidden3d\n"
                         "set urange [0:2*pi]\nset vrange [-pi/2:pi/2]\nset isosamples 25, 13\n"
                         "set key at screen 0.98, 0.97 right top\nset xtics 0.5 offset 0, -0.5\nset ytics 0.5\nset ztics 0.5\n";
    script += "set xlabel '" + plain_name(e.omega[0]) + "'\nset ylabel '" + plain_name(e.omega[1]) + "'\nset zlabel '" +
              plain_name(e.omega[2]) + "'\n";
    script += "$polhode << EOD\n";
    for (const auto& point : p.polhode)
        script += gnuplot_number(point[0]) + " " + gnuplot_number(point[1]) + " " + gnuplot_number(point[2]) + "\n";
    const auto& first = p.polhode.front();
    script += gnuplot_number(first[0]) + " " + gnuplot_number(first[1]) + " " + gnuplot_number(first[2]) + "\nEOD\n";
    script += "splot " + gnuplot_number(p.ellipsoid_axes[0]) + "*cos(u)*cos(v), " + gnuplot_number(p.ellipsoid_axes[1]) +
              "*sin(u)*cos(v), " + gnuplot_number(p.ellipsoid_axes[2]) +
              "*sin(v) with lines lc rgb '#c8c8c8' title 'inertia ellipsoid', "
              "$polhode using 1:2:3 with lines lw 2.5 lc rgb '#c00000' title 'polhode'\n";
    w.figure(tag + "polhode", script, 12, 10,
             "The polhode of body " + body_title(e.body) +
                 ": the tip of $\\boldsymbol{\\omega}$ over one period, on the inertia ellipsoid "
                 "$\\boldsymbol{\\omega}^{T}\\mathbf{I}\\boldsymbol{\\omega} = 2T$.");
}

/// The seed's Figure 8: Poinsot's construction in space at t = 0 — the inertia ellipsoid
/// ρᵀIρ = 1 turned to its orientation then, resting on the invariable plane, the polhode on it,
/// ω through the point of contact, and the herpolhode the contact traces on the plane.
void poinsot_figure(report_writer& w, const poinsot_motion& m, const std::string& tag)
{
    if (m.rotation.empty() || m.polhode.empty())
        return;
    const auto& R = m.rotation.front();
    const auto& a = m.semi_axes;
    auto triple = [](const std::array<double, 3>& r) {
        return gnuplot_number(r[0]) + " " + gnuplot_number(r[1]) + " " + gnuplot_number(r[2]) + "\n";
    };
    double half = std::max({a[0], a[1], a[2]});
    for (const auto& c : m.contact)
        half = std::max({half, std::abs(c[0]), std::abs(c[1])});
    half *= 1.15;
    const std::string z = gnuplot_number(-m.plane_distance), h = gnuplot_number(half);
    std::string script = "set parametric\nset view equal xyz\nset view 68, 32, 1.25\nset ticslevel 0\n"
                         "set urange [0:2*pi]\nset vrange [-pi/2:pi/2]\nset isosamples 19, 11\nunset xtics\nunset ytics\n"
                         "unset ztics\nunset border\nset key at screen 0.99, 0.98 right top\n";
    script += "$plane << EOD\n";
    for (int k = -4; k <= 4; ++k) {
        const std::string s = gnuplot_number(k * half / 4);
        script += "-" + h + " " + s + " " + z + "\n" + h + " " + s + " " + z + "\n\n\n" + s + " -" + h + " " + z + "\n" +
                  s + " " + h + " " + z + "\n\n\n";
    }
    script += "EOD\n$polhode << EOD\n";
    for (const auto& b : m.polhode)
        script += triple({R[0] * b[0] + R[1] * b[1] + R[2] * b[2], R[3] * b[0] + R[4] * b[1] + R[5] * b[2],
                          R[6] * b[0] + R[7] * b[1] + R[8] * b[2]});
    script += "EOD\n$herpolhode << EOD\n";
    for (const auto& c : m.contact)
        script += triple(c);
    script += "EOD\n$omega << EOD\n0 0 0\n" + triple(m.contact.front()) + "EOD\n";
    // The ellipsoid's surface: body point (a cos u cos v, b sin u cos v, c sin v) turned by R(0).
    std::string surface;
    for (int i = 0; i < 3; ++i)
        surface += std::string(i ? ", " : "") + gnuplot_number(R[3 * i] * a[0]) + "*cos(u)*cos(v) + " +
                   gnuplot_number(R[3 * i + 1] * a[1]) + "*sin(u)*cos(v) + " + gnuplot_number(R[3 * i + 2] * a[2]) +
                   "*sin(v)";
    script += "splot " + surface + " with lines lc rgb '#c8c8c8' title 'inertia ellipsoid', "
              "$plane using 1:2:3 with lines lc rgb '#9ab0d0' title 'invariable plane', "
              "$herpolhode using 1:2:3 with lines lw 2 lc rgb '#1f4e9c' title 'herpolhode', "
              "$polhode using 1:2:3 with lines lw 2.5 lc rgb '#c00000' title 'polhode', "
              "$omega using 1:2:3 with lines lw 2.5 lc rgb '#e07000' title 'ω'\n";
    w.figure(tag + "poinsot", script, 13, 11,
             "Poinsot's construction for body " + body_title(m.body) +
                 ": the inertia ellipsoid $\\boldsymbol{\\rho}^{T}\\mathbf{I}\\boldsymbol{\\rho} = 1$ at $t = 0$, "
                 "touching the invariable plane (normal to $\\mathbf{L}$, at $\\sqrt{2T}/|\\mathbf{L}| = " +
                 report_writer::number(m.plane_distance, 6) +
                 "$ from the centre) at $\\boldsymbol{\\rho} = \\boldsymbol{\\omega}/\\sqrt{2T}$; the polhode on the "
                 "ellipsoid and the herpolhode it rolls out on the plane over $t \\le " +
                 report_writer::number(m.times.back(), 4) + "$.");
}

/// ω(t) of the elliptic solution over one period.
void omega_figure(report_writer& w, const euler_result& e, const std::string& tag)
{
    const auto& s = *e.elliptic;
    constexpr int samples = 240;
    std::string script = "set key outside right\nset xlabel 't'\nset ylabel 'body components of ω'\nset grid\n$omega << EOD\n";
    for (int n = 0; n <= samples; ++n) {
        double t = s.period * n / samples;
        std::array<double, 3> v = s.evaluate(t);
        script += gnuplot_number(t) + " " + gnuplot_number(v[0]) + " " + gnuplot_number(v[1]) + " " +
                  gnuplot_number(v[2]) + "\n";
    }
    script += "EOD\nset xrange [0:" + gnuplot_number(s.period) + "]\nplot ";
    const char* colours[] = {"#1f4e9c", "#c00000", "#2a8a2a"};
    for (int k = 0; k < 3; ++k)
        script += std::string(k ? ", " : "") + "$omega using 1:" + std::to_string(k + 2) + " with lines lw 2 lc rgb '" +
                  colours[k] + "' title '" + plain_name(e.omega[static_cast<std::size_t>(k)]) + "'";
    script += "\n";
    w.figure(tag + "omega", script, 14, 6,
             "The body components of $\\boldsymbol{\\omega}(t)$ of body " + body_title(e.body) +
                 " over one period, from the Jacobi elliptic solution.");
}

void write_body_euler(report_writer& w, const euler_result& e)
{
    const term_order order{{e.rates, e.omega}};
    w.latex("\\subsection{Body " + body_title(e.body) + "}\n");
    w.text("The rate of change of ").latex("$\\mathbf{L}$").text(" in space is its rate in the body frame plus ")
        .latex("$\\boldsymbol{\\omega}\\times\\mathbf{L}$")
        .text(", so ")
        .latex("$\\mathbf{I}\\dot{\\boldsymbol{\\omega}} + \\boldsymbol{\\omega}\\times\\mathbf{I}\\boldsymbol{\\omega} = \\mathbf{N}$")
        .text(e.torque_free ? ", and with no torque, in the body axes," : ", in the body axes,");
    std::vector<report_writer::row> rows;
    for (const GiNaC::ex& equation : e.equations)
        rows.push_back({"", print_terms(equation, syntax::latex, order), " = 0"});
    w.display_rows(rows);
    if (!e.principal_equations.empty()) {
        w.text("In principal axes:");
        rows.clear();
        for (const GiNaC::ex& equation : e.principal_equations)
            rows.push_back({"", print_terms(equation, syntax::latex, order), " = 0"});
        w.display_rows(rows);
    }
    if (e.torque_free && e.moments.size() == 3) {
        std::string moments;
        std::string energy = "\\tfrac{1}{2}\\left(", momentum;
        for (std::size_t k = 0; k < 3; ++k) {
            const std::string I = "I_{" + std::to_string(k + 1) + "}", wk = report_writer::math(e.omega[k]);
            moments += (k ? ",\\quad " : "") + I + " = " + report_writer::math(e.moments[k]);
            energy += (k ? " + " : "") + I + wk + "^{2}";
            momentum += (k ? " + " : "") + I + "^{2}" + wk + "^{2}";
        }
        energy += "\\right)";
        w.text("With the principal moments ").latex("$" + moments + "$").text(
            ", multiplying each equation by its component of ");
        w.latex("$\\boldsymbol{\\omega}$").text(" (or of ").latex("$\\mathbf{L}$").text(") and adding shows that the "
                                                                                          "kinetic energy and the "
                                                                                          "magnitude of the angular "
                                                                                          "momentum are conserved:");
        auto equal = [](std::vector<std::string> terms) {
            if (!terms.empty())
                terms.front() = "= " + terms.front();
            return terms;
        };
        w.display_rows({{"T", {energy}},
                        {"", equal(print_terms(e.kinetic_energy, syntax::latex, order))},
                        {"|\\mathbf{L}|^{2}", {momentum}},
                        {"", equal(print_terms(e.angular_momentum_squared, syntax::latex, order))}});
    }
    if (e.symmetric) {
        const auto& s = *e.symmetric;
        w.text("The body is symmetric about its axis " + std::to_string(s.axis + 1) + ": ")
            .latex("$" + report_writer::math(e.omega[s.axis]) + "$")
            .text(" is constant and the other two components turn at the rate");
        w.display("\\Omega", s.precession);
        w.text("The torque-free solution, from ")
            .latex("$\\boldsymbol{\\omega}(0) = \\left(");
        for (std::size_t k = 0; k < s.constants.size(); ++k)
            w.latex((k ? ",\\ " : "") + report_writer::math(s.constants[k]));
        w.latex("\\right)$").text(", is");
        rows.clear();
        for (std::size_t k = 0; k < 3; ++k)
            rows.push_back({report_writer::math(e.omega[k]) + "(t)", print_terms(s.omega[k], syntax::latex)});
        w.display_rows(rows);
    }
    const std::string tag = "body-" + e.body + "-";
    if (e.elliptic) {
        const auto& s = *e.elliptic;
        const char* functions[] = {"cn", "sn", "dn"};
        w.text("The body is asymmetric. At the values of the scene and from its initial ")
            .latex("$\\boldsymbol{\\omega}(0)$")
            .text(", Euler's equations are solved by Jacobi's elliptic functions (Landau and Lifshitz, ")
            .latex("\\S")
            .text("37)");
        w.text(", with the modulus ").latex("$k = " + report_writer::number(s.modulus, 10) + "$").text(":");
        rows.clear();
        for (std::size_t k = 0; k < 3; ++k) {
            std::size_t role = 0;
            while (s.roles[role] != k)
                ++role;
            rows.push_back({report_writer::math(e.omega[k]) + "(t)",
                            {report_writer::number(s.amplitudes[role], 10) + "\\,\\mathrm{" + functions[role] + "}\\!\\left(" +
                             report_writer::number(s.rate, 10) + "\\,t " + (s.phase < 0 ? "- " : "+ ") +
                             report_writer::number(std::abs(s.phase), 10) + ",\\ k\\right)"}});
        }
        w.display_rows(rows);
        w.text("Its period is ").latex("$4K(k)/\\lambda = " + report_writer::number(s.period, 10) + "$")
            .text(" (").latex("$\\lambda$").text(" the rate of the argument above), and along it ")
            .latex("$T = " + report_writer::number(s.energy, 10) + "$")
            .text(" and ")
            .latex("$|\\mathbf{L}|^{2} = " + report_writer::number(s.momentum_squared, 10) + "$")
            .text(".\n");
        omega_figure(w, e, tag);
    }
    if (e.poinsot) {
        const auto& p = *e.poinsot;
        w.text("Poinsot's construction: ").latex("$\\boldsymbol{\\omega}$").text(" lies on the inertia ellipsoid ")
            .latex("$\\boldsymbol{\\omega}^{T}\\mathbf{I}\\boldsymbol{\\omega} = 2T$")
            .text(" with the semi-axes ")
            .latex("$\\sqrt{2T/I_{k}} = " + report_writer::number(p.ellipsoid_axes[0], 8) + ",\\ " +
                   report_writer::number(p.ellipsoid_axes[1], 8) + ",\\ " + report_writer::number(p.ellipsoid_axes[2], 8) + "$")
            .text(", which rolls without slipping on the invariable plane normal to ")
            .latex("$\\mathbf{L}$")
            .text(" at the distance ")
            .latex("$2T/|\\mathbf{L}| = " + report_writer::number(p.plane_distance, 8) + "$")
            .text(" from the centre. The curve ").latex("$\\boldsymbol{\\omega}(t)$")
            .text(" traces on the ellipsoid is the polhode.\n");
        polhode_figure(w, e, tag);
        if (w.result().poinsot)
            for (const poinsot_motion& m : *w.result().poinsot)
                if (m.body == e.body) {
                    w.text("The ellipsoid ").latex("$\\boldsymbol{\\rho}^{T}\\mathbf{I}\\boldsymbol{\\rho} = 1$")
                        .text(" of ").latex("$\\boldsymbol{\\rho} = \\boldsymbol{\\omega}/\\sqrt{2T}$")
                        .text(", fixed in the body, turns with it and rolls without slipping on the invariable plane: "
                              "the point of contact lies on the instantaneous axis, so it is at rest. Euler's "
                              "equations and the orientation integrated together (" + m.method + ", " +
                              std::to_string(m.steps) + " steps) draw it in space.\n");
                    poinsot_figure(w, m, tag);
                }
    }
    if (e.stability.size() == 3) {
        w.text("Steady rotation about each principal axis, perturbed slightly:");
        w.latex("\n\\begin{center}\n\\begin{tabular}{cll}\n\\hline\naxis & moment & rotation\\\\\n\\hline\n");
        for (std::size_t k = 0; k < 3; ++k)
            w.latex(std::to_string(k + 1) + " & $" + (k < e.moments.size() ? report_writer::math(e.moments[k]) : "") +
                    "$ & " + latex_text(e.stability[k]) + "\\\\\n");
        w.latex("\\hline\n\\end{tabular}\n\\end{center}\n");
        w.text("Rotation about the axes of the largest and the smallest moment is stable, about the intermediate one "
               "unstable; equal moments make the rotation about those axes marginal.\n\n");
    }
}

void write_euler(report_writer& w)
{
    w.latex("\\section{Euler's equations}\n");
    for (const euler_result& e : *w.result().euler)
        write_body_euler(w, e);
}

void write_tops(report_writer& w)
{
    w.latex("\\section{The heavy top}\n");
    for (const top_result& top : *w.result().tops) {
        const term_order order{{{top.spin}}};
        const std::string theta = report_writer::math(top.nutation);
        if (w.result().tops->size() > 1)
            w.latex("\\subsection{Body " + body_title(top.body) + "}\n");
        w.text("The body ").latex(body_title(top.body)).text(" has the moment ")
            .latex("$I_{1} = " + report_writer::math(top.pivot_moment) + "$")
            .text(" about the pivot (perpendicular to its axis) and ")
            .latex("$I_{3} = " + report_writer::math(top.spin_moment) + "$")
            .text(" about its axis. Two Euler angles are cyclic, so their momenta are conserved; the top sleeps "
                  "(spins upright, ")
            .latex("$" + theta + " = 0$")
            .text(") with both equal to ")
            .latex("$I_{3}" + report_writer::math(top.spin) + "$")
            .text(", where ")
            .latex("$" + report_writer::math(top.spin) + "$")
            .text(" is the conserved spin. Routh's procedure with these momenta leaves the motion in ")
            .latex("$" + theta + "$")
            .text(" alone, in the effective potential");
        w.display("V_{\\mathrm{eff}}(" + theta + ")", top.effective_potential);
        w.text("Near the upright position,");
        w.display_terms("V_{\\mathrm{eff}}", {"\\text{const} + \\left(" +
                                                  [&] {
                                                      std::string joined;
                                                      for (const std::string& t :
                                                           print_terms(top.curvature, syntax::latex, order))
                                                          joined += (joined.empty() ? "" : " ") + t;
                                                      return joined;
                                                  }() +
                                                  "\\right)" + theta + "^{2} + O(" + theta + "^{4})"});
        w.text("so the sleeping top is stable when the curvature is positive, that is when");
        w.display_rows({{"", print_terms(top.condition, syntax::latex, order), " > 0."}});
        if (!top.precession_quadratic.empty()) {
            const term_order by_rate{{{top.precession}, {top.spin}}};
            const GiNaC::ex& rate = top.precession;
            const std::vector<GiNaC::ex>& a = top.precession_quadratic;
            w.text("The top precesses steadily at the angle ")
                .latex("$" + theta + "$")
                .text(" (with ")
                .latex("$\\dot{" + theta + "} = 0$")
                .text(") at a rate ")
                .latex("$\\Omega = \\dot{\\phi}$")
                .text(" that makes the nutation equation vanish, a quadratic in the rate:");
            w.display_rows({{"", print_terms(a[2] * rate * rate + a[1] * rate + a[0], syntax::latex, by_rate), " = 0."}});
            w.text("Its two roots are the slow and the fast precession (for a positive spin):");
            w.display("\\Omega_{\\mathrm{slow}}", top.slow_precession);
            w.display("\\Omega_{\\mathrm{fast}}", top.fast_precession);
            if (!top.nutation_frequency_squared.is_zero()) {
                w.text("About a steady precession, with both cyclic momenta at their values there, the "
                       "curvature of the effective potential over the moment about the pivot gives the "
                       "frequency of small nutation:");
                w.display("\\omega_{\\mathrm{nut}}^{2}", top.nutation_frequency_squared);
            }
        }
    }
}

} // namespace

void write_body_sections(report_writer& w)
{
    const analysis& r = w.result();
    if (r.inertia)
        write_inertia(w);
    if (r.tops && !r.tops->empty())
        write_tops(w);
    if (r.euler)
        write_euler(w);
}

} // namespace lagrange
