// SPDX-License-Identifier: GPL-2.0-or-later
/** @file calculus.h
 *  ∂/∂x and the total time derivative d/dt with q, q̇, q̈ as plain symbols. */
#pragma once

#include "core/model.h"

#include <ginac/ginac.h>

namespace lagrange {

/// ∂e/∂variable.
GiNaC::ex differentiate(const GiNaC::ex& e, const GiNaC::symbol& variable);

/// d/dt e = ∂e/∂t + Σ (∂e/∂q q̇ + ∂e/∂q̇ q̈).
GiNaC::ex time_derivative(const GiNaC::ex& e, const model& scene);

} // namespace lagrange
