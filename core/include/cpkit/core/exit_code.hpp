#pragma once
// The outcome classes of a cpkit command, as the program's exit codes (docs/conventions.md).
// Users script against these numbers: keep them exactly. The program returns them; library
// functions that run a whole command's request (rate, step, simulate, map) compute them, so the
// decision is tested without a subprocess.

namespace cpkit {

enum ExitCode : int {
  kExitOk = 0,            ///< solved / at least one solution
  kExitNoSolution = 1,    ///< the solve ran but found no solution
  kExitBadInput = 2,      ///< bad input or usage; message on stderr, nothing on stdout
  kExitDisagreement = 3,  ///< a disagreement between solvers or routes (`lcp verify`, `rate`, `map`)
  kExitInternal = 4,      ///< internal error (a bug), or a requested picture that could not be drawn
  kExitInconclusive = 5,  ///< incomplete enumeration that proves nothing (`lcp verify`: no
                          ///< disagreement; `lcp enumerate`: no solution found so far)
};

}  // namespace cpkit
