// SPDX-License-Identifier: GPL-2.0-or-later
/** @file response_output.cpp
 *  Writers of the frequency response. */
#include "output/response_output.h"
#include "output/format.h"

#include "core/number_text.h"

#include "output/print.h"
#include "output/simulation.h"
#include "system/gnuplot.h"

#include <nlohmann/json.hpp>

#include <charconv>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace lagrange {

namespace {

std::string values_line(const frequency_response& r)
{
    std::string out;
    for (const auto& [name, value] : r.values)
        out += (out.empty() ? "" : " ") + print_name(name, syntax::text) + " = " + round_trip(value);
    return out;
}

} // namespace

void write_response_text(std::ostream& out, const frequency_response& r)
{
    out << "Frequency response H(iω) of " << print_name(r.output, syntax::text) << " to "
        << print_name(r.input, syntax::text) << "\n  at " << values_line(r) << "\n  " << r.omega.size()
        << " frequencies from " << round_trip(r.omega.front()) << " to " << round_trip(r.omega.back()) << "\n";
    if (std::isnan(r.peak_omega))
        out << "  no resonance peak inside the range\n";
    else
        out << "  peak |H| = " << round_trip(r.peak_magnitude) << " at ω = " << round_trip(r.peak_omega) << "\n";
    out << "\n  ω  |H|  |H| (dB)  phase (°)\n";
    for (std::size_t k = 0; k < r.omega.size(); ++k)
        out << "  " << round_trip(r.omega[k]) << "  " << round_trip(r.magnitude[k]) << "  " << round_trip(r.magnitude_db[k])
            << "  " << round_trip(r.phase_degrees[k]) << "\n";
}

void write_response_csv(std::ostream& out, const frequency_response& r)
{
    out << "omega,magnitude,magnitude_db,phase_degrees,real,imag\n";
    for (std::size_t k = 0; k < r.omega.size(); ++k)
        out << round_trip(r.omega[k]) << ',' << round_trip(r.magnitude[k]) << ',' << round_trip(r.magnitude_db[k]) << ','
            << round_trip(r.phase_degrees[k]) << ',' << round_trip(r.gain[k].real()) << ','
            << round_trip(r.gain[k].imag()) << '\n';
}

void write_response_json(std::ostream& out, const frequency_response& r)
{
    nlohmann::ordered_json doc;
    doc["input"] = r.input;
    doc["output"] = r.output;
    nlohmann::ordered_json values = values_json(r.values);
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
        data << round_trip(r.omega[k]) << ' ' << round_trip(r.magnitude[k]) << ' ' << round_trip(r.phase_degrees[k]) << '\n';
    const std::string name = print_name(r.input, syntax::text) + " → " + print_name(r.output, syntax::text);
    std::ostringstream script;
    script << "set multiplot layout 2,1 title "
           << gnuplot_string(title + ": Bode diagram of " + name) << " noenhanced\n"
           << "set logscale x\nset autoscale xfix\nset grid\nunset key\nset format x '%g'\n"
              "set lmargin 12\n" // the same left margin in both panels, so that their ω axes line up
              "set logscale y\nset ylabel '|H(iω)|'\n";
    // The resonance peak, marked where the search found one inside the range.
    const bool peak = std::isfinite(r.peak_omega) && std::isfinite(r.peak_magnitude) && r.peak_magnitude > 0;
    if (peak) {
        script << "set label 1 " << gnuplot_string("resonance ω_r = " + significant(r.peak_omega, 6)) << " at "
               << round_trip(r.peak_omega) << ", " << round_trip(r.peak_magnitude)
               << " offset 1.5,0.6 noenhanced\n";
    }
    script << "plot 'data.txt' using 1:2 with lines lw 1.5";
    if (peak)
        script << ", '-' using 1:2 with points pt 7 ps 0.8\n"
               << round_trip(r.peak_omega) << ' ' << round_trip(r.peak_magnitude) << "\ne";
    script << "\nunset label 1\nunset logscale y\nset ylabel 'phase (degrees)'\nset xlabel 'ω'\n"
              "plot 'data.txt' using 1:3 with lines lw 1.5\n"
              "unset multiplot\n";
    draw_gnuplot(path, "", 900, 640, "", script.str(), {{"data.txt", data.str()}});
}

} // namespace lagrange
