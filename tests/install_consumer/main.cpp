// SPDX-License-Identifier: GPL-2.0-or-later
/** @file main.cpp
 *  Derives a harmonic oscillator's equation through the installed library, and prints the
 *  version of <lagrange/version.h>. */
#include <lagrange/lagrange.h>
#include <lagrange/version.h>

#include <iostream>

static_assert(LAGRANGE_VERSION_MAJOR >= 0 && LAGRANGE_VERSION_MINOR >= 0 && LAGRANGE_VERSION_PATCH >= 0,
              "the version header gives the version's parts");

int main()
{
    lagrange::model scene = lagrange::load_model(
        lagrange::source_text("oscillator.lag", "parameters m k\ncoordinates x\nT = 1/2*m*x'^2\nV = 1/2*k*x^2\n"));
    lagrange::analysis result = lagrange::analyze(scene);
    std::cout << lagrange::print(result.equations->residuals->at(0), lagrange::syntax::plain) << '\n';
    std::cout << LAGRANGE_VERSION_STRING << '\n';
}
