// SPDX-License-Identifier: GPL-2.0-or-later
/** @file simulation.h
 *  The `simulation` and `workprecision` products: the scene's equations of motion
 *  compiled at its parameter point, integrated by the chosen (or automatically
 *  picked) method, with an error estimate, invariant drift, steps and run time; and
 *  the work-precision table of every method over a ladder of tolerances. */
#pragma once

#include "mechanics/equations_of_motion.h"
#include "numeric/compiled_motion.h"
#include "numeric/ode.h"
#include "core/model.h"
#include "core/progress.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace lagrange {

struct simulation_settings {
    std::optional<double> until;      ///< overrides the scene's `simulate until`
    std::optional<std::string> method; ///< overrides the scene's method ("auto" picks)
    std::optional<double> tolerance;  ///< overrides the scene's tolerance (default 1e-9)
    bool estimate_error = true;       ///< also run at tolerance/1000 to estimate the error
    /// An initial state off the constraints is an error (a scene_error at its value) unless
    /// this asks to move it onto them by least change (`--project-initial`).
    bool project_initial = false;
    double max_seconds = 120;
    /// Compile the equations to machine code with the system's C compiler (one compilation,
    /// then faster evaluations than the interpreter's); the default. Without a
    /// compiler, or when false (`--interpret`), the interpreter evaluates them.
    bool native = true;
    /// The C compiler's time limit; past it, or for C source too large to pay off, the
    /// interpreter runs (the `evaluation` says why). The engine keeps it within the time budget.
    double compile_seconds = 120;
    /// Progress of the runs: the simulation, its error estimate's reference runs and any
    /// tighter rerun, or each run of the work-precision table. May be empty.
    progress_callback progress;
};

/// The end time and the tolerance of a run (time in the scene's unit; the tolerance a
/// relative error, with no unit).
struct simulation_span {
    double until = 0;
    double tolerance = 1e-9;
};

/// The settings' end time and tolerance, else those of the scene's `simulate` line (the
/// tolerance 1e-9 when neither gives one). Throws computation_error when there is no end
/// time or it is not positive and finite, or the tolerance is outside 1e-14 … 1.
simulation_span simulation_span_of(const model& scene, const simulation_settings& settings);

/// Beats: the envelope of a coordinate swells and fades with period 2π/(ω₂ − ω₁).
struct beat_measurement {
    std::string coordinate;  ///< the coordinate whose envelope was measured
    double predicted = 0;    ///< 2π/(ω₂ − ω₁) from the linearized frequencies
    double measured = 0;     ///< mean spacing of the envelope's minima in the trajectory
    std::size_t minima = 0;  ///< how many minima were found
};

/// A constraint's multiplier changes sign (a ladder leaves its wall): the time, found by
/// bisection, and the state (q, q̇) then.
struct constraint_event {
    std::string constraint;
    double time = 0;
    std::vector<double> state;
};

struct simulation_result {
    std::vector<std::string> coordinates;
    std::map<std::string, GiNaC::ex> values;  ///< the parameter point
    std::string method;                       ///< the method that ran
    std::string choice;                       ///< why (for `auto`)
    double tolerance = 0;                     ///< the tolerance asked for (a target for the global error)
    /// The absolute tolerance that goes with it: `tolerance` for motions of order one, less
    /// for small ones (integration_options::absolute_scale); a tighter rerun scales it alike.
    double absolute_tolerance = 0;
    /// The tolerance setting of the run reported: `tolerance`, or tighter when the error
    /// estimate of a first run missed `tolerance` and the run was repeated.
    double run_tolerance = 0;
    std::optional<double> missed_error;       ///< the first run's error estimate, when it missed
    /// The linearized rates at the equilibrium that do not grow (ascending): angular
    /// frequencies, and decay rates of modes that only decay.
    std::vector<double> frequencies;
    /// The growth rates γ > 0 of its unstable modes (q ∝ e^{γt}), ascending; printed as such,
    /// never as frequencies.
    std::vector<double> growth_rates;
    double stiffness = 1;                     ///< ω_max/ω_min of the linearization
    trajectory run;
    std::optional<double> error_estimate;     ///< relative trajectory error
    std::string error_basis;                  ///< how the estimate was made
    std::optional<beat_measurement> beats;
    /// A free body: the state is (ω1, ω2, ω3) named by `coordinates`, without velocities.
    bool first_order = false;
    std::string evaluation;                   ///< empty: native code; else how, and why not native
    /// Scenes with constraints: the largest residual of the constraints before each projection.
    std::optional<double> constraint_residual;
    std::optional<double> initial_residual;   ///< of the `initial` state, when it was projected
    std::optional<std::vector<double>> projected_initial; ///< (q, q̇) it was projected to
    std::vector<constraint_event> constraint_events;
    /// Where the stage's time went (`--timings`): the equations compiled or loaded and the
    /// linearization that picks the method; and every integration (the run reported, its
    /// reference runs and reruns), added up. 0 runs: not measured (constrained scenes).
    double preparation_seconds = 0;
    double jacobian_seconds = 0; ///< the Jacobian compiled or loaded, for an implicit method (0: not)
    double integration_seconds = 0;
    std::size_t integration_runs = 0;
};

/// Frequency spread above which `auto` picks the implicit BDF method.
constexpr double stiffness_threshold = 1e3;

/// Runs the simulation the scene's `simulate` line (and `settings`) ask for.
/// `equilibrium`: numeric coordinates of the equilibrium to linearize about for the
/// automatic choice (else the initial position).
simulation_result simulate(const model& scene, const equations_of_motion& equations,
                           const std::optional<std::vector<GiNaC::ex>>& equilibrium,
                           const simulation_settings& settings = {});

/// Integrates a free body's Euler equations (a scene without coordinates with `omega B
/// (w1, w2, w3)`, see free_body_motion.h); the error is measured against the exact
/// solution when the body is torque-free, with the drift of T and |L|².
simulation_result simulate_free_body(const model& scene, const simulation_settings& settings = {});

/// Linearized angular frequencies of `system` about the state `x` (|Im λ| and |Re λ|
/// of the Jacobian's eigenvalues, each pair once), ascending, zeros dropped: the rates that
/// set the method and the step. `growth_rates` (may be null) gets, ascending, those of them
/// that are real λ > 0: unstable modes, which grow as e^{λt} rather than oscillate.
std::vector<double> linearized_frequencies(const ode_system& system, const std::vector<double>& x,
                                           std::vector<double>* growth_rates = nullptr);

/// The exact solution of a linear conservative system x = (q, q̇), q̈ = −M⁻¹K q, by its
/// normal modes, if the Jacobian is the same at every state (checked at a few states);
/// else empty.
std::function<void(double, double*)> normal_mode_solution(const ode_system& system, std::size_t coordinates,
                                                          const std::vector<double>& x0);

/// Mean spacing of the minima of a signal's envelope (peaks of |signal|); 0 if fewer than two.
beat_measurement measure_beats(const std::vector<double>& times, const std::vector<double>& signal);

struct workprecision_point {
    std::string method;
    double tolerance = 0;
    std::optional<double> error;     ///< relative trajectory error against the reference
    double seconds = 0;              ///< fastest of the repeats
    std::size_t steps = 0;
    std::optional<double> energy_drift;
    std::string failure;             ///< why the run stopped, if it did
};

struct workprecision_result {
    std::string reference;           ///< "exact: normal modes" or "reference: rkf78 at tolerance 1e-13"
    bool exact = false;
    double until = 0;
    std::vector<workprecision_point> points;
    std::string evaluation;          ///< empty: native code; else how, and why not native
};

/// `work_precision` on the scene's equations of motion at its parameter point, from
/// its initial state over the `simulate` time span (or settings.until).
workprecision_result scene_work_precision(const model& scene, const equations_of_motion& equations,
                                          const std::optional<std::vector<GiNaC::ex>>& equilibrium,
                                          const simulation_settings& settings = {});

/// `work_precision` on a free body, against its exact solution when it has one.
workprecision_result free_body_work_precision(const model& scene, const simulation_settings& settings = {});

/// Every method over tolerances 1e-3 … 1e-12 (`tolerances` if given), each run
/// repeated while it takes under 0.2 s in total (the fastest kept).
workprecision_result work_precision(const ode_system& system, const std::vector<double>& x0, double until,
                                    std::size_t coordinates, const std::vector<double>& frequencies,
                                    const std::vector<double>& tolerances = {}, double max_seconds = 20,
                                    const progress_callback& progress = {});

} // namespace lagrange
