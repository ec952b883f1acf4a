// SPDX-License-Identifier: GPL-2.0-or-later
/** @file values.cpp
 *  Expressions at the parameter values as doubles, numbers for messages, merged values. */
#include "numeric/values.h"

#include "core/number_text.h"

#include "core/errors.h"
#include "core/model.h"

#include <cln/cln.h>

#include <cmath>
#include <cstdio>

namespace lagrange {

double real_value(const GiNaC::ex& e, const std::string& what)
{
    GiNaC::ex value = e.evalf();
    if (!GiNaC::is_a<GiNaC::numeric>(value) || !GiNaC::ex_to<GiNaC::numeric>(value).is_real())
        throw computation_error(what + " is not a real number");
    double d = GiNaC::ex_to<GiNaC::numeric>(value).to_double();
    if (!std::isfinite(d))
        throw computation_error(what + " is not a finite number");
    return d;
}

std::optional<std::complex<double>> complex_at(const GiNaC::ex& e, const GiNaC::exmap& at)
{
    GiNaC::ex value;
    try {
        value = e.subs(at).evalf();
    } catch (const std::exception&) {
        return std::nullopt;
    }
    if (!GiNaC::is_a<GiNaC::numeric>(value))
        return std::nullopt;
    const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(value);
    const std::complex<double> z(GiNaC::real(n).to_double(), GiNaC::imag(n).to_double());
    if (!std::isfinite(z.real()) || !std::isfinite(z.imag()))
        return std::nullopt;
    return z;
}

std::optional<double> real_at(const GiNaC::ex& e, const GiNaC::exmap& at)
{
    std::optional<std::complex<double>> z = complex_at(e, at);
    if (!z || std::abs(z->imag()) > 1e-12 * (1 + std::abs(z->real())))
        return std::nullopt;
    return z->real();
}

std::string message_number(double x, int digits)
{
    return significant(x, digits);
}

std::map<std::string, GiNaC::ex> merged_values(const model& scene)
{
    std::map<std::string, GiNaC::ex> values;
    for (const value_point& point : scene.values) {
        for (const auto& [name, value] : point.values)
            values[name] = value;
        for (const auto& [name, value] : point.inputs)
            values[name] = value;
    }
    return values;
}

namespace {

GiNaC::numeric exact_number(const GiNaC::numeric& n)
{
    if (n.is_rational())
        return n;
    const cln::cl_N z = n.to_cl_N();
    return GiNaC::numeric(cln::complex(cln::rational(cln::realpart(z)), cln::rational(cln::imagpart(z))));
}

struct exact_numbers_map : GiNaC::map_function {
    GiNaC::ex operator()(const GiNaC::ex& e) override
    {
        if (GiNaC::is_a<GiNaC::numeric>(e))
            return exact_number(GiNaC::ex_to<GiNaC::numeric>(e));
        return e.map(*this);
    }
};

} // namespace

GiNaC::ex exact_numbers(const GiNaC::ex& e)
{
    exact_numbers_map exact;
    return exact(e);
}

GiNaC::ex at_values(const GiNaC::ex& e, const model& scene, const std::map<std::string, GiNaC::ex>& values)
{
    GiNaC::exmap inputs;
    for (const input_signal& u : scene.inputs) {
        auto found = values.find(u.name);
        if (found == values.end()) {
            scene_error error(u.where, "input `" + u.name + "` has no value: give it in a `values` line, "
                                       "as a number or an expression in t (`values " + u.name + " = sin(2*t)`)");
            error.attach_line_text(u.line_text);
            throw error;
        }
        inputs[u.symbol] = exact_numbers(found->second);
    }
    GiNaC::ex with_inputs = inputs.empty() ? e : e.subs(inputs);
    GiNaC::lst substitutions;
    for (const parameter& p : scene.parameters) {
        auto found = values.find(p.name);
        if (found != values.end())
            substitutions.append(p.symbol == exact_numbers(found->second));
        else if (with_inputs.has(p.symbol))
            throw computation_error("the simulation needs a value for the parameter `" + p.name +
                                    "` (a `values` line or --values)");
    }
    return with_inputs.subs(substitutions);
}

} // namespace lagrange
