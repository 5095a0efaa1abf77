#include "cpkit/lcp/solvers.hpp"

#include "cpkit/lcp/auto_chain.hpp"
#include "cpkit/lcp/fb_newton.hpp"
#include "cpkit/lcp/friction/auto.hpp"
#include "cpkit/lcp/friction/faceted.hpp"
#include "cpkit/lcp/friction/fb_soc.hpp"
#include "cpkit/lcp/friction/ipopt_fc.hpp"
#include "cpkit/lcp/friction/nsgs.hpp"
#include "cpkit/lcp/friction/prox.hpp"
#include "cpkit/lcp/lemke.hpp"
#include "cpkit/lcp/mpcc_solvers.hpp"
#include "cpkit/lcp/cone_complementarity_fb.hpp"

namespace cpkit::lcp {
namespace {

SolverRegistry build() {
  SolverRegistry r;
  r.add(friction::with_faceted_lemke(lemke_entry()));  // + friction problems, faceted cone
  r.add(fb_newton_entry());
  r.add(friction::with_ipopt_fc(ipopt_entry()));  // + friction problems (MPCC)
  r.add(nlopt_entry());
  SolverEntry automatic = auto_entry();  // one "auto": LCP/box/MCP chain and the friction chain
  automatic.solve_fc = [](const FrictionContactProblem& p, const CommonOptions& o) {
    return friction::solve_auto(p, o);
  };
  automatic.info.description += "; friction problems: fb-soc, nsgs, prox, lemke(-faceted), ipopt";
  r.add(std::move(automatic));
  r.add(friction::nsgs_entry());  // friction problems (issue 26)
  r.add(with_soc_fb(friction::fb_soc_entry()));  // + cone complementarity problems (issue 25)
  r.add(friction::prox_entry());
  // Each solver module adds its entry here, in the order of the automatic chain.
  return r;
}

}  // namespace

const SolverRegistry& solvers() {
  static const SolverRegistry registry = build();
  return registry;
}

}  // namespace cpkit::lcp
