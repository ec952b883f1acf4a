// SPDX-License-Identifier: GPL-2.0-or-later
/** @file sweep_output.cpp
 *  Streamed sweep output (see sweep_output.h). Numbers are the shortest decimals
 *  that read back as the same double, so the output is byte-identical across runs. */
#include "output/sweep_output.h"

#include "core/number_text.h"

#include <nlohmann/json.hpp>

#include <charconv>

namespace lagrange {

namespace {

void put_number(std::ostream& out, double x) { out << shortest(x); }

} // namespace

void write_sweep(std::ostream& out, const model& scene, point_modes& path, const std::vector<sweep_axis>& axes,
                 const std::string& format)
{
    const std::size_t n = path.size();
    const bool json = format == "json";
    if (json) {
        nlohmann::json names = nlohmann::json::array(), columns = nlohmann::json::array();
        for (const sweep_axis& a : axes) {
            names.push_back(a.name);
            columns.push_back(a.name);
        }
        for (std::size_t k = 1; k <= n; ++k)
            columns.push_back("omega" + std::to_string(k));
        for (std::size_t k = 1; k <= n; ++k)
            columns.push_back("error" + std::to_string(k));
        columns.push_back("stability");
        out << "{\"sweep\": {\"parameters\": " << names.dump() << ", \"columns\": " << columns.dump()
            << ", \"points\": [";
    } else {
        out << "#";
        for (const sweep_axis& a : axes)
            out << ' ' << a.name;
        for (std::size_t k = 1; k <= n; ++k)
            out << " omega" << k;
        for (std::size_t k = 1; k <= n; ++k)
            out << " error" << k;
        out << " stability\n";
    }
    sweep_numeric_modes(scene, path, axes, [&](const sweep_row& row) {
        if (json)
            out << (row.index ? ",\n" : "\n") << '[';
        bool first = true;
        auto cell = [&](double x) {
            if (!first)
                out << (json ? ", " : " ");
            first = false;
            put_number(out, x);
        };
        for (const sweep_axis& a : axes)
            cell(row.parameter_values[a.parameter]);
        for (std::size_t k = 0; k < n; ++k)
            cell(row.modes->omega[k]);
        for (std::size_t k = 0; k < n; ++k)
            cell(row.modes->error[k]);
        out << (json ? ", \"" + row.stability + "\"]" : " " + row.stability + "\n");
    });
    if (json)
        out << "\n]}}\n";
}

} // namespace lagrange
