/** @file normal_modes.h
 *  Numeric normal modes at each `values` point: ω ascending, the mode matrix with
 *  Aᵀ T A = I, and an error estimate per frequency that bounds the error. */
#pragma once

#include "mechanics/oscillations.h"
#include "scene/model.h"

#include <Eigen/Dense>

#include <string>
#include <utility>
#include <vector>

namespace lagrange {

struct numeric_modes {
    std::vector<std::pair<std::string, double>> values; ///< the parameter point
    std::vector<double> omega_squared;                  ///< ascending, signed (ω² < 0: unstable mode)
    std::vector<double> omega;                          ///< sign(ω²)·√|ω²|: a negative entry is the growth
                                                        ///< rate of an imaginary frequency
    Eigen::MatrixXd modes;                              ///< columns, Aᵀ T A = I
    std::vector<double> error;                          ///< estimated relative error of each ω
    std::string method;                                 ///< which numeric path gave these
};

/// Numeric modes at every `values` point of the scene. Throws computation_error
/// with the cause (singular kinetic matrix at these values, a parameter without a
/// value, ...) rather than returning NaN or infinity.
std::vector<numeric_modes> numeric_normal_modes(const model& scene, const linearization_result& linear);

} // namespace lagrange
