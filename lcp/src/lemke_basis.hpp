#pragma once
/// \file lemke_basis.hpp
/// Private to cpkit::lcp: the basis of Lemke's method in block form.
///
/// System (cpkit convention, with the artificial column c for z0):
///   w = G x + q,  G = [M | c]  (n x (n+1)),  x = (z_0..z_{n-1}, z0),  w, x >= 0.
/// A basis has the basic w_i for i in W, and k basic x_j for j in Z (z0 included when basic);
/// R is the complement of W (the rows where w is nonbasic), |R| = |Z| = k. With
/// H = G(R, Z) (k x k) the basic values are
///   x_Z = -H^{-1} q_R,   w_W = q_W + G(W, Z) x_Z,
/// so only H^{-1} is maintained (explicit k x k, updated by rank-one / bordering formulas, and
/// recomputed from the data when a residual check fails). Work per pivot: O(n k + k^2) instead
/// of the O(n^2) of a full basis inverse [Cottle-Pang-Stone 1992, Sec. 4.4 for the method].
///
/// Basis inverse B^{-1} of the system I w - G x = q (rows: basic variables, columns: the
/// equations 0..n-1): the row of the basic x at Z position p is -H^{-1}(p, :) on the columns R
/// (0 on W); the row of a basic w_i is e_i - X(i, :) on R, with X = G(:, Z) H^{-1} (n x k).
/// X is needed only by the lexicographic tie-break; it is built on the first tie
/// (enable_lexico_rows(), O(n k^2)) and from then on updated at every pivot (O(n k)), so
/// problems without ties never pay for it.
///
/// Variable ids: 0..n-1 = z_i, n = z0, n+1+i = w_i.
#include <vector>

#include <Eigen/Dense>

namespace cpkit::lcp::detail {

using Vec = Eigen::VectorXd;
using Mat = Eigen::MatrixXd;

/// The arrays of a LemkeBasis. A caller that solves many problems keeps one and passes it to
/// each basis: the arrays are resized, not reallocated, when n repeats (no allocation per call
/// for small problems, issue 27). Every entry that is read is set by the basis first.
struct LemkeBasisStorage {
  Vec c, xz, w, tmp, tmp2;
  Mat hinv, gz, x;
  std::vector<int> zcols, rrows, zpos, rpos;
};

class LemkeBasis {
 public:
  /// M (n x n, column-major, not owned: must outlive the basis) and q (not owned). `storage`:
  /// the arrays to use (not owned, one basis at a time); nullptr: the basis owns its arrays.
  LemkeBasis(const Mat& M, const Vec& q, LemkeBasisStorage* storage = nullptr);
  LemkeBasis(const LemkeBasis&) = delete;
  LemkeBasis& operator=(const LemkeBasis&) = delete;

  Eigen::Index n() const { return n_; }
  const Mat& matrix() const { return M_; }
  int k() const { return k_; }

  /// Sets the z0 column c (size n).
  void set_artificial_column(const Vec& c) { c_ = c; }
  const Vec& artificial_column() const { return c_; }

  /// G(i, j) for j in 0..n (j = n: the artificial column).
  double g(Eigen::Index i, int j) const { return j < n_ ? M_(i, j) : c_[i]; }
  const double* gcol(int j) const { return j < n_ ? M_.data() + j * n_ : c_.data(); }

  /// Sets a complementary basis with basic z_j for j in `zset` (R = zset), computes H^{-1}
  /// from the data. Returns false when H = M(zset, zset) is singular.
  bool reset(const std::vector<int>& zset);

  /// Recomputes H^{-1} from the data (LU with full pivoting). False when H is singular.
  bool refactor();
  /// Recomputes the basic values from the data with one step of iterative refinement.
  void recompute_values();
  /// Accuracy of H^{-1}: for the probes b = q_R and b = ones, x = H^{-1} b, the largest
  /// componentwise backward error |H x - b|_t / (|H| |x| + |b|)_t (O(k^2), no allocation).
  double hinv_quality();

  /// Basic values: xz(p) for the p-th basic x (zcols()[p]); w(i) for i in W (0 for i in R).
  const Vec& xz() const { return xz_; }
  const Vec& w() const { return w_; }
  const std::vector<int>& zcols() const { return zcols_; }
  const std::vector<int>& rrows() const { return rrows_; }
  /// Position of x_j in Z (-1 when nonbasic), position of row i in R (-1: w_i basic).
  int zpos(int j) const { return zpos_[static_cast<size_t>(j)]; }
  int rpos(Eigen::Index i) const { return rpos_[static_cast<size_t>(i)]; }
  bool is_basic(int var) const {
    return var <= n_ ? zpos(var) >= 0 : rpos(var - n_ - 1) < 0;
  }

  /// Direction of the basic values when the nonbasic variable `var` increases at unit rate:
  /// dxz (by Z position) and dw (every row; meaningful on W).
  void direction(int var, Vec& dxz, Vec& dw);

  /// Row of the basis inverse B^{-1} (system I w - G x = q, equation order 0..n-1) of the basic
  /// variable `var`, into out (size n). O(n k) (O(n) once enable_lexico_rows() was called).
  void inverse_row(int var, Vec& out);

  /// Builds X = G(:, Z) H^{-1} and keeps it updated from now on (see the file comment).
  void enable_lexico_rows();
  bool lexico_rows_enabled() const { return x_on_; }
  /// B^{-1}(var, j) for a basic `var` (needs enable_lexico_rows() for a basic w). O(1).
  double inverse_entry(int var, Eigen::Index j) const;
  /// max_j |B^{-1}(var, j)| and sum_j |B^{-1}(var, j)| |q_j| (the size of the terms of the
  /// value of `var` = B^{-1}(var, :) q). O(k); needs enable_lexico_rows() for a basic w.
  void inverse_row_scales(int var, double& row_max, double& value_terms) const;
  /// Size of the terms of the rate of basic `var` in the last direction(`entering`):
  /// sum |H^{-1}(p, :)| |G(R, entering)| for an x (when a w enters, the rate is the entry
  /// H^{-1}(p, pj), rounded relative to its row: max_t |H^{-1}(p, t)|), |G(i, entering)| +
  /// |G(i, Z)| |dxz| for a w.
  /// O(k). Used to tell a pivot entry from rounding noise.
  double rate_terms(int var, int entering, const Vec& dxz) const;

  /// Pivot: `entering` becomes basic at value t, `leaving` leaves; dxz/dw from direction().
  void pivot(int entering, int leaving, double t, const Vec& dxz, const Vec& dw);

  /// z (size n) of the current basic solution, z0 (0 when nonbasic).
  void current_point(Vec& z, double& z0) const;

 private:
  void compute_x();  // X = G(:, Z) H^{-1} from the current H^{-1}

  const Mat& M_;
  const Vec& q_;
  Eigen::Index n_;
  LemkeBasisStorage own_;  // used when no storage is given
  LemkeBasisStorage& s_;
  Vec& c_;
  int k_ = 0;
  Mat& hinv_;             // top-left k x k block is H^{-1}
  Vec &xz_, &w_;          // basic values
  std::vector<int> &zcols_, &rrows_, &zpos_, &rpos_;
  Mat& gz_;               // column p = G(:, zcols_[p]) (contiguous copy for gemv)
  Mat& x_;                // X = G(:, Z) H^{-1} (n x k) when x_on_ (rows of R: unit rows)
  bool x_on_ = false;
  Vec &tmp_, &tmp2_;      // workspaces (size n + 1)
};

}  // namespace cpkit::lcp::detail
