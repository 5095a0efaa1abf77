#pragma once
// A friction problem given through cpkit.h (W in compressed sparse columns, or dense for the
// batched call) checked and mapped into the library's FrictionContactProblem.
#include <string>

#include "cpkit/core/friction_cone.hpp"
#include "cpkit/core/friction_problem.hpp"

namespace cpkit::capi {

/// The checks of map_friction_problem() alone (nothing mapped): InputError naming the argument.
void check_friction_input(int contacts, int nnz, const int* col_ptr, const int* row_index,
                          const double* values, const double* q, const double* mu);

/// Checks contacts >= 1, the pointers, the CSC structure of W (col_ptr from 0 to nnz,
/// non-decreasing; row indices in range and increasing within a column), finite values, q and
/// mu (each finite and >= 0): InputError naming the argument. Then p = (W, q, mu).
void map_friction_problem(int contacts, int nnz, const int* col_ptr, const int* row_index,
                          const double* values, const double* q, const double* mu,
                          FrictionContactProblem& p);

/// The same for a dense W (m x m, column-major, m = 3 contacts; already checked finite):
/// W's exact zeros are not stored.
void map_dense_friction_problem(int contacts, const double* W, const double* q, const double* mu,
                                FrictionContactProblem& p);

/// One contact's W as a dense 3 x 3 block, with the number of entries each row stores (the
/// verdict's rounding allowance counts them: one_contact_unit_free()).
struct OneContact {
  Mat3 W;
  int stored[3];
};
/// W of one contact from checked compressed columns (check_friction_input(1, ...)).
void read_one_contact(const int* col_ptr, const int* row_index, const double* values,
                      OneContact& c);
/// W of one contact from a dense column-major 3 x 3 array, stored as
/// map_dense_friction_problem() stores it (its nonzeros).
void read_one_contact_dense(const double* W, OneContact& c);

/// InputError unless every mu[i] is finite and >= 0 (`what`: "mu", "mu of problem k").
void check_mu(const double* mu, int contacts, const std::string& what);
/// True when every mu[i] is finite and >= 0.
bool valid_mu(const double* mu, int contacts);

}  // namespace cpkit::capi
