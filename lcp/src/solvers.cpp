#include "cpkit/lcp/solvers.hpp"

#include "cpkit/lcp/lemke.hpp"

namespace cpkit::lcp {
namespace {

SolverRegistry build() {
  SolverRegistry r;
  r.add(lemke_entry());
  // Each solver module adds its entry here, in the order of the automatic chain.
  return r;
}

}  // namespace

const SolverRegistry& solvers() {
  static const SolverRegistry registry = build();
  return registry;
}

}  // namespace cpkit::lcp
