// SPDX-License-Identifier: GPL-2.0-or-later
/** @file ensemble.h
 *  Ensembles: the scene's motion integrated from many initial states and parameter points
 *  at once (`lagrange ensemble SCENE --grid "theta=-3.1..3.1:400, phi=-3.1..3.1:400"`), each
 *  reduced to a few numbers (the final state, the time of the first flip, the largest
 *  Lyapunov exponent). The equations are compiled once with the gridded parameters as inputs,
 *  and every point is computed independently by DOP853 (numeric/dop853.h), so a point's row
 *  does not depend on which thread or process computed it. Running it in parallel (threads,
 *  MPI) is in run.h. */
#pragma once

#include "mechanics/equations_of_motion.h"
#include "mechanics/time_dependence.h"
#include "program/expression_program.h"
#include "program/native_code.h"
#include "core/model.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace lagrange {

/// One entry of `--grid`: `NAME=from..to:count[:log]`. NAME is a coordinate (its initial
/// value), a velocity `q'` or `q_dot` (its initial value), or a parameter.
struct ensemble_axis {
    enum class target { position, velocity, parameter };
    std::string name;         ///< as written
    target kind = target::position;
    std::size_t index = 0;    ///< coordinate index, or index into model::parameters
    double from = 0, to = 0;
    std::size_t count = 1;    ///< 0 with --random (no count given)
    bool logarithmic = false;
    double at(std::size_t k) const; ///< the k-th grid value (exact ends)
    /// The value at u ∈ [0, 1): uniform between the ends, or uniform in their logarithm.
    double sample(double u) const;
};

/// Parses the comma-separated `--grid` list. With `random` the counts may be left out
/// (`NAME=from..to[:log]`: a range to sample). Throws scene_error located in the
/// pseudo-file `--grid` on bad syntax, an unknown or repeated name, a count of 0, or a
/// logarithmic range that is not positive.
std::vector<ensemble_axis> parse_ensemble_grid(const std::string& text, const model& scene, bool random = false);

/// What each point is reduced to (`--measure`).
struct ensemble_measure {
    enum class kind { final_state, flip_time, max_lyapunov, floquet_stable };
    kind what = kind::final_state;
    /// flip_time: the coordinate watched; `any` watches every coordinate (the first flip of any).
    std::size_t coordinate = 0;
    bool any = true;
    /// max_lyapunov: the time between renormalizations of the tangent vector.
    double renormalize_every = 1;
};

/// What a measure is, one row per kind (measures(), in the order of the kind enum): its name in
/// `--measure`, whether it takes a coordinate (`flip_time:NAME`), the tangent vectors its runs
/// carry beside the state, whether each run lasts one period of the drive (and so needs the
/// `floquet` stage's point), and its columns after the grid's.
struct measure_definition {
    ensemble_measure::kind what;
    const char* name;
    bool takes_coordinate;
    enum class tangent_vectors { none, one, all } tangents; ///< all: the 2n columns of the monodromy matrix
    bool one_period;
    std::vector<std::string> (*columns)(const model& scene);
};
const std::vector<measure_definition>& measures();
const measure_definition& definition_of(ensemble_measure::kind what);

/// Parses a measure's name (measures()), with `:NAME` where it takes a coordinate; throws
/// scene_error located in the pseudo-file `--measure`.
ensemble_measure parse_ensemble_measure(const std::string& text, const model& scene);

struct ensemble_settings {
    double until = 10;              ///< the end time of every run
    double tolerance = 1e-9;        ///< target of the global relative error (per step: ÷12, as simulate)
    std::size_t random = 0;         ///< > 0: this many random points instead of the grid
    std::uint64_t seed = 1;         ///< seed of the random points
    bool native = true;             ///< compile the equations to machine code (else interpret)
    std::size_t max_steps = 10'000'000; ///< per point; past it the point fails
};

/// The numbers of one point beyond its row: the cost and, on the sampled points, the error.
struct ensemble_point_stats {
    std::size_t steps = 0;
    bool failed = false;
    bool sampled = false;        ///< rerun at a tighter tolerance to estimate the error
    double error = 0;            ///< sampled: largest |measure − tight measure| over the columns
};

/// Per-thread scratch of ensemble_problem::compute (the problem itself is shared read-only).
struct ensemble_workspace {
    std::vector<double> symbols, outputs, factor, jacobian, acceleration, column, state, parameters, scratch;
};

/// The compiled scene and the grid: what every thread and process shares. Its programs are its
/// own, not compiled_motion's, whose evaluations share mutable scratch: expression_program::run
/// takes the caller's scratch, and the native functions keep no state.
class ensemble_problem {
public:
    /// Throws computation_error for a scene that cannot be run as an ensemble (constraints,
    /// no coordinates, a parameter without a value) and when the equations cannot be compiled.
    /// `floquet_stable` needs `time`: the point that solves the equations at every t (its
    /// first point) and the drive's frequencies come from there.
    ensemble_problem(const model& scene, const equations_of_motion& equations, std::vector<ensemble_axis> axes,
                     const ensemble_measure& measure, const ensemble_settings& settings,
                     const time_dependence_result* time = nullptr);

    std::size_t points() const { return points_; }
    /// The column names: the grid's names (or the random ranges'), then the measure's.
    const std::vector<std::string>& columns() const { return columns_; }
    std::size_t grid_columns() const { return axes_.size(); }
    const std::vector<ensemble_axis>& axes() const { return axes_; }
    const ensemble_measure& measure() const { return measure_; }
    const ensemble_settings& settings() const { return settings_; }
    /// "native code" or why the interpreter runs.
    const std::string& evaluation() const { return evaluation_; }
    /// Whether q̈ comes from the recursion of a tree (see rhs_program_).
    bool recursive() const { return recursive_; }
    /// A fingerprint of what the rows depend on (columns, points, settings, evaluation), so that
    /// processes of one MPI run can check that they compute the same ensemble.
    std::uint64_t signature() const;
    /// Every `sample_every()`-th point (from index 0) is also run at tolerance/1000.
    std::size_t sample_every() const { return sample_every_; }

    /// Point `index`: its grid values and measure into `row` (columns().size() entries).
    /// A point whose integration fails gets NaN measures and stats.failed. Thread-safe with one
    /// workspace per thread.
    ensemble_point_stats compute(std::size_t index, ensemble_workspace& work, double* row) const;
    /// Why point `index` fails (its computation_error's message), or "" if it does not.
    std::string failure_message(std::size_t index) const;
    /// The grid (or random) values of point `index`, one per axis.
    void grid_values(std::size_t index, double* values) const;
    /// The grid values of point `index` as `name = value, …`, for messages.
    std::string point_text(std::size_t index) const;

private:
    struct run_result;
    run_result integrate(const double* x0, double tolerance, ensemble_workspace& work) const;
    /// Sizes the workspace, writes the grid values into `row`, the gridded parameters into the
    /// symbols and the initial state into work.state.
    void prepare(std::size_t index, ensemble_workspace& work, double* row) const;
    double step_tolerance() const;

    std::vector<ensemble_axis> axes_;
    ensemble_measure measure_;
    ensemble_settings settings_;
    std::size_t points_ = 0;
    std::size_t sample_every_ = 1;
    std::size_t n_ = 0;              ///< coordinates
    std::vector<std::string> columns_;
    std::vector<std::size_t> gridded_parameters_; ///< scene parameter index of each program parameter
    /// M then f in (q, q̇, t, gridded parameters), or (q̇, q̈) by the recursion of a tree
    /// (numeric/point_tree.h) where compiled_motion would take it and no tangents are needed
    expression_program rhs_program_;
    bool recursive_ = false;
    expression_program jacobian_program_; ///< ∂M/∂q_k (n³), ∂f/∂q (n²), ∂f/∂q̇ (n²)
    expression_program initial_program_;  ///< the scene's initial (q, q̇) in the gridded parameters
    /// floquet_stable: |ω₀|, the drive's base frequency, in the gridded parameters; the period
    /// is period_factor_ / |ω₀| (2π times the common denominator of the frequency ratios).
    expression_program frequency_program_;
    double period_factor_ = 0;
    void floquet_setup(const model& scene, const equations_of_motion& equations, const time_dependence_result* time,
                       const std::map<std::string, GiNaC::ex>& values, const std::vector<GiNaC::ex>& parameter_symbols,
                       std::vector<GiNaC::ex>& initial_outputs);
    std::shared_ptr<native_module> native_;
    native_module::function native_rhs_ = nullptr, native_jacobian_ = nullptr;
    std::string evaluation_;
};

} // namespace lagrange
