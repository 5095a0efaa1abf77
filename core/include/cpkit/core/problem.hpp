#pragma once
/// \file problem.hpp
/// Complementarity problem types. Sign convention everywhere in cpkit:
///   LCP(M, q):  z >= 0,  w = M z + q >= 0,  z . w = 0.
#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <functional>
#include <string>

namespace cpkit {

using Vec = Eigen::VectorXd;
using Mat = Eigen::MatrixXd;
using SparseMat = Eigen::SparseMatrix<double>;  // column-major

/// Linear complementarity problem 0 <= z _|_ M z + q >= 0 [Cottle-Pang-Stone 1992, Sec. 1.1].
/// Storage is dense (`M`) unless `M_sparse` is non-empty, in which case `M` is ignored.
struct LcpProblem {
  Mat M;               ///< dense n x n matrix (dense storage)
  SparseMat M_sparse;  ///< sparse n x n matrix (sparse storage, when non-empty)
  Vec q;               ///< n-vector
  std::string name;    ///< optional label (from files: "name")
  std::string note;    ///< optional free text (from files: "note", or .dat trailing text)

  LcpProblem() = default;
  LcpProblem(Mat m, Vec q_in, std::string name_in = {})
      : M(std::move(m)), q(std::move(q_in)), name(std::move(name_in)) {}

  bool is_sparse() const noexcept { return M_sparse.nonZeros() > 0 || M_sparse.rows() > 0; }
  Eigen::Index size() const noexcept { return q.size(); }
  /// w = M z + q computed from the stored data (dense or sparse).
  Vec w(const Vec& z) const;
  /// Dense copy of M whatever the storage.
  Mat dense_M() const;
  /// ||M||_max = max |M_ij| over the stored entries (0 for an empty M); no densifying.
  double max_abs_entry() const;
  /// Empty when usable; otherwise a message naming what is wrong (sizes, non-finite entries).
  std::string validate() const;
};

/// Box-constrained LCP (a linear MCP): l <= z <= u, w = M z + q, with
///   z_i = l_i => w_i >= 0,  z_i = u_i => w_i <= 0,  l_i < z_i < u_i => w_i = 0.
/// Bounds may be infinite; l_i = -inf, u_i = +inf makes z_i free (w_i = 0).
struct BoxLcpProblem {
  LcpProblem lcp;  ///< M, q (and storage); its complementarity is replaced by the box rule
  Vec lower;       ///< l (entries may be -inf)
  Vec upper;       ///< u (entries may be +inf), l <= u
  Eigen::Index size() const noexcept { return lcp.size(); }
  std::string validate() const;
};

/// F(x) into F. Return false when x is outside F's domain (F is then ignored), e.g. a negative
/// base under a fractional power. Non-finite entries in F are treated the same way.
using FunctionCallback = std::function<bool(const Vec& x, Vec& F)>;
/// Dense Jacobian dF/dx (n x n) into J; false outside the domain.
using JacobianCallback = std::function<bool(const Vec& x, Mat& J)>;
/// Sparse Jacobian dF/dx into J; false outside the domain.
using SparseJacobianCallback = std::function<bool(const Vec& x, SparseMat& J)>;

/// Mixed complementarity problem MCP(F, l, u):
///   x_i = l_i => F_i(x) >= 0,  x_i = u_i => F_i(x) <= 0,  l_i < x_i < u_i => F_i(x) = 0.
/// An NCP is l = 0, u = +inf (see make_ncp). Without a Jacobian callback, solvers use finite
/// differences (documented by each solver).
struct McpProblem {
  Eigen::Index n = 0;
  FunctionCallback F;
  JacobianCallback jacobian;                ///< optional (dense)
  SparseJacobianCallback sparse_jacobian;   ///< optional (sparse); preferred when set
  Vec lower;                                ///< size n, entries may be -inf
  Vec upper;                                ///< size n, entries may be +inf
  Vec x0;                                   ///< optional starting point (size n or empty)
  std::string name;
  std::string note;

  Eigen::Index size() const noexcept { return n; }
  bool is_ncp() const;  ///< l == 0 and u == +inf
  std::string validate() const;
};

/// NCP(F): x >= 0, F(x) >= 0, x . F(x) = 0, as an McpProblem with l = 0, u = +inf.
McpProblem make_ncp(Eigen::Index n, FunctionCallback F, JacobianCallback J = {},
                    std::string name = {});
/// The LCP as an NCP with F(z) = M z + q (exact Jacobian M; sparse when the LCP is sparse).
McpProblem lcp_as_mcp(const LcpProblem& lcp);
/// The box LCP as an MCP with F(z) = M z + q.
McpProblem box_lcp_as_mcp(const BoxLcpProblem& box);

}  // namespace cpkit
