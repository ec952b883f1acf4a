// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_native_cache.cpp
 *  The file cache (system/cache.h) and the native code kept in it: a second compile of the
 *  same programs finds the library instead of running the compiler; unsafe folders, changed
 *  keys and LAGRANGE_CACHE=0 are misses; the least recently used entries go. */
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
#include <filesystem>
#include <optional>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

namespace {

/// Points XDG_CACHE_HOME at a private folder while it lives (and LAGRANGE_CACHE at `setting`).
class scratch_cache {
public:
    explicit scratch_cache(const char* setting = nullptr) : folder_("lagrange-cache-test")
    {
        if (const char* old = std::getenv("XDG_CACHE_HOME"))
            old_ = old;
        setenv("XDG_CACHE_HOME", folder_.path().c_str(), 1);
        if (setting)
            setenv("LAGRANGE_CACHE", setting, 1);
    }
    ~scratch_cache()
    {
        if (old_)
            setenv("XDG_CACHE_HOME", old_->c_str(), 1);
        else
            unsetenv("XDG_CACHE_HOME");
        unsetenv("LAGRANGE_CACHE");
        std::filesystem::remove_all(folder_.path() + "/lagrange"); // nested: private_directory removes one level
    }
    const std::string& path() const { return folder_.path(); }

private:
    lagrange::private_directory folder_;
    std::optional<std::string> old_;
};

std::string file_text(const std::string& path)
{
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string made_file(const scratch_cache& cache, const std::string& name, const std::string& content)
{
    const std::string path = cache.path() + "/" + name;
    std::ofstream(path) << content;
    return path;
}

} // namespace

TEST_CASE("file cache: stored under a key, found only by the same key", "[cache]")
{
    scratch_cache scratch;
    lagrange::file_cache cache("test");
    REQUIRE(cache.enabled());
    CHECK(cache.folder() == scratch.path() + "/lagrange/test");
    struct stat info {};
    REQUIRE(stat(cache.folder().c_str(), &info) == 0);
    CHECK((info.st_mode & 0777) == 0700);

    CHECK(!cache.find("key one"));
    cache.store("key one", made_file(scratch, "a", "first content"));
    const std::optional<std::string> found = cache.find("key one");
    REQUIRE(found);
    CHECK(*found == "first content");
    CHECK(!cache.find("key one "));
    CHECK(!cache.find(""));

    // An entry that no longer holds the key (a hash collision, or tampering) is a miss.
    const std::string entry = cache.folder() + "/" + lagrange::file_cache::entry_name("key one");
    std::ofstream(entry) << "lagrange cache entry 1\n11\nanother keyfirst content";
    CHECK(!cache.find("key one"));
}

TEST_CASE("file cache: off when asked, and in folders others could write", "[cache]")
{
    {
        scratch_cache scratch("0");
        lagrange::file_cache cache("test");
        CHECK(!cache.enabled());
        cache.store("k", made_file(scratch, "a", "x"));
        CHECK(!cache.find("k"));
        CHECK(!std::filesystem::exists(scratch.path() + "/lagrange"));
    }
    {
        scratch_cache scratch;
        REQUIRE(mkdir((scratch.path() + "/lagrange").c_str(), 0777) == 0);
        REQUIRE(chmod((scratch.path() + "/lagrange").c_str(), 0777) == 0); // not reduced by the umask
        CHECK(!lagrange::file_cache("test").enabled());
    }
    {
        scratch_cache scratch;
        lagrange::private_directory elsewhere("lagrange-cache-target");
        REQUIRE(symlink(elsewhere.path().c_str(), (scratch.path() + "/lagrange").c_str()) == 0);
        CHECK(!lagrange::file_cache("test").enabled());
    }
}

TEST_CASE("file cache: the least recently used entries go past the limit", "[cache]")
{
    scratch_cache scratch;
    lagrange::file_cache cache("test", 3);
    const std::string file = made_file(scratch, "a", "content");
    for (int k = 0; k < 3; ++k)
        cache.store("key " + std::to_string(k), file);
    // Entry times one second apart, oldest first, whatever the clock's resolution; key 0 is
    // then used, so key 1 is the least recently used.
    for (int k = 0; k < 3; ++k) {
        const std::string key_file =
            cache.folder() + "/" + lagrange::file_cache::entry_name("key " + std::to_string(k));
        const struct timespec times[2] = {{1000 + k, 0}, {1000 + k, 0}};
        REQUIRE(utimensat(AT_FDCWD, key_file.c_str(), times, 0) == 0);
    }
    CHECK(cache.find("key 0"));
    cache.store("key 3", file);
    CHECK(cache.find("key 0"));
    CHECK(!cache.find("key 1"));
    CHECK(cache.find("key 2"));
    CHECK(cache.find("key 3"));
    std::size_t files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(cache.folder())) {
        (void)entry;
        ++files;
    }
    CHECK(files == 3); // three entries (key and content in one file), no temporaries
}

TEST_CASE("native code: a second compile of the same programs uses the cache", "[cache][native][cc]")
{
    scratch_cache scratch;
    // A compiler that counts its runs.
    lagrange::private_directory folder("lagrange-test");
    const std::string count = folder.path() + "/count";
    folder.write("cc", "#!/bin/sh\necho run >> '" + count + "'\nexec " + lagrange_test::configured_compiler() + " \"$@\"\n");
    std::filesystem::permissions(folder.path() + "/cc", std::filesystem::perms::owner_all);
    std::optional<lagrange_test::compiler_override> wrapped(std::in_place, folder.path() + "/cc");
    GiNaC::symbol x("x"), y("y");
    lagrange::expression_program program({GiNaC::sin(x) * y, x * x - y}, {x, y});
    lagrange::expression_program other({x + y}, {x, y});
    std::string why;
    std::shared_ptr<lagrange::native_module> first = lagrange::native_module::compile({&program}, {}, &why);
    const std::size_t runs = file_text(count).size();
    std::shared_ptr<lagrange::native_module> second = lagrange::native_module::compile({&program});
    const std::size_t runs_after_second = file_text(count).size();
    std::shared_ptr<lagrange::native_module> third = lagrange::native_module::compile({&other});
    const std::size_t runs_after_third = file_text(count).size();
    wrapped.reset();
    INFO(why);
    REQUIRE(first);
    REQUIRE(second);
    REQUIRE(third);
    CHECK(runs > 0);
    CHECK(runs_after_second == runs);      // found, not compiled
    CHECK(runs_after_third > runs);        // other programs: compiled
    std::vector<double> at = {0.7, -2.3}, a(2), b(2), c(1), scratch_space, interpreted(2);
    first->get(0)(at.data(), a.data());
    second->get(0)(at.data(), b.data());
    third->get(0)(at.data(), c.data());
    program.run(at.data(), scratch_space, interpreted.data());
    CHECK(a == b);
    CHECK(b[1] == interpreted[1]);
    CHECK(c[0] == at[0] + at[1]);
}
