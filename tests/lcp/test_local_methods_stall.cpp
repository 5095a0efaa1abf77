// A class where local methods stall (docs/fb_newton.md, "Guarantees and known limits"):
// M = [[-1.5, 2], [-4, 4]] (not P0: M_11 < 0), q = (-5, 17). The unique solution solves M z = -q
// (hand calculation: from row 2, z_2 = z_1 - 4.25; row 1 then gives 0.5 z_1 = 13.5):
// z = (27, 22.75), w = (0, 0). Every solver either returns that point, verified, or ends without
// a claim; Lemke and the auto chain return it.
#include <catch2/catch.hpp>

#include "cpkit/core/registry.hpp"
#include "cpkit/lcp/auto_chain.hpp"
#include "cpkit/lcp/lemke.hpp"
#include "cpkit/lcp/solvers.hpp"

using cpkit::LcpProblem;
using cpkit::Mat;
using cpkit::Vec;

namespace {
const LcpProblem kProblem(Mat{{-1.5, 2}, {-4, 4}}, Vec{{-5, 17}}, "not_p0_stall");
const Vec kSolution{{27, 22.75}};
}  // namespace

TEST_CASE("Not-P0 LCP: no solver claims a wrong point; Lemke and auto solve it", "[stall]") {
  for (const cpkit::SolverEntry& e : cpkit::lcp::solvers().entries()) {
    if (!e.solve_lcp) continue;
    CAPTURE(e.info.name);
    const auto r = e.solve_lcp(kProblem, cpkit::CommonOptions{});
    INFO(r.message);
    if (cpkit::is_solution(r.status))
      CHECK((r.z - kSolution).cwiseAbs().maxCoeff() <= 1e-9 * 27);
    else
      CHECK(r.status != cpkit::Status::kInfeasible);
  }
  const auto l = cpkit::lcp::solve_lemke(kProblem);
  REQUIRE(l.status == cpkit::Status::kSolved);
  CHECK((l.z - kSolution).cwiseAbs().maxCoeff() <= 1e-12 * 27);
  const auto a = cpkit::lcp::solve_auto(kProblem);
  REQUIRE(a.status == cpkit::Status::kSolved);
  CHECK((a.z - kSolution).cwiseAbs().maxCoeff() <= 1e-12 * 27);
}
