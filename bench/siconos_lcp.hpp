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
#endif
