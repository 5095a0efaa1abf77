// Solves a hand-checked 2x2 LCP through the installed cpkit::lcp and checks the answer.
// M = [[2, 1], [1, 2]], q = (-5, -6): z = (4/3, 7/3), w = 0 (solve M z = -q).
#include <cmath>
#include <cpkit/lcp/lemke.hpp>
#include <iostream>

int main() {
  cpkit::LcpProblem p(cpkit::Mat{{2, 1}, {1, 2}}, cpkit::Vec{{-5, -6}});
  const auto r = cpkit::lcp::solve_lemke(p, {});
  const bool ok = cpkit::is_solution(r.status) && std::abs(r.z[0] - 4.0 / 3.0) < 1e-12 &&
                  std::abs(r.z[1] - 7.0 / 3.0) < 1e-12;
  std::cout << "consumer: " << cpkit::to_string(r.status) << (ok ? " ok" : " WRONG") << '\n';
  return ok ? 0 : 1;
}
