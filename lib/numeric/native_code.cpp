/** @file native_code.cpp
 *  Run-time compilation of expression programs (C source, cc, dlopen). */
#include "numeric/native_code.h"

#include <dlfcn.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <fstream>

extern char** environ;

namespace lagrange {

namespace {

/// A private temporary folder (mkdtemp, mode 0700), removed with its contents on scope exit.
class private_folder {
public:
    private_folder()
    {
        std::string pattern = (std::filesystem::temp_directory_path() / "lagrange-native-XXXXXX").string();
        std::vector<char> buffer(pattern.begin(), pattern.end());
        buffer.push_back('\0');
        if (mkdtemp(buffer.data()))
            path_ = buffer.data();
    }
    ~private_folder()
    {
        if (!path_.empty()) {
            std::error_code ignored;
            std::filesystem::remove_all(path_, ignored);
        }
    }
    private_folder(const private_folder&) = delete;
    private_folder& operator=(const private_folder&) = delete;
    bool ok() const { return !path_.empty(); }
    const std::string& path() const { return path_; }

private:
    std::string path_;
};

/// Runs `argv` (searched in PATH) with its output discarded; true if it exits with 0.
bool run_quietly(const std::vector<std::string>& arguments)
{
    std::vector<char*> argv;
    for (const std::string& a : arguments)
        argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
    pid_t child = 0;
    int error = posix_spawnp(&child, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (error != 0)
        return false;
    int status = 0;
    while (waitpid(child, &status, 0) < 0)
        if (errno != EINTR)
            return false;
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

} // namespace

std::shared_ptr<native_module> native_module::compile(const std::vector<const expression_program*>& programs)
{
    private_folder folder;
    if (!folder.ok())
        return nullptr;
    std::string source = folder.path() + "/programs.c";
    std::string library = folder.path() + "/programs.so";
    {
        std::ofstream out(source);
        out << "#include <math.h>\n";
        for (std::size_t k = 0; k < programs.size(); ++k)
            out << programs[k]->c_source("program_" + std::to_string(k));
        out << "void (*lagrange_programs[])(const double*, double*) = {";
        for (std::size_t k = 0; k < programs.size(); ++k)
            out << (k ? ", " : "") << "program_" << k;
        out << "};\n";
        if (!out)
            return nullptr;
    }
    const char* compiler = std::getenv("LAGRANGE_CC");
    std::string cc = compiler && *compiler ? compiler : "cc";
    if (!run_quietly({cc, "-O2", "-fno-math-errno", "-shared", "-fPIC", "-o", library, source, "-lm"}))
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
