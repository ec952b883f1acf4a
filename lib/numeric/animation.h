// SPDX-License-Identifier: GPL-2.0-or-later
/** @file animation.h
 *  The frames of an animation (`lagrange animate`): the scene's motion integrated once by
 *  DOP853, read at evenly spaced times from its dense output, and turned into what is drawn:
 *  the points (with their masses), the rigid bodies placed in the coordinates (their outline
 *  by shape in their own axes, and their pose at each frame), the ends of the springs, the
 *  fixed pivot, moving supports, and the rods — pairs of these whose distance the motion keeps
 *  constant (a pendulum's string, a shared body). A free body's frames are Poinsot's
 *  construction (numeric/poinsot.h). The writers (output/animation_output.h) only draw what
 *  is here. */
#pragma once

#include "mechanics/equations_of_motion.h"
#include "numeric/poinsot.h"
#include "core/model.h"

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace lagrange {

struct animation_settings {
    double fps = 30;                ///< samples per unit of simulated time
    std::optional<double> until;    ///< overrides the scene's `simulate until`
    double tolerance = 1e-9;        ///< target of the relative error (per step ÷12, as simulate)
    bool native = true;
    /// An initial state off the constraints is an error unless this asks to move it onto
    /// them by least change (`--project-initial`), as for simulate.
    bool project_initial = false;
};

struct animation_frames {
    /// What is drawn at each frame, in order: the points, the bodies' centres of mass, the
    /// pivot (the origin; named "pivot" when a rod or a body holds to it, else ""), the moving
    /// supports (named "support" when a rod holds a point to one, else ""), then the ends of
    /// each spring.
    struct marker {
        std::string name;
        double mass = 0;     ///< points: their mass at the values; 0 for the others
        bool point = false;  ///< a point mass (drawn as a disc)
    };
    std::vector<marker> markers;
    struct link {
        std::size_t a = 0, b = 0; ///< markers
    };
    std::vector<link> rods, springs;
    /// A rigid body placed in the coordinates (`at`, `orientation`; not a free one): drawn by
    /// its shape, turned by its rotation at each frame, with its body axes.
    struct body_drawing {
        std::string name;
        std::string shape;      ///< the shape drawn: "stick", "disk", …, or "inertia ellipsoid"
        std::size_t centre = 0; ///< the marker of its centre of mass
        /// The outline: polylines in the body's axes, about its centre of mass.
        std::vector<std::vector<std::array<double, 3>>> outline;
        double size = 0;        ///< the outline's largest distance from the centre (the axes' length)
    };
    std::vector<body_drawing> bodies;
    /// Frame after frame, each body's rotation R (its axes' components in the scene's), row by row.
    std::vector<double> rotations;
    /// The ground, when the scene has gravity: the one the pivot is fixed in, when a pivot holds
    /// something, else the plane a moving body's lowest point stays on (rolling or sliding); a
    /// square normal to gravity (seen edge-on, a line, in a planar view).
    struct ground_square {
        std::array<double, 3> centre{}; ///< the pivot, or the mean of the body's lowest points
        std::array<double, 3> u{}, v{}; ///< two unit vectors in it, normal to gravity
        double half_width = 0;          ///< a quarter of the largest distance from the pivot drawn
    };
    std::optional<ground_square> ground;
    std::size_t dimensions = 2;     ///< 2 when every position is planar, else 3
    double step = 0;                ///< simulated time between frames (1/fps)
    std::vector<double> times;
    std::vector<double> positions;  ///< frame after frame: each marker's (x, y, z)
    std::vector<double> energy_drift; ///< (h − h₀)/scale at each frame (empty: h is not conserved)
    /// A free body's frames: Poinsot's construction (then there are no markers).
    std::optional<poinsot_motion> poinsot;
    std::string method;             ///< the integrator's name
    std::size_t steps = 0;
    const double* at(std::size_t frame, std::size_t marker) const
    {
        return positions.data() + (frame * markers.size() + marker) * 3;
    }
    const double* rotation(std::size_t frame, std::size_t body) const
    {
        return rotations.data() + (frame * bodies.size() + body) * 9;
    }
};

/// A scene with constraints runs as `simulate` runs it: DOP853 from frame to frame, projected
/// onto the constraints after each. Throws computation_error for a scene with nothing to draw
/// (no points, no placed bodies), an initial state off the constraints, or no end time; the
/// integration's own errors pass through.
animation_frames compute_animation(const model& scene, const equations_of_motion& equations,
                                   const animation_settings& settings);

/// The frames of a torque-free body (`body`, the scene's `euler` result): Poinsot's
/// construction over the animation's length, and T's drift. Throws computation_error as
/// compute_poinsot does, or when the length is not given.
animation_frames compute_body_animation(const model& scene, const euler_result& body,
                                        const animation_settings& settings);

} // namespace lagrange
