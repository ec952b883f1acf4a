// SPDX-License-Identifier: GPL-2.0-or-later
/** @file double_double.cpp
 *  The run-time choice of the FMA kernels: the CPU is asked once, tests and benchmarks
 *  may force either version. */
#include "program/double_double.h"

#include <atomic>

namespace lagrange {

namespace {

bool cpu_has_fma()
{
#if LAGRANGE_HAVE_FMA_KERNELS
    __builtin_cpu_init();
    return __builtin_cpu_supports("fma");
#else
    return false;
#endif
}

std::atomic<bool>& fma_switch()
{
    static std::atomic<bool> on{cpu_has_fma()};
    return on;
}

} // namespace

bool fma_kernels() { return fma_switch().load(std::memory_order_relaxed); }
void use_fma_kernels(bool on) { fma_switch().store(on && cpu_has_fma(), std::memory_order_relaxed); }

} // namespace lagrange
