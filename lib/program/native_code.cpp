// SPDX-License-Identifier: GPL-2.0-or-later
/** @file native_code.cpp
 *  Run-time compilation of expression programs (C source, cc through run_program, dlopen). */
#include "program/native_code.h"

#include "core/errors.h"
#include "system/cache.h"
#include "system/external.h"

#include <dlfcn.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <sstream>
#include <thread>

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

/// The first few lines of the compiler's messages on one line (they go into the output's
/// `evaluation:` line), without the private folder's path and without control characters.
std::string first_lines(std::string log, const std::string& folder)
{
    for (std::size_t at; (at = log.find(folder + "/")) != std::string::npos;)
        log.erase(at, folder.size() + 1);
    std::string joined;
    std::istringstream lines(log);
    int kept = 0;
    for (std::string line; kept < 3 && std::getline(lines, line);) {
        for (char& c : line)
            if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
                c = ' ';
        line.erase(0, line.find_first_not_of(' '));
        if (line.empty())
            continue;
        if (line.size() > 200)
            line = line.substr(0, 200) + "…";
        joined += (kept++ ? "; " : "") + line;
    }
    return joined.empty() ? "it printed no message" : joined;
}

/// What is wrong with the temporary folder, for the user.
std::string temporary_problem(const temporary_error& e)
{
    const std::string folder = "the temporary folder " + e.folder + " (TMPDIR)";
    switch (e.error) {
    case ENOSPC:
    case EDQUOT:
        return folder + " is full, so the equations were not compiled";
    case EACCES:
    case EPERM:
    case EROFS:
        return folder + " is not writable, so the equations were not compiled";
    case ENOENT:
        return folder + " does not exist, so the equations were not compiled";
    case ENOTDIR:
        return folder + " is not a folder, so the equations were not compiled";
    default:
        return folder + " cannot be used to compile the equations (" + std::strerror(e.error) + ")";
    }
}

/// Why a loaded library cannot be used ("" when it can): it lacks the table of programs or
/// holds another number of them (an entry or output that is not what was compiled).
std::string unusable(void* handle, std::size_t count)
{
    dlerror();
    if (!dlsym(handle, "lagrange_programs")) {
        const char* error = dlerror();
        return error ? error : "it has no lagrange_programs";
    }
    auto* stored = static_cast<const unsigned long*>(dlsym(handle, "lagrange_program_count"));
    if (!stored || *stored != count)
        return "it does not hold the " + std::to_string(count) + " programs compiled";
    return "";
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
    // Compiled code is loaded from the private folder by its path: no one but root and this
    // user may be able to swap a folder above it (the rule of the cache, system/cache.h).
    const std::string temporary = temporary_folder();
    std::optional<private_directory> folder;
    try {
        folder.emplace("lagrange-native");
    } catch (const temporary_error& e) {
        return refuse(temporary_problem(e));
    }
    if (std::string unsafe; !trusted_folder(temporary, &unsafe))
        return refuse("the temporary folder " + temporary + " (TMPDIR) is not safe for compiled code: " + unsafe);
    const char* compiler = std::getenv("LAGRANGE_CC");
    const bool chosen = compiler && *compiler;
    const std::string cc = chosen ? compiler : "cc";
    const std::string cc_named = "`" + cc + "`" + (chosen ? " (LAGRANGE_CC)" : "");
    // -ffp-contract=off: no fused multiply-adds where the interpreter has none (with -mfma, or
    // on a CPU where FMA is the baseline), so native code rounds as the interpreter does;
    // only SLEEF's sines and cosines may differ from libm's, by an ulp or two.
    // -fno-tree-slp-vectorize: GCC's packing of straight-line code into vectors took a third
    // of a large program's compile, and its packed code ran slower (docs/benchmarks.md).
    bool too_large = false, timed_out = false;
    std::string failure; // why the last attempt failed
    const file_cache cache("native");
    void* handle = nullptr; // the loaded library: compiled now, or found in the cache
    // A large program's parts in two translation units compiled side by side (then linked),
    // where there are two cores or more: GCC uses one core per compile.
    const std::size_t units = std::thread::hardware_concurrency() >= 2 ? 2 : 1;
    auto build = [&](bool with_sleef) {
        std::vector<std::string> sources(1);
        const std::string header =
            std::string("#include <math.h>\n") + (with_sleef ? expression_program::sleef_declarations() : "");
        for (std::size_t k = 0; k < programs.size(); ++k) {
            std::vector<std::string> parts =
                programs[k]->c_units("program_" + std::to_string(k), with_sleef, limits.part_statements, units);
            sources.resize(std::max(sources.size(), parts.size()));
            for (std::size_t u = 0; u < parts.size(); ++u)
                sources[u] += parts[u];
        }
        std::ostringstream table;
        table << "void (*lagrange_programs[])(const double*, double*) = {";
        for (std::size_t k = 0; k < programs.size(); ++k)
            table << (k ? ", " : "") << "program_" << k;
        table << "};\nconst unsigned long lagrange_program_count = " << programs.size() << ";\n";
        sources.front() += table.str();
        std::size_t bytes = 0;
        for (std::string& unit : sources) {
            unit = header + unit;
            bytes += unit.size();
        }
        if (bytes > limits.max_source_bytes) {
            too_large = true;
            failure = "the equations' C source is larger than " + std::to_string(limits.max_source_bytes >> 20) +
                      " MB, too large for compiling to pay off";
            return false;
        }
        const std::string suffix = with_sleef ? "_sleef.so" : ".so";
        const std::string library = folder->path() + "/programs" + suffix;
        // The commands: one, or a compile per unit and a link.
        std::vector<std::string> options = {cc, "-O2", "-fno-tree-slp-vectorize", "-fno-math-errno",
                                            "-ffp-contract=off", "-fPIC"};
        if (with_sleef)
            options.insert(options.end(), {"-mavx2", "-mfma"});
        std::vector<std::string> libraries;
        if (with_sleef)
            libraries.push_back("-lsleef");
        libraries.push_back("-lm");
        std::vector<std::string> files, objects;
        std::vector<std::vector<std::string>> compiles;
        for (std::size_t u = 0; u < sources.size(); ++u) {
            const std::string stem = "programs" + (u ? "_" + std::to_string(u) : std::string());
            files.push_back(stem + ".c");
            objects.push_back(folder->path() + "/" + stem + ".o");
        }
        std::vector<std::string> link;
        if (sources.size() == 1) {
            std::vector<std::string> command = options;
            command.insert(command.end(), {"-shared", "-o", library, folder->path() + "/" + files[0]});
            command.insert(command.end(), libraries.begin(), libraries.end());
            compiles.push_back(command);
        } else {
            for (std::size_t u = 0; u < sources.size(); ++u) {
                std::vector<std::string> command = options;
                command.insert(command.end(), {"-c", "-o", objects[u], folder->path() + "/" + files[u]});
                compiles.push_back(command);
            }
            link = {cc, "-shared", "-o", library};
            link.insert(link.end(), objects.begin(), objects.end());
            link.insert(link.end(), libraries.begin(), libraries.end());
        }
        // The cache's key: the commands (without the private folder's paths) and the sources.
        std::string key;
        auto add_command = [&](const std::vector<std::string>& command) {
            for (const std::string& a : command)
                key += (a.compare(0, folder->path().size() + 1, folder->path() + "/") == 0
                            ? "FOLDER/" + a.substr(folder->path().size() + 1)
                            : a) +
                       "\n";
        };
        for (const auto& command : compiles)
            add_command(command);
        add_command(link);
        for (const std::string& unit : sources)
            key += unit;
        // A hit is loaded from a copy in our private folder of the bytes the cache checked,
        // never from the cache's own path; one that does not load, or lacks the programs, is
        // removed and compiled again (so it is replaced, and cannot spoil later runs). Not
        // dlopen("/proc/self/fd/N"): the loader knows a library by that name, and would hand
        // back the old one for a later descriptor N of another file while it stays loaded.
        if (std::optional<std::string> found = cache.find(key)) {
            const std::string copy = folder->path() + "/cached" + suffix;
            bool copied = false;
            try {
                folder->write("cached" + suffix, *found);
                copied = true;
                cache_testing::run_race_hook(cache.folder());
                handle = dlopen(copy.c_str(), RTLD_NOW | RTLD_LOCAL);
            } catch (const temporary_error&) {
                handle = nullptr;
            }
            if (handle && unusable(handle, programs.size()).empty())
                return true;
            if (handle)
                dlclose(handle);
            handle = nullptr;
            if (copied) // the entry's fault, not a full TMPDIR's
                cache.remove(key);
        }
        try {
            for (std::size_t u = 0; u < sources.size(); ++u)
                folder->write(files[u], sources[u]);
        } catch (const temporary_error& e) {
            failure = temporary_problem(e);
            return false;
        }
        // One command; "" when it succeeded, else why not (`late`: it ran out of time).
        auto run_cc = [&](const std::vector<std::string>& command, const std::string& log_name, bool& late) {
            // TMPDIR: the compiler's own temporary files go into the private folder too.
            program_result run = run_program(command, folder->path(), log_name, {"TMPDIR=" + folder->path()},
                                              limits.seconds);
            if (run.timed_out) {
                late = true;
                return std::string("compiling the equations took longer than the time budget");
            }
            if (run.start_error != 0) {
                const int e = run.start_error;
                return e == ENOSPC || e == EDQUOT
                           ? temporary_problem(temporary_error("", e, temporary))
                       : e == ENOENT || e == EACCES || e == ENOEXEC || e == ENOTDIR || e == ELOOP || e == EPERM
                           ? "no C compiler was found to compile the equations: " + cc_named +
                                 " could not be started (" + std::strerror(e) + ")"
                           : "the C compiler " + cc_named + " could not be started (" + std::strerror(e) + ")";
            }
            if (run.exit_code != 0) {
                std::string log;
                try {
                    log = folder->read(log_name);
                } catch (const computation_error&) {
                }
                return std::string(log.find("No space left on device") != std::string::npos
                                       ? "the temporary folder " + temporary + " (TMPDIR) is full: "
                                       : "") +
                       "compile error: " + cc_named +
                       (run.signal ? " was ended by signal " + std::to_string(run.signal)
                                   : " exited with status " + std::to_string(run.exit_code)) +
                       ": " + first_lines(log, folder->path());
            }
            return std::string();
        };
        std::vector<std::string> failures(compiles.size());
        std::vector<char> late(compiles.size(), 0);
        {
            std::vector<std::thread> others;
            for (std::size_t u = 1; u < compiles.size(); ++u)
                others.emplace_back([&, u] {
                    bool l = false;
                    try {
                        failures[u] = run_cc(compiles[u], "cc_" + std::to_string(u) + ".log", l);
                    } catch (const std::exception& e) { // nothing may leave a thread
                        failures[u] = std::string("the C compiler could not be run: ") + e.what();
                    }
                    late[u] = l;
                });
            bool l = false;
            try {
                failures[0] = run_cc(compiles[0], "cc.log", l);
            } catch (const std::exception& e) { // the others are joined first
                failures[0] = std::string("the C compiler could not be run: ") + e.what();
            }
            late[0] = l;
            for (std::thread& t : others)
                t.join();
        }
        for (std::size_t u = 0; u < compiles.size(); ++u)
            if (!failures[u].empty()) {
                failure = failures[u];
                timed_out = late[u] != 0;
                return false;
            }
        if (!link.empty()) {
            bool l = false;
            failure = run_cc(link, "link.log", l);
            timed_out = l;
            if (!failure.empty())
                return false;
        }
        handle = dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            const char* error = dlerror();
            failure = std::string("the compiled equations could not be loaded: ") + (error ? error : "dlopen failed");
            return false;
        }
        if (std::string problem = unusable(handle, programs.size()); !problem.empty()) {
            dlclose(handle);
            handle = nullptr;
            failure = "the compiled equations could not be loaded: " + problem;
            return false;
        }
        cache.store(key, library);
        return true;
    };
    bool built = sleef && build(true);
    if (sleef && !built && !too_large && !timed_out) {
        // Perhaps SLEEF is missing (no libsleef-dev): libm's then, and later modules of this
        // process skip SLEEF when that works.
        built = build(false);
        sleef = false;
        if (built)
            sleef_failed = true;
    } else if (!sleef) {
        built = build(false);
    }
    if (!built)
        return refuse(failure);
    std::shared_ptr<native_module> module(new native_module());
    module->handle_ = handle;
    auto* table = static_cast<function*>(dlsym(module->handle_, "lagrange_programs"));
    module->functions_.assign(table, table + programs.size());
    module->sleef_ = sleef;
    return module; // the folder and its files go; the loaded library stays mapped
}

namespace {

/// Compiles `program` into `module` once, and sets `entry` to its function.
bool compile_once(const expression_program& program, std::shared_ptr<native_module>& module,
                  native_module::function& entry, const native_limits& limits, std::string* why)
{
    if (module)
        return true;
    std::shared_ptr<native_module> compiled = native_module::compile({&program}, limits, why);
    if (!compiled)
        return false;
    module = std::move(compiled);
    entry = module->get(0);
    return true;
}

} // namespace

bool native_rhs::compile(const expression_program& rhs_program, const native_limits& limits, std::string* why)
{
    return compile_once(rhs_program, module, rhs, limits, why);
}

bool native_rhs::compile_jacobian(const expression_program& jacobian_program, const native_limits& limits,
                                  std::string* why)
{
    return compile_once(jacobian_program, jacobian_module, jacobian, limits, why);
}

native_module::~native_module()
{
    if (handle_)
        dlclose(handle_);
}

} // namespace lagrange
