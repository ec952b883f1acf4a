// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_cache_security.cpp
 *  The cache of compiled code against a hostile local user (issue 34; the trust model in
 *  docs/reliability.md): a file or folder swapped between the check and the load is never
 *  loaded; an entry is bound to its key; an entry that does not load or lacks the programs
 *  is replaced; a folder above the cache that others may write turns the cache off; stale
 *  temporary files are swept. */
#include "program/expression_program.h"
#include "program/native_code.h"
#include "system/cache.h"
#include "system/external.h"
#include "helpers/tools.h"

#include <catch2/catch.hpp>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace {

/// Points XDG_CACHE_HOME at a private folder while it lives, LAGRANGE_CACHE unset; these and
/// LAGRANGE_CC (which a test may set to a wrapper of the configured compiler) restored after.
class scratch_cache {
public:
    scratch_cache() : folder_("lagrange-cache-security")
    {
        for (const char* name : {"XDG_CACHE_HOME", "LAGRANGE_CC", "LAGRANGE_CACHE"}) {
            const char* value = std::getenv(name);
            saved_.emplace_back(name, value ? std::optional<std::string>(value) : std::nullopt);
        }
        setenv("XDG_CACHE_HOME", folder_.path().c_str(), 1);
        unsetenv("LAGRANGE_CACHE");
    }
    ~scratch_cache()
    {
        for (const auto& [name, value] : saved_) {
            if (value)
                setenv(name.c_str(), value->c_str(), 1);
            else
                unsetenv(name.c_str());
        }
        std::error_code ignored;
        std::filesystem::remove_all(folder_.path() + "/lagrange", ignored);
    }
    const std::string& path() const { return folder_.path(); }

private:
    lagrange::private_directory folder_;
    std::vector<std::pair<std::string, std::optional<std::string>>> saved_;
};

std::string file_text(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

/// Compiles the C file `source` into the shared library `library` with cc; false if it cannot.
bool compile_library(const lagrange::private_directory& folder, const std::string& source, const std::string& library)
{
    lagrange::program_result run =
        lagrange::run_program({lagrange_test::configured_compiler(), "-shared", "-fPIC", "-o", library, source},
                              folder.path(), "cc.log");
    return run.exit_code == 0;
}

/// The one entry in the folder `folder`, as its key and its stored bytes.
std::pair<std::string, std::string> only_entry(const std::string& folder)
{
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(folder))
        names.push_back(entry.path().string());
    REQUIRE(names.size() == 1);
    const std::string bytes = file_text(names[0]);
    const std::string magic = "lagrange cache entry 1\n";
    REQUIRE(bytes.compare(0, magic.size(), magic) == 0);
    const std::size_t newline = bytes.find('\n', magic.size());
    const std::size_t size = std::stoul(bytes.substr(magic.size(), newline - magic.size()));
    return {bytes.substr(newline + 1, size), bytes.substr(newline + 1 + size)};
}

// The race hook's state: a function pointer cannot capture.
std::string foreign_library;
int hook_runs = 0;

/// What a hostile user who may write a folder above the cache would do between the check
/// and the load: replace every file of the cache folder by a foreign library, then swap the
/// folder itself for a link to a folder of foreign libraries of the same names.
void swap_everything(const std::string& folder)
{
    ++hook_runs;
    const std::string decoy = folder + ".decoy";
    std::filesystem::create_directory(decoy);
    std::vector<std::string> names; // first: the loop below adds files to the folder
    for (const auto& entry : std::filesystem::directory_iterator(folder))
        names.push_back(entry.path().filename().string());
    for (const std::string& name : names) {
        std::filesystem::copy_file(foreign_library, decoy + "/" + name);
        std::filesystem::copy_file(foreign_library, folder + "/" + name + ".swap");
        std::filesystem::rename(folder + "/" + name + ".swap", folder + "/" + name);
    }
    std::filesystem::rename(folder, folder + ".aside");
    std::filesystem::create_directory_symlink(decoy, folder);
}

} // namespace

TEST_CASE("cache security: files swapped between the check and the load are never loaded", "[cache][security][cc]")
{
    scratch_cache scratch;
    lagrange::private_directory work("lagrange-race");
    // A foreign library with the right symbols, whose constructor leaves a marker.
    const std::string marker = work.path() + "/marker";
    work.write("foreign.c", "#include <fcntl.h>\n#include <unistd.h>\n"
                            "static void program_0(const double* s, double* o) { (void)s; o[0] = 12345; }\n"
                            "void (*lagrange_programs[])(const double*, double*) = {program_0};\n"
                            "const unsigned long lagrange_program_count = 1;\n"
                            "__attribute__((constructor)) static void planted(void) {\n"
                            "  int fd = open(\"" + marker + "\", O_WRONLY | O_CREAT, 0600); if (fd >= 0) close(fd); }\n");
    foreign_library = work.path() + "/foreign.so";
    REQUIRE(compile_library(work, work.path() + "/foreign.c", foreign_library));

    GiNaC::symbol x("x"), y("y");
    lagrange::expression_program program({x * y + 1}, {x, y});
    std::shared_ptr<lagrange::native_module> first = lagrange::native_module::compile({&program});
    REQUIRE(first); // compiled and stored

    hook_runs = 0;
    lagrange::cache_testing::set_race_hook(swap_everything);
    std::string why;
    std::shared_ptr<lagrange::native_module> second = lagrange::native_module::compile({&program}, {}, &why);
    lagrange::cache_testing::set_race_hook(nullptr);
    INFO(why);
    CHECK(hook_runs == 1);                     // the entry was found and checked
    CHECK(!std::filesystem::exists(marker));   // and no foreign code ran
    REQUIRE(second);
    double at[2] = {3, 5}, out[1] = {0};
    second->get(0)(at, out);
    CHECK(out[0] == 16); // what was checked was loaded: the programs compiled, not the foreign ones
}

TEST_CASE("cache security: an entry whose stored key differs is a miss", "[cache][security]")
{
    scratch_cache scratch;
    lagrange::file_cache cache("test");
    REQUIRE(cache.enabled());
    std::ofstream(scratch.path() + "/a") << "content of a";
    std::ofstream(scratch.path() + "/b") << "content of b";
    cache.store("key a", scratch.path() + "/a");
    cache.store("key b", scratch.path() + "/b");
    REQUIRE(cache.find("key a") == std::optional<std::string>("content of a"));
    // b's entry moved into a's place (by someone who could write the folder): a miss, not b's content.
    const std::string a = cache.folder() + "/" + lagrange::file_cache::entry_name("key a");
    const std::string b = cache.folder() + "/" + lagrange::file_cache::entry_name("key b");
    REQUIRE(rename(b.c_str(), a.c_str()) == 0);
    CHECK(!cache.find("key a"));
    CHECK(!cache.find("key b"));
    // An entry under the right name with another key of the same length (a collision).
    std::ofstream(a, std::ios::trunc) << "lagrange cache entry 1\n5\nkey bcontent of b";
    CHECK(!cache.find("key a"));
    // Truncated inside the key, or an unknown format: misses too.
    std::ofstream(a, std::ios::trunc) << "lagrange cache entry 1\n5\nkey";
    CHECK(!cache.find("key a"));
    std::ofstream(a, std::ios::trunc) << "content of a";
    CHECK(!cache.find("key a"));
    // A link, or a file others may write, in the entry's place: misses.
    std::ofstream(scratch.path() + "/planted") << "lagrange cache entry 1\n5\nkey acontent of a";
    REQUIRE(unlink(a.c_str()) == 0);
    REQUIRE(symlink((scratch.path() + "/planted").c_str(), a.c_str()) == 0);
    CHECK(!cache.find("key a"));
    REQUIRE(unlink(a.c_str()) == 0);
    std::ofstream(a) << "lagrange cache entry 1\n5\nkey acontent of a";
    REQUIRE(chmod(a.c_str(), 0666) == 0);
    CHECK(!cache.find("key a"));
    REQUIRE(chmod(a.c_str(), 0600) == 0);
    CHECK(cache.find("key a") == std::optional<std::string>("content of a"));
}

TEST_CASE("cache security: an entry that does not load, or lacks the programs, is replaced",
          "[cache][security][cc]")
{
    scratch_cache scratch;
    lagrange::private_directory work("lagrange-corrupt");
    // A compiler that counts its runs.
    const std::string count = work.path() + "/count";
    work.write("cc", "#!/bin/sh\necho run >> '" + count + "'\nexec " + lagrange_test::configured_compiler() +
                         " \"$@\"\n");
    std::filesystem::permissions(work.path() + "/cc", std::filesystem::perms::owner_all);
    work.write("garbage.so", "not a library at all");
    work.write("empty.c", "int lagrange_nothing;\n");
    REQUIRE(compile_library(work, work.path() + "/empty.c", work.path() + "/empty.so"));

    GiNaC::symbol x("x"), y("y");
    lagrange::expression_program program({x * y + 1}, {x, y});
    lagrange_test::compiler_override wrapped(work.path() + "/cc");
    REQUIRE(lagrange::native_module::compile({&program}));
    const lagrange::file_cache cache("native");
    const auto [key, good] = only_entry(cache.folder());
    for (const std::string bad : {"garbage.so", "empty.so"}) {
        INFO(bad);
        cache.store(key, work.path() + "/" + bad); // the right key, a useless object
        REQUIRE(cache.find(key) == std::optional<std::string>(file_text(work.path() + "/" + bad)));
        const std::size_t runs = file_text(count).size();
        std::string why;
        std::shared_ptr<lagrange::native_module> module = lagrange::native_module::compile({&program}, {}, &why);
        INFO(why);
        REQUIRE(module);                            // compiled again, not refused
        CHECK(file_text(count).size() > runs);
        CHECK(only_entry(cache.folder()).second.compare(0, 4, "\x7f" "ELF") == 0); // and replaced
        const std::size_t after = file_text(count).size();
        REQUIRE(lagrange::native_module::compile({&program}));
        CHECK(file_text(count).size() == after);    // the next run finds the new entry
        double at[2] = {3, 5}, out[1] = {0};
        module->get(0)(at, out);
        CHECK(out[0] == 16);
    }
}

TEST_CASE("cache security: a folder above the cache that others may write turns it off", "[cache][security]")
{
    scratch_cache scratch;
    // XDG_CACHE_HOME below a folder anyone may write: another user could rename it and put
    // a folder of theirs in its place.
    const std::string open = scratch.path() + "/open", base = open + "/cache";
    REQUIRE(mkdir(open.c_str(), 0700) == 0);
    REQUIRE(mkdir(base.c_str(), 0700) == 0);
    setenv("XDG_CACHE_HOME", base.c_str(), 1);
    REQUIRE(chmod(open.c_str(), 0777) == 0);
    CHECK(!lagrange::file_cache("test").enabled());
    std::string why;
    CHECK(!lagrange::trusted_folder(base, &why));
    CHECK(why == open + " is writable by others without the sticky bit");
    REQUIRE(chmod(open.c_str(), 0770) == 0);
    CHECK(!lagrange::file_cache("test").enabled());
    // Sticky (as /tmp): no one renames another's folder there.
    REQUIRE(chmod(open.c_str(), 01777) == 0);
    CHECK(lagrange::file_cache("test").enabled());
    REQUIRE(chmod(open.c_str(), 0755) == 0);
    CHECK(lagrange::file_cache("test").enabled());
    // A folder above that belongs to another user (only root can make one to test).
    if (geteuid() == 0) {
        REQUIRE(chown(open.c_str(), 65534, 65534) == 0);
        CHECK(!lagrange::file_cache("test").enabled());
        CHECK(!lagrange::trusted_folder(base, &why));
        CHECK(why == open + " belongs to another user (uid 65534)");
        REQUIRE(chown(open.c_str(), 0, 0) == 0);
    }
    std::filesystem::remove_all(open);
}

TEST_CASE("cache security: stale temporary files are swept, fresh ones kept", "[cache][security]")
{
    scratch_cache scratch;
    lagrange::file_cache cache("test");
    REQUIRE(cache.enabled());
    // Left by runs killed between creating a temporary file and renaming it.
    const std::string stale = cache.folder() + "/tmp-0123456789ab", fresh = cache.folder() + "/tmp-ba9876543210";
    const std::string old_format = cache.folder() + "/0123456789abcdef.file";
    for (const std::string& path : {stale, fresh, old_format})
        std::ofstream(path) << "half an entry";
    const struct timespec hour_ago[2] = {{std::time(nullptr) - 3600, 0}, {std::time(nullptr) - 3600, 0}};
    REQUIRE(utimensat(AT_FDCWD, stale.c_str(), hour_ago, 0) == 0);
    std::ofstream(scratch.path() + "/a") << "content";
    cache.store("k", scratch.path() + "/a");
    CHECK(!std::filesystem::exists(stale));
    CHECK(!std::filesystem::exists(old_format));
    CHECK(std::filesystem::exists(fresh)); // perhaps another run's, still being written
    CHECK(cache.find("k") == std::optional<std::string>("content"));
}
