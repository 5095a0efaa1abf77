#pragma once
/// \file options.hpp
/// Options shared by every solver. Solver-specific option structs embed a CommonOptions.
#include <limits>
#include <string>

namespace cpkit {

class LogSink;

struct CommonOptions {
  /// Acceptance tolerance on the unit-free residual (residuals.hpp, docs/conventions.md):
  /// natural <= tol  =>  Status::kSolved.
  double tol = 1e-10;
  /// Residual in (tol, tol_acceptable]  =>  Status::kSolvedInaccurate.
  double tol_acceptable = 1e-6;
  /// Iterations (or pivots) allowed; 0 means the solver's documented default.
  int max_iterations = 0;
  /// Wall-clock limit in seconds (checked between iterations).
  double time_limit_s = std::numeric_limits<double>::infinity();
  /// 0: errors only ... 3: debug. Only used when `log` is set.
  int verbosity = 0;
  /// Receives log lines; nullptr: nothing is logged. Not owned.
  LogSink* log = nullptr;
  /// Record a per-iteration trace in SolveResult::trace.
  bool record_trace = false;

  /// Empty when usable; otherwise names the bad field and its value.
  std::string validate() const;
};

}  // namespace cpkit
