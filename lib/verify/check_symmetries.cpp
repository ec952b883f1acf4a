// SPDX-License-Identifier: GPL-2.0-or-later
/** @file check_symmetries.cpp
 *  Numeric checks of the symmetries against the Lagrangian as built. */
#include "verify/check_symmetries.h"

#include "program/double_double.h"
#include "program/expression_program.h"
#include "numeric/values.h"

#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace lagrange {

namespace {

using GiNaC::ex;

/// Agreement asked of a symbolic result and its finite-difference reference, relative to
/// the size of the terms compared (the reference is good to about 1e-12).
constexpr double tolerance = 1e-7;
constexpr double step = 0x1p-12;
constexpr int states_per_point = 3;
constexpr int parameter_points = 2;

/// A seeded sequence of multiples of 1/64: the same points, and messages, on every run.
class sampler {
public:
    double uniform(double lo, double hi)
    {
        state_ = state_ * 6364136223846793005ULL + 1442695040888963407ULL;
        return lo + (hi - lo) * static_cast<double>((state_ >> 33) % 65) / 64;
    }

private:
    std::uint64_t state_ = 0x73796d6d65747279ULL; // "symmetry"
};

/// L as built, compiled over (q, q̇, t, parameters), with finite-difference derivatives.
class reference {
public:
    reference(const model& scene, const lagrangian_result& lagrangian) : n_(scene.coordinates.size())
    {
        for (const coordinate& c : scene.coordinates)
            symbols_.push_back(c.position);
        for (const coordinate& c : scene.coordinates)
            symbols_.push_back(c.velocity);
        symbols_.push_back(scene.time);
        for (const parameter& p : scene.parameters)
            symbols_.push_back(p.symbol);
        ex l = lagrangian.kinetic_built - lagrangian.potential_built;
        if (scene.lagrangian_terms)
            l += *scene.lagrangian_terms;
        program_ = expression_program({l}, symbols_);
    }
    const std::vector<ex>& symbols() const { return symbols_; }
    double value(const std::vector<double>& x) const { return to_double(run(x)); }
    /// ∂L/∂x_k by fourth-order central differences in double-double.
    double derivative(std::vector<double> x, std::size_t k) const
    {
        const double x0 = x[k];
        const double offsets[4] = {-2, -1, 1, 2}, weights[4] = {1, -8, 8, -1};
        double_double sum;
        for (int j = 0; j < 4; ++j) {
            x[k] = x0 + offsets[j] * step;
            sum = dd::add(sum, dd::mul(run(x), double_double{weights[j], 0}));
        }
        return to_double(dd::div(sum, double_double{12 * step, 0}));
    }
    double momentum(const std::vector<double>& x, std::size_t i) const { return derivative(x, n_ + i); }
    double force(const std::vector<double>& x, std::size_t i) const { return derivative(x, i); }

private:
    double_double run(const std::vector<double>& x) const
    {
        double_double out;
        program_.run(x.data(), scratch_, &out);
        return out;
    }
    static double to_double(double_double x) { return x.hi + x.lo; }
    std::size_t n_;
    std::vector<ex> symbols_;
    expression_program program_;
    mutable std::vector<double_double> scratch_;
};

/// e at the values (symbols matched by identity); nothing if it is not a real number.
std::optional<double> value_at(const ex& e, const GiNaC::exmap& at)
{
    try {
        const ex v = e.subs(at).evalf();
        if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real())
            return std::nullopt;
        const double x = GiNaC::ex_to<GiNaC::numeric>(v).to_double();
        return std::isfinite(x) ? std::optional<double>(x) : std::nullopt;
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

struct check_point {
    std::vector<double> x; ///< (q, q̇, t, parameters)
    GiNaC::exmap map;
    std::string text;
};

class checker {
public:
    checker(const model& scene, const lagrangian_result& lagrangian) : scene_(scene), l_(scene, lagrangian) {}

    /// Parameter values (the first `values` line's, else seeded ones in [1/2, 2]) and a
    /// seeded state in [−1, 1]; `fix` may overwrite entries of x before the map is made.
    std::vector<check_point> points(const std::function<bool(check_point&)>& fix = {})
    {
        std::vector<check_point> all;
        GiNaC::exmap given;
        if (!scene_.values.empty())
            given = value_map(scene_, scene_.values.front());
        const std::size_t n = scene_.coordinates.size();
        for (int p = 0; p < parameter_points; ++p)
            for (int s = 0; s < states_per_point; ++s) {
                check_point point;
                for (std::size_t i = 0; i < 2 * n; ++i)
                    point.x.push_back(random_.uniform(-1, 1));
                point.x.push_back(random_.uniform(0, 1));
                for (const parameter& q : scene_.parameters) {
                    double v = random_.uniform(0.5, 2);
                    auto found = given.find(q.symbol);
                    if (p == 0 && found != given.end())
                        if (std::optional<double> x = value_at(found->second, {}))
                            v = *x;
                    point.x.push_back(v);
                }
                if (fix && !fix(point))
                    continue;
                make_map(point);
                all.push_back(point);
            }
        return all;
    }
    void make_map(check_point& point) const
    {
        point.map.clear();
        point.text.clear();
        const std::vector<ex>& symbols = l_.symbols();
        for (std::size_t k = 0; k < symbols.size(); ++k) {
            point.map[symbols[k]] = GiNaC::numeric(point.x[k]);
            if (k < 2 * scene_.coordinates.size() || k > 2 * scene_.coordinates.size())
                point.text += (point.text.empty() ? "" : ", ") + GiNaC::ex_to<GiNaC::symbol>(symbols[k]).get_name() +
                              " = " + message_number(point.x[k]);
        }
    }
    const reference& l() const { return l_; }
    std::size_t n() const { return scene_.coordinates.size(); }
    std::size_t parameter_index(const ex& symbol) const
    {
        for (std::size_t k = 0; k < scene_.parameters.size(); ++k)
            if (symbol.is_equal(scene_.parameters[k].symbol))
                return 2 * n() + 1 + k;
        return static_cast<std::size_t>(-1);
    }

private:
    const model& scene_;
    reference l_;
    sampler random_;
};

/// Compares a symbolic value with its reference; returns false (not checkable) when the
/// symbolic one is not a real number there, throws when they disagree.
bool compare(const std::string& item, const std::string& what, const ex& symbolic, const GiNaC::exmap& at,
             double expected, double scale, const std::string& where)
{
    std::optional<double> got = value_at(symbolic, at);
    if (!got)
        return false;
    if (std::abs(*got - expected) > tolerance * (1 + scale))
        throw computation_error("verification failed: " + item + ": " + what + " at " + where + " is " +
                                message_number(*got, 10) + ", but " + message_number(expected, 10) +
                                " by the independent check; the result is not printed");
    return true;
}

std::string how(int checked, const std::string& what)
{
    if (checked == 0)
        return "not checked: no point where the result is a real number";
    return what + " by finite differences of L as built, at " + std::to_string(checked) + " points";
}

} // namespace

void check_symmetries(const model& scene, const lagrangian_result& lagrangian, const symmetry_input& input,
                      std::vector<verification_entry>& entries)
{
    if (!input.conserved && !input.hamiltonian && !input.reduced && !input.steady)
        return;
    checker c(scene, lagrangian);
    const std::size_t n = c.n();
    const reference& l = c.l();
    if (input.conserved) {
        int checked = 0;
        for (check_point& p : c.points()) {
            double h = -l.value(p.x), scale = std::abs(h);
            for (std::size_t i = 0; i < n; ++i) {
                h += p.x[n + i] * l.momentum(p.x, i);
                scale += std::abs(p.x[n + i] * l.momentum(p.x, i));
            }
            bool ok = true;
            if (input.conserved->energy)
                ok = compare("conserved", "h", *input.conserved->energy, p.map, h, scale, p.text) && ok;
            for (std::size_t k = 0; k < input.conserved->cyclic.size(); ++k) {
                const std::size_t i = input.conserved->cyclic[k];
                const double momentum = l.momentum(p.x, i);
                ok = compare("conserved", "p_" + scene.coordinates[i].name, input.conserved->momenta[k], p.map,
                             momentum, std::abs(momentum), p.text) && ok;
                // Cyclic: ∂L/∂q = 0.
                ok = compare("conserved", "∂L/∂" + scene.coordinates[i].name, 0, p.map, l.force(p.x, i), scale,
                             p.text) && ok;
            }
            checked += ok;
        }
        entries.push_back({"conserved", how(checked, "h = Σ q̇ ∂L/∂q̇ − L, p = ∂L/∂q̇ and ∂L/∂q = 0 for the cyclic q"),
                           checked > 0});
    }
    if (input.hamiltonian) {
        const hamiltonian_result& h = *input.hamiltonian;
        int checked = 0;
        for (check_point& p : c.points()) {
            double energy = -l.value(p.x), scale = std::abs(energy);
            std::vector<double> momenta;
            for (std::size_t i = 0; i < n; ++i) {
                momenta.push_back(l.momentum(p.x, i));
                energy += p.x[n + i] * momenta[i];
                scale += std::abs(p.x[n + i] * momenta[i]);
            }
            GiNaC::exmap at = p.map;
            for (std::size_t i = 0; i < n; ++i) {
                at.erase(scene.coordinates[i].velocity);
                at[h.momenta[i]] = GiNaC::numeric(momenta[i]);
            }
            bool ok = compare("hamiltonian", "H(q, p(q, q̇))", h.hamiltonian, at, energy, scale, p.text);
            for (std::size_t i = 0; i < n; ++i) {
                ok = compare("hamiltonian", "∂H/∂p_" + scene.coordinates[i].name, h.velocities[i], at, p.x[n + i],
                             std::abs(p.x[n + i]), p.text) && ok;
                const double force = l.force(p.x, i);
                ok = compare("hamiltonian", "−∂H/∂" + scene.coordinates[i].name, h.forces[i], at, force,
                             scale + std::abs(force), p.text) && ok;
            }
            checked += ok;
        }
        entries.push_back({"hamiltonian",
                           how(checked, "H(q, p(q, q̇)) = h(q, q̇), ∂H/∂p = q̇ and −∂H/∂q = ∂L/∂q with p = ∂L/∂q̇"),
                           checked > 0});
    }
    if (input.reduced) {
        const reduced_result& r = *input.reduced;
        int checked = 0;
        for (check_point& p : c.points()) {
            GiNaC::exmap at = p.map;
            double routhian = l.value(p.x), scale = std::abs(routhian);
            for (std::size_t k = 0; k < r.cyclic.size(); ++k) {
                const std::size_t i = r.cyclic[k];
                const double momentum = l.momentum(p.x, i);
                routhian -= momentum * p.x[n + i];
                scale += std::abs(momentum * p.x[n + i]);
                at.erase(scene.coordinates[i].velocity);
                at[r.momenta[k]] = GiNaC::numeric(momentum);
            }
            bool ok = compare("reduced", "R", r.routhian, at, routhian, scale, p.text);
            // With the kept coordinates at rest, R = −V_eff.
            std::vector<double> rest = p.x;
            for (std::size_t i : r.kept)
                rest[n + i] = 0;
            double at_rest = l.value(rest), rest_scale = std::abs(at_rest);
            GiNaC::exmap rest_at = at;
            for (std::size_t k = 0; k < r.cyclic.size(); ++k) {
                const std::size_t i = r.cyclic[k];
                const double momentum = l.momentum(rest, i);
                at_rest -= momentum * rest[n + i];
                rest_scale += std::abs(momentum * rest[n + i]);
                rest_at[r.momenta[k]] = GiNaC::numeric(momentum);
            }
            ok = compare("reduced", "V_eff", -r.effective_potential, rest_at, at_rest, rest_scale, p.text) && ok;
            checked += ok;
        }
        entries.push_back({"reduced", how(checked, "R = L − Σ p_c q̇_c and V_eff = −R at rest, with p_c = ∂L/∂q̇_c"),
                           checked > 0});
    }
    if (input.steady) {
        const steady_motion_result& m = *input.steady;
        int checked = 0;
        // The motion at each point: the solved unknown from the others, then a0 and the rates.
        auto fix = [&](check_point& p) {
            c.make_map(p);
            for (const auto& [symbol, value] : m.solution) {
                const std::size_t k = c.parameter_index(symbol);
                if (k == static_cast<std::size_t>(-1))
                    continue;
                std::optional<double> v = value_at(value, p.map);
                if (!v || *v <= 0)
                    return false;
                p.x[k] = *v;
            }
            c.make_map(p);
            GiNaC::exmap rates = p.map;
            for (const auto& [symbol, value] : m.solution)
                if (c.parameter_index(symbol) == static_cast<std::size_t>(-1))
                    rates[symbol] = value.subs(p.map);
            for (std::size_t i = 0; i < 2 * n; ++i)
                p.x[i] = 0;
            for (std::size_t k = 0; k < m.kept.size(); ++k) {
                std::optional<double> v = value_at(m.position[k], p.map);
                if (!v)
                    return false;
                p.x[m.kept[k]] = *v;
            }
            for (std::size_t k = 0; k < m.cyclic.size(); ++k) {
                std::optional<double> v = value_at(m.rates[k].subs(rates), p.map);
                if (!v)
                    return false;
                p.x[n + m.cyclic[k]] = *v;
            }
            return true;
        };
        for (check_point& p : c.points(fix)) {
            double scale = std::abs(l.value(p.x));
            for (std::size_t i = 0; i < n; ++i)
                scale += std::abs(p.x[n + i] * l.momentum(p.x, i));
            bool ok = true;
            for (std::size_t i : m.kept)
                ok = compare("steady_motion", "∂L/∂" + scene.coordinates[i].name, 0, p.map, l.force(p.x, i), scale,
                             p.text) && ok;
            for (std::size_t k = 0; k < m.cyclic.size(); ++k) {
                const double momentum = l.momentum(p.x, m.cyclic[k]);
                ok = compare("steady_motion", "p_" + scene.coordinates[m.cyclic[k]].name, m.momenta[k], p.map,
                             momentum, std::abs(momentum), p.text) && ok;
            }
            checked += ok;
        }
        entries.push_back({"steady_motion",
                           how(checked, "∂L/∂q = 0 for the coordinates at rest and p_c = ∂L/∂q̇_c at the motion"),
                           checked > 0});
    }
}

} // namespace lagrange
