// SPDX-License-Identifier: GPL-2.0-or-later
/** @file points.h
 *  What the self-verification files share (internal to lib/verify): the seeded parameter
 *  points, results evaluated there, the tolerance and the failure messages, and the check
 *  of the small-oscillation results (check_modes.cpp). */
#pragma once

#include "core/model.h"
#include "mechanics/linearization.h"
#include "mechanics/modes.h"
#include "verify/verify.h"

#include <Eigen/Dense>
#include <ginac/ginac.h>

#include <complex>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace lagrange::verification_points {

/// Agreement asked of a symbolic result and its reference, relative to the size of the
/// terms compared: the references reach about 1e-14 (fourth-order differences in
/// double-double with step 2⁻¹²), so a real disagreement is many orders above this.
constexpr double tolerance = 1e-7;
/// Parameter points tried per check, and how many must be usable.
constexpr int attempts = 10;
constexpr int points_wanted = 2;

/// SplitMix64: the same sequence on every platform and standard library, so that the
/// points, and so every message, are the same on every run.
class sampler {
public:
    std::uint64_t next()
    {
        std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }
    /// A multiple of 1/64 in [lo, hi]: exact in double.
    double uniform(double lo, double hi) { return lo + (hi - lo) * static_cast<double>(next() % 65) / 64; }

private:
    std::uint64_t state_ = 0x6c616772616e6765ULL; // "lagrange"
};

/// Parameter values: a `values` line's, else seeded ones in [1/2, 2].
struct parameter_point {
    std::vector<double> values; ///< in scene.parameters order
    GiNaC::exmap map;           ///< the same values, exactly, for GiNaC
    std::string text;           ///< "a = 1.25, g = 0.75"
};

/// The parameter points of the checks: the `values` lines' first, then seeded ones.
std::vector<parameter_point> parameter_points(const model& scene);

/// m at the parameter point; nothing if an entry is not real.
std::optional<Eigen::MatrixXd> matrix_at(const GiNaC::matrix& m, const GiNaC::exmap& at);

/// Throws computation_error: `what` of `product` is not real at `where`.
[[noreturn]] void not_real(const std::string& product, const std::string& what, const std::string& where);

/// Throws computation_error: `what` of `product` is `here` at `where`, but `reference` by the check.
[[noreturn]] void fail(const std::string& product, const std::string& what, const std::string& where, double here,
                       double reference);

/// Whether a and b agree to the tolerance, relative to `scale`.
bool close(double a, double b, double scale);

/// How a point is named in a message: its values, or "the check" when it has none.
std::string at_point(const parameter_point& p);

/// The results of the small oscillations to check: the characteristic polynomial, the
/// frequencies, the modes and the normal coordinates (each may be absent).
struct oscillation_results {
    const linearization_result& linear;
    const characteristic_result* characteristic = nullptr;
    const modes_result* modes = nullptr;
};

/// Checks them against the pencil (V, T) (and G) at the usable points among `points`;
/// adds an entry for each checked product in `shown`, throws on a disagreement.
void check_oscillations(const model& scene, const std::vector<parameter_point>& points,
                        const oscillation_results& results, const std::set<product>& shown,
                        std::vector<verification_entry>& entries);

} // namespace lagrange::verification_points
