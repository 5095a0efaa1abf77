// A whole `cpkit map` request run by the library (requests/map_request_run.hpp), without the
// program: the Fig. 5(b) direction map against the closed forms of its critical directions
// [Stromberg et al. 1996, Sec. 4.3; docs/model.md, as in test_map_direction.cpp], the same
// model as a one-point system file (the N-point route gives the same directions), the grid
// map's critical value D+ = a11 - mu a12 = 0 at mu = a11/a12 = 2, the exit codes of a picture
// asked for (4 when not drawn), and refused requests with the messages users see (exit 2).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <unistd.h>
#include <filesystem>
#include <string>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/requests/map_request_run.hpp"
#include "cpkit/rate_problem/system/system_file.hpp"

using namespace cpkit::rate;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// The Fig. 5(b) preset (a11 = 1, a12 = 0.5, a22 = 1, C_T = 0.25, mu = 3, state b; a direction
/// map, or a mu axis over [0.1, 4]) with the options `given` over it.
MapRequest fig5b_request() {
  MapRequest a;
  a.preset = "fig5b";
  return a;
}

/// By hand (docs/model.md): L+ = 0 at tan t = (1 + mu a12 C_T) / (mu (1 + a11 C_T)) = 1.375/3.75,
/// N = 0 at tan t = a12/a11, L- = 0 at pi - atan((1 - mu a12 C_T) / (mu (1 + a11 C_T))), and N = 0
/// again at atan(a12/a11) + pi; counts 2, 2, 1, 1 there.
const std::vector<double> kFig5bCritical = {std::atan(1.375 / 3.75), std::atan(0.5),
                                            kPi - std::atan(0.625 / 3.75), std::atan(0.5) + kPi};
const std::vector<int> kFig5bCriticalCount = {2, 2, 1, 1};

void check_fig5b_critical(const nlohmann::json& critical) {
  REQUIRE(critical.size() == kFig5bCritical.size());
  for (std::size_t k = 0; k < critical.size(); ++k) {
    CAPTURE(k);
    CHECK(critical[k]["theta"].get<double>() == Approx(kFig5bCritical[k]).margin(1e-12));
    CHECK(critical[k]["count"].get<int>() == kFig5bCriticalCount[k]);
  }
}

/// A job of `size` processes seen from `rank` (only rank() and size() are asked before a
/// direction map is refused).
class FakeTransport final : public MapTransport {
 public:
  FakeTransport(int rank, int size) : rank_(rank), size_(size) {}
  int rank() const override { return rank_; }
  int size() const override { return size_; }
  void send_bytes(const std::string&, int, int) override { FAIL("no message expected"); }
  std::string recv_bytes(int, int*) override { FAIL("no message expected"); return {}; }
  bool probe(int, int*, bool) override { FAIL("no message expected"); return false; }
  void send_int(long long, int, int) override { FAIL("no message expected"); }
  long long recv_int(int, int) override { FAIL("no message expected"); return 0; }
  [[noreturn]] void abort(const std::string&, int) override { std::abort(); }

 private:
  int rank_, size_;
};

std::filesystem::path scratch(const std::string& name) {
  const auto d = std::filesystem::temp_directory_path() /
                 ("cpkit_map_run_request_" + std::to_string(::getpid())) / name;
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

}  // namespace

TEST_CASE("Fig. 5(b) direction map from the request: closed-form critical directions, exit 0",
          "[rate][maps][request]") {
  MapEnvironment env;
  env.version = "test-version";
  env.run_echo = {{"command", "test"}};
  const MapOutcome o = run_map_request(fig5b_request(), env);
  CHECK(o.exit_code == cpkit::kExitOk);
  CHECK(o.printing);
  CHECK(o.json["kind"] == "direction");
  CHECK(o.json["preset"] == "fig5b");
  CHECK(o.json["cpkit_version"] == "test-version");
  CHECK(o.json["run"] == env.run_echo);
  check_fig5b_critical(o.json["critical"]);
  // Three solutions between L+ = 0 (0.3517) and N = 0 (0.4636), at two decimals.
  CHECK_THAT(o.text, StartsWith("direction map, state b, a11 = 1, a12 = 0.5, a22 = 1, mu = 3, "
                                "C_T = 0.25\n"));
  CHECK_THAT(o.text, Contains("summary: 3 solutions for theta in (0.35, 0.46)\n"));
}

TEST_CASE("The same model as a one-point system file: the N-point route's critical directions",
          "[rate][maps][request]") {
  MapRequest a;
  a.system = "fig5b.json";
  a.file = parse_system_file(R"({"name": "fig5b", "A": [[1, 0.5], [0.5, 1]],
      "points": [{"state": "b", "mu": 3, "C_T": 0.25}]})", "fig5b.json");
  const MapOutcome o = run_map_request(a);
  CHECK(o.exit_code == cpkit::kExitOk);
  CHECK(o.json["complete"] == true);
  check_fig5b_critical(o.json["critical"]);
  CHECK_THAT(o.text, StartsWith("direction map of 1 points (fig5b.json)"));
}

TEST_CASE("A param-direction grid over mu: the critical value D+ = 0 at mu = a11/a12 = 2",
          "[rate][maps][request]") {
  MapRequest a = fig5b_request();
  a.kind = "param-direction";
  a.n = 7;  // mu = 0.1, 0.75, ..., 4
  a.theta_n = 24;
  a.threads = 1;
  const MapOutcome o = run_map_request(a);
  CHECK(o.exit_code == cpkit::kExitOk);
  CHECK(o.json["cells"] == 7 * 24);
  REQUIRE(o.json["critical_values"].size() == 1);
  CHECK(o.json["critical_values"][0]["x"].get<double>() == Approx(2.0).margin(1e-12));
  CHECK_THAT(o.text, Contains("critical: D+=0 at mu = 2\n"));
  // Three solutions need mu > a11/a12 = 2 (b.iii with both slip signs): every such cell lies there.
  bool three = false;
  for (const auto& c : o.json["classes"])
    if (c["count"] == 3) {
      three = true;
      CHECK(c["x_min"].get<double>() > 2.0);
    }
  CHECK(three);
}

TEST_CASE("Exit codes of a picture asked for: 4 when not drawn, 0 when drawn",
          "[rate][maps][request]") {
  const auto dir = scratch("plot");
  MapRequest a = fig5b_request();
  a.out = (dir / "m").string();
  a.plot = true;
  int claims = 0;
  MapEnvironment env;
  env.claim_prefix = [&](const std::string& prefix, const auto& inputs) {
    ++claims;
    CHECK(prefix == a.out);
    CHECK(inputs.empty());  // a one-point map reads no file
    return std::shared_ptr<void>();
  };
  for (bool drawn : {false, true}) {
    CAPTURE(drawn);
    env.plot = [drawn](const std::string&, nlohmann::json& files) {
      if (drawn) files["png"] = "m.png";
      return drawn;
    };
    const MapOutcome o = run_map_request(a, env);
    CHECK(o.exit_code == (drawn ? cpkit::kExitOk : cpkit::kExitInternal));
    CHECK(std::filesystem::exists(dir / "m.json"));
    CHECK(std::filesystem::exists(dir / "m.csv"));
    CHECK(o.json["files"].contains("png") == drawn);
    CHECK_THAT(o.text, Contains("wrote " + (dir / "m.csv").string() + " " +
                                (dir / "m.json").string()));
  }
  CHECK(claims == 2);
  std::filesystem::remove_all(dir.parent_path());
}

TEST_CASE("Refused requests: the messages users see (exit 2)", "[rate][maps][request]") {
  MapRequest a = fig5b_request();
  SECTION("--resume without --out") {
    a.resume = true;
    CHECK_THROWS_WITH(run_map_request(a), "--resume applies to grid maps written with --out "
                                          "PREFIX (the finished chunks are kept in PREFIX.parts)");
  }
  SECTION("an axis of no values, in options") {
    a = fig5b_request();
    a.kind = "param-direction";
    a.n = 0;
    CHECK_THROWS_WITH(run_map_request(a), "--n must be >= 1, got 0");
  }
  SECTION("a direction map's range of directions, in options") {
    a.theta_from = 1;
    CHECK_THROWS_WITH(run_map_request(a),
                      "--theta-from applies to --kind param-direction only (a direction map "
                      "computes the critical directions exactly, without sampling)");
  }
  SECTION("a 3-D option without a 3-D system") {
    a.facets = 8;
    CHECK_THROWS_WITH(run_map_request(a), "--facets applies to maps of 3-D systems (--system "
                                          "FILE with \"dim\": 3)");
  }
  SECTION("a direction map over the processes of a job") {
    FakeTransport job(0, 2);
    MapEnvironment env;
    env.transport = &job;
    CHECK_THROWS_AS(run_map_request(a, env), cpkit::InputError);
    CHECK_THROWS_WITH(run_map_request(a, env),
                      "a direction map is one exact computation, not a grid of cells: run it "
                      "without mpirun");
  }
}

TEST_CASE("Output that would not fit the free disk: refused with the N-point wording",
          "[rate][maps][request]") {
  MapEnvironment env;
  env.free_disk = [](const std::string& dir) {
    CHECK(dir == "out");
    return 1000.0;
  };
  // 2000 bytes > 0.95 x 1000 free: 2000 / 1e9 = 2e-06 GB, 1000 / 1e9 = 1e-06 GB.
  CHECK_THROWS_WITH(check_output_fits("3 x 4 cells", "use fewer", 2000, 1e12, "out", "", "", env,
                                      true),
                    "the map has 3 x 4 cells and its output would take about 2e-06 GB but only "
                    "1e-06 GB is free in 'out': use fewer");
  // 900 bytes fit under 95 % of 1000.
  CHECK_NOTHROW(check_output_fits("3 x 4 cells", "use fewer", 900, 1e12, "out", "", "", env,
                                  true));
}
