// SPDX-License-Identifier: GPL-2.0-or-later
/** @file model.h
 *  The model: what a scene said, as plain data, with every symbol created once.
 *  It knows nothing of printing or of the command line. */
#pragma once

#include "core/errors.h"
#include "core/rule.h"

#include <ginac/ginac.h>

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace lagrange {

/// A generalized coordinate q with its velocity and acceleration as plain symbols,
/// named `q`, `q_dot` and `q_ddot` (the reserved suffixes tell printers which is which).
struct coordinate {
    std::string name;
    GiNaC::realsymbol position;
    GiNaC::realsymbol velocity;
    GiNaC::realsymbol acceleration;
};

/// A constant symbol of the scene, assumed real and positive.
struct parameter {
    std::string name;
    GiNaC::possymbol symbol;
};

/// A point mass: adds ½ m |ṙ|² to T (and −m g·r to V under gravity).
struct point_mass {
    std::string name;
    GiNaC::ex mass;
    std::vector<GiNaC::ex> position; ///< 2 or 3 components, in the coordinates
    source_location where;
};

/// Uniform gravity of strength g along a unit vector.
struct gravity_field {
    GiNaC::ex strength;
    std::vector<GiNaC::ex> direction; ///< normalized, 2 or 3 components
};

/// A spring between two points or fixed positions: adds ½ k (|r_A − r_B| − a)² to V.
struct spring {
    GiNaC::ex stiffness;
    std::vector<GiNaC::ex> end_a;
    std::vector<GiNaC::ex> end_b;
    GiNaC::ex rest_length; ///< 0 if omitted
};

/// `input u`: a named input u(t), a symbol in the equations; in `values` a number or an
/// expression in t.
struct input_signal {
    std::string name;
    GiNaC::realsymbol symbol;
    source_location where;
    std::string line_text; ///< the `input` line, to quote when the simulation finds no value
};

/// `damper b between A and B`: a linear damper along the line from A to B, with the
/// Rayleigh function ½ b (d/dt |r_A − r_B|)².
struct damper {
    GiNaC::ex coefficient;
    std::vector<GiNaC::ex> end_a; ///< 3 components
    std::vector<GiNaC::ex> end_b;
    source_location where;
};

/// `force q = expr`: a generalized force on one coordinate.
struct generalized_force {
    std::size_t coordinate = 0; ///< index into model::coordinates
    GiNaC::ex value;            ///< in t, coordinates, velocities, parameters and inputs
    source_location where;
};

/// `force on P (Fx, Fy[, Fz])`: a force applied at a point.
struct point_force {
    std::string point;
    std::vector<GiNaC::ex> position; ///< the point's position (3 components)
    std::vector<GiNaC::ex> force;    ///< 3 components
    source_location where;
};

/// `constraint NAME: lhs = rhs` (§5 of the spec). With f = lhs − rhs, its velocity form is
/// Σ_j a_j(q, t) q̇_j + b(q, t) = 0: for a holonomic constraint f(q, t) = 0, a_j = ∂f/∂q_j and
/// b = ∂f/∂t; for a Pfaffian one (linear in the velocities) f itself. It adds a_j λ to the
/// generalized force on q_j, with the multiplier λ named `lambda_NAME`.
struct constraint {
    enum class kind { holonomic, pfaffian };
    std::string name;
    kind constraint_kind = kind::holonomic;
    GiNaC::ex function;                  ///< f = lhs − rhs
    std::vector<GiNaC::ex> coefficients; ///< a_j, one per coordinate
    GiNaC::ex rest;                      ///< b
    GiNaC::realsymbol multiplier;        ///< lambda_NAME
    source_location where;               ///< the constraint's name
};

/// `rolls W on ground`: the constraints that hold W's contact point P, each with the vector
/// e_k along which it holds P (its velocity form is e_k·v_P: the vertical for `W_contact`, a
/// horizontal for `W_roll_x`), so that the ground's force on W at P is Σ_k λ_k e_k (the
/// `contact` product): that force's generalized force is Σ_k λ_k e_k·∂v_P/∂q̇ = Aᵀλ.
struct rolling_contact {
    std::string body;
    std::vector<GiNaC::ex> point;                   ///< the contact point p(q), scene frame
    std::vector<std::string> constraints;           ///< the constraints' names, in the order made
    std::vector<std::vector<GiNaC::ex>> directions; ///< e_k of each (3 components)
    /// The wheel's height holds by the coordinates themselves (no `W_contact`): the normal
    /// force does no virtual work in them, so it is no multiplier.
    bool normal_by_construction = false;
    source_location where; ///< the body's name in the statement
};

/// A rigid body (§2 of the spec). Its inertia is derived later (bodies/inertia.h);
/// the model keeps what the scene said.
struct rigid_body {
    enum class kind { shape, region, inertia };
    std::string name;
    kind body_kind = kind::shape;
    std::string shape;                     ///< `disk`, `ball`, ... (shape or region name)
    std::vector<GiNaC::ex> dimensions;     ///< the shape's arguments (R, h, ...)
    GiNaC::ex mass;                        ///< shape and inertia bodies (region bodies: derived)
    GiNaC::ex density;                     ///< region bodies, in the body coordinates below
    std::vector<GiNaC::ex> moments;        ///< inertia bodies: (I1, I2, I3)
    /// inertia bodies given a full tensor: its nine entries, row by row, about `about`
    std::vector<GiNaC::ex> tensor;
    std::optional<std::vector<GiNaC::ex>> about; ///< the body point of `tensor`, from the centre of mass
    char axis = 'z';                       ///< the body axis that is the shape's symmetry axis
    std::optional<std::vector<GiNaC::ex>> position;    ///< `at`: the centre of mass (3 components), scene frame
    /// The angles of `orientation zxz(φ, θ, ψ)` or `rotations(a1 q1, …)`, in the scene's frame:
    /// with `attached to A`, A's angles come first. R = R_{a1}(q1) R_{a2}(q2) ⋯.
    std::optional<std::vector<GiNaC::ex>> orientation;
    std::vector<char> rotation_axes;       ///< the axis of each angle of `orientation`: 'x', 'y' or 'z'
    std::string attached_to;               ///< `attached to A`: position and orientation composed with A's
    std::optional<std::vector<GiNaC::realsymbol>> omega; ///< `omega B (w1, w2, w3)`, free bodies
    std::vector<GiNaC::realsymbol> omega_rates;         ///< w1_dot, w2_dot, w3_dot
    std::vector<GiNaC::ex> torque{0, 0, 0};            ///< `torque B (N1, N2, N3)`, body frame
    GiNaC::realsymbol x{"x"}, y{"y"}, z{"z"}, r{"r"}; ///< body coordinates of `density`
    source_location where;
};

/// `equilibrium theta = th0, phi' = Omega`: a steady motion (relative equilibrium). The
/// coordinates given a rate are cyclic and move at that constant rate; the others rest at
/// their values. A cyclic coordinate given neither is left to the engine, which solves
/// the steady-motion condition for its rate.
struct steady_motion_request {
    std::vector<std::optional<GiNaC::ex>> positions; ///< per coordinate; none for a cyclic one
    std::vector<std::optional<GiNaC::ex>> rates;     ///< per coordinate; set for those given a rate
    source_location where;
};

/// `linearize about q1 = e1, q1' = w1, u = u0`: the operating point of `state_space`. A
/// coordinate not named stays free (A and B are functions of it); a velocity not named is 0,
/// or, for a dependent speed, solved from the velocity constraints; an input not named is 0.
struct operating_point_request {
    std::vector<std::optional<GiNaC::ex>> positions;  ///< per coordinate
    std::vector<std::optional<GiNaC::ex>> velocities; ///< per coordinate
    std::vector<GiNaC::ex> inputs;                    ///< per input
    std::vector<source_location> position_where, velocity_where; ///< each entry's value (or the statement)
    source_location where;
    std::map<int, std::string> line_texts; ///< the statement's lines, to quote in a later error
};

/// `independent q2, q4, q5'`: the independent coordinates (names without `'`) and speeds
/// (names with `'`) of a constrained linearization; an empty list is chosen by the engine.
struct independent_request {
    std::vector<std::size_t> coordinates;
    std::vector<std::size_t> speeds;
    source_location where;
    std::string line_text; ///< the statement's line, to quote in a later error
};

/// `ratio rho = m/M`: results are also written with `numerator` replaced by rho·denominator.
struct ratio_request {
    std::string name;
    GiNaC::possymbol symbol;
    GiNaC::ex definition; ///< m/M
};

/// `limit rho -> 0` or `limit rho -> oo`.
struct limit_request {
    std::string variable;
    bool to_infinity = false;
};

/// `critical v from 0 to 10`: where a real part of an eigenvalue crosses zero as the
/// parameter runs over [from, to], the other parameters at the first `values` point.
struct critical_request {
    std::size_t parameter = 0; ///< index into model::parameters
    double from = 0, to = 0;   ///< 0 ≤ from < to, finite
    source_location where;
};

/// One `values` line: exact or floating values of parameters, in the order written.
struct value_point {
    std::vector<std::pair<std::string, GiNaC::ex>> values;
    source_location where;
    /// Inputs given on this line (`values u = sin(2*t)`): numbers or expressions in t
    /// and the parameters, in the order written.
    std::vector<std::pair<std::string, GiNaC::ex>> inputs;
};

/// Where a statement or value was written, with the text of its line: an error found
/// later (an initial state off the constraints, at simulation) points there with a caret.
struct written_at {
    source_location where;
    std::string line_text;
};

/// `initial q = 0.1, q' = 0`: entries not named are 0.
struct initial_state {
    std::map<std::string, GiNaC::ex> positions;  ///< by coordinate name
    std::map<std::string, GiNaC::ex> velocities; ///< by coordinate name
    std::map<std::string, GiNaC::ex> others;     ///< e.g. body angular velocities
    /// Where each position's and velocity's value was written (a scene line or --initial).
    std::map<std::string, written_at> position_written, velocity_written;
    written_at statement; ///< the last `initial` line or --initial that gave entries
    /// The entries `later` gives replace these (an --initial after the scene's line).
    void merge(const initial_state& later);
};

/// `simulate until T_end [step dt] [method NAME] [tolerance tol]`.
struct simulation_request {
    GiNaC::ex until;
    std::optional<GiNaC::ex> step;
    std::string method = "auto";
    std::optional<GiNaC::ex> tolerance;
    written_at statement;
};

/// The products a scene can ask for (§4 of the spec), in the spec's order.
enum class product {
#define LAGRANGE_PRODUCT(id, name, scope, by_default) id,
#include "core/products.inc"
#undef LAGRANGE_PRODUCT
};

/// Spec names of the products, in order.
const std::vector<std::pair<product, std::string>>& product_names();
std::optional<product> product_from_name(const std::string& name);
/// The name of `p` in the language.
const std::string& name_of(product p);
/// Whether `p` needs a scene with coordinates (all but inertia, euler, simulation and
/// workprecision, which a free body's scene also has).
bool needs_coordinates(product p);

/// A likely slip in a valid scene (a kinetic energy without velocities): printed as
/// `FILE:LINE:COL: warning: MESSAGE` with the line and a caret, never an error.
struct scene_warning {
    source_location where;
    std::string message;
    std::string line_text; ///< the line `where` points into
};

/// Everything a scene said.
struct model {
    std::string file;
    std::string title;
    GiNaC::realsymbol time{"t"};
    std::vector<parameter> parameters;
    std::vector<coordinate> coordinates;

    GiNaC::ex kinetic_terms;   ///< sum of the `T = ...` lines (0 if none)
    GiNaC::ex potential_terms; ///< sum of the `V = ...` lines (0 if none)
    std::optional<GiNaC::ex> lagrangian_terms; ///< an `L = ...` line
    std::vector<point_mass> points;
    std::optional<gravity_field> gravity;
    std::vector<spring> springs;
    std::vector<rigid_body> bodies;

    GiNaC::ex dissipation;     ///< sum of the `dissipation F = ...` lines (0 if none)
    std::optional<source_location> dissipation_line; ///< the first `dissipation` line
    std::vector<damper> dampers;
    std::vector<generalized_force> forces;
    std::vector<point_force> point_forces;
    std::vector<input_signal> inputs;
    std::vector<constraint> constraints; ///< in the order written
    std::vector<rolling_contact> contacts; ///< one per `rolls` line, in the order written

    std::optional<std::vector<GiNaC::ex>> equilibrium; ///< one value per coordinate
    std::optional<steady_motion_request> steady; ///< an `equilibrium` line that names a rate
    std::optional<operating_point_request> operating_point; ///< a `linearize about` line
    std::optional<independent_request> independent;         ///< an `independent` line
    std::optional<ratio_request> ratio;
    std::optional<limit_request> limit;
    std::optional<critical_request> critical; ///< a `critical` line
    std::vector<value_point> values;
    std::optional<initial_state> initial;
    std::optional<simulation_request> simulation;
    std::vector<rewrite_rule> rules; ///< from `use` lines (the embedded rules are added by the stages)
    std::set<product> wanted; ///< empty: everything the scene supports
    std::vector<scene_warning> warnings; ///< likely slips, in the order found

    /// Positions, velocities and accelerations of all coordinates, in order.
    GiNaC::lst positions() const;
    GiNaC::lst velocities() const;
    GiNaC::lst accelerations() const;
    /// True if the scene has dissipation, dampers, forces or inputs: the equations of
    /// motion then have generalized forces beyond L.
    bool has_generalized_forces() const;
};

/// The values of a `values` line as a substitution.
GiNaC::exmap value_map(const model& scene, const value_point& point);

/// The body of that name, or null when the scene has none.
const rigid_body* body_named(const model& scene, const std::string& name);

/// The names of the coordinates and of the parameters, in the scene's order.
std::vector<std::string> coordinate_names(const model& scene);
std::vector<std::string> parameter_names(const model& scene);

} // namespace lagrange
