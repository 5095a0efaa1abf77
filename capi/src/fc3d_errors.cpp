// cpkit_fc3d_errors: the friction verdict (core/friction_verdict.hpp) on a caller's r: the
// errors, each contact's state, and the decision finalize() takes on r claimed as a solution.
#include <optional>
#include <string>
#include <vector>

#include "c_boundary.hpp"
#include "friction_input.hpp"
#include "cpkit/core/friction_verdict.hpp"

using namespace cpkit;
using namespace cpkit::capi;

extern "C" int cpkit_fc3d_errors(int contacts, int nnz, const int* col_ptr, const int* row_index,
                                 const double* values, const double* q, const double* mu,
                                 const double* r, const cpkit_options* options,
                                 cpkit_fc3d_error_values* errors, int* states, cpkit_info* info) {
  return guarded(info, [&](cpkit_info& out) {
    require(r, "r");
    const CommonOptions o = common_options(options);
    FrictionContactProblem p;
    map_friction_problem(contacts, nnz, col_ptr, row_index, values, q, mu, p);
    // A non-finite r is a candidate the verdict rejects (unit_free = +inf), not bad input.
    SolveResult claim;
    claim.status = Status::kSolved;
    claim.z = Eigen::Map<const Eigen::VectorXd>(r, 3LL * contacts);
    if (errors != nullptr) {
      const FrictionErrors e = friction_errors(p, claim.z);
      errors->unit_free = e.unit_free;
      errors->relative_q = e.relative_q;
      errors->relative_max = e.relative_max;
    }
    if (states != nullptr) {
      const std::vector<ContactReport> reports = friction_contacts(p, claim.z);
      for (int i = 0; i < contacts; ++i) states[i] = static_cast<int>(reports[i].state);
    }
    const SolveResult decided = finalize(p, std::move(claim), o);
    out.residual = decided.residuals.natural;
    if (is_solution(decided.status)) {
      if (decided.status == Status::kSolvedInaccurate)
        set_message(out, "cpkit: solved_inaccurate: " + decided.message);
      return 0;
    }
    set_message(out, "cpkit: r is not a solution: " + decided.message);
    return 5;
  });
}
