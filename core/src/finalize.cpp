#include "cpkit/core/finalize.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "cpkit/core/short_number.hpp"
#include "finalize_decide.hpp"

namespace cpkit {

namespace detail {

void append(std::string& message, const std::string& text) {
  if (!message.empty()) message += "; ";
  message += text;
}

// Shared decision once residuals are known: the data decide, not the claim. `natural` is unit-free
// and already has the rounding allowance deducted (residuals.hpp); non-finite is never accepted.
void decide(SolveResult& r, bool claimed_solution, const CommonOptions& o) {
  const double res = r.residuals.finite ? r.residuals.natural : std::numeric_limits<double>::infinity();
  if (res <= o.tol) {
    if (!claimed_solution && r.status != Status::kNotRun)
      append(r.message, std::string("point verified as a solution although the solver reported ") +
                            std::string(to_string(r.status)));
    r.status = Status::kSolved;
  } else if (res <= o.tol_acceptable) {
    r.status = Status::kSolvedInaccurate;
    append(r.message, "unit-free residual " + short_number(res) + " above tol " + short_number(o.tol));
  } else if (claimed_solution) {
    r.status = Status::kNumericalFailure;
    append(r.message, !r.residuals.finite
                          ? std::string("claimed solution refuted: w = M z + q or its scale is not "
                                        "representable in double precision (overflow/NaN)")
                          : "claimed solution refuted by the data: unit-free residual " + short_number(res) +
                                " > tol_acceptable " + short_number(o.tol_acceptable));
  }
}

// Common pre-checks on z; returns false when no residuals can be computed.
bool usable_point(SolveResult& r, Eigen::Index n, bool claimed_solution) {
  if (r.z.size() == n && r.z.allFinite()) return true;
  if (claimed_solution) {
    r.status = Status::kNumericalFailure;
    append(r.message, r.z.size() != n ? "claimed solution has size " + std::to_string(r.z.size()) +
                                            ", expected " + std::to_string(n)
                                      : "claimed solution has non-finite entries");
  }
  return false;
}

bool refuse_infeasibility(SolveResult& r, const char* kind) {
  r.certificate.reset();
  if (r.status != Status::kInfeasible) return false;
  r.status = Status::kNumericalFailure;
  append(r.message, std::string("infeasibility claimed for ") + kind +
                        " without a checkable certificate");
  return true;
}

}  // namespace detail

using detail::append;
using detail::refuse_infeasibility;
using detail::decide;
using detail::usable_point;

SolveResult finalize(const LcpProblem& p, SolveResult r, const CommonOptions& o) {
  const bool claimed_solution = is_solution(r.status);
  if (r.status == Status::kInfeasible) {
    if (r.certificate && check_certificate(p, *r.certificate)) {
      if (r.z.size() == p.size() && r.z.allFinite()) r.residuals = lcp_residuals(p, r.z, r.w);
      if (!r.certificate->exact)
        append(r.message, "the certificate holds within the rounding error of M^T y and q^T y "
                          "(componentwise), not exactly");
      return r;
    }
    r.status = Status::kNumericalFailure;
    append(r.message, r.certificate ? "infeasibility certificate refuted by the data"
                                    : "infeasibility claimed without a certificate");
    r.certificate.reset();
    return r;
  }
  r.certificate.reset();  // a certificate only accompanies a checked kInfeasible
  if (!usable_point(r, p.size(), claimed_solution)) return r;
  r.residuals = lcp_residuals(p, r.z, r.w);
  decide(r, claimed_solution, o);
  return r;
}

SolveResult finalize(const BoxLcpProblem& p, SolveResult r, const CommonOptions& o) {
  const bool claimed_solution = is_solution(r.status);
  if (refuse_infeasibility(r, "a box LCP") || !usable_point(r, p.size(), claimed_solution))
    return r;
  r.residuals = box_lcp_residuals(p, r.z, r.w);
  decide(r, claimed_solution, o);
  return r;
}

SolveResult finalize(const McpProblem& p, SolveResult r, const CommonOptions& o) {
  const bool claimed_solution = is_solution(r.status);
  if (refuse_infeasibility(r, "an MCP") || !usable_point(r, p.size(), claimed_solution)) return r;
  Vec F(p.size());
  if (!p.F(r.z, F) || F.size() != p.size() || !F.allFinite()) {
    if (claimed_solution) {
      r.status = Status::kNumericalFailure;
      append(r.message, "F is undefined or non-finite at the claimed solution");
    }
    return r;
  }
  r.w = F;
  r.residuals = mcp_residuals(p, r.z, F);
  decide(r, claimed_solution, o);
  return r;
}

}  // namespace cpkit
