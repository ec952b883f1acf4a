// SPDX-License-Identifier: GPL-2.0-or-later
/** @file model.cpp
 *  Product names and the model's symbol lists. */
#include "core/model.h"
#include "core/names.h"

namespace lagrange {

const std::vector<std::pair<product, std::string>>& product_names()
{
    static const std::vector<std::pair<product, std::string>> names = {
        {product::equations, "equations"},
        {product::equilibrium, "equilibrium"},
        {product::linearization, "linearization"},
        {product::characteristic, "characteristic"},
        {product::frequencies, "frequencies"},
        {product::modes, "modes"},
        {product::normal_coordinates, "normal_coordinates"},
        {product::asymptotic, "asymptotic"},
        {product::numeric, "numeric"},
        {product::inertia, "inertia"},
        {product::euler, "euler"},
        {product::simulation, "simulation"},
        {product::workprecision, "workprecision"},
        {product::floquet, "floquet"},
        {product::damping, "damping"},
        {product::state_space, "state_space"},
        {product::transfer, "transfer"},
        {product::conserved, "conserved"},
        {product::hamiltonian, "hamiltonian"},
        {product::reduced, "reduced"},
        {product::multipliers, "multipliers"},
        {product::eliminated, "eliminated"},
        {product::gyroscopic, "gyroscopic"},
        {product::verification, "verification"},
    };
    return names;
}

std::optional<product> product_from_name(const std::string& name)
{
    for (const auto& [p, n] : product_names())
        if (n == name)
            return p;
    return std::nullopt;
}

GiNaC::lst model::positions() const
{
    GiNaC::lst result;
    for (const coordinate& c : coordinates)
        result.append(c.position);
    return result;
}

GiNaC::lst model::velocities() const
{
    GiNaC::lst result;
    for (const coordinate& c : coordinates)
        result.append(c.velocity);
    return result;
}

GiNaC::lst model::accelerations() const
{
    GiNaC::lst result;
    for (const coordinate& c : coordinates)
        result.append(c.acceleration);
    return result;
}

bool model::has_generalized_forces() const
{
    return !dissipation.is_zero() || !dampers.empty() || !forces.empty() || !point_forces.empty() ||
           !inputs.empty();
}

GiNaC::exmap value_map(const model& scene, const value_point& point)
{
    GiNaC::exmap map;
    for (const auto& [name, value] : point.values)
        for (const parameter& p : scene.parameters)
            if (p.name == name)
                map[p.symbol] = value;
    return map;
}

std::string unused_name(const model& scene, std::string base)
{
    auto taken = [&](const std::string& name) {
        for (const parameter& p : scene.parameters)
            if (p.name == name)
                return true;
        for (const coordinate& c : scene.coordinates)
            if (c.name == name)
                return true;
        for (const input_signal& u : scene.inputs)
            if (u.name == name)
                return true;
        return scene.ratio && scene.ratio->name == name;
    };
    while (taken(base))
        base += "_";
    return base;
}

std::vector<std::string> coordinate_names(const model& scene)
{
    std::vector<std::string> names;
    for (const coordinate& c : scene.coordinates)
        names.push_back(c.name);
    return names;
}

std::vector<std::string> parameter_names(const model& scene)
{
    std::vector<std::string> names;
    for (const parameter& p : scene.parameters)
        names.push_back(p.name);
    return names;
}

} // namespace lagrange
