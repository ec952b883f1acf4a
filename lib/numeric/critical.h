// SPDX-License-Identifier: GPL-2.0-or-later
/** @file critical.h
 *  Critical parameters (`critical v from 0 to 10`): where the real part of an eigenvalue
 *  of the linearization crosses zero as one parameter runs over a range, the others at the
 *  scene's first `values` point — the bicycle's weave and capsize speeds. The eigenvalues
 *  come from the one numeric path (numeric/point_modes.h) at each point of a grid; the
 *  k-th largest real part, a continuous function of the parameter, is bracketed where it
 *  changes sign on the grid and the crossing refined by Boost.Math's TOMS 748. */
#pragma once

#include "core/model.h"
#include "mechanics/linearization.h"

#include <ginac/ginac.h>

#include <complex>
#include <string>
#include <utility>
#include <vector>

namespace lagrange {

/// One crossing of the imaginary axis.
struct critical_crossing {
    double value = 0;                 ///< the parameter where a real part is 0
    double tolerance = 0;             ///< the width of the root finder's last bracket
    std::complex<double> eigenvalue;  ///< s there with the smallest |Re s|, Im s ≥ 0 (Im s = 0: a real s through 0)
    int unstable_before = 0;          ///< eigenvalues with Re s > 0 just below `value`
    int unstable_after = 0;           ///< and just above
};

struct critical_result {
    std::string parameter;                              ///< the name of the parameter that runs
    double from = 0, to = 0;
    std::vector<std::pair<std::string, double>> values; ///< the other parameters used, in declared order
    std::vector<double> grid;                           ///< the points of the locus, from … to
    /// The 2n eigenvalues s at each grid point (quadratic_modes order: ascending imaginary
    /// part, then real part).
    std::vector<std::vector<std::complex<double>>> locus;
    std::size_t table_every = 1; ///< the printed table shows every table_every-th grid point
    std::vector<critical_crossing> crossings; ///< ascending; empty: none in the range
};

/// The crossings over the scene's `critical` range and the eigenvalues along it.
/// `damping`: C at the equilibrium (null without). Throws computation_error when the scene
/// has no `critical` line, a parameter other than the one that runs has no value, or the
/// eigenvalues cannot be computed at a point of the range (naming it).
critical_result critical_parameters(const model& scene, const linearization_result& linear,
                                    const GiNaC::matrix* damping);

/// The same about an operating point: the eigenvalues of the state matrix A of
/// `state_space` (mechanics/operating_point.h), the bicycle's lean and steer. The states
/// whose row or column of A is 0 identically (ignorable coordinates: eigenvalues 0 at every
/// value) are left out of the search and of the locus. A is compiled once and evaluated in
/// double-double. Throws computation_error as above, and when A depends on a coordinate.
critical_result critical_parameters(const model& scene, const GiNaC::matrix& state_matrix);

} // namespace lagrange
