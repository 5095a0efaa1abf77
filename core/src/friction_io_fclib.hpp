#pragma once
// FCLIB (HDF5) side of friction_io.hpp, internal to cpkit_core (friction_io_fclib.cpp).
#include <string>

#include "cpkit/core/friction_problem.hpp"

namespace cpkit::fclib_io {
FrictionContactProblem read_local(const std::string& path);
GlobalFrictionContactProblem read_global(const std::string& path);
/// True when the HDF5 file holds /fclib_global and no /fclib_local.
bool holds_global(const std::string& path);
void write_local_with_solution(const std::string& path, const FrictionContactProblem& problem,
                               const Eigen::VectorXd& r, const Eigen::VectorXd& u);
}  // namespace cpkit::fclib_io
