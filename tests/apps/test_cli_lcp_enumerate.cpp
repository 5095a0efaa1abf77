// `cpkit lcp enumerate` on the inputs of issue 11: a solution double precision cannot represent
// is reported (complete = false, a message), never listed as a wrong point; a tiny entry next to
// a huge one; and a 16 x 16 problem with extreme entries returns promptly under --time-limit
// (a hang guard with a generous bound, not a timing).
#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>

#include "cli_runner.hpp"

namespace {

std::string write(const std::string& name, const std::string& text) {
  const auto path = cpkit::test::scratch_dir() / name;
  std::ofstream(path) << text;
  return "'" + path.string() + "'";
}

}  // namespace

TEST_CASE("cli lcp enumerate: a non-representable solution is reported, not listed", "[cli][enumerate]") {
  for (const char* text : {R"({"M": [[1e-320]], "q": [-1]})", R"({"M": [[1e-200]], "q": [-1e200]})"}) {
    CAPTURE(text);
    const auto r = cpkit::test::run_cpkit("lcp enumerate --json " + write("tiny.json", text));
    // A solution exists but double precision cannot hold it: nothing is listed and the answer
    // is inconclusive (exit 5), never "no solution" (exit 1).
    CHECK(r.code == 5);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j.at("complete") == false);
    CHECK(j.at("solutions").empty());
    CHECK(j.at("message").get<std::string>().find("not representable") != std::string::npos);
  }
}

TEST_CASE("cli lcp enumerate: diag(1e200, 1), q = (1, -1) lists w = (1, 0)", "[cli][enumerate]") {
  const auto r = cpkit::test::run_cpkit(
      "lcp enumerate --json " + write("big.json", R"({"M": [[1e200, 0], [0, 1]], "q": [1, -1]})"));
  CHECK(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j.at("complete") == true);
  REQUIRE(j.at("solutions").size() == 1);
  CHECK(j.at("solutions")[0].at("z") == nlohmann::json::array({0.0, 1.0}));
  CHECK(j.at("solutions")[0].at("w") == nlohmann::json::array({1.0, 0.0}));
}

TEST_CASE("cli lcp enumerate: extreme 16 x 16 entries honour --time-limit", "[cli][enumerate][time]") {
  std::mt19937 rng(16);
  std::uniform_int_distribution<int> k(-300, 300), sg(0, 1);
  std::ostringstream o;
  o.precision(17);
  o << "{\"M\": [";
  for (int i = 0; i < 16; ++i) {
    o << (i ? ", [" : "[");
    for (int jj = 0; jj < 16; ++jj) o << (jj ? ", " : "") << (sg(rng) ? 1 : -1) * std::pow(10.0, k(rng));
    o << "]";
  }
  o << "], \"q\": [";
  for (int i = 0; i < 16; ++i) o << (i ? ", " : "") << (sg(rng) ? 1 : -1) * std::pow(10.0, k(rng));
  o << "]}";
  const auto t0 = std::chrono::steady_clock::now();
  const auto r = cpkit::test::run_cpkit("lcp enumerate --json --time-limit 2 " + write("x16.json", o.str()));
  const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  CHECK(dt < 20);
  REQUIRE((r.code == 0 || r.code == 1 || r.code == 5));
  const auto j = nlohmann::json::parse(r.out);
  for (const auto& s : j.at("solutions"))
    for (const auto& v : s.at("z")) CHECK(v.is_number());  // never null (NaN or inf)
  if (j.at("complete") == false) CHECK(j.contains("message"));
}
