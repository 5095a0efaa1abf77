#include "cpkit/core/problem.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>

namespace {
constexpr double kInf() { return std::numeric_limits<double>::infinity(); }
}  // namespace

namespace cpkit {
namespace {

// First non-finite entry of a dense object, as "(i, j)" / "[i]"; empty if all finite.
std::string first_nonfinite(const Mat& m) {
  for (Eigen::Index j = 0; j < m.cols(); ++j)
    for (Eigen::Index i = 0; i < m.rows(); ++i)
      if (!std::isfinite(m(i, j)))
        return "(" + std::to_string(i) + ", " + std::to_string(j) + ")";
  return {};
}
std::string first_nonfinite(const Vec& v) {
  for (Eigen::Index i = 0; i < v.size(); ++i)
    if (!std::isfinite(v[i])) return "[" + std::to_string(i) + "]";
  return {};
}
std::string first_nonfinite(const SparseMat& m) {
  for (Eigen::Index k = 0; k < m.outerSize(); ++k)
    for (SparseMat::InnerIterator it(m, k); it; ++it)
      if (!std::isfinite(it.value()))
        return "(" + std::to_string(it.row()) + ", " + std::to_string(it.col()) + ")";
  return {};
}

}  // namespace

Vec LcpProblem::w(const Vec& z) const {
  if (is_sparse()) return M_sparse * z + q;
  return M * z + q;
}

double LcpProblem::max_abs_entry() const {
  if (!is_sparse()) return M.size() ? M.cwiseAbs().maxCoeff() : 0.0;
  double m = 0;
  for (Eigen::Index k = 0; k < M_sparse.outerSize(); ++k)
    for (SparseMat::InnerIterator it(M_sparse, k); it; ++it) m = std::max(m, std::abs(it.value()));
  return m;
}

Mat LcpProblem::dense_M() const { return is_sparse() ? Mat(M_sparse) : M; }

std::string LcpProblem::validate() const {
  // Runs on every solve: the message (and its stream) is built only for bad data.
  const Eigen::Index n = q.size();
  if (n == 0) return "q is empty (an LCP needs n >= 1)";
  const Eigen::Index rows = is_sparse() ? M_sparse.rows() : M.rows();
  const Eigen::Index cols = is_sparse() ? M_sparse.cols() : M.cols();
  if (rows != cols)
    return "M is not square (" + std::to_string(rows) + " x " + std::to_string(cols) + ")";
  if (rows != n)
    return "size mismatch: M is " + std::to_string(rows) + " x " + std::to_string(cols) +
           " but q has " + std::to_string(n) + " entries";
  if (auto at = is_sparse() ? first_nonfinite(M_sparse) : first_nonfinite(M); !at.empty())
    return "M has a non-finite entry at " + at;
  if (auto at = first_nonfinite(q); !at.empty()) return "q has a non-finite entry at " + at;
  return {};
}

std::string BoxLcpProblem::validate() const {
  if (auto m = lcp.validate(); !m.empty()) return m;
  std::ostringstream msg;
  const Eigen::Index n = lcp.size();
  if (lower.size() != n || upper.size() != n) {
    msg << "bounds have sizes " << lower.size() << " and " << upper.size() << ", expected " << n;
    return msg.str();
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    if (std::isnan(lower[i]) || std::isnan(upper[i]) || lower[i] == kInf() || upper[i] == -kInf())
      msg << "bound " << i << " is invalid (l = " << lower[i] << ", u = " << upper[i] << ")";
    else if (lower[i] > upper[i])
      msg << "bound " << i << " has l > u (" << lower[i] << " > " << upper[i] << ")";
    if (msg.tellp() != 0) break;
  }
  return msg.str();
}

bool McpProblem::is_ncp() const {
  return lower.size() == n && upper.size() == n && (lower.array() == 0.0).all() &&
         (upper.array() == std::numeric_limits<double>::infinity()).all();
}

std::string McpProblem::validate() const {
  std::ostringstream msg;
  if (n <= 0) {
    msg << "n must be >= 1 (got " << n << ")";
  } else if (!F) {
    msg << "F callback is missing";
  } else if (lower.size() != n || upper.size() != n) {
    msg << "bounds have sizes " << lower.size() << " and " << upper.size() << ", expected " << n;
  } else if (x0.size() != 0 && x0.size() != n) {
    msg << "x0 has size " << x0.size() << ", expected " << n;
  } else if (x0.size() == n && !x0.allFinite()) {
    msg << "x0 has a non-finite entry";
  } else {
    for (Eigen::Index i = 0; i < n; ++i) {
      if (std::isnan(lower[i]) || std::isnan(upper[i]) || lower[i] == kInf() ||
          upper[i] == -kInf()) {
        msg << "bound " << i << " is invalid (l = " << lower[i] << ", u = " << upper[i] << ")";
        break;
      }
      if (lower[i] > upper[i]) {
        msg << "bound " << i << " has l > u (" << lower[i] << " > " << upper[i] << ")";
        break;
      }
    }
  }
  return msg.str();
}

McpProblem make_ncp(Eigen::Index n, FunctionCallback F, JacobianCallback J, std::string name) {
  McpProblem p;
  p.n = n;
  p.F = std::move(F);
  p.jacobian = std::move(J);
  p.lower = Vec::Zero(n);
  p.upper = Vec::Constant(n, std::numeric_limits<double>::infinity());
  p.name = std::move(name);
  return p;
}

McpProblem box_lcp_as_mcp(const BoxLcpProblem& box) {
  auto data = std::make_shared<const LcpProblem>(box.lcp);
  McpProblem p;
  p.n = data->size();
  p.F = [data](const Vec& x, Vec& F) {
    F = data->w(x);
    return true;
  };
  if (data->is_sparse()) {
    p.sparse_jacobian = [data](const Vec&, SparseMat& J) {
      J = data->M_sparse;
      return true;
    };
  } else {
    p.jacobian = [data](const Vec&, Mat& J) {
      J = data->M;
      return true;
    };
  }
  p.lower = box.lower;
  p.upper = box.upper;
  p.name = data->name;
  p.note = data->note;
  return p;
}

McpProblem lcp_as_mcp(const LcpProblem& lcp) {
  BoxLcpProblem box{lcp, Vec::Zero(lcp.size()),
                    Vec::Constant(lcp.size(), std::numeric_limits<double>::infinity())};
  return box_lcp_as_mcp(box);
}

}  // namespace cpkit
