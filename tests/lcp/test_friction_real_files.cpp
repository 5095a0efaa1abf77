// h16's friction solvers on real FCLIB / Siconos files (tests/data/fclib, copies of
// ../shared/problems/fclib with the checksums of its MANIFEST.txt). The files ship no
// solution: every r is re-checked by the test's own violation() (friction_examples.hpp) and the
// physics of the file is not assumed; .dat files are read by the test's own reader
// (friction_dat.hpp), compared with cpkit's read_friction_problem (which also reads the HDF5 ones).
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>

#include "cpkit/core/friction_io.hpp"
#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/lcp/friction/faceted.hpp"
#include "cpkit/lcp/friction/ipopt_fc.hpp"
#include "cpkit/lcp/friction/prox.hpp"
#include "cpkit/lcp/friction/solutions.hpp"
#include "friction_dat.hpp"
#include "friction_examples.hpp"

namespace {

using cpkit::Status;
const std::string kDir = CPKIT_TEST_DATA_DIR "/fclib/local/";

double rel_distance(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  const double d = (a - b).lpNorm<Eigen::Infinity>();
  return d == 0 ? 0.0 : d / std::max(a.lpNorm<Eigen::Infinity>(), b.lpNorm<Eigen::Infinity>());
}

}  // namespace

TEST_CASE("real files: prox, faceted Lemke and Ipopt solve small Siconos problems",
          "[friction][real]") {
  for (const char* f : {"FC3D_Example1.dat", "Rover4396.dat"}) {
    const auto p = cpkit::test::read_dat(kDir + f);
    cpkit::CommonOptions c;
    c.tol = 1e-8;
    cpkit::lcp::friction::ProxOptions po;
    po.common = c;
    cpkit::lcp::friction::FacetedLemkeOptions lo;
    lo.common = c;
    cpkit::lcp::friction::IpoptFcOptions io;
    io.common = c;
    const cpkit::SolveResult results[] = {cpkit::lcp::friction::solve_prox(p, po),
                                          cpkit::lcp::friction::solve_faceted_lemke(p, lo),
                                          cpkit::lcp::friction::solve_ipopt_fc(p, io)};
    for (const auto& r : results) {
      INFO(f << ": " << r.solver << ": " << r.message);
      REQUIRE(r.status == Status::kSolved);
      CHECK(cpkit::test::violation(p, r.z) <= 1e-7);
    }
  }
}

TEST_CASE("real files: BoxesStack1 (52 contacts, rank 78 of 156) has distinct verified solutions",
          "[friction][real]") {
  const auto p = cpkit::test::read_dat(kDir + "BoxesStack1-i100000-32.hdf5.dat");
  REQUIRE(p.contacts() == 52);
  cpkit::lcp::friction::FrictionSolutionsOptions o;
  o.common.tol = 1e-8;
  // The test's budget, deterministic (no time limit): 60 iterations (pivots, sweeps, Newton
  // steps) per solve; Lemke needs 41 pivots here, fb-soc converges within it.
  o.common.max_iterations = 60;
  o.starts = 1;
  const auto set = cpkit::lcp::friction::friction_solutions(p, o);
  INFO(set.message);
  CHECK_FALSE(set.complete);
  REQUIRE(set.solutions.size() >= 2);
  double widest = 0;
  for (std::size_t i = 0; i < set.solutions.size(); ++i) {
    CHECK(set.solutions[i].status == Status::kSolved);
    CHECK(cpkit::test::violation(p, set.solutions[i].z) <= 1e-7);
    for (std::size_t j = 0; j < i; ++j) {
      const double d = rel_distance(set.solutions[i].z, set.solutions[j].z);
      CHECK(d > 1e-6);
      widest = std::max(widest, d);
    }
  }
  std::cout << "BoxesStack1: " << set.solutions.size()
            << " distinct verified solutions, largest relative difference " << widest << "\n";
  CHECK(widest > 0.1);  // not rounding: the solutions differ in the first digits
}

TEST_CASE("real files: prox on every local file; the test's .dat reader agrees with cpkit's",
          "[friction][real]") {
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(kDir)) {
    ++files;
    const std::string path = e.path().string();
    const auto p = cpkit::read_friction_problem(path);
    INFO(path << " (" << p.contacts() << " contacts)");
    if (e.path().extension() == ".dat") {  // a second route to the same data
      const auto t = cpkit::test::read_dat(path);
      CHECK((Eigen::MatrixXd(t.W) - Eigen::MatrixXd(p.W)).cwiseAbs().maxCoeff() == 0);
      CHECK((t.q - p.q).cwiseAbs().maxCoeff() == 0);
      CHECK((t.mu - p.mu).cwiseAbs().maxCoeff() == 0);
    }
    cpkit::lcp::friction::ProxOptions o;
    o.common.tol = 1e-8;
    const auto t0 = std::chrono::steady_clock::now();
    const auto r = cpkit::lcp::friction::solve_prox(p, o);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::cout << e.path().filename().string() << ": " << p.contacts() << " contacts, prox "
              << cpkit::to_string(r.status) << " in " << s << " s, unit-free "
              << r.residuals.natural << "\n";
    INFO(r.message);
    CHECK(r.status == Status::kSolved);
    CHECK(cpkit::test::violation(p, r.z) <= 1e-6);
    // Outer (proximal) iterations: Siconos' PROX (fc3d_proximal, run by
    // bench/bench_friction_siconos.py on the same files at 1e-8) needs 4 on Capsules-i125, 5 on
    // Capsules-i100, 7 on BoxesStack1; PROX's alpha rule alone took cpkit 20 to 184. At most 8.
    CHECK(r.iterations <= 8);
  }
  CHECK(files == 12);  // the local files of tests/data/fclib (MANIFEST.txt)
}
