// SPDX-License-Identifier: GPL-2.0-or-later
/** @file address_layout.h
 *  A fixed address layout for the process, so that GiNaC's term order is the same in
 *  every run. GiNaC seeds the hash of each symbol and function with the address of its
 *  type's name (make_hash_seed in GiNaC's utils.h). Under address-space layout
 *  randomization that address changes from process to process, and with it the order of
 *  terms in sums and products, and the form that normal(), collect() and factor() choose
 *  (which variable leads, which sign a factor takes). The printers order terms
 *  themselves, but the form of a result is decided inside GiNaC; only a fixed layout
 *  makes it reproducible. */
#pragma once

namespace lagrange {

/// If address-space randomization is on for this process, turns it off and executes
/// the program again (/proc/self/exe) with the same arguments and environment, so that
/// this call does not return. Returns when the layout is already fixed, or when it
/// cannot be fixed (personality(2) or the exec refused); the output is then still
/// correct, but may differ in form from run to run.
void use_fixed_address_layout(char** argv);

/// True if address-space randomization is off for this process.
bool address_layout_fixed();

} // namespace lagrange
