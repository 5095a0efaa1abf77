#pragma once
// Siconos numerics' LCP solvers, the peer of the benchmarks (when CMake found it:
// CPKIT_HAVE_SICONOS); its headers are not warning-clean.
#ifdef CPKIT_HAVE_SICONOS
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include "LCP_Solvers.h"
#include "LinearComplementarityProblem.h"
#include "NonSmoothDrivers.h"
#include "NumericsMatrix.h"
#include "SolverOptions.h"
#include "lcp_cst.h"
#pragma GCC diagnostic pop

#include <Eigen/Dense>

/// A Siconos LCP over copies of cpkit's (M, q): dense and column-major, as NM_DENSE expects.
/// The NumericsMatrix views the copy and is freed without it (setup is not part of any timing).
struct SiconosLcp {
  Eigen::MatrixXd M;
  Eigen::VectorXd q;
  NumericsMatrix* nm = nullptr;
  LinearComplementarityProblem lcp{};
  SiconosLcp(const Eigen::MatrixXd& M0, const Eigen::VectorXd& q0) : M(M0), q(q0) {
    const int n = static_cast<int>(q.size());
    nm = NM_create_from_data(NM_DENSE, n, n, M.data());
    lcp.size = n;
    lcp.M = nm;
    lcp.q = q.data();
  }
  ~SiconosLcp() { NM_free_not_dense(nm); }
  SiconosLcp(const SiconosLcp&) = delete;
  SiconosLcp& operator=(const SiconosLcp&) = delete;
};
#endif
