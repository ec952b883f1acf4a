// SPDX-License-Identifier: GPL-2.0-or-later
/** @file address_layout.cpp
 *  Turning off address-space randomization for the process, by personality(2) and a re-exec. */
#include "system/address_layout.h"

#include "system/external.h"

#include <cstdlib>

#include <sys/personality.h>

namespace lagrange {

namespace {

/// Set in the environment before the re-exec: a second start that still finds the
/// layout random does not try again (personality accepted but not honoured).
constexpr const char* tried_variable = "LAGRANGE_FIXED_LAYOUT_TRIED";

} // namespace

bool address_layout_fixed()
{
    const int current = personality(0xffffffff);
    return current != -1 && (current & ADDR_NO_RANDOMIZE) != 0;
}

void use_fixed_address_layout(char** argv)
{
    const int current = personality(0xffffffff);
    if (current == -1 || (current & ADDR_NO_RANDOMIZE) != 0 || std::getenv(tried_variable) != nullptr)
        return;
    if (personality(static_cast<unsigned long>(current) | ADDR_NO_RANDOMIZE) == -1)
        return;
    setenv(tried_variable, "1", 1);
    execute_self_again(argv);
    // The exec was refused: go on with the layout this process has.
    personality(static_cast<unsigned long>(current));
    unsetenv(tried_variable);
}

} // namespace lagrange
