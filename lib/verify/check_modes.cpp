// SPDX-License-Identifier: GPL-2.0-or-later
/** @file check_modes.cpp
 *  The small-oscillation results against the pencil (V, T) evaluated at parameter
 *  points: the characteristic polynomial against det(V − ω²T) (LU), the frequencies
 *  against the eigenvalues (Eigen's generalized self-adjoint solver, or the quadratic
 *  eigenproblem with G), the modes by their residual, the normal coordinates by
 *  C T⁻¹ Cᵀ = I and Aᵀ V A = diag(ω²). */
#include "verify/points.h"

#include "core/errors.h"
#include "numeric/quadratic_modes.h"
#include "numeric/values.h"

#include <algorithm>
#include <cmath>

namespace lagrange::verification_points {

namespace {

using GiNaC::ex;

/// The parameter points where T and V are real, with them as numbers.
struct numeric_pencil {
    const parameter_point* point;
    Eigen::MatrixXd kinetic, potential;
    Eigen::MatrixXd gyroscopic; ///< zero without a part of L linear in the velocities
};

std::vector<numeric_pencil> pencils(const std::vector<parameter_point>& points, const linearization_result& linear)
{
    std::vector<numeric_pencil> result;
    for (const parameter_point& p : points) {
        std::optional<Eigen::MatrixXd> kinetic = matrix_at(linear.kinetic, p.map);
        std::optional<Eigen::MatrixXd> potential = matrix_at(linear.potential, p.map);
        if (!kinetic || !potential || kinetic->ldlt().info() != Eigen::Success ||
            kinetic->llt().info() != Eigen::Success)
            continue;
        Eigen::MatrixXd gyroscopic = Eigen::MatrixXd::Zero(kinetic->rows(), kinetic->cols());
        if (linear.has_gyroscopic()) {
            std::optional<Eigen::MatrixXd> g = matrix_at(linear.gyroscopic, p.map);
            if (!g)
                continue;
            gyroscopic = *g;
        }
        result.push_back({&p, *kinetic, *potential, gyroscopic});
        if (result.size() == points_wanted)
            break;
    }
    return result;
}

verification_entry check_characteristic(const model& scene, const linearization_result& linear,
                                        const characteristic_result& characteristic,
                                        const std::vector<numeric_pencil>& pencils)
{
    (void)scene;
    const std::size_t n = linear.kinetic.rows(); // with constraints: the independent coordinates
    const ex& p = characteristic.polynomial;
    if (!p.is_polynomial(characteristic.omega) || p.degree(characteristic.omega) != static_cast<int>(2 * n))
        throw computation_error("verification failed: the characteristic polynomial is not of degree " +
                                std::to_string(2 * n) + " in " + characteristic.omega.get_name());
    for (const numeric_pencil& pencil : pencils) {
        // p(ω)/det(V − ω²T) is the same at every ω (the factor removed to make p primitive).
        std::optional<double> ratio;
        int compared = 0;
        for (int k = 0; compared < static_cast<int>(n) + 2 && k < 4 * static_cast<int>(n) + 8; ++k) {
            const double omega = 0.375 + 0.25 * k;
            const double w = omega * omega;
            Eigen::MatrixXcd pencil_at = (pencil.potential - w * pencil.kinetic).cast<std::complex<double>>() +
                                         std::complex<double>(0, omega) * pencil.gyroscopic.cast<std::complex<double>>();
            const double det = pencil_at.partialPivLu().determinant().real();
            const double size = std::pow(
                pencil.potential.norm() + w * pencil.kinetic.norm() + omega * pencil.gyroscopic.norm(),
                static_cast<double>(n));
            if (std::abs(det) < 1e-6 * size)
                continue; // too near a root for the ratio to be well conditioned
            GiNaC::exmap at = pencil.point->map;
            at[characteristic.omega] = GiNaC::numeric(omega);
            std::optional<double> value = real_at(p, at);
            if (!value)
                break;
            const double r = *value / det;
            if (!ratio) {
                ratio = r;
                if (r == 0 || !std::isfinite(r))
                    break;
            } else if (!close(r, *ratio, std::abs(*ratio))) {
                fail("the characteristic polynomial",
                     std::string(linear.has_gyroscopic() ? "p(ω)/det(V − ω²T + iωG)" : "p(ω)/det(V − ω²T)") +
                         " at ω = " + message_number(omega),
                     at_point(*pencil.point), r, *ratio);
            }
            ++compared;
        }
    }
    if (pencils.empty())
        return {"characteristic", "not checked: T and V are not real at any parameter point tried", false};
    return {"characteristic", std::string(linear.has_gyroscopic() ? "against det(V − ω²T + iωG)" : "against det(V − ω²T)") +
                                  " (LU) at " + std::to_string(n + 2) +
                                  " frequencies and " + std::to_string(pencils.size()) + " parameter points",
            true};
}

/// The frequencies ω of a gyroscopic linearization: their squares (complex where the point
/// is unstable) against −s² of the eigenvalues s of (s²T − sG + V)x = 0 in the upper half
/// plane (numeric/quadratic_modes.h), matched as multisets.
void check_gyroscopic_frequencies(const model& scene, const modes_result& modes,
                                  const std::vector<numeric_pencil>& pencils, const std::set<product>& shown,
                                  std::vector<verification_entry>& entries)
{
    const std::size_t n = scene.coordinates.size();
    for (const numeric_pencil& pencil : pencils) {
        const parameter_point& p = *pencil.point;
        quadratic_modes q = solve_quadratic_modes(pencil.kinetic, -pencil.gyroscopic, pencil.potential);
        std::vector<std::complex<double>> reference;
        double scale = 1e-300;
        for (std::size_t k = n; k < 2 * n; ++k) {
            reference.push_back(-q.eigenvalues[k] * q.eigenvalues[k]);
            scale = std::max(scale, std::abs(reference.back()));
        }
        if (modes.frequencies.size() != n)
            throw computation_error("verification failed: the frequencies: " +
                                    std::to_string(modes.frequencies.size()) + " listed for " + std::to_string(n) +
                                    " coordinates");
        std::vector<bool> used(n, false);
        for (std::size_t k = 0; k < n; ++k) {
            std::optional<std::complex<double>> omega = complex_at(modes.frequencies[k], p.map);
            if (!omega)
                not_real("the frequencies", "an ω", at_point(p));
            const std::complex<double> w = *omega * *omega;
            std::size_t best = n;
            for (std::size_t j = 0; j < n; ++j)
                if (!used[j] && (best == n || std::abs(reference[j] - w) < std::abs(reference[best] - w)))
                    best = j;
            if (std::abs(reference[best] - w) > tolerance * scale)
                fail("the frequencies", "ω² of frequency " + std::to_string(k + 1), at_point(p), w.real(),
                     reference[best].real());
            used[best] = true;
        }
    }
    if (!pencils.empty() && shown.count(product::frequencies))
        entries.push_back({"frequencies", "ω² against −s² of the quadratic eigenproblem (s²T − sG + V)x = 0 at " +
                                              std::to_string(pencils.size()) + " parameter points",
                           true});
}

void check_modes(const model& scene, const modes_result& modes, const std::vector<numeric_pencil>& pencils,
                 const std::set<product>& shown, std::vector<verification_entry>& entries)
{
    const std::size_t n = modes.displacements.size(); // with constraints: the independent coordinates
    if (!modes.closed_form)
        return;
    if (modes.gyroscopic) {
        check_gyroscopic_frequencies(scene, modes, pencils, shown, entries);
        return;
    }
    for (const numeric_pencil& pencil : pencils) {
        const parameter_point& p = *pencil.point;
        Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(pencil.potential, pencil.kinetic);
        if (solver.info() != Eigen::Success)
            continue;
        std::vector<double> eigenvalues(solver.eigenvalues().data(), solver.eigenvalues().data() + n);
        const double scale = std::max(std::abs(eigenvalues.front()), std::abs(eigenvalues.back())) + 1e-300;
        std::vector<double> frequencies;
        for (const ex& f : modes.frequencies) {
            std::optional<double> value = real_at(f, p.map);
            if (!value)
                not_real("the frequencies", "an ω²", at_point(p));
            frequencies.push_back(*value);
        }
        std::vector<double> sorted = frequencies;
        std::sort(sorted.begin(), sorted.end());
        if (sorted.size() != eigenvalues.size())
            throw computation_error("verification failed: the frequencies: " + std::to_string(sorted.size()) +
                                    " listed for " + std::to_string(n) + " coordinates");
        for (std::size_t k = 0; k < n; ++k)
            if (!close(sorted[k], eigenvalues[k], scale))
                fail("the frequencies", "ω² number " + std::to_string(k + 1) + " in ascending order", at_point(p),
                     sorted[k], eigenvalues[k]);
        const double pencil_size = pencil.potential.norm() + pencil.kinetic.norm() * scale;
        for (std::size_t k = 0; k < modes.modes.size() && k < n; ++k) {
            Eigen::VectorXd a(static_cast<Eigen::Index>(n));
            for (std::size_t i = 0; i < n; ++i) {
                std::optional<double> x = real_at(modes.modes[k][i], p.map);
                if (!x)
                    not_real("the modes", "a component of mode " + std::to_string(k + 1), at_point(p));
                a[static_cast<Eigen::Index>(i)] = *x;
            }
            const double residual =
                ((pencil.potential - frequencies[k] * pencil.kinetic) * a).norm();
            if (a.norm() == 0 || residual > tolerance * pencil_size * a.norm())
                fail("the modes", "|(V − ω²T) a| for mode " + std::to_string(k + 1), at_point(p), residual, 0);
        }
        if (modes.normal_coordinates.size() == n) {
            // ζ = C (q − q₀) with C = Aᵀ T and Aᵀ T A = I, so C T⁻¹ Cᵀ = I and
            // Aᵀ V A = diag(ω²), with A = T⁻¹ Cᵀ.
            Eigen::MatrixXd rows(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
            for (std::size_t k = 0; k < n; ++k)
                for (std::size_t j = 0; j < n; ++j) {
                    // The coordinate of displacement j (with constraints: the j-th independent one).
                    GiNaC::ex q = scene.coordinates[j].position;
                    for (const coordinate& c : scene.coordinates)
                        if (modes.displacements[j].has(c.position))
                            q = c.position;
                    std::optional<double> x =
                        real_at(modes.normal_coordinates[k].diff(GiNaC::ex_to<GiNaC::symbol>(q)), p.map);
                    if (!x)
                        not_real("the normal coordinates", "a coefficient of ζ" + std::to_string(k + 1), at_point(p));
                    rows(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(j)) = *x;
                }
            const Eigen::MatrixXd a = pencil.kinetic.ldlt().solve(rows.transpose());
            const Eigen::MatrixXd unit = rows * a;
            const Eigen::MatrixXd diagonal = a.transpose() * pencil.potential * a;
            for (std::size_t k = 0; k < n; ++k)
                for (std::size_t j = 0; j < n; ++j) {
                    const auto r = static_cast<Eigen::Index>(k), s = static_cast<Eigen::Index>(j);
                    const double expected_unit = k == j ? 1 : 0;
                    const double expected_diagonal = k == j ? frequencies[k] : 0;
                    if (!close(unit(r, s), expected_unit, 1))
                        fail("the normal coordinates", "(C T⁻¹ Cᵀ)" + std::to_string(k + 1) + std::to_string(j + 1),
                             at_point(p), unit(r, s), expected_unit);
                    if (!close(diagonal(r, s), expected_diagonal, scale))
                        fail("the normal coordinates", "(Aᵀ V A)" + std::to_string(k + 1) + std::to_string(j + 1),
                             at_point(p), diagonal(r, s), expected_diagonal);
                }
        }
    }
    const std::string points = " at " + std::to_string(pencils.size()) + " parameter points";
    if (pencils.empty())
        return;
    if (shown.count(product::frequencies))
        entries.push_back({"frequencies", "against the eigenvalues of the pencil (V, T) (Eigen)" + points, true});
    if (shown.count(product::modes))
        entries.push_back({"modes", "(V − ω²T) a = 0" + points, true});
    if (shown.count(product::normal_coordinates) && modes.normal_coordinates.size() == n)
        entries.push_back({"normal_coordinates", "C T⁻¹ Cᵀ = I and Aᵀ V A = diag(ω²)" + points, true});
}

} // namespace

void check_oscillations(const model& scene, const std::vector<parameter_point>& points,
                        const oscillation_results& results, const std::set<product>& shown,
                        std::vector<verification_entry>& entries)
{
    const std::vector<numeric_pencil> numeric = pencils(points, results.linear);
    if (results.characteristic)
        entries.push_back(check_characteristic(scene, results.linear, *results.characteristic, numeric));
    if (results.modes)
        check_modes(scene, *results.modes, numeric, shown, entries);
}

} // namespace lagrange::verification_points
