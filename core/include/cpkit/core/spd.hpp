#pragma once
/// \file spd.hpp
/// Is a stiffness matrix symmetric positive definite? Judged scale-free: the matrix is first
/// scaled by a power of two (exact) that brings its largest entry to [1, 2), so that the same
/// matrix in other units (x 1e-300 or x 1e300) gets the same verdict, where an unscaled Cholesky
/// factorisation overflows (entries near 1e300: their squares) or underflows (near 1e-300).
#include <cmath>
#include <sstream>
#include <string>

#include <Eigen/Cholesky>
#include <Eigen/Core>

namespace cpkit {

/// The verdict of check_spd; `message` is empty when the matrix passes.
struct SpdVerdict {
  std::string message;  ///< "A is not symmetric", "A is not positive definite", ...
  double rcond = 0;     ///< reciprocal condition estimate of the (scaled, symmetrised) matrix
};

/// Checks that `A` (square) is finite, symmetric to `sym_tol` relative to its largest entry, and
/// positive definite with a reciprocal condition estimate above `rcond_min` (Cholesky on the
/// scaled, symmetrised matrix). `name` starts the messages.
template <class Derived>
SpdVerdict check_spd(const Eigen::MatrixBase<Derived>& A, double sym_tol, double rcond_min,
                     const std::string& name = "A") {
  using Square = Eigen::Matrix<double, Derived::RowsAtCompileTime, Derived::ColsAtCompileTime>;
  SpdVerdict v;
  if (A.rows() != A.cols() || A.size() == 0) {
    v.message = name + " must be square and not empty";
    return v;
  }
  if (!A.allFinite()) {
    v.message = name + " has a NaN or infinite entry";
    return v;
  }
  const double amax = A.cwiseAbs().maxCoeff();
  if (!(amax > 0)) {
    v.message = name + " is not positive definite (it is zero)";
    return v;
  }
  const Square B = std::ldexp(1.0, -std::ilogb(amax)) * A;  // exact: a power of two
  if ((B - B.transpose()).cwiseAbs().maxCoeff() > sym_tol * B.cwiseAbs().maxCoeff()) {
    v.message = name + " is not symmetric";
    return v;
  }
  const Square S = (0.5 * (B + B.transpose())).eval();
  const Eigen::LLT<Square> llt(S);
  if (llt.info() != Eigen::Success) {
    v.message = name + " is not positive definite (Cholesky factorisation failed)";
    return v;
  }
  v.rcond = llt.rcond();
  if (!(v.rcond > rcond_min)) {
    std::ostringstream m;
    m << name << " is numerically singular (reciprocal condition number estimate " << v.rcond << ")";
    v.message = m.str();
  }
  return v;
}

/// A symmetrised: (A + A^T) / 2 without aliasing (A = 0.5 * A + 0.5 * A.transpose() would read
/// entries it has already overwritten) and without overflow near the largest double.
template <class Derived>
void symmetrize(Eigen::MatrixBase<Derived>& A) {
  A = (0.5 * A + 0.5 * A.transpose()).eval();
}

}  // namespace cpkit
