// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_reliability.cpp
 *  Reliability (issue 7): budgets that trip (message, exit code, what is still
 *  computed), `-o` never losing an existing file, no files left in the working
 *  folder, and regressions for what the fuzzer found (named after the bug). */
#include "helpers/cli_runner.h"
#include "engine/analysis.h"
#include "algebra/budget.h"
#include "algebra/factor.h"
#include "helpers/scene_helpers.h"

#include <catch2/catch.hpp>

#include <filesystem>

#include <set>
#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <cstdlib>
#include <dirent.h>
#include <sstream>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

using namespace lagrange;
using namespace lagrange_test;

namespace {

const std::string examples = std::string(LAGRANGE_SOURCE_DIR) + "/examples/";

/// A planar chain of n links (chain_scene) with values for every mass and length, and its
/// hanging equilibrium.
std::string chain(int n)
{
    std::string values = "values g = 9.81", equilibrium = "equilibrium ";
    for (int k = 1; k <= n; ++k) {
        std::string i = std::to_string(k);
        values += ", m" + i + " = " + std::to_string(1 + k) + ", l" + i + " = 1";
        equilibrium += (k > 1 ? ", q" : "q") + i + " = 0";
    }
    return chain_scene(n) + equilibrium + "\n" + values + "\n";
}

std::vector<std::string> folder_entries(const std::string& folder)
{
    std::vector<std::string> names;
    if (DIR* d = opendir(folder.c_str())) {
        while (dirent* e = readdir(d)) {
            std::string name = e->d_name;
            if (name != "." && name != "..")
                names.push_back(name);
        }
        closedir(d);
    }
    std::sort(names.begin(), names.end());
    return names;
}

std::string fresh_folder()
{
    char pattern[] = "/tmp/lagrange-rel-XXXXXX";
    const char* made = mkdtemp(pattern);
    REQUIRE(made);
    return made;
}

/// Runs `lagrange ARGS` with `folder` as the working folder; returns the exit code.
int run_in(const std::string& folder, const std::string& args)
{
    std::string command = "cd " + folder + " && timeout -s KILL 60 " + std::string(LAGRANGE_BINARY) + " " + args +
                          " >/dev/null 2>&1 </dev/null";
    int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

} // namespace

TEST_CASE("budget: the term count of an unexpanded expression matches its expansion", "[budget]")
{
    GiNaC::symbol a("a"), b("b"), c("c"), d("d");
    // Independent reference: GiNaC's own expansion.
    for (const GiNaC::ex& e : {GiNaC::ex(pow(a + b + c, 5)), GiNaC::ex((a + b) * (c + d)),
                               GiNaC::ex(pow(a + b, 7) * (c + d)), GiNaC::ex(a * b), GiNaC::ex(a + b + c + d)}) {
        INFO(e);
        std::size_t expanded = GiNaC::is_a<GiNaC::add>(e.expand()) ? e.expand().nops() : 1;
        CHECK(expanded_terms(e, 1u << 30) == expanded);
    }
    // An upper bound where terms cancel or combine, and saturation at the cap.
    CHECK(expanded_terms((a + b) * (a - b), 100) >= 2);
    CHECK(expanded_terms(pow(a + b + c + d, 1000), 5000) == 5000);
    CHECK(expanded_terms(pow(a + b, GiNaC::numeric(1) / 2), 100) == 1);
}

TEST_CASE("budget: the checks throw only inside a scope, with the stage's name", "[budget]")
{
    GiNaC::symbol a("a"), b("b");
    GiNaC::ex big = pow(a + b, 40); // 41 terms once expanded
    CHECK_NOTHROW(budget_check_terms(big, "it"));
    budget_limits limits;
    limits.max_terms = 40;
    {
        budget_scope scope("characteristic", limits);
        CHECK(budget_stage() == "characteristic");
        try {
            budget_check_terms(big, "the determinant");
            FAIL("no budget_exceeded");
        } catch (const budget_exceeded& e) {
            CHECK(e.stage() == "characteristic");
            CHECK(std::string(e.what()) ==
                  "the `characteristic` stage exceeded its size budget: the determinant has more than 40 terms "
                  "(--max-terms)");
        }
        limits.max_terms = 41;
        budget_scope inner("modes", limits);
        CHECK_NOTHROW(budget_check_terms(big, "it"));
    }
    CHECK(budget_stage().empty());
    limits.max_seconds = 0.01;
    budget_scope scope("equations", limits);
    std::this_thread::sleep_for(std::chrono::milliseconds(30));
    CHECK_THROWS_WITH(budget_check(), "the `equations` stage exceeded its time budget of 0.01 s (--max-seconds)");
}

TEST_CASE("budget: a 6-link chain over its size budget still gets its numeric modes", "[budget]")
{
    model scene = load(chain(6));
    budget_limits limits;
    limits.max_terms = 200;
    analysis a = analyze(scene, {product::frequencies, product::numeric}, limits);
    CHECK_FALSE(a.characteristic);
    CHECK_FALSE(a.modes);
    REQUIRE(a.numeric);
    REQUIRE(a.notes.size() == 1);
    CHECK(a.notes[0].find("the `characteristic` stage exceeded its size budget") != std::string::npos);
    CHECK(a.notes[0].find("more than 200 terms (--max-terms)") != std::string::npos);
    // The numeric frequencies are right. Independent reference: the sum of the ω²
    // is the trace of T⁻¹V, from T and V evaluated here and an LU solve.
    REQUIRE(a.linearization);
    GiNaC::exmap at;
    for (const auto& [name, value] : scene.values.at(0).values)
        for (const parameter& p : scene.parameters)
            if (p.name == name)
                at[p.symbol] = value;
    const std::size_t n = scene.coordinates.size();
    Eigen::MatrixXd t(n, n), v(n, n);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) {
            t(i, j) = GiNaC::ex_to<GiNaC::numeric>(a.linearization->kinetic(i, j).subs(at).evalf()).to_double();
            v(i, j) = GiNaC::ex_to<GiNaC::numeric>(a.linearization->potential(i, j).subs(at).evalf()).to_double();
        }
    double trace = t.lu().solve(v).trace();
    double sum = 0;
    for (double w2 : a.numeric->at(0).omega_squared)
        sum += w2;
    CHECK(sum == Approx(trace).epsilon(1e-10));
    CHECK(a.numeric->at(0).omega_squared.size() == n);
}

TEST_CASE("budget: --max-terms trips with a message naming the stage, exit 1 only if nothing was computed",
          "[budget][cli]")
{
    std::string scene = temporary_file("chain6.lag", chain(6));
    // Only the symbolic product was wanted: nothing computed, exit 1.
    cli_result alone = run_cli(scene + " --want characteristic --max-terms 200");
    CHECK(alone.exit_code == 1);
    CHECK(alone.err ==
          "lagrange: error: the `characteristic` stage exceeded its size budget: a minor of the determinant has "
          "more than 200 terms (--max-terms)\n");
    CHECK(alone.out.empty());
    // With the numeric modes too: exit 0, the numeric modes and a note.
    cli_result both = run_cli(scene + " --want characteristic,numeric --max-terms 200 --format json");
    CHECK(both.exit_code == 0);
    CHECK(both.out.find("\"numeric\"") != std::string::npos);
    CHECK(both.out.find("exceeded its size budget") != std::string::npos);
    // The default budget is enough for the examples and for a 3-link chain.
    cli_result roomy = run_cli(temporary_file("chain3.lag", chain(3)) + " --want characteristic");
    CHECK(roomy.exit_code == 0);
    // Bad budget values are usage errors.
    CHECK(run_cli(scene + " --max-terms 0").exit_code == 2);
    CHECK(run_cli(scene + " --max-seconds -1").exit_code == 2);
    CHECK(run_cli(scene + " --max-seconds abc").exit_code == 2);
}

TEST_CASE("budget: --max-seconds trips with a message naming the stage and exit code 1", "[budget][cli]")
{
    std::string scene = temporary_file("chain9.lag", chain(9));
    cli_result r = run_cli(scene + " --want characteristic --max-seconds 0.001 --max-terms 100000000", "", 60);
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("stage exceeded its time budget of 0.001 s (--max-seconds)") != std::string::npos);
}

namespace {

/// The 9-link chain with every mass and length distinct, whose characteristic polynomial
/// takes seconds (with the size budget lifted), most of it inside FLINT's and GiNaC's
/// calls that no cooperative check reaches.
std::string slow_chain() { return temporary_file("chain9.lag", chain(9)); }

/// One run under `seconds`: it stops with exit 1, naming the stage and the budget, within a
/// tenth of the budget plus the earlier stages and start-up. Those are measured just before,
/// as a run that stops after the linearization, so that a loaded machine slows both alike.
void require_budget_held(const std::string& scene, double seconds)
{
    std::ostringstream budget;
    budget << seconds;
    const cli_result before = run_cli(scene + " --want linearization", "", 60);
    REQUIRE(before.exit_code == 0);
    cli_result r =
        run_cli(scene + " --want characteristic --max-terms 100000000 --max-seconds " + budget.str(), "", 60);
    INFO(r.err);
    INFO("start-up and the earlier stages: " << before.seconds << " s");
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("stage exceeded its time budget of " + budget.str() + " s (--max-seconds)") != std::string::npos);
    const char* scale = std::getenv("LAGRANGE_TEST_TIME_SCALE"); // sanitized builds start slower
    CHECK(r.seconds < 1.1 * seconds + before.seconds + 0.3 * (scale ? std::max(1, std::atoi(scale)) : 1));
}

} // namespace

TEST_CASE("budget: the watchdog holds --max-seconds inside GiNaC calls", "[budget][cli]")
{
    require_budget_held(slow_chain(), 0.5);
}

TEST_CASE("budget: the slow chain stops within a tenth of a 2 s budget, 20 times", "[budget][cli][slow]")
{
    const std::string scene = slow_chain();
    for (int run = 0; run < 20; ++run) {
        INFO("run " << run);
        require_budget_held(scene, 2);
    }
}

TEST_CASE("output: a failing run with -o leaves the existing file intact and no temporary file", "[cli][output]")
{
    std::string folder = fresh_folder();
    std::string target = folder + "/result.txt";
    temporary_file("unused", "");
    {
        std::ofstream out(target);
        out << "the old result\n";
    }
    std::string bad = temporary_file("bad.lag", "parameters m\ncoordinates q\nV = q @\n");
    std::string chain6 = temporary_file("chain6o.lag", chain(6));
    // Bad input (exit 2), a computation that cannot be done (exit 1), a budget that trips (exit 1).
    CHECK(run_cli(bad + " -o " + target).exit_code == 2);
    CHECK(run_cli(examples + "charged_particle.lag --want frequencies -o " + target).exit_code == 1);
    CHECK(run_cli(chain6 + " --want characteristic --max-terms 10 -o " + target).exit_code == 1);
    CHECK(read_file(target) == "the old result\n");
    CHECK(folder_entries(folder) == std::vector<std::string>{"result.txt"});
    // A target that cannot be written (a folder): exit 2, nothing left behind.
    std::string sub = folder + "/sub";
    REQUIRE(mkdir(sub.c_str(), 0755) == 0);
    cli_result onto_folder = run_cli(examples + "double_pendulum.lag -o " + sub);
    CHECK(onto_folder.exit_code == 2);
    CHECK(onto_folder.err.find("cannot write") != std::string::npos);
    CHECK(folder_entries(folder) == std::vector<std::string>{"result.txt", "sub"});
    CHECK(folder_entries(sub).empty());
    // Success replaces the file whole, with the usual permissions.
    CHECK(run_cli(examples + "double_pendulum.lag -o " + target).exit_code == 0);
    CHECK(read_file(target) == run_cli(examples + "double_pendulum.lag").out);
    CHECK(folder_entries(folder) == std::vector<std::string>{"result.txt", "sub"});
    struct stat info {};
    REQUIRE(stat(target.c_str(), &info) == 0);
    CHECK((info.st_mode & 0044) == 0044); // readable by others, as with a plain redirect (umask 022)
    rmdir(sub.c_str());
    std::remove(target.c_str());
    rmdir(folder.c_str());
}

TEST_CASE("nothing is left in the working folder after any run", "[cli][output]")
{
    std::string folder = fresh_folder();
    std::string chain6 = temporary_file("chain6w.lag", chain(6));
    std::string bad = temporary_file("bad2.lag", "parameters m\ncoordinates q\nV = 1/0*q\n");
    std::vector<std::string> runs;
    for (const char* example : {"double_pendulum.lag", "charged_particle.lag", "rotating_hoop.lag",
                                "linear_molecule.lag", "elastic_pendulum.lag"})
        for (const char* format : {"text", "latex", "json"})
            runs.push_back(examples + example + " --timings --format " + format);
    runs.push_back(examples + "double_pendulum.lag --want numeric --values M=1,m=1e-8,l=1,g=9.81");
    runs.push_back("check " + examples + "coupled_oscillators.lag");
    runs.push_back(chain6 + " --max-terms 50 --want characteristic,numeric");
    runs.push_back(chain6 + " --max-terms 50 --want characteristic");
    runs.push_back(bad);
    runs.push_back("no-such-file.lag");
    runs.push_back("simulate " + examples + "double_pendulum.lag");
    runs.push_back("--help");
    for (const std::string& args : runs) {
        INFO(args);
        int code = run_in(folder, args);
        CHECK(code <= 2);
        CHECK(folder_entries(folder).empty());
    }
    // Output files land where -o says and nowhere else.
    CHECK(run_in(folder, examples + "double_pendulum.lag -o out.json --format json") == 0);
    CHECK(folder_entries(folder) == std::vector<std::string>{"out.json"});
    std::remove((folder + "/out.json").c_str());
    rmdir(folder.c_str());
}

TEST_CASE("sweep: the double pendulum over m/M = 1e-6 ... 1e6 matches the closed form, streamed", "[sweep][cli]")
{
    std::string out = temporary_file("sweep.txt", "");
    cli_result r = run_cli(examples + "double_pendulum.lag --values M=1,l=1,g=9.81 --sweep m=1e-6..1e6:1201:log -o " +
                           out);
    REQUIRE(r.exit_code == 0);
    std::istringstream lines(read_file(out));
    std::string line;
    std::getline(lines, line);
    CHECK(line == "# m omega1 omega2 error1 error2 stability");
    std::size_t rows = 0;
    double previous = 0;
    while (std::getline(lines, line)) {
        std::istringstream fields(line);
        double mu, w1, w2, e1, e2;
        REQUIRE(fields >> mu >> w1 >> w2 >> e1 >> e2);
        CHECK(mu > previous);
        previous = mu;
        if (rows % 100 == 0) // the grid's powers of ten are exact: 1e-3, not 0.0010000000000000002
            CHECK(mu == std::stod("1e" + std::to_string(static_cast<int>(rows / 100) - 6)));
        // Independent reference (M = l = 1): ω±² = g (1 + μ ± √(μ(1 + μ))); the small
        // root from the product of the roots, g² (1 + μ), to avoid cancellation.
        const double g = 9.81;
        const double large = g * (1 + mu + std::sqrt(mu * (1 + mu)));
        const double small = g * g * (1 + mu) / large;
        CHECK(w1 == Approx(std::sqrt(small)).epsilon(1e-13));
        CHECK(w2 == Approx(std::sqrt(large)).epsilon(1e-13));
        CHECK(e1 < 1e-13);
        CHECK(e2 < 1e-13);
        ++rows;
    }
    CHECK(rows == 1201);
    CHECK(previous == 1e6);
    // JSON: one object, streamed, that parses.
    cli_result json = run_cli(examples + "double_pendulum.lag --sweep m=1..2:3 --sweep l=1..3:2 --format json");
    REQUIRE(json.exit_code == 0);
    CHECK(json.out.find("\"points\"") != std::string::npos);
    CHECK(std::count(json.out.begin(), json.out.end(), '\n') == 1 + 6 + 1);
}

TEST_CASE("sweep: bad sweeps are located input errors, a singular point is named, and -o keeps the old file",
          "[sweep][cli]")
{
    const std::string scene = examples + "double_pendulum.lag";
    cli_result unknown = run_cli(scene + " --sweep q=1..2:3");
    CHECK(unknown.exit_code == 2);
    CHECK(unknown.err == "--sweep:1:1: error: `q` is not a parameter of the scene\nq=1..2:3\n^\n");
    CHECK(run_cli(scene + " --sweep m=1..x:3").exit_code == 2);
    CHECK(run_cli(scene + " --sweep m=0..1:3:log").exit_code == 2);
    CHECK(run_cli(scene + " --sweep m=1..2:0").exit_code == 2);
    CHECK(run_cli(scene + " --sweep m=1..2").exit_code == 2);
    CHECK(run_cli(scene + " --sweep m=1..2:3 --format latex").exit_code == 2);
    // T = (a − b) x'²/2 with positive values: singular at the third point, a = b.
    const std::string singular_scene = temporary_file("singular_sweep.lag", "parameters a b k\ncoordinates x\n"
                                                      "T = 1/2*(a - b)*x'^2\nV = 1/2*k*x^2\nvalues a = 2, b = 1, k = 1\n");
    std::string target = temporary_file("sweep-old.txt", "old\n");
    cli_result singular = run_cli(singular_scene + " --sweep a=3..1:3 -o " + target);
    CHECK(singular.exit_code == 1);
    CHECK(singular.err.find("sweep point 3 (a = 1, b = 1, k = 1)") != std::string::npos);
    CHECK(read_file(target) == "old\n");
}

TEST_CASE("numeric modes: a non-finite value is an error naming its cause", "[numeric][cli]")
{
    cli_result overflow = run_cli(examples + "double_pendulum.lag --want numeric --values M=1e200,m=1,l=1e200,g=1");
    CHECK(overflow.exit_code == 1);
    CHECK(overflow.err == "lagrange: error: the entry T(1,1) of the kinetic matrix overflows double precision at the "
                          "values on line 1 (its magnitude is beyond 1.8e308)\n");
    std::string root = temporary_file("sqrt.lag", "parameters m k\ncoordinates x\nT = 1/2*m*x'^2\n"
                                                  "V = 1/2*sqrt(k-2)*x^2\nequilibrium x = 0\nvalues m = 1, k = 1\n");
    cli_result domain = run_cli(root + " --want numeric");
    CHECK(domain.exit_code == 1);
    CHECK(domain.err.find("the entry V(1,1) of the potential matrix is not real at the values on line 6: a value "
                          "outside the domain of sqrt") != std::string::npos);
    std::string log = temporary_file("log.lag", "parameters m k\ncoordinates x\nT = 1/2*m*x'^2\n"
                                                "V = 1/2*log(k-1)*x^2\nequilibrium x = 0\nvalues m = 1, k = 1\n");
    cli_result pole = run_cli(log + " --want numeric");
    CHECK(pole.exit_code == 1);
    CHECK(pole.err.find("V(1,1) of the potential matrix cannot be evaluated at the values on line 6") !=
          std::string::npos);
    for (const cli_result* r : {&overflow, &domain, &pole}) {
        CHECK(r->out.find("nan") == std::string::npos);
        CHECK(r->out.find("inf") == std::string::npos);
    }
}

TEST_CASE("nothing runs a shell: no system or popen, and programs start only from the one runner", "[output]")
{
    // A guard over the sources: scene text must never reach a shell. External programs
    // (cc for native equations of motion; gnuplot and pdflatex) are started with an
    // argument vector, and only from this file (run_program).
    const std::set<std::string> runners = {"lib/system/external.cpp"};
    std::size_t scanned = 0;
    std::set<std::string> starting;
    for (const char* folder : {"lib", "cli"})
        for (const auto& entry :
             std::filesystem::recursive_directory_iterator(std::string(LAGRANGE_SOURCE_DIR) + "/" + folder)) {
            std::string ext = entry.path().extension().string();
            if (ext != ".cpp" && ext != ".h")
                continue;
            std::string path = std::filesystem::relative(entry.path(), LAGRANGE_SOURCE_DIR).string();
            std::string text = read_file(entry.path().string());
            ++scanned;
            for (const char* call : {"std::system(", " system(\"", "(system(", "= system(", "popen(", "/bin/sh", "execl"}) {
                INFO(path << " contains " << call);
                CHECK(text.find(call) == std::string::npos);
            }
            for (const char* call : {"execv(", "execvp(", "fork()", "posix_spawn(", "posix_spawnp("})
                if (ext == ".cpp" && text.find(call) != std::string::npos)
                    starting.insert(path);
        }
    CHECK(scanned > 20);
    for (const std::string& path : starting) {
        INFO(path << " starts a program but is not the runner");
        CHECK(runners.count(path) == 1);
    }
    CHECK(starting.size() == 1);
}
