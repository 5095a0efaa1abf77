// `cpkit lcp solve|verify|enumerate`'s requests in the library (lcp/lcp_request.hpp): the exit
// codes, the refusals in option words and the reports, without a subprocess. Values solved by
// hand: M = [[2, 1], [1, 2]] is positive definite (one solution for every q); with q = (-5, -6)
// both z_i > 0 solve 2 z1 + z2 = 5, z1 + 2 z2 = 6: z = (4/3, 7/3), w = 0.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/lcp/lcp_request.hpp"

using namespace cpkit;
using namespace cpkit::lcp;

namespace {

std::string write_file(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path) << text;
  return path.string();
}

const std::string& pd_file() {
  static const std::string path = write_file(
      "cpkit_test_lcp_request_pd.json", R"({"name": "pd2", "M": [[2, 1], [1, 2]], "q": [-5, -6]})");
  return path;
}

/// w1 = -z1 - 1 < 0 for every z1 >= 0: no solution (by hand).
const std::string& infeasible_file() {
  static const std::string path = write_file(
      "cpkit_test_lcp_request_none.json", R"({"M": [[-1, 0], [0, 1]], "q": [-1, 1]})");
  return path;
}

template <class F>
std::string refusal(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

}  // namespace

TEST_CASE("lcp request: a 2x2 LCP solved by hand, by solve, enumerate and verify", "[lcp][request]") {
  LcpSolveRequest s;
  s.file = pd_file();
  const LcpSolveOutcome solved = run_lcp_solve_request(s);
  CHECK(solved.exit_code == kExitOk);
  REQUIRE(solved.results.size() == 1);
  CHECK(solved.entries[0] == "auto");  // the default (issue 37)
  // A positive definite 2 x 2: one solution, answered by the tiny route without Lemke's pivots.
  CHECK(solved.results[0].solver == "enumeration");
  CHECK(solved.hint.empty());
  CHECK(solved.results[0].z(0) == Approx(4.0 / 3));
  CHECK(solved.results[0].z(1) == Approx(7.0 / 3));
  CHECK(lcp_solve_json(solved)["problem"] == "pd2");
  CHECK(lcp_solve_text(solved).rfind("problem:    pd2 (n = 2)\n", 0) == 0);

  LcpEnumerateRequest e;
  e.file = pd_file();
  const LcpEnumerateOutcome all = run_lcp_enumerate_request(e);
  CHECK(all.exit_code == kExitOk);
  CHECK(all.result.complete);
  REQUIRE(all.result.count() == 1);
  CHECK(all.result.solutions[0].z(0) == Approx(4.0 / 3));
  const auto j = lcp_enumerate_json(all);
  CHECK(j["count"] == 1);
  CHECK(j["complete"] == true);
  CHECK(j["n"] == 2);
  const std::string text = lcp_enumerate_text(all);
  CHECK(text.find("complete:   yes\ncount:      1\nextreme solutions: 1\n") != std::string::npos);

  LcpVerifyRequest v;
  v.file = pd_file();
  const LcpVerifyOutcome ver = run_lcp_verify_request(v);
  CHECK(ver.exit_code == kExitOk);
  CHECK(lcp_verify_json(ver)["verdict"] == "consistent");
  CHECK(lcp_verify_text(ver).find("consistent: every solver agrees with the enumeration\n") !=
        std::string::npos);
}

TEST_CASE("lcp request: no solution exits 1 (solve, every solver, a complete enumeration)",
          "[lcp][request]") {
  LcpSolveRequest s;
  s.file = infeasible_file();
  const LcpSolveOutcome proved = run_lcp_solve_request(s);
  CHECK(proved.exit_code == kExitNoSolution);
  CHECK(proved.results.at(0).status == cpkit::Status::kInfeasible);
  CHECK(proved.hint.empty());  // a proof needs no "what to try"
  s.all_solvers = true;
  const LcpSolveOutcome every = run_lcp_solve_request(s);
  CHECK(every.exit_code == kExitNoSolution);
  CHECK(every.results.size() > 1);
  CHECK(lcp_solve_json(every)["solved_by_any"] == false);
  LcpEnumerateRequest e;
  e.file = infeasible_file();
  const LcpEnumerateOutcome all = run_lcp_enumerate_request(e);
  CHECK(all.result.complete);
  CHECK(all.result.count() == 0);
  CHECK(all.exit_code == kExitNoSolution);
}

TEST_CASE("lcp request: an enumeration that is not complete and found nothing exits 5",
          "[lcp][request]") {
  // n = 5 above --max-size 4, and not a bimatrix game (the diagonal of M is not zero): the
  // general engine is not run, complete = false (cpkit lcp enumerate --help), nothing found.
  LcpEnumerateRequest e;
  e.file = write_file("cpkit_test_lcp_request_5.json",
                      R"({"M": [[1,0,0,0,0],[0,1,0,0,0],[0,0,1,0,0],[0,0,0,1,0],[0,0,0,0,1]],
                          "q": [-1, -1, -1, -1, -1]})");
  e.max_size = 4;
  const LcpEnumerateOutcome all = run_lcp_enumerate_request(e);
  CHECK_FALSE(all.result.complete);
  CHECK(all.result.solutions.empty());
  CHECK(all.exit_code == kExitInconclusive);
  CHECK(lcp_enumerate_json(all)["complete"] == false);
  std::filesystem::remove(e.file);
}

TEST_CASE("lcp request: refusals name the option the user typed", "[lcp][request]") {
  LcpSolveRequest s;
  s.file = pd_file();
  s.tol = 0.1;
  CHECK(refusal([&] { run_lcp_solve_request(s); }) ==
        "--tol must be at most 1e-3 (a larger tolerance on the scaled residual would call almost "
        "any z solved), got 0.1");
  s.tol = 1e-10;
  s.solver = "simplex";
  CHECK(refusal([&] { run_lcp_solve_request(s); }) ==
        "unknown solver 'simplex' (valid: " + lcp_solver_list() + ")");
  s.solver = "lemke";
  s.all_solvers = true;
  s.trace = true;
  CHECK(refusal([&] { run_lcp_solve_request(s); }).rfind("--trace with --all-solvers needs --json", 0) == 0);
  s.json = true;
  CHECK(refusal([&] { run_lcp_solve_request(s); }) == "(accepted)");

  LcpVerifyRequest v;
  v.file = pd_file();
  v.skip = {"lemkee"};
  CHECK(refusal([&] { run_lcp_verify_request(v); }) ==
        "--skip: unknown solver 'lemkee' (valid: " + lcp_solver_list() + ")");

  LcpEnumerateRequest e;
  e.file = pd_file();
  e.max_size = 100;
  const std::string m = refusal([&] { run_lcp_enumerate_request(e); });
  CHECK(m.rfind("--max-size must lie in [1, ", 0) == 0);
  CHECK(m.find("got 100") != std::string::npos);
  e.max_size = 64;
  e.file = "/nonexistent/problem.json";
  CHECK(refusal([&] { run_lcp_enumerate_request(e); }).find("/nonexistent/problem.json") !=
        std::string::npos);
}
