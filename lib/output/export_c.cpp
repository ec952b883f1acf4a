// SPDX-License-Identifier: GPL-2.0-or-later
/** @file export_c.cpp
 *  The C target of `lagrange export`: NAME.h and NAME.c (C99, nothing beyond <math.h>). The small
 *  LDLᵀ solve and the sines and cosines are written out here because the target promises no other
 *  dependency. */
#include "output/export_program.h"

#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace lagrange::export_detail {

namespace {

/// Sines and cosines written out, because the target holds to <math.h> and libm's calls were
/// most of a right-hand side's time: one call gives an argument's sine and cosine (see
/// write_program), and inlined, several arguments overlap. fdlibm's reduction by π/2 in four
/// parts (each product exact for |x| ≤ 8e5) and its kernel polynomials on [−π/4, π/4], in
/// Estrin's order: within 2 ulp there; libm's sin and cos beyond, and for NaN and infinities.
constexpr const char* sincos_source = R"(/* sin(x) and cos(x) together, within 2 ulp for |x| <= 8e5 (fdlibm's reduction and
   kernels); libm's beyond. */
static inline void lagrange_sincos(double x, double *s, double *c)
{
    union { double d; uint64_t u; } shifted, ps, pc, so, co;
    double q, r, z, z2, z4, ss, cs;
    uint64_t swap;
    shifted.d = x * 6.36619772367581382433e-01 + 0x1.8p52; /* its low bits: round(2x/pi) */
    q = shifted.d - 0x1.8p52;
    r = (((x - q * 1.57079632673412561417e+00) - q * 6.07710050630396597660e-11) - q * 2.02226624871116645580e-21)
        - q * 8.47842766036889956997e-32;
    z = r * r;
    z2 = z * z;
    z4 = z2 * z2;
    ss = (-1.66666666666666324348e-01 + z * 8.33333333332248946124e-03)
         + z2 * (-1.98412698298579493134e-04 + z * 2.75573137070700676789e-06)
         + z4 * (-2.50507602534068634195e-08 + z * 1.58969099521155010221e-10);
    cs = (4.16666666666666019037e-02 + z * -1.38888888888741095749e-03)
         + z2 * (2.48015872894767294178e-05 + z * -2.75573143513906633035e-07)
         + z4 * (2.08757232129817482790e-09 + z * -1.13596475577881948265e-11);
    ps.d = r + (r * z) * ss;
    pc.d = (1.0 - 0.5 * z) + z2 * cs;
    swap = (uint64_t)0 - (shifted.u & 1); /* odd quadrants swap sine and cosine */
    so.u = ((ps.u & ~swap) | (pc.u & swap)) ^ ((shifted.u & 2) << 62);
    co.u = ((pc.u & ~swap) | (ps.u & swap)) ^ (((shifted.u + 1) & 2) << 62);
    *s = x == 0.0 ? x : so.d; /* sin(-0) = -0 */
    *c = co.d;
    if (!(fabs(x) <= 8.0e5)) {
        *s = sin(x);
        *c = cos(x);
    }
}

)";

/// Two arguments' sines and cosines: lagrange_sincos's operations in the same order (so the
/// same values), written lane by lane as straight-line code, which compilers at -O2 (GCC's and
/// Clang's SLP vectorizers) take two lanes at a time; the exceptions (0, beyond 8e5) after.
constexpr const char* sincos2_source = R"(/* The sines and cosines of x0 and x1: the values of two lagrange_sincos calls, written
   lane by lane so that a compiler can evaluate both lanes at once. */
static inline void lagrange_sincos2(double x0, double x1, double *s0, double *c0, double *s1, double *c1)
{
    union { double d; uint64_t u; } shifted[2], ps[2], pc[2], so[2], co[2];
    const double x[2] = {x0, x1};
    double q[2], r[2], z[2], z2[2], z4[2], ss[2], cs[2], s[2], c[2];
    uint64_t swap[2];
    int i;
    shifted[0].d = x[0] * 6.36619772367581382433e-01 + 0x1.8p52;
    shifted[1].d = x[1] * 6.36619772367581382433e-01 + 0x1.8p52;
    q[0] = shifted[0].d - 0x1.8p52;
    q[1] = shifted[1].d - 0x1.8p52;
    r[0] = (((x[0] - q[0] * 1.57079632673412561417e+00) - q[0] * 6.07710050630396597660e-11)
            - q[0] * 2.02226624871116645580e-21) - q[0] * 8.47842766036889956997e-32;
    r[1] = (((x[1] - q[1] * 1.57079632673412561417e+00) - q[1] * 6.07710050630396597660e-11)
            - q[1] * 2.02226624871116645580e-21) - q[1] * 8.47842766036889956997e-32;
    z[0] = r[0] * r[0];
    z[1] = r[1] * r[1];
    z2[0] = z[0] * z[0];
    z2[1] = z[1] * z[1];
    z4[0] = z2[0] * z2[0];
    z4[1] = z2[1] * z2[1];
    ss[0] = (-1.66666666666666324348e-01 + z[0] * 8.33333333332248946124e-03)
            + z2[0] * (-1.98412698298579493134e-04 + z[0] * 2.75573137070700676789e-06)
            + z4[0] * (-2.50507602534068634195e-08 + z[0] * 1.58969099521155010221e-10);
    ss[1] = (-1.66666666666666324348e-01 + z[1] * 8.33333333332248946124e-03)
            + z2[1] * (-1.98412698298579493134e-04 + z[1] * 2.75573137070700676789e-06)
            + z4[1] * (-2.50507602534068634195e-08 + z[1] * 1.58969099521155010221e-10);
    cs[0] = (4.16666666666666019037e-02 + z[0] * -1.38888888888741095749e-03)
            + z2[0] * (2.48015872894767294178e-05 + z[0] * -2.75573143513906633035e-07)
            + z4[0] * (2.08757232129817482790e-09 + z[0] * -1.13596475577881948265e-11);
    cs[1] = (4.16666666666666019037e-02 + z[1] * -1.38888888888741095749e-03)
            + z2[1] * (2.48015872894767294178e-05 + z[1] * -2.75573143513906633035e-07)
            + z4[1] * (2.08757232129817482790e-09 + z[1] * -1.13596475577881948265e-11);
    ps[0].d = r[0] + (r[0] * z[0]) * ss[0];
    ps[1].d = r[1] + (r[1] * z[1]) * ss[1];
    pc[0].d = (1.0 - 0.5 * z[0]) + z2[0] * cs[0];
    pc[1].d = (1.0 - 0.5 * z[1]) + z2[1] * cs[1];
    swap[0] = (uint64_t)0 - (shifted[0].u & 1);
    swap[1] = (uint64_t)0 - (shifted[1].u & 1);
    so[0].u = ((ps[0].u & ~swap[0]) | (pc[0].u & swap[0])) ^ ((shifted[0].u & 2) << 62);
    so[1].u = ((ps[1].u & ~swap[1]) | (pc[1].u & swap[1])) ^ ((shifted[1].u & 2) << 62);
    co[0].u = ((pc[0].u & ~swap[0]) | (ps[0].u & swap[0])) ^ (((shifted[0].u + 1) & 2) << 62);
    co[1].u = ((pc[1].u & ~swap[1]) | (ps[1].u & swap[1])) ^ (((shifted[1].u + 1) & 2) << 62);
    s[0] = so[0].d;
    s[1] = so[1].d;
    c[0] = co[0].d;
    c[1] = co[1].d;
    for (i = 0; i < 2; ++i) {
        if (x[i] == 0.0) /* sin(-0) = -0 */
            s[i] = x[i];
        if (!(fabs(x[i]) <= 8.0e5)) {
            s[i] = sin(x[i]);
            c[i] = cos(x[i]);
        }
    }
    *s0 = s[0];
    *c0 = c[0];
    *s1 = s[1];
    *c1 = c[1];
}

)";

/// The body of a C function that evaluates `program` into out[]: the symbols' aliases, the
/// program, the stores; arguments it does not read are cast to void.
std::string c_body(const expression_program& program, const naming& names, const exported_system& system,
                   const std::string& out)
{
    std::ostringstream lines;
    std::set<int> used;
    std::vector<std::string> outputs = write_program(program, dialect::c, names, "    ", lines, used);
    std::ostringstream body;
    std::set<char> read;
    for (int k : used) {
        const argument_place at = place_of(k, system);
        read.insert(at.array);
        if (at.array != 't')
            body << "    const double " << names.symbols[static_cast<std::size_t>(k)] << " = " << at.array << "["
                 << at.index << "];\n";
    }
    for (char array : {'t', 'x', 'p', 'u'})
        if (!read.count(array))
            body << "    (void)" << array << ";\n";
    body << lines.str();
    for (std::size_t k = 0; k < outputs.size(); ++k)
        body << "    " << out << "[" << k << "] = " << outputs[k] << ";\n";
    return body.str();
}

std::string nx_of(const std::string& name) { return name + "_NX"; }

/// The declarations of a constrained scene's functions (nothing without constraints).
std::string constrained_declarations(const exported_system& system, const std::string& name, const std::string& args)
{
    if (!system.constraint_parts)
        return "";
    std::ostringstream h;
    h << "#define " << name << "_NC " << system.constraint_names.size() << " /* constraints */\n"
      << "extern const char *const " << name << "_constraint_names[" << name << "_NC];\n\n"
      << "/* dxdt = f(t, x, u, p), with q'' and the multipliers lambda from\n"
      << "   [M -A^T; A 0] [q''; lambda] = [F; -c] (M q'' = F + A^T lambda, A q'' = -c): the constraints\n"
      << "   differentiated to the accelerations, so an integration keeps them up to its error;\n"
      << "   " << name << "_constraints measures the drift. Returns 0, or 1 where the matrix is singular. */\n"
      << "int " << name << "_rhs" << args << ", double *dxdt);\n"
      << "/* The multipliers lambda (NC) at (t, x). Returns as " << name << "_rhs. */\n"
      << "int " << name << "_multipliers" << args << ", double *lambda);\n"
      << "/* The constraints' residuals g (NC), 0 on the motion: f(q, t) of a holonomic constraint,\n"
      << "   A(q) q' + b of a velocity one; and A (NC x NQ), the Jacobian of their velocity form. */\n"
      << "void " << name << "_constraints" << args << ", double *g);\n"
      << "void " << name << "_constraint_jacobian" << args << ", double *A);\n";
    return h.str();
}

/// A constrained scene's functions: its constraints, and the right-hand side and multipliers
/// from the augmented system, solved by Gaussian elimination with partial pivoting (the
/// matrix is symmetric but indefinite, so the mass matrix's LDLᵀ does not apply).
std::string constrained_functions(const exported_system& system, const naming& names, const std::string& name,
                                  const std::string& args)
{
    const std::size_t n = system.coordinates, m = system.constraint_names.size(), size = n + m;
    const std::string nq = std::to_string(n), nc = std::to_string(m), s = std::to_string(size);
    const std::string parts = nc + " * " + nq + " + 2 * " + nc;
    std::ostringstream c;
    c << "const char *const " << name << "_constraint_names[" << name << "_NC] = {";
    for (std::size_t k = 0; k < m; ++k)
        c << (k ? ", " : "") << '"' << system.constraint_names[k] << '"';
    c << "};\n\n"
      << "static void lagrange_constraint_parts" << args << ", double *out)\n{\n"
      << c_body(*system.constraint_parts, names, system, "out") << "}\n\n"
      << "void " << name << "_constraints" << args << ", double *g)\n{\n    double out[" << parts << "];\n    int i;\n"
      << "    lagrange_constraint_parts(t, x, u, p, out);\n    for (i = 0; i < " << nc << "; ++i)\n"
      << "        g[i] = out[" << nc << " * " << nq << " + " << nc << " + i];\n}\n\n"
      << "void " << name << "_constraint_jacobian" << args << ", double *A)\n{\n    double out[" << parts
      << "];\n    int i;\n    lagrange_constraint_parts(t, x, u, p, out);\n"
      << "    for (i = 0; i < " << nc << " * " << nq << "; ++i)\n        A[i] = out[i];\n}\n\n"
      << "/* Solves a y = b in place (a: " << s << " x " << s << ", row-major) by Gaussian elimination with partial\n"
      << "   pivoting: 1 if a is singular. */\n"
      << "static int lagrange_lu_solve(double *a, double *b)\n{\n    int i, j, k;\n"
      << "    for (k = 0; k < " << s << "; ++k) {\n        int best = k;\n"
      << "        for (i = k + 1; i < " << s << "; ++i)\n"
      << "            if (fabs(a[i * " << s << " + k]) > fabs(a[best * " << s << " + k]))\n                best = i;\n"
      << "        if (!(fabs(a[best * " << s << " + k]) > 0.0))\n            return 1;\n"
      << "        if (best != k) {\n            double swap;\n            for (j = 0; j < " << s << "; ++j) {\n"
      << "                swap = a[k * " << s << " + j];\n                a[k * " << s << " + j] = a[best * " << s
      << " + j];\n                a[best * " << s << " + j] = swap;\n            }\n"
      << "            swap = b[k];\n            b[k] = b[best];\n            b[best] = swap;\n        }\n"
      << "        for (i = k + 1; i < " << s << "; ++i) {\n"
      << "            const double f = a[i * " << s << " + k] / a[k * " << s << " + k];\n"
      << "            for (j = k; j < " << s << "; ++j)\n                a[i * " << s << " + j] -= f * a[k * " << s
      << " + j];\n            b[i] -= f * b[k];\n        }\n    }\n"
      << "    for (i = " << s << " - 1; i >= 0; --i) {\n        for (j = i + 1; j < " << s << "; ++j)\n"
      << "            b[i] -= a[i * " << s << " + j] * b[j];\n        b[i] /= a[i * " << s << " + i];\n    }\n"
      << "    return 0;\n}\n\n"
      << "/* q'' then lambda, from [M -A^T; A 0] [q''; lambda] = [F; -c]. */\n"
      << "/* a = [M -A^T; A 0] and y = [F; -c]. */\n"
      << "static void lagrange_augmented_system" << args << ", double *a, double *y)\n{\n"
      << "    double m[" << nq << " * " << nq << " + " << nq << "], k[" << parts << "];\n    int i, j;\n"
      << "    lagrange_mass_and_forcing(t, x, u, p, m);\n    lagrange_constraint_parts(t, x, u, p, k);\n"
      << "    for (i = 0; i < " << s << " * " << s << "; ++i)\n        a[i] = 0.0;\n"
      << "    for (i = 0; i < " << nq << "; ++i) {\n        for (j = 0; j < " << nq << "; ++j)\n"
      << "            a[i * " << s << " + j] = m[i * " << nq << " + j];\n        y[i] = m[" << nq << " * " << nq
      << " + i];\n    }\n"
      << "    for (i = 0; i < " << nc << "; ++i) {\n        for (j = 0; j < " << nq << "; ++j) {\n"
      << "            a[(" << nq << " + i) * " << s << " + j] = k[i * " << nq << " + j];\n"
      << "            a[j * " << s << " + " << nq << " + i] = -k[i * " << nq << " + j];\n        }\n"
      << "        y[" << nq << " + i] = -k[" << nc << " * " << nq << " + i];\n    }\n}\n\n"
      << "static int lagrange_augmented" << args << ", double *y)\n{\n    double a[" << s << " * " << s << "];\n"
      << "    lagrange_augmented_system(t, x, u, p, a, y);\n    return lagrange_lu_solve(a, y);\n}\n\n"
      << "int " << name << "_rhs" << args << ", double *dxdt)\n{\n    double y[" << s << "];\n    int i;\n"
      << "    if (lagrange_augmented(t, x, u, p, y))\n        return 1;\n"
      << "    for (i = 0; i < " << nq << "; ++i) {\n        dxdt[i] = x[" << nq << " + i];\n"
      << "        dxdt[" << nq << " + i] = y[i];\n    }\n    return 0;\n}\n\n"
      << "int " << name << "_multipliers" << args << ", double *lambda)\n{\n    double y[" << s << "];\n    int i;\n"
      << "    if (lagrange_augmented(t, x, u, p, y))\n        return 1;\n"
      << "    for (i = 0; i < " << nc << "; ++i)\n        lambda[i] = y[" << nq << " + i];\n    return 0;\n}\n\n";
    // d[q'', lambda]/ds = K^-1 (d[F; -c]/ds - (dK/ds) [q''; lambda]), K = [M -A^T; A 0]; M and
    // A depend on q alone, so dK/ds is there only for s a coordinate.
    const std::size_t inputs = system.input_names.size();
    const std::string nu = std::to_string(inputs);
    const std::string cube = nq + " * " + nq + " * " + nq, square = nq + " * " + nq;
    const std::string abase = nc + " * " + nq + " * " + nq;
    c << "static void lagrange_constraint_derivatives" << args << ", double *out)\n{\n"
      << c_body(*system.constraint_derivatives, names, system, "out") << "}\n\n"
      << "int " << name << "_jacobian" << args << ", double *dfdx, double *dfdu)\n{\n"
      << "    double y[" << s << "], k0[" << s << " * " << s << "], k[" << s << " * " << s << "], col[" << s << "];\n"
      << "    double d[" << cube << " + 2 * " << square << " + " << nq << " * " << nu << " + 1];\n"
      << "    double e[" << abase << " + 2 * " << nc << " * " << nq << " + " << nc << " * " << nu << " + 1];\n"
      << "    int i, j, r, v;\n"
      << "    lagrange_augmented_system(t, x, u, p, k0, y);\n"
      << "    for (i = 0; i < " << s << " * " << s << "; ++i)\n        k[i] = k0[i];\n"
      << "    if (lagrange_lu_solve(k, y))\n        return 1;\n"
      << "    lagrange_derivatives(t, x, u, p, d);\n    lagrange_constraint_derivatives(t, x, u, p, e);\n"
      << "    for (i = 0; i < " << nx_of(name) << " * " << nx_of(name) << "; ++i)\n        dfdx[i] = 0.0;\n"
      << "    for (i = 0; i < " << nq << "; ++i)\n        dfdx[i * " << nx_of(name) << " + " << nq << " + i] = 1.0;\n"
      << "    for (v = 0; v < 2 * " << nq << " + " << nu << "; ++v) {\n"
      << "        if (v >= 2 * " << nq << " && !dfdu)\n            break;\n"
      << "        for (i = 0; i < " << nq << "; ++i)\n"
      << "            col[i] = v < 2 * " << nq << " ? d[" << cube << " + (v < " << nq << " ? 0 : " << square
      << ") + i * " << nq << " + v % " << nq << "]\n"
      << "                                : d[" << cube << " + 2 * " << square << " + i * " << nu << " + v - 2 * " << nq
      << "];\n"
      << "        for (r = 0; r < " << nc << "; ++r)\n"
      << "            col[" << nq << " + r] = v < 2 * " << nq << " ? -e[" << abase << " + (v < " << nq << " ? 0 : "
      << nc << " * " << nq << ") + r * " << nq << " + v % " << nq << "]\n"
      << "                                     : -e[" << abase << " + 2 * " << nc << " * " << nq << " + r * " << nu
      << " + v - 2 * " << nq << "];\n"
      << "        if (v < " << nq << ") {\n"
      << "            for (i = 0; i < " << nq << "; ++i)\n                for (j = 0; j < " << nq << "; ++j)\n"
      << "                    col[i] -= d[(v * " << nq << " + i) * " << nq << " + j] * y[j];\n"
      << "            for (r = 0; r < " << nc << "; ++r)\n                for (j = 0; j < " << nq << "; ++j) {\n"
      << "                    col[j] += e[(v * " << nc << " + r) * " << nq << " + j] * y[" << nq << " + r];\n"
      << "                    col[" << nq << " + r] -= e[(v * " << nc << " + r) * " << nq << " + j] * y[j];\n"
      << "                }\n        }\n"
      << "        for (i = 0; i < " << s << " * " << s << "; ++i)\n            k[i] = k0[i];\n"
      << "        if (lagrange_lu_solve(k, col))\n            return 1;\n"
      << "        for (i = 0; i < " << nq << "; ++i) {\n"
      << "            if (v < 2 * " << nq << ")\n"
      << "                dfdx[(" << nq << " + i) * " << nx_of(name) << " + v] = col[i];\n"
      << "            else\n                dfdu[(" << nq << " + i) * " << nu << " + v - 2 * " << nq << "] = col[i];\n"
      << "        }\n    }\n";
    if (inputs > 0)
        c << "    if (dfdu)\n        for (i = 0; i < " << nq << " * " << nu << "; ++i)\n            dfdu[i] = 0.0;\n";
    else
        c << "    (void)dfdu;\n";
    c << "    return 0;\n}\n";
    return c.str();
}

} // namespace

std::vector<exported_file> export_c(const model& scene, const exported_system& system, const std::string& name,
                                    const std::string& version)
{
    const naming names = name_symbols(system, dialect::c);
    const std::size_t n = system.coordinates, inputs = system.input_names.size();
    const std::string args = "(double t, const double *x, const double *u, const double *p";
    const bool constrained = system.constraint_parts.has_value();
    std::ostringstream h;
    h << "/* " << name << ".h: the equations of motion as C99 functions.\n"
      << provenance(scene, system, names, version, " * ")
      << " * Every function is re-entrant and allocates nothing; u may be NULL when " << name << "_NU is 0.\n"
      << " * Arrays are row-major. Build: cc -std=c99 -c " << name << ".c (link with -lm). */\n"
      << "#ifndef " << name << "_H_INCLUDED\n#define " << name << "_H_INCLUDED\n\n"
      << "#define " << name << "_NQ " << n << " /* coordinates */\n"
      << "#define " << name << "_NX " << 2 * n << " /* states: the coordinates, then their velocities */\n"
      << "#define " << name << "_NU " << inputs << " /* inputs */\n"
      << "#define " << name << "_NP " << system.parameter_names.size() << " /* parameters */\n\n"
      << "/* The scene's `values` (the first line), NaN where it gives none. */\n"
      << "extern const double " << name << "_default_p[" << name << "_NP > 0 ? " << name << "_NP : 1];\n"
      << "extern const char *const " << name << "_state_names[" << name << "_NX];\n"
      << "extern const char *const " << name << "_parameter_names[" << name << "_NP > 0 ? " << name << "_NP : 1];\n\n"
      << constrained_declarations(system, name, args)
      << (constrained ? ""
          : system.recursion
              ? "/* dxdt = f(t, x, u, p), q'' by the articulated-body recursion. Returns 0, or 1 where a q'' is\n"
                "   not finite: where the mass matrix is singular (a zero pivot of the recursion). */\n"
              : "/* dxdt = f(t, x, u, p). Returns 0, or 1 where the mass matrix is not positive definite. */\n")
      << (constrained ? "" : "int " + name + "_rhs" + args + ", double *dxdt);\n")
      << "/* dfdx = df/dx (NX x NX) and dfdu = df/du (NX x NU; may be NULL). Returns 0, or 1 where "
      << (constrained ? "[M -A^T; A 0] is singular" : "the mass matrix is not positive definite") << ". */\n"
      << "int " << name << "_jacobian" << args << ", double *dfdx, double *dfdu);\n"
      << "/* The mass matrix M (NQ x NQ) and the forcing F (NQ) of M q'' = F" << (constrained ? " + A^T lambda" : "")
      << ". */\n"
      << "void " << name << "_mass_matrix" << args << ", double *M);\n"
      << "void " << name << "_forcing" << args << ", double *F);\n"
      << "/* The energy function h = sum q' dL/dq' - L (conserved when nothing drives or damps the motion). */\n"
      << "double " << name << "_energy" << args << ");\n";
    if (system.conserved) {
        h << "/* What the motion conserves (NCONSERVED values, named in " << name << "_conserved_names): the\n"
          << "   energy function where L does not depend on t, then the momentum of each cyclic coordinate. */\n"
          << "#define " << name << "_NCONSERVED " << system.conserved_names.size() << "\n"
          << "extern const char *const " << name << "_conserved_names[" << name << "_NCONSERVED];\n"
          << "void " << name << "_conserved" << args << ", double *conserved);\n";
    }
    if (system.linear)
        h << "/* At the equilibrium the small oscillations are about, functions of p only: the state there\n"
          << "   (NX), and T and V (NQ x NQ each) of T q'' + V q = 0. The linearized x' = A x + B u there\n"
          << "   has A = df/dx and B = df/du of " << name << "_jacobian at that state with u = 0. */\n"
          << "void " << name << "_equilibrium(const double *p, double *x);\n"
          << "void " << name << "_linear(const double *p, double *T, double *V);\n";
    h << "\n#endif\n";

    std::ostringstream c;
    const std::string nq = name + "_NQ";
    c << "/* " << name << ".c: see " << name << ".h.\n" << provenance(scene, system, names, version, " * ") << " */\n"
      << "#include \"" << name << ".h\"\n\n#include <math.h>\n#include <stddef.h>\n#include <stdint.h>\n\n"
      << "const double " << name << "_default_p[" << name << "_NP > 0 ? " << name << "_NP : 1] = {"
      << (system.defaults.empty() ? "0.0" : number_list(system.defaults, "NAN")) << "};\n"
      << "const char *const " << name << "_state_names[" << name << "_NX] = {";
    for (std::size_t k = 0; k < system.state_names.size(); ++k)
        c << (k ? ", " : "") << '"' << system.state_names[k] << '"';
    c << "};\nconst char *const " << name << "_parameter_names[" << name << "_NP > 0 ? " << name << "_NP : 1] = {";
    for (std::size_t k = 0; k < system.parameter_names.size(); ++k)
        c << (k ? ", " : "") << '"' << system.parameter_names[k] << '"';
    c << (system.parameter_names.empty() ? "\"\"" : "") << "};\n";
    if (system.conserved) {
        c << "const char *const " << name << "_conserved_names[" << name << "_NCONSERVED] = {";
        for (std::size_t k = 0; k < system.conserved_names.size(); ++k)
            c << (k ? ", " : "") << '"' << system.conserved_names[k] << '"';
        c << "};\n";
    }
    c << "\n";
    // Helpers only where used: an unused static function is a warning.
    std::vector<const expression_program*> programs = {&system.mass, &system.forcing, &system.mass_and_forcing,
                                                       &system.derivatives, &system.energy};
    for (const std::optional<expression_program>* program :
         {&system.recursion, &system.linear, &system.constraint_parts, &system.constraint_derivatives,
          &system.conserved})
        if (*program)
            programs.push_back(&**program);
    auto uses = [&](instruction::code op) {
        bool found = false;
        for (const expression_program* program : programs)
            for (const instruction& i : program->code())
                found = found || i.op == op;
        return found;
    };
    const bool powers = uses(instruction::code::integer_power);
    bool pairs = false;
    for (const expression_program* program : programs)
        pairs = pairs || takes_sincos_pairs(*program);
    if (uses(instruction::code::sine) || uses(instruction::code::cosine))
        c << sincos_source;
    if (pairs)
        c << sincos2_source;
    if (powers)
        c << "static double lagrange_ipow(double a, int n)\n{\n    double r = 1.0;\n    int k = n < 0 ? -n : n;\n"
          << "    for (; k > 0; --k)\n        r *= a;\n    return n < 0 ? 1.0 / r : r;\n}\n\n";
    // LDLᵀ without square roots, as the engine's own solve (numeric/mass_matrix.h), with row j
    // of L D kept once instead of multiplied again for every row below it.
    if (!constrained)
        c << "/* The LDL^T factor of a (row-major, in place: L below the diagonal, D on it): 1 if a is not\n"
      << "   positive definite. */\n"
      << "static int lagrange_factor(double *a)\n{\n    double w[" << nq << "]; /* row j of L times D */\n"
      << "    int i, j, k;\n    for (j = 0; j < " << nq << "; ++j) {\n"
      << "        double d = a[j * " << nq << " + j];\n        for (k = 0; k < j; ++k) {\n"
      << "            w[k] = a[j * " << nq << " + k] * a[k * " << nq << " + k];\n"
      << "            d -= a[j * " << nq << " + k] * w[k];\n        }\n"
      << "        if (!(d > 0.0))\n            return 1;\n        a[j * " << nq << " + j] = d;\n"
      << "        for (i = j + 1; i < " << nq << "; ++i) {\n            double s = a[i * " << nq << " + j];\n"
      << "            for (k = 0; k < j; ++k)\n"
      << "                s -= a[i * " << nq << " + k] * w[k];\n"
      << "            a[i * " << nq << " + j] = s / d;\n        }\n    }\n    return 0;\n}\n\n"
      << "/* Solves L D L^T y = b in place, b of NQ entries. */\n"
      << "static void lagrange_solve(const double *l, double *b)\n{\n    int i, k;\n"
      << "    for (i = 0; i < " << nq << "; ++i)\n        for (k = 0; k < i; ++k)\n"
      << "            b[i] -= l[i * " << nq << " + k] * b[k];\n"
      << "    for (i = 0; i < " << nq << "; ++i)\n        b[i] /= l[i * " << nq << " + i];\n"
      << "    for (i = " << nq << " - 1; i >= 0; --i)\n        for (k = i + 1; k < " << nq << "; ++k)\n"
      << "            b[i] -= l[k * " << nq << " + i] * b[k];\n}\n\n";
    c << "void " << name << "_mass_matrix" << args << ", double *M)\n{\n"
      << c_body(system.mass, names, system, "M") << "}\n\n";
    c << "void " << name << "_forcing" << args << ", double *F)\n{\n"
      << c_body(system.forcing, names, system, "F") << "}\n\n";
    c << "static inline void lagrange_mass_and_forcing" << args << ", double *out)\n{\n"
      << c_body(system.mass_and_forcing, names, system, "out") << "}\n\n";
    c << "static void lagrange_derivatives" << args << ", double *out)\n{\n"
      << c_body(system.derivatives, names, system, "out") << "}\n\n";
    c << "double " << name << "_energy" << args << ")\n{\n    double h[1];\n"
      << c_body(system.energy, names, system, "h") << "    return h[0];\n}\n\n";
    if (system.conserved)
        c << "void " << name << "_conserved" << args << ", double *conserved)\n{\n"
          << c_body(*system.conserved, names, system, "conserved") << "}\n\n";
    const std::string nx = name + "_NX", nu = name + "_NU";
    if (constrained) {
        c << constrained_functions(system, names, name, args);
    } else {
        c << "int " << name << "_rhs" << args << ", double *dxdt)\n{\n";
        if (system.recursion) { // O(n), as the engine from recursive_coordinates on; the stores last: dxdt may be x
            c << "    double qdd[" << nq << "];\n    int i;\n" << c_body(*system.recursion, names, system, "qdd")
              << "    for (i = 0; i < " << nq << "; ++i)\n        if (!isfinite(qdd[i]))\n            return 1;\n"
              << "    for (i = 0; i < " << nq << "; ++i) {\n        dxdt[i] = x[" << nq << " + i];\n"
              << "        dxdt[" << nq << " + i] = qdd[i];\n    }\n    return 0;\n}\n\n";
        } else {
            c << "    double m[" << nq << " * " << nq << " + " << nq << "];\n    int i;\n"
              << "    lagrange_mass_and_forcing(t, x, u, p, m);\n";
            if (n == 2) // Cramer's rule, as the engine solves two coordinates
                c << "    {\n        const double det = m[0] * m[3] - m[1] * m[1];\n"
                  << "        if (!(m[0] > 0.0 && det > 0.0))\n            return 1;\n"
                  << "        dxdt[2] = (m[3] * m[4] - m[1] * m[5]) / det;\n"
                  << "        dxdt[3] = (m[0] * m[5] - m[1] * m[4]) / det;\n    }\n"
                  << "    dxdt[0] = x[2];\n    dxdt[1] = x[3];\n    (void)i;\n    return 0;\n}\n\n";
            else
                c << "    if (lagrange_factor(m))\n        return 1;\n"
                  << "    lagrange_solve(m, m + " << nq << " * " << nq << ");\n"
                  << "    for (i = 0; i < " << nq << "; ++i) {\n        dxdt[i] = x[" << nq << " + i];\n"
                  << "        dxdt[" << nq << " + i] = m[" << nq << " * " << nq << " + i];\n    }\n    return 0;\n}\n\n";
        }
        c << "int " << name << "_jacobian" << args << ", double *dfdx, double *dfdu)\n{\n"
          << "    /* d(q'')/dy = M^-1 (dF/dy - (dM/dy) q''), y each coordinate, velocity and input. */\n"
          << "    double m[" << nq << " * " << nq << " + " << nq << "], column[" << nq << "];\n"
          << "    double d[" << nq << " * " << nq << " * " << nq << " + 2 * " << nq << " * " << nq << " + " << nq << " * "
          << nu << " + 1];\n"
          << "    const double *qdd = m + " << nq << " * " << nq << ";\n    int i, j, k;\n"
          << "    lagrange_mass_and_forcing(t, x, u, p, m);\n    lagrange_derivatives(t, x, u, p, d);\n"
          << "    if (lagrange_factor(m))\n        return 1;\n    lagrange_solve(m, m + " << nq << " * " << nq << ");\n"
          << "    for (i = 0; i < " << nx << " * " << nx << "; ++i)\n        dfdx[i] = 0.0;\n"
          << "    for (i = 0; i < " << nq << "; ++i)\n        dfdx[i * " << nx << " + " << nq << " + i] = 1.0;\n"
          << "    for (k = 0; k < 2 * " << nq << "; ++k) {\n        for (i = 0; i < " << nq << "; ++i) {\n"
          << "            column[i] = d[" << nq << " * " << nq << " * " << nq << " + (k < " << nq << " ? 0 : " << nq
          << " * " << nq << ") + i * " << nq << " + k % " << nq << "];\n"
          << "            if (k < " << nq << ")\n                for (j = 0; j < " << nq << "; ++j)\n"
          << "                    column[i] -= d[(k * " << nq << " + i) * " << nq << " + j] * qdd[j];\n        }\n"
          << "        lagrange_solve(m, column);\n        for (i = 0; i < " << nq << "; ++i)\n"
          << "            dfdx[(" << nq << " + i) * " << nx << " + k] = column[i];\n    }\n";
        if (inputs == 0) {
            c << "    (void)dfdu;\n";
        } else {
            c << "    if (dfdu) {\n        for (k = 0; k < " << nu << "; ++k) {\n"
              << "            for (i = 0; i < " << nq << "; ++i) {\n"
              << "                column[i] = d[" << nq << " * " << nq << " * " << nq << " + 2 * " << nq << " * " << nq
              << " + i * " << nu << " + k];\n                dfdu[i * " << nu << " + k] = 0.0;\n            }\n"
              << "            lagrange_solve(m, column);\n            for (i = 0; i < " << nq << "; ++i)\n"
              << "                dfdu[(" << nq << " + i) * " << nu << " + k] = column[i];\n        }\n    }\n";
        }
        c << "    return 0;\n}\n";
    }
    if (system.linear) {
        const std::string parts = "2 * " + nq + " + 2 * " + nq + " * " + nq;
        c << "\nstatic void lagrange_linear" << args << ", double *out)\n{\n"
          << c_body(*system.linear, names, system, "out") << "}\n\n"
          << "void " << name << "_equilibrium(const double *p, double *x)\n{\n    double out[" << parts
          << "];\n    int i;\n    lagrange_linear(0.0, NULL, NULL, p, out);\n"
          << "    for (i = 0; i < " << nx << "; ++i)\n        x[i] = out[i];\n}\n\n"
          << "void " << name << "_linear(const double *p, double *T, double *V)\n{\n    double out[" << parts
          << "];\n    int i;\n    lagrange_linear(0.0, NULL, NULL, p, out);\n"
          << "    for (i = 0; i < " << nq << " * " << nq << "; ++i) {\n        T[i] = out[" << nx << " + i];\n"
          << "        V[i] = out[" << nx << " + " << nq << " * " << nq << " + i];\n    }\n}\n";
    }
    return {{name + ".h", h.str()}, {name + ".c", c.str()}};
}

} // namespace lagrange::export_detail
