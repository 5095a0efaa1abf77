// The friction verdict's two published relative errors (friction_verdict.hpp) against Siconos'
// own fc3d_compute_error, through python3-siconos: a program of its own so that the verdict's
// hand-computed cases (test_friction_verdict.cpp) always run. Skipped (exit 77, the reason
// printed) when python3-siconos is missing; a failure where peers are required (peer_skip.hpp).
#include <catch2/catch.hpp>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "cpkit/core/friction_verdict.hpp"
#include "peer_skip.hpp"
#include "scratch_files.hpp"

namespace {

using cpkit::FrictionContactProblem;
using Eigen::MatrixXd;
using Eigen::VectorXd;

// As in test_friction_verdict.cpp: a random rank-deficient Delassus operator W = J J^T
// (J: 3 nc x m) and a q whose normal entries have both signs.
FrictionContactProblem random_problem(std::mt19937& rng, int nc, int m) {
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> U(0.1, 1.0);
  MatrixXd J(3 * nc, m);
  for (int i = 0; i < J.rows(); ++i)
    for (int j = 0; j < m; ++j) J(i, j) = g(rng);
  FrictionContactProblem p;
  p.q.resize(3 * nc);
  p.mu.resize(nc);
  for (int i = 0; i < 3 * nc; ++i) p.q[i] = g(rng);
  for (int i = 0; i < nc; ++i) p.mu[i] = U(rng);
  p.W = (J * J.transpose()).sparseView();
  return p;
}

std::string python() {
  if (const char* env = std::getenv("CPKIT_PYTHON")) return env;
  return std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
}

// Siconos' own errors for (W, q, mu, r): fc3d_compute_error with norm = ||q|| (what Siconos'
// solvers pass; it divides by max(norm, ||r||, ||u||)), and E itself from the same function
// with a norm larger than every vector, times that norm.
const char* kPeer = R"(
import sys, numpy as np
try:
    import siconos.numerics as sn
except Exception as e:
    print("python3-siconos not importable:", e); sys.exit(77)
d = [np.array([float(x) for x in l.split()]) for l in open(sys.argv[1]).read().strip().split("\n")]
nc = len(d[2]); n = 3 * nc
W = d[0].reshape(n, n); q = d[1]; mu = d[2]
p = sn.FrictionContactProblem(3, nc, W, q, mu)
so = sn.SolverOptions(sn.SICONOS_FRICTION_3D_NSGS)
for r in d[3:]:
    u = np.zeros(n)
    rel_max = sn.fc3d_compute_error(p, r.copy(), u, 1e-8, so, np.linalg.norm(q))[1]
    big = 4.0 * max(np.linalg.norm(q), np.linalg.norm(r), np.linalg.norm(W @ r + q), 1.0)
    E = sn.fc3d_compute_error(p, r.copy(), u, 1e-8, so, big)[1] * big
    print(repr(E / np.linalg.norm(q)), repr(rel_max))
)";

}  // namespace

TEST_CASE("relative_q and relative_max agree with Siconos' fc3d_compute_error",
          "[friction][verdict][siconos]") {
  namespace fs = std::filesystem;
  const fs::path dir = cpkit::test::scratch_dir("cpkit_test_friction_verdict_");
  const std::string script = cpkit::test::write_file(dir, "peer.py", kPeer);
  std::mt19937 rng(17);
  std::normal_distribution<double> g;
  int compared = 0;
  for (int trial = 0; trial < 4; ++trial) {
    const int nc = 1 + 2 * trial;
    const auto p = random_problem(rng, nc, 2 * nc);
    std::vector<VectorXd> cands;
    for (int k = 0; k < 4; ++k) {
      VectorXd r(3 * nc);
      for (int i = 0; i < 3 * nc; ++i) r[i] = g(rng) * std::pow(10.0, k - 2);
      cands.push_back(r);
    }
    std::ostringstream text;
    text.precision(17);
    const MatrixXd Wd = MatrixXd(p.W);
    for (int i = 0; i < Wd.rows(); ++i)
      for (int j = 0; j < Wd.cols(); ++j) text << Wd(i, j) << ' ';  // row-major for numpy
    text << '\n' << p.q.transpose() << '\n' << p.mu.transpose() << '\n';
    for (const auto& c : cands) text << c.transpose() << '\n';
    const std::string in = cpkit::test::write_file(dir, "in.txt", text.str());
    const std::string out = (dir / "out.txt").string();
    const int status = std::system(("'" + python() + "' '" + script + "' '" + in + "' > '" + out +
                                    "' 2>&1").c_str());
    const int rc = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream res(out);
    if (rc == 77 || rc == 127)  // python3-siconos not importable / no interpreter at all
      cpkit::test::skip_program(rc == 77 ? std::string(std::istreambuf_iterator<char>(res), {})
                                         : "no Python interpreter '" + python() + "'");
    REQUIRE(rc == 0);
    for (const auto& c : cands) {
      double rel_q = 0, rel_max = 0;
      REQUIRE(res >> rel_q >> rel_max);
      const auto e = cpkit::friction_errors(p, c);
      CHECK(e.relative_q == Approx(rel_q).epsilon(1e-10));
      CHECK(e.relative_max == Approx(rel_max).epsilon(1e-10));
      ++compared;
    }
  }
  CHECK(compared == 16);
  std::error_code ec;
  fs::remove_all(dir, ec);
}
