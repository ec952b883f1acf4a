/** @file message_text.h
 *  An expression as text for error messages, the same from run to run. */
#pragma once

#include <ginac/ginac.h>

#include <string>

namespace lagrange {

/// e as text for messages, the same whatever GiNaC's internal term order: the
/// operands of sums and products are printed recursively and sorted (the full
/// printer lives in lib/output, which the layers below it may not use).
std::string message_text(const GiNaC::ex& e);

} // namespace lagrange
