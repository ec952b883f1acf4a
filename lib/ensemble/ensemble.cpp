// SPDX-License-Identifier: GPL-2.0-or-later
/** @file ensemble.cpp
 *  One ensemble point: the compiled equations integrated by DOP853 and reduced to its
 *  measure (see ensemble.h). */
#include "ensemble/ensemble.h"

#include "numeric/compiled_motion.h"
#include "numeric/dop853.h"
#include "numeric/floquet.h"
#include "numeric/mass_matrix.h"
#include "numeric/values.h"

#include <Eigen/Eigenvalues>

#include <charconv>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace lagrange {

namespace {

constexpr double pi = 3.141592653589793238462643383279502884;

/// SplitMix64 (Steele, Lea, Flood 2014), written out: a counter-based generator, so that
/// the random point k is the same whichever thread or process draws it, with any
/// library and on any platform (std::uniform_real_distribution is not specified bit for bit).
std::uint64_t splitmix64(std::uint64_t x)
{
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

/// Which band (2k − 1)π ≤ q < (2k + 1)π the angle q is in: a flip changes it.
double band(double q) { return std::floor((q + pi) / (2 * pi)); }

std::string shortest(double x)
{
    char buffer[32];
    auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, x);
    return std::string(buffer, end);
}

} // namespace

/// What one integration gives: the measure's values, its steps, and whether it failed.
struct ensemble_problem::run_result {
    std::size_t steps = 0;
    bool failed = false;
    std::string message;
};

namespace {

/// The right-hand side (q̇, q̈) with M q̈ = f, or from a program that writes it (`recursive`),
/// and with `tangents` > 0 also the variational equations v̇ = J v for that many tangent
/// vectors v after the state (M q̈ = f only).
struct point_rhs {
    std::size_t n = 0;
    std::size_t tangents = 0;
    bool recursive = false;
    native_module::function native_rhs = nullptr, native_jacobian = nullptr;
    const expression_program* rhs_program = nullptr;
    const expression_program* jacobian_program = nullptr;
    ensemble_workspace* work = nullptr;

    void evaluate(native_module::function native, const expression_program& program, double* out) const
    {
        if (native)
            native(work->symbols.data(), out);
        else
            program.run(work->symbols.data(), work->scratch, out);
    }

    /// The motion alone (no tangents) with N coordinates known at compile time: the copies
    /// and the mass matrix's solve inline (through operator() they call memmove and loop over
    /// a run-time n, out of line). The same numbers.
    template <std::size_t N>
    [[gnu::always_inline]] void motion(double t, const double* x, double* dxdt) const
    {
        double* symbols = work->symbols.data();
        for (std::size_t i = 0; i < 2 * N; ++i)
            symbols[i] = x[i];
        symbols[2 * N] = t;
        if (recursive)
            return by_recursion(t, x, dxdt, N);
        double* outputs = work->outputs.data();
        evaluate(native_rhs, *rhs_program, outputs);
        for (std::size_t i = 0; i < N; ++i)
            dxdt[i] = x[N + i];
        if (!solve_mass_matrix(outputs, N, work->factor.data(), dxdt + N)) [[unlikely]]
            singular(t, x, 2 * N);
    }

    /// The recursion's program writes dxdt (the symbols set); a q̈ not finite is a zero pivot,
    /// where M is singular.
    [[gnu::always_inline]] void by_recursion(double t, const double* x, double* dxdt, std::size_t coordinates) const
    {
        evaluate(native_rhs, *rhs_program, dxdt);
        for (std::size_t i = coordinates; i < 2 * coordinates; ++i)
            if (!std::isfinite(dxdt[i])) [[unlikely]]
                singular(t, x, 2 * coordinates);
    }

    [[noreturn, gnu::noinline]] static void singular(double t, const double* x, std::size_t size)
    {
        throw computation_error(singular_mass_matrix_message(t, x, size));
    }

    void operator()(double t, const double* x, double* dxdt) const
    {
        double* symbols = work->symbols.data();
        std::copy(x, x + 2 * n, symbols);
        symbols[2 * n] = t;
        if (recursive)
            return by_recursion(t, x, dxdt, n);
        evaluate(native_rhs, *rhs_program, work->outputs.data());
        std::copy(x + n, x + 2 * n, dxdt);
        if (!solve_mass_matrix(work->outputs.data(), n, work->factor.data(), dxdt + n, tangents > 0))
            throw computation_error(singular_mass_matrix_message(t, x, 2 * n));
        if (tangents == 0)
            return;
        // δq̈ = M⁻¹ (∂f/∂q δq + ∂f/∂q̇ δq̇ − Σ_k (∂M/∂q_k δq_k) q̈), M's factor kept from the solve.
        evaluate(native_jacobian, *jacobian_program, work->jacobian.data());
        const double* mass_derivative = work->jacobian.data();   // [k][i][j]: ∂M_ij/∂q_k
        const double* force_position = mass_derivative + n * n * n; // [i][k]: ∂f_i/∂q_k
        const double* force_velocity = force_position + n * n;      // [i][k]: ∂f_i/∂q̇_k
        const double* acceleration = dxdt + n;
        double* column = work->column.data();
        for (std::size_t tangent = 0; tangent < tangents; ++tangent) {
            const double* v = x + 2 * n * (1 + tangent);
            double* v_rate = dxdt + 2 * n * (1 + tangent);
            for (std::size_t i = 0; i < n; ++i) {
                double s = 0;
                for (std::size_t k = 0; k < n; ++k) {
                    s += force_position[i * n + k] * v[k] + force_velocity[i * n + k] * v[n + k];
                    double mass_row = 0;
                    for (std::size_t j = 0; j < n; ++j)
                        mass_row += mass_derivative[(k * n + i) * n + j] * acceleration[j];
                    s -= mass_row * v[k];
                }
                column[i] = s;
            }
            ldlt_solve(work->factor.data(), n, column);
            std::copy(v + n, v + 2 * n, v_rate);
            std::copy(column, column + n, v_rate + n);
        }
    }
};

/// The measure of one run from x0: the state, then the tangent vectors (one for Lyapunov, 2n for Floquet).
template <int Dim, class F>
void run_point_with(F& f, std::size_t n, const ensemble_measure& measure, const ensemble_settings& settings,
                    double until, double tolerance, std::vector<double>& x0, double* values, std::size_t& steps)
{
    dop853_stepper<Dim> stepper(x0.size(), tolerance);
    auto advance = [&](double t_end) {
        if (!stepper.step(f, t_end))
            throw computation_error("the step size of dop853 collapsed at t = " + message_number(stepper.time()));
        if (++steps > settings.max_steps)
            throw computation_error("the run took more than " + std::to_string(settings.max_steps) + " steps");
    };
    stepper.start(f, 0.0, x0.data(), until);
    switch (measure.what) {
    case ensemble_measure::kind::final_state: {
        while (stepper.time() < until)
            advance(until);
        std::copy(stepper.state(), stepper.state() + 2 * n, values);
        return;
    }
    case ensemble_measure::kind::flip_time: {
        const std::size_t first = measure.any ? 0 : measure.coordinate, last = measure.any ? n : measure.coordinate + 1;
        std::vector<double> bands(n);
        for (std::size_t c = first; c < last; ++c)
            bands[c] = band(x0[c]);
        values[0] = std::numeric_limits<double>::infinity();
        std::vector<double> at(x0.size());
        while (stepper.time() < until) {
            const double t_before = stepper.time();
            advance(until);
            const double* x = stepper.state();
            double earliest = std::numeric_limits<double>::infinity();
            for (std::size_t c = first; c < last; ++c) {
                double now = band(x[c]);
                if (now == bands[c])
                    continue;
                // The first crossing of the odd multiple of π next to the old band, by bisection
                // on the dense output (7th order) down to the rounding of t.
                double level = now > bands[c] ? pi * (2 * bands[c] + 1) : pi * (2 * bands[c] - 1);
                double low = t_before, high = stepper.time();
                for (int k = 0; k < 200 && high - low > 4 * std::numeric_limits<double>::epsilon() * high; ++k) {
                    double middle = low + (high - low) / 2;
                    stepper.interpolate(f, middle, at.data());
                    bool crossed = now > bands[c] ? at[c] >= level : at[c] < level;
                    (crossed ? high : low) = middle;
                }
                earliest = std::min(earliest, high);
            }
            if (earliest < std::numeric_limits<double>::infinity()) {
                values[0] = earliest;
                return;
            }
        }
        return;
    }
    case ensemble_measure::kind::max_lyapunov: {
        // Benettin's method: the tangent vector renormalized every `renormalize_every`, the
        // logarithms of its growth summed.
        const double every = std::min(measure.renormalize_every, until);
        double sum = 0;
        std::vector<double> y(x0.size());
        std::size_t interval = 0;
        while (stepper.time() < until) {
            ++interval;
            double t_next = std::min(until, static_cast<double>(interval) * every);
            while (stepper.time() < t_next)
                advance(t_next);
            std::copy(stepper.state(), stepper.state() + x0.size(), y.begin());
            double norm = 0;
            for (std::size_t i = 2 * n; i < 4 * n; ++i)
                norm += y[i] * y[i];
            norm = std::sqrt(norm);
            if (!(norm > 0) || !std::isfinite(norm))
                throw computation_error("the tangent vector vanished or overflowed at t = " + message_number(t_next));
            sum += std::log(norm);
            for (std::size_t i = 2 * n; i < 4 * n; ++i)
                y[i] /= norm;
            if (stepper.time() < until)
                stepper.start(f, stepper.time(), y.data(), until, stepper.step_size());
        }
        values[0] = sum / until;
        return;
    }
    case ensemble_measure::kind::floquet_stable: {
        // The monodromy matrix: the 2n tangent vectors, started as the identity's columns, after one period.
        while (stepper.time() < until)
            advance(until);
        const auto d = static_cast<Eigen::Index>(2 * n);
        Eigen::MatrixXd monodromy(d, d);
        for (Eigen::Index column = 0; column < d; ++column)
            for (Eigen::Index row = 0; row < d; ++row)
                monodromy(row, column) = stepper.state()[static_cast<std::size_t>((1 + column) * d + row)];
        if (!monodromy.allFinite())
            throw computation_error("the monodromy matrix is not finite");
        const Eigen::EigenSolver<Eigen::MatrixXd> solver(monodromy, false);
        if (solver.info() != Eigen::Success)
            throw computation_error("the Floquet multipliers could not be computed");
        double largest = 0;
        for (Eigen::Index k = 0; k < d; ++k)
            largest = std::max(largest, std::abs(solver.eigenvalues()(k)));
        values[0] = largest <= 1 + floquet_tolerance ? 1 : 0;
        values[1] = largest;
        return;
    }
    }
}

/// run_point_with on point_rhs, inlined at a fixed size when the state is (q, q̇) alone.
template <int Dim>
void run_point(const point_rhs& f_in, const ensemble_measure& measure, const ensemble_settings& settings,
               double until, double tolerance, std::vector<double>& x0, double* values, std::size_t& steps)
{
    point_rhs f = f_in;
    if constexpr (Dim > 0 && Dim % 2 == 0) {
        if (f.tangents == 0 && 2 * f.n == static_cast<std::size_t>(Dim)) {
            auto motion = [&f](double t, const double* x, double* dxdt) LAGRANGE_LAMBDA_INLINE {
                f.motion<Dim / 2>(t, x, dxdt);
            };
            return run_point_with<Dim>(motion, f.n, measure, settings, until, tolerance, x0, values, steps);
        }
    }
    run_point_with<Dim>(f, f.n, measure, settings, until, tolerance, x0, values, steps);
}

} // namespace

const std::vector<measure_definition>& measures()
{
    using tangent = measure_definition::tangent_vectors;
    static const std::vector<measure_definition> table = {
        {ensemble_measure::kind::final_state, "final", false, tangent::none, false,
         [](const model& scene) {
             std::vector<std::string> columns;
             for (const coordinate& c : scene.coordinates)
                 columns.push_back("final_" + c.name);
             for (const coordinate& c : scene.coordinates)
                 columns.push_back("final_" + c.name + "_dot");
             return columns;
         }},
        {ensemble_measure::kind::flip_time, "flip_time", true, tangent::none, false,
         [](const model&) { return std::vector<std::string>{"flip_time"}; }},
        {ensemble_measure::kind::max_lyapunov, "max_lyapunov", false, tangent::one, false,
         [](const model&) { return std::vector<std::string>{"max_lyapunov"}; }},
        {ensemble_measure::kind::floquet_stable, "floquet_stable", false, tangent::all, true,
         [](const model&) { return std::vector<std::string>{"floquet_stable", "max_multiplier"}; }},
    };
    return table;
}

const measure_definition& definition_of(ensemble_measure::kind what)
{
    const measure_definition& definition = measures().at(static_cast<std::size_t>(what));
    if (definition.what != what) // the rows are in the order of the kind enum
        throw std::logic_error(std::string("the measures table is out of order at `") + definition.name + "`");
    return definition;
}

ensemble_problem::ensemble_problem(const model& scene, const equations_of_motion& equations,
                                   std::vector<ensemble_axis> axes, const ensemble_measure& measure,
                                   const ensemble_settings& settings, const time_dependence_result* time)
    : axes_(std::move(axes)), measure_(measure), settings_(settings)
{
    n_ = scene.coordinates.size();
    if (n_ == 0)
        throw computation_error("the scene has no coordinates to run an ensemble of");
    if (equations.constraints)
        throw computation_error("ensembles of scenes with constraints are not implemented: eliminate the "
                                "constraints (`want eliminated`) or write the scene in independent coordinates");
    if (!(settings_.until > 0) || !std::isfinite(settings_.until))
        throw std::invalid_argument("the end time of an ensemble must be positive");
    if (axes_.empty())
        throw std::invalid_argument("an ensemble needs at least one grid entry");
    // The points: the grid's product, or the random count.
    if (settings_.random > 0) {
        points_ = settings_.random;
    } else {
        double total = 1;
        for (const ensemble_axis& a : axes_)
            total *= static_cast<double>(a.count);
        if (total > 1e12)
            throw computation_error("the grid has more than 1e12 points");
        points_ = 1;
        for (const ensemble_axis& a : axes_)
            points_ *= a.count;
    }
    sample_every_ = std::max<std::size_t>(1, std::min<std::size_t>(61, points_ / 100));
    for (const ensemble_axis& a : axes_)
        columns_.push_back(a.name);
    const measure_definition& definition = definition_of(measure_.what);
    for (const std::string& column : definition.columns(scene))
        columns_.push_back(column);

    // The gridded parameters stay symbols (after q, q̇ and t); the others take their values.
    std::map<std::string, GiNaC::ex> values = merged_values(scene);
    std::vector<GiNaC::ex> symbols = state_symbols(scene);
    std::vector<GiNaC::ex> parameter_symbols;
    for (const ensemble_axis& a : axes_)
        if (a.kind == ensemble_axis::target::parameter) {
            const parameter& p = scene.parameters[a.index];
            values[p.name] = p.symbol;
            gridded_parameters_.push_back(a.index);
            symbols.push_back(p.symbol);
            parameter_symbols.push_back(p.symbol);
        }
    std::vector<GiNaC::ex> jacobian_outputs, initial_outputs;
    const motion_expressions motion = motion_at_values(scene, equations, values);
    std::vector<GiNaC::ex> rhs_outputs = motion.mass;
    rhs_outputs.insert(rhs_outputs.end(), motion.force.begin(), motion.force.end());
    const bool tangents = definition.tangents != measure_definition::tangent_vectors::none;
    if (tangents)
        jacobian_outputs = motion_jacobian(scene, motion);
    // The scene's initial state (zeros where not given), possibly in the gridded parameters.
    for (int part = 0; part < 2; ++part)
        for (const coordinate& c : scene.coordinates) {
            GiNaC::ex value = 0;
            if (scene.initial) {
                const auto& given = part == 0 ? scene.initial->positions : scene.initial->velocities;
                auto found = given.find(c.name);
                if (found != given.end())
                    value = at_values(found->second, scene, values);
            }
            initial_outputs.push_back(value);
        }
    if (definition.one_period)
        floquet_setup(scene, equations, time, values, parameter_symbols, initial_outputs);
    try {
        std::optional<expression_program> rates;
        if (!tangents && n_ >= recursive_coordinates)
            rates = recursive_rates(scene, equations, values, symbols);
        recursive_ = rates.has_value();
        rhs_program_ = rates ? std::move(*rates) : expression_program(rhs_outputs, symbols);
        jacobian_program_ = expression_program(jacobian_outputs, symbols);
        initial_program_ = expression_program(initial_outputs, parameter_symbols);
    } catch (const std::invalid_argument& error) {
        throw computation_error(std::string("the equations of motion cannot be compiled for the ensemble: ") +
                                error.what());
    }
    if (settings_.native) {
        std::string why;
        std::vector<const expression_program*> programs{&rhs_program_};
        if (tangents)
            programs.push_back(&jacobian_program_);
        native_ = native_module::compile(programs, {}, &why);
        if (native_) {
            native_rhs_ = native_->get(0);
            if (programs.size() > 1)
                native_jacobian_ = native_->get(1);
            evaluation_ = "native code";
        } else {
            evaluation_ = "interpreter (" + why + ")";
        }
    } else {
        evaluation_ = "interpreter (--interpret)";
    }
}

void ensemble_problem::floquet_setup(const model& scene, const equations_of_motion& equations,
                                     const time_dependence_result* time,
                                     const std::map<std::string, GiNaC::ex>& values,
                                     const std::vector<GiNaC::ex>& parameter_symbols,
                                     std::vector<GiNaC::ex>& initial_outputs)
{
    if (!time || !time->depends_on_time || time->points.empty())
        throw computation_error("floquet_stable needs an L periodic in t and a point that solves the equations at "
                                "every t (an `equilibrium` line)");
    for (const ensemble_axis& a : axes_)
        if (a.kind != ensemble_axis::target::parameter)
            throw computation_error("floquet_stable starts at the point that solves the equations at every t: grid "
                                    "parameters only, not `" + a.name + "`");
    // The point, at rest, in place of the initial state.
    const std::vector<GiNaC::ex>& point = time->points.front();
    for (std::size_t i = 0; i < n_; ++i) {
        initial_outputs[i] = at_values(point[i], scene, values);
        initial_outputs[n_ + i] = 0;
    }
    // The period: 2π q / |ω₀|, q the common denominator of ω_j/ω₀, which must not depend on the grid.
    const std::vector<GiNaC::ex> frequencies =
        drive_frequencies(scene, equations, linearize_about(scene, equations, point));
    if (frequencies.empty())
        throw computation_error("L does not depend on t, so it has no period");
    long denominators = 1;
    const GiNaC::ex first = at_values(frequencies.front(), scene, values);
    for (std::size_t j = 1; j < frequencies.size(); ++j) {
        const GiNaC::ex ratio = (at_values(frequencies[j], scene, values) / first).normal();
        const std::optional<long> q = frequency_ratio_denominator(ratio);
        if (!q)
            throw computation_error("the drive's frequencies are incommensurate, or their ratio depends on the grid: "
                                    "no common period");
        denominators = std::lcm(denominators, *q);
    }
    period_factor_ = 2 * pi * static_cast<double>(denominators);
    try {
        frequency_program_ = expression_program({first}, parameter_symbols);
    } catch (const std::invalid_argument& error) {
        throw computation_error(std::string("the drive's frequency cannot be compiled: ") + error.what());
    }
}

std::uint64_t ensemble_problem::signature() const
{
    std::ostringstream text;
    for (const std::string& c : columns_)
        text << c << ',';
    text << points_ << ',' << shortest(settings_.until) << ',' << shortest(settings_.tolerance) << ','
         << settings_.random << ',' << settings_.seed << ',' << (native_ ? 1 : 0) << ',' << rhs_program_.instruction_count();
    for (const ensemble_axis& a : axes_)
        text << ',' << shortest(a.from) << ',' << shortest(a.to) << ',' << a.count << ',' << a.logarithmic;
    std::uint64_t hash = 0;
    for (char c : text.str())
        hash = splitmix64(hash ^ static_cast<unsigned char>(c));
    return hash;
}

void ensemble_problem::grid_values(std::size_t index, double* values) const
{
    if (settings_.random > 0) {
        for (std::size_t a = 0; a < axes_.size(); ++a) {
            std::uint64_t bits = splitmix64(splitmix64(settings_.seed) + index * axes_.size() + a);
            values[a] = axes_[a].sample(static_cast<double>(bits >> 11) * 0x1p-53);
        }
        return;
    }
    std::size_t rest = index;
    for (std::size_t a = axes_.size(); a-- > 0;) {
        values[a] = axes_[a].at(rest % axes_[a].count);
        rest /= axes_[a].count;
    }
}

std::string ensemble_problem::point_text(std::size_t index) const
{
    std::vector<double> values(axes_.size());
    grid_values(index, values.data());
    std::string text;
    for (std::size_t a = 0; a < axes_.size(); ++a)
        text += (a ? ", " : "") + axes_[a].name + " = " + shortest(values[a]);
    return text;
}

ensemble_problem::run_result ensemble_problem::integrate(const double* x_start, double tolerance,
                                                          ensemble_workspace& work) const
{
    const std::size_t n = n_;
    std::size_t tangents = 0;
    std::vector<double> x0(x_start, x_start + 2 * n);
    double until = settings_.until;
    const measure_definition& definition = definition_of(measure_.what);
    if (definition.tangents == measure_definition::tangent_vectors::one) {
        tangents = 1; // the tangent vector starts along (1, 1, …, 1), normalized
        x0.resize(4 * n, 1 / std::sqrt(static_cast<double>(2 * n)));
    } else if (definition.tangents == measure_definition::tangent_vectors::all) {
        tangents = 2 * n; // the identity's columns
        x0.resize(2 * n * (1 + 2 * n), 0.0);
        for (std::size_t k = 0; k < 2 * n; ++k)
            x0[2 * n * (1 + k) + k] = 1;
    }
    if (definition.one_period) {
        double frequency = 0;
        frequency_program_.run(work.parameters.data(), work.scratch, &frequency);
        until = period_factor_ / std::abs(frequency);
    }
    const std::size_t dimension = x0.size();
    point_rhs f;
    f.n = n;
    f.tangents = tangents;
    f.recursive = recursive_;
    f.native_rhs = native_rhs_;
    f.native_jacobian = native_jacobian_;
    f.rhs_program = &rhs_program_;
    f.jacobian_program = &jacobian_program_;
    f.work = &work;
    run_result result;
    double* values = work.outputs.data() + rhs_program_.output_count(); // after M and f
    try {
        if (!(until > 0) || !std::isfinite(until))
            throw computation_error("the period of the drive is not a positive number here");
        switch (dimension) {
        case 2: run_point<2>(f, measure_, settings_, until, tolerance, x0, values, result.steps); break;
        case 4: run_point<4>(f, measure_, settings_, until, tolerance, x0, values, result.steps); break;
        case 6: run_point<6>(f, measure_, settings_, until, tolerance, x0, values, result.steps); break;
        case 8: run_point<8>(f, measure_, settings_, until, tolerance, x0, values, result.steps); break;
        default: run_point<0>(f, measure_, settings_, until, tolerance, x0, values, result.steps); break;
        }
    } catch (const computation_error& error) {
        result.failed = true;
        result.message = error.what();
    }
    return result;
}

void ensemble_problem::prepare(std::size_t index, ensemble_workspace& work, double* row) const
{
    const std::size_t n = n_, grid = axes_.size(), measures = columns_.size() - grid;
    // Workspace sizes (the measure's values live after M and f in `outputs`).
    work.symbols.resize(2 * n + 1 + gridded_parameters_.size());
    work.outputs.resize(rhs_program_.output_count() + measures);
    work.factor.resize(n * n);
    work.jacobian.resize(jacobian_program_.output_count());
    work.column.resize(n);
    work.state.resize(2 * n);
    work.parameters.resize(gridded_parameters_.size());
    grid_values(index, row);
    std::size_t p = 0;
    for (std::size_t a = 0; a < grid; ++a)
        if (axes_[a].kind == ensemble_axis::target::parameter)
            work.parameters[p++] = row[a];
    std::copy(work.parameters.begin(), work.parameters.end(), work.symbols.begin() + static_cast<long>(2 * n + 1));
    initial_program_.run(work.parameters.data(), work.scratch, work.state.data());
    for (std::size_t a = 0; a < grid; ++a) {
        if (axes_[a].kind == ensemble_axis::target::position)
            work.state[axes_[a].index] = row[a];
        else if (axes_[a].kind == ensemble_axis::target::velocity)
            work.state[n + axes_[a].index] = row[a];
    }
}

double ensemble_problem::step_tolerance() const
{
    return std::max(settings_.tolerance / 12, 1e-15); // as simulate's DOP853
}

ensemble_point_stats ensemble_problem::compute(std::size_t index, ensemble_workspace& work, double* row) const
{
    const std::size_t grid = axes_.size(), measures = columns_.size() - grid;
    prepare(index, work, row);
    ensemble_point_stats stats;
    const std::vector<double> start = work.state;
    run_result run = integrate(start.data(), step_tolerance(), work);
    stats.steps = run.steps;
    stats.failed = run.failed;
    double* measure = row + grid;
    const double* values = work.outputs.data() + rhs_program_.output_count();
    for (std::size_t k = 0; k < measures; ++k)
        measure[k] = run.failed ? std::nan("") : values[k];
    if (!run.failed && index % sample_every_ == 0) {
        run_result tight = integrate(start.data(), std::max(step_tolerance() / 1000, 1e-15), work);
        stats.steps += tight.steps;
        if (!tight.failed) {
            stats.sampled = true;
            for (std::size_t k = 0; k < measures; ++k) {
                double a = measure[k], b = values[k];
                double difference = a == b ? 0 : std::abs(a - b); // both infinite (no flip): no error
                stats.error = std::max(stats.error, std::isnan(difference) ? HUGE_VAL : difference);
            }
        }
    }
    return stats;
}

std::string ensemble_problem::failure_message(std::size_t index) const
{
    ensemble_workspace work;
    std::vector<double> row(columns_.size());
    prepare(index, work, row.data());
    const std::vector<double> start = work.state;
    return integrate(start.data(), step_tolerance(), work).message;
}

} // namespace lagrange
