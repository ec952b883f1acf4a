// SPDX-License-Identifier: GPL-2.0-or-later
/** @file products.h
 *  Which products a run computes when the scene has no `want` line: each product's
 *  by_default predicate of core/products.inc. */
#pragma once

#include "core/model.h"

#include <set>

namespace lagrange {

/// The products a scene supports when it has no `want` line.
std::set<product> default_products(const model& scene);

} // namespace lagrange
