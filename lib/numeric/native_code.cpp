/** @file native_code.cpp
 *  Run-time compilation of expression programs (C source, cc through run_program, dlopen). */
#include "numeric/native_code.h"

#include "scene/source.h"
#include "system/external.h"

#include <dlfcn.h>

#include <cstdlib>
#include <optional>
#include <sstream>

namespace lagrange {

std::shared_ptr<native_module> native_module::compile(const std::vector<const expression_program*>& programs)
{
    std::ostringstream code;
    code << "#include <math.h>\n";
    for (std::size_t k = 0; k < programs.size(); ++k)
        code << programs[k]->c_source("program_" + std::to_string(k));
    code << "void (*lagrange_programs[])(const double*, double*) = {";
    for (std::size_t k = 0; k < programs.size(); ++k)
        code << (k ? ", " : "") << "program_" << k;
    code << "};\n";
    std::optional<private_directory> folder;
    try {
        folder.emplace("lagrange-native");
        folder->write("programs.c", code.str());
    } catch (const computation_error&) {
        return nullptr; // no temporary folder or file: the interpreter runs
    }
    std::string source = folder->path() + "/programs.c";
    std::string library = folder->path() + "/programs.so";
    const char* compiler = std::getenv("LAGRANGE_CC");
    std::string cc = compiler && *compiler ? compiler : "cc";
    if (run_program({cc, "-O2", "-fno-math-errno", "-shared", "-fPIC", "-o", library, source, "-lm"}, folder->path(),
                    "cc.log")
            .exit_code != 0)
        return nullptr;
    std::shared_ptr<native_module> module(new native_module());
    module->handle_ = dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!module->handle_)
        return nullptr;
    auto* table = static_cast<function*>(dlsym(module->handle_, "lagrange_programs"));
    if (!table)
        return nullptr;
    module->functions_.assign(table, table + programs.size());
    return module; // the folder and its files go; the loaded library stays mapped
}

bool native_rhs::compile(const expression_program& rhs_program, const expression_program& jacobian_program)
{
    if (module)
        return true;
    std::shared_ptr<native_module> compiled = native_module::compile({&rhs_program, &jacobian_program});
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
