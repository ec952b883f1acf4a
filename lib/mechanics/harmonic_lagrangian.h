// SPDX-License-Identifier: GPL-2.0-or-later
/** @file harmonic_lagrangian.h
 *  L as a harmonic polynomial (algebra/harmonic.h) over a scene's symbols: built once
 *  by derive_lagrangian, differentiated by the equations of motion. Internal to mechanics/. */
#pragma once

#include "algebra/harmonic.h"
#include "core/model.h"

#include <ginac/ginac.h>

#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace lagrange {

/// True if every entry of `list` is a symbol (harmonic spaces need symbols as angles).
inline bool all_symbols(const GiNaC::lst& list)
{
    for (const GiNaC::ex& e : list)
        if (!GiNaC::is_a<GiNaC::symbol>(e))
            return false;
    return true;
}

/// L as a harmonic polynomial over the symbols of a scene, with the index pairs
/// (q, q̇), (q̇, q̈) and the index of t for the total time derivative.
struct harmonic_lagrangian {
    harmonic_lagrangian(const model& scene, const GiNaC::lst& angles) : space(angles), lagrangian(space)
    {
        time = space.add_symbol(scene.time);
        for (const coordinate& c : scene.coordinates) {
            const std::size_t velocity = space.add_symbol(c.velocity);
            rates.emplace_back(space.add_symbol(c.position), velocity);
            rates.emplace_back(velocity, space.add_symbol(c.acceleration));
        }
        for (const parameter& p : scene.parameters)
            space.add_symbol(p.symbol);
    }

    /// L in harmonic form if `l` converts, else nullptr.
    static std::shared_ptr<harmonic_lagrangian> of(const model& scene, const GiNaC::lst& angles, const GiNaC::ex& l)
    {
        if (!all_symbols(angles))
            return nullptr;
        auto h = std::make_shared<harmonic_lagrangian>(scene, angles);
        if (!h->space.add_symbols_of(l))
            return nullptr;
        std::optional<harmonic_polynomial> p = to_harmonic(l, h->space);
        if (!p)
            return nullptr;
        h->lagrangian = std::move(*p);
        return h;
    }

    /// True if no term has a negative power of t, a coordinate, velocity or acceleration
    /// (the condition under which the expanded derivatives stay in canonical form).
    bool is_polynomial_in_motion() const
    {
        std::vector<bool> moves(space.symbol_count(), false);
        moves[time] = true;
        for (const auto& [variable, rate] : rates)
            moves[variable] = moves[rate] = true;
        for (std::size_t i = 0; i < lagrangian.size(); ++i) {
            const harmonic_term t = lagrangian.term(i);
            for (std::size_t s = 0; s < lagrangian.symbol_count(); ++s)
                if (moves[s] && t.exponents[s] < 0)
                    return false;
        }
        return true;
    }

    harmonic_space space;
    std::vector<std::pair<std::size_t, std::size_t>> rates;
    std::size_t time = 0;
    harmonic_polynomial lagrangian;
};

} // namespace lagrange
