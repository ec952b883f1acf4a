// SPDX-License-Identifier: GPL-2.0-or-later
/** @file native_code.cpp
 *  Run-time compilation of expression programs (C source, cc through run_program, dlopen). */
#include "numeric/native_code.h"

#include "core/errors.h"
#include "system/cache.h"
#include "system/external.h"

#include <dlfcn.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <optional>
#include <sstream>

namespace lagrange {

namespace {

/// Whether sines and cosines go to SLEEF (see expression_program::c_source): on an x86-64
/// CPU with AVX2 and FMA, unless LAGRANGE_SLEEF=0, and until compiling with it has failed
/// once in this process (no libsleef-dev: then libm's, as without AVX2).
std::atomic<bool> sleef_failed{false};

bool sleef_wanted()
{
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
    const char* setting = std::getenv("LAGRANGE_SLEEF");
    if (setting && std::string(setting) == "0")
        return false;
    return !sleef_failed && __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#else
    return false;
#endif
}

} // namespace

std::shared_ptr<native_module> native_module::compile(const std::vector<const expression_program*>& programs,
                                                      const native_limits& limits, std::string* why)
{
    auto refuse = [why](const std::string& reason) {
        if (why)
            *why = reason;
        return nullptr;
    };
    bool sleef = sleef_wanted() &&
                 std::any_of(programs.begin(), programs.end(), [](const auto* p) { return p->trigonometric(); });
    std::optional<private_directory> folder;
    try {
        folder.emplace("lagrange-native");
    } catch (const computation_error&) {
        return refuse("no temporary folder could be made to compile the equations");
    }
    std::string source = folder->path() + "/programs.c";
    std::string library = folder->path() + "/programs.so";
    const char* compiler = std::getenv("LAGRANGE_CC");
    std::string cc = compiler && *compiler ? compiler : "cc";
    // -ffp-contract=off: no fused multiply-adds where the interpreter has none (with -mfma, or
    // on a CPU where FMA is the baseline), so native code rounds as the interpreter does;
    // only SLEEF's sines and cosines may differ from libm's, by an ulp or two.
    bool too_large = false, timed_out = false, load_failed = false;
    const file_cache cache("native");
    void* handle = nullptr; // the loaded library: compiled now, or found in the cache
    auto build = [&](bool with_sleef) {
        std::ostringstream code;
        code << "#include <math.h>\n";
        if (with_sleef)
            code << expression_program::sleef_declarations();
        for (std::size_t k = 0; k < programs.size(); ++k)
            code << programs[k]->c_source("program_" + std::to_string(k), with_sleef);
        code << "void (*lagrange_programs[])(const double*, double*) = {";
        for (std::size_t k = 0; k < programs.size(); ++k)
            code << (k ? ", " : "") << "program_" << k;
        code << "};\n";
        if (code.tellp() > static_cast<std::streamoff>(limits.max_source_bytes)) {
            too_large = true;
            return false;
        }
        std::vector<std::string> arguments = {cc, "-O2", "-fno-math-errno", "-ffp-contract=off", "-shared", "-fPIC"};
        if (with_sleef)
            arguments.insert(arguments.end(), {"-mavx2", "-mfma"});
        arguments.insert(arguments.end(), {"-o", library, source});
        if (with_sleef)
            arguments.push_back("-lsleef");
        arguments.push_back("-lm");
        // The cache's key: the command (without the private folder's paths) and the source.
        std::string key;
        for (const std::string& a : arguments)
            key += (a == library ? "OUTPUT" : a == source ? "SOURCE" : a) + "\n";
        key += code.str();
        if (std::string found = cache.find(key); !found.empty() && (handle = dlopen(found.c_str(), RTLD_NOW | RTLD_LOCAL)))
            return true;
        try {
            folder->write("programs.c", code.str());
        } catch (const computation_error&) {
            return false;
        }
        // TMPDIR: the compiler's own temporary files go into the private folder too.
        program_result run = run_program(arguments, folder->path(), "cc.log", {"TMPDIR=" + folder->path()},
                                          limits.seconds);
        timed_out = timed_out || run.timed_out;
        if (run.exit_code != 0)
            return false;
        handle = dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
        load_failed = !handle;
        if (!handle)
            return false;
        cache.store(key, library);
        return true;
    };
    bool built = sleef && build(true);
    if (sleef && !built && !too_large && !timed_out) {
        sleef_failed = true;
        sleef = false;
    }
    if (!sleef)
        built = build(false);
    if (!built)
        return refuse(too_large ? "the equations' C source is larger than " +
                                      std::to_string(limits.max_source_bytes >> 20) +
                                      " MB, too large for compiling to pay off"
                      : timed_out ? "compiling the equations took longer than the time budget"
                      : load_failed ? "the compiled equations could not be loaded"
                                    : "no C compiler was found to compile the equations");
    std::shared_ptr<native_module> module(new native_module());
    module->handle_ = handle;
    auto* table = static_cast<function*>(dlsym(module->handle_, "lagrange_programs"));
    if (!table)
        return refuse("the compiled equations could not be loaded");
    module->functions_.assign(table, table + programs.size());
    module->sleef_ = sleef;
    return module; // the folder and its files go; the loaded library stays mapped
}

bool native_rhs::compile(const expression_program& rhs_program, const expression_program& jacobian_program,
                         const native_limits& limits, std::string* why)
{
    if (module)
        return true;
    std::shared_ptr<native_module> compiled = native_module::compile({&rhs_program, &jacobian_program}, limits, why);
    if (!compiled)
        return false;
    module = std::move(compiled);
    rhs = module->get(0);
    jacobian = module->get(1);
    return true;
}

native_module::~native_module()
{
    if (handle_)
        dlclose(handle_);
}

} // namespace lagrange
