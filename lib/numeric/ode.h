// SPDX-License-Identifier: GPL-2.0-or-later
/** @file ode.h
 *  Time integration of a generic first-order system x' = f(t, x): the system
 *  (right-hand side, optional Jacobian, invariants, optional exact solution), the
 *  methods (Boost.Odeint's explicit adaptive steppers, SUNDIALS CVODE BDF with the
 *  given Jacobian, implicit midpoint with Newton on the Jacobian), and a trajectory
 *  with its steps, run time and invariant drift. Free rigid bodies, pendulums and
 *  hand-built systems all plug in as an `ode_system`. */
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace lagrange {

/// x' = f(t, x) with what is known about it.
struct ode_system {
    std::size_t dimension = 0;
    /// dxdt = f(t, x); both arrays have `dimension` entries.
    std::function<void(double t, const double* x, double* dxdt)> rhs;
    /// ∂f/∂x, row-major dimension × dimension (optional: then implicit methods are unavailable).
    std::function<void(double t, const double* x, double* jacobian)> jacobian;
    /// A quantity that the exact motion conserves (energy, |L|); its drift is reported
    /// relative to `scale` (0: to its initial magnitude).
    struct invariant {
        std::string name;
        std::function<double(const double* x)> value;
        double scale = 0;
    };
    std::vector<invariant> invariants;
    /// The exact solution x(t) when one is known (optional).
    std::function<void(double t, double* x)> exact;

    /// `rhs` as one compiled function without state, when there is one (native code):
    /// DOP853 then calls it directly in its inner loop. Through `rhs` each evaluation passes
    /// std::function and the motion class out of line, which costs a third of the run time
    /// on a two-coordinate linear system. It gives the same numbers as `rhs`.
    struct compiled_rhs {
        void (*program)(const double* symbols, double* out) = nullptr;
        /// 0: the program writes dxdt. n > 0: x = (q, q̇) with n coordinates, the program
        /// writes M (row-major, n × n) then f, and q̈ solves M q̈ = f (numeric/mass_matrix.h).
        std::size_t coordinates = 0;
        bool time = false; ///< the program reads (x, t) instead of x
    };
    std::optional<compiled_rhs> compiled;
};

enum class ode_method {
    dopri5,            ///< Dormand–Prince 5(4), Boost.Odeint, dense output
    rkf78,             ///< Fehlberg 7(8), Boost.Odeint
    dop853,            ///< Hairer's DOP853, order 8 with a 7th-order dense output (numeric/dop853.h)
    bulirsch_stoer,    ///< Bulirsch–Stoer extrapolation, Boost.Odeint, dense output
    bdf,               ///< SUNDIALS CVODE, variable-order BDF, Newton with the given Jacobian
    implicit_midpoint, ///< symplectic, symmetric, order 2; fixed step, Newton with the given Jacobian
};

std::string to_string(ode_method m); ///< "dopri5", "rkf78", "dop853", "bulirsch-stoer", "bdf", "implicit-midpoint"
/// Whether the method, having no interpolant, ends a step at each output time, and so takes
/// other (longer) steps without output times (`integration_options::outputs`): rkf78. The
/// others take the same steps either way (dopri5, DOP853, Bulirsch–Stoer: dense output; BDF,
/// implicit midpoint: they keep their output times).
bool steps_to_outputs(ode_method m);
std::optional<ode_method> ode_method_from_name(const std::string& name);
const std::vector<ode_method>& all_ode_methods();

struct integration_options {
    double start = 0;
    double until = 1;
    double tolerance = 1e-8;      ///< relative tolerance per step
    /// The absolute tolerance per step is tolerance × absolute_scale: 1 for motions of order
    /// one, the size of the motion for small ones (so that the control stays relative to it).
    double absolute_scale = 1;
    double output_step = 0;       ///< spacing of the output times (0: until/1000)
    double fixed_step = 0;        ///< implicit midpoint: its step (0: from the tolerance and `frequency`)
    double frequency = 1;         ///< largest angular frequency of the motion (sets the fixed step)
    std::size_t max_steps = 20'000'000; ///< stop with a message beyond this many steps
    double max_seconds = 120;     ///< stop with a message beyond this much run time
    bool keep_states = true;      ///< keep the states at the output times
    /// false: no output times for dopri5, DOP853, Bulirsch–Stoer and rkf78, which then observe the
    /// end of each step instead (the trajectory's `times` are the step ends). The dense-output
    /// methods take the same steps either way, so a run without outputs
    /// times the integration alone (as SciPy's solve_ivp without t_eval) and a run with them
    /// measures its error. rkf78 has no interpolant: with output times it ends a step at each
    /// of them, without it takes its own steps (far fewer at tight tolerances); its error is
    /// then measured at its step ends. BDF and implicit midpoint keep their output times.
    bool outputs = true;
    /// Output times given explicitly (ascending, the first at `start`, the last at `until`);
    /// empty: every `output_step`.
    std::vector<double> times;
    /// Called now and then with the fraction done (for a progress bar); may be empty.
    std::function<void(double fraction)> progress;
};

struct trajectory {
    std::string method;
    std::vector<double> times;               ///< the output times
    std::vector<std::vector<double>> states; ///< state at each output time (if kept)
    std::vector<double> final_state;
    std::size_t steps = 0;                   ///< accepted steps
    std::size_t evaluations = 0;             ///< right-hand side evaluations
    std::size_t jacobians = 0;               ///< Jacobian evaluations
    double seconds = 0;                      ///< run time of the integration
    /// max over output times of |I(x) − I(x0)| / scale (or / |I(x0)|), per invariant
    std::vector<std::pair<std::string, double>> invariant_drift;
    /// max over output times of ‖x − x_exact‖₂ / max ‖x_exact‖₂ when the system has an exact solution
    std::optional<double> exact_error;
};

/// Integrates from x0 over [start, until]. Throws computation_error with a message
/// when the step size collapses, the state stops being finite, or the step or time
/// limit is reached; std::invalid_argument for an implicit method without a Jacobian.
trajectory integrate(const ode_system& system, ode_method method, const std::vector<double>& x0,
                     const integration_options& options);

/// `integrate` with its output at exactly `times` (ascending, from options.start; the last
/// is the end): a reference at another run's step ends, as for rkf78, which has no interpolant.
trajectory integrate_at(const ode_system& system, ode_method method, const std::vector<double>& x0,
                        integration_options options, const std::vector<double>& times);

/// Relative error between two trajectories at the same output times:
/// max_k ‖a_k − b_k‖₂ / max_k ‖b_k‖₂.
double trajectory_difference(const trajectory& a, const trajectory& b);

} // namespace lagrange
