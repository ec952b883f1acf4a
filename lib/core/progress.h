// SPDX-License-Identifier: GPL-2.0-or-later
/** @file progress.h
 *  Progress of a long computation, for a program to show (the command line draws one
 *  line on a terminal); the library only reports. */
#pragma once

#include <functional>
#include <string>

namespace lagrange {

/// Called now and then during a long step. `what` names the step ("simulating with
/// dop853", "error estimate: dop853 at tolerance 1e-12"); `fraction` is the share of it
/// done, in [0, 1], or negative when it cannot be told (a symbolic stage). An empty
/// `what` says the steps are over: whatever was shown can go.
using progress_callback = std::function<void(const std::string& what, double fraction)>;

} // namespace lagrange
