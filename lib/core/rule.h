// SPDX-License-Identifier: GPL-2.0-or-later
/** @file rule.h
 *  A rewrite rule as a scene states it (`use`); algebra/rules.h applies them. */
#pragma once

#include <ginac/ginac.h>

#include <string>

namespace lagrange {

/// One rule: every match of `pattern` (with GiNaC wildcards) is replaced by `replacement`.
struct rewrite_rule {
    GiNaC::ex pattern;
    GiNaC::ex replacement;
    std::string origin; ///< "file:line", for messages
};

} // namespace lagrange
