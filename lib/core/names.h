// SPDX-License-Identifier: GPL-2.0-or-later
/** @file names.h
 *  Names for the symbols that results introduce (ω, s), clear of the scene's own. */
#pragma once

#include "core/model.h"

#include <string>

namespace lagrange {

/// `base`, or base_, base__, …: the first name that no parameter, coordinate, input or
/// ratio of the scene uses.
std::string unused_name(const model& scene, std::string base);

} // namespace lagrange
