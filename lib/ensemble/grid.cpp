// SPDX-License-Identifier: GPL-2.0-or-later
/** @file grid.cpp
 *  The `--grid` and `--measure` options of `lagrange ensemble` (see ensemble.h). */
#include "ensemble/ensemble.h"

#include "core/assumptions.h"
#include "numeric/sweep.h"

#include <cmath>
#include <cstdlib>
#include <optional>
#include <utility>

namespace lagrange {

namespace {

[[noreturn]] void bad_option(const std::string& option, const std::string& text, std::size_t column,
                             const std::string& message)
{
    scene_error error({option, 1, static_cast<int>(column) + 1}, message);
    error.attach_line_text(text);
    throw error;
}

/// The position of the first non-blank character in text[begin, end), or `end`.
std::size_t skip_blanks(const std::string& text, std::size_t begin, std::size_t end)
{
    while (begin < end && text[begin] == ' ')
        ++begin;
    return begin;
}

/// text[begin, end) without blanks at either end, and where it starts.
std::pair<std::string, std::size_t> trimmed(const std::string& text, std::size_t begin, std::size_t end)
{
    begin = skip_blanks(text, begin, end);
    while (end > begin && text[end - 1] == ' ')
        --end;
    return {text.substr(begin, end - begin), begin};
}

/// A finite number filling text[begin, end) (blanks around it allowed).
double parse_number(const std::string& text, std::size_t begin, std::size_t end)
{
    auto [part, at] = trimmed(text, begin, end);
    if (part.empty())
        bad_option("--grid", text, at, "expected a number");
    char* stop = nullptr;
    double value = std::strtod(part.c_str(), &stop);
    if (stop != part.c_str() + part.size() || part.find_first_of("xXpPnN") != std::string::npos)
        bad_option("--grid", text, at, "`" + part + "` is not a number");
    if (!std::isfinite(value))
        bad_option("--grid", text, at, "the number " + part + " is out of the range of floating point");
    return value;
}

/// One entry text[begin, end) of the list.
ensemble_axis parse_axis(const std::string& text, std::size_t begin, std::size_t end, const model& scene, bool random)
{
    const std::string form = random ? "`name=from..to[:log]`" : "`name=from..to:count[:log]`";
    ensemble_axis axis;
    std::size_t equals = text.find('=', begin);
    if (equals == std::string::npos || equals >= end)
        bad_option("--grid", text, skip_blanks(text, begin, end), "give each grid entry as " + form);
    auto [name, name_at] = trimmed(text, begin, equals);
    axis.name = name;
    bool found = false;
    std::string base = name;
    bool velocity = false;
    if (base.size() > 1 && base.back() == '\'') {
        base.pop_back();
        velocity = true;
    } else if (base.size() > 4 && base.compare(base.size() - 4, 4, "_dot") == 0) {
        base.resize(base.size() - 4);
        velocity = true;
    }
    for (std::size_t k = 0; k < scene.coordinates.size() && !found; ++k)
        if (scene.coordinates[k].name == base) {
            axis.kind = velocity ? ensemble_axis::target::velocity : ensemble_axis::target::position;
            axis.index = k;
            found = true;
        }
    for (std::size_t k = 0; k < scene.parameters.size() && !found && !velocity; ++k)
        if (scene.parameters[k].name == name) {
            axis.kind = ensemble_axis::target::parameter;
            axis.index = k;
            found = true;
        }
    if (name.empty())
        bad_option("--grid", text, name_at, "expected a name before `=`");
    if (!found)
        bad_option("--grid", text, name_at,
                   "`" + name + "` is neither a coordinate, a velocity (`q'`) nor a parameter of the scene");
    std::size_t dots = text.find("..", equals + 1);
    if (dots == std::string::npos || dots >= end)
        bad_option("--grid", text, skip_blanks(text, equals + 1, end), "expected `from..to` after `" + name + "=`");
    std::size_t colon = text.find(':', dots + 2);
    if (colon >= end)
        colon = std::string::npos;
    axis.from = parse_number(text, equals + 1, dots);
    axis.to = parse_number(text, dots + 2, colon == std::string::npos ? end : colon);
    std::size_t rest = colon; // the `:log` part, if any
    if (!random) {
        if (colon == std::string::npos)
            bad_option("--grid", text, end, "expected `:count` after the range of `" + name + "`");
        std::size_t second = text.find(':', colon + 1);
        if (second >= end)
            second = std::string::npos;
        std::size_t count_end = second == std::string::npos ? end : second;
        auto [count_text, count_at] = trimmed(text, colon + 1, count_end);
        double n = count_text == "log" ? -1 : parse_number(text, colon + 1, count_end);
        if (!(n >= 1) || n != std::floor(n) || n > 1e9)
            bad_option("--grid", text, count_at,
                       "the count `" + count_text + "` must be a whole number from 1 to 1e9");
        axis.count = static_cast<std::size_t>(n);
        rest = second;
        if (axis.count == 1 && axis.from != axis.to)
            bad_option("--grid", text, count_at, "a count of 1 needs from = to (one value)");
    } else {
        axis.count = 0;
    }
    if (rest != std::string::npos) {
        auto [word, word_at] = trimmed(text, rest + 1, end);
        if (word != "log")
            bad_option("--grid", text, word_at,
                       random ? "expected `log` (sampled uniformly in the logarithm) after the range"
                              : "expected `log` (geometric spacing) after the count");
        axis.logarithmic = true;
        if (!(axis.from > 0 && axis.to > 0))
            bad_option("--grid", text, skip_blanks(text, equals + 1, end), "a logarithmic range needs both ends positive");
    }
    if (axis.from > axis.to)
        bad_option("--grid", text, skip_blanks(text, equals + 1, end),
                   "the range of `" + name + "` runs backwards: give it as from..to with from <= to");
    // Every point lies between the ends, so the ends agreeing with the assumptions suffices.
    if (axis.kind == ensemble_axis::target::parameter)
        for (auto [value, at] : {std::pair{axis.from, equals + 1}, std::pair{axis.to, dots + 2}})
            if (std::optional<std::string> why = parameter_value_contradiction(name, value))
                bad_option("--grid", text, skip_blanks(text, at, end), *why);
    return axis;
}

} // namespace

double ensemble_axis::at(std::size_t k) const { return grid_value(from, to, count, logarithmic, k); }

double ensemble_axis::sample(double u) const { return between(from, to, u, logarithmic); }

std::vector<ensemble_axis> parse_ensemble_grid(const std::string& text, const model& scene, bool random)
{
    std::vector<ensemble_axis> axes;
    std::size_t begin = 0;
    for (;;) {
        std::size_t comma = text.find(',', begin);
        std::size_t end = comma == std::string::npos ? text.size() : comma;
        if (skip_blanks(text, begin, end) == end)
            bad_option("--grid", text, begin, "an empty grid entry: give `name=from..to:count`, separated by commas");
        axes.push_back(parse_axis(text, begin, end, scene, random));
        for (std::size_t k = 0; k + 1 < axes.size(); ++k)
            if (axes[k].kind == axes.back().kind && axes[k].index == axes.back().index)
                bad_option("--grid", text, skip_blanks(text, begin, end),
                           "`" + axes.back().name + "` is already in the grid");
        if (comma == std::string::npos)
            break;
        begin = comma + 1;
    }
    return axes;
}

ensemble_measure parse_ensemble_measure(const std::string& text, const model& scene)
{
    ensemble_measure measure;
    std::size_t colon = text.find(':');
    std::string head = text.substr(0, colon);
    const measure_definition* found = nullptr;
    std::vector<std::string> names;
    for (const measure_definition& m : measures()) {
        if (head == m.name)
            found = &m;
        names.push_back(m.name);
        if (m.takes_coordinate)
            names.push_back(std::string(m.name) + ":COORDINATE");
    }
    if (!found) {
        std::string use;
        for (std::size_t k = 0; k < names.size(); ++k)
            use += (k == 0 ? "" : k + 1 == names.size() ? " or " : ", ") + names[k];
        bad_option("--measure", text, 0, "unknown measure `" + head + "`: use " + use);
    }
    measure.what = found->what;
    if (!found->takes_coordinate && colon != std::string::npos)
        bad_option("--measure", text, colon, "`" + head + "` takes no argument");
    if (colon == std::string::npos)
        return measure;
    std::string name = text.substr(colon + 1);
    for (std::size_t k = 0; k < scene.coordinates.size(); ++k)
        if (scene.coordinates[k].name == name) {
            measure.coordinate = k;
            measure.any = false;
            return measure;
        }
    bad_option("--measure", text, colon + 1, "`" + name + "` is not a coordinate of the scene");
}

} // namespace lagrange
