// SPDX-License-Identifier: GPL-2.0-or-later
/** @file native_cache_hit.cpp
 *  Benchmark: the cost of one hit in the cache of compiled equations (system/cache.h) —
 *  the lookup, the checks and the load of the double pendulum's compiled right-hand side
 *  and Jacobian, as a warm `simulate` run does it — in a private cache folder filled by one
 *  compile first. Each hit's module is released before the next, as one run holds one.
 *  Prints the median and fastest of `hits` hits and the one compile.
 *  Usage: native_cache_hit [hits [scene]] (default: 200 hits of examples/double_pendulum.lag,
 *  from the repository's folder; bench/cache_hit.sh times whole runs). */
#include "engine/analysis.h"
#include "numeric/compiled_motion.h"
#include "scene/lower.h"

#include <stdlib.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

int main(int argc, char** argv)
{
    using clock_type = std::chrono::steady_clock;
    const int hits = argc > 1 ? std::atoi(argv[1]) : 200;
    const std::string path = argc > 2 ? argv[2] : "examples/double_pendulum.lag";
    std::ifstream in(path);
    if (!in) {
        std::fprintf(stderr, "native_cache_hit: cannot read %s\n", path.c_str());
        return 2;
    }
    std::stringstream text;
    text << in.rdbuf();
    char folder[] = "/tmp/lagrange-cache-hit-XXXXXX";
    if (!mkdtemp(folder))
        return 1;
    setenv("XDG_CACHE_HOME", folder, 1);
    unsetenv("LAGRANGE_CACHE");
    lagrange::model scene = lagrange::load_model(lagrange::source_text(path, text.str()));
    lagrange::analysis result = lagrange::analyze(scene, {lagrange::product::equations});
    std::vector<std::unique_ptr<lagrange::compiled_motion>> motions;
    for (int k = 0; k <= hits; ++k)
        motions.push_back(std::make_unique<lagrange::compiled_motion>(scene, *result.equations,
                                                                      lagrange::first_value_point(scene)));
    std::vector<double> seconds;
    for (int k = 0; k <= hits; ++k) {
        auto start = clock_type::now();
        if (!motions[k]->compile_native()) {
            std::fprintf(stderr, "native_cache_hit: not compiled\n");
            return 1;
        }
        seconds.push_back(std::chrono::duration<double>(clock_type::now() - start).count());
        motions[k].reset(); // unloaded again, as at the end of a run: each hit loads anew
    }
    const double compile = seconds.front();
    seconds.erase(seconds.begin());
    std::sort(seconds.begin(), seconds.end());
    std::printf("%s: compile %.1f ms; cache hit median %.1f us, fastest %.1f us (%d hits)\n",
                path.c_str(), 1e3 * compile, 1e6 * seconds[seconds.size() / 2], 1e6 * seconds.front(), hits);
    std::filesystem::remove_all(folder);
    return 0;
}
