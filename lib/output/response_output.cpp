/** @file response_output.cpp
 *  Writers of the frequency response. */
#include "output/response_output.h"

#include "output/print.h"
#include "output/simulation_output.h"

#include <nlohmann/json.hpp>

#include <charconv>
#include <cmath>
#include <sstream>

namespace lagrange {

namespace {

/// The shortest decimal that reads back as the same double.
std::string shortest(double x)
{
    if (x == 0)
        x = 0; // no −0
    char buffer[64];
    auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, x);
    return error == std::errc() ? std::string(buffer, end) : std::string("?");
}

std::string values_line(const frequency_response& r)
{
    std::string out;
    for (const auto& [name, value] : r.values)
        out += (out.empty() ? "" : " ") + print_name(name, syntax::text) + " = " + shortest(value);
    return out;
}

} // namespace

void write_response_text(std::ostream& out, const frequency_response& r)
{
    out << "Frequency response H(iω) of " << print_name(r.output, syntax::text) << " to "
        << print_name(r.input, syntax::text) << "\n  at " << values_line(r) << "\n  " << r.omega.size()
        << " frequencies from " << shortest(r.omega.front()) << " to " << shortest(r.omega.back()) << "\n";
    if (std::isnan(r.peak_omega))
        out << "  no resonance peak inside the range\n";
    else
        out << "  peak |H| = " << shortest(r.peak_magnitude) << " at ω = " << shortest(r.peak_omega) << "\n";
    out << "\n  ω  |H|  |H| (dB)  phase (°)\n";
    for (std::size_t k = 0; k < r.omega.size(); ++k)
        out << "  " << shortest(r.omega[k]) << "  " << shortest(r.magnitude[k]) << "  " << shortest(r.magnitude_db[k])
            << "  " << shortest(r.phase_degrees[k]) << "\n";
}

void write_response_csv(std::ostream& out, const frequency_response& r)
{
    out << "omega,magnitude,magnitude_db,phase_degrees,real,imag\n";
    for (std::size_t k = 0; k < r.omega.size(); ++k)
        out << shortest(r.omega[k]) << ',' << shortest(r.magnitude[k]) << ',' << shortest(r.magnitude_db[k]) << ','
            << shortest(r.phase_degrees[k]) << ',' << shortest(r.gain[k].real()) << ','
            << shortest(r.gain[k].imag()) << '\n';
}

void write_response_json(std::ostream& out, const frequency_response& r)
{
    nlohmann::ordered_json doc;
    doc["input"] = r.input;
    doc["output"] = r.output;
    nlohmann::ordered_json values = nlohmann::ordered_json::object();
    for (const auto& [name, value] : r.values)
        values[name] = value;
    doc["values"] = values;
    if (std::isnan(r.peak_omega))
        doc["peak"] = nullptr;
    else
        doc["peak"] = {{"omega", r.peak_omega}, {"magnitude", r.peak_magnitude}};
    doc["omega"] = r.omega;
    doc["magnitude"] = r.magnitude;
    doc["magnitude_db"] = r.magnitude_db;
    doc["phase_degrees"] = r.phase_degrees;
    nlohmann::ordered_json gain = nlohmann::ordered_json::array();
    for (const std::complex<double>& h : r.gain)
        gain.push_back({h.real(), h.imag()});
    doc["gain"] = gain;
    out << doc.dump(2) << '\n';
}

void plot_response(const std::string& path, const frequency_response& r, const std::string& title)
{
    std::ostringstream data;
    for (std::size_t k = 0; k < r.omega.size(); ++k)
        data << shortest(r.omega[k]) << ' ' << shortest(r.magnitude[k]) << ' ' << shortest(r.phase_degrees[k]) << '\n';
    const std::string name = print_name(r.input, syntax::text) + " → " + print_name(r.output, syntax::text);
    std::ostringstream script;
    script << "set terminal svg size 900,640 dynamic font 'sans,12'\n"
              "set output 'plot.svg'\n"
              "set multiplot layout 2,1 title "
           << gnuplot_quoted(title + ": Bode diagram of " + name) << " noenhanced\n"
           << "set logscale x\nset autoscale xfix\nset grid\nunset key\nset format x '%g'\n"
              "set logscale y\nset ylabel '|H(iω)|'\n"
              "plot 'data.txt' using 1:2 with lines lw 1.5\n"
              "unset logscale y\nset ylabel 'phase (degrees)'\nset xlabel 'ω'\n"
              "plot 'data.txt' using 1:3 with lines lw 1.5\n"
              "unset multiplot\n";
    draw_gnuplot_svg(path, script.str(), {{"data.txt", data.str()}});
}

} // namespace lagrange
