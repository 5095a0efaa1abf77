// `cpkit fc solve|solutions`' requests in the library (lcp/friction/fc_request.hpp): exit codes,
// refusals and the reports, without a subprocess. One contact with W = I and mu = 0.5 (Siconos
// .dat), solved by hand: u = r + q, r in K_mu, u + mu |u_T| e_N in K*_mu, r . (that) = 0.
//   q = (-1, 0.2, 0): stick, r = -q = (1, -0.2, 0) (|r_T| = 0.2 <= mu r_N = 0.5), u = 0.
//   q = (1, 0.3, 0): separation, r = 0, u = q (u_N + mu |u_T| = 1.15 >= |u_T| / mu = 0.6).
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/lcp/friction/fc_bench.hpp"
#include "cpkit/lcp/friction/fc_request.hpp"

using namespace cpkit;
using namespace cpkit::lcp::friction;

namespace {

/// A Siconos FrictionContact .dat file of one contact, W = I (3 x 3), mu = 0.5.
std::string one_contact(const std::string& name, const std::string& q) {
  const auto path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path) << "3\n1\n\n0\n3\n3\n\n3\n3\n\n1\n0\n0\n\n0\n1\n0\n\n0\n0\n1\n\n" << q << "\n\n0.5\n";
  return path.string();
}

std::string refusal(const FcRequest& r, bool solutions = false) {
  try {
    if (solutions) run_fc_solutions_request(r);
    else run_fc_solve_request(r);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

}  // namespace

TEST_CASE("fc request: one contact by hand, stick and separation, exit 0", "[fc][request]") {
  FcRequest r;
  r.file = one_contact("cpkit_test_fc_request_stick.dat", "-1\n0.2\n0");
  const FcSolveOutcome stick = run_fc_solve_request(r);
  CHECK(stick.exit_code == kExitOk);
  CHECK_FALSE(stick.is_global);
  REQUIRE(stick.result.z.size() == 3);
  CHECK(stick.result.z(0) == Approx(1));
  CHECK(stick.result.z(1) == Approx(-0.2));
  CHECK(stick.result.z(2) == Approx(0).margin(1e-9));
  const auto j = fc_solve_json(stick);
  CHECK(j["contacts"] == 1);
  CHECK(j["per_contact"][0]["state"] == "stick");
  CHECK(fc_solve_text(stick).find("contacts:   1 stick, 0 slip, 0 separated\n") != std::string::npos);
  std::filesystem::remove(r.file);

  r.file = one_contact("cpkit_test_fc_request_open.dat", "1\n0.3\n0");
  const FcSolveOutcome open = run_fc_solve_request(r);
  CHECK(open.exit_code == kExitOk);
  CHECK(open.result.z.norm() == Approx(0).margin(1e-9));
  CHECK(fc_solve_json(open)["per_contact"][0]["state"] == "separated");
  // the solution is unique (W = I is positive definite): at most one distinct solution listed
  r.starts = 3;
  const FcSolutionsOutcome all = run_fc_solutions_request(r);
  CHECK(all.exit_code == kExitOk);
  REQUIRE(all.set.solutions.size() == 1);
  CHECK(all.set.solutions[0].z.norm() == Approx(0).margin(1e-9));
  std::filesystem::remove(r.file);
}

TEST_CASE("fc request: refusals name the option", "[fc][request]") {
  FcRequest r;
  r.file = one_contact("cpkit_test_fc_request_bad.dat", "-1\n0.2\n0");
  r.tol = 0.1;
  CHECK(refusal(r) == "--tol must be in (0, 1e-3] (the unit-free residual: a larger tolerance "
                      "would call almost any r solved), got 0.1");
  r.tol = 1e-10;
  r.solver = "simplex";
  CHECK(refusal(r) == "unknown friction solver 'simplex' (valid: " + fc_solver_list() + ")");
  r.solver = "auto";
  r.starts = 0;
  CHECK(refusal(r, true) == "--starts must be in [1, 10000], got 0");
  r.starts = 10001;  // the documented bound (FrictionSolutionsOptions::kMaxStarts)
  CHECK(refusal(r, true) == "--starts must be in [1, 10000], got 10001");
  r.starts = 20;
  std::filesystem::remove(r.file);
  r.file = "/nonexistent/problem.dat";
  CHECK(refusal(r).find("/nonexistent/problem.dat") != std::string::npos);
}

// Issue 34, F4-12: a global problem whose M is diag(1, ..., 1, -1) (indefinite: no LDL^T of a
// positive definite matrix, and not singular, so no proximal route) is not run; its JSON says
// so (it threw "W is 0 x 0"), with null errors, and the exit code is the text output's, 5.
TEST_CASE("fc request: a global M that cannot be condensed is not_run in the JSON too",
          "[fc][request][global]") {
  FcRequest r;
  r.file = std::string(CPKIT_TEST_DATA_DIR) + "/fclib/hostile/F4-12_M_indefinite.dat";
  const FcSolveOutcome out = run_fc_solve_request(r);
  REQUIRE(out.is_global);
  CHECK(out.exit_code == kExitInconclusive);
  CHECK(out.result.status == Status::kNotRun);
  const auto j = fc_solve_json(out);
  CHECK(j["status"] == "not_run");
  CHECK(j["global"]["errors"]["balance"].is_null());
  CHECK(j["global"]["errors"]["local"].is_null());
  CHECK(j["per_contact"].empty());
  CHECK(fc_solve_text(out).find("status:     not_run\n") != std::string::npos);
}

// `cpkit fc bench`'s table (fc_bench.hpp) on the hand-solved stick contact above: the header, a
// row per solver with the hand answer's state solved; refusals before any solve; a stream that
// fails stops the table at once (issue 34, F4-09).
TEST_CASE("fc bench table: rows, refusals, and a failing stream", "[fc][request][bench]") {
  FcBenchRequest r;
  r.files = {one_contact("cpkit_test_fc_bench_stick.dat", "-1\n0.2\n0")};
  r.solvers = {"nsgs", "prox"};
  const FcBench bench = prepare_fc_bench(r);
  std::ostringstream csv, progress;
  write_fc_bench_table(bench, csv, "t.csv", &progress);
  std::istringstream lines(csv.str());
  std::string line;
  REQUIRE(std::getline(lines, line));
  CHECK(line == "file,problem,contacts,solver,status,iterations,seconds,unit_free,relative_q,"
                "relative_max,measure");
  int rows = 0;
  for (const char* solver : {"nsgs", "prox"}) {
    REQUIRE(std::getline(lines, line));
    ++rows;
    CHECK(line.rfind("\"" + r.files[0] + "\",", 0) == 0);
    CHECK(line.find(std::string(",1,") + solver + ",solved,") != std::string::npos);
    CHECK(line.substr(line.size() - 11) == ",relative_q");  // the default: the published measure
  }
  CHECK_FALSE(std::getline(lines, line));
  CHECK(rows == 2);
  // A stream that cannot be written: InputError naming the table, before the first solve.
  std::ostream broken(nullptr);
  std::ostringstream none;
  try {
    write_fc_bench_table(bench, broken, "t.csv", &none);
    FAIL("accepted a stream that cannot be written");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()) == "error writing 't.csv' (disk full or not writable?)");
  }
  CHECK(none.str().empty());
  // Refusals in the user's words.
  FcBenchRequest bad = r;
  bad.solvers = {"simplex"};
  CHECK_THROWS_WITH(prepare_fc_bench(bad),
                    Catch::StartsWith("unknown friction solver 'simplex' in --solvers (valid: ") &&
                        Catch::Contains("nsgs") && Catch::Contains("fb-soc"));
  bad = r;
  bad.tol = 0.5;
  CHECK_THROWS_WITH(prepare_fc_bench(bad), "--tol must be in (0, 1e-3], got 0.5");
  std::filesystem::remove(r.files[0]);
}
