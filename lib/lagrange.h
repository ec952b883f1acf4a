// SPDX-License-Identifier: GPL-2.0-or-later
/** @file lagrange.h
 *  The library in one header, installed as <lagrange/lagrange.h>: load a scene,
 *  analyze it, and write the results as text, LaTeX, JSON or a derivation report.
 *  @code
 *  lagrange::model scene = lagrange::load_model(lagrange::source_text("pendulum.lag", text));
 *  lagrange::analysis result = lagrange::analyze(scene);   // every product the scene supports
 *  lagrange::write_text(std::cout, result);                // or write_latex, write_json
 *  @endcode
 *  Errors: scene_error (bad input, with file, line and column; format_error prints
 *  it), computation_error and budget_exceeded (core/errors.h, algebra/budget.h).
 *  The version: LAGRANGE_VERSION_MAJOR, _MINOR, _PATCH and _STRING (<lagrange/version.h>). */
#pragma once

#include <lagrange/version.h>

#include "engine/analysis.h"
#include "output/document.h"
#include "output/print.h"
#include "output/report.h"
#include "output/simulation.h"
#include "output/sweep_output.h"
#include "output/ensemble_output.h"
#include "scene/lower.h"
#include "scene/source.h"
