// SPDX-License-Identifier: GPL-2.0-or-later
/** @file report_sections.h
 *  Section writers of the report that live in their family's file (output/<family>.cpp,
 *  beside its text, LaTeX and JSON writers). Each is listed in report_sections()
 *  (report.cpp). Internal to output/. */
#pragma once

#include "output/report.h"

#include <string>

namespace lagrange {

/// The figure of the mode shapes, with a sentence on which mode is in phase (mode_figures.cpp).
void write_mode_figures(report_writer& w);

/// The rigid-body sections (bodies.cpp, with inertia.cpp, tops.cpp, euler.cpp): each inertia component as the
/// integral it comes from, the tensor, L and T; the heavy top; Euler's
/// equations, the torque-free solution, conserved quantities, stability, polhode.
void write_body_sections(report_writer& w);

/// The motion in time (simulation.cpp): the simulation with the coordinates
/// against time (the beats, measured against 2π/(ω₊ − ω₋)), the work-precision diagram.
void write_motion_sections(report_writer& w);

/// The gyroscopic sections (oscillations.cpp): G with the Kelvin–Tait–Chetaev
/// verdict, and the numeric values from the quadratic eigenproblem with complex modes.
void write_gyroscopic_matrix(report_writer& w);
void write_gyroscopic_numeric(report_writer& w);

/// An L that depends on t (floquet.cpp): the Floquet multipliers about the points
/// that solve the equations at every t.
void write_floquet_section(report_writer& w);

/// Damped small oscillations (damping.cpp): C, det(K + sC + s²M) with its roots and
/// regimes, proportional damping, and the damped eigenvalues at the `values` points.
void write_damping_section(report_writer& w);
/// The linearized input–output system (linear_system.cpp): A, B and the transfer functions.
void write_linear_system_section(report_writer& w);
/// Each transfer function H_{u→q}(s) of `transfer` as a displayed row (the damping and the
/// operating point sections both list them).
void write_transfer_rows(report_writer& w, const model& scene, const transfer_result& transfer, const std::string& s);
/// A and B about an operating point, with constraints (linear_system.cpp).
void write_operating_point_section(report_writer& w);
/// Symmetries (symmetries.cpp): the conserved quantities, the Hamiltonian, Routh's
/// reduction and the steady motion.
void write_symmetries_section(report_writer& w);
/// Scenes with constraints (constraints.cpp): the constraints with their kind and
/// integrability, the multipliers and the constraint forces.
void write_constraints_section(report_writer& w);

/// The report sections of the products with an output family of their own
/// (core/products.inc), defined in output/<id>.cpp; listed in report_sections() after the
/// Floquet section, in products.inc's order.
#define LAGRANGE_PRODUCT(id, name, scope, by_default)
#define LAGRANGE_OWN_PRODUCT(id, name, scope, by_default, result) void write_##id##_section(report_writer& w);
#include "core/products.inc"
#undef LAGRANGE_OWN_PRODUCT
#undef LAGRANGE_PRODUCT

/// The phase portrait of a scene of one coordinate (phase_output.cpp): the level curves of
/// the energy, with the separatrices.
void write_phase_section(report_writer& w);

/// The parameter values of a numeric point as LaTeX, "m = 1,\ k = 4" (the numeric sections'
/// subsection titles).
std::string values_latex(const numeric_modes& point);

/// After a numeric point's table: one sentence per mode that grows, naming its growth rate
/// (output/mode_frequency.h), so that the table's imaginary ω is never read as a frequency.
void write_growth_rates(report_writer& w, const numeric_modes& nm);

} // namespace lagrange
