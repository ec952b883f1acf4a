// SPDX-License-Identifier: GPL-2.0-or-later
/** @file export_code.h
 *  `lagrange export`: the equations of motion as source code that users put into their own
 *  work — C99 (one .c and one .h), a Python module on NumPy arrays, or MATLAB/Octave function
 *  files — written from the straight-line programs of numeric/exported_system.h, with the
 *  scene's names. The interface of each target is in docs/export.md. */
#pragma once

#include "algebra/budget.h"
#include "core/model.h"
#include "numeric/exported_system.h"

#include <optional>
#include <string>
#include <vector>

namespace lagrange {

enum class export_target { c, python, octave };

/// "c", "python" or "octave"; nothing for another word.
std::optional<export_target> export_target_named(const std::string& word);

/// The scene file's stem made an identifier ("double_pendulum" for
/// examples/double_pendulum.lag, "scene" for standard input): the default NAME.
std::string default_export_name(const std::string& scene_file);

/// Whether `name` can name the exported functions: an ASCII identifier, not a keyword of any target.
bool valid_export_name(const std::string& name);

struct exported_file {
    std::string name; ///< file name, no folder
    std::string text;
};

/// The files of `target`: for C NAME.h and NAME.c; for Python NAME.py; for Octave one
/// NAME_FUNCTION.m per function. `version` is the engine's, for the header comment.
std::vector<exported_file> export_code(const model& scene, const exported_system& system, export_target target,
                                       const std::string& name, const std::string& version);

/// The files of `target` for `scene`: its equations of motion, and the equilibrium with T and
/// V where the scene has one (engine/analysis.h, analyze_for_export), derived under `limits`.
/// Throws computation_error for a scene that cannot be exported.
std::vector<exported_file> export_scene(const model& scene, export_target target, const std::string& name,
                                        const std::string& version, const budget_limits& limits = {});

} // namespace lagrange
