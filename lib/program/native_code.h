// SPDX-License-Identifier: GPL-2.0-or-later
/** @file native_code.h
 *  Expression programs compiled to machine code at run time: C source generated from
 *  the programs, compiled by the system's C compiler (`cc -O2 -shared`) in a private
 *  temporary folder that is always removed, and loaded with dlopen. The compiler runs
 *  through run_program (system/external.h) with an argument vector — no shell — and the
 *  source holds only generated identifiers and numbers, never scene text. On an x86-64
 *  CPU with AVX2 and FMA the sines and cosines go four at a time to SLEEF (Debian's
 *  libsleef-dev), when it is installed; libm's otherwise. */
#pragma once

#include "program/expression_program.h"

#include <memory>
#include <string>
#include <vector>

namespace lagrange {

/// Bounds on compiling: the compiler is stopped after `seconds` (with its children), and
/// source beyond `max_source_bytes` is not compiled at all, since the compile would then
/// take longer than the interpreter's whole run.
struct native_limits {
    double seconds = 120;
    std::size_t max_source_bytes = 4u << 20;
    /// Statements per function of a large program (expression_program::c_source).
    std::size_t part_statements = expression_program::default_part_statements;
};

/// A loaded native module with one function per program.
class native_module {
public:
    using function = void (*)(const double* symbols, double* out);

    /// Compiles `programs` (or loads them from the cache, system/cache.h); returns nullptr
    /// (never throws) when they cannot be, so callers fall back to the interpreter; then `why`
    /// (if given) says which failure it was, on one line, for the user: no compiler (the
    /// command named), a compile error (the compiler's first lines), a library that does not
    /// load (dlerror's text), a missing, full, unwritable or unsafe TMPDIR, the time budget,
    /// or source too large.
    static std::shared_ptr<native_module> compile(const std::vector<const expression_program*>& programs,
                                                  const native_limits& limits = {}, std::string* why = nullptr);

    ~native_module();
    native_module(const native_module&) = delete;
    native_module& operator=(const native_module&) = delete;

    function get(std::size_t k) const { return functions_.at(k); }
    /// Whether its sines and cosines are SLEEF's (see expression_program::c_source).
    bool sleef() const { return sleef_; }

private:
    native_module() = default;
    void* handle_ = nullptr;
    bool sleef_ = false;
    std::vector<function> functions_;
};

/// A right-hand side and its Jacobian as the motion classes use them, each in a module of its
/// own: the Jacobian's program is the larger (∂M/∂q alone has n³ entries; its compile took 8
/// times the right-hand side's for a 20-link chain) and explicit methods never call it. Both
/// null (the interpreter runs) until compiled.
struct native_rhs {
    std::shared_ptr<native_module> module;          ///< the right-hand side's
    std::shared_ptr<native_module> jacobian_module; ///< the Jacobian's
    native_module::function rhs = nullptr;
    native_module::function jacobian = nullptr;

    /// Compiles the right-hand side once; false when it cannot be (nothing changes; `why` says why).
    bool compile(const expression_program& rhs_program, const native_limits& limits = {}, std::string* why = nullptr);
    /// Compiles the Jacobian once, likewise.
    bool compile_jacobian(const expression_program& jacobian_program, const native_limits& limits = {},
                          std::string* why = nullptr);
    /// Both; false when either cannot be (then the one that could stays compiled).
    bool compile(const expression_program& rhs_program, const expression_program& jacobian_program,
                 const native_limits& limits = {}, std::string* why = nullptr)
    {
        return compile(rhs_program, limits, why) && compile_jacobian(jacobian_program, limits, why);
    }
    explicit operator bool() const { return static_cast<bool>(module); }
};

} // namespace lagrange
