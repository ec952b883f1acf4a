// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_export.cpp
 *  `lagrange export`: the exported C, Python and Octave code reproduces `lagrange simulate`
 *  (at tolerance 1e-12) to 1e-8 relative over the same run, and its Jacobian agrees with
 *  central differences of its own right-hand side to 1e-6; for the double pendulum, the
 *  heavy top, the damped driven oscillator (an input), a 10-link chain and a scene with
 *  sinh, cosh, tanh, asin, acos, atan and abs; the exported
 *  equilibrium, T and V against `state_space`; the rolling coin's constrained export against
 *  simulate and the engine's multipliers; for trees of point masses, each target's rhs by the
 *  articulated-body recursion against its own M and F solved (1e-12). And bad input. */
#include "helpers/chain_scene.h"
#include "helpers/cli_runner.h"
#include "helpers/tools.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <vector>

using namespace lagrange_test;

namespace {

const std::string examples = std::string(LAGRANGE_SOURCE_DIR) + "/examples/";

/// A scene of the equivalence tests: its file, the end time, and the input u(t) in each
/// target's syntax (p is the parameter vector, 0-based in C and Python, 1-based in Octave).
struct exported_case {
    std::string file;
    double until;
    std::string c_input, python_input, octave_input;
};

std::vector<exported_case> cases()
{
    std::string values = "values g = 9.81";
    for (int k = 1; k <= 10; ++k)
        values += ", m" + std::to_string(k) + " = " + std::to_string(k) + ", l" + std::to_string(k) + " = 0.5";
    static const std::string chain =
        temporary_file("chain10.lag", chain_scene(10) + values + "\ninitial q1 = 0.3, q5 = -0.2\n");
    // every function beyond sin, cos, tan, exp and log, in M, in F and in their derivatives
    static const std::string functions = temporary_file(
        "functions.lag", "parameters m k c g\ncoordinates x y\n"
                         "T = 1/2*m*(2 + acos(tanh(y)))*x'^2 + 1/2*m*(1 + atan(x)^2 + sinh(x)*tanh(x))*y'^2\n"
                         "V = k*(cosh(x) - 1) + g*asin(tanh(y))^2 + c*abs(y)^3\n"
                         "values m = 1, k = 2, c = 0.5, g = 3\ninitial x = 0.4, y = -0.3, y' = 0.2\n");
    return {{examples + "double_pendulum.lag", 2, "", "", ""},
            {examples + "heavy_top.lag", 0.5, "", "", ""},
            {examples + "damped_driven_oscillator.lag", 3, "p[3] * cos(p[4] * t)", "[p[3] * np.cos(p[4] * t)]",
             "p(4) * cos(p(5) * t)"},
            {chain, 0.5, "", "", ""},
            {functions, 3, "", "", ""}};
}

/// `lagrange simulate` at tolerance 1e-12: the states at t = 0 and at the end, in state order.
struct reference {
    std::vector<double> start, end;
};

reference simulate(const exported_case& c)
{
    cli_result r = run_cli("simulate " + c.file + " --until " + std::to_string(c.until) +
                               " --tolerance 1e-12 --format json",
                           "", 120);
    REQUIRE(r.exit_code == 0);
    nlohmann::json doc = nlohmann::json::parse(r.out);
    reference out;
    for (const std::string& q : doc["coordinates"].get<std::vector<std::string>>()) {
        out.start.push_back(doc["simulation"]["states"][q].front().get<double>());
        out.end.push_back(doc["simulation"]["states"][q].back().get<double>());
    }
    for (const std::string& q : doc["coordinates"].get<std::vector<std::string>>()) {
        out.start.push_back(doc["simulation"]["states"][q + "_dot"].front().get<double>());
        out.end.push_back(doc["simulation"]["states"][q + "_dot"].back().get<double>());
    }
    return out;
}

std::string folder_for(const std::string& what)
{
    const std::string probe = temporary_file(what + ".probe", "");
    return probe.substr(0, probe.size() - 6);
}

std::string name_of(const exported_case& c)
{
    std::string stem = c.file.substr(c.file.rfind('/') + 1);
    return stem.substr(0, stem.rfind('.'));
}

std::string numbers(const std::vector<double>& x, const char* separator)
{
    std::ostringstream out;
    out.precision(17);
    for (std::size_t k = 0; k < x.size(); ++k)
        out << (k ? separator : "") << x[k];
    return out.str();
}

/// What a program printed: the end state, then the worst relative difference of the
/// Jacobian from central differences, all on one line.
std::vector<double> read_numbers(const std::string& text)
{
    std::istringstream in(text);
    std::vector<double> out;
    for (double v; in >> v;)
        out.push_back(v);
    return out;
}

void check_against(const reference& expected, const std::vector<double>& printed)
{
    REQUIRE(printed.size() == expected.end.size() + 1);
    double scale = 1;
    for (double v : expected.end)
        scale = std::max(scale, std::abs(v));
    for (std::size_t k = 0; k < expected.end.size(); ++k)
        CHECK(std::abs(printed[k] - expected.end[k]) <= 1e-8 * scale);
    CHECK(printed.back() <= 1e-6); // the Jacobian against central differences
}

/// The exported equilibrium, T, V, and the Jacobian there as printed by a target's program:
/// x* (NX), T and V (row-major), A (NX × NX), B (NX × NU). A and B must be `state_space`'s at the
/// scene's first `values` point (the engine's own symbolic A, B), and T A₂₁ = −V (A's
/// lower-left block is −T⁻¹V when nothing depends on the velocities at rest).
void check_linear(const std::string& file, const std::vector<double>& printed, bool velocity_free)
{
    cli_result r = run_cli(file + " --want state_space --format json");
    REQUIRE(r.exit_code == 0);
    const nlohmann::json point = nlohmann::json::parse(r.out)["state_space"]["numeric"].at(0);
    const auto a = point["A"].get<std::vector<std::vector<double>>>();
    const auto b = point["B"].get<std::vector<std::vector<double>>>();
    const std::size_t nx = a.size(), n = nx / 2, nu = b.empty() ? 0 : b[0].size();
    REQUIRE(printed.size() == nx + 2 * n * n + nx * nx + nx * nu);
    const double* t = &printed[nx];
    const double* v = t + n * n;
    const double* exported_a = v + n * n;
    const double* exported_b = exported_a + nx * nx;
    for (std::size_t i = 0; i < nx; ++i) {
        for (std::size_t j = 0; j < nx; ++j)
            CHECK(std::abs(exported_a[i * nx + j] - a[i][j]) <= 1e-12 * (1 + std::abs(a[i][j])));
        for (std::size_t k = 0; k < nu; ++k)
            CHECK(std::abs(exported_b[i * nu + k] - b[i][k]) <= 1e-12 * (1 + std::abs(b[i][k])));
    }
    for (std::size_t i = 0; i < n && velocity_free; ++i)
        for (std::size_t j = 0; j < n; ++j) {
            double ta = 0; // (T A₂₁)_ij
            for (std::size_t k = 0; k < n; ++k)
                ta += t[i * n + k] * exported_a[(n + k) * nx + j];
            CHECK(std::abs(ta + v[i * n + j]) <= 1e-12 * (1 + std::abs(v[i * n + j])));
        }
}

/// The scenes whose equilibrium and linearization the targets export: the double pendulum
/// (T, V coupled) and the damped driven oscillator (an input, and damping in A).
const std::vector<std::pair<std::string, bool>> linear_cases = {{"double_pendulum", true},
                                                                {"damped_driven_oscillator", false}};

const char* c_harness = R"(#include "NAME.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#define NX NAME_NX
static double p[NAME_NP > 0 ? NAME_NP : 1];
static void input(double t, double *u) { (void)t; (void)u; INPUT }
static void f(double t, const double *x, double *dxdt)
{
    double u[NAME_NU > 0 ? NAME_NU : 1];
    input(t, u);
    if (NAME_rhs(t, x, u, p, dxdt)) { fprintf(stderr, "singular mass matrix\n"); exit(1); }
}
int main(int argc, char **argv)
{
    double x[NX], k1[NX], k2[NX], k3[NX], k4[NX], y[NX], worst = 0;
    double dfdx[NX * NX], dfdu[NX * (NAME_NU > 0 ? NAME_NU : 1)], u[NAME_NU > 0 ? NAME_NU : 1];
    double until = atof(argv[1]);
    int steps = atoi(argv[2]), i, j, s;
    double h = until / steps, t = 0;
    for (i = 0; i < NAME_NP; ++i) p[i] = NAME_default_p[i];
    for (i = 0; i < NX && i + 3 < argc; ++i) x[i] = atof(argv[i + 3]);
    /* The Jacobian at the start against central differences of the right-hand side. */
    input(0.0, u);
    NAME_jacobian(0.0, x, u, p, dfdx, dfdu);
    for (j = 0; j < NX; ++j) {
        double e = 1e-6 * (fabs(x[j]) > 1 ? fabs(x[j]) : 1), up[NX], down[NX], fu[NX], fd[NX], big = 1;
        for (i = 0; i < NX; ++i) { up[i] = x[i]; down[i] = x[i]; }
        up[j] += e; down[j] -= e;
        f(0.0, up, fu); f(0.0, down, fd);
        for (i = 0; i < NX; ++i) if (fabs(dfdx[i * NX + j]) > big) big = fabs(dfdx[i * NX + j]);
        for (i = 0; i < NX; ++i) {
            double d = fabs((fu[i] - fd[i]) / (2 * e) - dfdx[i * NX + j]) / big;
            if (d > worst) worst = d;
        }
    }
    for (s = 0; s < steps; ++s, t = s * h) {
        f(t, x, k1);
        for (i = 0; i < NX; ++i) y[i] = x[i] + 0.5 * h * k1[i];
        f(t + 0.5 * h, y, k2);
        for (i = 0; i < NX; ++i) y[i] = x[i] + 0.5 * h * k2[i];
        f(t + 0.5 * h, y, k3);
        for (i = 0; i < NX; ++i) y[i] = x[i] + h * k3[i];
        f(t + h, y, k4);
        for (i = 0; i < NX; ++i) x[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    }
#ifdef CONSTRAINED
    { /* the constraints' largest residual at the end */
        double g[NAME_NC];
        NAME_constraints(until, x, NULL, p, g);
        for (i = 0; i < NAME_NC; ++i) if (fabs(g[i]) > worst) worst = fabs(g[i]);
    }
#endif
    for (i = 0; i < NX; ++i) printf("%.17g ", x[i]);
    printf("%.17g\n", worst);
    return 0;
}
)";

std::string replace_all(std::string text, const std::string& from, const std::string& to)
{
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
        text.replace(at, from.size(), to);
    return text;
}

} // namespace

TEST_CASE("export: the C code compiles warning-free and reproduces simulate", "[export][cc]")
{
    for (const exported_case& c : cases()) {
        INFO(c.file);
        const reference expected = simulate(c);
        const std::string folder = folder_for("c-" + name_of(c));
        REQUIRE(run_cli("export " + c.file + " --to c -o " + folder).exit_code == 0);
        const std::string name = name_of(c);
        std::ofstream(folder + "/harness.c")
            << replace_all(replace_all(c_harness, "NAME", name), "INPUT",
                           c.c_input.empty() ? "" : "u[0] = " + c.c_input + ";");
        // The harness's own size of loops is fine at -O2; the exported file is held to -Werror.
        const std::string cc = configured_compiler(); // LAGRANGE_CC, as the engine's own code
        run_shell("cd " + folder + " && " + cc + " -std=c99 -Wall -Wextra -pedantic -Werror -O2 -c " + name +
                  ".c 2>&1 && " + cc + " -std=c99 -O2 -o harness harness.c " + name + ".o -lm 2>&1");
        const int steps = static_cast<int>(std::ceil(c.until / 2e-4));
        check_against(expected, read_numbers(run_shell(folder + "/harness " + std::to_string(c.until) + " " +
                                                       std::to_string(steps) + " " + numbers(expected.start, " "))));
    }
}

TEST_CASE("export: the Python module works with solve_ivp and reproduces simulate", "[export][scipy]")
{
    for (const exported_case& c : cases()) {
        INFO(c.file);
        const reference expected = simulate(c);
        const std::string folder = folder_for("py-" + name_of(c));
        REQUIRE(run_cli("export " + c.file + " --to python -o " + folder).exit_code == 0);
        const std::string name = name_of(c);
        std::ofstream(folder + "/check.py")
            << "import sys\nsys.path.insert(0, " << nlohmann::json(folder).dump() << ")\n"
            << "import numpy as np\nfrom scipy.integrate import solve_ivp\nimport " << name << " as m\n"
            << "p = m.DEFAULTS\nx0 = np.array([" << numbers(expected.start, ", ") << "], dtype=float)\n"
            << "u = lambda t: " << (c.python_input.empty() ? "None" : c.python_input) << "\n"
            << "run = solve_ivp(lambda t, x: m.rhs(t, x, p, u(t)), (0, " << c.until
            << "), x0, method='DOP853', rtol=1e-13, atol=1e-13)\n"
            << "dfdx, dfdu = m.jacobian(0.0, x0, p, u(0.0))\nworst = 0.0\n"
            << "for j in range(m.NX):\n    e = 1e-6 * max(1.0, abs(x0[j]))\n"
            << "    up, down = x0.copy(), x0.copy()\n    up[j] += e\n    down[j] -= e\n"
            << "    fd = (m.rhs(0.0, up, p, u(0.0)) - m.rhs(0.0, down, p, u(0.0))) / (2 * e)\n"
            << "    worst = max(worst, np.max(np.abs(fd - dfdx[:, j])) / max(1.0, np.max(np.abs(dfdx[:, j]))))\n"
            << "print(' '.join(repr(v) for v in run.y[:, -1]), repr(worst))\n"
            << "batch = np.stack([x0, x0])\n"
            << "assert np.allclose(m.rhs(0.0, batch, p, None if u(0.0) is None else np.stack([u(0.0)] * 2)),"
               " m.rhs(0.0, x0, p, u(0.0)), rtol=0, atol=0)\n";
        check_against(expected, read_numbers(run_shell("/usr/bin/python3 " + folder + "/check.py")));
    }
}

TEST_CASE("export: the Octave functions work with ode45 and reproduce simulate", "[export][octave]")
{
    for (const exported_case& c : cases()) {
        if (c.file.find("chain10") != std::string::npos)
            continue; // ode45 at 1e-12 on twenty states takes minutes in Octave; the chain is C's and Python's
        INFO(c.file);
        const reference expected = simulate(c);
        const std::string folder = folder_for("octave-" + name_of(c));
        REQUIRE(run_cli("export " + c.file + " --to octave -o " + folder).exit_code == 0);
        const std::string name = name_of(c);
        const std::string input = c.octave_input.empty() ? "zeros(0, 1)" : c.octave_input;
        std::ofstream(folder + "/check.m")
            << "p = " << name << "_defaults();\nx0 = [" << numbers(expected.start, "; ") << "];\n"
            << "u = @(t) " << input << ";\n"
            << "opts = odeset('RelTol', 1e-12, 'AbsTol', 1e-13);\n"
            << "[t, X] = ode45(@(t, x) " << name << "_rhs(t, x, p, u(t)), [0 " << c.until << "], x0, opts);\n"
            << "[dfdx, dfdu] = " << name << "_jacobian(0, x0, p, u(0));\nworst = 0;\n"
            << "for j = 1:numel(x0)\n  e = 1e-6 * max(1, abs(x0(j)));\n  up = x0; down = x0;\n"
            << "  up(j) += e; down(j) -= e;\n"
            << "  fd = (" << name << "_rhs(0, up, p, u(0)) - " << name << "_rhs(0, down, p, u(0))) / (2 * e);\n"
            << "  worst = max(worst, max(abs(fd - dfdx(:, j))) / max(1, max(abs(dfdx(:, j)))));\nend\n"
            << "printf('%.17g ', X(end, :));\nprintf('%.17g\\n', worst);\n";
        check_against(expected,
                      read_numbers(run_shell("cd " + folder + " && octave-cli --no-gui --quiet check.m 2>&1")));
    }
}

namespace {

/// Trees of points and bodies, whose exported rhs takes q'' from the articulated-body recursion:
/// a 3-link chain, a cart on a spring and a damper, pushed by an input, carrying a double
/// pendulum, and a chain of three rods each turning with its own angle; with their sizes, and the index of a parameter (a rod's length) that makes M
/// singular at 0.
struct tree_case {
    std::string file, name;
    int coordinates, inputs, singular;
};

std::vector<tree_case> tree_cases()
{
    static const std::string chain =
        temporary_file("tree_chain.lag", chain_scene(3) + "values g = 9.81, m1 = 1.1, l1 = 0.9, m2 = 0.7, l2 = 1.3, "
                                                          "m3 = 0.5, l3 = 0.6\n");
    static const std::string cart = temporary_file(
        "tree_cart.lag", "parameters mc m1 m2 l1 l2 g k b\ncoordinates x th1 th2\ninput F\n"
                         "point C mass mc at (x, 0)\n"
                         "point P1 mass m1 at (x + l1*sin(th1), -l1*cos(th1))\n"
                         "point P2 mass m2 at (x + l1*sin(th1) + l2*sin(th2), -l1*cos(th1) - l2*cos(th2))\n"
                         "gravity g along (0, -1)\nspring k between C and (0, 0)\ndamper b between C and (0, 0)\n"
                         "force on C (F, 0)\n"
                         "values mc = 1.5, m1 = 0.4, m2 = 0.3, l1 = 0.6, l2 = 0.5, g = 9.81, k = 20, b = 0.7\n");
    static const std::string rods = temporary_file(
        "tree_rods.lag",
        "parameters m l g\ncoordinates a b c\n"
        "body A stick(l) mass m axis y at (l/2*sin(a), -l/2*cos(a), 0) orientation rotations(z a)\n"
        "body B stick(l) mass m axis y at (l*sin(a) + l/2*sin(b), -l*cos(a) - l/2*cos(b), 0) "
        "orientation rotations(z b)\n"
        "body C stick(l) mass 2*m axis y at (l*sin(a) + l*sin(b) + l/2*sin(c), -l*cos(a) - l*cos(b) - l/2*cos(c), 0) "
        "orientation rotations(z c)\n"
        "gravity g along (0, -1, 0)\nvalues m = 1.1, l = 0.8, g = 9.81\n");
    return {{chain, "tree_chain", 3, 0, 4}, {cart, "tree_cart", 3, 1, 4}, {rods, "tree_rods", 3, 0, 1}};
}

/// What every target's check prints: the largest difference of rhs's q'' from M q'' = F solved
/// with the exported mass_matrix and forcing, relative to the largest q'', over random states,
/// inputs and times in [-2, 2]; whether rhs's q' is x's; and whether rhs reports the singular
/// M of a rod of length 0 (C: returns nonzero; Python: LinAlgError; Octave: a q'' not finite).
void check_tree(const std::vector<double>& printed)
{
    REQUIRE(printed.size() == 3);
    CHECK(printed[0] <= 1e-12);
    CHECK(printed[1] == 1.0);
    CHECK(printed[2] == 1.0);
}

} // namespace

TEST_CASE("export: a tree's C rhs takes the recursion and agrees with M and F", "[export][cc]")
{
    for (const tree_case& c : tree_cases()) {
        INFO(c.file);
        const std::string folder = folder_for("c-" + c.name);
        REQUIRE(run_cli("export " + c.file + " --to c -o " + folder).exit_code == 0);
        CHECK(read_file(folder + "/" + c.name + ".c").find("articulated-body recursion") != std::string::npos);
        std::ofstream(folder + "/tree.c") << replace_all(replace_all(R"(#include "NAME.h"
#include <math.h>
#include <stdio.h>
static double uniform(unsigned long long *seed)
{
    *seed = *seed * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*seed >> 11) / 9007199254740992.0 * 4.0 - 2.0;
}
int main(void)
{
    double x[NAME_NX], dxdt[NAME_NX], M[NAME_NQ * NAME_NQ], F[NAME_NQ], u[NAME_NU + 1], p[NAME_NP], worst = 0.0;
    unsigned long long seed = 2026;
    int k, i, j, r, ok = 1;
    for (i = 0; i < NAME_NP; ++i)
        p[i] = NAME_default_p[i];
    for (k = 0; k < 2000; ++k) {
        const double t = uniform(&seed);
        long double a[NAME_NQ][NAME_NQ + 1], q[NAME_NQ], largest = 0, difference = 0;
        for (i = 0; i < NAME_NX; ++i)
            x[i] = uniform(&seed);
        for (i = 0; i < NAME_NU; ++i)
            u[i] = uniform(&seed);
        ok = ok && NAME_rhs(t, x, u, p, dxdt) == 0;
        NAME_mass_matrix(t, x, u, p, M);
        NAME_forcing(t, x, u, p, F);
        /* M q'' = F by Gaussian elimination with partial pivoting, in long double */
        for (i = 0; i < NAME_NQ; ++i) {
            for (j = 0; j < NAME_NQ; ++j)
                a[i][j] = M[i * NAME_NQ + j];
            a[i][NAME_NQ] = F[i];
        }
        for (j = 0; j < NAME_NQ; ++j) {
            int best = j;
            for (i = j + 1; i < NAME_NQ; ++i)
                if (fabsl(a[i][j]) > fabsl(a[best][j]))
                    best = i;
            for (r = 0; r <= NAME_NQ; ++r) {
                const long double swap = a[j][r];
                a[j][r] = a[best][r];
                a[best][r] = swap;
            }
            for (i = j + 1; i < NAME_NQ; ++i)
                for (r = NAME_NQ; r >= j; --r)
                    a[i][r] -= a[i][j] / a[j][j] * a[j][r];
        }
        for (i = NAME_NQ - 1; i >= 0; --i) {
            q[i] = a[i][NAME_NQ];
            for (j = i + 1; j < NAME_NQ; ++j)
                q[i] -= a[i][j] * q[j];
            q[i] /= a[i][i];
        }
        for (i = 0; i < NAME_NQ; ++i) {
            largest = fabsl(q[i]) > largest ? fabsl(q[i]) : largest;
            difference = fabsl(dxdt[NAME_NQ + i] - q[i]) > difference ? fabsl(dxdt[NAME_NQ + i] - q[i]) : difference;
            ok = ok && dxdt[i] == x[NAME_NQ + i];
        }
        worst = (double)(difference / largest) > worst ? (double)(difference / largest) : worst;
    }
    p[SINGULAR] = 0.0;
    printf("%.17g %d %d\n", worst, ok, NAME_rhs(0.5, x, u, p, dxdt) != 0);
    return 0;
}
)", "NAME", c.name), "SINGULAR", std::to_string(c.singular));
        const std::string cc = configured_compiler();
        check_tree(read_numbers(run_shell("cd " + folder + " && " + cc +
                                          " -std=c99 -Wall -Wextra -pedantic -Werror -O2 -o tree tree.c " + c.name +
                                          ".c -lm 2>&1 && ./tree")));
    }
}

TEST_CASE("export: a tree's Python rhs takes the recursion and agrees with M and F", "[export][scipy]")
{
    for (const tree_case& c : tree_cases()) {
        INFO(c.file);
        const std::string folder = folder_for("py-" + c.name);
        REQUIRE(run_cli("export " + c.file + " --to python -o " + folder).exit_code == 0);
        std::ofstream(folder + "/check.py")
            << "import sys\nsys.path.insert(0, " << nlohmann::json(folder).dump() << ")\n"
            << "import numpy as np\nimport " << c.name << " as m\n"
            << "assert 'articulated-body recursion' in m.__doc__\n"
            << "rng = np.random.default_rng(2026)\nn = 2000\n"
            << "t, x, u = rng.uniform(-2, 2, n), rng.uniform(-2, 2, (n, m.NX)), rng.uniform(-2, 2, (n, m.NU))\n"
            << "p = np.broadcast_to(m.DEFAULTS, (n, m.NP))\n"
            << "f = m.rhs(t, x, p, u)\n"
            << "q = np.linalg.solve(m.mass_matrix(t, x, p, u), m.forcing(t, x, p, u)[..., None])[..., 0]\n"
            << "worst = np.max(np.max(np.abs(f[:, m.NQ:] - q), axis=1) / np.max(np.abs(q), axis=1))\n"
            // one state at a time (on Python floats) as in the batch
            << "for j in range(50):\n"
            << "    one = m.rhs(t[j], x[j], m.DEFAULTS, u[j])\n"
            << "    worst = max(worst, np.max(np.abs(one[m.NQ:] - q[j])) / np.max(np.abs(q[j])))\n"
            << "velocities = int(np.array_equal(f[:, :m.NQ], x[:, m.NQ:]))\n"
            << "singular = m.DEFAULTS.copy()\nsingular[" << c.singular << "] = 0\nreported = 0\n"
            << "for state in (x[0], x[:3]):\n"
            << "    try:\n        m.rhs(0.5, state, singular, u[0])\n"
            << "    except np.linalg.LinAlgError:\n        reported += 1\n"
            << "print(repr(worst), velocities, int(reported == 2))\n";
        check_tree(read_numbers(run_shell("/usr/bin/python3 -W ignore " + folder + "/check.py")));
    }
}

TEST_CASE("export: a tree's Octave rhs takes the recursion and agrees with M and F", "[export][octave]")
{
    for (const tree_case& c : tree_cases()) {
        INFO(c.file);
        const std::string folder = folder_for("octave-" + c.name);
        REQUIRE(run_cli("export " + c.file + " --to octave -o " + folder).exit_code == 0);
        CHECK(read_file(folder + "/" + c.name + "_rhs.m").find("articulated-body recursion") != std::string::npos);
        const std::string n = c.name;
        std::ofstream(folder + "/check.m")
            << "rand('state', 2026);\np = " << n << "_defaults();\nnq = " << c.coordinates << ";\nnu = " << c.inputs
            << ";\nworst = 0;\nvelocities = 1;\n"
            << "for k = 1:300\n  t = 4 * rand() - 2;\n  x = 4 * rand(2 * nq, 1) - 2;\n  u = 4 * rand(nu, 1) - 2;\n"
            << "  f = " << n << "_rhs(t, x, p, u);\n"
            << "  q = " << n << "_mass_matrix(t, x, p, u) \\ " << n << "_forcing(t, x, p, u);\n"
            << "  worst = max(worst, max(abs(f(nq + 1:end) - q)) / max(abs(q)));\n"
            << "  velocities = velocities && isequal(f(1:nq), x(nq + 1:end));\nend\n"
            << "p(" << c.singular + 1 << ") = 0;\nf = " << n << "_rhs(0.5, x, p, u);\n"
            << "printf('%.17g %d %d\\n', worst, velocities, any(~isfinite(f)));\n";
        check_tree(read_numbers(run_shell("cd " + folder + " && octave-cli --no-gui --quiet check.m 2>&1")));
    }
}

TEST_CASE("export: the C equilibrium, T and V give state_space's A and B", "[export][cc]")
{
    for (const auto& [name, velocity_free] : linear_cases) {
        INFO(name);
        const std::string folder = folder_for("c-linear-" + name);
        REQUIRE(run_cli("export " + examples + name + ".lag --to c -o " + folder).exit_code == 0);
        std::ofstream(folder + "/linear.c") << replace_all(R"(#include "NAME.h"
#include <stdio.h>
int main(void)
{
    double x[NAME_NX], T[NAME_NQ * NAME_NQ], V[NAME_NQ * NAME_NQ], A[NAME_NX * NAME_NX], B[NAME_NX * NAME_NU + 1];
    double u[NAME_NU + 1] = {0.0};
    int i;
    NAME_equilibrium(NAME_default_p, x);
    NAME_linear(NAME_default_p, T, V);
    if (NAME_jacobian(0.0, x, u, NAME_default_p, A, B))
        return 1;
    for (i = 0; i < NAME_NX; ++i)
        printf("%.17g ", x[i]);
    for (i = 0; i < NAME_NQ * NAME_NQ; ++i)
        printf("%.17g ", T[i]);
    for (i = 0; i < NAME_NQ * NAME_NQ; ++i)
        printf("%.17g ", V[i]);
    for (i = 0; i < NAME_NX * NAME_NX; ++i)
        printf("%.17g ", A[i]);
    for (i = 0; i < NAME_NX * NAME_NU; ++i)
        printf("%.17g ", B[i]);
    printf("\n");
    return 0;
}
)", "NAME", name);
        const std::string cc = configured_compiler();
        run_shell("cd " + folder + " && " + cc + " -std=c99 -Wall -Wextra -pedantic -Werror -c " + name + ".c 2>&1 && " +
                  cc + " -std=c99 -o linear linear.c " + name + ".o -lm 2>&1");
        check_linear(examples + name + ".lag", read_numbers(run_shell(folder + "/linear")), velocity_free);
    }
}

TEST_CASE("export: the Python equilibrium, T and V give state_space's A and B", "[export][scipy]")
{
    for (const auto& [name, velocity_free] : linear_cases) {
        INFO(name);
        const std::string folder = folder_for("py-linear-" + name);
        REQUIRE(run_cli("export " + examples + name + ".lag --to python -o " + folder).exit_code == 0);
        std::ofstream(folder + "/linear.py")
            << "import sys\nsys.path.insert(0, " << nlohmann::json(folder).dump() << ")\n"
            << "import numpy as np\nimport " << name << " as m\n"
            << "x = m.equilibrium()\nT, V = m.linear()\nA, B = m.jacobian(0.0, x, m.DEFAULTS, np.zeros(m.NU))\n"
            << "print(' '.join(repr(float(v)) for v in np.concatenate([x, T.ravel(), V.ravel(), A.ravel(), "
               "B.ravel()])))\n";
        check_linear(examples + name + ".lag", read_numbers(run_shell("/usr/bin/python3 " + folder + "/linear.py")),
                     velocity_free);
    }
}

TEST_CASE("export: the Octave equilibrium, T and V give state_space's A and B", "[export][octave]")
{
    for (const auto& [name, velocity_free] : linear_cases) {
        INFO(name);
        const std::string folder = folder_for("octave-linear-" + name);
        REQUIRE(run_cli("export " + examples + name + ".lag --to octave -o " + folder).exit_code == 0);
        std::ofstream(folder + "/linear.m")
            << "x = " << name << "_equilibrium();\n[T, V] = " << name << "_linear();\n"
            << "[A, B] = " << name << "_jacobian(0, x, " << name << "_defaults());\n"
            << "printf('%.17g ', x, T', V', A', B');\nprintf('\\n');\n";
        check_linear(examples + name + ".lag",
                     read_numbers(run_shell("cd " + folder + " && octave-cli --no-gui --quiet linear.m 2>&1")),
                     velocity_free);
    }
}

TEST_CASE("export: a scene without an equilibrium is exported without the linearization", "[export]")
{
    const std::string folder = folder_for("c-kapitza");
    REQUIRE(run_cli("export " + examples + "kapitza_pendulum.lag --to c -o " + folder).exit_code == 0);
    std::ifstream header(folder + "/kapitza_pendulum.h");
    const std::string text((std::istreambuf_iterator<char>(header)), std::istreambuf_iterator<char>());
    CHECK(text.find("No equilibrium was found to linearize about") != std::string::npos);
    CHECK(text.find("_linear(") == std::string::npos);
}

TEST_CASE("export: the rolling coin's constrained C code reproduces simulate and its Jacobian", "[export][cc]")
{
    const exported_case coin{examples + "rolling_coin.lag", 1, "", "", ""};
    const reference expected = simulate(coin);
    const std::string folder = folder_for("c-coin");
    REQUIRE(run_cli("export " + coin.file + " --to c -o " + folder).exit_code == 0);
    std::ofstream(folder + "/coin.c") << replace_all(replace_all(c_harness, "NAME", "rolling_coin"), "INPUT", "");
    const std::string cc = configured_compiler();
    run_shell("cd " + folder + " && " + cc + " -std=c99 -Wall -Wextra -pedantic -Werror -O2 -c rolling_coin.c 2>&1 && " +
              cc + " -std=c99 -O2 -DCONSTRAINED -o coin coin.c rolling_coin.o -lm 2>&1");
    // the last number is the constraints' largest residual at the end, which check_against holds to 1e-6;
    // RK4's drift off them is far below
    check_against(expected, read_numbers(run_shell(folder + "/coin 1 5000 " + numbers(expected.start, " "))));
}

TEST_CASE("export: the rolling coin's Python module reproduces simulate, the multipliers and the Jacobian", "[export][scipy]")
{
    const exported_case coin{examples + "rolling_coin.lag", 1, "", "", ""};
    const reference expected = simulate(coin);
    const std::string folder = folder_for("py-coin");
    REQUIRE(run_cli("export " + coin.file + " --to python -o " + folder).exit_code == 0);
    // The engine's λ in closed form (`want multipliers`), evaluated by SymPy at the start.
    cli_result r = run_cli(coin.file + " --want multipliers --format json");
    REQUIRE(r.exit_code == 0);
    const nlohmann::json lambdas = nlohmann::json::parse(r.out)["multipliers"];
    std::ofstream(folder + "/check.py")
        << "import sys, json\nsys.path.insert(0, " << nlohmann::json(folder).dump() << ")\n"
        << "import numpy as np\nimport sympy\nfrom scipy.integrate import solve_ivp\nimport rolling_coin as m\n"
        << "x0 = np.array([" << numbers(expected.start, ", ") << "], dtype=float)\n"
        << "run = solve_ivp(m.rhs, (0, 1), x0, args=(m.DEFAULTS,), method='DOP853', rtol=1e-13, atol=1e-13)\n"
        << "lambdas = json.loads(" << nlohmann::json(lambdas.dump()).dump() << ")\n"
        << "at = dict(zip(m.STATE + m.PARAMETERS, list(x0) + list(m.DEFAULTS)))\n"
        << "names = {n: sympy.Symbol(n) for n in at}\n"
        << "engine = [float(sympy.sympify(lambdas[c].replace('^', '**'), locals=names).subs(at)) for c in m.CONSTRAINTS]\n"
        << "ours = m.multipliers(0.0, x0)\n"
        << "worst = max(abs(a - b) / max(1.0, abs(b)) for a, b in zip(ours, engine))\n"
        // the constrained Jacobian against central differences of rhs
        << "dfdx, dfdu = m.jacobian(0.0, x0)\n"
        << "for j in range(m.NX):\n    e = 1e-6 * max(1.0, abs(x0[j]))\n"
        << "    up, down = x0.copy(), x0.copy()\n    up[j] += e\n    down[j] -= e\n"
        << "    fd = (m.rhs(0.0, up) - m.rhs(0.0, down)) / (2 * e)\n"
        << "    worst = max(worst, np.max(np.abs(fd - dfdx[:, j])) / max(1.0, np.max(np.abs(dfdx[:, j]))))\n"
        << "batch = np.stack([x0, x0])\nassert np.allclose(m.jacobian(0.0, batch)[0][1], dfdx, rtol=1e-12, atol=1e-12)\n"
        << "drift = np.max(np.abs(m.constraints(1.0, run.y[:, -1])))\n"
        << "print(' '.join(repr(v) for v in run.y[:, -1]), repr(max(worst, drift)))\n";
    check_against(expected, read_numbers(run_shell("/usr/bin/python3 " + folder + "/check.py")));
}

TEST_CASE("export: the rolling coin's Octave functions reproduce simulate and the Jacobian", "[export][octave]")
{
    const exported_case coin{examples + "rolling_coin.lag", 1, "", "", ""};
    const reference expected = simulate(coin);
    const std::string folder = folder_for("octave-coin");
    REQUIRE(run_cli("export " + coin.file + " --to octave -o " + folder).exit_code == 0);
    std::ofstream(folder + "/check.m")
        << "p = rolling_coin_defaults();\nx0 = [" << numbers(expected.start, "; ") << "];\n"
        << "opts = odeset('RelTol', 1e-12, 'AbsTol', 1e-13);\n"
        << "[t, X] = ode45(@(t, x) rolling_coin_rhs(t, x, p), [0 1], x0, opts);\n"
        << "lambda = rolling_coin_multipliers(0, x0, p);\n"
        << "g = rolling_coin_constraints(1, X(end, :)', p);\n"
        << "[dfdx, dfdu] = rolling_coin_jacobian(0, x0, p);\nworst = max(abs(g));\n"
        << "for j = 1:numel(x0)\n  e = 1e-6 * max(1, abs(x0(j)));\n  up = x0; down = x0;\n"
        << "  up(j) += e; down(j) -= e;\n"
        << "  fd = (rolling_coin_rhs(0, up, p) - rolling_coin_rhs(0, down, p)) / (2 * e);\n"
        << "  worst = max(worst, max(abs(fd - dfdx(:, j))) / max(1, max(abs(dfdx(:, j)))));\nend\n"
        << "printf('%.17g ', X(end, :));\nprintf('%.17g\\n', worst);\n";
    check_against(expected,
                  read_numbers(run_shell("cd " + folder + " && octave-cli --no-gui --quiet check.m 2>&1")));
}

TEST_CASE("export: bad input is refused with nothing written", "[export]")
{
    const std::string pendulum = examples + "double_pendulum.lag";
    const std::string folder = folder_for("bad");
    cli_result target = run_cli("export " + pendulum + " --to fortran -o " + folder + "/a");
    CHECK(target.exit_code == 2);
    CHECK(target.err.find("--to") != std::string::npos);
    cli_result name = run_cli("export " + pendulum + " --to c --name 2fast -o " + folder + "/b");
    CHECK(name.exit_code == 2);
    CHECK(name.err.find("must be an identifier") != std::string::npos);
    cli_result keyword = run_cli("export " + pendulum + " --to c --name while -o " + folder + "/c");
    CHECK(keyword.exit_code == 2);
    cli_result unwritable = run_cli("export " + pendulum + " --to c -o /proc/lagrange-export");
    CHECK(unwritable.exit_code == 2);
    CHECK(unwritable.err.find("cannot write into `/proc/lagrange-export`") != std::string::npos);
    for (const char* never : {"/a", "/b", "/c"}) {
        struct stat info {};
        CHECK(::stat((folder + never).c_str(), &info) != 0);
    }
    // A free body's scene has no equations of motion to export: exit 1 with the reason.
    cli_result body = run_cli("export " + examples + "free_asymmetric_top.lag --to c -o " + folder + "/d");
    CHECK(body.exit_code == 1);
    CHECK(body.err.find("has no coordinates") != std::string::npos);
    struct stat info {};
    CHECK(::stat((folder + "/d").c_str(), &info) != 0);
}

TEST_CASE("export: the functions C code calls are reserved, in names and as the NAME", "[export]")
{
    // abs is written fabs in C (sinh, asin and the others are scene functions, never names)
    const std::string scene = temporary_file("reserved.lag", "parameters m fabs\ncoordinates x\n"
                                                             "T = 1/2*m*x'^2\nV = fabs*abs(x)^3\n"
                                                             "values m = 1, fabs = 2\n");
    const std::string folder = folder_for("reserved");
    REQUIRE(run_cli("export " + scene + " --to c -o " + folder + "/c").exit_code == 0);
    const std::string text = read_file(folder + "/c/reserved.c");
    CHECK(text.find("const double fabs_ = p[1];") != std::string::npos);
    CHECK(text.find("fabs(x_)") != std::string::npos);
    for (const char* reserved : {"fabs", "sinh", "cosh", "tanh", "asin", "acos", "atan"}) {
        INFO(reserved);
        CHECK(run_cli("export " + scene + " --to c --name " + reserved + " -o " + folder + "/" + reserved).exit_code ==
              2);
    }
}

TEST_CASE("export: names are the scene's, and a keyword is renamed as the header says", "[export]")
{
    const std::string scene = temporary_file("keywords.lag", "parameters m k lambda\ncoordinates x while\n"
                                                             "T = 1/2*m*(x'^2 + while'^2)\n"
                                                             "V = 1/2*k*x^2 + lambda*x*while + 1/2*k*while^2\n"
                                                             "values m = 1, k = 2, lambda = 0.5\n");
    const std::string folder = folder_for("names");
    REQUIRE(run_cli("export " + scene + " --to python -o " + folder + "/py").exit_code == 0);
    REQUIRE(run_cli("export " + scene + " --to c -o " + folder + "/c").exit_code == 0);
    std::ifstream py(folder + "/py/keywords.py");
    std::string python((std::istreambuf_iterator<char>(py)), {});
    // `x` and `k` are names of the generated functions' own (the state, a loop index).
    CHECK(python.find("Renamed (a keyword or an argument name gets `_` appended): x -> x_, while -> while_, "
                      "k -> k_, lambda -> lambda_.") != std::string::npos);
    CHECK(python.find("STATE = [\"x\", \"while\", \"x_dot\", \"while_dot\"]") != std::string::npos);
    CHECK(python.find("PARAMETERS = [\"m\", \"k\", \"lambda\"]") != std::string::npos);
    CHECK(python.find("DEFAULTS = np.array([1.0, 2.0, 0.5], dtype=float)") != std::string::npos);
    std::ifstream c(folder + "/c/keywords.c");
    std::string text((std::istreambuf_iterator<char>(c)), {});
    CHECK(text.find("const double while_ = x[1];") != std::string::npos);
    CHECK(text.find("const char *const keywords_state_names[keywords_NX] = {\"x\", \"while\", \"x_dot\", "
                    "\"while_dot\"};") != std::string::npos);
}

namespace {

/// The spherical pendulum's conserved quantities in closed form (θ from the downward
/// vertical, φ cyclic): h = ½ m l²(θ̇² + sin²θ φ̇²) − m g l cos θ and p_φ = m l² sin²θ φ̇, at
/// the state and parameters below.
const std::vector<double> spherical_state{0.7, 0.3, 0.4, 1.1}, spherical_p{1.3, 0.8, 9.81};
std::vector<double> spherical_conserved()
{
    const double th = spherical_state[0], thd = spherical_state[2], phd = spherical_state[3];
    const double m = spherical_p[0], l = spherical_p[1], g = spherical_p[2], s = std::sin(th);
    return {0.5 * m * l * l * (thd * thd + s * s * phd * phd) - m * g * l * std::cos(th), m * l * l * s * s * phd};
}

void check_conserved(const std::vector<double>& printed)
{
    const std::vector<double> expected = spherical_conserved();
    REQUIRE(printed.size() >= expected.size());
    for (std::size_t k = 0; k < expected.size(); ++k)
        CHECK(std::abs(printed[k] - expected[k]) < 1e-13 * std::max(1.0, std::abs(expected[k])));
}

} // namespace

TEST_CASE("export: the C conserved quantities are the energy and the cyclic momentum", "[export][cc]")
{
    const std::string folder = folder_for("c-conserved");
    REQUIRE(run_cli("export " + examples + "spherical_pendulum.lag --to c -o " + folder).exit_code == 0);
    std::ofstream(folder + "/conserved.c") << R"(#include "spherical_pendulum.h"
#include <stdio.h>
#include <string.h>
int main(void)
{
    const double x[4] = {)" + numbers(spherical_state, ", ") + R"(}, p[3] = {)" + numbers(spherical_p, ", ") + R"(};
    double c[spherical_pendulum_NCONSERVED];
    if (spherical_pendulum_NCONSERVED != 2 || strcmp(spherical_pendulum_conserved_names[0], "energy") != 0 ||
        strcmp(spherical_pendulum_conserved_names[1], "p_phi") != 0)
        return 1;
    spherical_pendulum_conserved(0.0, x, NULL, p, c);
    printf("%.17g %.17g\n", c[0], c[1]);
    return 0;
}
)";
    const std::string cc = configured_compiler();
    check_conserved(read_numbers(run_shell("cd " + folder + " && " + cc +
                                           " -std=c99 -Wall -Wextra -pedantic -Werror -O2 -o conserved conserved.c "
                                           "spherical_pendulum.c -lm 2>&1 && ./conserved")));
}

TEST_CASE("export: the Python conserved quantities hold along a solve_ivp run", "[export][scipy]")
{
    const std::string folder = folder_for("py-conserved");
    REQUIRE(run_cli("export " + examples + "spherical_pendulum.lag --to python -o " + folder).exit_code == 0);
    std::ofstream(folder + "/check.py")
        << "import sys\nsys.path.insert(0, " << nlohmann::json(folder).dump() << ")\n"
        << "import numpy as np\nfrom scipy.integrate import solve_ivp\nimport spherical_pendulum as m\n"
        << "assert m.CONSERVED == ['energy', 'p_phi'], m.CONSERVED\n"
        << "p = np.array([" << numbers(spherical_p, ", ") << "])\nx0 = np.array([" << numbers(spherical_state, ", ")
        << "])\nrun = solve_ivp(lambda t, x: m.rhs(t, x, p), (0, 5), x0, method='DOP853', rtol=1e-13, atol=1e-13)\n"
        << "c = m.conserved(0.0, run.y.T, p)\ndrift = np.max(np.abs(c - c[0]), axis=0) / np.maximum(1, np.abs(c[0]))\n"
        << "print(repr(c[0][0]), repr(c[0][1]), repr(float(np.max(drift))))\n";
    const std::vector<double> printed = read_numbers(run_shell("/usr/bin/python3 " + folder + "/check.py"));
    check_conserved(printed);
    REQUIRE(printed.size() == 3);
    CHECK(printed[2] < 1e-10); // constant along the motion, to the integration's error
}

TEST_CASE("export: the Octave conserved quantities are the energy and the cyclic momentum", "[export][octave]")
{
    const std::string folder = folder_for("octave-conserved");
    REQUIRE(run_cli("export " + examples + "spherical_pendulum.lag --to octave -o " + folder).exit_code == 0);
    std::ofstream(folder + "/check.m") << "c = spherical_pendulum_conserved(0, [" << numbers(spherical_state, "; ")
                                       << "], [" << numbers(spherical_p, "; ") << "]);\nprintf('%.17g ', c);\n";
    check_conserved(read_numbers(run_shell("cd " + folder + " && octave-cli --no-gui --quiet check.m 2>&1")));
}

TEST_CASE("export: a driven or damped scene exports no conserved quantities", "[export]")
{
    const std::string folder = folder_for("py-not-conserved");
    REQUIRE(run_cli("export " + examples + "damped_driven_oscillator.lag --to python -o " + folder).exit_code == 0);
    const std::string module = read_file(folder + "/damped_driven_oscillator.py");
    CHECK(module.find("CONSERVED") == std::string::npos);
    CHECK(module.find("def conserved") == std::string::npos);
}

TEST_CASE("export: the C sines and cosines are within 2 ulp of long double libm", "[export][cc]")
{
    // The exported file's own lagrange_sincos (it is static: the check includes the .c file),
    // against sinl and cosl rounded to double, on arguments where reductions go wrong: next to
    // multiples of pi/2, tiny, large, beyond the inlined range, and not finite; and its
    // lagrange_sincos2, two arguments at a time, against it bit for bit.
    const std::string folder = folder_for("c-sincos");
    REQUIRE(run_cli("export " + examples + "double_pendulum.lag --to c -o " + folder).exit_code == 0);
    std::ofstream(folder + "/sincos.c") << R"(#include "double_pendulum.c"
#include <stdio.h>
#include <string.h>
static double ulps(double got, long double exact)
{
    const double e = (double)exact;
    if (got == e)
        return 0.0;
    return fabs(got - e) / (nextafter(fabs(e), INFINITY) - fabs(e));
}
int main(void)
{
    double worst = 0.0, s, c, previous = 0.5, s2[2], c2[2];
    unsigned long long seed = 12345;
    long i, differ = 0;
    for (i = 0; i < 4000000; ++i) {
        double x, u, s1, c1;
        seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
        u = (double)(seed >> 11) / 9007199254740992.0 - 0.5;
        switch (i % 5) {
        case 0: x = 20.0 * u; break;
        case 1: x = 1.6e6 * u; break;
        case 2: x = nextafter((double)(long)(u * 4e5) * 1.5707963267948966, i % 2 ? INFINITY : -INFINITY); break;
        case 3: x = 1e-6 * u; break;
        default: x = 1e12 * u; break;
        }
        lagrange_sincos(x, &s, &c);
        if (ulps(s, sinl((long double)x)) > worst) worst = ulps(s, sinl((long double)x));
        if (ulps(c, cosl((long double)x)) > worst) worst = ulps(c, cosl((long double)x));
        /* two at a time: the same bits as one at a time */
        if (i % 7 == 0) x = i % 2 ? -0.0 : (i % 3 ? NAN : INFINITY);
        lagrange_sincos(x, &s, &c);
        lagrange_sincos(previous, &s1, &c1);
        lagrange_sincos2(x, previous, &s2[0], &c2[0], &s2[1], &c2[1]);
        differ += memcmp(&s, &s2[0], sizeof s) != 0 || memcmp(&c, &c2[0], sizeof c) != 0 ||
                  memcmp(&s1, &s2[1], sizeof s) != 0 || memcmp(&c1, &c2[1], sizeof c) != 0;
        previous = x;
    }
    printf("%.3f", worst);
    lagrange_sincos(-0.0, &s, &c);
    printf(" %d %d", signbit(s) != 0 && s == 0.0, c == 1.0);
    lagrange_sincos(NAN, &s, &c);
    printf(" %d", isnan(s) && isnan(c));
    lagrange_sincos(INFINITY, &s, &c);
    printf(" %d", isnan(s) && isnan(c));
    printf(" %ld\n", differ);
    return 0;
}
)";
    const std::string cc = configured_compiler();
    const std::vector<double> r = read_numbers(run_shell("cd " + folder + " && " + cc +
                                                          " -std=c99 -O2 -o sincos sincos.c -lm 2>&1 && ./sincos"));
    REQUIRE(r.size() == 6);
    CHECK(r[0] <= 2.0);
    CHECK(r[1] == 1.0); // sin(-0) = -0
    CHECK(r[2] == 1.0); // cos(-0) = 1
    CHECK(r[3] == 1.0); // NaN in, NaN out
    CHECK(r[4] == 1.0); // and for an infinity
    CHECK(r[5] == 0.0); // lagrange_sincos2 gives the bits of two lagrange_sincos calls

}

TEST_CASE("export: every example and test scene that exports compiles warning-free as C", "[export][cc]")
{
    // Beyond the five equivalence cases: every scene the engine exports (the rest exit 1 with
    // their reason), held to -Werror, so that no form of its programs writes invalid C. At -O0:
    // the front end's errors and warnings are the point here, and the equivalence cases
    // compile at -O2.
    std::vector<std::string> scenes = example_scenes();
    for (const auto& entry : std::filesystem::directory_iterator(std::string(LAGRANGE_SOURCE_DIR) + "/tests/scenes"))
        if (entry.path().extension() == ".lag")
            scenes.push_back(entry.path().string());
    std::sort(scenes.begin(), scenes.end());
    const std::string cc = configured_compiler();
    int exported = 0;
    for (const std::string& scene : scenes) {
        INFO(scene);
        const std::string folder = folder_for("c-all-" + std::to_string(exported) + "-" +
                                              scene.substr(scene.rfind('/') + 1, scene.size() - scene.rfind('/') - 5));
        const cli_result r = run_cli("export " + scene + " --to c -o " + folder + " --name scene", "", 120);
        REQUIRE((r.exit_code == 0 || r.exit_code == 1));
        if (r.exit_code == 1)
            continue;
        ++exported;
        CHECK(run_shell("cd " + folder + " && " + cc +
                        " -std=c99 -Wall -Wextra -pedantic -Werror -O0 -c scene.c 2>&1 && echo compiled") ==
              "compiled\n");
    }
    CHECK(exported >= 50);
}
