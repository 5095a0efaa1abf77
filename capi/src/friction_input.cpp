#include "friction_input.hpp"

#include <cmath>
#include <string>

#include "c_boundary.hpp"
#include "finite_check.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/core/number_text.hpp"

namespace cpkit::capi {

bool valid_mu(const double* mu, int contacts) {
  for (int i = 0; i < contacts; ++i)
    if (!(std::isfinite(mu[i]) && mu[i] >= 0)) return false;
  return true;
}

void check_mu(const double* mu, int contacts, const std::string& what) {
  for (int i = 0; i < contacts; ++i)
    if (!(std::isfinite(mu[i]) && mu[i] >= 0))
      throw InputError(what + "[" + std::to_string(i) + "] must be a finite number >= 0, got " +
                       num_text(mu[i]));
}

void check_friction_input(int contacts, int nnz, const int* col_ptr, const int* row_index,
                          const double* values, const double* q, const double* mu) {
  check_positive(contacts, "contacts");
  if (contacts > (1 << 28)) throw InputError("contacts is too large: " + std::to_string(contacts));
  const int m = 3 * contacts;
  if (nnz < 0) throw InputError("nnz must be >= 0, got " + std::to_string(nnz));
  require(col_ptr, "col_ptr");
  require(q, "q");
  require(mu, "mu");
  if (nnz > 0) {
    require(row_index, "row_index");
    require(values, "values");
  }
  if (col_ptr[0] != 0)
    throw InputError("col_ptr[0] must be 0 (0-based compressed columns), got " +
                     std::to_string(col_ptr[0]));
  for (int j = 0; j < m; ++j) {
    if (col_ptr[j + 1] < col_ptr[j] || col_ptr[j + 1] > nnz)
      throw InputError("col_ptr must be non-decreasing from 0 to nnz = " + std::to_string(nnz) +
                       "; col_ptr[" + std::to_string(j + 1) + "] = " +
                       std::to_string(col_ptr[j + 1]));
    for (int k = col_ptr[j]; k < col_ptr[j + 1]; ++k) {
      if (row_index[k] < 0 || row_index[k] >= m)
        throw InputError("row_index[" + std::to_string(k) + "] = " + std::to_string(row_index[k]) +
                         " is outside 0.." + std::to_string(m - 1) + " (W is 3 contacts = " +
                         std::to_string(m) + " square, 0-based)");
      if (k > col_ptr[j] && row_index[k] <= row_index[k - 1])
        throw InputError("row_index must increase within each column (no duplicates); column " +
                         std::to_string(j) + " has " + std::to_string(row_index[k - 1]) +
                         " then " + std::to_string(row_index[k]));
    }
  }
  if (col_ptr[m] != nnz)
    throw InputError("col_ptr[3 contacts] = " + std::to_string(col_ptr[m]) +
                     " must equal nnz = " + std::to_string(nnz));
  if (nnz > 0) check_finite(values, nnz, "values");
  check_finite(q, m, "q");
  check_mu(mu, contacts, "mu");
}

void map_friction_problem(int contacts, int nnz, const int* col_ptr, const int* row_index,
                          const double* values, const double* q, const double* mu,
                          FrictionContactProblem& p) {
  check_friction_input(contacts, nnz, col_ptr, row_index, values, q, mu);
  const int m = 3 * contacts;
  p.W = Eigen::Map<const Eigen::SparseMatrix<double, Eigen::ColMajor, int>>(m, m, nnz, col_ptr,
                                                                           row_index, values);
  p.q = Eigen::Map<const Eigen::VectorXd>(q, m);
  p.mu = Eigen::Map<const Eigen::VectorXd>(mu, contacts);
}

void read_one_contact(const int* col_ptr, const int* row_index, const double* values,
                      OneContact& c) {
  c.W.setZero();
  c.stored[0] = c.stored[1] = c.stored[2] = 0;
  for (int j = 0; j < 3; ++j)
    for (int k = col_ptr[j]; k < col_ptr[j + 1]; ++k) {
      c.W(row_index[k], j) = values[k];
      ++c.stored[row_index[k]];
    }
}

void read_one_contact_dense(const double* W, OneContact& c) {
  c.W = Eigen::Map<const Mat3>(W);
  for (int i = 0; i < 3; ++i)  // map_dense_friction_problem() stores the nonzeros only
    c.stored[i] = (W[i] != 0) + (W[i + 3] != 0) + (W[i + 6] != 0);
}

void map_dense_friction_problem(int contacts, const double* W, const double* q, const double* mu,
                                FrictionContactProblem& p) {
  const int m = 3 * contacts;
  p.W = Eigen::Map<const Eigen::MatrixXd>(W, m, m).sparseView(1.0, 0.0);
  p.q = Eigen::Map<const Eigen::VectorXd>(q, m);
  p.mu = Eigen::Map<const Eigen::VectorXd>(mu, contacts);
}

}  // namespace cpkit::capi
