// `cpkit lcp verify`: an incomplete enumeration verifies nothing (issue 11, sec. 4): it is
// reported as inconclusive with exit code 5, never as "consistent" with exit 0.
#include <catch2/catch.hpp>

#include "cli_runner.hpp"

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

namespace {

using Run = cpkit::test::CliRun;
using cpkit::test::run_cpkit;
using cpkit::test::scratch_dir;

/// M = -I, q = 1 (n variables): z_i in {0, 1} independently, 2^n solutions; an enumeration
/// with a short time limit cannot list them all.
std::string many_solutions(int n) {
  nlohmann::json M = nlohmann::json::array(), q = nlohmann::json::array();
  for (int i = 0; i < n; ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (int k = 0; k < n; ++k) row.push_back(i == k ? -1.0 : 0.0);
    M.push_back(row);
    q.push_back(1.0);
  }
  const auto path = scratch_dir() / ("minus_identity_" + std::to_string(n) + ".json");
  std::ofstream(path) << nlohmann::json{{"M", M}, {"q", q}}.dump();
  return path.string();
}

}  // namespace

TEST_CASE("lcp verify: an incomplete enumeration is inconclusive (exit 5)", "[cli][verify]") {
  const std::string file = many_solutions(22);
  const std::string args = "lcp verify '" + file + "' --time-limit 0.2 --skip ipopt --skip nlopt";
  const Run t = run_cpkit(args);
  INFO(t.err << t.out);
  CHECK(t.code == 5);
  CHECK(t.out.find("INCONCLUSIVE") != std::string::npos);
  CHECK(t.out.find("consistent: every solver agrees") == std::string::npos);
  const Run j = run_cpkit(args + " --json");
  INFO(j.err);
  CHECK(j.code == 5);
  const auto o = nlohmann::json::parse(j.out);
  CHECK(o["enumeration"]["complete"] == false);
  CHECK(o["consistent"] == false);
  CHECK(o["verdict"] == "inconclusive");
  CHECK(o["disagreements"].empty());
}

TEST_CASE("lcp verify: a complete enumeration with agreeing solvers is consistent (exit 0)",
          "[cli][verify]") {
  // M = -I, q = 1 with n = 3: 8 solutions, all found.
  const Run j = run_cpkit("lcp verify '" + many_solutions(3) + "' --json");
  INFO(j.err);
  CHECK(j.code == 0);
  const auto o = nlohmann::json::parse(j.out);
  CHECK(o["enumeration"]["complete"] == true);
  CHECK(o["enumeration"]["count"] == 8);
  CHECK(o["consistent"] == true);
  CHECK(o["verdict"] == "consistent");
}

TEST_CASE("lcp enumerate: incomplete with no solution found is inconclusive (exit 5)",
          "[cli][enumerate]") {
  // n = 24, M with entries in [-1, 1] (first column <= 0), q = -1: a search of 2^24 supports
  // that a 0.1 s limit cuts short; none of the supports visited by then is a solution.
  const int n = 24;
  std::uint64_t state = 12345;
  auto uniform = [&state] {  // 64-bit LCG (Knuth), deterministic
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) / 9007199254740992.0 * 2 - 1;
  };
  nlohmann::json M = nlohmann::json::array(), q = nlohmann::json::array();
  for (int i = 0; i < n; ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (int k = 0; k < n; ++k) row.push_back(k == 0 ? -std::abs(uniform()) : uniform());
    M.push_back(row);
    q.push_back(-1.0);
  }
  const auto path = scratch_dir() / "random_24.json";
  std::ofstream(path) << nlohmann::json{{"M", M}, {"q", q}}.dump();
  const Run r = run_cpkit("lcp enumerate '" + path.string() + "' --time-limit 0.1 --json");
  INFO(r.err);
  const auto j = nlohmann::json::parse(r.out);
  REQUIRE(j["complete"] == false);
  REQUIRE(j["num_extreme"] == 0);
  CHECK(r.code == 5);
  const Run t = run_cpkit("lcp enumerate '" + path.string() + "' --time-limit 0.1");
  CHECK(t.code == 5);
  CHECK(t.out.find("at least 0 (the enumeration is INCOMPLETE") != std::string::npos);
}
