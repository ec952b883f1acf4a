// SPDX-License-Identifier: GPL-2.0-or-later
/** @file ensemble_output.cpp
 *  Ensemble rows as CSV, JSON and a gnuplot map (see ensemble_output.h). */
#include "output/ensemble_output.h"

#include "output/simulation.h"
#include "system/gnuplot.h"
#include "system/external.h"
#include "system/files.h"

#include <nlohmann/json.hpp>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <sstream>

namespace lagrange {

namespace {

void put_number(std::ostream& out, double x)
{
    char buffer[32];
    auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, x);
    out.write(buffer, end - buffer);
}

std::string number_text(double x)
{
    std::ostringstream out;
    put_number(out, x);
    return out.str();
}

std::string short_number(double x)
{
    std::ostringstream out;
    out.precision(3);
    out << x;
    return out.str();
}

} // namespace

void write_ensemble_csv_header(std::ostream& out, const ensemble_problem& problem)
{
    const std::vector<std::string>& columns = problem.columns();
    for (std::size_t k = 0; k < columns.size(); ++k)
        out << (k ? "," : "") << columns[k];
    out << '\n';
}

void write_ensemble_csv_row(std::ostream& out, const ensemble_problem& problem, const double* row)
{
    for (std::size_t k = 0; k < problem.columns().size(); ++k) {
        if (k)
            out << ',';
        put_number(out, row[k]);
    }
    out << '\n';
}

void write_ensemble_json_begin(std::ostream& out, const ensemble_problem& problem)
{
    out << "{\"ensemble\": {\"columns\": " << nlohmann::json(problem.columns()).dump() << ", \"rows\": [";
}

void write_ensemble_json_row(std::ostream& out, const ensemble_problem& problem, std::size_t index, const double* row)
{
    out << (index ? ",\n[" : "\n[");
    for (std::size_t k = 0; k < problem.columns().size(); ++k) {
        if (k)
            out << ", ";
        if (std::isfinite(row[k]))
            put_number(out, row[k]);
        else
            out << "null";
    }
    out << ']';
}

void write_ensemble_json_end(std::ostream& out, const ensemble_problem& problem, const ensemble_summary& summary)
{
    nlohmann::json estimate = {{"sampled", summary.sampled},
                               {"every", problem.sample_every()},
                               {"tolerance", problem.settings().tolerance / 1000}};
    if (summary.sampled > 0) {
        if (std::isfinite(summary.worst_error))
            estimate["worst"] = summary.worst_error;
        else
            estimate["worst"] = nullptr;
        estimate["at"] = summary.worst_error_index;
    }
    out << "\n], \"steps\": " << summary.steps << ", \"failures\": " << summary.failures
        << ", \"error_estimate\": " << estimate.dump() << "}}\n";
}

std::size_t resume_ensemble_csv(const std::string& path, const ensemble_problem& problem)
{
    std::error_code error;
    if (!std::filesystem::exists(path, error) || std::filesystem::file_size(path, error) == 0)
        return 0;
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw file_error("cannot read `" + path + "` to resume from it");
    std::ostringstream header;
    write_ensemble_csv_header(header, problem);
    // Count the complete lines in blocks (constant memory), remembering the last two line ends.
    std::vector<char> block(1 << 16);
    std::uintmax_t offset = 0, last_end = 0, before_last_end = 0, lines = 0;
    std::string first_line;
    bool first_done = false;
    while (in) {
        in.read(block.data(), static_cast<std::streamsize>(block.size()));
        std::streamsize got = in.gcount();
        for (std::streamsize k = 0; k < got; ++k) {
            char c = block[static_cast<std::size_t>(k)];
            if (!first_done) {
                first_line += c;
                if (first_line.size() > header.str().size())
                    throw file_error("`" + path + "` does not start with this ensemble's header (" +
                                     header.str().substr(0, header.str().size() - 1) + "): cannot resume from it");
            }
            if (c == '\n') {
                ++lines;
                before_last_end = last_end;
                last_end = offset + static_cast<std::uintmax_t>(k) + 1;
                first_done = true;
            }
        }
        offset += static_cast<std::uintmax_t>(got);
    }
    if (first_line != header.str())
        throw file_error("`" + path + "` does not start with this ensemble's header (" +
                         header.str().substr(0, header.str().size() - 1) + "): cannot resume from it");
    const std::size_t rows = static_cast<std::size_t>(lines - 1);
    if (rows > problem.points())
        throw file_error("`" + path + "` has more rows than this ensemble has points: cannot resume from it");
    if (rows > 0) {
        // The last complete row must start with the grid values of its point.
        in.clear();
        in.seekg(static_cast<std::streamoff>(before_last_end));
        std::string last(static_cast<std::size_t>(last_end - before_last_end), '\0');
        in.read(last.data(), static_cast<std::streamsize>(last.size()));
        std::vector<double> grid(problem.grid_columns());
        problem.grid_values(rows - 1, grid.data());
        std::string expected;
        for (double v : grid)
            expected += number_text(v) + ",";
        if (last.compare(0, expected.size(), expected) != 0)
            throw file_error("the last row of `" + path + "` is not point " + std::to_string(rows) +
                             " of this grid: cannot resume from it (another grid, or a file edited since)");
    }
    in.close();
    if (last_end < offset)
        std::filesystem::resize_file(path, last_end); // the last line was cut off by the interruption
    return rows;
}

ensemble_map::ensemble_map(const ensemble_problem& problem) : problem_(problem)
{
    if (problem.grid_columns() != 2 || problem.settings().random > 0)
        throw computation_error("a PNG map needs a grid of two entries (this ensemble has " +
                                std::to_string(problem.grid_columns()) +
                                (problem.settings().random > 0 ? " random ranges" : " grid entries") +
                                "): write CSV or JSON instead");
    folder_ = std::make_unique<private_directory>("lagrange-map");
    data_.open(folder_->path() + "/map.dat");
}

ensemble_map::~ensemble_map() = default;

void ensemble_map::row(const double* row)
{
    double x = row[0], y = row[1], value = row[2];
    if (!first_ && x != previous_x_)
        data_ << '\n'; // a new scan line of the image
    first_ = false;
    previous_x_ = x;
    bool drawn = std::isfinite(value) &&
                 (problem_.measure().what != ensemble_measure::kind::flip_time || value > 0);
    put_number(data_, x);
    data_ << ' ';
    put_number(data_, y);
    data_ << ' ';
    if (drawn) {
        put_number(data_, value);
        low_ = any_ ? std::min(low_, value) : value;
        high_ = any_ ? std::max(high_, value) : value;
        any_ = true;
    } else {
        data_ << "NaN";
    }
    data_ << '\n';
}

void ensemble_map::draw(const std::string& path, const std::string& title)
{
    data_.close();
    const bool flips = problem_.measure().what == ensemble_measure::kind::flip_time;
    const std::string measure = problem_.columns()[2];
    const auto& axes = problem_.axes();
    std::ostringstream script;
    script << "set terminal pngcairo size 900,760 font 'sans,12'\n"
              "set output 'plot.png'\n"
              "set xlabel "
           << gnuplot_string(axes[0].name) << " noenhanced\nset ylabel " << gnuplot_string(axes[1].name)
           << " noenhanced\nset cblabel "
           << gnuplot_string(flips ? "time of the first flip (white: no flip before t = " +
                                         short_number(problem_.settings().until) + ")"
                                   : measure)
           << " noenhanced\nset title " << gnuplot_string(title) << " noenhanced\n"
           << "set xrange [" << number_text(axes[0].from) << ":" << number_text(axes[0].to) << "]\n"
           << "set yrange [" << number_text(axes[1].from) << ":" << number_text(axes[1].to) << "]\n"
           << "set size square\nset tics out\nunset key\n"
              "set palette defined (0 '#000004', 1 '#3b0f70', 2 '#8c2981', 3 '#de4968', 4 '#fe9f6d', 5 '#fcfdbf')\n";
    if (axes[0].logarithmic)
        script << "set logscale x\n";
    if (axes[1].logarithmic)
        script << "set logscale y\n";
    if (flips && any_ && low_ > 0) {
        script << "set logscale cb\nset cbrange [" << number_text(low_) << ":"
               << number_text(std::max(high_, low_ * 10)) << "]\n"
               << "set cbtics (0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 2000, "
                  "5000, 10000)\n";
    } else if (any_ && high_ > low_) {
        script << "set cbrange [" << number_text(low_) << ":" << number_text(high_) << "]\n";
    }
    script << "plot 'map.dat' using 1:2:3 with image\n";
    folder_->write("plot.gp", script.str());
    if (!program_available("gnuplot"))
        throw computation_error("gnuplot is not installed (Debian package gnuplot-nox): no map drawn");
    program_result run = run_program({"gnuplot", "plot.gp"}, folder_->path(), "gnuplot.log");
    if (run.exit_code != 0)
        throw computation_error(run.timed_out ? "gnuplot did not finish in time: no map drawn"
                                              : "gnuplot failed to draw the map");
    write_output(path, folder_->read("plot.png"));
}

std::string ensemble_summary_text(const ensemble_problem& problem, const ensemble_summary& summary,
                                  const std::string& first_failure_message)
{
    std::ostringstream out;
    out << "ensemble: " << summary.points << " points on " << summary.threads
        << (summary.threads == 1 ? " thread" : " threads");
    if (summary.threads_asked > summary.threads)
        out << " (of " << summary.threads_asked << " asked: the system refused to start more)";
    if (summary.processes > 1)
        out << " x " << summary.processes << " processes";
    out << " in " << short_number(summary.seconds) << " s";
    if (summary.seconds > 0)
        out << " (" << short_number(static_cast<double>(summary.points) / summary.seconds) << " points/s)";
    out << "; " << summary.steps << " integration steps; evaluation: " << problem.evaluation() << '\n';
    if (summary.sampled > 0)
        out << "ensemble: worst error estimate " << short_number(summary.worst_error)
            << " (the largest change of the measure in a rerun at tolerance "
            << short_number(problem.settings().tolerance / 1000) << ", on " << (problem.sample_every() == 1 ? std::string("every point")
                                                       : "1 point in " + std::to_string(problem.sample_every()))
            << ", " << summary.sampled << " in all; largest at " << problem.point_text(summary.worst_error_index)
            << ")\n";
    if (summary.failures > 0)
        out << "ensemble: " << summary.failures << " points failed (nan in the output); the first, at "
            << problem.point_text(summary.first_failure) << ": " << first_failure_message << '\n';
    return out.str();
}

} // namespace lagrange
