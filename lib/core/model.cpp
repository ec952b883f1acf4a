// SPDX-License-Identifier: GPL-2.0-or-later
/** @file model.cpp
 *  Product names and the model's symbol lists. */
#include "core/model.h"
#include "core/names.h"

namespace lagrange {

void initial_state::merge(const initial_state& later)
{
    for (const auto& [name, value] : later.positions)
        positions[name] = value;
    for (const auto& [name, value] : later.velocities)
        velocities[name] = value;
    for (const auto& [name, value] : later.others)
        others[name] = value;
    for (const auto& [name, written] : later.position_written)
        position_written[name] = written;
    for (const auto& [name, written] : later.velocity_written)
        velocity_written[name] = written;
    statement = later.statement;
}

const std::vector<std::pair<product, std::string>>& product_names()
{
    static const std::vector<std::pair<product, std::string>> names = {
#define LAGRANGE_PRODUCT(id, name, scope, by_default) {product::id, name},
#include "core/products.inc"
#undef LAGRANGE_PRODUCT
    };
    return names;
}

const std::string& name_of(product p)
{
    return product_names().at(static_cast<std::size_t>(p)).second;
}

bool needs_coordinates(product p)
{
    constexpr bool coordinates = true, any = false;
    static const std::vector<bool> needs = {
#define LAGRANGE_PRODUCT(id, name, scope, by_default) scope,
#include "core/products.inc"
#undef LAGRANGE_PRODUCT
    };
    return needs.at(static_cast<std::size_t>(p));
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

const rigid_body* body_named(const model& scene, const std::string& name)
{
    for (const rigid_body& b : scene.bodies)
        if (b.name == name)
            return &b;
    return nullptr;
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
