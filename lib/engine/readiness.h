// SPDX-License-Identifier: GPL-2.0-or-later
/** @file readiness.h
 *  What the commands that run numbers need and a scene does not give: `lagrange check`
 *  prints it, so that a scene that parses is not taken for one that simulates. */
#pragma once

#include "core/model.h"

#include <string>
#include <vector>

namespace lagrange {

/// One line per unmet need, each naming the commands and what would meet it (a scene line
/// or a command-line option), e.g. "simulate, workprecision: an end time (a `simulate
/// until T` line or --until)". Empty when every command has what it needs.
std::vector<std::string> unmet_needs(const model& scene);

} // namespace lagrange
