// Solves a hand-checked 2x2 LCP through the installed cpkit::lcp and checks the answer.
// M = [[2, 1], [1, 2]], q = (-5, -6): z = (4/3, 7/3), w = 0 (solve M z = -q).
// The problem is read from the JSON file given as argv[1] (written by run_consumer_test.cmake):
// a consumer that reads a problem file links the file readers and their dependencies
// (simdjson), which cpkit.pc and cpkitConfig.cmake must both supply.
// The same problem through enumerate_small<2> and SmallPreparedLcp<2> (M is a P-matrix: that z
// is the only solution): their code is compiled into the installed library, not its headers.
#include <cmath>
#include <cpkit/core/io.hpp>
#include <cpkit/lcp/enumerate_small_prepared.hpp>
#include <cpkit/lcp/lemke.hpp>
#include <iostream>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: consumer PROBLEM.json\n";
    return 2;
  }
  const cpkit::LcpProblem p = cpkit::read_lcp_file(argv[1]);
  const auto r = cpkit::lcp::solve_lemke(p, {});
  bool ok = p.size() == 2 && cpkit::is_solution(r.status) &&
            std::abs(r.z[0] - 4.0 / 3.0) < 1e-12 && std::abs(r.z[1] - 7.0 / 3.0) < 1e-12;
  std::cout << "consumer: " << cpkit::to_string(r.status) << (ok ? " ok" : " WRONG") << '\n';
  if (!ok) return 1;
  const Eigen::Matrix2d M = p.M;
  const Eigen::Vector2d q = p.q;
  cpkit::lcp::SmallSolutionSet<2> all, prepared;
  cpkit::lcp::enumerate_small<2>(M, q, all);
  cpkit::lcp::SmallPreparedLcp<2>(M).enumerate(q, prepared);
  for (const auto* s : {&all, &prepared})
    ok = ok && s->num_points == 1 && !s->infinite && s->dropped == 0 &&
         std::abs(s->z[0](0) - 4.0 / 3.0) < 1e-12 && std::abs(s->z[0](1) - 7.0 / 3.0) < 1e-12;
  std::cout << "consumer: enumerate_small" << (ok ? " ok" : " WRONG") << '\n';
  return ok ? 0 : 1;
}
