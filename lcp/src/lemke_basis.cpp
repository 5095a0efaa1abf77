#include "lemke_basis.hpp"

#include <algorithm>
#include <cmath>

namespace cpkit::lcp::detail {

LemkeBasis::LemkeBasis(const Mat& M, const Vec& q, LemkeBasisStorage* storage)
    : M_(M),
      q_(q),
      n_(q.size()),
      s_(storage != nullptr ? *storage : own_),
      c_(s_.c),
      hinv_(s_.hinv),
      xz_(s_.xz),
      w_(s_.w),
      zcols_(s_.zcols),
      rrows_(s_.rrows),
      zpos_(s_.zpos),
      rpos_(s_.rpos),
      gz_(s_.gz),
      x_(s_.x),
      tmp_(s_.tmp),
      tmp2_(s_.tmp2) {
  // resize/assign keep the storage when the size repeats; hinv_, gz_ and the workspaces are
  // written before they are read (only their leading k columns/entries are used).
  c_.setOnes(n_);
  hinv_.resize(n_, n_);
  xz_.setZero(n_ + 1);
  w_ = q;
  zcols_.assign(static_cast<size_t>(n_ + 1), -1);
  rrows_.assign(static_cast<size_t>(n_ + 1), -1);
  zpos_.assign(static_cast<size_t>(n_ + 1), -1);
  rpos_.assign(static_cast<size_t>(n_), -1);
  gz_.resize(n_, n_);
  tmp_.resize(n_ + 1);
  tmp2_.resize(n_ + 1);
}

bool LemkeBasis::reset(const std::vector<int>& zset) {
  std::fill(zpos_.begin(), zpos_.end(), -1);
  std::fill(rpos_.begin(), rpos_.end(), -1);
  k_ = static_cast<int>(zset.size());
  for (int p = 0; p < k_; ++p) {
    const int j = zset[static_cast<size_t>(p)];
    zcols_[static_cast<size_t>(p)] = j;
    rrows_[static_cast<size_t>(p)] = j;
    zpos_[static_cast<size_t>(j)] = p;
    rpos_[static_cast<size_t>(j)] = p;
    gz_.col(p) = Eigen::Map<const Vec>(gcol(j), n_);
  }
  if (!refactor()) return false;
  recompute_values();
  return true;
}

bool LemkeBasis::refactor() {
  if (k_ == 0) return true;
  Mat h(k_, k_);
  for (int t = 0; t < k_; ++t) h.row(t) = gz_.row(rrows_[static_cast<size_t>(t)]).head(k_);
  const Eigen::PartialPivLU<Mat> lu(h);
  const double rc = lu.rcond();
  if (!(rc > 1e-14) || !std::isfinite(rc)) return false;
  hinv_.topLeftCorner(k_, k_) = lu.inverse();
  if (!hinv_.topLeftCorner(k_, k_).allFinite()) return false;
  if (x_on_) compute_x();
  return true;
}

void LemkeBasis::compute_x() {
  const Eigen::Index k = k_;
  if (k == 0) return;
  x_.leftCols(k).noalias() = gz_.leftCols(k) * hinv_.topLeftCorner(k, k);
  // Rows of R are exactly unit rows (H H^{-1} = I); the updates keep them so.
  for (int t = 0; t < k_; ++t) {
    x_.row(rrows_[static_cast<size_t>(t)]).head(k).setZero();
    x_(rrows_[static_cast<size_t>(t)], t) = 1.0;
  }
}

void LemkeBasis::enable_lexico_rows() {
  if (x_on_) return;
  x_.resize(n_, n_ + 1);
  x_on_ = true;
  compute_x();
}

double LemkeBasis::inverse_entry(int var, Eigen::Index j) const {
  const int t = rpos(j);
  if (t < 0) return var == n_ + 1 + j ? 1.0 : 0.0;
  if (var <= n_) return -hinv_(zpos(var), t);
  return -x_(var - n_ - 1, t);
}

void LemkeBasis::inverse_row_scales(int var, double& row_max, double& value_terms) const {
  row_max = 0.0;
  value_terms = 0.0;
  if (var <= n_) {
    const int p = zpos(var);
    for (int t = 0; t < k_; ++t) {
      const double h = std::abs(hinv_(p, t));
      row_max = std::max(row_max, h);
      value_terms += h * std::abs(q_[rrows_[static_cast<size_t>(t)]]);
    }
  } else {
    const Eigen::Index i = var - n_ - 1;
    row_max = 1.0;
    value_terms = std::abs(q_[i]);
    for (int t = 0; t < k_; ++t) {
      const double x = std::abs(x_(i, t));
      row_max = std::max(row_max, x);
      value_terms += x * std::abs(q_[rrows_[static_cast<size_t>(t)]]);
    }
  }
}

double LemkeBasis::rate_terms(int var, int entering, const Vec& dxz) const {
  double s = 0.0;
  if (var <= n_) {
    const int p = zpos(var);
    if (entering > n_) {
      // The rate is the entry H^{-1}(p, pj) itself, whose rounding (from the updates of
      // H^{-1}) is relative to its row, not to the entry: |dxz[p]| as its own scale let a
      // rate of 3e-16 (0 in exact arithmetic) pivot and derailed the path (issue 24, item 7).
      (void)dxz;
      double row_max = 0;
      for (int t = 0; t < k_; ++t) row_max = std::max(row_max, std::abs(hinv_(p, t)));
      return row_max;
    }
    const double* col = gcol(entering);
    for (int t = 0; t < k_; ++t)
      s += std::abs(hinv_(p, t)) * std::abs(col[rrows_[static_cast<size_t>(t)]]);
    return s;
  }
  const Eigen::Index i = var - n_ - 1;
  if (entering <= n_) s = std::abs(gcol(entering)[i]);
  for (int p = 0; p < k_; ++p) {
    // When a w enters, dxz is a column of H^{-1}: its entries are rounded relative to their
    // rows (as above), O(k) each; reached only when the cheap bound of the caller fails.
    double d = std::abs(dxz[p]);
    if (entering > n_ && gz_(i, p) != 0.0)
      for (int t = 0; t < k_; ++t) d = std::max(d, std::abs(hinv_(p, t)));
    s += std::abs(gz_(i, p)) * d;
  }
  return s;
}

void LemkeBasis::recompute_values() {
  const Eigen::Index k = k_;
  // x_Z = -H^{-1} q_R, then one refinement step r = H x_Z + q_R, x_Z -= H^{-1} r.
  for (int t = 0; t < k_; ++t) tmp_[t] = q_[rrows_[static_cast<size_t>(t)]];
  xz_.head(k).noalias() = -hinv_.topLeftCorner(k, k) * tmp_.head(k);
  for (int t = 0; t < k_; ++t)
    tmp_[t] = gz_.row(rrows_[static_cast<size_t>(t)]).head(k).dot(xz_.head(k)) +
              q_[rrows_[static_cast<size_t>(t)]];
  xz_.head(k).noalias() -= hinv_.topLeftCorner(k, k) * tmp_.head(k);
  w_ = q_;
  w_.noalias() += gz_.leftCols(k) * xz_.head(k);
  for (int t = 0; t < k_; ++t) w_[rrows_[static_cast<size_t>(t)]] = 0.0;
}

double LemkeBasis::hinv_quality() {
  if (k_ == 0) return 0.0;
  const Eigen::Index k = k_;
  double worst = 0.0;
  // Two probes b: q_R (the values the method uses) and all ones (every column of H^{-1}).
  // With x = H^{-1} b, the componentwise backward error |H x - b|_t / (|H| |x| + |b|)_t.
  for (int probe = 0; probe < 2; ++probe) {
    for (int t = 0; t < k_; ++t) tmp_[t] = probe == 0 ? q_[rrows_[static_cast<size_t>(t)]] : 1.0;
    tmp2_.head(k).noalias() = hinv_.topLeftCorner(k, k) * tmp_.head(k);
    for (int t = 0; t < k_; ++t) {
      const auto row = gz_.row(rrows_[static_cast<size_t>(t)]).head(k);
      const double r = row.dot(tmp2_.head(k)) - tmp_[t];
      const double s = row.cwiseAbs().dot(tmp2_.head(k).cwiseAbs()) + std::abs(tmp_[t]);
      if (!std::isfinite(r)) return INFINITY;
      if (s > 0) worst = std::max(worst, std::abs(r) / s);
    }
  }
  return worst;
}

void LemkeBasis::direction(int var, Vec& dxz, Vec& dw) {
  const Eigen::Index k = k_;
  if (var <= n_) {
    const double* col = gcol(var);
    for (int t = 0; t < k_; ++t) tmp_[t] = col[rrows_[static_cast<size_t>(t)]];
    dxz.head(k).noalias() = -hinv_.topLeftCorner(k, k) * tmp_.head(k);
    dw = Eigen::Map<const Vec>(col, n_);
  } else {
    const int pj = rpos(var - n_ - 1);
    dxz.head(k) = hinv_.col(pj).head(k);
    dw.setZero();
  }
  dw.noalias() += gz_.leftCols(k) * dxz.head(k);
  // Rows of R: w stays nonbasic (0 in exact arithmetic; the X update relies on exact zeros).
  for (int t = 0; t < k_; ++t) dw[rrows_[static_cast<size_t>(t)]] = 0.0;
}

void LemkeBasis::inverse_row(int var, Vec& out) {
  const Eigen::Index k = k_;
  out.setZero();
  if (var <= n_) {
    const int p = zpos(var);
    for (int t = 0; t < k_; ++t) out[rrows_[static_cast<size_t>(t)]] = -hinv_(p, t);
  } else if (x_on_) {
    const Eigen::Index i = var - n_ - 1;
    out[i] = 1.0;
    for (int t = 0; t < k_; ++t) out[rrows_[static_cast<size_t>(t)]] = -x_(i, t);
  } else {
    const Eigen::Index i = var - n_ - 1;
    tmp_.head(k) = gz_.row(i).head(k).transpose();
    tmp2_.head(k).noalias() = hinv_.topLeftCorner(k, k).transpose() * tmp_.head(k);
    out[i] = 1.0;
    for (int t = 0; t < k_; ++t) out[rrows_[static_cast<size_t>(t)]] -= tmp2_[t];
  }
}

void LemkeBasis::pivot(int entering, int leaving, double t, const Vec& dxz, const Vec& dw) {
  const Eigen::Index k = k_;
  xz_.head(k) += t * dxz.head(k);
  w_ += t * dw;
  auto H = hinv_.topLeftCorner(k, k);
  if (entering <= n_ && leaving > n_) {
    // z_j enters, w_r leaves: H grows by row r and column j (bordering).
    const Eigen::Index r = leaving - n_ - 1;
    const double s = dw[r];  // = G(r, j) + G(r, Z) dxz, the Schur complement
    if (x_on_) {
      tmp2_.head(k) = x_.row(r).head(k).transpose();  // X(r, :) = (H^{-T} g)^T
    } else {
      tmp_.head(k) = gz_.row(r).head(k).transpose();
      tmp2_.head(k).noalias() = H.transpose() * tmp_.head(k);  // v = H^{-T} g
    }
    tmp2_.head(k) /= s;
    if (x_on_) {
      // X' = [X - dw v^T, dw / s]; row r becomes the unit row of the new position k.
      x_.leftCols(k).noalias() -= dw * tmp2_.head(k).transpose();
      x_.col(k) = dw / s;
      x_.row(r).head(k + 1).setZero();
      x_(r, k) = 1.0;
    }
    H.noalias() -= dxz.head(k) * tmp2_.head(k).transpose();
    hinv_.col(k).head(k) = dxz.head(k) / s;
    hinv_.row(k).head(k) = -tmp2_.head(k).transpose();
    hinv_(k, k) = 1.0 / s;
    zcols_[static_cast<size_t>(k)] = entering;
    rrows_[static_cast<size_t>(k)] = static_cast<int>(r);
    zpos_[static_cast<size_t>(entering)] = k_;
    rpos_[static_cast<size_t>(r)] = k_;
    gz_.col(k) = Eigen::Map<const Vec>(gcol(entering), n_);
    xz_[k] = t;
    w_[r] = 0.0;
    ++k_;
  } else if (entering <= n_) {
    // z_j enters, x_l leaves: column p of H replaced (Sherman-Morrison).
    const int p = zpos(leaving);
    const double up = -dxz[p];
    tmp_.head(k) = hinv_.row(p).head(k).transpose() / up;
    H.noalias() += dxz.head(k) * tmp_.head(k).transpose();
    if (x_on_) x_.leftCols(k).noalias() += dw * tmp_.head(k).transpose();
    hinv_.row(p).head(k) = tmp_.head(k).transpose();
    zcols_[static_cast<size_t>(p)] = entering;
    zpos_[static_cast<size_t>(entering)] = p;
    zpos_[static_cast<size_t>(leaving)] = -1;
    gz_.col(p) = Eigen::Map<const Vec>(gcol(entering), n_);
    xz_[p] = t;
  } else if (leaving > n_) {
    // w_j enters, w_r leaves: row pj of H replaced by G(r, Z).
    const Eigen::Index j = entering - n_ - 1;
    const Eigen::Index r = leaving - n_ - 1;
    const int pj = rpos(j);
    if (x_on_) {
      tmp2_.head(k) = x_.row(r).head(k).transpose();  // X(r, :) = (H^{-T} g)^T
      // u = X(r, :) / s with s = X(r, pj) = dw_r: X' = X - dw u^T on the rows of W, column pj
      // (now equation r) = dw / s; row j (w_j now basic) = -u with 1 / s at pj; row r = unit.
      const double s = tmp2_[pj];
      tmp_.head(k) = tmp2_.head(k) / s;
      x_.leftCols(k).noalias() -= dw * tmp_.head(k).transpose();
      x_.col(pj) = dw / s;
      x_.row(j).head(k) = -tmp_.head(k).transpose();
      x_(j, pj) = 1.0 / s;
      x_.row(r).head(k).setZero();
      x_(r, pj) = 1.0;
    } else {
      tmp_.head(k) = gz_.row(r).head(k).transpose();
      tmp2_.head(k).noalias() = H.transpose() * tmp_.head(k);
    }
    const double den = tmp2_[pj];
    tmp2_[pj] -= 1.0;
    tmp2_.head(k) /= den;
    H.noalias() -= dxz.head(k) * tmp2_.head(k).transpose();
    rrows_[static_cast<size_t>(pj)] = static_cast<int>(r);
    rpos_[static_cast<size_t>(r)] = pj;
    rpos_[static_cast<size_t>(j)] = -1;
    w_[j] = t;
    w_[r] = 0.0;
  } else {
    // w_j enters, x_l leaves: H loses row pj and column p (Schur complement in H^{-1}).
    const Eigen::Index j = entering - n_ - 1;
    const int pj = rpos(j);
    const int p = zpos(leaving);
    const double piv = hinv_(p, pj);
    tmp_.head(k) = hinv_.row(p).head(k).transpose() / piv;
    H.noalias() -= dxz.head(k) * tmp_.head(k).transpose();
    if (x_on_) {
      // X' = X - dw tmp^T on the rows of W; row j (w_j now basic) = -tmp; column pj removed.
      x_.leftCols(k).noalias() -= dw * tmp_.head(k).transpose();
      x_.row(j).head(k) = -tmp_.head(k).transpose();
      if (pj != k_ - 1) x_.col(pj) = x_.col(k_ - 1);
    }
    const int last = k_ - 1;
    zpos_[static_cast<size_t>(leaving)] = -1;
    rpos_[static_cast<size_t>(j)] = -1;
    if (p != last) {
      hinv_.row(p).head(k) = hinv_.row(last).head(k);
      const int moved = zcols_[static_cast<size_t>(last)];
      zcols_[static_cast<size_t>(p)] = moved;
      zpos_[static_cast<size_t>(moved)] = p;
      gz_.col(p) = gz_.col(last);
      xz_[p] = xz_[last];
    }
    if (pj != last) {
      hinv_.col(pj).head(last) = hinv_.col(last).head(last);
      const int moved = rrows_[static_cast<size_t>(last)];
      rrows_[static_cast<size_t>(pj)] = moved;
      rpos_[static_cast<size_t>(moved)] = pj;
    }
    w_[j] = t;
    --k_;
  }
  for (int s = 0; s < k_; ++s) w_[rrows_[static_cast<size_t>(s)]] = 0.0;
}

void LemkeBasis::current_point(Vec& z, double& z0) const {
  z.setZero(n_);
  z0 = 0.0;
  for (int p = 0; p < k_; ++p) {
    const int j = zcols_[static_cast<size_t>(p)];
    if (j < n_) z[j] = xz_[p];
    else z0 = xz_[p];
  }
}

}  // namespace cpkit::lcp::detail
