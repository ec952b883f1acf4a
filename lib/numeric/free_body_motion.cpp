// SPDX-License-Identifier: GPL-2.0-or-later
/** @file free_body_motion.cpp
 *  A free body's Euler equations compiled for time integration. */
#include "numeric/free_body_motion.h"

#include "numeric/values.h"

#include <cmath>
#include <stdexcept>

namespace lagrange {

namespace {

GiNaC::exmap parameter_map(const model& scene, const std::map<std::string, GiNaC::ex>& values)
{
    GiNaC::exmap map;
    for (const parameter& p : scene.parameters) {
        auto found = values.find(p.name);
        if (found != values.end())
            map[p.symbol] = found->second;
    }
    return map;
}

/// Throws computation_error naming the first parameter that `e` still has.
void require_values(const GiNaC::ex& e, const model& scene)
{
    for (const parameter& p : scene.parameters)
        if (e.has(p.symbol))
            throw computation_error("the simulation needs a value for the parameter `" + p.name +
                                    "` (a `values` line or --values)");
}

} // namespace

bool has_free_body(const model& scene)
{
    if (!scene.coordinates.empty())
        return false;
    for (const rigid_body& b : scene.bodies)
        if (b.omega)
            return true;
    return false;
}

free_body_motion::free_body_motion(const model& scene, const std::map<std::string, GiNaC::ex>& values)
{
    const rigid_body* found = nullptr;
    for (const rigid_body& b : scene.bodies) {
        if (!b.omega)
            continue;
        if (found)
            throw computation_error("the simulation integrates one free body; the scene has `" + found->name +
                                    "` and `" + b.name + "`");
        found = &b;
    }
    if (!found)
        throw computation_error("the scene has no free body to simulate (`omega B (w1, w2, w3)`)");
    const rigid_body& body = *found;
    body_ = body.name;
    const GiNaC::exmap map = parameter_map(scene, values);

    // Euler's equations and their torque-free solutions from the rigid-body derivation.
    inertia_result inertia = derive_inertia(body);
    euler_result euler = derive_euler(body, inertia, scene.initial, map);
    torque_free_ = euler.torque_free;

    std::vector<GiNaC::ex> symbols;
    for (const GiNaC::ex& w : euler.omega) {
        names_.push_back(GiNaC::ex_to<GiNaC::symbol>(w).get_name());
        symbols.push_back(w);
    }
    symbols.push_back(scene.time);
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) {
            GiNaC::ex entry = inertia.tensor(i, j).subs(map);
            require_values(entry, scene);
            tensor_[3 * i + j] = real_value(entry, "the inertia of `" + body_ + "`");
        }
    for (const std::string& name : names_) {
        GiNaC::ex start = 0;
        if (scene.initial) {
            auto value = scene.initial->others.find(name);
            if (value != scene.initial->others.end())
                start = value->second.subs(map);
        }
        require_values(start, scene);
        initial_.push_back(real_value(start, "the initial value of `" + name + "`"));
    }

    // ω̇ from the equations, linear in the rates with the constant matrix I at numbers.
    GiNaC::lst equations, rates;
    for (std::size_t i = 0; i < 3; ++i) {
        GiNaC::ex e = euler.equations[i].subs(map);
        require_values(e, scene);
        equations.append(e == 0);
        rates.append(euler.rates[i]);
    }
    GiNaC::ex solved;
    try {
        solved = GiNaC::lsolve(equations, rates);
    } catch (const std::exception&) {
        solved = GiNaC::lst{};
    }
    if (!GiNaC::is_a<GiNaC::lst>(solved) || solved.nops() != 3)
        throw computation_error("Euler's equations of `" + body_ + "` cannot be solved for ω̇ (a singular inertia)");
    std::vector<GiNaC::ex> rhs, jacobian;
    for (std::size_t i = 0; i < 3; ++i)
        rhs.push_back(solved.op(i).rhs());
    for (const GiNaC::ex& f : rhs) {
        time_dependent_ = time_dependent_ || f.has(scene.time);
        for (std::size_t j = 0; j < 3; ++j)
            jacobian.push_back(f.diff(GiNaC::ex_to<GiNaC::symbol>(euler.omega[j])));
    }
    try {
        rhs_program_ = expression_program(rhs, symbols);
        jacobian_program_ = expression_program(jacobian, symbols);
    } catch (const std::invalid_argument& error) {
        throw computation_error(std::string("Euler's equations cannot be compiled: ") + error.what());
    }
    scratch_.reserve(64);

    // The exact solution, when the body axes are principal axes (the solutions are written in them).
    if (!torque_free_ || !inertia.diagonal)
        return;
    if (euler.elliptic) {
        elliptic_ = euler.elliptic;
        exact_kind_ = "the Jacobi elliptic solution";
    } else if (euler.symmetric) {
        std::vector<GiNaC::ex> omega;
        bool numbers = true;
        for (const GiNaC::ex& w : euler.symmetric->omega) {
            GiNaC::ex e = w.subs(map);
            for (const parameter& p : scene.parameters)
                numbers = numbers && !e.has(p.symbol);
            omega.push_back(e);
        }
        if (!numbers)
            return;
        try {
            symmetric_program_ = expression_program(omega, {euler.symmetric->time});
            exact_kind_ = "the symmetric-body closed form";
        } catch (const std::invalid_argument&) {
            // Left without an exact solution; the error is then estimated numerically.
        }
    }
}

void free_body_motion::rhs(double t, const double* w, double* dwdt) const
{
    const double symbols[4] = {w[0], w[1], w[2], t};
    if (native_.rhs)
        native_.rhs(symbols, dwdt);
    else
        rhs_program_.run(symbols, scratch_, dwdt);
}

void free_body_motion::jacobian(double t, const double* w, double* out) const
{
    const double symbols[4] = {w[0], w[1], w[2], t};
    if (native_.jacobian)
        native_.jacobian(symbols, out);
    else
        jacobian_program_.run(symbols, scratch_, out);
}

std::array<double, 3> free_body_motion::exact(double t) const
{
    if (elliptic_)
        return elliptic_->evaluate(t);
    std::array<double, 3> w{};
    std::vector<double> scratch;
    symmetric_program_.run(&t, scratch, w.data());
    return w;
}

bool free_body_motion::compile_native(const native_limits& limits, std::string* why)
{
    return native_.compile(rhs_program_, jacobian_program_, limits, why);
}

ode_system free_body_motion::system() const
{
    ode_system s;
    s.dimension = 3;
    s.rhs = [this](double t, const double* x, double* dxdt) { rhs(t, x, dxdt); };
    s.jacobian = [this](double t, const double* x, double* out) { jacobian(t, x, out); };
    // Without a time-dependent torque the program never reads t: DOP853 then passes it the state
    // itself, not a copy of it with t appended.
    if (native_.rhs)
        s.compiled = ode_system::compiled_rhs{native_.rhs, 0, time_dependent_};
    if (torque_free_) {
        s.invariants.push_back({"energy", [this](const double* w) {
                                    double e = 0;
                                    for (int i = 0; i < 3; ++i)
                                        for (int j = 0; j < 3; ++j)
                                            e += 0.5 * w[i] * tensor_[3 * i + j] * w[j];
                                    return e;
                                }, 0});
        s.invariants.push_back({"angular_momentum_squared", [this](const double* w) {
                                    double l2 = 0;
                                    for (int i = 0; i < 3; ++i) {
                                        double l = 0;
                                        for (int j = 0; j < 3; ++j)
                                            l += tensor_[3 * i + j] * w[j];
                                        l2 += l * l;
                                    }
                                    return l2;
                                }, 0});
    }
    if (!exact_kind_.empty())
        s.exact = [this](double t, double* x) {
            std::array<double, 3> w = exact(t);
            std::copy(w.begin(), w.end(), x);
        };
    return s;
}

} // namespace lagrange
