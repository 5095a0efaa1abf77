#pragma once
// Siconos numerics' 3-D frictional contact problem over a copy of cpkit's (W, q, mu), with W in
// Siconos' sparse-block storage (NM_SPARSE_BLOCK: 3 x 3 blocks, block rows, as its own .dat
// reader builds it), so that a packing of 1e5 contacts needs no dense matrix. Only when CMake
// found Siconos (CPKIT_HAVE_SICONOS); its headers are not warning-clean.
#ifdef CPKIT_HAVE_SICONOS
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include "FrictionContactProblem.h"
#include "Friction_cst.h"
#include "NonSmoothDrivers.h"
#include "NumericsMatrix.h"
#include "SolverOptions.h"
#include "SparseBlockMatrix.h"
#include "fc3d_compute_error.h"
#pragma GCC diagnostic pop

#include <Eigen/SparseCore>
#include <algorithm>
#include <cfloat>
#include <cstdlib>
#include <vector>

#include "cpkit/core/friction_problem.hpp"

namespace cpkit::bench {

/// The problem in Siconos' structures; owns every array it points to (malloc'ed, as
/// SBM_clear frees them).
class SiconosFriction {
 public:
  explicit SiconosFriction(const FrictionContactProblem& p) : q_(p.q), mu_(p.mu) {
    const Eigen::Index nc = p.contacts();
    const Eigen::SparseMatrix<double, Eigen::RowMajor> rows = p.W;
    SparseBlockStructuredMatrix* m = SBM_new();
    m->blocknumber0 = m->blocknumber1 = static_cast<unsigned>(nc);
    m->blocksize0 = alloc<unsigned>(static_cast<size_t>(nc));
    m->blocksize1 = alloc<unsigned>(static_cast<size_t>(nc));
    for (Eigen::Index i = 0; i < nc; ++i)
      m->blocksize0[i] = m->blocksize1[i] = static_cast<unsigned>(3 * (i + 1));
    m->filled1 = static_cast<size_t>(nc) + 1;
    m->index1_data = alloc<size_t>(m->filled1);
    // Block columns of each block row (sorted), then the blocks, column-major 3 x 3.
    std::vector<size_t> cols;
    std::vector<std::vector<size_t>> row_cols(static_cast<size_t>(nc));
    size_t total = 0;
    for (Eigen::Index I = 0; I < nc; ++I) {
      cols.clear();
      for (int i = 0; i < 3; ++i)
        for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(rows, 3 * I + i); it; ++it)
          cols.push_back(static_cast<size_t>(it.col() / 3));
      std::sort(cols.begin(), cols.end());
      cols.erase(std::unique(cols.begin(), cols.end()), cols.end());
      row_cols[static_cast<size_t>(I)] = cols;
      total += cols.size();
    }
    m->nbblocks = static_cast<unsigned>(total);
    m->filled2 = total;
    m->index2_data = alloc<size_t>(total);
    m->block = alloc<double*>(total);
    size_t k = 0;
    for (Eigen::Index I = 0; I < nc; ++I) {
      m->index1_data[I] = k;
      const std::vector<size_t>& rc = row_cols[static_cast<size_t>(I)];
      const size_t first = k;
      for (const size_t J : rc) {
        m->index2_data[k] = J;
        m->block[k] = alloc<double>(9);
        std::fill(m->block[k], m->block[k] + 9, 0.0);
        ++k;
      }
      for (int i = 0; i < 3; ++i)
        for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(rows, 3 * I + i); it; ++it) {
          const size_t J = static_cast<size_t>(it.col() / 3);
          const size_t slot = first + static_cast<size_t>(std::lower_bound(rc.begin(), rc.end(), J) - rc.begin());
          m->block[slot][(it.col() % 3) * 3 + i] = it.value();
        }
    }
    m->index1_data[nc] = k;
    blocks_ = total;
    const int n = static_cast<int>(3 * nc);
    problem_ = frictionContactProblem_new_with_data(3, static_cast<int>(nc), NM_new_SBM(n, n, m),
                                                    q_.data(), mu_.data());
  }
  ~SiconosFriction() {
    NM_clear(problem_->M);
    std::free(problem_->M);
    std::free(problem_);  // q and mu are q_ and mu_
  }
  SiconosFriction(const SiconosFriction&) = delete;
  SiconosFriction& operator=(const SiconosFriction&) = delete;

  ::FrictionContactProblem* get() { return problem_; }
  /// Bytes of W in this storage: the blocks and their indices.
  size_t w_bytes() const {
    return blocks_ * (9 * sizeof(double) + sizeof(double*) + sizeof(size_t)) +
           (q_.size() / 3 + 1) * sizeof(size_t);
  }

  /// |F_nat| / |q| of r by Siconos' own code: fc3d_compute_error forms u = W r + q and the
  /// natural map's norm E over the cones, and returns E / max(||q||, ||r||, ||u||) (Siconos'
  /// relative measure, cpkit's relative_max); that scale is undone here, giving E / ||q||.
  double error(Eigen::VectorXd r) {
    Eigen::VectorXd u = Eigen::VectorXd::Zero(r.size());
    SolverOptions* so = solver_options_create(SICONOS_FRICTION_3D_NSGS);
    double e = 0;
    const double nq = q_.norm();
    fc3d_compute_error(problem_, r.data(), u.data(), 0.0, so, nq, &e);
    solver_options_delete(so);
    const double scale = std::max({nq, r.norm(), u.norm()});
    if (scale > DBL_EPSILON) e *= scale;
    return nq > DBL_EPSILON ? e / nq : e;
  }

 private:
  template <class T>
  static T* alloc(size_t n) {
    return static_cast<T*>(std::malloc(std::max<size_t>(n, 1) * sizeof(T)));
  }
  Eigen::VectorXd q_, mu_;
  size_t blocks_ = 0;
  ::FrictionContactProblem* problem_ = nullptr;
};

}  // namespace cpkit::bench
#endif
