// SPDX-License-Identifier: GPL-2.0-or-later
/** @file top.cpp
 *  The heavy symmetric top by Routh's procedure. */
#include "mechanics/top.h"

#include "algebra/calculus.h"
#include "algebra/factor.h"
#include "algebra/sign.h"
#include "mechanics/equilibrium.h"
#include "mechanics/symmetries.h"

namespace lagrange {

namespace {

/// The steady precession of a top: the quadratic in Ω = φ̇ from ∂L/∂θ = 0 at θ̇ = 0 with
/// ψ̇ = ω3 − Ω cos θ, its two roots, and the nutation frequency about it.
void steady_precession(const model& scene, const lagrangian_result& lagrangian, const coordinate& phi,
                       const coordinate& theta, const coordinate& psi, const GiNaC::matrix& block, top_result& top)
{
    GiNaC::realsymbol precession("Omega");
    top.precession = precession;
    const GiNaC::ex& l = lagrangian.lagrangian_canonical;
    const GiNaC::ex q = theta.position;
    const GiNaC::exmap motion{{theta.velocity, 0}, {phi.velocity, precession},
                              {psi.velocity, top.spin - precession * GiNaC::cos(q)}};
    const GiNaC::ex condition =
        reduce_trigonometric(differentiate(l, theta.position).subs(motion) / GiNaC::sin(q)).normal();
    GiNaC::ex p = condition.numer().expand();
    if (!p.is_polynomial(precession) || p.degree(precession) != 2)
        return;
    std::vector<GiNaC::ex> a{p.coeff(precession, 0), p.coeff(precession, 1), p.coeff(precession, 2)};
    if (sign_of(a[0]) == std::optional<int>(-1))
        for (GiNaC::ex& c : a)
            c = -c;
    for (GiNaC::ex& c : a)
        c = tidy(c);
    top.precession_quadratic = a;
    const GiNaC::ex root = GiNaC::sqrt(tidy((a[1] * a[1] - 4 * a[2] * a[0]).expand()));
    top.slow_precession = (-a[1] - root) / (2 * a[2]);
    top.fast_precession = (-a[1] + root) / (2 * a[2]);

    // V_eff(θ; p_φ, p_ψ) = V + ½ pᵀK⁻¹p, its curvature at the precession's momenta.
    GiNaC::realsymbol p_phi("p_phi"), p_psi("p_psi");
    const GiNaC::ex determinant = block(0, 0) * block(1, 1) - block(0, 1) * block(1, 0);
    const GiNaC::ex quadratic =
        (block(1, 1) * p_phi * p_phi - 2 * block(0, 1) * p_phi * p_psi + block(0, 0) * p_psi * p_psi) /
        (2 * determinant);
    const GiNaC::ex effective = lagrangian.potential + quadratic;
    const GiNaC::exmap momenta{{p_phi, differentiate(l, phi.velocity).subs(motion)},
                               {p_psi, differentiate(l, psi.velocity).subs(motion)}};
    GiNaC::ex curvature = differentiate(differentiate(effective, theta.position), theta.position).subs(momenta);
    // Eliminate the gravity strength by the condition (linear in it).
    if (!scene.gravity || !GiNaC::is_a<GiNaC::symbol>(scene.gravity->strength))
        return;
    const GiNaC::ex g = scene.gravity->strength;
    if (!p.is_polynomial(g) || p.degree(g) != 1)
        return;
    curvature = curvature.subs(g == -p.coeff(g, 0) / p.coeff(g, 1));
    top.nutation_frequency_squared = tidy_trigonometric(curvature / top.pivot_moment);
}

} // namespace

std::vector<top_result> analyze_tops(const model& scene, const lagrangian_result& lagrangian,
                                     const simplifier& simplify)
{
    std::vector<top_result> tops;
    if (!lagrangian.split)
        return tops;
    auto coordinate_of = [&](const GiNaC::ex& e) -> const coordinate* {
        for (const coordinate& c : scene.coordinates)
            if (e.is_equal(c.position))
                return &c;
        return nullptr;
    };
    for (const rigid_body& b : scene.bodies) {
        if (!b.orientation || b.rotation_axes != std::vector<char>{'z', 'x', 'z'})
            continue;
        const coordinate* phi = coordinate_of((*b.orientation)[0]);
        const coordinate* theta = coordinate_of((*b.orientation)[1]);
        const coordinate* psi = coordinate_of((*b.orientation)[2]);
        if (!phi || !theta || !psi || phi == theta || theta == psi || phi == psi)
            continue;
        if (lagrangian.lagrangian.has(phi->position) || lagrangian.lagrangian.has(psi->position))
            continue;
        try {
            top_result top;
            top.body = b.name;
            top.nutation = theta->position;
            const GiNaC::ex& t = lagrangian.kinetic;
            top.pivot_moment = simplify(t.diff(theta->velocity, 2));
            top.spin_moment = simplify(t.diff(psi->velocity, 2));
            if (top.pivot_moment.has(theta->position) || top.spin_moment.has(theta->position))
                continue;
            // The (φ̇, ψ̇) block of the kinetic matrix and V_eff = V + ½ pᵀ K⁻¹ p (Routh).
            GiNaC::matrix block(2, 2);
            const GiNaC::symbol* cyclic[] = {&phi->velocity, &psi->velocity};
            for (int i = 0; i < 2; ++i)
                for (int j = 0; j < 2; ++j)
                    block(i, j) = t.diff(*cyclic[i]).diff(*cyclic[j]);
            GiNaC::realsymbol spin("omega3");
            top.spin = spin;
            // pᵀ K⁻¹ p for p = (P, P) and the 2×2 block K: P² (K11 − 2 K12 + K22) / det K.
            const GiNaC::ex momentum = top.spin_moment * spin;
            const GiNaC::ex determinant = simplify.canonical(block(0, 0) * block(1, 1) - block(0, 1) * block(1, 0));
            if (determinant.is_zero())
                continue;
            const GiNaC::ex routh = momentum * momentum *
                                    simplify.canonical(block(0, 0) - 2 * block(0, 1) + block(1, 1)) / determinant;
            top.effective_potential = lagrangian.potential + GiNaC::numeric(1, 2) * routh;
            GiNaC::ex expansion =
                GiNaC::series_to_poly(top.effective_potential.series(theta->position == 0, 3));
            top.curvature = normal_with_pi(expansion.expand().coeff(theta->position, 2));
            top.condition = normal_with_pi((8 * top.pivot_moment * top.curvature).expand());
            steady_precession(scene, lagrangian, *phi, *theta, *psi, block, top);
            tops.push_back(top);
        } catch (const computation_error&) {
            throw;
        } catch (const std::exception&) {
            continue; // not a top this analysis can expand (a series GiNaC cannot do)
        }
    }
    return tops;
}

} // namespace lagrange
