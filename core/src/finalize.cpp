#include "cpkit/core/finalize.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace cpkit {
namespace {

std::string fmt(double v) {
  std::ostringstream s;
  s.precision(3);
  s << v;
  return s.str();
}

void append(std::string& message, const std::string& text) {
  if (!message.empty()) message += "; ";
  message += text;
}

// Shared decision once residuals are known: the data decide, not the claim.
void decide(SolveResult& r, bool claimed_solution, const CommonOptions& o) {
  // The rounding allowance of w is granted on top of each band (residuals.hpp).
  const double res = std::max(0.0, r.residuals.natural - r.residuals.rounding);
  if (res <= o.tol) {
    if (!claimed_solution && r.status != Status::kNotRun)
      append(r.message, std::string("point verified as a solution although the solver reported ") +
                            std::string(to_string(r.status)));
    r.status = Status::kSolved;
  } else if (res <= o.tol_acceptable) {
    r.status = Status::kSolvedInaccurate;
    append(r.message, "scaled residual " + fmt(res) + " above tol " + fmt(o.tol));
  } else if (claimed_solution) {
    r.status = Status::kNumericalFailure;
    append(r.message, "claimed solution refuted by the data: scaled natural residual " + fmt(res) +
                          " > tol_acceptable " + fmt(o.tol_acceptable));
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

// Largest |M_ij| without densifying sparse storage.
double max_abs_entry(const LcpProblem& p) {
  if (!p.is_sparse()) return p.M.size() ? p.M.cwiseAbs().maxCoeff() : 0.0;
  double m = 0;
  for (Eigen::Index k = 0; k < p.M_sparse.outerSize(); ++k)
    for (SparseMat::InnerIterator it(p.M_sparse, k); it; ++it) m = std::max(m, std::abs(it.value()));
  return m;
}

}  // namespace

bool check_certificate(const LcpProblem& p, Certificate& cert, double tol) {
  cert.checked = false;
  const Eigen::Index n = p.size();
  if (cert.y.size() != n || !cert.y.allFinite()) return false;
  const double ymax = cert.y.lpNorm<Eigen::Infinity>();
  if (!(ymax > 0)) return false;
  const Vec y = cert.y / ymax;
  if (y.minCoeff() < -tol) return false;
  const Vec yp = y.cwiseMax(0.0);  // tiny negatives dropped: the proof is made with yp
  const Vec mty = p.is_sparse() ? Vec(p.M_sparse.transpose() * yp) : Vec(p.M.transpose() * yp);
  const double mscale = std::max(1.0, max_abs_entry(p));
  const double qscale = std::max(1.0, p.q.lpNorm<Eigen::Infinity>());
  cert.max_MTy = mty.maxCoeff();
  cert.q_dot_y = p.q.dot(yp);
  cert.y = yp;
  cert.checked = cert.max_MTy <= tol * mscale * static_cast<double>(n) && cert.q_dot_y < -tol * qscale;
  return cert.checked;
}

SolveResult finalize(const LcpProblem& p, SolveResult r, const CommonOptions& o) {
  const bool claimed_solution = is_solution(r.status);
  if (r.status == Status::kInfeasible) {
    if (r.certificate && check_certificate(p, *r.certificate)) {
      if (r.z.size() == p.size() && r.z.allFinite()) r.residuals = lcp_residuals(p, r.z, r.w);
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
  if (r.status == Status::kInfeasible) {
    // No box certificate format yet: never grant infeasibility without a checkable proof.
    r.status = Status::kNumericalFailure;
    append(r.message, "infeasibility claimed for a box LCP without a checkable certificate");
    r.certificate.reset();
    return r;
  }
  r.certificate.reset();
  if (!usable_point(r, p.size(), claimed_solution)) return r;
  r.residuals = box_lcp_residuals(p, r.z, r.w);
  decide(r, claimed_solution, o);
  return r;
}

SolveResult finalize(const McpProblem& p, SolveResult r, const CommonOptions& o) {
  const bool claimed_solution = is_solution(r.status);
  if (r.status == Status::kInfeasible) {
    r.status = Status::kNumericalFailure;
    append(r.message, "infeasibility claimed for an MCP without a checkable certificate");
    r.certificate.reset();
    return r;
  }
  r.certificate.reset();
  if (!usable_point(r, p.size(), claimed_solution)) return r;
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
