// cpkit's friction solvers against Siconos' fc3d solvers (python3-siconos, a peer, not ground
// truth) on random problems whose solution is unique (W close to the identity, small mu:
// the one-contact maps are contractions), so both must return the same r. Also: Siconos' own
// answer must pass cpkit's verdict. Exits 77 (ctest: skipped) with the reason printed when
// python3-siconos is not importable.
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

#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/lcp/solvers.hpp"
#include "friction_check.hpp"
#include "peer_skip.hpp"
#include "scratch_files.hpp"

namespace {

using cpkit::FrictionContactProblem;
using cpkit::Status;
using Eigen::MatrixXd;
using Eigen::VectorXd;

std::string python() {
  if (const char* env = std::getenv("CPKIT_PYTHON")) return env;
  return std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
}

// Siconos' NSN_FB and NSGS at tol 1e-14 on (W, q, mu): prints r of each, one line per solver.
const char* kPeer = R"(
import sys, numpy as np
try:
    import siconos.numerics as sn
except Exception as e:
    print("python3-siconos not importable:", e); sys.exit(77)
d = [np.array([float(x) for x in l.split()]) for l in open(sys.argv[1]).read().strip().split("\n")]
nc = len(d[2]); n = 3 * nc
p = sn.FrictionContactProblem(3, nc, d[0].reshape(n, n), d[1], d[2])
for sid in (sn.SICONOS_FRICTION_3D_NSN_FB, sn.SICONOS_FRICTION_3D_NSGS):
    so = sn.SolverOptions(sid)
    so.iparam[sn.SICONOS_IPARAM_MAX_ITER] = 10000
    so.dparam[sn.SICONOS_DPARAM_TOL] = 1e-14
    r = np.zeros(n); u = np.zeros(n)
    info = sn.fc3d_driver(p, r, u, so)
    print(info, " ".join(repr(x) for x in r))
)";

}  // namespace

TEST_CASE("fb-soc and nsgs agree with Siconos' NSN_FB and NSGS on problems with one solution",
          "[friction][siconos]") {
  namespace fs = std::filesystem;
  const fs::path dir = cpkit::test::scratch_dir("cpkit_test_friction_peer_");
  const std::string script = cpkit::test::write_file(dir, "peer.py", kPeer);
  std::mt19937 rng(29);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> U(0.1, 0.3);
  int compared = 0;
  for (int trial = 0; trial < 4; ++trial) {
    const int nc = 3 + 3 * trial, n = 3 * nc;
    MatrixXd A(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) A(i, j) = g(rng);
    FrictionContactProblem p;
    p.W = (MatrixXd::Identity(n, n) + 0.02 * (A + A.transpose())).sparseView();
    p.q.resize(n);
    for (int i = 0; i < n; ++i) p.q[i] = g(rng);
    p.mu.resize(nc);
    for (int i = 0; i < nc; ++i) p.mu[i] = U(rng);
    std::ostringstream text;
    text.precision(17);
    const MatrixXd Wd(p.W);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) text << Wd(i, j) << ' ';
    text << '\n' << p.q.transpose() << '\n' << p.mu.transpose() << '\n';
    const std::string in = cpkit::test::write_file(dir, "in.txt", text.str());
    const std::string out = (dir / "out.txt").string();
    const int status = std::system(
        ("'" + python() + "' '" + script + "' '" + in + "' > '" + out + "' 2>&1").c_str());
    const int rc = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream res(out);
    if (rc == 77 || rc == 127)  // python3-siconos not importable / no interpreter at all
      cpkit::test::skip_program(rc == 77 ? std::string(std::istreambuf_iterator<char>(res), {})
                                         : "no Python interpreter '" + python() + "'");
    REQUIRE(rc == 0);
    std::vector<VectorXd> peers;
    for (int s = 0; s < 2; ++s) {
      int info = -1;
      VectorXd r(n);
      REQUIRE(res >> info);
      for (int i = 0; i < n; ++i) REQUIRE(res >> r[i]);
      if (info == 0) {
        // Siconos' answer passes cpkit's verdict (at 1e-8: its own tolerance is relative to |q|).
        CHECK(cpkit::friction_errors(p, r).unit_free < 1e-8);
        peers.push_back(r);
      }
    }
    REQUIRE(!peers.empty());
    for (const std::string name : {"fb-soc", "nsgs"}) {
      const auto s = cpkit::lcp::solvers().find(name)->solve_fc(p, {});
      REQUIRE(s.status == Status::kSolved);
      CHECK(cpkit::test::friction_violation(p.W, p.q, p.mu, s.z) < 1e-8);
      for (const VectorXd& r : peers) CHECK((s.z - r).norm() <= 1e-6 * (1 + r.norm()));
      ++compared;
    }
  }
  CHECK(compared == 8);
  std::error_code ec;
  fs::remove_all(dir, ec);
}
