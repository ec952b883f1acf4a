// SPDX-License-Identifier: GPL-2.0-or-later
/** @file analysis.h
 *  The stage planner: walks back from the wanted products, runs each needed
 *  stage once, in order, and records its time. Stages that are not needed do not run. */
#pragma once

#include "algebra/budget.h"
#include "mechanics/equations_of_motion.h"
#include "mechanics/lagrangian.h"
#include "mechanics/asymptotic.h"
#include "mechanics/elimination.h"
#include "mechanics/contact.h"
#include "mechanics/constrained_linearization.h"
#include "mechanics/damping.h"
#include "mechanics/equilibrium.h"
#include "mechanics/gyroscopic.h"
#include "mechanics/linearization.h"
#include "mechanics/modes.h"
#include "mechanics/operating_point.h"
#include "mechanics/state_space.h"
#include "bodies/euler.h"
#include "bodies/inertia.h"
#include "mechanics/top.h"
#include "mechanics/steady_motion.h"
#include "mechanics/symmetries.h"
#include "numeric/compiled_modes.h"
#include "numeric/critical.h"
#include "numeric/floquet.h"
#include "numeric/linear_response.h"
#include "numeric/point_modes.h"
#include "numeric/poinsot.h"
#include "mechanics/time_dependence.h"
#include "numeric/phase_portrait.h"
#include "numeric/simulation.h"
#include "numeric/virial.h"
#include "verify/verify.h"
#include "core/model.h"

#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace lagrange {

struct stage_time {
    std::string stage;
    double seconds;
    /// Where some of the time went, for the text and LaTeX `--timings` (JSON's `timings`
    /// keeps one number per stage): the simulation's preparation and integration.
    std::vector<std::pair<std::string, double>> parts = {};
};

/// Everything the stages computed for one scene.
struct analysis {
    const model* scene = nullptr;
    std::set<product> wanted;            ///< what was asked for (resolved)
    std::vector<stage_time> stages;      ///< the stages that ran, in order, with their times
    std::vector<std::string> notes;      ///< products left out of a default run, and why
    std::optional<lagrangian_result> lagrangian;
    std::optional<equations_of_motion> equations;
    std::optional<equilibria_result> equilibria;
    std::optional<linearization_result> linearization;
    std::optional<characteristic_result> characteristic;
    std::optional<modes_result> modes;
    std::optional<asymptotic_result> asymptotic;
    std::optional<std::vector<numeric_modes>> numeric;
    std::optional<std::vector<inertia_result>> inertia; ///< one per body, in scene order
    std::optional<std::vector<euler_result>> euler;     ///< one per free body (with `omega`)
    std::optional<std::vector<poinsot_motion>> poinsot; ///< one per torque-free body with numbers, in space
    std::optional<std::vector<top_result>> tops;        ///< bodies turned by three coordinates (heavy tops)
    std::optional<simulation_result> simulation;
    std::optional<workprecision_result> workprecision;
    std::optional<damping_result> damping;   ///< damped small oscillations (dissipation, dampers)
    /// How each symbolic result was checked numerically before it is printed.
    std::optional<verification_result> verification;
    std::optional<time_dependence_result> time; ///< whether L depends on t (scenes that mention t)
    std::optional<std::vector<floquet_point>> floquet; ///< per point solving at every t and `values` point
    std::optional<state_space_result> state_space;     ///< ẋ = A x + B u at the equilibrium (inputs)
    std::vector<state_space_point> state_space_values; ///< A and B at the `values` points
    std::optional<transfer_result> transfer;           ///< H(s) of each input to each coordinate
    std::optional<conserved_result> conserved;     ///< the energy function and the cyclic momenta
    std::optional<hamiltonian_result> hamiltonian; ///< H(q, p) and Hamilton's equations
    std::optional<reduced_result> reduced;         ///< Routh's reduction of the cyclic coordinates
    std::optional<steady_motion_result> steady;    ///< the `equilibrium` line's steady motion, reduced
    std::optional<multipliers_result> multipliers; ///< constraint multipliers and forces (scenes with constraints)
    std::optional<contact_result> contact;         ///< the ground's force on each rolling wheel
    /// The constraints that can be solved for a coordinate, and the reduced equations when asked for.
    std::optional<elimination_result> elimination;
    /// Small oscillations with constraints: `linearization` is then in the independent coordinates.
    std::optional<constrained_linearization> constrained;
    /// `state_space` about an operating point (constraints, or a `linearize about` line): then
    /// `state_space` holds its A and B in the independent states.
    std::optional<operating_linearization> operating;
    /// The report's phase portrait of a scene of one coordinate (engine/pictures.h).
    std::optional<phase_portrait> phase;
    // The products with a result of their own (core/products.inc): `std::optional<result> id`.
#define LAGRANGE_PRODUCT(id, name, scope, by_default)
#define LAGRANGE_OWN_PRODUCT(id, name, scope, by_default, result) std::optional<result> id;
#include "core/products.inc"
#undef LAGRANGE_OWN_PRODUCT
#undef LAGRANGE_PRODUCT
};

/// What verify_results reads of an analysis: a pointer to each result it computed.
verification_input verification_input_of(const analysis& result);

/// The products this version computes.
const std::set<product>& available_products();

/// Runs the stages that `wanted` needs. If `wanted` is empty: the scene's `want`
/// line, or else every available product the scene's content supports (then a
/// product that cannot be computed is left out with a note instead of failing).
/// Throws computation_error for a product this version does not compute, or when
/// a stage of an explicitly wanted product cannot be done.
///
/// Each symbolic stage runs under `limits` (see algebra/budget.h). A stage that exceeds
/// its budget leaves out its products and those that depend on it, with a note naming
/// the stage and the limit; the rest is still computed (numeric modes need only the
/// linearization). Throws budget_exceeded only when none of the wanted products
/// could be computed. `simulation` overrides the scene's `simulate` line (end time,
/// method, tolerance).
analysis analyze(const model& scene, const std::set<product>& wanted = {}, const budget_limits& limits = {},
                 const simulation_settings& simulation = {});

/// The same, with the default budgets.
analysis analyze(const model& scene, const std::set<product>& wanted, const simulation_settings& simulation);

/// What `export` needs: the equations of motion, the conserved quantities of a scene without
/// constraints or generalized forces, and the linearization at the scene's equilibrium where
/// one can be found (a scene without one is exported without it).
analysis analyze_for_export(const model& scene, const budget_limits& limits = {});

/// The numeric modes' path for `result` (which holds a linearization): its T, V, G and, when
/// the scene has dissipation, the damping matrix C at the same equilibrium: what the
/// `numeric` stage evaluates at the `values` points and `--sweep` at the points of its grid.
/// It refers to `result`, which must outlive it.
point_modes numeric_modes_path(const analysis& result);

} // namespace lagrange
