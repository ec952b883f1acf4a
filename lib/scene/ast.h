// SPDX-License-Identifier: GPL-2.0-or-later
/** @file ast.h
 *  The syntax tree of a scene, exactly as written: no names are resolved here. */
#pragma once

#include "scene/source.h"

#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace lagrange {

/// The functions of expressions: `sin`, `cos`, ... `abs` (a call is NAME `(` ... `)`).
const std::set<std::string>& function_names();

struct expr_node;
using expr_ptr = std::unique_ptr<expr_node>;

/// An expression. Sums and products are n-ary so that long flat expressions
/// do not make deep trees.
struct expr_node {
    enum class kind {
        integer,  ///< text: the digits
        decimal,  ///< text: the literal
        name,     ///< text: the name
        velocity, ///< text: the coordinate name (`q'` or `dot(q)`)
        wildcard, ///< text: the number after `$`
        negate,   ///< operands[0]
        sum,      ///< operands, with signs '+' / '-'
        product,  ///< operands, with ops '*' / '/'
        power,    ///< operands[0] ^ operands[1]
        call,     ///< text: function name; operands: arguments
    };
    kind node_kind;
    source_location where;
    std::string text;
    std::vector<expr_ptr> operands;
    std::vector<char> ops; ///< for sum and product: one per operand
};

struct name_ref {
    std::string name;
    source_location where;
};

/// `name = expr` or `name' = expr` in equilibrium, values and initial lines.
struct assignment {
    name_ref target;
    bool velocity = false;
    expr_ptr value;
};

/// A vector `(x, y[, z])`.
struct vector_expr {
    std::vector<expr_ptr> components;
    source_location where;
};

/// One end of a spring: a point's name or a fixed position.
struct endpoint {
    std::optional<name_ref> point;
    std::optional<vector_expr> position;
};

/// A call-like shape or region: `disk(R)`, `box(a, b, c)`.
struct shape_expr {
    name_ref name;
    std::vector<expr_ptr> arguments;
};

struct body_statement {
    enum class kind { shape, region, inertia };
    kind body_kind = kind::shape;
    name_ref name;
    std::optional<shape_expr> shape;           ///< shape or region
    std::optional<vector_expr> moments;        ///< inertia (I1, I2, I3)
    std::vector<vector_expr> tensor_rows;      ///< inertia ((Ixx, Ixy, Ixz), …): the rows
    source_location tensor_where;              ///< the tensor's opening parenthesis
    std::optional<vector_expr> about;          ///< about (x, y, z)
    std::optional<name_ref> attached_to;       ///< attached to A
    expr_ptr mass;                             ///< shape, inertia
    expr_ptr density;                          ///< region
    std::optional<name_ref> axis;              ///< x | y | z
    std::optional<vector_expr> at;
    std::optional<shape_expr> orientation;     ///< zxz(phi, theta, psi) or rotations(z q1, x q2, …)
    std::vector<name_ref> rotation_axes;       ///< rotations: the axis before each angle
};

/// One statement; `keyword` says which, and only the matching fields are set.
struct statement {
    std::string keyword; ///< "scene", "parameters", ..., "T", "V", "L"
    source_location where;
    std::string text;                ///< scene title, use file
    std::vector<name_ref> names;     ///< parameters, coordinates, want; [0] for let/point/ratio/limit/omega/torque
    expr_ptr value;                  ///< let, T/V/L, point mass, gravity strength, spring stiffness, ratio, simulate until
    std::vector<assignment> assignments; ///< equilibrium, values, initial
    std::optional<vector_expr> vector;   ///< point position, gravity direction, omega, torque
    std::optional<endpoint> end_a, end_b;
    expr_ptr rest;                   ///< spring rest length
    std::optional<name_ref> limit_target; ///< `0` or `oo` in limit lines
    expr_ptr step, tolerance;        ///< simulate
    std::optional<name_ref> method;  ///< simulate
    std::optional<body_statement> body;
    bool on_point = false;           ///< `force on P (...)` rather than `force q = ...`
    expr_ptr right;                  ///< constraint: the right-hand side (`value` is the left); critical: `to`
    std::optional<name_ref> axis;    ///< rolls: `axis y` (`names` holds the body and the surface, `value` the radius)
};

struct scene_ast {
    std::vector<statement> statements;
};

} // namespace lagrange
