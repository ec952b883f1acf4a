// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_determinism.cpp
 *  Byte-identical output from run to run on scenes nobody wrote by hand: a seeded
 *  generator of textbook-like systems (pendulum chains, spring chains, pendulums on
 *  carts and springs, two-dimensional oscillators, rigid bodies) and the fuzz seeds,
 *  each run in three processes. The command runs with address-space randomization on
 *  (it no longer fixes its layout), so each process has its own GiNaC hash order. */
#include "helpers/cli_runner.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace lagrange_test;

namespace {

/// Scene generator: the same seed gives the same scenes.
class scene_generator {
public:
    explicit scene_generator(unsigned seed) : random_(seed) {}

    std::string next(int index)
    {
        switch (index % 6) {
        case 0: return pendulum_chain(index);
        case 1: return spring_chain(index);
        case 2: return cart_pendulum(index);
        case 3: return sprung_pendulum(index);
        case 4: return planar_oscillator(index);
        default: return body(index);
        }
    }

private:
    int pick(int low, int high) { return std::uniform_int_distribution<int>(low, high)(random_); }
    bool coin() { return pick(0, 1) == 1; }

    /// `base` or `base1`, `base2`, ... for n parts: equal or distinct parameters.
    std::vector<std::string> names(const std::string& base, int n, bool distinct)
    {
        std::vector<std::string> result;
        for (int i = 1; i <= n; ++i)
            result.push_back(distinct ? base + std::to_string(i) : base);
        return result;
    }

    static std::string parameters(const std::vector<std::vector<std::string>>& groups)
    {
        std::vector<std::string> all;
        for (const auto& group : groups)
            for (const std::string& name : group)
                if (std::find(all.begin(), all.end(), name) == all.end())
                    all.push_back(name);
        std::string line = "parameters";
        for (const std::string& name : all)
            line += " " + name;
        return line + "\n";
    }

    std::string pendulum_chain(int index)
    {
        const int n = pick(1, 2);
        const auto m = names("m", n, coin()), l = names("l", n, coin());
        std::ostringstream s;
        s << "scene \"chain " << index << "\"\n" << parameters({m, l, {"g"}}) << "coordinates";
        for (int i = 1; i <= n; ++i)
            s << " q" << i;
        s << "\n";
        std::string x = "0", y = "0";
        for (int i = 0; i < n; ++i) {
            x += " + " + l[i] + "*sin(q" + std::to_string(i + 1) + ")";
            y += " - " + l[i] + "*cos(q" + std::to_string(i + 1) + ")";
            s << "point P" << i + 1 << " mass " << m[i] << " at (" << x << ", " << y << ")\n";
        }
        s << "gravity g along (0, -1)\n";
        if (coin())
            s << "values " << values({m, l}) << ", g = 9.81\n";
        return s.str();
    }

    std::string spring_chain(int index)
    {
        const int n = pick(1, 3);
        const auto m = names("m", n, coin()), k = names("k", n + 1, coin() && n < 3);
        std::ostringstream s;
        s << "scene \"springs " << index << "\"\n" << parameters({m, k}) << "coordinates";
        for (int i = 1; i <= n; ++i)
            s << " x" << i;
        s << "\n";
        for (int i = 1; i <= n; ++i)
            s << "point P" << i << " mass " << m[i - 1] << " at (x" << i << ", 0)\n";
        s << "spring " << k[0] << " between (0, 0) and P1\n";
        for (int i = 1; i < n; ++i)
            s << "spring " << k[i] << " between P" << i << " and P" << i + 1 << "\n";
        if (coin())
            s << "spring " << k[n] << " between P" << n << " and (0, 0)\n";
        if (coin())
            s << "values " << values({m, k}) << "\n";
        return s.str();
    }

    std::string cart_pendulum(int index)
    {
        std::ostringstream s;
        const bool sprung = coin();
        s << "scene \"cart " << index << "\"\n"
          << "parameters M m l g" << (sprung ? " k" : "") << "\ncoordinates x th\n"
          << "point cart mass M at (x, 0)\n"
          << "point bob mass m at (x + l*sin(th), -l*cos(th))\n"
          << "gravity g along (0, -1)\n";
        if (sprung)
            s << "spring k between cart and (0, 0)\n";
        if (coin())
            s << "values M = 2, m = 1, l = 1, g = 9.81" << (sprung ? ", k = 3" : "") << "\n";
        return s.str();
    }

    std::string sprung_pendulum(int index)
    {
        std::ostringstream s;
        const int ax = pick(-2, 2), ay = pick(-2, 0);
        s << "scene \"sprung pendulum " << index << "\"\n"
          << "parameters m l g k\ncoordinates th\n"
          << "point bob mass m at (l*sin(th), -l*cos(th))\n"
          << "spring k between bob and (" << ax << "*l, " << ay << "*l)\n"
          << "gravity g along (0, -1)\n"
          << "equilibrium th = 0\n";
        if (coin())
            s << "values m = 1, l = 1, g = 9.81, k = " << pick(1, 9) << "\n";
        return s.str();
    }

    std::string planar_oscillator(int index)
    {
        std::ostringstream s;
        const bool coupled = coin();
        s << "scene \"planar " << index << "\"\n"
          << "parameters m kx ky" << (coupled ? " c" : "") << "\ncoordinates x y\n"
          << "T = 1/2*m*(x'^2 + y'^2)\n"
          << "V = 1/2*kx*x^2 + 1/2*ky*y^2" << (coupled ? " + c*x*y" : "") << "\n"
          << "equilibrium x = 0, y = 0\n";
        if (coin())
            s << "values m = 1, kx = 4, ky = " << pick(5, 9) << (coupled ? ", c = 1" : "") << "\n";
        return s.str();
    }

    std::string body(int index)
    {
        static const char* shapes[] = {"disk(R)", "ball(R)", "stick(l)", "ring(R)"};
        const std::string shape = shapes[pick(0, 3)];
        std::ostringstream s;
        s << "scene \"body " << index << "\"\nparameters M R l\n"
          << "body B " << shape << " mass M\n";
        if (coin())
            s << "omega B (w1, w2, w3)\nwant inertia, euler\n";
        else
            s << "want inertia\n";
        return s.str();
    }

    std::string values(const std::vector<std::vector<std::string>>& groups)
    {
        std::vector<std::string> seen;
        std::string text;
        for (const auto& group : groups)
            for (const std::string& name : group) {
                if (std::find(seen.begin(), seen.end(), name) != seen.end())
                    continue;
                seen.push_back(name);
                text += (text.empty() ? "" : ", ") + name + " = " + std::to_string(pick(1, 5));
            }
        return text;
    }

    std::mt19937 random_;
};

/// Runs `scene` in three processes and returns the distinct outputs (one when deterministic).
std::size_t distinct_outputs(const std::string& path, const std::string& format = "json")
{
    std::vector<std::string> outputs;
    for (int run = 0; run < 3; ++run) {
        cli_result r = run_cli("'" + path + "' --format " + format, "", 60);
        const std::string output = std::to_string(r.exit_code) + "\n" + r.out + r.err;
        if (std::find(outputs.begin(), outputs.end(), output) == outputs.end())
            outputs.push_back(output);
    }
    return outputs.size();
}

} // namespace

TEST_CASE("determinism: 200 generated scenes and the fuzz seeds print the same bytes in 3 processes",
          "[determinism][cli][generated][slow]")
{
    scene_generator generator(20261124);
    std::vector<std::string> scenes;
    for (int i = 0; i < 200; ++i) {
        const std::string text = generator.next(i);
        scenes.push_back(temporary_file("generated_" + std::to_string(i) + ".lag", text));
    }
    for (const auto& entry : std::filesystem::directory_iterator(std::string(LAGRANGE_SOURCE_DIR) + "/fuzz/seeds"))
        scenes.push_back(entry.path().string());
    for (const std::string& scene : scenes) {
        INFO(scene << ":\n" << read_file(scene));
        CHECK(distinct_outputs(scene) == 1);
    }
}

TEST_CASE("determinism: every example and test scene prints the same bytes in 3 processes, in every format",
          "[determinism][cli][generated][slow]")
{
    std::vector<std::string> scenes;
    for (const char* folder : {"/examples", "/tests/scenes"}) {
        const std::filesystem::path path = std::string(LAGRANGE_SOURCE_DIR) + folder;
        if (!std::filesystem::exists(path))
            continue;
        for (const auto& entry : std::filesystem::directory_iterator(path))
            if (entry.path().extension() == ".lag")
                scenes.push_back(entry.path().string());
    }
    std::sort(scenes.begin(), scenes.end());
    REQUIRE(scenes.size() >= 19);
    for (const std::string& scene : scenes)
        for (const char* format : {"text", "latex", "json"}) {
            INFO(scene << " --format " << format);
            CHECK(distinct_outputs(scene, format) == 1);
        }
}
