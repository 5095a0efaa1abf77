#pragma once
// The result dataclasses of cpkit/results.py (SolveResult, Residuals, Attempt, Certificate)
// built directly by the extension (issue 27: the dict-then-dataclass route cost more than the
// tiny solve itself). Same objects, same fields as SolveResult._from(to_dict(r)).
#include "convert.hpp"

namespace cpkit::py {

/// Registers the classes (called once by cpkit/results.py at import).
void set_result_classes(pyb::object solve_result, pyb::object residuals, pyb::object attempt,
                        pyb::object certificate);

/// A cpkit.SolveResult for `r`; falls back to the dict of to_dict(r) if the classes were never
/// registered (the module used without its Python package).
pyb::object make_solve_result(const SolveResult& r);

}  // namespace cpkit::py
