// SPDX-License-Identifier: GPL-2.0-or-later
/** @file check_symmetries.h
 *  Self-verification of the symmetries (see verify.h): the conserved quantities,
 *  the Hamiltonian, the effective potential and the steady motion, each against the
 *  Lagrangian as built, differentiated by finite differences. */
#pragma once

#include "core/model.h"
#include "mechanics/lagrangian.h"
#include "mechanics/steady_motion.h"
#include "mechanics/symmetries.h"
#include "verify/verify.h"

#include <vector>

namespace lagrange {

/// The results to check; a null pointer is one not computed.
struct symmetry_input {
    const conserved_result* conserved = nullptr;
    const hamiltonian_result* hamiltonian = nullptr;
    const reduced_result* reduced = nullptr;
    const steady_motion_result* steady = nullptr;
};

/// Appends one entry per result given. Throws computation_error "verification failed: …"
/// when one disagrees with its reference.
void check_symmetries(const model& scene, const lagrangian_result& lagrangian, const symmetry_input& input,
                      std::vector<verification_entry>& entries);

} // namespace lagrange
