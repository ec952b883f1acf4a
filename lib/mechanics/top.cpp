/** @file top.cpp
 *  The heavy symmetric top by Routh's procedure. */
#include "mechanics/top.h"

#include "algebra/factor.h"

namespace lagrange {

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
        if (!b.orientation)
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
