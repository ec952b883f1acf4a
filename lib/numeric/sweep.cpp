// SPDX-License-Identifier: GPL-2.0-or-later
/** @file sweep.cpp
 *  Streamed numeric sweeps (see sweep.h). */
#include "numeric/sweep.h"

#include "core/assumptions.h"
#include "core/number_text.h"


#include <cmath>
#include <cstdlib>
#include <sstream>
#include <utility>

namespace lagrange {

namespace {

[[noreturn]] void bad_sweep(const std::string& text, std::size_t column, const std::string& message)
{
    scene_error error({"--sweep", 1, static_cast<int>(column) + 1}, message);
    error.attach_line_text(text);
    throw error;
}

/// A finite number filling text[begin, end) exactly.
double parse_number(const std::string& text, std::size_t begin, std::size_t end)
{
    std::string part = text.substr(begin, end - begin);
    if (part.empty())
        bad_sweep(text, begin, "expected a number");
    char* stop = nullptr;
    double value = std::strtod(part.c_str(), &stop);
    if (stop != part.c_str() + part.size() || part.find_first_of("xXpPnN") != std::string::npos)
        bad_sweep(text, begin, "`" + part + "` is not a number");
    if (!std::isfinite(value))
        bad_sweep(text, begin, "the number " + part + " is out of the range of floating point");
    return value;
}

std::string point_text(const model& scene, const std::vector<double>& values)
{
    std::string out;
    for (std::size_t k = 0; k < scene.parameters.size(); ++k)
        out += (k ? ", " : "") + scene.parameters[k].name + " = " + significant(values[k], 17);
    return out;
}

} // namespace

double between(double from, double to, double t, bool logarithmic)
{
    if (logarithmic)
        return std::pow(10.0, std::log10(from) + t * (std::log10(to) - std::log10(from)));
    return from + t * (to - from);
}

double grid_value(double from, double to, std::size_t count, bool logarithmic, std::size_t k)
{
    if (count <= 1 || k == 0)
        return from;
    if (k + 1 == count)
        return to;
    return between(from, to, static_cast<double>(k) / static_cast<double>(count - 1), logarithmic);
}

double sweep_axis::at(std::size_t k) const { return grid_value(from, to, count, logarithmic, k); }

sweep_axis parse_sweep_axis(const std::string& text, const model& scene)
{
    sweep_axis axis;
    std::size_t equals = text.find('=');
    if (equals == std::string::npos)
        bad_sweep(text, 0, "give a sweep as `name=from..to:count` or `name=from..to:count:log`");
    std::size_t name_begin = text.find_first_not_of(' ');
    std::size_t name_end = text.find_last_not_of(' ', equals == 0 ? 0 : equals - 1);
    axis.name = name_begin < equals ? text.substr(name_begin, name_end - name_begin + 1) : "";
    bool found = false;
    for (std::size_t k = 0; k < scene.parameters.size(); ++k)
        if (scene.parameters[k].name == axis.name) {
            axis.parameter = k;
            found = true;
        }
    if (!found)
        bad_sweep(text, name_begin < equals ? name_begin : 0, "`" + axis.name + "` is not a parameter of the scene");
    std::size_t dots = text.find("..", equals + 1);
    if (dots == std::string::npos)
        bad_sweep(text, equals + 1, "expected `from..to:count`");
    std::size_t colon = text.find(':', dots + 2);
    if (colon == std::string::npos)
        bad_sweep(text, text.size(), "expected `:count` after the range");
    std::size_t second = text.find(':', colon + 1);
    std::size_t count_end = second == std::string::npos ? text.size() : second;
    axis.from = parse_number(text, equals + 1, dots);
    axis.to = parse_number(text, dots + 2, colon);
    // Every point lies between the ends, so the ends agreeing with the assumptions suffices.
    for (auto [value, at] : {std::pair{axis.from, equals + 1}, std::pair{axis.to, dots + 2}})
        if (std::optional<std::string> why = parameter_value_contradiction(axis.name, value))
            bad_sweep(text, at, *why);
    std::string count = text.substr(colon + 1, count_end - colon - 1);
    double n = parse_number(text, colon + 1, count_end);
    if (!(n >= 1) || n != std::floor(n) || n > 1e10)
        bad_sweep(text, colon + 1, "the count `" + count + "` must be a whole number from 1 to 1e10");
    axis.count = static_cast<std::size_t>(n);
    if (second != std::string::npos) {
        if (text.substr(second + 1) != "log")
            bad_sweep(text, second + 1, "expected `log` (geometric spacing) after the count");
        axis.logarithmic = true;
        if (!(axis.from > 0 && axis.to > 0))
            bad_sweep(text, equals + 1, "a logarithmic sweep needs both ends positive");
    }
    return axis;
}

std::size_t sweep_size(const std::vector<sweep_axis>& axes)
{
    double total = 1;
    for (const sweep_axis& a : axes)
        total *= static_cast<double>(a.count);
    if (total > 1e10)
        throw computation_error("the sweep has more than 1e10 points");
    std::size_t n = 1;
    for (const sweep_axis& a : axes)
        n *= a.count;
    return n;
}

void sweep_numeric_modes(const model& scene, point_modes& path, const std::vector<sweep_axis>& axes,
                         const std::function<void(const sweep_row&)>& each)
{
    const std::size_t points = sweep_size(axes);
    std::vector<double> values(scene.parameters.size(), std::nan(""));
    std::vector<bool> given(scene.parameters.size(), false);
    for (const value_point& point : scene.values)
        read_value_point(scene, point, values, given);
    for (const sweep_axis& a : axes)
        given[a.parameter] = true;
    for (std::size_t k = 0; k < scene.parameters.size(); ++k)
        if (path.uses(k) && !given[k])
            throw computation_error("no value for parameter `" + scene.parameters[k].name +
                                    "` in the sweep: give it with `values` or --values");
    numeric_modes modes;
    sweep_row row;
    row.parameter_values = values.data();
    row.modes = &modes;
    for (std::size_t index = 0; index < points; ++index) {
        std::size_t rest = index;
        for (std::size_t a = axes.size(); a-- > 0;) {
            values[axes[a].parameter] = axes[a].at(rest % axes[a].count);
            rest /= axes[a].count;
        }
        path.evaluate(values.data(), modes, [&] {
            return "sweep point " + std::to_string(index + 1) + " (" + point_text(scene, values) + ")";
        });
        row.index = index;
        row.stability = stability_of(modes);
        each(row);
    }
}

} // namespace lagrange
