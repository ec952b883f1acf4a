/** @file main.cpp
 *  Derives a harmonic oscillator's equation through the installed library. */
#include <lagrange/lagrange.h>

#include <iostream>

int main()
{
    lagrange::model scene = lagrange::load_model(
        lagrange::source_text("oscillator.lag", "parameters m k\ncoordinates x\nT = 1/2*m*x'^2\nV = 1/2*k*x^2\n"));
    lagrange::analysis result = lagrange::analyze(scene);
    std::cout << lagrange::print(result.equations->residuals->at(0), lagrange::syntax::plain) << '\n';
}
