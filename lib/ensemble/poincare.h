// SPDX-License-Identifier: GPL-2.0-or-later
/** @file poincare.h
 *  Poincaré sections (`lagrange poincare SCENE --section "phi = 0, phi' > 0" --energy E`):
 *  orbits of a conservative scene with two or more degrees of freedom, started on the section
 *  at the energy E (seeded, uniformly in the free coordinates and velocities over the part of
 *  the section the energy reaches), each integrated by DOP853 (numeric/dop853.h) and cut by
 *  the section. Each crossing is the root of q − level on the step's 7th-order dense output
 *  (TOMS 748, to the rounding of t), so a point is as accurate as the integration, not as a
 *  line through two steps. The orbits run on threads as ensembles do (run.h's start_threads),
 *  each on its own, and are written in orbit order, so the result is the same for any number
 *  of threads. With n coordinates the section has 2n − 2 dimensions; every crossing carries
 *  all of them, and `--axes` picks the two a picture shows. */
#pragma once

#include "mechanics/equations_of_motion.h"
#include "mechanics/equilibrium.h"
#include "core/model.h"

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace lagrange {

/// `--section "q = level[, q' > 0 | q' < 0]"`: where the section lies, and which way
/// through it counts (0: both ways).
struct poincare_section {
    std::size_t coordinate = 0;
    double level = 0;
    int direction = 0;
    std::string text; ///< as written, for messages
};

/// Parses `--section`; throws scene_error located in the pseudo-file `--section` (a caret
/// under the column) for an unknown coordinate, a level that is not a number, a velocity
/// condition on another coordinate, or anything else it cannot read.
poincare_section parse_poincare_section(const std::string& text, const model& scene);

/// The two quantities a picture of the section shows, as columns of a crossing's numbers
/// (t, q1 … qn, q̇1 … q̇n): 1 + c for coordinate c, 1 + n + c for its velocity.
struct poincare_axes {
    std::size_t horizontal = 0, vertical = 0;
};

/// `--axes "y, y'"` (or `y_dot`): two of the section's quantities, neither the section's own
/// coordinate (its level on every crossing). Throws scene_error located in the pseudo-file
/// `--axes` for an unknown name or the section's coordinate.
poincare_axes parse_poincare_axes(const std::string& text, const model& scene, const poincare_section& section);

/// The picture's default: the first coordinate other than the section's, against its velocity.
poincare_axes default_poincare_axes(const model& scene, const poincare_section& section);

struct poincare_settings {
    double energy = 0;            ///< the energy function h = Σ q̇ ∂L/∂q̇ − L of every orbit
    std::size_t orbits = 50;      ///< orbits, each started on the section
    std::size_t crossings = 100;  ///< crossings per orbit (the start counts), at most
    double until = 1000;          ///< and at most this long per orbit
    double tolerance = 1e-9;      ///< target of the relative error (per step ÷12, as simulate)
    std::uint64_t seed = 1;       ///< orbit k's start depends on the seed and k only
    std::size_t threads = 0;      ///< 0: the machine's hardware threads
    bool native = true;           ///< compile the equations to machine code (else interpret)
    std::size_t max_steps = 10'000'000; ///< per orbit; past it the orbit stops as failed
};

/// What cannot be asked (exit 2 in the CLI): an energy below the minimum of the energy.
struct poincare_request_error : std::invalid_argument {
    using std::invalid_argument::invalid_argument;
};

/// One orbit: its crossings, each `t, q1 … qn, q̇1 … q̇n` (angles reduced to within π of
/// the level and of the equilibrium), in time order.
struct poincare_orbit {
    std::vector<double> points;
    std::size_t steps = 0;
    std::string failure; ///< why the orbit stopped early ("" if it did not)
};

struct poincare_result {
    std::vector<std::string> coordinates; ///< the scene's, in order
    poincare_section section;
    poincare_axes axes;          ///< what the picture shows (default_poincare_axes unless chosen)
    double energy = 0;
    double minimum = 0;          ///< the energy's minimum (at a stable equilibrium), if known
    bool has_minimum = false;
    double energy_scale = 1;     ///< energy errors are relative to this: E − minimum, or max(|E|, 1)
    std::vector<poincare_orbit> orbits;
    /// Non-empty when no orbit can cross: why (the section lies outside the energy surface).
    std::string no_crossings;
    double worst_energy_error = 0; ///< max |h − E| / energy_scale over the crossings
    std::string evaluation;        ///< "native code" or why the interpreter runs
    /// Draws (more than two coordinates) where the velocity ellipsoid's volume passed the
    /// bound sampled on a grid: the starts there are drawn too rarely. 0 when the bound held.
    std::size_t overweight_starts = 0;
    std::size_t threads = 1;
    double seconds = 0;
    std::size_t crossings() const;
    std::size_t steps() const;
    std::size_t failures() const;
    std::size_t width() const { return 1 + 2 * coordinates.size(); } ///< numbers per crossing
};

/// The section at `settings.energy`. `equilibria` (the `equilibrium` stage's, may be null)
/// gives the minimum of the energy and the centre of the well the orbits start in. Throws
/// poincare_request_error for an energy below that minimum, computation_error for a scene
/// that has no conserved energy, constraints, or fewer than two coordinates.
poincare_result compute_poincare(const model& scene, const equations_of_motion& equations,
                                 const equilibria_result* equilibria, const poincare_section& section,
                                 const poincare_settings& settings);

} // namespace lagrange
