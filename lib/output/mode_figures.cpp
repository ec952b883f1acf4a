// SPDX-License-Identifier: GPL-2.0-or-later
/** @file mode_figures.cpp
 *  The report's figure of the mode shapes: point masses in a plane drawn at
 *  equilibrium and displaced along each mode, or bar charts of the mode vectors.
 *  Positions are evaluated numerically here only to draw them. */
#include "output/report_sections.h"

#include "core/number_text.h"

#include "output/mode_frequency.h"
#include "output/print.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>

namespace lagrange {

namespace {

std::string index(std::size_t k) { return "_{" + std::to_string(k + 1) + "}"; }

/// The modes at the first `values` point, numerically: from the analysis, or
/// computed for the figures when the scene did not ask for the numeric table.
std::optional<numeric_modes> figure_modes(const analysis& result)
{
    if (result.numeric && !result.numeric->empty())
        return result.numeric->front();
    if (!result.linearization || result.scene->values.empty())
        return std::nullopt;
    try {
        std::vector<numeric_modes> all = numeric_normal_modes(*result.scene, *result.linearization);
        if (!all.empty())
            return all.front();
    } catch (const computation_error&) {
    }
    return std::nullopt;
}

/// A coordinate value at the values point, or nothing when it is not a real number there.
std::optional<double> evaluate(const GiNaC::ex& e, const GiNaC::exmap& at)
{
    try {
        GiNaC::ex value = e.subs(at).evalf();
        if (!GiNaC::is_a<GiNaC::numeric>(value) || !GiNaC::ex_to<GiNaC::numeric>(value).is_real())
            return std::nullopt;
        double x = GiNaC::ex_to<GiNaC::numeric>(value).to_double();
        return std::isfinite(x) ? std::optional<double>(x) : std::nullopt;
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

std::string gnuplot_number(double x) { return significant(std::abs(x) < 1e-12 ? 0.0 : x, 6); }

/// The drawing of point-mass scenes in the plane: rods (constant distance from
/// the origin or from another point), springs, masses, each mode at ± amplitude.
/// Returns the gnuplot script, or nothing when the scene cannot be drawn so.
std::optional<std::string> pendulum_script(const analysis& result, const numeric_modes& numbers,
                                           std::size_t& panels)
{
    const model& scene = *result.scene;
    const std::size_t n = scene.coordinates.size();
    // With constraints the modes are in the independent coordinates: no positions to draw.
    if (scene.points.empty() || !result.linearization || result.constrained)
        return std::nullopt;
    for (const point_mass& p : scene.points)
        if (p.position.size() < 2 || p.position.size() > 3 ||
            (p.position.size() == 3 && !p.position[2].is_zero()))
            return std::nullopt;
    // All the values of the point (the numeric modes list only those T and V use).
    GiNaC::exmap parameters = scene.values.empty() ? GiNaC::exmap{} : value_map(scene, scene.values.front());
    for (const auto& [name, value] : numbers.values)
        for (const parameter& p : scene.parameters)
            if (p.name == name)
                parameters[p.symbol] = GiNaC::numeric(value);
    std::vector<double> rest(n);
    for (std::size_t i = 0; i < n; ++i) {
        std::optional<double> q0 = evaluate(result.linearization->at[i], parameters);
        if (!q0)
            return std::nullopt;
        rest[i] = *q0;
    }
    using point2 = std::array<double, 2>;
    // Positions of every point at the coordinates q; nothing if one is not a number.
    auto positions = [&](const std::vector<double>& q) -> std::optional<std::vector<point2>> {
        GiNaC::exmap at = parameters;
        for (std::size_t i = 0; i < n; ++i)
            at[scene.coordinates[i].position] = GiNaC::numeric(q[i]);
        std::vector<point2> out;
        for (const point_mass& p : scene.points) {
            std::optional<double> x = evaluate(p.position[0], at), y = evaluate(p.position[1], at);
            if (!x || !y)
                return std::nullopt;
            out.push_back({*x, *y});
        }
        return out;
    };
    auto shifted = [&](const std::vector<double>& direction, double s) {
        std::vector<double> q = rest;
        for (std::size_t i = 0; i < n; ++i)
            q[i] += s * direction[i];
        return q;
    };
    std::optional<std::vector<point2>> base = positions(rest);
    if (!base)
        return std::nullopt;
    // Rods: a point at a constant distance (tried at a few configurations) from the
    // nearest earlier point, else from the origin.
    auto distance = [](const point2& a, const point2& b) { return std::hypot(a[0] - b[0], a[1] - b[1]); };
    std::vector<std::vector<point2>> probes;
    for (double t : {0.3, -0.7, 1.1}) {
        std::vector<double> q(n);
        for (std::size_t i = 0; i < n; ++i)
            q[i] = rest[i] + t * (0.5 + 0.37 * static_cast<double>(i));
        std::optional<std::vector<point2>> at = positions(q);
        if (!at)
            return std::nullopt;
        probes.push_back(*at);
    }
    const point2 origin{0.0, 0.0};
    std::vector<int> parent(scene.points.size(), -2); // -1 origin, -2 none
    for (std::size_t i = 0; i < scene.points.size(); ++i) {
        auto constant = [&](auto&& other) {
            double d0 = distance(probes[0][i], other(0));
            if (d0 < 1e-9)
                return false;
            for (std::size_t k = 1; k < probes.size(); ++k)
                if (std::abs(distance(probes[k][i], other(k)) - d0) > 1e-9 * (1 + d0))
                    return false;
            return true;
        };
        for (int j = static_cast<int>(i) - 1; j >= 0 && parent[i] == -2; --j)
            if (constant([&](std::size_t k) { return probes[k][static_cast<std::size_t>(j)]; }))
                parent[i] = j;
        if (parent[i] == -2 && constant([&](std::size_t) { return origin; }))
            parent[i] = -1;
    }
    // Spring ends: a point of the scene (matched by position) or a fixed place.
    auto spring_end = [&](const std::vector<GiNaC::ex>& end, const GiNaC::exmap& at) -> std::optional<point2> {
        if (end.size() < 2 || end.size() > 3 || (end.size() == 3 && !end[2].is_zero()))
            return std::nullopt;
        std::optional<double> x = evaluate(end[0], at), y = evaluate(end[1], at);
        if (!x || !y)
            return std::nullopt;
        return point2{*x, *y};
    };
    // The amplitude: the largest displacement of a point is 15% of the drawing's size.
    double size = 0;
    for (const point2& p : *base) {
        size = std::max(size, distance(p, origin));
        for (const point2& r : *base)
            size = std::max(size, distance(p, r));
    }
    if (!(size > 0))
        return std::nullopt;
    std::ostringstream data, plots;
    double xmin = 0, xmax = 0, ymin = 0, ymax = 0;
    auto extend = [&](const point2& p) {
        xmin = std::min(xmin, p[0]);
        xmax = std::max(xmax, p[0]);
        ymin = std::min(ymin, p[1]);
        ymax = std::max(ymax, p[1]);
    };
    panels = n;
    for (std::size_t k = 0; k < n; ++k) {
        std::vector<double> direction(n);
        for (std::size_t i = 0; i < n; ++i)
            direction[i] = numbers.modes(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k));
        const double h = 1e-6;
        std::optional<std::vector<point2>> nudged = positions(shifted(direction, h));
        if (!nudged)
            return std::nullopt;
        double speed = 0;
        for (std::size_t p = 0; p < base->size(); ++p)
            speed = std::max(speed, distance((*nudged)[p], (*base)[p]) / h);
        if (!(speed > 0))
            return std::nullopt;
        double amplitude = 0.15 * size / speed;
        const char* names[] = {"rest", "plus", "minus"};
        for (int c = 0; c < 3; ++c) {
            double s = c == 0 ? 0.0 : c == 1 ? amplitude : -amplitude;
            std::vector<double> q = shifted(direction, s);
            std::optional<std::vector<point2>> at = positions(q);
            if (!at)
                return std::nullopt;
            GiNaC::exmap subs = parameters;
            for (std::size_t i = 0; i < n; ++i)
                subs[scene.coordinates[i].position] = GiNaC::numeric(q[i]);
            data << "$" << names[c] << "_lines_" << k << " << EOD\n";
            for (std::size_t p = 0; p < at->size(); ++p) {
                if (parent[p] == -2)
                    continue;
                const point2& from = parent[p] == -1 ? origin : (*at)[static_cast<std::size_t>(parent[p])];
                data << gnuplot_number(from[0]) << ' ' << gnuplot_number(from[1]) << '\n'
                     << gnuplot_number((*at)[p][0]) << ' ' << gnuplot_number((*at)[p][1]) << "\n\n";
                extend(from);
            }
            for (const spring& sp : scene.springs) {
                std::optional<point2> a = spring_end(sp.end_a, subs), b = spring_end(sp.end_b, subs);
                if (!a || !b)
                    continue;
                // a zigzag of 8 teeth between the ends
                double dx = (*b)[0] - (*a)[0], dy = (*b)[1] - (*a)[1];
                double length = std::hypot(dx, dy);
                if (length < 1e-12)
                    continue;
                double nx = -dy / length * 0.04 * size, ny = dx / length * 0.04 * size;
                for (int t = 0; t <= 18; ++t) {
                    double side = (t == 0 || t == 18 || t == 1 || t == 17) ? 0.0 : (t % 2 ? 1.0 : -1.0);
                    double sf = t <= 1 ? 0.1 * t : t >= 17 ? 1.0 - 0.1 * (18 - t) : 0.1 + 0.8 * (t - 1) / 16.0;
                    data << gnuplot_number((*a)[0] + sf * dx + side * nx) << ' '
                         << gnuplot_number((*a)[1] + sf * dy + side * ny) << '\n';
                }
                data << "\n";
                extend(*a);
                extend(*b);
            }
            data << "0 0\nEOD\n";
            data << "$" << names[c] << "_masses_" << k << " << EOD\n";
            for (const point2& p : *at) {
                data << gnuplot_number(p[0]) << ' ' << gnuplot_number(p[1]) << '\n';
                extend(p);
            }
            data << "EOD\n";
        }
        plots << "set title \"mode " << k + 1 << ":  "
              << mode_frequency_text(numbers, k, [](double x) { return significant(x, 4); })
              << "\"\n"
              << "plot $rest_lines_" << k << " with lines lc rgb '#b8b8b8' lw 3, "
              << "$rest_masses_" << k << " with points pt 7 ps 0.9 lc rgb '#b8b8b8', "
              << "$minus_lines_" << k << " with lines lc rgb '#c0392b' lw 2 dt 2, "
              << "$minus_masses_" << k << " with points pt 7 ps 1.1 lc rgb '#c0392b', "
              << "$plus_lines_" << k << " with lines lc rgb '#1f4e9c' lw 2, "
              << "$plus_masses_" << k << " with points pt 7 ps 1.1 lc rgb '#1f4e9c', "
              << "'-' with points pt 5 ps 0.7 lc rgb 'black'\n0 0\ne\n";
    }
    // Everything on one line (a chain moving along it): the drawing would overlap
    // itself; the bar chart shows such modes better.
    if (xmax - xmin < 1e-6 * size || ymax - ymin < 1e-6 * size)
        return std::nullopt;
    double pad = 0.08 * size;
    std::ostringstream script;
    script << data.str() << "set size ratio -1\nunset border\nunset xtics\nunset ytics\nunset key\n"
           << "set xrange [" << gnuplot_number(xmin - pad) << ":" << gnuplot_number(xmax + pad) << "]\n"
           << "set yrange [" << gnuplot_number(ymin - pad) << ":" << gnuplot_number(ymax + pad) << "]\n"
           << "set multiplot layout 1," << n << "\n"
           << plots.str() << "unset multiplot\n";
    return script.str();
}

/// Bar charts of the mode vector components (largest component 1 in size, last nonzero positive).
std::string bar_script(const std::vector<std::string>& coordinates, const numeric_modes& numbers)
{
    const std::size_t n = coordinates.size();
    std::ostringstream script;
    for (std::size_t k = 0; k < n; ++k) {
        double largest = 0, sign = 1;
        for (std::size_t i = 0; i < n; ++i) {
            double a = numbers.modes(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k));
            largest = std::max(largest, std::abs(a));
            if (std::abs(a) > 1e-12)
                sign = a < 0 ? -1 : 1;
        }
        script << "$mode_" << k << " << EOD\n";
        for (std::size_t i = 0; i < n; ++i) {
            double a = numbers.modes(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k));
            script << i + 1 << ' ' << gnuplot_number(largest > 0 ? sign * a / largest : 0.0) << " \""
                   << print_name(coordinates[i], syntax::text) << "\"\n";
        }
        script << "EOD\n";
    }
    script << "set style fill solid 0.7 noborder\nset boxwidth 0.6\nunset key\nset yrange [-1.15:1.15]\n"
           << "set xrange [0.4:" << n << ".6]\nset xzeroaxis lt -1\nset ytics 0.5\nset grid ytics lc rgb '#dddddd'\n"
           << "set multiplot layout 1," << n << "\n";
    for (std::size_t k = 0; k < n; ++k) {
        script << "set title \"mode " << k + 1 << ":  "
              << mode_frequency_text(numbers, k, [](double x) { return significant(x, 4); })
              << "\"\n"
               << "plot $mode_" << k << " using 1:2:xtic(3) with boxes lc rgb '#1f4e9c'\n";
    }
    script << "unset multiplot\n";
    return script.str();
}

} // namespace

void write_mode_figures(report_writer& w)
{
    const analysis& result = w.result();
    const model& scene = w.scene();
    std::optional<numeric_modes> numbers = figure_modes(result);
    w.latex("\\subsection*{Mode shapes}\n");
    if (!numbers) {
        w.text("The mode shapes are drawn at the parameter values of a `values' line; this scene has none.");
        w.latex("\n");
        return;
    }
    std::string at;
    for (std::size_t i = 0; i < numbers->values.size(); ++i)
        at += (i ? ",\\ " : "") + report_writer::name(numbers->values[i].first) + " = " +
              report_writer::number(numbers->values[i].second);
    // The coordinates the modes are in: with constraints, the independent ones.
    std::vector<std::string> coordinates;
    if (result.constrained)
        for (std::size_t i : result.constrained->independent)
            coordinates.push_back(scene.coordinates[i].name);
    else
        for (const coordinate& c : scene.coordinates)
            coordinates.push_back(c.name);
    const std::size_t n = coordinates.size();
    // In phase / antiphase, for two coordinates.
    if (n == 2) {
        for (std::size_t k = 0; k < 2; ++k) {
            double product = numbers->modes(0, static_cast<Eigen::Index>(k)) * numbers->modes(1, static_cast<Eigen::Index>(k));
            w.text((k == 0 ? "In mode " : "mode ") + std::to_string(k + 1) + " (").latex("$" + report_writer::name("omega") + index(k) +
                                                                    " = " + omega_value_latex(*numbers, k, [](double x) { return report_writer::number(x, 6); }) + "$")
                .text(std::string(") the coordinates move ") + (product > 0 ? "in phase" : product < 0 ? "in antiphase" : "one at a time") +
                      (k == 0 ? "; in " : "."));
        }
        if (numbers->modes(0, 0) * numbers->modes(1, 0) > 0 && numbers->modes(0, 1) * numbers->modes(1, 1) < 0)
            w.text(" The antiphase mode is the faster one.");
        w.latex("\n");
    }
    std::size_t panels = n;
    std::optional<std::string> drawing = pendulum_script(result, *numbers, panels);
    double width = std::min(17.0, 5.5 * static_cast<double>(std::max<std::size_t>(panels, 1)));
    if (drawing) {
        w.figure("modes", *drawing, width, 6.5,
                 "The normal modes at $" + at + "$: the equilibrium (grey) and the system displaced along each "
                 "mode, one way (solid, blue) and the other (dashed, red). The displacement is exaggerated.");
    } else if (n >= 2) {
        w.figure("modes", bar_script(coordinates, *numbers), width, 5.5,
                 "The components of each mode vector at $" + at +
                     "$, scaled so that the largest is 1 in size.");
    }
}

} // namespace lagrange
