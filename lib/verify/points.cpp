// SPDX-License-Identifier: GPL-2.0-or-later
/** @file points.cpp
 *  The parameter points and helpers of the self-verification (see points.h). */
#include "verify/points.h"

#include "core/errors.h"
#include "numeric/values.h"

#include <cmath>

namespace lagrange::verification_points {

using GiNaC::ex;

std::vector<parameter_point> parameter_points(const model& scene)
{
    sampler random;
    std::vector<parameter_point> points;
    for (int attempt = 0; attempt < attempts; ++attempt) {
        GiNaC::exmap given;
        if (attempt < static_cast<int>(scene.values.size()))
            given = value_map(scene, scene.values[static_cast<std::size_t>(attempt)]);
        parameter_point p;
        for (const parameter& parameter : scene.parameters) {
            double x = random.uniform(0.5, 2);
            auto found = given.find(parameter.symbol);
            if (found != given.end()) {
                ex v = found->second.evalf();
                if (GiNaC::is_a<GiNaC::numeric>(v) && GiNaC::ex_to<GiNaC::numeric>(v).is_real())
                    x = GiNaC::ex_to<GiNaC::numeric>(v).to_double();
            }
            p.values.push_back(x);
            p.map[parameter.symbol] = GiNaC::numeric(x);
            p.text += (p.text.empty() ? "" : ", ") + parameter.name + " = " + message_number(x);
        }
        points.push_back(std::move(p));
    }
    return points;
}

std::optional<Eigen::MatrixXd> matrix_at(const GiNaC::matrix& m, const GiNaC::exmap& at)
{
    Eigen::MatrixXd result(m.rows(), m.cols());
    for (unsigned i = 0; i < m.rows(); ++i)
        for (unsigned j = 0; j < m.cols(); ++j) {
            std::optional<double> x = real_at(m(i, j), at);
            if (!x)
                return std::nullopt;
            result(i, j) = *x;
        }
    return result;
}

[[noreturn]] void not_real(const std::string& product, const std::string& what, const std::string& where)
{
    throw computation_error("verification failed: " + product + ": " + what + " is not a real number at " + where +
                            "; the result is not printed");
}

[[noreturn]] void fail(const std::string& product, const std::string& what, const std::string& where, double here,
                       double reference)
{
    throw computation_error("verification failed: " + product + ": " + what + " at " + where + " is " +
                            message_number(here, 10) + ", but " + message_number(reference, 10) +
                            " by the independent check; the result is not printed");
}

bool close(double a, double b, double scale) { return std::abs(a - b) <= tolerance * scale; }


std::string at_point(const parameter_point& p) { return p.text.empty() ? "the check" : p.text; }

} // namespace lagrange::verification_points
