#pragma once
// Private to fb_newton.cpp (included there only, so the code stays in its one translation unit):
// the two linear-algebra back ends of the FB Newton driver, dense LU (LAPACK or Eigen, chosen by
// size) and sparse LU, each solving H d = rhs with H = diag(Da) + diag(Db) J.
#include <Eigen/LU>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "cpkit/core/problem.hpp"

#ifdef CPKIT_HAVE_LAPACK
// LAPACK's LU factorization (Debian's liblapack3; OpenBLAS when it provides the alternative).
extern "C" void dgetrf_(const int* m, const int* n, double* a, const int* lda, int* ipiv,
                        int* info);
#endif

namespace cpkit::lcp {
namespace {

constexpr double kAlgebraEps = std::numeric_limits<double>::epsilon();
/// Dense LU by LAPACK's dgetrf (when cpkit was built with LAPACK) or Eigen's PartialPivLU,
/// chosen by size from measurements against Debian's OpenBLAS (docs/benchmarks/fb_newton.md):
/// Eigen below 32 (call overhead dominates) and for 100 <= n < 150, where OpenBLAS switches to
/// multi-threaded factorization (n^2 >= 10^4) and loses more than it gains on a shared 2-core
/// machine; LAPACK otherwise (vectorized single-threaded kernels below 100, blocked
/// multi-threaded ones from 150).
constexpr bool use_lapack_lu(Eigen::Index n) { return n >= 32 && (n < 100 || n >= 150); }

/// Dense: J (n x n) from M, a dense Jacobian callback, or forward differences; H = diag(Da) +
/// diag(Db) J factorized by partial-pivoting LU.
struct DenseAlgebra {
  const Mat* J = nullptr;  // points at M (affine) or at J_own
  Mat J_own;
  Mat H;
  Eigen::PartialPivLU<Mat> lu;
  Vec fd_x, fd_F;  // finite-difference workspaces

  explicit DenseAlgebra(Eigen::Index n) : H(n, n), lu(n) {}

  void jz(const Vec& z, Vec& out) const { out.noalias() = *J * z; }
  /// grad Psi = H^T Phi = Da .* Phi + J^T (Db .* Phi); `tmp` a workspace.
  void grad(const Vec& Da, const Vec& Db, const Vec& Phi, Vec& tmp, Vec& g) const {
    tmp = Db.cwiseProduct(Phi);
    g.noalias() = J->transpose() * tmp;
    g += Da.cwiseProduct(Phi);
  }
  /// Solves H d = rhs; false when H is (numerically) singular or d is not finite.
  bool solve(const Vec& Da, const Vec& Db, const Vec& rhs, Vec& d) {
    H.noalias() = Db.asDiagonal() * *J;
    H.diagonal() += Da;
    const Eigen::Index n = H.rows();
#ifdef CPKIT_HAVE_LAPACK
    if (use_lapack_lu(n)) {
      // In place: H becomes L\U with row interchanges ipiv (1-based).
      const int nn = static_cast<int>(n);
      int info = 0;
      if (ipiv.size() != static_cast<size_t>(n)) ipiv.resize(static_cast<size_t>(n));
      dgetrf_(&nn, &nn, H.data(), &nn, ipiv.data(), &info);
      if (info < 0 || !pivots_ok(H.diagonal())) return false;
      d = rhs;
      for (Eigen::Index i = 0; i < n; ++i) std::swap(d[i], d[ipiv[static_cast<size_t>(i)] - 1]);
      H.triangularView<Eigen::UnitLower>().solveInPlace(d);
      H.triangularView<Eigen::Upper>().solveInPlace(d);
      return d.allFinite();
    }
#endif
    lu.compute(H);
    if (!pivots_ok(lu.matrixLU().diagonal())) return false;
    d.noalias() = lu.solve(rhs);
    return d.allFinite();
  }
  /// U's diagonal: every |u_ii| > n eps max |u_jj| (else H is treated as singular).
  template <class Diag>
  static bool pivots_ok(const Diag& u) {
    const double umax = u.cwiseAbs().maxCoeff();
    return umax > 0 && std::isfinite(umax) &&
           u.cwiseAbs().minCoeff() > umax * kAlgebraEps * static_cast<double>(u.size());
  }
  std::vector<int> ipiv;
};

/// Sparse: J from sparse M or a sparse Jacobian callback; H shares J's pattern plus the
/// diagonal, analysed once (re-analysed only when the callback changes the pattern).
struct SparseAlgebra {
  const SparseMat* J = nullptr;
  SparseMat J_own;
  SparseMat H;
  std::vector<Eigen::Index> diag_pos;  // position of H(j, j) in H's value array
  std::vector<Eigen::Index> j_pos;     // position in H of the k-th stored entry of J
  Eigen::SparseLU<SparseMat, Eigen::COLAMDOrdering<int>> lu;
  bool analysed = false;
  Eigen::Index pattern_nnz = -1;

  explicit SparseAlgebra(Eigen::Index /*n*/) {}

  void jz(const Vec& z, Vec& out) const { out.noalias() = *J * z; }
  void grad(const Vec& Da, const Vec& Db, const Vec& Phi, Vec& tmp, Vec& g) const {
    tmp = Db.cwiseProduct(Phi);
    g.noalias() = J->transpose() * tmp;
    g += Da.cwiseProduct(Phi);
  }
  // Builds H's pattern = pattern(J) + diagonal and the maps from J and the diagonal into it.
  void build_pattern() {
    const Eigen::Index n = J->rows();
    SparseMat I(n, n);
    I.setIdentity();
    H = *J + I;  // union of patterns (values rewritten below)
    H.makeCompressed();
    diag_pos.assign(static_cast<size_t>(n), -1);
    j_pos.assign(static_cast<size_t>(J->nonZeros()), -1);
    const auto* hout = H.outerIndexPtr();
    const auto* hin = H.innerIndexPtr();
    for (Eigen::Index c = 0; c < n; ++c) {
      for (auto k = hout[c]; k < hout[c + 1]; ++k)
        if (hin[k] == c) diag_pos[static_cast<size_t>(c)] = k;
    }
    Eigen::Index idx = 0;
    for (Eigen::Index c = 0; c < n; ++c) {
      auto hk = hout[c];
      for (SparseMat::InnerIterator it(*J, c); it; ++it, ++idx) {
        while (hin[hk] != it.row()) ++hk;
        j_pos[static_cast<size_t>(idx)] = hk;
      }
    }
    pattern_nnz = J->nonZeros();
    analysed = false;
  }
  bool solve(const Vec& Da, const Vec& Db, const Vec& rhs, Vec& d) {
    if (pattern_nnz != J->nonZeros() || H.rows() != J->rows()) build_pattern();
    if (symmetric && ldlt_usable && solve_symmetric(Da, Db, rhs, d)) return true;
    double* hv = H.valuePtr();
    std::fill(hv, hv + H.nonZeros(), 0.0);
    Eigen::Index idx = 0;
    for (Eigen::Index c = 0; c < J->outerSize(); ++c)
      for (SparseMat::InnerIterator it(*J, c); it; ++it, ++idx)
        hv[j_pos[static_cast<size_t>(idx)]] = Db[it.row()] * it.value();
    for (Eigen::Index c = 0; c < H.cols(); ++c) hv[diag_pos[static_cast<size_t>(c)]] += Da[c];
    if (!analysed) {
      lu.analyzePattern(H);
      analysed = true;
    }
    lu.factorize(H);
    if (lu.info() != Eigen::Success) return false;
    d = lu.solve(rhs);
    return lu.info() == Eigen::Success && d.allFinite();
  }

  /// Symmetric J (affine problems with M = M^T): H = diag(Db) K with K = J + diag(Da / Db)
  /// symmetric, so H d = rhs is K d = rhs ./ Db, solved by sparse LDL^T (AMD ordering), much
  /// cheaper than LU. Db_i = 0 (z_i = 0 < w_i) is replaced by 1e-30 Da_i, which changes d_i by a
  /// relative 1e-30. The solve is accepted only when ||H d - rhs|| is small; otherwise (e.g. an
  /// indefinite K where LDL^T without pivoting is unreliable) the LU path is used from then on.
  bool solve_symmetric(const Vec& Da, const Vec& Db, const Vec& rhs, Vec& d) {
    double* hv = H.valuePtr();
    std::fill(hv, hv + H.nonZeros(), 0.0);
    Eigen::Index idx = 0;
    for (Eigen::Index c = 0; c < J->outerSize(); ++c)
      for (SparseMat::InnerIterator it(*J, c); it; ++it, ++idx)
        hv[j_pos[static_cast<size_t>(idx)]] = it.value();
    db_safe.resize(Da.size());
    for (Eigen::Index c = 0; c < H.cols(); ++c) {
      db_safe[c] = std::max(Db[c], 1e-30 * Da[c]);
      if (!(db_safe[c] > 0)) return false;
      hv[diag_pos[static_cast<size_t>(c)]] += Da[c] / db_safe[c];
    }
    if (!ldlt_analysed) {
      ldlt.analyzePattern(H);
      ldlt_analysed = true;
    }
    ldlt.factorize(H);
    if (ldlt.info() != Eigen::Success) {
      ldlt_usable = false;
      return false;
    }
    scaled_rhs = rhs.cwiseQuotient(db_safe);
    d = ldlt.solve(scaled_rhs);
    if (ldlt.info() != Eigen::Success || !d.allFinite()) {
      ldlt_usable = false;
      return false;
    }
    // Residual check on the original system H d = rhs.
    check.noalias() = *J * d;
    check = check.cwiseProduct(Db) + Da.cwiseProduct(d) - rhs;
    if (!(check.lpNorm<Eigen::Infinity>() <=
          1e-8 * (rhs.lpNorm<Eigen::Infinity>() + std::numeric_limits<double>::min()))) {
      ldlt_usable = false;
      return false;
    }
    return true;
  }

  bool symmetric = false;  // J == J^T (set for affine problems)
  bool ldlt_usable = true;
  bool ldlt_analysed = false;
  Eigen::SimplicialLDLT<SparseMat, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt;
  Vec db_safe, scaled_rhs, check;
};

}  // namespace
}  // namespace cpkit::lcp
