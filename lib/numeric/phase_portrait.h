// SPDX-License-Identifier: GPL-2.0-or-later
/** @file phase_portrait.h
 *  The phase portrait of one coordinate (`lagrange phase SCENE [--coordinate q]`): the
 *  energy function h(q, q̇) on a grid of the plane (q, q̇), the other coordinates held at
 *  the well's equilibrium and at rest, with the energies whose level curves are the orbits:
 *  a grid of energies from the minimum up, and the energies of the unstable equilibria,
 *  whose level curves are the separatrices. For one degree of freedom the level curves are
 *  exactly the orbits (h is conserved); for more they are the slice's. The curves are drawn
 *  by gnuplot's contouring (output/phase_output.h), which does that well. */
#pragma once

#include "mechanics/equations_of_motion.h"
#include "mechanics/equilibrium.h"
#include "core/model.h"

#include <cstddef>
#include <string>
#include <vector>

namespace lagrange {

struct phase_settings {
    std::size_t coordinate = 0; ///< index into model::coordinates
    std::size_t levels = 12;    ///< energies between the minimum and the top of the picture
    std::size_t grid = 301;     ///< points per side of the grid
};

struct phase_portrait {
    std::string coordinate;
    double q_low = 0, q_high = 0, v_low = 0, v_high = 0;
    std::size_t grid = 0;
    std::vector<double> energy;        ///< h at (q_i, v_r), row r (velocity) after row, grid × grid
    std::vector<double> levels;        ///< the energies drawn, ascending
    std::vector<double> separatrices;  ///< the energies of the unstable equilibria in the picture
    std::vector<double> stable, unstable; ///< q of the equilibria in the picture, by kind (q̇ = 0)
    double minimum = 0;                ///< the lowest energy (at a stable equilibrium, or on the grid)
    double q(std::size_t i) const { return q_low + (q_high - q_low) * static_cast<double>(i) / static_cast<double>(grid - 1); }
    double v(std::size_t r) const { return v_low + (v_high - v_low) * static_cast<double>(r) / static_cast<double>(grid - 1); }
};

/// The index of coordinate `name` (`--coordinate`); throws scene_error located in the
/// pseudo-file `--coordinate`, naming the scene's coordinates, for another name.
std::size_t phase_coordinate(const std::string& name, const model& scene);

/// Throws computation_error for a scene without coordinates, with constraints, forces or an L
/// that depends on t (no conserved energy), or where a parameter has no value.
phase_portrait compute_phase_portrait(const model& scene, const equations_of_motion& equations,
                                      const equilibria_result* equilibria, const phase_settings& settings);

} // namespace lagrange
