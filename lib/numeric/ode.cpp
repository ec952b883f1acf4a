// SPDX-License-Identifier: GPL-2.0-or-later
/** @file ode.cpp
 *  The integrators: Boost.Odeint (Dormand–Prince 5(4), Fehlberg 7(8),
 *  Bulirsch–Stoer), DOP853 (numeric/dop853.h), SUNDIALS CVODE (BDF with the system's
 *  Jacobian), and implicit midpoint. Implicit midpoint is written here by hand: Odeint's symplectic steppers
 *  need a separable Hamiltonian, which a pendulum's is not, and no Debian library
 *  has a symplectic implicit Runge–Kutta method with a user Jacobian. */
#include "numeric/ode.h"

#include "numeric/dop853.h"
#include "program/double_double.h"
#include "numeric/mass_matrix.h"
#include "numeric/values.h"

#include "core/errors.h"

#include <Eigen/Dense>
#include <boost/numeric/odeint.hpp>
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace lagrange {

namespace odeint = boost::numeric::odeint;
using state_type = std::vector<double>;
using clock_type = std::chrono::steady_clock;

std::string to_string(ode_method m)
{
    switch (m) {
    case ode_method::dopri5: return "dopri5";
    case ode_method::rkf78: return "rkf78";
    case ode_method::dop853: return "dop853";
    case ode_method::bulirsch_stoer: return "bulirsch-stoer";
    case ode_method::bdf: return "bdf";
    case ode_method::implicit_midpoint: return "implicit-midpoint";
    }
    return "?";
}

bool steps_to_outputs(ode_method m) { return m == ode_method::rkf78; }

const std::vector<ode_method>& all_ode_methods()
{
    static const std::vector<ode_method> methods = {ode_method::dopri5, ode_method::rkf78, ode_method::dop853,
                                                    ode_method::bulirsch_stoer, ode_method::bdf,
                                                    ode_method::implicit_midpoint};
    return methods;
}

std::optional<ode_method> ode_method_from_name(const std::string& name)
{
    for (ode_method m : all_ode_methods())
        if (to_string(m) == name)
            return m;
    if (name == "dp5" || name == "rk45" || name == "dormand-prince")
        return ode_method::dopri5;
    if (name == "fehlberg" || name == "rk78")
        return ode_method::rkf78;
    if (name == "bs" || name == "bulirsch_stoer")
        return ode_method::bulirsch_stoer;
    if (name == "cvode" || name == "stiff")
        return ode_method::bdf;
    if (name == "midpoint" || name == "implicit_midpoint" || name == "symplectic")
        return ode_method::implicit_midpoint;
    return std::nullopt;
}

namespace {

/// ‖v‖₂ of the n entries v(i) without under- or overflow in the squares: scaled by the power
/// of two of the largest first. That is exact, so in range it is the plain sum's to the bit,
/// while a motion of size 1e-300, whose squares underflow to 0, still has its norm.
template <class Entry>
double euclidean_norm(std::size_t n, Entry v)
{
    double largest = 0;
    for (std::size_t i = 0; i < n; ++i)
        largest = std::max(largest, std::abs(v(i)));
    if (largest == 0 || !std::isfinite(largest))
        return largest;
    int exponent = std::ilogb(largest);
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i) {
        double scaled = std::ldexp(v(i), -exponent);
        sum += scaled * scaled;
    }
    return std::ldexp(std::sqrt(sum), exponent);
}

/// Counts evaluations and enforces the step and time limits; records the output.
class run_state {
public:
    run_state(const ode_system& system, const integration_options& options, trajectory& result)
        : system_(system), options_(options), result_(result), start_(clock_type::now())
    {
    }

    void rhs(double t, const double* x, double* dxdt)
    {
        count(t);
        system_.rhs(t, x, dxdt);
    }

    /// Counts one evaluation (at t) and checks the limits now and then.
    void count(double t)
    {
        if ((++result_.evaluations & 1023) == 0)
            check_limits(t);
    }

    /// Adds `evaluations` counted elsewhere (compiled_evaluation).
    void add_evaluations(std::size_t evaluations) { result_.evaluations += evaluations; }

    const ode_system& system() const { return system_; }

    void check_limits(double t) const
    {
        std::chrono::duration<double> elapsed = clock_type::now() - start_;
        if (elapsed.count() > options_.max_seconds)
            throw computation_error("the integration stopped at t = " + message_number(t) + " after " +
                                    message_number(options_.max_seconds) + " s (the time limit); the problem needs a "
                                    "looser tolerance, another method or a shorter time span");
        if (result_.evaluations > 12 * options_.max_steps)
            throw computation_error("the integration stopped at t = " + message_number(t) + " after " +
                                    std::to_string(result_.evaluations) + " evaluations (the step limit); "
                                    "the problem is too stiff or too long for this method and tolerance");
    }

    void observe(double t, const double* x)
    {
        std::size_t n = system_.dimension;
        for (std::size_t i = 0; i < n; ++i)
            if (!std::isfinite(x[i]))
                throw computation_error("the solution stopped being finite at t = " + message_number(t) +
                                        " (the motion runs away or the method is unstable at this tolerance)");
        if (!initialized_) {
            initialized_ = true;
            initial_.assign(x, x + n);
            for (const auto& inv : system_.invariants) {
                double value = inv.value(x);
                initial_values_.push_back(value);
                double scale = inv.scale > 0 ? inv.scale : std::abs(value);
                scales_.push_back(scale > 0 ? scale : 1.0);
                result_.invariant_drift.emplace_back(inv.name, 0.0);
            }
        }
        for (std::size_t k = 0; k < system_.invariants.size(); ++k) {
            double drift = std::abs(system_.invariants[k].value(x) - initial_values_[k]) / scales_[k];
            result_.invariant_drift[k].second = std::max(result_.invariant_drift[k].second, drift);
        }
        if (system_.exact) {
            std::vector<double> exact(n);
            system_.exact(t, exact.data());
            exact_difference_ = std::max(exact_difference_, euclidean_norm(n, [&](std::size_t i) {
                                                 return x[i] - exact[i];
                                             }));
            exact_size_ = std::max(exact_size_, euclidean_norm(n, [&](std::size_t i) { return exact[i]; }));
        }
        result_.times.push_back(t);
        if (options_.keep_states)
            result_.states.emplace_back(x, x + n);
        result_.final_state.assign(x, x + n);
        if (options_.progress && ++observed_ % 16 == 0) {
            double span = options_.until - options_.start;
            options_.progress(span > 0 ? (t - options_.start) / span : 1.0);
        }
    }

    void finish()
    {
        std::chrono::duration<double> elapsed = clock_type::now() - start_;
        result_.seconds = elapsed.count();
        if (system_.exact)
            result_.exact_error = exact_size_ > 0 ? exact_difference_ / exact_size_ : exact_difference_;
        if (options_.progress)
            options_.progress(1.0);
    }

private:
    const ode_system& system_;
    const integration_options& options_;
    trajectory& result_;
    clock_type::time_point start_;
    bool initialized_ = false;
    std::vector<double> initial_;
    std::vector<double> initial_values_;
    std::vector<double> scales_;
    double exact_difference_ = 0;
    double exact_size_ = 0;
    std::size_t observed_ = 0;
};

std::vector<double> output_times(const integration_options& options)
{
    if (!options.times.empty()) {
        if (options.times.front() != options.start || options.times.back() != options.until ||
            !std::is_sorted(options.times.begin(), options.times.end()))
            throw std::invalid_argument("output times must ascend from the start to the end time");
        return options.times;
    }
    double span = options.until - options.start;
    double step = options.output_step > 0 ? options.output_step : span / 1000;
    const double intervals = std::ceil(span / step - 1e-9);
    if (!(intervals <= 10'000'000)) // before the cast: a tiny step's count does not fit an integer
        throw computation_error("the output step " + message_number(step) + " gives more than 10^7 output times");
    std::size_t count = static_cast<std::size_t>(intervals);
    std::vector<double> times;
    for (std::size_t k = 0; k < count; ++k)
        times.push_back(options.start + static_cast<double>(k) * step);
    times.push_back(options.until);
    return times;
}

void run_odeint(ode_method method, const std::vector<double>& x0, const integration_options& options,
                run_state& run, trajectory& result)
{
    state_type x = x0;
    auto rhs = [&](const state_type& state, state_type& dxdt, double t) { run.rhs(t, state.data(), dxdt.data()); };
    auto observer = [&](const state_type& state, double t) { run.observe(t, state.data()); };
    std::vector<double> times = output_times(options);
    double tol = options.tolerance, absolute = options.tolerance * options.absolute_scale;
    double first_step = std::min(1e-3, (options.until - options.start) / 100) * std::cbrt(tol);
    odeint::max_step_checker checker(static_cast<int>(std::min<std::size_t>(options.max_steps, 2'000'000'000)));
    try {
        switch (method) {
        case ode_method::dopri5: {
            auto stepper = odeint::make_dense_output(absolute, tol, odeint::runge_kutta_dopri5<state_type>());
            result.steps = options.outputs ? odeint::integrate_times(stepper, rhs, x, times.begin(), times.end(),
                                                                     first_step, observer, checker)
                                           : odeint::integrate_adaptive(stepper, rhs, x, options.start,
                                                                        options.until, first_step, observer);
            break;
        }
        case ode_method::rkf78: {
            auto stepper = odeint::make_controlled(absolute, tol, odeint::runge_kutta_fehlberg78<state_type>());
            result.steps = options.outputs ? odeint::integrate_times(stepper, rhs, x, times.begin(), times.end(),
                                                                     first_step, observer, checker)
                                           : odeint::integrate_adaptive(stepper, rhs, x, options.start,
                                                                        options.until, first_step, observer);
            break;
        }
        case ode_method::bulirsch_stoer: {
            // control_interpolation: the dense output's error is part of the step control too (else
            // long steps interpolate 1000 output times with errors far above the tolerance).
            odeint::bulirsch_stoer_dense_out<state_type> stepper(absolute, tol, 1.0, 0.0, 0.0, true);
            result.steps = options.outputs ? odeint::integrate_times(stepper, rhs, x, times.begin(), times.end(),
                                                                     first_step, observer, checker)
                                           : odeint::integrate_adaptive(stepper, rhs, x, options.start,
                                                                        options.until, first_step, observer);
            break;
        }
        default:
            throw std::logic_error("not an Odeint method");
        }
    } catch (const odeint::step_adjustment_error&) {
        throw computation_error("the step size of " + to_string(method) +
                                " collapsed: the problem is too stiff for it at this tolerance");
    } catch (const odeint::no_progress_error&) {
        throw computation_error(to_string(method) + " made no progress within the step limit");
    } catch (const std::overflow_error&) {
        throw computation_error("the step size of " + to_string(method) +
                                " collapsed: the problem is too stiff for it at this tolerance");
    }
}

// ---- DOP853 ----

/// The system's compiled right-hand side (ode_system::compiled) evaluated inline, counted
/// as run_state::rhs counts: the same numbers as the system's rhs, without its out-of-line
/// layers. `Coordinates` > 0: M q̈ = f with that many coordinates (its scratch on the stack);
/// 0: any number, read at run time; −1: the program writes dxdt (a first-order system).
template <int Coordinates>
class compiled_evaluation {
public:
    compiled_evaluation(run_state& run, const ode_system::compiled_rhs& compiled, std::size_t dimension)
        : run_(run), program_(compiled.program), time_(compiled.time), dimension_(dimension),
          n_(Coordinates > 0 ? static_cast<std::size_t>(Coordinates) : compiled.coordinates)
    {
        if constexpr (Coordinates == 0) {
            symbols_.resize(dimension_ + 1);
            outputs_.resize(n_ * n_ + n_);
            factor_.resize(n_ * n_);
        } else if constexpr (Coordinates < 0) {
            symbols_.resize(dimension_ + 1);
        }
    }

    compiled_evaluation(const compiled_evaluation&) = delete;
    compiled_evaluation& operator=(const compiled_evaluation&) = delete;
    ~compiled_evaluation() { run_.add_evaluations(count_); }

    // Inlined into each of DOP853's stages (GCC calls it out of line otherwise, and the run then
    // takes up to a tenth longer on a two-coordinate system).
    [[gnu::always_inline]] void operator()(double t, const double* x, double* dxdt)
    {
        // Counted here, in a register, and added to the run's count every 1024 evaluations.
        if (++count_ == 1024) [[unlikely]]
            add_count(t);
        const double* symbols = x;
        if (time_) {
            std::copy(x, x + dimension(), symbols_.begin());
            symbols_[dimension()] = t;
            symbols = symbols_.data();
        }
        if constexpr (Coordinates < 0) {
            program_(symbols, dxdt);
        } else {
            const std::size_t n = coordinates();
            program_(symbols, outputs_.data());
            std::copy(x + n, x + 2 * n, dxdt);
            if (!solve_mass_matrix(outputs_.data(), n, factor_.data(), dxdt + n)) [[unlikely]]
                singular(t, x, 2 * n);
        }
    }

private:
    [[gnu::noinline]] void add_count(double t)
    {
        run_.add_evaluations(count_);
        count_ = 0;
        run_.check_limits(t);
    }
    [[noreturn, gnu::noinline]] static void singular(double t, const double* x, std::size_t size)
    {
        throw computation_error(singular_mass_matrix_message(t, x, size));
    }
    static constexpr std::size_t fixed = Coordinates > 0 ? static_cast<std::size_t>(Coordinates) : 0;
    std::size_t coordinates() const { return Coordinates > 0 ? fixed : n_; }
    std::size_t dimension() const { return Coordinates > 0 ? 2 * fixed : dimension_; }
    template <std::size_t N>
    using scratch = std::conditional_t<(Coordinates > 0), std::array<double, N>, std::vector<double>>;
    run_state& run_;
    std::size_t count_ = 0;
    void (*program_)(const double*, double*);
    bool time_;
    std::size_t dimension_, n_;
    scratch<2 * fixed + 1> symbols_{};
    scratch<fixed * fixed + fixed> outputs_{};
    scratch<fixed * fixed> factor_{};
};

template <int Dim, bool Fused, class F>
LAGRANGE_DOP853_INLINE void run_dop853_with(F& f, const std::vector<double>& x0, const integration_options& options,
                                            run_state& run, trajectory& result)
{
    dop853_stepper<Dim, Fused> stepper(x0.size(), options.tolerance, options.absolute_scale);
    stepper.start(f, options.start, x0.data(), options.until);
    run.observe(options.start, x0.data());
    auto advance = [&]() LAGRANGE_LAMBDA_INLINE {
        if (!stepper.step(f, options.until))
            throw computation_error("the step size of dop853 collapsed at t = " + message_number(stepper.time()) +
                                    ": the problem is too stiff for it at this tolerance, or its solution runs away");
        if (++result.steps > options.max_steps)
            throw computation_error("dop853 made no progress within the step limit");
    };
    if (!options.outputs) {
        while (stepper.time() < options.until) {
            advance();
            run.observe(stepper.time(), stepper.state());
        }
        return;
    }
    std::vector<double> times = output_times(options), at(x0.size());
    for (std::size_t k = 1; k < times.size(); ++k) {
        while (stepper.time() < times[k])
            advance();
        if (stepper.time() == times[k]) {
            run.observe(times[k], stepper.state());
        } else {
            stepper.interpolate(f, times[k], at.data());
            run.observe(times[k], at.data());
        }
    }
}

/// DOP853 on the compiled right-hand side when the system has one (and its coordinates fit
/// the state), else through the system's rhs.
template <int Dim, bool Fused>
LAGRANGE_DOP853_INLINE void run_dop853_sized(const std::vector<double>& x0, const integration_options& options,
                                             run_state& run, trajectory& result)
{
    const auto& compiled = run.system().compiled;
    if (compiled && compiled->program && compiled->coordinates == 0) {
        compiled_evaluation<-1> f(run, *compiled, x0.size());
        return run_dop853_with<Dim, Fused>(f, x0, options, run, result);
    }
    if (compiled && compiled->program && 2 * compiled->coordinates == x0.size()) {
        if constexpr (Dim > 0 && Dim % 2 == 0) {
            compiled_evaluation<Dim / 2> f(run, *compiled, x0.size());
            return run_dop853_with<Dim, Fused>(f, x0, options, run, result);
        } else if constexpr (Dim == 0) {
            compiled_evaluation<0> f(run, *compiled, x0.size());
            return run_dop853_with<Dim, Fused>(f, x0, options, run, result);
        }
    }
    auto f = [&run](double t, const double* x, double* dxdt) LAGRANGE_LAMBDA_INLINE { run.rhs(t, x, dxdt); };
    run_dop853_with<Dim, Fused>(f, x0, options, run, result);
}

/// Fixed-size states for the common small dimensions (a pendulum's 2 and 4, a free body's 3).
template <bool Fused>
LAGRANGE_DOP853_INLINE void run_dop853_any_size(const std::vector<double>& x0, const integration_options& options,
                                                run_state& run, trajectory& result)
{
    switch (x0.size()) {
    case 2: return run_dop853_sized<2, Fused>(x0, options, run, result);
    case 3: return run_dop853_sized<3, Fused>(x0, options, run, result);
    case 4: return run_dop853_sized<4, Fused>(x0, options, run, result);
    case 6: return run_dop853_sized<6, Fused>(x0, options, run, result);
    default: return run_dop853_sized<0, Fused>(x0, options, run, result);
    }
}

#if LAGRANGE_HAVE_FMA_KERNELS
/// The same integration compiled for CPUs with FMA (everything above inlines into it): the
/// stepper's madd() is std::fma there (nothing else fuses: ode.cpp is compiled with
/// -ffp-contract=off) and its vectors take AVX's three-operand form, in 128-bit lanes: faster,
/// most of all where the right-hand side is cheap. Its numbers differ from the portable
/// version's in the last bits (the fused products round once), as they do from CPU to CPU with
/// SLEEF's sines against libm's.
LAGRANGE_FMA_TARGET void run_dop853_fma(const std::vector<double>& x0, const integration_options& options,
                                        run_state& run, trajectory& result)
{
    run_dop853_any_size<true>(x0, options, run, result);
}
#endif

/// DOP853, in its FMA version where the CPU has FMA (fma_kernels(), program/double_double.h).
void run_dop853(const std::vector<double>& x0, const integration_options& options, run_state& run,
                trajectory& result)
{
#if LAGRANGE_HAVE_FMA_KERNELS
    if (fma_kernels())
        return run_dop853_fma(x0, options, run, result);
#endif
    run_dop853_any_size<false>(x0, options, run, result);
}

// ---- SUNDIALS CVODE ----

struct cvode_data {
    const ode_system* system;
    run_state* run;
    trajectory* result;
    bool stopped = false;
    std::string message;
};

int cvode_rhs(sunrealtype t, N_Vector y, N_Vector ydot, void* user)
{
    auto* data = static_cast<cvode_data*>(user);
    try {
        data->run->rhs(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot));
    } catch (const computation_error& error) {
        data->stopped = true;
        data->message = error.what();
        return -1;
    }
    return 0;
}

int cvode_jacobian(sunrealtype t, N_Vector y, N_Vector, SUNMatrix jac, void* user, N_Vector, N_Vector, N_Vector)
{
    auto* data = static_cast<cvode_data*>(user);
    std::size_t n = data->system->dimension;
    std::vector<double> j(n * n);
    data->system->jacobian(t, N_VGetArrayPointer(y), j.data());
    ++data->result->jacobians;
    for (std::size_t r = 0; r < n; ++r)
        for (std::size_t c = 0; c < n; ++c)
            SM_ELEMENT_D(jac, static_cast<sunindextype>(r), static_cast<sunindextype>(c)) = j[r * n + c];
    return 0;
}

void cvode_silent(int, const char*, const char*, char*, void*) {}

/// Owns the SUNDIALS objects of one run.
struct cvode_session {
    SUNContext context = nullptr;
    N_Vector y = nullptr;
    SUNMatrix matrix = nullptr;
    SUNLinearSolver solver = nullptr;
    void* memory = nullptr;
    ~cvode_session()
    {
        if (memory)
            CVodeFree(&memory);
        if (solver)
            SUNLinSolFree(solver);
        if (matrix)
            SUNMatDestroy(matrix);
        if (y)
            N_VDestroy(y);
        if (context)
            SUNContext_Free(&context);
    }
};

void run_cvode(const ode_system& system, const std::vector<double>& x0, const integration_options& options,
               run_state& run, trajectory& result)
{
    const auto n = static_cast<sunindextype>(system.dimension);
    cvode_session s;
    cvode_data data{&system, &run, &result, false, {}};
    if (SUNContext_Create(nullptr, &s.context) != 0)
        throw computation_error("SUNDIALS could not be initialized");
    s.y = N_VNew_Serial(n, s.context);
    std::copy(x0.begin(), x0.end(), N_VGetArrayPointer(s.y));
    s.memory = CVodeCreate(CV_BDF, s.context);
    s.matrix = SUNDenseMatrix(n, n, s.context);
    s.solver = SUNLinSol_Dense(s.y, s.matrix, s.context);
    if (!s.y || !s.memory || !s.matrix || !s.solver)
        throw computation_error("SUNDIALS could not allocate its workspace");
    CVodeSetErrHandlerFn(s.memory, cvode_silent, nullptr);
    CVodeInit(s.memory, cvode_rhs, options.start, s.y);
    CVodeSStolerances(s.memory, options.tolerance, options.tolerance * options.absolute_scale);
    CVodeSetUserData(s.memory, &data);
    CVodeSetLinearSolver(s.memory, s.solver, s.matrix);
    CVodeSetJacFn(s.memory, cvode_jacobian);
    CVodeSetMaxNumSteps(s.memory, static_cast<long>(std::min<std::size_t>(options.max_steps, 1L << 40)));
    CVodeSetMaxOrd(s.memory, 5);
    CVodeSetStopTime(s.memory, options.until);
    std::vector<double> times = output_times(options);
    run.observe(times[0], x0.data());
    for (std::size_t k = 1; k < times.size(); ++k) {
        sunrealtype reached = 0;
        int flag = CVode(s.memory, times[k], s.y, &reached, CV_NORMAL);
        if (flag < 0) {
            if (data.stopped)
                throw computation_error(data.message);
            std::string why = flag == CV_TOO_MUCH_WORK  ? "it reached the step limit"
                              : flag == CV_TOO_MUCH_ACC ? "the tolerance is below what double precision allows"
                              : flag == CV_ERR_FAILURE || flag == CV_CONV_FAILURE
                                  ? "its step size collapsed (a singularity or a runaway motion)"
                                  : "CVODE failed with code " + std::to_string(flag);
            throw computation_error("the BDF integration stopped at t = " + message_number(reached) + ": " + why);
        }
        run.observe(times[k], N_VGetArrayPointer(s.y));
    }
    long steps = 0;
    CVodeGetNumSteps(s.memory, &steps);
    result.steps = static_cast<std::size_t>(steps);
}

// ---- implicit midpoint ----

void run_implicit_midpoint(const ode_system& system, const std::vector<double>& x0,
                           const integration_options& options, run_state& run, trajectory& result)
{
    const auto n = static_cast<Eigen::Index>(system.dimension);
    std::vector<double> times = output_times(options);
    double span = options.until - options.start;
    double h = options.fixed_step;
    if (!(h > 0)) {
        // Phase error of the midpoint rule on x'' = −ω²x: ω³h²t/24 → ≤ tol over the run.
        double w = std::max(options.frequency, 1e-12);
        h = std::sqrt(24 * options.tolerance / (w * w * w * std::max(span, 1e-300)));
    }
    double max_spacing = times.size() > 1 ? times[1] - times[0] : span;
    h = std::min(h, max_spacing);
    double needed = span / h;
    if (needed > static_cast<double>(options.max_steps))
        throw computation_error("implicit midpoint would need " + message_number(needed) + " steps at tolerance " +
                                message_number(options.tolerance) + " (the limit is " +
                                message_number(options.max_steps) + "): use a looser tolerance or another method");
    Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(x0.data(), n);
    Eigen::VectorXd y(n), mid(n), f(n), residual(n);
    Eigen::MatrixXd jacobian(n, n);
    Eigen::PartialPivLU<Eigen::MatrixXd> lu;
    const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(n, n);
    run.observe(times[0], x.data());
    double t = options.start;
    for (std::size_t k = 1; k < times.size(); ++k) {
        double interval = times[k] - t;
        auto substeps = static_cast<std::size_t>(std::ceil(interval / h - 1e-9));
        substeps = std::max<std::size_t>(substeps, 1);
        double step = interval / static_cast<double>(substeps);
        for (std::size_t s = 0; s < substeps; ++s) {
            double tm = t + step / 2;
            run.rhs(tm, x.data(), f.data());
            y = x + step * f;
            bool fresh = false, converged = false;
            for (int attempt = 0; attempt < 2 && !converged; ++attempt) {
                mid = (x + y) / 2;
                system.jacobian(tm, mid.data(), jacobian.data());
                ++result.jacobians;
                // Eigen is column-major; the system gives row-major: use the transpose.
                lu.compute(identity - (step / 2) * jacobian.transpose());
                fresh = true;
                for (int iteration = 0; iteration < 12; ++iteration) {
                    mid = (x + y) / 2;
                    run.rhs(tm, mid.data(), f.data());
                    residual = y - x - step * f;
                    Eigen::VectorXd delta = lu.solve(residual);
                    y -= delta;
                    if (!delta.allFinite())
                        break;
                    if (delta.lpNorm<Eigen::Infinity>() <= 4e-16 * (1 + y.lpNorm<Eigen::Infinity>())) {
                        converged = true;
                        break;
                    }
                }
            }
            if (!converged || !fresh)
                throw computation_error("implicit midpoint: Newton's method did not converge at t = " +
                                        message_number(t) + " (the step " + message_number(step) + " is too large)");
            x = y;
            t += step;
            ++result.steps;
        }
        t = times[k];
        run.observe(t, x.data());
    }
}

} // namespace

trajectory integrate(const ode_system& system, ode_method method, const std::vector<double>& x0,
                     const integration_options& options)
{
    if (x0.size() != system.dimension)
        throw std::invalid_argument("the initial state has " + std::to_string(x0.size()) + " entries, not " +
                                    std::to_string(system.dimension));
    if (!(options.until > options.start))
        throw std::invalid_argument("the end time must be after the start time");
    if ((method == ode_method::bdf || method == ode_method::implicit_midpoint) && !system.jacobian)
        throw std::invalid_argument(to_string(method) + " needs the system's Jacobian");
    trajectory result;
    result.method = to_string(method);
    // The tolerance asked for is a target for the global relative error; each method's
    // per-step tolerance is tightened by the factor its global error was found to exceed
    // the per-step tolerance by on the harmonic oscillator over ten periods (Fehlberg 7(8)
    // only on its own steps: ending a step at each output time keeps it within the
    // tolerance). DOP853's ÷12 comes from a longer run, the linearized double pendulum over
    // 32 periods, where ÷10 missed the tolerance.
    integration_options tightened = options;
    switch (method) {
    case ode_method::dopri5:
    case ode_method::bulirsch_stoer: tightened.tolerance = std::max(options.tolerance / 100, 1e-15); break;
    case ode_method::bdf: tightened.tolerance = std::max(options.tolerance / 3000, 1e-14); break;
    case ode_method::implicit_midpoint: tightened.tolerance = options.tolerance / 4; break;
    case ode_method::dop853: tightened.tolerance = std::max(options.tolerance / 12, 1e-15); break;
    case ode_method::rkf78:
        if (!options.outputs)
            tightened.tolerance = std::max(options.tolerance / 10, 1e-15);
        break;
    }
    run_state run(system, tightened, result);
    const integration_options& options_used = tightened;
    switch (method) {
    case ode_method::bdf:
        run_cvode(system, x0, options_used, run, result);
        break;
    case ode_method::implicit_midpoint:
        run_implicit_midpoint(system, x0, options_used, run, result);
        break;
    case ode_method::dop853:
        run_dop853(x0, options_used, run, result);
        break;
    default:
        run_odeint(method, x0, options_used, run, result);
    }
    run.finish();
    return result;
}

trajectory integrate_at(const ode_system& system, ode_method method, const std::vector<double>& x0,
                        integration_options options, const std::vector<double>& times)
{
    if (times.empty())
        throw std::invalid_argument("no output times");
    options.until = times.back();
    options.times = times;
    options.outputs = true;
    return integrate(system, method, x0, options);
}

double trajectory_difference(const trajectory& a, const trajectory& b)
{
    if (a.states.size() != b.states.size())
        throw std::invalid_argument("the trajectories have different output times");
    double difference = 0, size = 0;
    for (std::size_t k = 0; k < a.states.size(); ++k) {
        const std::vector<double>&x = a.states[k], &y = b.states[k];
        difference = std::max(difference, euclidean_norm(x.size(), [&](std::size_t i) { return x[i] - y[i]; }));
        size = std::max(size, euclidean_norm(y.size(), [&](std::size_t i) { return y[i]; }));
    }
    return size > 0 ? difference / size : difference;
}

} // namespace lagrange
