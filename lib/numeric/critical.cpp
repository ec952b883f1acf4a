// SPDX-License-Identifier: GPL-2.0-or-later
/** @file critical.cpp
 *  Crossings of the imaginary axis over a parameter range (see critical.h). */
#include "numeric/critical.h"

#include "core/errors.h"
#include "core/number_text.h"
#include "mechanics/operating_point.h"
#include "numeric/compiled_modes.h"
#include "numeric/point_modes.h"
#include "program/double_double.h"
#include "program/expression_program.h"

#include <Eigen/Eigenvalues>

#include <boost/math/tools/toms748_solve.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>

namespace lagrange {

namespace {

/// Intervals of the grid: enough that the bicycle's crossings, 1.7 m/s apart, lie in
/// different cells many times over; a multiple of 10 so that the table shows 11 points.
constexpr std::size_t grid_intervals = 400;
constexpr std::size_t table_rows = 10;

/// The eigenvalues at one parameter point, and how far below which |Re s| is not told
/// from 0 there.
struct spectrum {
    std::vector<std::complex<double>> eigenvalues;
    double zero = 0;
};

/// The 2n eigenvalues of the point's modes: the damped or gyroscopic ones where the path
/// gave them, else ±iω (±γ for a mode that grows) of the conservative modes.
spectrum spectrum_of(const numeric_modes& modes)
{
    spectrum result;
    double largest = 0, error = 0;
    if (!modes.eigenvalues.empty()) {
        result.eigenvalues = modes.eigenvalues;
        for (std::size_t k = 0; k < modes.eigenvalue_error.size(); ++k)
            error = std::max(error, modes.eigenvalue_error[k]);
    } else {
        for (std::size_t k = 0; k < modes.omega.size(); ++k) {
            const double w = modes.omega[k];
            const std::complex<double> s = w >= 0 ? std::complex<double>(0, w) : std::complex<double>(-w, 0);
            result.eigenvalues.push_back(s);
            result.eigenvalues.push_back(w >= 0 ? std::conj(s) : -s);
        }
    }
    for (std::size_t k = 0; k < modes.error.size() && k < modes.omega.size(); ++k)
        error = std::max(error, modes.error[k] * std::max(std::abs(modes.omega[k]), 1.0));
    for (const std::complex<double>& s : result.eigenvalues)
        largest = std::max(largest, std::abs(s));
    // rounding of an eigenvalue that is 0 identically (a free coordinate) is not a crossing
    result.zero = std::max(error, 1e-12 * (1 + largest));
    return result;
}

/// The real parts, largest first: the k-th is a continuous function of the parameter.
std::vector<double> real_parts(const spectrum& s)
{
    std::vector<double> parts;
    for (const std::complex<double>& e : s.eigenvalues)
        parts.push_back(e.real());
    std::sort(parts.begin(), parts.end(), std::greater<double>());
    return parts;
}

int unstable_count(const spectrum& s)
{
    int count = 0;
    for (const std::complex<double>& e : s.eigenvalues)
        count += e.real() > s.zero ? 1 : 0;
    return count;
}

/// The scene's `critical` request, with the parameter's name and range.
critical_result started(const model& scene)
{
    if (!scene.critical)
        throw computation_error("`critical` needs a range: a line such as `critical v from 0 to 10`");
    critical_result result;
    result.parameter = scene.parameters.at(scene.critical->parameter).name;
    result.from = scene.critical->from;
    result.to = scene.critical->to;
    return result;
}

/// The eigenvalues over the grid of [from, to], and the crossings of each real part
/// through 0 between grid points, refined by TOMS 748 (`at`: the spectrum at a value).
void search(const critical_request& request, const std::function<spectrum(double)>& at, critical_result& result)
{
    std::vector<spectrum> spectra;
    for (std::size_t i = 0; i <= grid_intervals; ++i) {
        // the ends exactly; between them, points that do not drift from the table's
        const double p = i == grid_intervals ? request.to
                                             : request.from + (request.to - request.from) * static_cast<double>(i) /
                                                                  static_cast<double>(grid_intervals);
        result.grid.push_back(p);
        spectra.push_back(at(p));
        result.locus.push_back(spectra.back().eigenvalues);
    }
    result.table_every = grid_intervals / table_rows;

    const std::size_t count = spectra.front().eigenvalues.size();
    std::vector<std::vector<double>> parts;
    for (const spectrum& s : spectra)
        parts.push_back(real_parts(s));
    for (std::size_t k = 0; k < count; ++k) {
        // between the last point where the k-th real part had a sign and the next: a point
        // in between where it is 0 within rounding (a crossing on the grid) is bracketed too
        std::optional<std::size_t> last;
        for (std::size_t i = 0; i < spectra.size(); ++i) {
            if (std::abs(parts[i][k]) <= spectra[i].zero)
                continue;
            const std::size_t before = last.value_or(i);
            last = i;
            if ((parts[before][k] > 0) == (parts[i][k] > 0))
                continue;
            const auto real_part = [&](double p) { return real_parts(at(p))[k]; };
            std::uintmax_t iterations = 200;
            const std::pair<double, double> bracket = boost::math::tools::toms748_solve(
                real_part, result.grid[before], result.grid[i], parts[before][k], parts[i][k],
                boost::math::tools::eps_tolerance<double>(50), iterations);
            critical_crossing crossing;
            crossing.value = (bracket.first + bracket.second) / 2;
            crossing.tolerance = bracket.second - bracket.first;
            // a complex pair crosses as two equal real parts: one crossing
            if (std::any_of(result.crossings.begin(), result.crossings.end(), [&](const critical_crossing& c) {
                    return std::abs(c.value - crossing.value) <= 1e-9 * (1 + std::abs(crossing.value));
                }))
                continue;
            const spectrum there = at(crossing.value);
            crossing.eigenvalue = there.eigenvalues.front();
            for (const std::complex<double>& s : there.eigenvalues)
                if (std::abs(s.real()) < std::abs(crossing.eigenvalue.real()) ||
                    (std::abs(s.real()) == std::abs(crossing.eigenvalue.real()) && s.imag() > crossing.eigenvalue.imag()))
                    crossing.eigenvalue = s;
            crossing.eigenvalue = {crossing.eigenvalue.real(), std::abs(crossing.eigenvalue.imag())};
            crossing.unstable_before = unstable_count(spectra[before]);
            crossing.unstable_after = unstable_count(spectra[i]);
            result.crossings.push_back(crossing);
        }
    }
    std::sort(result.crossings.begin(), result.crossings.end(),
              [](const critical_crossing& x, const critical_crossing& y) { return x.value < y.value; });
}

} // namespace

critical_result critical_parameters(const model& scene, const linearization_result& linear,
                                    const GiNaC::matrix* damping)
{
    critical_result result = started(scene);
    const critical_request& request = *scene.critical;
    point_modes path(scene, linear, damping);
    std::vector<double> values(scene.parameters.size(), std::nan(""));
    std::vector<bool> given(scene.parameters.size(), false);
    if (!scene.values.empty())
        read_value_point(scene, scene.values.front(), values, given);
    for (std::size_t k = 0; k < scene.parameters.size(); ++k) {
        if (k == request.parameter)
            continue;
        if (path.uses(k) && !given[k])
            throw computation_error("`critical` needs a value of parameter `" + scene.parameters[k].name +
                                    "` (a `values` line or --values)");
        if (path.uses(k))
            result.values.emplace_back(scene.parameters[k].name, values[k]);
    }

    numeric_modes modes;
    const auto at = [&](double p) {
        values[request.parameter] = p;
        path.evaluate(values.data(), modes,
                      [&] { return "`" + result.parameter + "` = " + shortest(p) + " in the critical range"; });
        return spectrum_of(modes);
    };

    search(request, at, result);
    return result;
}

critical_result critical_parameters(const model& scene, const GiNaC::matrix& state_matrix)
{
    critical_result result = started(scene);
    const critical_request& request = *scene.critical;
    // Ignorable states give eigenvalues 0 at every value: only the coupled block can cross.
    const std::vector<std::size_t> kept = coupled_states(state_matrix);
    if (kept.empty())
        throw computation_error("`critical`: every eigenvalue of A is 0 at every value of `" + result.parameter +
                                "`, so none crosses the imaginary axis");
    const auto size = static_cast<Eigen::Index>(kept.size());
    std::vector<GiNaC::ex> entries, symbols;
    for (std::size_t i : kept)
        for (std::size_t j : kept)
            entries.push_back(state_matrix(static_cast<unsigned>(i), static_cast<unsigned>(j)));
    for (const parameter& p : scene.parameters)
        symbols.push_back(p.symbol);
    expression_program program;
    try {
        program = expression_program(entries, symbols);
    } catch (const std::invalid_argument& error) {
        throw computation_error(std::string("`critical` needs A in the parameters only (give every coordinate a "
                                            "value in `linearize about`): ") + error.what());
    }
    std::vector<double> values(scene.parameters.size(), std::nan(""));
    std::vector<bool> given(scene.parameters.size(), false);
    if (!scene.values.empty())
        read_value_point(scene, scene.values.front(), values, given);
    const GiNaC::lst all(entries.begin(), entries.end());
    for (std::size_t k = 0; k < scene.parameters.size(); ++k) {
        if (k == request.parameter || !all.has(scene.parameters[k].symbol))
            continue;
        if (!given[k])
            throw computation_error("`critical` needs a value of parameter `" + scene.parameters[k].name +
                                    "` (a `values` line or --values)");
        result.values.emplace_back(scene.parameters[k].name, values[k]);
    }
    // A in double-double, rounded once: its entries are exact rational functions whose
    // terms may cancel; the eigenvalues then come from Eigen.
    std::vector<double_double> scratch, out(entries.size());
    Eigen::MatrixXd a(size, size);
    const auto at = [&](double p) {
        values[request.parameter] = p;
        program.run(values.data(), scratch, out.data());
        for (Eigen::Index i = 0; i < size; ++i)
            for (Eigen::Index j = 0; j < size; ++j) {
                const double entry = out[static_cast<std::size_t>(i * size + j)].hi;
                if (!std::isfinite(entry))
                    throw computation_error("`critical`: an entry of A is not finite at `" + result.parameter +
                                            "` = " + shortest(p) + " in the critical range");
                a(i, j) = entry;
            }
        Eigen::EigenSolver<Eigen::MatrixXd> solver(a, false);
        if (solver.info() != Eigen::Success)
            throw computation_error("`critical`: the eigenvalues of A did not converge at `" + result.parameter +
                                    "` = " + shortest(p));
        spectrum s;
        double largest = 0;
        for (Eigen::Index k = 0; k < size; ++k) {
            s.eigenvalues.push_back(solver.eigenvalues()(k));
            largest = std::max(largest, std::abs(s.eigenvalues.back()));
        }
        std::sort(s.eigenvalues.begin(), s.eigenvalues.end(), [](const auto& x, const auto& y) {
            return x.imag() != y.imag() ? x.imag() < y.imag() : x.real() < y.real();
        });
        s.zero = 1e-12 * (1 + largest);
        return s;
    };
    search(request, at, result);
    return result;
}

} // namespace lagrange
