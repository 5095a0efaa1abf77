// cpkit's friction solvers on the real Siconos FrictionContact files of tests/data/fclib/local
// (copied from Siconos' test data, MANIFEST.txt): "auto" solves each at the unit-free tol 1e-10
// and every answer is re-checked by the test's own computation (friction_check.hpp: u recomputed
// densely, De Saxce's three conditions checked directly); fb-soc and nsgs each solve the small
// ones. The files are read by cpkit's reader (friction_io.hpp), which decodes every one of them
// exactly as Siconos' own reader does (core.test_friction_io_siconos_peer: every entry, bit for
// bit), so this test needs no peer.
// Capsules-i125-1213.hdf5 (286 contacts, ~2 s) and the FCLIB HDF5 files are left to bench/.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "cpkit/core/friction_io.hpp"
#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/lcp/friction/fb_soc.hpp"
#include "cpkit/lcp/friction/nsgs.hpp"
#include "cpkit/lcp/solvers.hpp"
#include "friction_check.hpp"

namespace {

using cpkit::FrictionContactProblem;
using cpkit::Status;

const std::vector<std::string> kFiles = {
    "FC3D_Example1.dat", "FrictionContact3D_1c.dat", "FrictionContact3D_RR_1c.dat",
    "NESpheres_10_1.dat", "Rover1039.dat", "Rover3865.dat", "Rover4396.dat",
    "Confeti-ex03-Fc3D-SBM.dat", "BoxesStack1-i100000-32.hdf5.dat", "Capsules-i100-889.dat"};

FrictionContactProblem read_local(const std::string& name) {
  const auto p = cpkit::read_friction_problem(std::string(CPKIT_TEST_DATA_DIR) + "/fclib/local/" +
                                              name);
  REQUIRE(p.validate().empty());
  REQUIRE(p.W.rows() > 0);
  return p;
}

const std::vector<std::string> kSmall(kFiles.begin(), kFiles.begin() + 8);

}  // namespace

TEST_CASE("auto solves the Siconos local problems; the test re-checks each answer",
          "[friction][fclib]") {
  // All of kFiles, with BoxesStack1 (52 contacts, rank-deficient W) and Capsules-i100-889 (276).
  for (const std::string& name : kFiles) {
    INFO(name);
    const auto p = read_local(name);
    cpkit::CommonOptions o;
    o.tol = 1e-10;
    const auto r = cpkit::lcp::solvers().find("auto")->solve_fc(p, o);
    REQUIRE(r.status == Status::kSolved);
    CHECK(!r.attempts.empty());
    CHECK(cpkit::test::friction_violation(p.W, p.q, p.mu, r.z) < 1e-8);
    // Acary-Bremond-Huber's criterion (|q| normalisation) at 1e-8 holds too.
    CHECK(cpkit::friction_errors(p, r.z).relative_q < 1e-8);
  }
}

TEST_CASE("nsgs and fb-soc each solve the small Siconos problems", "[friction][fclib]") {
  for (const std::string& name : kSmall) {
    INFO(name);
    const auto p = read_local(name);
    const auto a = cpkit::lcp::friction::solve_nsgs(p);
    CHECK(a.status == Status::kSolved);
    CHECK(cpkit::test::friction_violation(p.W, p.q, p.mu, a.z) < 1e-8);
    const auto b = cpkit::lcp::friction::solve_fb_soc(p);
    CHECK(b.status == Status::kSolved);
    CHECK(cpkit::test::friction_violation(p.W, p.q, p.mu, b.z) < 1e-8);
  }
}
